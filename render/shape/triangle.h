/* triangle.h: the triangle by the indices of its vertices, and the watertight ray test
 * (NUMERICS.md section 5), its bounds and surface; the four-lane packet test
 * (tri_packet.h) performs the same steps. */
#ifndef SCN_TRIANGLE_H
#define SCN_TRIANGLE_H

#include <stdbool.h>
#include <stdint.h>

#include "ray.h"
#include "rounding.h"

/* a triangle's n[] when it has no vertex normals: shaded flat */
#define TRIANGLE_FLAT UINT32_MAX

/* A triangle by the indices of its vertices. The BVH's traversal reads their positions
 * from its packets (tri_packet.h), four triangles' in one run of memory, which copy them;
 * everything else (hit points, bounds, the grid) goes through v[]. */
struct triangle {
	uint32_t v[3];                 /* into geometry.vertices */
	uint32_t n[3];                 /* into geometry.normals, or TRIANGLE_FLAT */
	uint32_t surface;              /* into geometry.surfaces */
};

/* A ray as the watertight triangle test takes it (Woop et al. section 3): the axes
 * permuted so that z is the direction's largest and the shear that turns the ray into
 * the +z axis, worked out once a ray rather than once a triangle (three divisions, and
 * branches that incoherent rays mispredict). */
struct triangle_ray {
	struct vec3 o;
	int k[3];                      /* the permutation: x, y, z are axes k[0], k[1], k[2] */
	double sx, sy, sz;
};
void triangle_ray_init(const struct ray *r, struct triangle_ray *tr);

/* Reports a hit of tri (its vertices in vertices[]) with 0 < t < h->t by updating h->t
 * and the barycentric h->b1, h->b2, for the ray tr was made from; true when it did. */
bool triangle_intersect(const struct triangle_ray *tr, const struct triangle *tri, const struct vec3 *vertices,
                        struct hit *h);
/* The same for r itself: triangle_ray_init() and triangle_intersect(), for one test of
 * one ray (an accelerator makes the triangle_ray once for all the triangles it tests). */
bool triangle_intersect_ray(const struct triangle *tri, const struct vec3 *vertices, const struct ray *r,
                            struct hit *h);

/* Two steps of the watertight test, written once for triangle_intersect() and for the
 * packet test (tri_packet.c), whose operands are doubles or vectors of four doubles: the
 * same operations in the same order give the same results.
 * TRIANGLE_T_OUTSIDE: t = tscaled / det lies outside (0, tmax), decided without the
 * division (limit = tmax * det), with | rather than || (one branch on the outcome rather
 * than one per comparison, which a ray that hits or misses at random mispredicts).
 * TRIANGLE_DELTA_T: pbrt-v3's bound on the rounding error of t, from the greatest
 * magnitudes of the transformed vertices' coordinates and of the edge functions, and
 * |1 / det|: 3 (g3 max_e max_z + delta_e max_z + delta_z max_e) |1 / det|, where
 * delta_z = g3 max_z, delta_x = g5 (max_x + max_z), delta_y = g5 (max_y + max_z) and
 * delta_e = 2 (g2 max_x max_y + delta_y max_x + delta_x max_y), gN = rounding_gamma(N). */
#define TRIANGLE_T_OUTSIDE(det, tscaled, limit, zero)                                                 \
	((((det) < (zero)) & (((tscaled) >= (zero)) | ((tscaled) < (limit)))) |                           \
	 (((det) > (zero)) & (((tscaled) <= (zero)) | ((tscaled) > (limit)))))
#define TRIANGLE_DELTA_T(max_x, max_y, max_z, max_e, abs_inv)                                         \
	(3 * (rounding_gamma(3) * (max_e) * (max_z) +                                                     \
	      2 * (rounding_gamma(2) * (max_x) * (max_y) + rounding_gamma(5) * ((max_y) + (max_z)) * (max_x) + \
	           rounding_gamma(5) * ((max_x) + (max_z)) * (max_y)) * (max_z) +                          \
	      rounding_gamma(3) * (max_z) * (max_e)) * (abs_inv))

/* Its vertices' least and greatest coordinates. */
void triangle_bounds(const struct triangle *tri, const struct vec3 *vertices, struct vec3 *lo, struct vec3 *hi);
/* The surface at the hit h of tri: the point from the barycentric weights, the normal
 * interpolated from normals[] unless tri is flat. */
void triangle_surface(const struct triangle *tri, const struct vec3 *vertices, const struct vec3 *normals,
                      const struct hit *h, struct surface_point *sp);
/* Moves sp->p, the hit h of the smooth tri, onto the curved surface its vertex normals
 * describe, as the start of shadow rays (Hanika, "Hacking the shadow terminator", Ray
 * Tracing Gems II, ch. 4): the barycentric blend of the point's projections onto the
 * tangent planes of the three vertices, each only where the point lies below that plane.
 * side (1 or -1) turns the normals to the side the rays leave by. Leaves sp alone where
 * no plane is above it, so that flat-looking regions start where they did. */
void triangle_lift(const struct triangle *tri, const struct vec3 *vertices, const struct vec3 *normals,
                   const struct hit *h, double side, struct surface_point *sp);

#endif
