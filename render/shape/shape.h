/* shape.h: the one entry to every kind of primitive: ids that name a primitive of any
 * kind, and by id its bounds, closest hit, shadow filter and surface, each handed to the
 * kind's own file (sphere.c, plane.c, triangle.c, and csg.c for the solids of part.h). */
#ifndef SCN_SHAPE_H
#define SCN_SHAPE_H

#include <stdbool.h>
#include <stdint.h>

#include "csg.h"
#include "geometry.h"

/* Shape ids: spheres, triangles, planes and solids (geometry.solids, or for an unbounded
 * one geometry.unbounded with SHAPE_UNBOUNDED set) share one number space, the kind in the
 * top bits (a solid's and a plane's set bit 31). */
#define SHAPE_KIND_SHIFT 30
enum shape_kind { SHAPE_SPHERE = 0, SHAPE_TRIANGLE = 1, SHAPE_SOLID = 2, SHAPE_PLANE = 3 };
#define SHAPE_UNBOUNDED (1u << 29)
static inline uint32_t shape_id(enum shape_kind k, uint32_t index) { return (uint32_t)k << SHAPE_KIND_SHIFT | index; }
static inline enum shape_kind shape_kind(uint32_t id) { return (enum shape_kind)(id >> SHAPE_KIND_SHIFT); }
static inline uint32_t shape_index(uint32_t id) { return id & ((1u << SHAPE_KIND_SHIFT) - 1); }

/* The primitives the accelerators hold: spheres, triangles and bounded solids. */
static inline size_t shape_count(const struct geometry *g)
{
	return g->nspheres + g->ntriangles + g->nsolids;
}

/* The id of the i-th of them, spheres first, then triangles, then solids: the order
 * accelerators number them in while they build. */
static inline uint32_t shape_nth(const struct geometry *g, size_t i)
{
	if (i < g->nspheres)
		return shape_id(SHAPE_SPHERE, (uint32_t)i);
	i -= g->nspheres;
	return i < g->ntriangles ? shape_id(SHAPE_TRIANGLE, (uint32_t)i)
	                         : shape_id(SHAPE_SOLID, (uint32_t)(i - g->ntriangles));
}

/* The root part of a solid by id. */
static inline uint32_t shape_solid_root(const struct geometry *g, uint32_t id)
{
	uint32_t i = shape_index(id);
	return i & SHAPE_UNBOUNDED ? g->unbounded[i & ~SHAPE_UNBOUNDED] : g->solids[i];
}

/* The closest visible surface of a solid by id with 0 < t < h->t: updates h, h->part
 * included; true when there is one. */
bool shape_solid_intersect(const struct geometry *g, uint32_t id, const struct ray *r, struct hit *h);
/* pass times the k_t of every visible surface of a solid by id that r crosses in (0, tmax). */
struct vec3 shape_solid_filter(const struct geometry *g, uint32_t id, const struct ray *r, double tmax,
                               struct vec3 pass);

/* The bounds of a sphere, triangle or solid by id, in double; a sphere's are rounded, so
 * an accelerator widens them outward. */
void shape_bounds(const struct geometry *g, uint32_t id, struct vec3 *lo, struct vec3 *hi);

/* Whether a ray leaving the surface of primitive id by the side its geometric normal
 * points to can never meet it again: the surface bounds a convex body or is flat (a
 * sphere, a triangle, a plane, a solid of one sphere, box, disc, or closed cone or
 * cylinder, not inverted). */
bool shape_convex(const struct geometry *g, uint32_t id);

/* triangle_ray_init() where g has triangles, the only case where tr is read. */
static inline void shape_triangle_ray(const struct geometry *g, const struct ray *r, struct triangle_ray *tr)
{
	if (g->ntriangles)
		triangle_ray_init(r, tr);
}

/* The closest-hit test of one sphere, triangle or solid by id: a hit with 0 < t < h->t updates
 * h, h->prim included; true when it did. tr: r made by shape_triangle_ray(). */
static inline bool shape_intersect(const struct geometry *g, uint32_t id, const struct ray *r,
                                   const struct triangle_ray *tr, struct hit *h)
{
	uint32_t i = shape_index(id);
	bool hit;
	switch (shape_kind(id)) {
	case SHAPE_SPHERE:
		hit = sphere_intersect(&g->spheres[i], r, h);
		break;
	case SHAPE_TRIANGLE:
		hit = triangle_intersect(tr, &g->triangles[i], g->vertices, h);
		break;
	default:
		return shape_solid_intersect(g, id, r, h);
	}
	if (hit)
		h->prim = id;
	return hit;
}

/* The k_t of a surface: what the shadow filter multiplies by at each crossing. */
static inline struct vec3 shape_transmit(const struct geometry *g, uint32_t surface)
{
	return g->transmit[g->surfaces[surface].material];
}

/* pass times the k_t of one sphere, triangle or solid (by id) for each time r crosses it in
 * (0, tmax): the shadow filter's step. tr as for shape_intersect(). */
static inline struct vec3 shape_filter(const struct geometry *g, uint32_t id, const struct ray *r,
                                       const struct triangle_ray *tr, double tmax, struct vec3 pass)
{
	uint32_t k = shape_index(id);
	if (shape_kind(id) == SHAPE_SOLID)
		return shape_solid_filter(g, id, r, tmax, pass);
	if (shape_kind(id) == SHAPE_SPHERE) {
		double t[2];
		int crossings = sphere_crossings(&g->spheres[k], r, tmax, t);
		for (int c = 0; c < crossings; c++)
			pass = vmul(pass, shape_transmit(g, g->spheres[k].surface));
	} else {
		struct hit h = { .t = tmax };
		if (triangle_intersect(tr, &g->triangles[k], g->vertices, &h))
			pass = vmul(pass, shape_transmit(g, g->triangles[k].surface));
	}
	return pass;
}

/* The planes and unbounded solids, which no accelerator holds: the closest hit among them
 * (updating h, true when one is closer), and their shadow filter over (0, tmax). */
bool shape_planes_intersect(const struct geometry *g, const struct ray *r, struct hit *h);
struct vec3 shape_planes_filter(const struct geometry *g, const struct ray *r, double tmax);

/* The surface where r hits h->prim at h->t. */
void shape_surface_at(const struct geometry *g, const struct ray *r, const struct hit *h, struct surface_point *sp);
/* Where shadow rays from sp, the surface at hit h, start: sp itself, but on a smooth
 * triangle lifted to the curved surface its shading normals describe (triangle_lift);
 * side is 1 when the rays leave by the side the shading normal points to, -1 if not. */
void shape_shadow_point(const struct geometry *g, const struct hit *h, double side, struct surface_point *sp);

/* What the surface at hit h is made of: its index in g->surfaces. */
static inline uint32_t shape_surface(const struct geometry *g, const struct hit *h)
{
	uint32_t i = shape_index(h->prim);
	switch (shape_kind(h->prim)) {
	case SHAPE_SPHERE: return g->spheres[i].surface;
	case SHAPE_TRIANGLE: return g->triangles[i].surface;
	case SHAPE_PLANE: return g->planes[i].surface;
	default: return g->parts[h->part].surface;
	}
}

#endif
