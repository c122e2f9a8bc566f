/* codec.h: the per-format halves of image_file.c's reading and writing, one file each:
 * png.c (libpng), exr.c (OpenEXR's C API), ppm.c (by hand). */
#ifndef SCN_CODEC_H
#define SCN_CODEC_H

#include <stdbool.h>
#include <stddef.h>

#include "image.h"
#include "image_file.h"

/* The per-format halves of image_write and image_read (image_file.h). A writer
 * gets an open, empty file (fd) and does not close it; a reader gets the file open
 * at offset 0 and does not close it either. path is only for messages. Both return
 * 0 or an errno code with the message in err; a failed reader may leave a partly
 * filled image in *out for image_read to free. The EXR writer's and reader's header h
 * (image_file.h) may be NULL: the image is then the whole file; a failed reader leaves
 * no attributes in it. */
int image_png_write(const struct image *img, int fd, const char *path, int bit_depth,
                    char *err, size_t errlen);
int image_exr_write(const struct image *img, int fd, const char *path, bool float32,
                    const struct image_exr_header *h, char *err, size_t errlen);
int image_ppm_write(const struct image *img, int fd, const char *path, int bit_depth,
                    char *err, size_t errlen);
int image_png_read(int fd, const char *path, struct image **out, char *err, size_t errlen);
int image_exr_read(int fd, const char *path, struct image **out, struct image_exr_header *h,
                   char *err, size_t errlen);
int image_ppm_read(int fd, const char *path, bool linear, struct image **out, char *err,
                   size_t errlen);

#endif
