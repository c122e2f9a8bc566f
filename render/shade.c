/* shade.c: a material's k_d and bumped shading normal at a hit: the hit point taken to the
 * object's own space (surface.to_object), then to the pattern's or image's own space; UV
 * coordinates from the primitive (a mesh's per-vertex ones, POV-Ray's uv_mapping of the
 * sphere and the torus) for `map uv`. */
#include "shade.h"

#include <math.h>

/* The hit point in the object's own space. */
static struct vec3 object_point(const struct scene *sc, const struct surface *srf, struct vec3 p)
{
	return srf->to_object >= 0 ? affine_point(&sc->affines[srf->to_object], p) : p;
}

/* The UV coordinates at hit h, as the point (u, v, 0). Lowering lets `map uv` reach only
 * spheres, tori and triangles with UVs; anything else reads (0, 0). */
static struct vec3 hit_uv(const struct scene *sc, const struct surface *srf, const struct hit *h,
                          const struct surface_point *sp)
{
	const struct geometry *g = &sc->geo;
	uint32_t i = shape_index(h->prim);
	double u = 0, v = 0;
	switch (shape_kind(h->prim)) {
	case SHAPE_SPHERE: {
		/* about the centre, turned as the object is */
		struct vec3 d = vsub(sp->p, g->spheres[i].center);
		if (srf->to_object >= 0)
			d = affine_vector(&sc->affines[srf->to_object], d);
		texture_uv_sphere(d, &u, &v);
		break;
	}
	case SHAPE_TRIANGLE: {
		if (!g->uvs)
			break;
		const struct triangle *t = &g->triangles[i];
		const struct uv *a = &g->uvs[t->v[0]], *b = &g->uvs[t->v[1]], *c = &g->uvs[t->v[2]];
		double w0 = 1 - h->b1 - h->b2;
		u = w0 * a->u + h->b1 * b->u + h->b2 * c->u;
		v = w0 * a->v + h->b1 * b->v + h->b2 * c->v;
		break;
	}
	case SHAPE_PLANE:
		break;
	default: {
		/* a solid's leaf, in its canonical space: the unit sphere, or the torus about y */
		const struct part *p = &g->parts[h->part];
		struct vec3 q = p->moved ? affine_point(&p->to_object, sp->p) : sp->p;
		if (p->kind == PART_SPHERE)
			texture_uv_sphere(q, &u, &v);
		else if (p->kind == PART_TORUS)
			texture_uv_torus(q, p->a[0], &u, &v);
		break;
	}
	}
	return v3(u, v, 0);
}

struct vec3 shade_diffuse(const struct scene *sc, const struct surface *srf, const struct material *m,
                          const struct hit *h, const struct surface_point *sp)
{
	switch (m->pigment) {
	case MATERIAL_CHECKER: {
		/* POV-Ray's 1e-10 bias: points a rounding error below a cell boundary count as
		 * above it */
		struct vec3 p = object_point(sc, srf, sp->p);
		double s = m->checker_size;
		double sum = floor(p.x / s + 1e-10) + floor(p.y / s + 1e-10) + floor(p.z / s + 1e-10);
		return fmod(sum, 2) == 0 ? m->diffuse : m->diffuse2;
	}
	case MATERIAL_PATTERN: {
		const struct pattern *pt = &sc->patterns[m->texture];
		struct vec3 q = object_point(sc, srf, sp->p);
		if (pt->moved)
			q = affine_point(&pt->to_pattern, q);
		return pattern_map(pt, pattern_value(pt, q));
	}
	case MATERIAL_IMAGE: {
		const struct image_map *im = &sc->image_maps[m->texture];
		struct vec3 q = im->map == TEXTURE_MAP_UV ? hit_uv(sc, srf, h, sp) : object_point(sc, srf, sp->p);
		if (im->moved)
			q = affine_point(&im->to_pattern, q);
		struct vec3 c;
		return image_map_lookup(im, q, &c) ? c : m->diffuse;
	}
	default:
		return m->diffuse;
	}
}

struct vec3 shade_bump(const struct scene *sc, const struct surface *srf, const struct material *m, struct vec3 p,
                       struct vec3 ns)
{
	/* POV-Ray's rule: the normal goes into the pattern's space through the object's and
	 * the pattern's own maps together, is bumped there and comes back */
	const struct pattern *pt = &sc->patterns[m->bump];
	struct affine to = srf->to_object >= 0 ? affine_compose(&pt->to_pattern, &sc->affines[srf->to_object])
	                                       : pt->to_pattern;
	return pattern_bump_normal(pt, &to, affine_point(&to, p), ns);
}
