/* sobol_bits.h: the bit-level pieces of the samplers (sampler.c, stream.c): splitmix64's
 * mix, the 2D Sobol sequence, a hash-based Owen scramble, and the conversion of 32 random
 * bits to a point strictly inside (0, 1). */
#ifndef SCN_SOBOL_BITS_H
#define SCN_SOBOL_BITS_H

#include <stdint.h>

#define GOLDEN 0x9e3779b97f4a7c15u     /* 2^64 / phi: splitmix64's Weyl increment */

/* splitmix64's finaliser (Stafford's variant 13), as lang/builtins.c's rand uses it. */
static inline uint64_t mix64(uint64_t z)
{
	z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
	z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
	return z ^ (z >> 31);
}

/* Jitter inside a stratum, at the midpoints of 2^32 sub-intervals: never 0 or 1. For a
 * stratum index k < 2^20, k + u is exact, and (k + u) / d, even computed as a product with
 * 1 / d, stays strictly inside [k / d, (k + 1) / d) for d < 2^20: no point lands on a
 * stratum's edge or on 1. */
static inline double jitter32(uint32_t bits) { return ((double)bits + 0.5) * 0x1.0p-32; }

static inline uint32_t reverse32(uint32_t x)
{
	x = (x << 16) | (x >> 16);
	x = ((x & 0x00ff00ffu) << 8) | ((x >> 8) & 0x00ff00ffu);
	x = ((x & 0x0f0f0f0fu) << 4) | ((x >> 4) & 0x0f0f0f0fu);
	x = ((x & 0x33333333u) << 2) | ((x >> 2) & 0x33333333u);
	return ((x & 0x55555555u) << 1) | ((x >> 1) & 0x55555555u);
}

/* Sobol's second dimension: the index's bits times the Pascal matrix mod 2. (The first is
 * the index's bits reversed.) */
static inline uint32_t sobol_y(uint32_t i)
{
	uint32_t r = 0;
	for (uint32_t v = 1u << 31; i; i >>= 1, v ^= v >> 1)
		if (i & 1)
			r ^= v;
	return r;
}

/* A nested uniform (Owen) scramble of a 32-bit fraction, by Laine and Karras's hash in
 * reversed bit order (Burley, "Practical hash-based Owen scrambling", JCGT 2020): each
 * bit is flipped by a function of the bits above it only. The first takes the fraction's
 * bits already reversed, for a caller that scrambles one point many ways. */
static inline uint32_t owen_scramble_reversed(uint32_t reversed, uint32_t seed)
{
	uint32_t x = reversed + seed;
	x ^= x * 0x6c50b47cu;
	x ^= x * 0xb82f1e52u;
	x ^= x * 0xc7afe638u;
	x ^= x * 0x8d22f6e6u;
	return reverse32(x);
}
static inline uint32_t owen_scramble(uint32_t x, uint32_t seed)
{
	return owen_scramble_reversed(reverse32(x), seed);
}

#endif
