/* sphere.h: the sphere's intersection, crossings, bounds and surface, robust in double
 * precision (NUMERICS.md section 4). */
#ifndef SCN_SPHERE_H
#define SCN_SPHERE_H

#include <stdbool.h>
#include <stdint.h>

#include "ray.h"

struct sphere {
	struct vec3 center;
	double radius;
	uint32_t surface;              /* into geometry.surfaces */
};

/* Reports a hit with 0 < t < h->t by updating h->t; true when it did. */
bool sphere_intersect(const struct sphere *s, const struct ray *r, struct hit *h);
/* Every t in (0, tmax) at which r crosses the sphere (0, 1 or 2 values); for the
 * shadow filter, which counts each crossing. */
int sphere_crossings(const struct sphere *s, const struct ray *r, double tmax, double t[2]);
/* centre -+ radius, rounded: an accelerator widens them outward */
void sphere_bounds(const struct sphere *s, struct vec3 *lo, struct vec3 *hi);
/* The surface where r hits s at h->t. */
void sphere_surface(const struct sphere *s, const struct ray *r, const struct hit *h, struct surface_point *sp);

#endif
