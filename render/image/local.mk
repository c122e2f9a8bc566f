# render/image/local.mk: the film, its pixel formats and files, and the image diff.
noinst_LIBRARIES += render/image/libscnimage.a
IMAGE_INCLUDES = -I$(srcdir)/%D% $(UTIL_INCLUDES)
render_image_libscnimage_a_CPPFLAGS = $(BASE_CPPFLAGS) $(IMAGE_INCLUDES) $(PNG_CFLAGS) $(EXR_CFLAGS)
render_image_libscnimage_a_CFLAGS = $(AM_CFLAGS) $(AVX_CFLAGS)
render_image_libscnimage_a_SOURCES = %D%/image.c %D%/image.h %D%/image_file.c %D%/image_file.h %D%/codec.h %D%/png.c %D%/exr.c %D%/ppm.c \
	%D%/imgdiff.c %D%/imgdiff.h
