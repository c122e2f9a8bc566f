# render/local.mk: the renderer's core: scene, camera, sampler, tracer, render loop; and
# lower.c, which builds the scene from the front end's description.
noinst_LIBRARIES += render/libscnrender.a
render_libscnrender_a_CFLAGS = $(AM_CFLAGS) $(AVX_CFLAGS)
render_libscnrender_a_SOURCES = \
	%D%/camera.c %D%/camera.h \
	%D%/render.c %D%/render.h \
	%D%/sampler.c %D%/sampler.h \
	%D%/scene.c %D%/scene.h \
	%D%/trace.c %D%/trace.h
noinst_LIBRARIES += render/libscnlower.a
render_libscnlower_a_SOURCES = %D%/lower.c %D%/lower.h
