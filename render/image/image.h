/* image.h: the film (linear float RGB) and its files: PNG, OpenEXR and binary PPM,
 * written atomically and read back for skyboxes and `scn diff`. */
#ifndef SCN_IMAGE_H
#define SCN_IMAGE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/* ORDER IMAGE_FORMAT: image.c's format_ext follows this order. */
enum image_format { IMAGE_PNG, IMAGE_EXR, IMAGE_PPM };

/* How image_read found a file encoded, for whoever must have another program decode it
 * the same way (scn pov); zero in an image made here. */
struct image_source {
	enum image_format format;
	double png_gamma;              /* PNG: the power law of its gAMA chunk; 0: the sRGB curve */
	bool exr_not_half;             /* OpenEXR: a channel stored as 32-bit float or integer */
};

/* Linear RGB, row 0 at the top, pixel (x, y) at rgb[3 * (y * width + x)]. */
struct image {
	int width, height;
	float *rgb;                    /* width * height * 3 */
	struct image_source source;
};

/* The most pixels one image may have (12 bytes each: 3 GiB). Bigger requests, from a
 * command line or a file's header, are refused before anything is allocated. */
#define IMAGE_MAX_PIXELS ((int64_t)1 << 28)

/* A zeroed (black) image, or NULL when width or height is not positive or the image
 * would have more than IMAGE_MAX_PIXELS pixels. The caller frees it with image_free. */
struct image *image_new(int width, int height);
void image_free(struct image *img);
/* What image_new allocates for width x height pixels. */
uint64_t image_bytes(int64_t width, int64_t height);

/* The format named by path's extension (.png, .exr, .ppm in any case), or -1. */
int image_format_of(const char *path);

struct image_write_options {
	int bit_depth;                 /* 8 or 16: PNG and PPM (EXR ignores it) */
	bool float32;                  /* EXR: 32-bit float instead of half */
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

/* What image_read_with may decide differently from image_read. */
struct image_read_options {
	bool ppm_linear;               /* PPM samples are linear (POV-Ray's File_Gamma=1.0), not sRGB */
};

/* image_read with options; NULL options is image_read. */
int image_read_with(const char *path, const struct image_read_options *opt, struct image **out,
                    char *err, size_t errlen);

/* The sRGB transfer curve (IEC 61966-2-1) on one value: linear -> encoded and back.
 * encode maps [0, 1] onto [0, 1]; neither clamps. */
double image_srgb_encode(double linear);
double image_srgb_decode(double encoded);

/* The integer sample (0..maxval) that PNG and PPM store for a linear value: the sRGB
 * curve, then floor(clamp(c, 0, 1) * maxval + 0.5) on the encoded c. Both steps run in
 * single precision as in POV-Ray (povray-equivalence.md section 1), so that the same
 * linear colour gives the same sample in both programs. NaN gives 0. */
unsigned image_srgb_sample(float linear, unsigned maxval);

/* The per-format halves of image_write and image_read, for image.c only. A writer
 * gets an open, empty file (fd) and does not close it; a reader gets the file open
 * at offset 0 and does not close it either. path is only for messages. Both return
 * 0 or an errno code with the message in err; a failed reader may leave a partly
 * filled image in *out for image_read to free. */
int image_png_write(const struct image *img, int fd, const char *path, int bit_depth,
                    char *err, size_t errlen);
int image_exr_write(const struct image *img, int fd, const char *path, bool float32,
                    char *err, size_t errlen);
int image_ppm_write(const struct image *img, int fd, const char *path, int bit_depth,
                    char *err, size_t errlen);
int image_png_read(int fd, const char *path, struct image **out, char *err, size_t errlen);
int image_exr_read(int fd, const char *path, struct image **out, char *err, size_t errlen);
int image_ppm_read(int fd, const char *path, bool linear, struct image **out, char *err,
                   size_t errlen);

/* Helpers shared by the format files. */
/* A table of maxval + 1 linear values, entry v = decode(v / maxval) through the sRGB
 * curve (gamma 0) or the power law x^(1/gamma) of a PNG gAMA value. Freed with free(). */
float *image_decode_table(unsigned maxval, double gamma);
/* image_new for a size read from a file's header; if it refuses, EINVAL (no pixels),
 * EFBIG (too many) or ENOMEM (more than the machine has: memory.h) with the message
 * naming path in err. data_bytes is how many bytes of pixel data the header implies;
 * the file, open at fd, must be able to hold them at max_ratio to 1, its format's best
 * compression, or it is refused (EINVAL) before anything is allocated: a few bytes that
 * claim 2^28 pixels would cost 3 GiB. */
int image_alloc_for_read(int64_t width, int64_t height, int fd, double data_bytes,
                         unsigned max_ratio, const char *path, struct image **out, char *err,
                         size_t errlen);

#endif
