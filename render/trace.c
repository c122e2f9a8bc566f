/* trace.c: the Whitted integrator of LANGUAGE.md ("Shading"): emission, Blinn-Phong
 * from each light through filtered hard shadows, mirror reflection, refraction with
 * POV-Ray's total internal reflection rule and optional Fresnel split, and the sky; k_d
 * and the bent shading normal of a textured material come from shade.c. A ray is spawned
 * only for a term whose weight is not zero, and a texture is looked up only for a material
 * that has one. POV-Ray's constant fog, when the scene has one, veils every segment a
 * followed ray travels through the open. */
#include "trace.h"

#include <math.h>

#include "accel.h"
#include "light.h"
#include "shade.h"

struct vec3 trace_sky(const struct sky *sky, struct vec3 d)
{
	switch (sky->kind) {
	case SKY_BLACK:
		return v3s(0);
	case SKY_CONSTANT:
		return sky->color;
	case SKY_ZENITH_HORIZON: {
		double t = d.y < 0 ? 0 : d.y > 1 ? 1 : d.y;
		return vadd(vscale(sky->horizon, 1 - t), vscale(sky->color, t));
	}
	case SKY_LATLONG: {
		/* POV-Ray's spherical map_type 1 with interpolate 2 (povray-equivalence.md
		 * section 9): rotate, then u from atan2(z, x), w from asin(y); bilinear between
		 * texel centres, wrapping both ways */
		double x = d.x * sky->rot_cos - d.z * sky->rot_sin;
		double z = d.x * sky->rot_sin + d.z * sky->rot_cos;
		double y = d.y < -1 ? -1 : d.y > 1 ? 1 : d.y;
		double u = atan2(z, x) / (2 * M_PI);
		u -= floor(u);
		double w = 0.5 - asin(y) / M_PI;
		int W = sky->width, H = sky->height;
		double fx = u * W - 0.5, fy = w * H - 0.5;
		double x0 = floor(fx), y0 = floor(fy);
		double ax = fx - x0, ay = fy - y0;
		long ix0 = (long)x0, iy0 = (long)y0;
		struct vec3 acc = v3s(0);
		for (int k = 0; k < 4; k++) {
			long ix = ix0 + (k & 1), iy = iy0 + (k >> 1);
			ix = ((ix % W) + W) % W;
			iy = ((iy % H) + H) % H;
			const float *t = &sky->texels[3 * ((size_t)iy * (size_t)W + (size_t)ix)];
			double wgt = ((k & 1) ? ax : 1 - ax) * ((k >> 1) ? ay : 1 - ay);
			acc = vadd(acc, vscale(v3(t[0], t[1], t[2]), wgt));
		}
		return vscale(acc, sky->intensity);
	}
	}
	return v3s(0);
}

/* Unpolarised dielectric reflectance for relative index eta = n_t / n_i at incidence
 * cosine c (the exact form POV-Ray uses); 1 past the critical angle. */
static double fresnel(double eta, double c)
{
	double g2 = eta * eta + c * c - 1;
	if (g2 < 0)
		return 1;
	double g = sqrt(g2);
	double a = (g - c) / (g + c);
	double b = (c * (g + c) - 1) / (c * (g - c) + 1);
	return 0.5 * a * a * (1 + b * b);
}

static bool any_positive(struct vec3 v)
{
	return v.x > 0 || v.y > 0 || v.z > 0;
}

/* An area light's tests share one walk of the tree when there are at least
 * AREA_SHARED_MIN of them and its pyramid meets at most AREA_LEAVES leaves; else each
 * walks the tree on its own. Measured on the headline's 1000 spheres under one jittered
 * area light (user time at -j 1, medians of alternating runs): the shared walk is 30%
 * faster for the whole render at 8 x 8 tests and 35% at 16 x 16, no faster at 4 x 4, and
 * 40% slower at 2 x 2, where the pyramid's walk costs more than the four walks it
 * replaces. Settling tests too changed nothing at 4 x 4 (the still life). */
enum { AREA_SHARED_MIN = 25, AREA_LEAVES = 32 };

/* Whether no plane (but self's own, which a ray leaving it never meets again) and no
 * unbounded solid can cross a segment inside the region with these vertices: each plane
 * has them all on one side, farther than margin. */
static bool open_beyond_planes(const struct geometry *geo, uint32_t self, const struct vec3 *vertex, int n,
                               double margin)
{
	if (geo->nunbounded)
		return false;
	for (size_t i = 0; i < geo->nplanes; i++) {
		if (shape_id(SHAPE_PLANE, (uint32_t)i) == self)
			continue;
		const struct plane *pl = &geo->planes[i];
		int above = 0, below = 0;
		for (int k = 0; k < n; k++) {
			double d = vdot(pl->normal, vertex[k]) - pl->offset;
			above += d > margin;
			below += d < -margin;
		}
		if (above != n && below != n)
			return false;
	}
	return true;
}

/* Whether the four corners of a light's extent lie in front of the surface at sp, farther
 * than margin: every test towards it leaves by the front. */
static bool in_front(const struct surface_point *sp, const struct vec3 corner[4], double margin)
{
	for (int k = 0; k < 4; k++)
		if (!(vdot(vsub(corner[k], sp->p), sp->ng) > margin))
			return false;
	return true;
}

/* Aims shadow (its origin set) at point q: a segment that ends just short of q, a relative
 * end, so that a light needs no tolerance (NUMERICS.md section 3). Its tmax; 0 or less,
 * with nothing set, when the origin is on q. */
static double aim_at(struct ray *shadow, struct vec3 q)
{
	struct vec3 to = vsub(q, shadow->o);
	double len = vlen(to), tmax = len * (1 - 1e-9);
	if (tmax > 0)
		shadow->d = vscale(to, 1 / len);
	return tmax;
}

enum { AREA_SETTLED = -2 };        /* share_walk: every test passes, without a ray */

/* How the tests of area light a (axes as seen from the point) from shadow_from, on
 * primitive self, whose origins are origin[0..1] (front, back), share their work: the
 * number of leaves they share into leaves (the leaves the pyramid from the point to the
 * light meets, which each test tries in place of its own walk of the tree); -1 when each
 * walks the tree alone; AREA_SETTLED when nothing can be in their way: no leaf holds a
 * primitive whose bounds meet the pyramid but the lit surface itself, where every test
 * leaves it by its front and it cannot be met again; the point is clear of the light's
 * plane (no test point on it); and no plane crosses the pyramid. The pyramid's margin
 * covers the tests' origins, moved off the point by at most its error bound (ray.h). */
static int share_walk(const struct scene *sc, const struct light *li, const struct area_light *a,
                      const struct vec3 axes[2], const struct surface_point *shadow_from, uint32_t self,
                      const struct vec3 origin[2], struct bvh_leaf leaves[AREA_LEAVES])
{
	if (!sc->accel.bvh || a->size[0] * a->size[1] < AREA_SHARED_MIN)
		return -1;
	const struct vec3 pe = shadow_from->p_err, p = shadow_from->p;
	double scale = fmax(fmax(fabs(p.x), fabs(p.y)), fmax(fabs(p.z), vlen(vsub(li->pos, p))));
	double margin = 1e-9 * scale + 4 * (pe.x + pe.y + pe.z);
	struct bvh_region region;
	struct vec3 vertex[6] = { origin[0], origin[1] };    /* then the extent's corners */
	if (!light_area_region(a, axes, li->pos, p, margin, &region, vertex + 2))
		return -1;
	int n = bvh_gather(sc->accel.bvh, &region, leaves, AREA_LEAVES);
	if (n < 0)
		return -1;
	/* not a triangle: a smooth one's tests start lifted off its plane (triangle_lift),
	 * from where they might meet it */
	uint32_t harmless = UINT32_MAX;
	if (shape_kind(self) != SHAPE_TRIANGLE && shape_convex(&sc->geo, self) &&
	    in_front(shadow_from, vertex + 2, margin))
		harmless = self;
	const double *far = region.plane[4];   /* the light's plane (light_area_region) */
	if (far[3] - (far[0] * p.x + far[1] * p.y + far[2] * p.z) > 4 * margin &&
	    bvh_leaves_clear(sc->accel.bvh, &sc->geo, leaves, n, &region, harmless) &&
	    open_beyond_planes(&sc->geo, self, vertex, 6, margin))
		return AREA_SETTLED;
	return n;
}

/* The light reaching a surface point from the test points of area light a (its centre at
 * li->pos, in unit direction l from the point), as POV-Ray's weighted average of them:
 * each a shadow test from shadow_from (on primitive self) towards the point, a jittered
 * light placing it at random in its cell from the sample's stream. Tests whose weight is
 * 0 are skipped; tests that nothing can be in the way of pass without a ray, their sum
 * the weights' as lowering added them in the tests' order (the bits the rays would give). */
static struct vec3 area_visibility(const struct scene *sc, const struct light *li, const struct area_light *a,
                                   const struct surface_point *shadow_from, uint32_t self, struct vec3 l,
                                   uint64_t dim, const struct sample_stream *ss, struct ray_stats *st)
{
	struct vec3 axes[2];
	light_area_axes(a, l, axes);
	/* a test's origin depends only on the side of the surface it leaves by */
	struct vec3 origin[2] = { ray_offset_origin(shadow_from, shadow_from->ng),
		                  ray_offset_origin(shadow_from, vneg(shadow_from->ng)) };
	struct bvh_leaf leaves[AREA_LEAVES];
	int nleaves = share_walk(sc, li, a, axes, shadow_from, self, origin, leaves);
	if (nleaves == AREA_SETTLED) {
		st->area_settled += (uint64_t)a->tests;
		return v3s(a->weight_sum);
	}
	const struct vec3 p = shadow_from->p;
	struct stream_dim sd;
	if (a->jitter)
		stream_dim(ss, dim, &sd);
	struct vec3 sum = v3s(0);
	for (int u = 0; u < a->size[0]; u++)
		for (int v = 0; v < a->size[1]; v++) {
			double w = a->weight[0][u] * a->weight[1][v];
			if (!(w > 0))
				continue;
			double ju = u, jv = v;
			if (a->jitter) {
				double du, dv;
				stream_point(&sd, (uint32_t)(u * AREA_MAX + v), &du, &dv);
				ju += du - 0.5;
				jv += dv - 0.5;
			}
			struct vec3 q = vadd(li->pos, light_area_offset(a, axes, ju, jv));
			struct vec3 to = vsub(q, p);
			if (vzero(to))
				continue; /* a test point on the lit point: no direction, as a point light */
			struct ray shadow = { origin[vdot(to, shadow_from->ng) < 0], v3s(0) };
			double tmax = aim_at(&shadow, q);
			if (!(tmax > 0))
				continue;
			st->area_shadow++;
			struct vec3 pass = nleaves >= 0
			                           ? bvh_transmittance_among(sc->accel.bvh, &sc->geo, &shadow, tmax, leaves, nleaves)
			                           : accel_transmittance(&sc->accel, &sc->geo, &shadow, tmax);
			sum = vadd(sum, vscale(pass, w));
		}
	return sum;
}

/* Direct light at sp (on primitive self) from every light, seen along v with facing normal
 * n; the shadow rays start from shadow_from (shape_shadow_point). An area light is shaded once towards its
 * centre, the test points only weighing how much of it arrives (POV-Ray's model). */
static struct vec3 direct_light(const struct scene *sc, const struct surface_point *sp,
                                const struct surface_point *shadow_from, uint32_t self, struct vec3 n, struct vec3 v,
                                struct vec3 kd, const struct material *m, uint64_t path_key,
                                const struct sample_stream *ss, struct ray_stats *st)
{
	struct vec3 sum = v3s(0);
	for (size_t i = 0; i < sc->nlights; i++) {
		const struct light *li = &sc->lights[i];
		struct vec3 l;
		double dist = INFINITY;
		if (li->kind == LIGHT_POINT) {
			struct vec3 to = vsub(li->pos, sp->p);
			dist = vlen(to);
			if (dist == 0)
				continue; /* a light on the point itself has no direction */
			l = vscale(to, 1 / dist);
		} else {
			l = li->to_light;
		}
		double ndotl = vdot(n, l);
		if (!(ndotl > 0))
			continue;
		struct vec3 color = li->color;
		if (li->spot) {
			double f = light_spot(li, l);
			if (!(f > 0))
				continue;
			color = vscale(color, f);
		}
		if (li->fade_power > 0) /* lower.c keeps it 0 unless fade_distance > 0 */
			color = vscale(color, light_fade(li, dist));
		if (!li->shadowless && li->area >= 0) {
			/* each branch of the sample's tree of rays, and each light, draws apart */
			uint64_t dim = path_key * 0x100000001b3u + i;
			color = vmul(color, area_visibility(sc, li, &sc->area_lights[li->area], shadow_from, self, l, dim, ss, st));
			if (vzero(color))
				continue;
		} else if (!li->shadowless) {
			/* a segment from just off the surface to the light */
			struct ray shadow = { ray_offset_origin(shadow_from, l), l };
			double tmax = INFINITY;
			if (li->kind == LIGHT_POINT && !((tmax = aim_at(&shadow, li->pos)) > 0))
				continue;
			st->shadow++;
			color = vmul(color, accel_transmittance(&sc->accel, &sc->geo, &shadow, tmax));
			if (vzero(color))
				continue;
		}
		struct vec3 term = vscale(kd, ndotl);
		if (!li->shadowless && any_positive(m->specular)) {
			double ndoth = vdot(n, vnorm(vadd(l, v)));
			if (ndoth > 0)
				term = vadd(term, vscale(m->specular, pow(ndoth, m->shininess)));
		}
		sum = vadd(sum, vmul(color, term));
	}
	return sum;
}

/* The mirror direction of d about the shading normal n (facing d's origin). A shading
 * normal that is not the geometric one (interpolated, bumped) can send it below the
 * surface, whose geometric normal on d's side is raw: POV-Ray's rule (trace.cpp's
 * reflection fix) mirrors d about raw instead when the ray also lies behind n, and else
 * reflects it back above the surface across the geometric plane. */
static struct vec3 mirror_direction(struct vec3 d, struct vec3 n, struct vec3 raw)
{
	struct vec3 mirror = vsub(d, vscale(n, 2 * vdot(d, n)));
	double below = vdot(mirror, raw);
	if (below >= 0)
		return mirror;
	return vdot(mirror, n) < 0 ? vsub(d, vscale(raw, 2 * vdot(d, raw))) : vsub(mirror, vscale(raw, 2 * below));
}

/* c, seen across t along a ray inside `inside` solids: fogged only outside every one, as
 * POV-Ray's objects are not hollow. */
static inline struct vec3 veil(const struct scene *sc, struct vec3 c, double t, int inside)
{
	if (!(sc->fog.distance > 0) || inside)
		return c;
	double k = exp(-t / sc->fog.distance);   /* rays have unit directions: t is the distance */
	return vadd(vscale(c, k), vscale(sc->fog.color, 1 - k));
}

/* The path of a ray's child: its depth one more, in `inside` solids, and its branch
 * named apart from its parent's and its sibling's (branch 1 the mirror, 2 the refraction). */
static inline struct path child_path(struct path p, int inside, uint64_t branch)
{
	return (struct path){ p.depth + 1, inside, p.key * 3 + branch };
}

struct vec3 trace_ray(const struct scene *sc, const struct ray *r, struct path path, const struct sample_stream *ss,
                      struct ray_stats *st)
{
	int depth = path.depth, inside = path.inside;
	struct hit h = { .t = INFINITY };
	if (!accel_intersect(&sc->accel, &sc->geo, r, &h)) /* an escaping ray: the fog's colour, when fogged */
		return sc->fog.distance > 0 && !inside ? sc->fog.color : trace_sky(&sc->sky, r->d);
	struct surface_point sp;
	shape_surface_at(&sc->geo, r, &h, &sp);
	const struct surface *srf = &sc->geo.surfaces[shape_surface(&sc->geo, &h)];
	const struct material *m = &sc->materials[srf->material];

	/* the shading normal (bumped, if the material says so) turned towards the viewer, the
	 * side decided before the bump; inside or outside from the geometric normal */
	bool entering = vdot(r->d, sp.ng) < 0;
	bool back = vdot(sp.ns, r->d) > 0;
	struct vec3 ns = sp.ns;
	if (m->bump >= 0) {
		st->bumps++;
		ns = shade_bump(sc, srf, m, sp.p, sp.ns);
	}
	struct vec3 n = back ? vneg(ns) : ns;
	struct vec3 v = vneg(r->d);
	struct vec3 color = m->emit;
	if (sc->nlights) {
		struct surface_point shadow_from = sp;
		shape_shadow_point(&sc->geo, &h, back ? -1 : 1, &shadow_from);
		struct vec3 kd = m->diffuse;
		if (m->pigment != MATERIAL_COLOR) {
			st->patterns += m->pigment == MATERIAL_PATTERN;
			st->images += m->pigment == MATERIAL_IMAGE;
			kd = shade_diffuse(sc, srf, m, &h, &sp);
		}
		color = vadd(color, direct_light(sc, &sp, &shadow_from, h.prim, n, v, kd, m, path.key, ss, st));
	}
	if (depth >= sc->max_depth)
		return veil(sc, color, h.t, inside);

	struct vec3 kr = m->reflect, kt = m->transmit;
	double cos_i = vdot(v, n);
	if (cos_i > 1)
		cos_i = 1;
	struct vec3 raw = entering ? sp.ng : vneg(sp.ng);
	if (any_positive(kt) || m->fresnel) {
		double eta = entering ? 1 / m->ior : m->ior; /* n_i / n_t */
		double k = 1 - eta * eta * (1 - cos_i * cos_i);
		if (k < 0 && any_positive(kt)) {
			/* total internal reflection: POV-Ray traces the mirror ray with weight 1
			 * in place of both terms */
			struct vec3 mirror = mirror_direction(r->d, n, raw);
			struct ray rr = { ray_offset_origin(&sp, mirror), vnorm(mirror) };
			st->reflection++;
			return veil(sc, vadd(color, trace_ray(sc, &rr, child_path(path, inside, 1), ss, st)), h.t, inside);
		}
		if (m->fresnel) {
			double f = fresnel(1 / eta, cos_i);
			kt = vmul(vsub(v3s(1), vscale(kr, f)), kt);
			kr = vscale(kr, f);
		}
		if (any_positive(kt)) {
			struct vec3 w = vadd(vscale(r->d, eta), vscale(n, eta * cos_i - sqrt(k)));
			struct ray rt = { ray_offset_origin(&sp, w), vnorm(w) };
			st->refraction++;
			/* through the surface: into one more solid, or out of one */
			int next = entering ? inside + 1 : inside > 0 ? inside - 1 : 0;
			color = vadd(color, vmul(kt, trace_ray(sc, &rt, child_path(path, next, 2), ss, st)));
		}
	}
	if (any_positive(kr)) {
		struct vec3 mirror = mirror_direction(r->d, n, raw);
		struct ray rr = { ray_offset_origin(&sp, mirror), vnorm(mirror) };
		st->reflection++;
		color = vadd(color, vmul(kr, trace_ray(sc, &rr, child_path(path, inside, 1), ss, st)));
	}
	return veil(sc, color, h.t, inside);
}

void trace_stats_add(struct ray_stats *to, const struct ray_stats *from)
{
	to->camera += from->camera;
	to->probe_camera += from->probe_camera;
	to->probe_pixels += from->probe_pixels;
	to->shadow += from->shadow;
	to->area_shadow += from->area_shadow;
	to->area_settled += from->area_settled;
	to->reflection += from->reflection;
	to->refraction += from->refraction;
	to->nonfinite += from->nonfinite;
	to->patterns += from->patterns;
	to->images += from->images;
	to->bumps += from->bumps;
}
