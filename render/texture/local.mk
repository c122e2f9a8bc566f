# render/texture/local.mk: what a surface's colour and shading normal vary with: noise,
# patterns and their colour maps, bump patterns, image maps and UV coordinates.
TEXTURE_INCLUDES = -I$(srcdir)/%D% $(MATH_INCLUDES) $(IMAGE_INCLUDES)
noinst_LIBRARIES += render/texture/libscntexture.a
render_texture_libscntexture_a_CPPFLAGS = $(BASE_CPPFLAGS) $(TEXTURE_INCLUDES)
render_texture_libscntexture_a_CFLAGS = $(AM_CFLAGS) $(AVX_CFLAGS)
render_texture_libscntexture_a_SOURCES = %D%/texture.h %D%/noise.c %D%/pattern.c %D%/image_map.c
