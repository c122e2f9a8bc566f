/* stream.h: the numbers of a camera sample beyond its place in the pixel: where it passes
 * through the lens and where in each cell of an area light its shadow tests aim
 * (LANGUAGE.md section 12). Each such use is a dimension, named by a 64-bit key. In a
 * dimension the pixel's samples take the points of an Owen-scrambled 2D Sobol set, in an
 * order shuffled per dimension: every dimension is stratified over the pixel's samples as
 * the samples' places in the pixel are, and no two dimensions move together. Like the
 * sampler's, every number depends on (seed, pixel, replica, sample, dimension) alone. */
#ifndef SCN_STREAM_H
#define SCN_STREAM_H

#include <stdbool.h>
#include <stdint.h>

/* One camera sample's stream. */
struct sample_stream {
	uint64_t key;                  /* the pixel's and replica's (stream_pixel_key) */
	uint32_t index, count;         /* this sample, and how many the pixel takes at most */
	bool independent;              /* the random pattern: plain uniform numbers, unstratified */
};

/* A dimension of a stream, fixed for its sample: where its Sobol set stands. */
struct stream_dim {
	uint64_t key;
	uint32_t x, y;                 /* the Sobol point's bits, before scrambling, reversed */
	bool independent;
};

/* The key of pixel (px, py)'s replica under the render's seed. */
uint64_t stream_pixel_key(uint64_t seed, uint32_t px, uint32_t py, uint32_t replica);

/* Dimension dim of s's sample. */
void stream_dim(const struct sample_stream *s, uint64_t dim, struct stream_dim *d);

/* The point of cell `cell` of dimension d, strictly inside (0, 1)^2. The cells of a
 * dimension (an area light's N1 x N2) are each scrambled apart: each is stratified over
 * the pixel's samples, and they are independent of each other. */
void stream_point(const struct stream_dim *d, uint32_t cell, double *u, double *v);

/* (u, v) in (0, 1)^2 onto the unit disc, area-preserving and continuous (Shirley and
 * Chiu's concentric map), so that strata of the square stay strata of the disc. */
void stream_disc(double u, double v, double *x, double *y);

#endif
