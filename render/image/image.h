/* image.h: the film (linear float RGB), the sRGB curve between it and 8- and 16-bit
 * samples, and what every format's reader shares (image_file.h has the files). */
#ifndef SCN_IMAGE_H
#define SCN_IMAGE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/* ORDER IMAGE_FORMAT: image_file.c's format_ext follows this order. */
enum image_format { IMAGE_PNG, IMAGE_EXR, IMAGE_PPM };

/* How image_read found a file encoded, for whoever must have another program decode it
 * the same way (scn pov); zero in an image made here. */
struct image_source {
	enum image_format format;
	double png_gamma;              /* PNG: the power law of its gAMA chunk; 0: the sRGB curve */
	bool exr_not_half;             /* OpenEXR: a channel stored as 32-bit float or integer */
	bool embedded;                 /* read from memory (a mesh file's own texture): no file of
	                                * its own for another program to read */
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

/* The sRGB transfer curve (IEC 61966-2-1) on one value: linear -> encoded and back.
 * encode maps [0, 1] onto [0, 1]; neither clamps. */
double image_srgb_encode(double linear);
double image_srgb_decode(double encoded);

/* The integer sample (0..maxval) that PNG and PPM store for a linear value: the sRGB
 * curve, then floor(clamp(c, 0, 1) * maxval + 0.5) on the encoded c. Both steps run in
 * single precision as in POV-Ray (povray-equivalence.md section 1), so that the same
 * linear colour gives the same sample in both programs. NaN gives 0. */
unsigned image_srgb_sample(float linear, unsigned maxval);

/* For the formats' readers (codec.h). */
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
