/* image_file.h: image files: PNG, OpenEXR and binary PPM, written atomically and read
 * back for skyboxes and `scn diff`. */
#ifndef SCN_IMAGE_FILE_H
#define SCN_IMAGE_FILE_H

#include <stdbool.h>
#include <stddef.h>

#include "image.h"

/* The format named by path's extension (.png, .exr, .ppm in any case), or -1. */
int image_format_of(const char *path);

/* An OpenEXR file's place in a bigger image and the string attributes it carries
 * beyond the pixels: a --tile part's (src/tile_part.h). */
enum { IMAGE_EXR_ATTRS = 8 };
struct image_exr_header {
	int display[4];                /* the display window [x0, x1) x [y0, y1) */
	int data_x, data_y;            /* the data window's top-left corner, in the display
	                                * window's coordinates; its size is the image's */
	int nattrs;
	struct image_attr {
		const char *name, *value;  /* read: malloc'd (image_exr_header_free) */
	} attrs[IMAGE_EXR_ATTRS];
};

struct image_write_options {
	int bit_depth;                 /* 8 or 16: PNG and PPM (EXR ignores it) */
	bool float32;                  /* EXR: 32-bit float instead of half */
	const struct image_exr_header *exr; /* EXR: its windows and attributes; NULL: the
	                                * image is the whole display window, no attributes */
};

/* An image file being written: created before the image exists (image_file_create),
 * so that an unwritable place is found before the work, and filled once it does
 * (image_file_commit). */
struct image_file {
	const char *path;
	int format, fd;
	char *tmp;                     /* the temporary file, renamed over path at the end */
	struct image_write_options opt;
};

/* Checks path's format and the options (NULL: 8-bit, half) and creates the temporary
 * file in path's directory. Returns 0, or an errno code with a message naming path in
 * err (EINVAL: bad options or unknown extension; otherwise the OS's reason), and there
 * is then nothing to commit. */
int image_file_create(struct image_file *f, const char *path, const struct image_write_options *opt,
                      char *err, size_t errlen);
/* Writes img into f's temporary file and renames it over f's path; with img NULL, when
 * the image could not be made, only removes the temporary file. Either way f is done.
 * Returns 0, or an errno code with a message naming the path in err. */
int image_file_commit(struct image_file *f, const struct image *img, char *err, size_t errlen);

/* Writes img to path in the format of its extension (options NULL: 8-bit, half).
 * The bytes go to a temporary file in path's directory that is then renamed over
 * path, so on any failure the temporary is removed and a file already at path is
 * left untouched. Returns 0, or an errno code with a message naming path in err
 * (EINVAL: bad options or unknown extension; otherwise the OS's reason). */
int image_write(const struct image *img, const char *path, const struct image_write_options *opt,
                char *err, size_t errlen);

/* Reads a PNG, OpenEXR or binary PPM file (told apart by their first bytes) into a
 * new linear image in *out. PNG honours its sRGB and gAMA chunks and is sRGB when
 * untagged; PPM is sRGB; EXR is linear. Returns 0, or an errno code (EINVAL: not a
 * readable image; EFBIG: too many pixels) with a message naming path in err; *out is
 * then NULL. */
int image_read(const char *path, struct image **out, char *err, size_t errlen);

/* image_read for an OpenEXR file, with its header in *h: the windows, and the string
 * attributes whose names start with "scn" (the first IMAGE_EXR_ATTRS of them, in file
 * order). Another format is refused (EINVAL). On success the caller frees the
 * attributes with image_exr_header_free; on failure *h holds none. */
int image_read_exr_header(const char *path, struct image **out, struct image_exr_header *h,
                          char *err, size_t errlen);
/* Frees the attributes image_read_exr_header copied into *h. (exr.c) */
void image_exr_header_free(struct image_exr_header *h);

/* What image_read_with may decide differently from image_read. */
struct image_read_options {
	bool ppm_linear;               /* PPM samples are linear (POV-Ray's File_Gamma=1.0), not sRGB */
};

/* image_read with options; NULL options is image_read. */
int image_read_with(const char *path, const struct image_read_options *opt, struct image **out,
                    char *err, size_t errlen);

/* image_read for a PNG file held in memory, size bytes at data (a mesh file's embedded
 * texture, mesh_import.h); name stands for the path in messages. (png.c) */
int image_read_png_memory(const unsigned char *data, size_t size, const char *name, struct image **out,
                          char *err, size_t errlen);

#endif
