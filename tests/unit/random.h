/* random.h: reproducible random numbers for the unit tests (splitmix64); each test
 * program seeds its own stream with rng_seed. */
#ifndef SCN_TEST_RANDOM_H
#define SCN_TEST_RANDOM_H

#include <math.h>
#include <stdint.h>

#include "vec.h"

static uint64_t rng_state;

static inline void rng_seed(uint64_t seed) { rng_state = seed; }

static inline uint64_t next_u64(void)
{
	uint64_t z = (rng_state += 0x9e3779b97f4a7c15u);
	z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
	z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
	return z ^ (z >> 31);
}

static inline double urand(void) { return (double)(next_u64() >> 11) * 0x1p-53; }
static inline double urange(double a, double b) { return a + (b - a) * urand(); }
static inline int irand(int n) { return (int)(next_u64() % (uint64_t)n); }
/* log-uniform in [a, b] */
static inline double lrand(double a, double b) { return a * pow(b / a, urand()); }

static inline struct vec3 rand_unit(void)
{
	for (;;) {
		struct vec3 v = v3(urange(-1, 1), urange(-1, 1), urange(-1, 1));
		double l = vdot(v, v);
		if (l > 1e-4 && l <= 1)
			return vscale(v, 1 / sqrt(l));
	}
}

#endif
