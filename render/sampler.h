/* sampler.h: where in a pixel its samples go (LANGUAGE.md section 5 "samples"), and the
 * project's one hash: every number depends on (seed, pixel, sample), never on the thread. */
#ifndef SCN_SAMPLER_H
#define SCN_SAMPLER_H

#include <stdbool.h>
#include <stdint.h>

enum sample_kind { SAMPLE_CENTER, SAMPLE_GRID, SAMPLE_RANDOM, SAMPLE_JITTERED, SAMPLE_POISSON };

/* A scene's anti-aliasing: LANGUAGE.md's samples statement. */
struct sampling {
	int count;
	enum sample_kind kind;
	uint64_t seed;
	double target_error;           /* 0: a fixed count */
};

/* The pattern's read-only tables plus per-thread scratch; no allocation per pixel.
 *   center    (0.5, 0.5), for count 1 (every sample there for a larger count)
 *   grid      ((a + 0.5) / n, (b + 0.5) / n) for count = n * n, row by row
 *   random    independent uniform points from the hash
 *   jittered  one point in each of count equal-area, near-square cells, for any count,
 *             with both projections stratified too (multi-jittered); random per pixel.
 *             With a target_error (adaptive), an Owen-scrambled Sobol sequence instead,
 *             whose first 2^m points are stratified for every m
 *   poisson   one Poisson-disc tile per count, mirrored and toroidally shifted per pixel */
struct sampler;

/* A sampler for s->count (1 to 65536) samples of pattern s->kind; grid needs a perfect
 * square count. For poisson this builds the tile: about 0.2 ms for count 16, 2 ms for
 * 256 and 0.2 s for 65536, so make one per render and give each thread a sampler_clone
 * of it (a sampler_new per thread gives the same points, only slower). */
struct sampler *sampler_new(const struct sampling *s);

/* Another sampler, with its own scratch, sharing proto's read-only tables; its points
 * equal proto's for every pixel. Only reads proto, so threads may clone at once. proto
 * must outlive the clone. Free it with sampler_free. */
struct sampler *sampler_clone(const struct sampler *proto);

void sampler_free(struct sampler *sm);

/* The sample positions of pixel (px, py): count points in [0,1)^2, point i at xy[2*i],
 * xy[2*i+1] (x along the pixel row, y across rows; the renderer picks y's direction).
 * They depend only on the seed, the pattern and count, px, py, replica and i; not on the
 * thread, the sampler object, or earlier calls. Replica 0 is the image's; another
 * replica is an independent randomisation of the same pattern (the error estimate's),
 * the same points for grid and center. For random, poisson and adaptive jittered, any
 * prefix of the points is spread over the whole pixel and unbiased, so an adaptive render
 * may stop early.
 * Writes 2 * count doubles and changes only sm's scratch. */
void sampler_pixel(struct sampler *sm, uint32_t px, uint32_t py, uint32_t replica, double *xy);

/* For the grid pattern: true, and the integer cell of sample i (a = i % n across, b =
 * i / n), whose position sampler_pixel gives as exactly ((a + 0.5) / n, (b + 0.5) / n).
 * The POV-Ray twin (povray-equivalence.md section 10) must compute sample i of pixel
 * (px, py) as (n*px + a + 0.5) / (n*W), not as px plus that position; this gives it a, b
 * and n. False, touching nothing, for every other pattern. */
bool sampler_grid_cell(const struct sampler *sm, int i, int *a, int *b, int *n);

/* The project's one hash of a key: 64 well-mixed bits, or a uniform double in [0,1) with
 * 53 random bits. Whatever needs randomness keys it by what it belongs to, such as
 * (seed, pixel, sample, dimension), so that no result depends on the thread. */
uint64_t sampler_hash64(uint64_t seed, uint64_t a, uint64_t b, uint64_t c);
double sampler_hash01(uint64_t seed, uint64_t a, uint64_t b, uint64_t c);

#endif
