# render/accel/local.mk: the accelerators (BVH and grid) and what only they use.
ACCEL_INCLUDES = -I$(srcdir)/%D% $(SHAPE_INCLUDES) $(UTIL_INCLUDES)
noinst_LIBRARIES += render/accel/libscnaccel.a
render_accel_libscnaccel_a_CPPFLAGS = $(BASE_CPPFLAGS) $(ACCEL_INCLUDES)
render_accel_libscnaccel_a_CFLAGS = $(AM_CFLAGS) $(AVX_CFLAGS)
render_accel_libscnaccel_a_SOURCES = %D%/accel.h %D%/bvh.h %D%/bvh_impl.h %D%/bvh_build.c %D%/bvh_collapse.c \
	%D%/bvh_reorder.c %D%/bvh_traverse.c %D%/grid.c %D%/grid.h %D%/tri_packet.c %D%/tri_packet.h \
	%D%/parallel.c %D%/parallel.h
