# render/local.mk: the renderer: scene, geometry, BVH, sampling, shading, images.
noinst_LIBRARIES += render/libscnrender.a
render_libscnrender_a_CPPFLAGS = $(AM_CPPFLAGS) $(PNG_CFLAGS) $(EXR_CFLAGS) $(ASSIMP_CFLAGS)
render_libscnrender_a_CFLAGS = $(AM_CFLAGS) $(AVX_CFLAGS)
render_libscnrender_a_SOURCES = \
	%D%/accel.h %D%/bvh.h %D%/bvh_impl.h %D%/bvh_build.c %D%/bvh_collapse.c %D%/bvh_reorder.c \
	%D%/bvh_traverse.c %D%/grid.c %D%/grid.h %D%/parallel.c %D%/parallel.h %D%/v4f.h \
	%D%/camera.c %D%/camera.h \
	%D%/render.c %D%/render.h \
	%D%/scene.c %D%/scene.h \
	%D%/shape.c %D%/shape.h %D%/tri_packet.c %D%/tri_packet.h %D%/v4d.h \
	%D%/trace.c %D%/trace.h \
	%D%/vec.h
# what a program needs to link the renderer (after lang/libscnlang.a, if it uses it)
RENDER_LIBS = render/libscnrender.a lang/libscnutil.a $(PNG_LIBS) $(EXR_LIBS) $(ASSIMP_LIBS) -lm
render_libscnrender_a_SOURCES += render/mesh_import.c render/mesh_import.h render/mesh_join.c render/mesh_join.h \
	render/mesh_header.c render/mesh_header.h
render_libscnrender_a_SOURCES += %D%/image.c %D%/image.h %D%/png.c %D%/exr.c %D%/ppm.c
render_libscnrender_a_SOURCES += render/sampler.c render/sampler.h
render_libscnrender_a_SOURCES += render/imgdiff.c render/imgdiff.h
render_libscnrender_a_SOURCES += %D%/pov_export.c %D%/pov_export.h %D%/pov_material.c %D%/pov_material.h \
	%D%/pov_write.c %D%/pov_write.h
render_libscnrender_a_SOURCES += %D%/atomic.c %D%/atomic.h
