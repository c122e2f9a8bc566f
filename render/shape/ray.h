/* ray.h: what every shape's tests take and give: the ray, the closest hit so far, the
 * surface at a hit with a bound on its error, and the origin of a ray that leaves it
 * (NUMERICS.md sections 2 and 3). */
#ifndef SCN_RAY_H
#define SCN_RAY_H

#include <stdint.h>

#include "vec.h"

struct ray {
	struct vec3 o, d;              /* d is a unit vector */
};

struct hit {
	double t;
	uint32_t prim;                 /* the shape's id (shape.h) */
	uint32_t part;                 /* a solid's: the leaf part whose surface it is (part.h) */
	double b1, b2;                 /* triangle: barycentric weights of vertices 1 and 2 */
};

/* The surface at a hit, computed from the primitive rather than from o + t d, whose
 * error grows with t. */
struct surface_point {
	struct vec3 p;
	struct vec3 p_err;             /* bound on the absolute error of each coordinate of p */
	struct vec3 ng;                /* unit geometric normal: outward (sphere), as defined (plane, triangle) */
	struct vec3 ns;                /* unit shading normal (interpolated on smooth triangles) */
};

/* The origin for a ray leaving sp in direction w: moved off the surface by the hit
 * point's error bound, to the side w goes to, then one ulp further (pbrt's
 * OffsetRayOrigin). A ray from there cannot re-hit the surface at t > 0 by rounding. */
struct vec3 ray_offset_origin(const struct surface_point *sp, struct vec3 w);

#endif
