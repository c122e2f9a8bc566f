/* accel.h: the scene's accelerator, a BVH or a uniform grid as --accel chooses; the
 * tracer asks whichever was built through these calls. */
#ifndef SCN_ACCEL_H
#define SCN_ACCEL_H

#include "bvh.h"
#include "grid.h"

/* Builds sc->grid for ACCEL_GRID, sc->bvh otherwise, with sc's primitives in its
 * leaves' order. */
static inline void accel_build(struct scene *sc, enum accel kind)
{
	if (kind == ACCEL_GRID) {
		sc->grid = grid_build(sc);
	} else {
		sc->bvh = bvh_build(sc, kind);
		bvh_reorder(sc->bvh, sc);
	}
}

static inline bool accel_intersect(const struct scene *sc, const struct ray *r, struct hit *h)
{
	return sc->grid ? grid_intersect(sc->grid, sc, r, h) : bvh_intersect(sc->bvh, sc, r, h);
}

static inline struct vec3 accel_transmittance(const struct scene *sc, const struct ray *r, double tmax)
{
	return sc->grid ? grid_transmittance(sc->grid, sc, r, tmax) : bvh_transmittance(sc->bvh, sc, r, tmax);
}

#endif
