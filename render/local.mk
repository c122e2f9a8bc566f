# render/local.mk: the renderer's core: scene, camera, sampler, tracer, render loop; and
# lower.c, which builds the scene from the front end's description.
RENDER_INCLUDES = -I$(srcdir)/%D% $(ACCEL_INCLUDES) $(IMAGE_INCLUDES) $(TEXTURE_INCLUDES)
noinst_LIBRARIES += render/libscnrender.a
render_libscnrender_a_CPPFLAGS = $(BASE_CPPFLAGS) $(RENDER_INCLUDES)
render_libscnrender_a_CFLAGS = $(AM_CFLAGS) $(AVX_CFLAGS)
render_libscnrender_a_SOURCES = \
	%D%/camera.c %D%/camera.h \
	%D%/light.c %D%/light.h \
	%D%/render.c %D%/render.h \
	%D%/sampler.c %D%/sampler.h %D%/sobol_bits.h \
	%D%/scene.c %D%/scene.h \
	%D%/shade.c %D%/shade.h \
	%D%/stream.c %D%/stream.h \
	%D%/trace.c %D%/trace.h
# lower*.c, a library of their own: the only files whose include path
# holds lang/
LOWER_INCLUDES = $(RENDER_INCLUDES) $(MESH_INCLUDES) $(LANG_INCLUDES)
noinst_LIBRARIES += render/libscnlower.a
render_libscnlower_a_CPPFLAGS = $(BASE_CPPFLAGS) $(LOWER_INCLUDES)
render_libscnlower_a_SOURCES = %D%/lower.c %D%/lower.h %D%/lower_internal.h %D%/lower_add.c %D%/lower_mesh.c \
	%D%/lower_texture.c %D%/lower_texture.h
