/* plane.h: the infinite plane's intersection and surface (NUMERICS.md section 7). Planes
 * are unbounded, so no accelerator holds them: the dispatch (shape.h) tests them all. */
#ifndef SCN_PLANE_H
#define SCN_PLANE_H

#include <stdbool.h>
#include <stdint.h>

#include "ray.h"

struct plane {
	struct vec3 normal;            /* unit */
	double offset;                 /* the plane is p . normal = offset */
	uint32_t surface;              /* into geometry.surfaces */
};

/* Reports a hit with 0 < t < h->t by updating h->t; true when it did. Inline: every ray
 * tests every plane, beside the accelerator, and a call each cost 2% of the headline's
 * instructions. */
static inline bool plane_intersect(const struct plane *pl, const struct ray *r, struct hit *h)
{
	double denom = vdot(pl->normal, r->d);
	if (denom == 0)
		return false; /* parallel: a miss, not a NaN (NUMERICS.md section 7) */
	double t = (pl->offset - vdot(pl->normal, r->o)) / denom;
	if (!(t > 0 && t < h->t))
		return false;
	h->t = t;
	return true;
}
/* The surface where r hits pl at h->t. */
void plane_surface(const struct plane *pl, const struct ray *r, const struct hit *h, struct surface_point *sp);

#endif
