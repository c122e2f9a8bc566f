/* accel.h: the scene's accelerator, a BVH or a uniform grid as --accel chooses, over the
 * scene's geometry; the tracer asks whichever was built through these calls. */
#ifndef SCN_ACCEL_H
#define SCN_ACCEL_H

#include "bvh.h"
#include "grid.h"

enum accel_kind { ACCEL_BVH, ACCEL_GRID, ACCEL_NONE }; /* ACCEL_NONE: a BVH of one leaf */

/* One of the two is built; both NULL before accel_build. */
struct accel {
	struct bvh *bvh;
	struct grid *grid;
};

/* Builds a over geo, and puts geo's primitives in its leaves' order. */
static inline void accel_build(struct accel *a, struct geometry *geo, enum accel_kind kind)
{
	if (kind == ACCEL_GRID) {
		a->grid = grid_build(geo);
	} else {
		a->bvh = bvh_build(geo, kind == ACCEL_NONE);
		bvh_reorder(a->bvh, geo);
	}
}

static inline void accel_free(struct accel *a)
{
	bvh_free(a->bvh);
	grid_free(a->grid);
	a->bvh = NULL;
	a->grid = NULL;
}

/* The most bytes either accelerator holds for nprims primitives, ntriangles of them
 * triangles: the larger of the two, for refusing a scene too big before it is built. */
static inline uint64_t accel_bytes(uint64_t nprims, uint64_t ntriangles)
{
	uint64_t bvh = bvh_bytes(nprims, ntriangles), grid = grid_bytes(nprims);
	return bvh > grid ? bvh : grid;
}

/* Closest hit with 0 < t < h->t over every primitive of geo, planes included; updates h. */
static inline bool accel_intersect(const struct accel *a, const struct geometry *geo, const struct ray *r,
                                   struct hit *h)
{
	return a->grid ? grid_intersect(a->grid, geo, r, h) : bvh_intersect(a->bvh, geo, r, h);
}

/* The product of k_t over every surface r crosses in (0, tmax) (bvh_transmittance). */
static inline struct vec3 accel_transmittance(const struct accel *a, const struct geometry *geo,
                                              const struct ray *r, double tmax)
{
	return a->grid ? grid_transmittance(a->grid, geo, r, tmax) : bvh_transmittance(a->bvh, geo, r, tmax);
}

#endif
