/* imgdiff.h: the error between two images of the same size, in linear light, and a
 * false-colour picture of where they differ (what `scn diff` reports). */
#ifndef SCN_IMGDIFF_H
#define SCN_IMGDIFF_H

#include <stdint.h>

#include "image.h"

/* Channel differences up to this much above k/255 do not count as "off by more than
 * k/255": two 8-bit samples one step apart, stored as floats, differ by 1/255 give or
 * take 6e-8, and such a pair must not count by chance. It is 1/16 of a 16-bit step. */
#define IMGDIFF_OFF_SLACK (1.0 / (16 * 65535.0))

/* The metrics over every channel of every pixel. The error of a channel is |a - b| in
 * linear light; it is 0 where a and b are equal (the same infinity, or both NaN) and
 * infinite where only one is NaN or they are opposite infinities. */
struct imgdiff_stats {
	int width, height;
	double rmse;                   /* sqrt(mean of squared channel errors) */
	double psnr;                   /* 20 log10(1 / rmse) dB (peak 1); INFINITY when rmse is 0 */
	double mean;                   /* mean channel error */
	double bias;                   /* mean of a - b over the channels where it is finite:
	                                * whether one image is brighter, beyond their noise */
	double max;                    /* largest channel error */
	int max_x, max_y;              /* its pixel (the first in reading order); 0, 0 when max is 0 */
	int64_t off1, off2;            /* pixels with a channel off by more than 1/255, 2/255 */
	int64_t pixels;                /* width * height */
};

/* The metrics of a against b, which must have the same size (false otherwise). */
bool imgdiff_compare(const struct image *a, const struct image *b, struct imgdiff_stats *out);

/* img shrunk n times in each direction, each pixel the mean of an n x n block; NULL
 * when n < 1 or a side is not a multiple of n. The caller frees it with image_free. */
struct image *imgdiff_downsample(const struct image *img, int n);

/* The heatmap scale, in powers of two of a pixel's largest channel error: below
 * 2^IMGDIFF_HEAT_BLACK (half a 16-bit step) black; from 2^IMGDIFF_HEAT_LO (about
 * 1/65535) dark blue through blue (2^-12) and yellow (2^-8, about 1/255) to white at
 * 2^IMGDIFF_HEAT_HI (1/16) and above. */
#define IMGDIFF_HEAT_BLACK (-17)
#define IMGDIFF_HEAT_LO (-16)
#define IMGDIFF_HEAT_HI (-4)

/* A false-colour image of a against b (same size, else NULL): each pixel shows its
 * largest channel error on the scale above. The caller frees it with image_free. */
struct image *imgdiff_heatmap(const struct image *a, const struct image *b);

#endif
