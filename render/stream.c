/* stream.c: the sample streams of stream.h: a permutation per dimension, a Sobol point,
 * and a per-cell Owen scramble. */
#include "stream.h"

#include <math.h>

#include "sampler.h"
#include "sobol_bits.h"

#define STREAM_KEY ((uint64_t)1 << 40)  /* above sampler_pixel's and render.c's hash keys */

uint64_t stream_pixel_key(uint64_t seed, uint32_t px, uint32_t py, uint32_t replica)
{
	return sampler_hash64(seed, px, py, STREAM_KEY | replica);
}

/* Element i of a random permutation of 0 .. count-1 chosen by seed, without building it:
 * a bijection of the smallest power-of-two range 2^w that holds count, walked until it
 * lands below count (the range is at most twice count: two steps on average). Each round
 * is a bijection of w bits: an xor with a key, a multiplication by an odd key, and a right
 * xorshift by half the width, which mixes the high bits into the low ones at every width. */
static uint32_t permute(uint32_t i, uint32_t count, uint64_t seed)
{
	uint32_t w = 1;
	while ((1u << w) < count)
		w++;
	uint32_t mask = (1u << w) - 1, half = (w + 1) / 2;
	do {
		uint64_t k = seed;
		for (int round = 0; round < 4; round++) {
			k = mix64(k + GOLDEN);
			i = (i ^ (uint32_t)k) & mask;
			i = (i * ((uint32_t)(k >> 32) | 1)) & mask;
			i ^= i >> half;
		}
	} while (i >= count);
	return i;
}

void stream_dim(const struct sample_stream *s, uint64_t dim, struct stream_dim *d)
{
	d->independent = s->independent;
	if (s->independent) {
		d->key = mix64(mix64(s->key + (dim + 1) * GOLDEN) + ((uint64_t)s->index + 1) * GOLDEN);
		d->x = d->y = 0;
		return;
	}
	d->key = mix64(s->key + (dim + 1) * GOLDEN);
	uint32_t j = s->count > 1 ? permute(s->index, s->count, mix64(d->key)) : 0;
	d->x = j;                      /* both reversed, as owen_scramble_reversed takes them */
	d->y = reverse32(sobol_y(j));
}

void stream_point(const struct stream_dim *d, uint32_t cell, double *u, double *v)
{
	uint64_t seeds = mix64(d->key + ((uint64_t)cell + 1) * GOLDEN);
	if (d->independent) {
		*u = jitter32((uint32_t)seeds);
		*v = jitter32((uint32_t)(seeds >> 32));
		return;
	}
	*u = jitter32(owen_scramble_reversed(d->x, (uint32_t)seeds));
	*v = jitter32(owen_scramble_reversed(d->y, (uint32_t)(seeds >> 32)));
}

void stream_disc(double u, double v, double *x, double *y)
{
	double a = 2 * u - 1, b = 2 * v - 1;
	if (a == 0 && b == 0) {
		*x = *y = 0;
		return;
	}
	double r, phi;
	if (fabs(a) > fabs(b)) {
		r = a;
		phi = (M_PI / 4) * (b / a);
	} else {
		r = b;
		phi = (M_PI / 2) - (M_PI / 4) * (a / b);
	}
	*x = r * cos(phi);
	*y = r * sin(phi);
}
