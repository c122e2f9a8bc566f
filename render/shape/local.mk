# render/shape/local.mk: ray intersection with each kind of primitive.
SHAPE_INCLUDES = -I$(srcdir)/%D% $(MATH_INCLUDES)
noinst_LIBRARIES += render/shape/libscnshape.a
render_shape_libscnshape_a_CPPFLAGS = $(BASE_CPPFLAGS) $(SHAPE_INCLUDES)
render_shape_libscnshape_a_CFLAGS = $(AM_CFLAGS) $(AVX_CFLAGS)
render_shape_libscnshape_a_SOURCES = %D%/shape.c %D%/shape.h %D%/geometry.c %D%/geometry.h %D%/ray.c %D%/ray.h \
	%D%/sphere.c %D%/sphere.h %D%/plane.c %D%/plane.h %D%/triangle.c %D%/triangle.h \
	%D%/part.c %D%/part.h %D%/part_make.c %D%/part_make.h %D%/csg.c %D%/csg.h %D%/csg_tree.c %D%/csg_tree.h \
	%D%/quartic.c %D%/quartic.h %D%/torus.c %D%/torus.h
