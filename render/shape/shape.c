/* shape.c: the dispatch by shape id (shape.h) that is not inline: bounds, surfaces, the
 * solids, and the planes and unbounded solids, which every ray tests beside the
 * accelerator. */
#include "shape.h"

void shape_bounds(const struct geometry *g, uint32_t id, struct vec3 *lo, struct vec3 *hi)
{
	uint32_t i = shape_index(id);
	switch (shape_kind(id)) {
	case SHAPE_SPHERE:
		sphere_bounds(&g->spheres[i], lo, hi);
		break;
	case SHAPE_TRIANGLE:
		triangle_bounds(&g->triangles[i], g->vertices, lo, hi);
		break;
	default: {
		const struct part *p = &g->parts[shape_solid_root(g, id)];
		*lo = p->lo;
		*hi = p->hi;
	}
	}
}

bool shape_convex(const struct geometry *g, uint32_t id)
{
	switch (shape_kind(id)) {
	case SHAPE_SPHERE:
	case SHAPE_TRIANGLE:
	case SHAPE_PLANE:
		return true;
	default: {
		if (shape_index(id) & SHAPE_UNBOUNDED)
			return false;
		const struct part *p = &g->parts[shape_solid_root(g, id)];
		return !p->inverse && (p->kind == PART_SPHERE || p->kind == PART_BOX || p->kind == PART_DISC ||
		                       (p->kind == PART_CONE && !p->open));
	}
	}
}

bool shape_solid_intersect(const struct geometry *g, uint32_t id, const struct ray *r, struct hit *h)
{
	struct csg_hit c;
	if (!csg_next(g, shape_solid_root(g, id), r, 0, h->t, &c))
		return false;
	h->t = c.t;
	h->prim = id;
	h->part = c.leaf;
	return true;
}

struct vec3 shape_solid_filter(const struct geometry *g, uint32_t id, const struct ray *r, double tmax,
                               struct vec3 pass)
{
	uint32_t root = shape_solid_root(g, id);
	struct csg_hit c;
	for (double t0 = 0; !vzero(pass) && csg_next(g, root, r, t0, tmax, &c); t0 = c.t)
		pass = vmul(pass, shape_transmit(g, g->parts[c.leaf].surface));
	return pass;
}

void shape_surface_at(const struct geometry *g, const struct ray *r, const struct hit *h, struct surface_point *sp)
{
	uint32_t i = shape_index(h->prim);
	switch (shape_kind(h->prim)) {
	case SHAPE_SPHERE:
		sphere_surface(&g->spheres[i], r, h, sp);
		break;
	case SHAPE_PLANE:
		plane_surface(&g->planes[i], r, h, sp);
		break;
	case SHAPE_TRIANGLE:
		triangle_surface(&g->triangles[i], g->vertices, g->normals, h, sp);
		break;
	case SHAPE_SOLID:
		csg_surface(g, h->part, r, h->t, sp);
		break;
	}
}

void shape_shadow_point(const struct geometry *g, const struct hit *h, double side, struct surface_point *sp)
{
	if (shape_kind(h->prim) != SHAPE_TRIANGLE)
		return;
	const struct triangle *tri = &g->triangles[shape_index(h->prim)];
	if (tri->n[0] != TRIANGLE_FLAT)
		triangle_lift(tri, g->vertices, g->normals, h, side, sp);
}

bool shape_planes_intersect(const struct geometry *g, const struct ray *r, struct hit *h)
{
	bool hit = false;
	for (size_t i = 0; i < g->nplanes; i++)
		if (plane_intersect(&g->planes[i], r, h)) {
			h->prim = shape_id(SHAPE_PLANE, (uint32_t)i);
			hit = true;
		}
	for (size_t i = 0; i < g->nunbounded; i++)
		hit |= shape_solid_intersect(g, shape_id(SHAPE_SOLID, SHAPE_UNBOUNDED | (uint32_t)i), r, h);
	return hit;
}

struct vec3 shape_planes_filter(const struct geometry *g, const struct ray *r, double tmax)
{
	struct vec3 pass = v3s(1);
	for (size_t i = 0; i < g->nplanes; i++) {
		struct hit h = { .t = tmax };
		if (plane_intersect(&g->planes[i], r, &h)) {
			pass = vmul(pass, shape_transmit(g, g->planes[i].surface));
			if (vzero(pass))
				return pass;
		}
	}
	for (size_t i = 0; i < g->nunbounded && !vzero(pass); i++)
		pass = shape_solid_filter(g, shape_id(SHAPE_SOLID, SHAPE_UNBOUNDED | (uint32_t)i), r, tmax, pass);
	return pass;
}
