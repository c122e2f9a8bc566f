/* image.c: the film, the sRGB curve, and what the readers of every format share: the
 * decoding tables and the checked allocation for a size read from a file. */
#include "image.h"


#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "memory.h"
#include "xalloc.h"

struct image *image_new(int width, int height)
{
	if (width <= 0 || height <= 0 || (int64_t)width * height > IMAGE_MAX_PIXELS)
		return NULL;
	struct image *img = xmalloc(sizeof *img);
	img->width = width;
	img->height = height;
	img->rgb = xcalloc((size_t)width * (size_t)height * 3, sizeof *img->rgb);
	return img;
}

uint64_t image_bytes(int64_t width, int64_t height)
{
	return sizeof(struct image) + (uint64_t)width * (uint64_t)height * 3 * sizeof(float);
}

void image_free(struct image *img)
{
	if (!img)
		return;
	free(img->rgb);
	free(img);
}

double image_srgb_encode(double linear)
{
	if (linear <= 0.0031308)
		return 12.92 * linear;
	return 1.055 * pow(linear, 1 / 2.4) - 0.055;
}

double image_srgb_decode(double encoded)
{
	if (encoded <= 0.04045)
		return encoded / 12.92;
	return pow((encoded + 0.055) / 1.055, 2.4);
}

/* Measured against POV-Ray 3.7's 16-bit output of 147,456 random half-float values:
 * all samples equal; the same steps in double precision differ by one in 0.2% of
 * them, where the product lands next to a rounding boundary. */
unsigned image_srgb_sample(float linear, unsigned maxval)
{
	float c = linear <= 0.0031308f ? linear * 12.92f : 1.055f * powf(linear, 1.0f / 2.4f) - 0.055f;
	if (!(c > 0))                  /* also NaN */
		return 0;
	if (c >= 1)
		return maxval;
	return (unsigned)(c * (float)maxval + 0.5f);
}

float *image_decode_table(unsigned maxval, double gamma)
{
	float *t = xmalloc(((size_t)maxval + 1) * sizeof *t);
	for (unsigned v = 0; v <= maxval; v++) {
		double e = (double)v / maxval;
		t[v] = (float)(gamma > 0 ? pow(e, 1 / gamma) : image_srgb_decode(e));
	}
	return t;
}

int image_alloc_for_read(int64_t width, int64_t height, int fd, double data_bytes,
                         unsigned max_ratio, const char *path, struct image **out, char *err,
                         size_t errlen)
{
	*out = NULL;
	if (width <= 0 || height <= 0) {
		snprintf(err, errlen, "cannot read '%s': invalid image size %lld x %lld", path,
		         (long long)width, (long long)height);
		return EINVAL;
	}
	if (width > INT32_MAX || height > INT32_MAX || width * height > IMAGE_MAX_PIXELS) {
		snprintf(err, errlen, "cannot read '%s': image too large (%lld x %lld pixels; at most %lld)",
		         path, (long long)width, (long long)height, (long long)IMAGE_MAX_PIXELS);
		return EFBIG;
	}
	char need[128];
	if (!memory_fits(image_bytes(width, height), need, sizeof need)) {
		snprintf(err, errlen, "cannot read '%s': its %lld x %lld image %s", path, (long long)width,
		         (long long)height, need);
		return ENOMEM;
	}
	struct stat st;    /* a pipe has no size to go by */
	if (fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && data_bytes > (double)st.st_size * max_ratio) {
		snprintf(err, errlen, "cannot read '%s': truncated or corrupt file: %lld x %lld pixels "
		         "cannot fit in its %lld bytes", path, (long long)width, (long long)height,
		         (long long)st.st_size);
		return EINVAL;
	}
	*out = image_new((int)width, (int)height);
	return 0;
}
