/* shape.h: ray intersection with spheres, planes and triangles, robust in double
 * precision (NUMERICS.md sections 2, 4, 5, 7), and the offset rule for spawned rays. */
#ifndef SCN_SHAPE_H
#define SCN_SHAPE_H

#include <stdbool.h>
#include <stdint.h>

#include "scene.h"
#include "vec.h"

struct ray {
	struct vec3 o, d;              /* d is a unit vector */
};

/* Primitive ids: spheres, triangles and planes share one number space. */
#define PRIM_KIND_SHIFT 30
enum prim_kind { PRIM_SPHERE = 0, PRIM_TRIANGLE = 1, PRIM_PLANE = 2 };
static inline uint32_t prim_id(enum prim_kind k, uint32_t index) { return (uint32_t)k << PRIM_KIND_SHIFT | index; }
static inline enum prim_kind prim_kind(uint32_t id) { return (enum prim_kind)(id >> PRIM_KIND_SHIFT); }
static inline uint32_t prim_index(uint32_t id) { return id & ((1u << PRIM_KIND_SHIFT) - 1); }

struct hit {
	double t;
	uint32_t prim;
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

/* gamma(n) of pbrt: a bound on the relative error of n roundings. */
static inline double err_gamma(int n)
{
	const double u = 0x1p-53;
	return n * u / (1 - n * u);
}

/* Two steps of the watertight triangle test, written once for tri_ray_hit() and for the
 * packet test (tri_packet.c), whose operands are doubles or vectors of four doubles: the
 * same operations in the same order give the same results.
 * TRI_T_OUTSIDE: t = tscaled / det lies outside (0, tmax), decided without the division
 * (limit = tmax * det), with | rather than || (one branch on the outcome rather than one
 * per comparison, which a ray that hits or misses at random mispredicts).
 * TRI_DELTA_T: pbrt-v3's bound on the rounding error of t, from the greatest magnitudes
 * of the transformed vertices' coordinates and of the edge functions, and |1 / det|:
 * 3 (g3 max_e max_z + delta_e max_z + delta_z max_e) |1 / det|, where delta_z = g3 max_z,
 * delta_x = g5 (max_x + max_z), delta_y = g5 (max_y + max_z) and
 * delta_e = 2 (g2 max_x max_y + delta_y max_x + delta_x max_y), gN = err_gamma(N). */
#define TRI_T_OUTSIDE(det, tscaled, limit, zero)                                                      \
	((((det) < (zero)) & (((tscaled) >= (zero)) | ((tscaled) < (limit)))) |                           \
	 (((det) > (zero)) & (((tscaled) <= (zero)) | ((tscaled) > (limit)))))
#define TRI_DELTA_T(max_x, max_y, max_z, max_e, abs_inv)                                              \
	(3 * (err_gamma(3) * (max_e) * (max_z) +                                                          \
	      2 * (err_gamma(2) * (max_x) * (max_y) + err_gamma(5) * ((max_y) + (max_z)) * (max_x) +       \
	           err_gamma(5) * ((max_x) + (max_z)) * (max_y)) * (max_z) +                               \
	      err_gamma(3) * (max_z) * (max_e)) * (abs_inv))

/* Each test reports a hit with 0 < t < h->t by updating h; true when it did. */
bool ray_sphere(const struct sphere *s, const struct ray *r, struct hit *h);
bool ray_plane(const struct plane *pl, const struct ray *r, struct hit *h);
/* triangle tri of sc */
bool ray_triangle(const struct scene *sc, uint32_t tri, const struct ray *r, struct hit *h);

/* A ray as the watertight triangle test takes it (Woop et al. section 3): the axes
 * permuted so that z is the direction's largest and the shear that turns the ray into
 * the +z axis, worked out once a ray rather than once a triangle (three divisions, and
 * branches that incoherent rays mispredict). */
struct tri_ray {
	struct vec3 o;
	int k[3];                      /* the permutation: x, y, z are axes k[0], k[1], k[2] */
	double sx, sy, sz;
};
void tri_ray_init(const struct ray *r, struct tri_ray *tr);
/* tri_ray_init() where sc has triangles, the only case where tr is read */
static inline void tri_ray_for(const struct scene *sc, const struct ray *r, struct tri_ray *tr)
{
	if (sc->ntriangles)
		tri_ray_init(r, tr);
}
/* ray_triangle() of the ray tr was made from */
bool tri_ray_hit(const struct tri_ray *tr, const struct scene *sc, uint32_t tri, struct hit *h);

/* Every t in (0, tmax) at which r crosses the sphere (0, 1 or 2 values); for the
 * shadow filter, which counts each crossing. */
int ray_sphere_crossings(const struct sphere *s, const struct ray *r, double tmax, double t[2]);

/* The id of the i-th sphere or triangle of sc, spheres first: the order accelerators
 * number them in while they build. */
static inline uint32_t nth_prim(const struct scene *sc, size_t i)
{
	return i < sc->nspheres ? prim_id(PRIM_SPHERE, (uint32_t)i)
	                        : prim_id(PRIM_TRIANGLE, (uint32_t)(i - sc->nspheres));
}

/* The bounds of a sphere (centre -+ radius) or triangle (its vertices' least and greatest
 * coordinates) by id, in double; a sphere's are rounded, so an accelerator widens them
 * outward. */
void prim_bounds(const struct scene *sc, uint32_t prim, struct vec3 *lo, struct vec3 *hi);

/* The closest-hit test of one sphere or triangle by id; sets h->prim when it hits. tr:
 * r made by tri_ray_init(), wherever the scene has triangles. */
static inline bool prim_intersect(const struct scene *sc, uint32_t prim, const struct ray *r,
                                  const struct tri_ray *tr, struct hit *h)
{
	uint32_t i = prim_index(prim);
	bool hit = prim_kind(prim) == PRIM_SPHERE ? ray_sphere(&sc->spheres[i], r, h)
	                                          : tri_ray_hit(tr, sc, i, h);
	if (hit)
		h->prim = prim;
	return hit;
}

static inline struct vec3 transmit_of(const struct scene *sc, uint32_t surface)
{
	return sc->materials[sc->surfaces[surface].material].transmit;
}

/* pass times the k_t of one sphere or triangle (by id) for each time r crosses it in
 * (0, tmax): the shadow filter's step. tr as for prim_intersect(). */
static inline struct vec3 prim_filter(const struct scene *sc, uint32_t prim, const struct ray *r,
                                      const struct tri_ray *tr, double tmax, struct vec3 pass)
{
	uint32_t k = prim_index(prim);
	if (prim_kind(prim) == PRIM_SPHERE) {
		double t[2];
		int crossings = ray_sphere_crossings(&sc->spheres[k], r, tmax, t);
		for (int c = 0; c < crossings; c++)
			pass = vmul(pass, transmit_of(sc, sc->spheres[k].surface));
	} else {
		struct hit h = { .t = tmax };
		if (tri_ray_hit(tr, sc, k, &h))
			pass = vmul(pass, transmit_of(sc, sc->triangles[k].surface));
	}
	return pass;
}

/* The planes, which no accelerator holds: the closest hit among them (updating h, true
 * when one is closer), and their shadow filter over (0, tmax). */
bool planes_intersect(const struct scene *sc, const struct ray *r, struct hit *h);
struct vec3 planes_filter(const struct scene *sc, const struct ray *r, double tmax);

void surface_at(const struct scene *sc, const struct ray *r, const struct hit *h, struct surface_point *sp);

/* The origin for a ray leaving sp in direction w: moved off the surface by the hit
 * point's error bound, to the side w goes to, then one ulp further (pbrt's
 * OffsetRayOrigin). A ray from there cannot re-hit the surface at t > 0 by rounding. */
struct vec3 offset_origin(const struct surface_point *sp, struct vec3 w);

#endif
