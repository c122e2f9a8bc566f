/* test_bvh.c: the BVH (render/accel/bvh_*.c) against brute force. Random scenes are built
 * directly as struct scene: spheres of random radii down to 1e-6, random triangles
 * including long thin ones, fans and grids that share edges and vertices, and planes.
 * For many rays (origins inside and outside the scene, on box faces and on vertices;
 * random, axis-aligned and +0/-0 directions) these answers must agree:
 *   ref   a plain loop over every primitive, with no bounding box at all;
 *   none  bvh_build(one_leaf): one leaf, through the traversal code;
 *   bvh   bvh_build();
 *   grid  grid_build (render/accel/grid.c), walked cell by cell.
 * And one more must be bvh's to the bit (same_answer): the same tree over a copy of the
 * scene reordered by bvh_reorder, whose triangle leaves are packets tested four at once.
 *
 * Same t, bitwise or within a few ulps? Each primitive's t is a pure function of the
 * primitive and the ray, and the closest hit is a minimum over those values, which
 * involves no arithmetic; the BVH (or grid) changes only the order of the tests and which
 * primitives get tested. So when one primitive is closest by a clear margin all three
 * agree bitwise, and the test demands it. Order can matter only between candidates a
 * few ulps apart: triangle_intersect's early-out compares tscaled against h->t * det, rounded
 * differently from t = tscaled / det, and a box's entry distance is compared against
 * h->t with its own rounding. So two answers may differ only when both name different
 * primitives, each of which alone really is hit at the t reported, and those t are
 * within NEAR_ULPS ulps of each other (seen: 1 ulp, at edges shared by two triangles,
 * each of which rounds its own t); TEST_BVH_VERBOSE=1 prints them. Exact ties (shared
 * vertices, coincident primitives) may name different primitives with the same t.
 *
 * Transmittance: each channel is a product of the k_t of the crossed surfaces. The x
 * and y channels use only powers of two, so every product is exact and must agree
 * bitwise in any order; the z channel uses other values and agrees to rounding. */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bvh.h"
#include "check.h"
#include "grid.h"
#include "scene.h"
#include "shape.h"
#include "xalloc.h"

#include "random.h"

#define NEAR_ULPS 4
#define PI 3.14159265358979323846

static struct vec3 rand_in_box(struct vec3 lo, struct vec3 hi)
{
	return v3(urange(lo.x, hi.x), urange(lo.y, hi.y), urange(lo.z, hi.z));
}

/* ---- building scenes ---- */

enum { NMAT = 6 };
/* x, y: powers of two (exact products); z: anything */
static const double transmit_of_mat[NMAT][3] = {
	{ 0, 0, 0 }, { 1, 1, 1 }, { 0.5, 0.25, 0.3 }, { 0.25, 1, 0.7 }, { 0.5, 0.5, 0.9 }, { 1, 0.5, 0.1 },
};

struct builder {
	struct scene sc;
	size_t cap_s, cap_t, cap_v, cap_p;
};

static void builder_init(struct builder *b)
{
	memset(b, 0, sizeof *b);
	b->sc.materials = xcalloc(NMAT, sizeof *b->sc.materials);
	b->sc.geo.surfaces = xcalloc(NMAT, sizeof *b->sc.geo.surfaces);
	b->sc.geo.transmit = xcalloc(NMAT, sizeof *b->sc.geo.transmit);
	b->sc.nmaterials = b->sc.geo.nsurfaces = b->sc.geo.ntransmit = NMAT;
	for (int i = 0; i < NMAT; i++) {
		b->sc.materials[i].transmit = b->sc.geo.transmit[i] = v3a(transmit_of_mat[i]);
		b->sc.materials[i].diffuse = v3s(0.8);
		b->sc.materials[i].ior = 1;
		b->sc.geo.surfaces[i] = (struct surface){ (uint32_t)i, -1 };
	}
	b->sc.max_depth = 5;
}

/* mostly see-through, so that the shadow filter crosses many surfaces */
static uint32_t rand_surface(void)
{
	return irand(8) == 0 ? 0 : (uint32_t)(1 + irand(NMAT - 1));
}

static void add_sphere(struct builder *b, struct vec3 c, double r)
{
	xgrow((void **)&b->sc.geo.spheres, &b->cap_s, b->sc.geo.nspheres + 1, sizeof *b->sc.geo.spheres);
	b->sc.geo.spheres[b->sc.geo.nspheres++] = (struct sphere){ c, r, rand_surface() };
}

static uint32_t add_vertex(struct builder *b, struct vec3 v)
{
	xgrow((void **)&b->sc.geo.vertices, &b->cap_v, b->sc.geo.nvertices + 1, sizeof *b->sc.geo.vertices);
	b->sc.geo.vertices[b->sc.geo.nvertices] = v;
	return (uint32_t)b->sc.geo.nvertices++;
}

static void add_tri_idx(struct builder *b, uint32_t i, uint32_t j, uint32_t k)
{
	xgrow((void **)&b->sc.geo.triangles, &b->cap_t, b->sc.geo.ntriangles + 1, sizeof *b->sc.geo.triangles);
	b->sc.geo.triangles[b->sc.geo.ntriangles++] =
		(struct triangle){ { i, j, k }, { TRIANGLE_FLAT, TRIANGLE_FLAT, TRIANGLE_FLAT }, rand_surface() };
}

static void add_triangle(struct builder *b, struct vec3 p0, struct vec3 p1, struct vec3 p2)
{
	uint32_t i = add_vertex(b, p0), j = add_vertex(b, p1), k = add_vertex(b, p2);
	add_tri_idx(b, i, j, k);
}

static void add_plane(struct builder *b, struct vec3 n, double offset)
{
	xgrow((void **)&b->sc.geo.planes, &b->cap_p, b->sc.geo.nplanes + 1, sizeof *b->sc.geo.planes);
	b->sc.geo.planes[b->sc.geo.nplanes++] = (struct plane){ vnorm(n), offset, rand_surface() };
}

static size_t nprims(const struct scene *sc)
{
	return sc->geo.nspheres + sc->geo.ntriangles;
}

/* A triangle fan of k triangles around a (raised) centre. */
static void add_fan(struct builder *b, struct vec3 c, double radius, int k)
{
	uint32_t ic = add_vertex(b, vadd(c, v3(0, radius * 0.3, 0)));
	uint32_t first = 0, prev = 0;
	for (int i = 0; i < k; i++) {
		double a = 2 * PI * i / k;
		uint32_t iv = add_vertex(b, vadd(c, v3(radius * cos(a), 0, radius * sin(a))));
		if (i == 0)
			first = iv;
		else
			add_tri_idx(b, ic, prev, iv);
		prev = iv;
	}
	add_tri_idx(b, ic, prev, first);
}

/* An n x n grid of quads, each split in two, with random heights: shared edges. */
static void add_grid(struct builder *b, struct vec3 origin, double cell, int n, bool lattice)
{
	uint32_t base = (uint32_t)b->sc.geo.nvertices;
	for (int j = 0; j <= n; j++)
		for (int i = 0; i <= n; i++) {
			double h = lattice ? (double)irand(3) * cell : urange(-0.3, 0.3) * cell;
			add_vertex(b, vadd(origin, v3(i * cell, h, j * cell)));
		}
	for (int j = 0; j < n; j++)
		for (int i = 0; i < n; i++) {
			uint32_t v00 = base + (uint32_t)(j * (n + 1) + i), v10 = v00 + 1;
			uint32_t v01 = v00 + (uint32_t)(n + 1), v11 = v01 + 1;
			add_tri_idx(b, v00, v10, v11);
			add_tri_idx(b, v00, v11, v01);
		}
}

/* About n bounded primitives of every kind, around the origin within size, moved by
 * offset. lattice: every coordinate is a multiple of size / 8 and every radius of
 * size / 16, all exact in float, so that the boxes have faces exactly where ray
 * origins can be put. */
static void random_scene(struct builder *b, size_t n, double size, struct vec3 offset, bool lattice, int nplanes)
{
	builder_init(b);
	while (nprims(&b->sc) < n) {
		int kind = irand(10);
		size_t left = n - nprims(&b->sc);
		if (lattice) {
			struct vec3 p = v3(irand(17) - 8, irand(17) - 8, irand(17) - 8);
			p = vadd(vscale(p, size / 8), offset);
			if (kind < 3) {
				add_sphere(b, p, size / 16 * (1 + irand(4)));
			} else if (kind < 8 || left < 8) {
				struct vec3 q = vadd(p, vscale(v3(irand(9) - 4, irand(9) - 4, irand(9) - 4), size / 8));
				struct vec3 r = vadd(p, vscale(v3(irand(9) - 4, irand(9) - 4, irand(9) - 4), size / 8));
				struct vec3 e = vcross(vsub(q, p), vsub(r, p));
				if (!vzero(e))
					add_triangle(b, p, q, r);
			} else if (kind == 8 && left >= 8) {
				add_fan(b, p, size / 8 * 2, 8);
			} else {
				add_grid(b, p, size / 8, 2, true);
			}
			continue;
		}
		struct vec3 p = vadd(rand_in_box(v3s(-size), v3s(size)), offset);
		if (kind < 3) {
			/* radii from 1e-6 of the scene to a tenth of it */
			add_sphere(b, p, size * lrand(1e-6, 0.1));
		} else if (kind < 6 || left < 16) {
			double s = size * lrand(1e-4, 0.2);
			add_triangle(b, p, vadd(p, vscale(rand_unit(), s)), vadd(p, vscale(rand_unit(), s)));
		} else if (kind == 6) {
			/* long and thin: two vertices close together, the third far away */
			double s = size * lrand(1e-2, 1), w = s * lrand(1e-7, 1e-2);
			struct vec3 q = vadd(p, vscale(rand_unit(), w));
			add_triangle(b, p, q, vadd(p, vscale(rand_unit(), s)));
		} else if (kind == 7) {
			add_fan(b, p, size * lrand(1e-3, 0.1), 3 + irand(12));
		} else {
			int g = 1 + irand(left >= 128 ? 8 : 2);
			add_grid(b, p, size * lrand(1e-3, 0.05) / g, g, false);
		}
	}
	for (int i = 0; i < nplanes; i++) {
		struct vec3 nrm = rand_unit();
		add_plane(b, nrm, vdot(offset, nrm) + urange(-size, size));
	}
}

static void scene_bounds(const struct scene *sc, struct vec3 *lo, struct vec3 *hi)
{
	*lo = v3s(INFINITY);
	*hi = v3s(-INFINITY);
	for (size_t i = 0; i < sc->geo.nspheres; i++) {
		*lo = vmin(*lo, vsub(sc->geo.spheres[i].center, v3s(sc->geo.spheres[i].radius)));
		*hi = vmax(*hi, vadd(sc->geo.spheres[i].center, v3s(sc->geo.spheres[i].radius)));
	}
	for (size_t i = 0; i < sc->geo.nvertices; i++) {
		*lo = vmin(*lo, sc->geo.vertices[i]);
		*hi = vmax(*hi, sc->geo.vertices[i]);
	}
}

/* ---- the reference: every primitive, no boxes ---- */

static bool ref_intersect(const struct scene *sc, const struct ray *r, struct hit *h)
{
	bool hit = false;
	for (size_t i = 0; i < sc->geo.nplanes; i++)
		if (plane_intersect(&sc->geo.planes[i], r, h)) {
			h->prim = shape_id(SHAPE_PLANE, (uint32_t)i);
			hit = true;
		}
	for (size_t i = 0; i < sc->geo.nspheres; i++)
		if (sphere_intersect(&sc->geo.spheres[i], r, h)) {
			h->prim = shape_id(SHAPE_SPHERE, (uint32_t)i);
			hit = true;
		}
	for (size_t i = 0; i < sc->geo.ntriangles; i++)
		if (triangle_intersect_ray(&sc->geo.triangles[i], sc->geo.vertices, r, h)) {
			h->prim = shape_id(SHAPE_TRIANGLE, (uint32_t)i);
			hit = true;
		}
	return hit;
}

static struct vec3 kt_of(const struct scene *sc, uint32_t surface)
{
	return sc->materials[sc->geo.surfaces[surface].material].transmit;
}

static struct vec3 ref_transmittance(const struct scene *sc, const struct ray *r, double tmax)
{
	struct vec3 pass = v3s(1);
	for (size_t i = 0; i < sc->geo.nplanes; i++) {
		struct hit h = { .t = tmax };
		if (plane_intersect(&sc->geo.planes[i], r, &h))
			pass = vmul(pass, kt_of(sc, sc->geo.planes[i].surface));
	}
	for (size_t i = 0; i < sc->geo.nspheres; i++) {
		double t[2];
		int n = sphere_crossings(&sc->geo.spheres[i], r, tmax, t);
		for (int c = 0; c < n; c++)
			pass = vmul(pass, kt_of(sc, sc->geo.spheres[i].surface));
	}
	for (size_t i = 0; i < sc->geo.ntriangles; i++) {
		struct hit h = { .t = tmax };
		if (triangle_intersect_ray(&sc->geo.triangles[i], sc->geo.vertices, r, &h))
			pass = vmul(pass, kt_of(sc, sc->geo.triangles[i].surface));
	}
	return pass;
}

/* The t at which prim alone is hit (INFINITY: missed). */
static double alone_t(const struct scene *sc, uint32_t prim, const struct ray *r)
{
	struct hit h = { .t = INFINITY };
	uint32_t i = shape_index(prim);
	switch (shape_kind(prim)) {
	case SHAPE_SPHERE: sphere_intersect(&sc->geo.spheres[i], r, &h); break;
	case SHAPE_TRIANGLE: triangle_intersect_ray(&sc->geo.triangles[i], sc->geo.vertices, r, &h); break;
	case SHAPE_PLANE: plane_intersect(&sc->geo.planes[i], r, &h); break;
	}
	return h.t;
}

/* ---- comparison ---- */

struct tally {
	long rays, hits, ties, near, shadow, fail;
	int printed;
};

static void print_ray(const char *what, const struct ray *r, double tmax)
{
	fprintf(stderr, "  %s ray o = <%a, %a, %a> d = <%a, %a, %a> tmax %a\n", what, r->o.x, r->o.y, r->o.z, r->d.x,
	        r->d.y, r->d.z, tmax);
}

static double ulps_apart(double a, double b)
{
	double u = nextafter(fmax(fabs(a), fabs(b)), INFINITY) - fmax(fabs(a), fabs(b));
	return fabs(a - b) / u;
}

/* Do answer (fa, ha) and (fb, hb) agree, as the header explains? */
static bool agree(const struct scene *sc, const struct ray *r, double tmax, bool fa, const struct hit *ha, bool fb,
                  const struct hit *hb, struct tally *ty)
{
	if (fa != fb)
		return false;
	if (!fa)
		return ha->t == tmax && hb->t == tmax;
	if (ha->t == hb->t) {
		if (ha->prim != hb->prim) {
			if (alone_t(sc, ha->prim, r) != ha->t || alone_t(sc, hb->prim, r) != hb->t)
				return false;
			ty->ties++;
		}
		return true;
	}
	/* a near tie between two primitives, each really hit where it says */
	if (ha->prim == hb->prim || alone_t(sc, ha->prim, r) != ha->t || alone_t(sc, hb->prim, r) != hb->t ||
	    ulps_apart(ha->t, hb->t) > NEAR_ULPS)
		return false;
	if (ty->near++ < 3 && getenv("TEST_BVH_VERBOSE")) {
		fprintf(stderr, "near tie: prim %#x t %a vs prim %#x t %a (%g ulps)\n", ha->prim, ha->t, hb->prim, hb->t,
		        ulps_apart(ha->t, hb->t));
		print_ray("near tie", r, tmax);
	}
	return true;
}

/* The answers compared: the reference, then each accelerator. */
enum { REF, NONE, BVH, GRID, NANSWERS };
static const char *const names[NANSWERS] = { "ref", "none", "bvh", "grid" };

struct accels {
	struct bvh *none, *bvh;
	struct grid *grid;
};

static void accels_build(const struct scene *sc, struct accels *a)
{
	a->none = bvh_build(&sc->geo, true);
	a->bvh = bvh_build(&sc->geo, false);
	a->grid = grid_build(&sc->geo);
}

static void accels_free(struct accels *a)
{
	bvh_free(a->none);
	bvh_free(a->bvh);
	grid_free(a->grid);
}

static bool answer_hit(const struct accels *a, int k, const struct scene *sc, const struct ray *r, struct hit *h)
{
	switch (k) {
	case NONE: return bvh_intersect(a->none, &sc->geo, r, h);
	case BVH: return bvh_intersect(a->bvh, &sc->geo, r, h);
	case GRID: return grid_intersect(a->grid, &sc->geo, r, h);
	default: return ref_intersect(sc, r, h);
	}
}

static struct vec3 answer_filter(const struct accels *a, int k, const struct scene *sc, const struct ray *r,
                                 double tmax)
{
	switch (k) {
	case NONE: return bvh_transmittance(a->none, &sc->geo, r, tmax);
	case BVH: return bvh_transmittance(a->bvh, &sc->geo, r, tmax);
	case GRID: return grid_transmittance(a->grid, &sc->geo, r, tmax);
	default: return ref_transmittance(sc, r, tmax);
	}
}

static void compare_ray(const struct scene *sc, const struct accels *a, const struct ray *r, double tmax,
                        const char *what, struct tally *ty)
{
	struct hit h[NANSWERS];
	bool f[NANSWERS];
	for (int k = 0; k < NANSWERS; k++) {
		h[k] = (struct hit){ .t = tmax, .prim = UINT32_MAX };
		f[k] = answer_hit(a, k, sc, r, &h[k]);
	}
	ty->rays++;
	ty->hits += f[0];
	for (int k = 1; k < NANSWERS; k++)
		if (!agree(sc, r, tmax, f[0], &h[0], f[k], &h[k], ty)) {
			ty->fail++;
			if (ty->printed++ < 10) {
				fprintf(stderr, "%s: %s and %s differ: %s prim %#x t %a, %s prim %#x t %a\n", what, names[0],
				        names[k], f[0] ? "hit" : "miss", h[0].prim, h[0].t, f[k] ? "hit" : "miss", h[k].prim,
				        h[k].t);
				print_ray(what, r, tmax);
			}
		}

	/* the shadow filter, over the segment and over the whole ray */
	double ends[2] = { tmax, INFINITY };
	for (int e = 0; e < 2; e++) {
		struct vec3 t[NANSWERS];
		for (int k = 0; k < NANSWERS; k++)
			t[k] = answer_filter(a, k, sc, r, ends[e]);
		ty->shadow++;
		for (int k = 1; k < NANSWERS; k++) {
			bool ok = t[k].x == t[0].x && t[k].y == t[0].y && fabs(t[k].z - t[0].z) <= 1e-13 * t[0].z;
			if (!ok) {
				ty->fail++;
				if (ty->printed++ < 10) {
					fprintf(stderr, "%s: transmittance %s <%a, %a, %a> but %s <%a, %a, %a>\n", what, names[0],
					        t[0].x, t[0].y, t[0].z, names[k], t[k].x, t[k].y, t[k].z);
					print_ray(what, r, ends[e]);
				}
			}
		}
	}
}

/* A direction with some components zeroed, each to +0 or -0 at random. */
static struct vec3 signed_zero_dir(void)
{
	for (;;) {
		struct vec3 d = rand_unit();
		double *c[3] = { &d.x, &d.y, &d.z };
		int zeros = 1 + irand(2);
		for (int k = 0; k < zeros; k++)
			*c[irand(3)] = irand(2) ? 0.0 : -0.0;
		if (!vzero(d))
			return vnorm(d);
	}
}

static struct vec3 axis_dir(void)
{
	double v[3] = { irand(2) ? 0.0 : -0.0, irand(2) ? 0.0 : -0.0, irand(2) ? 0.0 : -0.0 };
	v[irand(3)] = irand(2) ? 1 : -1;
	return v3a(v);
}

/* A point of a random primitive (for rays that hit something). */
static struct vec3 point_on_prim(const struct scene *sc)
{
	size_t n = nprims(sc);
	size_t k = (size_t)(next_u64() % n);
	if (k < sc->geo.nspheres) {
		const struct sphere *s = &sc->geo.spheres[k];
		return irand(2) ? s->center : vadd(s->center, vscale(rand_unit(), s->radius * urand()));
	}
	const struct triangle *t = &sc->geo.triangles[k - sc->geo.nspheres];
	struct vec3 a = sc->geo.vertices[t->v[0]], b = sc->geo.vertices[t->v[1]], c = sc->geo.vertices[t->v[2]];
	switch (irand(4)) {
	case 0: return a; /* a vertex */
	case 1: return vadd(a, vscale(vsub(b, a), urand())); /* an edge */
	default: {
		double u = urand(), v = urand();
		if (u + v > 1)
			u = 1 - u, v = 1 - v;
		return vadd(a, vadd(vscale(vsub(b, a), u), vscale(vsub(c, a), v)));
	}
	}
}

/* A coordinate on the lattice of a lattice scene (spacing size / 8): where its boxes have faces. */
static double lattice_coord(double size, double offset)
{
	return offset + (irand(25) - 12) * size / 8;
}

/* bvh_shape's node count and depth, after checking the bound bvh_bytes relies on: over L
 * leaves there are at most L W / (2 (W - 1)) interior nodes of width W. */
static void shape_of(const struct bvh *b, size_t *nodes, int *depth)
{
	struct bvh_shape s = bvh_shape(b);
	size_t leaves = s.nodes - s.interior, w = BVH_WIDTH;
	CHECK(s.interior * 2 * (w - 1) <= leaves * w + 2 * (w - 1) - 1);
	*nodes = s.nodes;
	*depth = s.depth;
}

static void prim_geometry(const struct scene *sc, uint32_t prim, double g[9])
{
	memset(g, 0, 9 * sizeof *g);
	uint32_t i = shape_index(prim);
	if (shape_kind(prim) == SHAPE_SPHERE) {
		const struct sphere *s = &sc->geo.spheres[i];
		g[0] = s->center.x, g[1] = s->center.y, g[2] = s->center.z, g[3] = s->radius;
	} else if (shape_kind(prim) == SHAPE_TRIANGLE) {
		for (int k = 0; k < 3; k++) {
			struct vec3 v = sc->geo.vertices[sc->geo.triangles[i].v[k]];
			g[3 * k] = v.x, g[3 * k + 1] = v.y, g[3 * k + 2] = v.z;
		}
	}
}

/* An answer of one BVH, kept to compare with another's: the hit, the geometry of the
 * primitive hit, and the light through (0, tmax) and through the whole ray. */
struct answer {
	bool found;
	struct hit h;
	double geom[9];
	struct vec3 pass[2];
};

static void answer_of(const struct bvh *bvh, const struct scene *sc, const struct ray *r, double tmax,
                      struct answer *a)
{
	a->h = (struct hit){ .t = tmax, .prim = UINT32_MAX };
	a->found = bvh_intersect(bvh, &sc->geo, r, &a->h);
	prim_geometry(sc, a->h.prim, a->geom);
	a->pass[0] = bvh_transmittance(bvh, &sc->geo, r, tmax);
	a->pass[1] = bvh_transmittance(bvh, &sc->geo, r, INFINITY);
}

/* The same answer to the bit: the same geometry hit at the same t and barycentrics, the
 * same light through. For the same tree before and after bvh_reorder, which tests the
 * same primitives in the same order, the triangles of its leaves in packets whose test
 * is the scalar one's lane by lane. */
static bool same_answer(const struct answer *a, const struct answer *b)
{
	bool same = a->found == b->found && a->h.t == b->h.t;
	if (same && a->found)
		same = a->h.b1 == b->h.b1 && a->h.b2 == b->h.b2 && memcmp(a->geom, b->geom, sizeof a->geom) == 0;
	for (int e = 0; e < 2; e++)
		same = same && memcmp(&a->pass[e], &b->pass[e], sizeof a->pass[e]) == 0;
	return same;
}

/* A copy of sc reordered, with bvh_reorder, for its tree's leaves in packets: its own
 * spheres and triangles, the rest shared with sc. */
static struct bvh *reordered_copy(const struct scene *sc, struct scene *copy)
{
	*copy = *sc;
	copy->geo.spheres = xmalloc(sc->geo.nspheres * sizeof *copy->geo.spheres);
	copy->geo.triangles = xmalloc(sc->geo.ntriangles * sizeof *copy->geo.triangles);
	if (sc->geo.nspheres) /* memcpy from NULL is undefined, even of nothing */
		memcpy(copy->geo.spheres, sc->geo.spheres, sc->geo.nspheres * sizeof *copy->geo.spheres);
	if (sc->geo.ntriangles)
		memcpy(copy->geo.triangles, sc->geo.triangles, sc->geo.ntriangles * sizeof *copy->geo.triangles);
	struct bvh *bvh = bvh_build(&copy->geo, false);
	bvh_reorder(bvh, &copy->geo);
	return bvh;
}

/* Compares nrays random rays; at least min_hits of them (a fraction) must hit something,
 * or the comparison proves little. */
static void compare_scene(const struct scene *sc, long nrays, double min_hits, bool lattice, double size,
                          struct vec3 offset, const char *what)
{
	struct accels a;
	accels_build(sc, &a);
	struct scene copy;
	struct bvh *packed = reordered_copy(sc, &copy);
	long packed_bad = 0;
	size_t nodes;
	int depth;
	shape_of(a.bvh, &nodes, &depth);
	size_t n = nprims(sc);
	CHECK(depth <= 96);
	CHECK(n == 0 || nodes <= 2 * n - 1);
	shape_of(a.none, &nodes, &depth);
	CHECK(depth == 0 && nodes == (n > 0));
	int cells[3];
	size_t refs;
	grid_shape(a.grid, cells, &refs);
	CHECK(refs >= n);

	struct vec3 lo, hi;
	scene_bounds(sc, &lo, &hi);
	if (n == 0)
		lo = hi = offset;
	struct vec3 mid = vscale(vadd(lo, hi), 0.5);
	double extent = fmax(vmaxc(vsub(hi, lo)), size);
	struct tally ty = { 0 };
	for (long i = 0; i < nrays; i++) {
		struct ray r;
		/* origin */
		switch (irand(lattice ? 6 : 5)) {
		case 0: case 1: r.o = rand_in_box(lo, hi); break;                       /* inside */
		case 2: r.o = vadd(mid, vscale(rand_unit(), extent * urange(1, 4))); break; /* outside */
		case 3:                                                                   /* on a vertex */
			r.o = sc->geo.nvertices ? sc->geo.vertices[next_u64() % sc->geo.nvertices] : rand_in_box(lo, hi);
			break;
		case 4: r.o = n ? point_on_prim(sc) : mid; break;                         /* on a surface */
		default:                                                                  /* on box faces */
			r.o = v3(lattice_coord(size, offset.x), lattice_coord(size, offset.y), lattice_coord(size, offset.z));
			break;
		}
		/* direction */
		switch (irand(5)) {
		case 0: r.d = rand_unit(); break;
		case 1: r.d = signed_zero_dir(); break;
		case 2: r.d = axis_dir(); break;
		default: {
			struct vec3 to = n ? point_on_prim(sc) : rand_unit();
			struct vec3 d = vsub(to, r.o);
			if (lattice && irand(2)) { /* keep it in a face plane: zero a component */
				int k = irand(3);
				if (k == 0) d.x = irand(2) ? 0.0 : -0.0;
				else if (k == 1) d.y = irand(2) ? 0.0 : -0.0;
				else d.z = irand(2) ? 0.0 : -0.0;
			}
			r.d = vzero(d) ? rand_unit() : vnorm(d);
			break;
		}
		}
		double tmax = irand(3) ? INFINITY : extent * lrand(1e-3, 2);
		compare_ray(sc, &a, &r, tmax, what, &ty);
		struct answer before, after;
		answer_of(a.bvh, sc, &r, tmax, &before);
		answer_of(packed, &copy, &r, tmax, &after);
		if (!same_answer(&before, &after) && packed_bad++ < 5) {
			fprintf(stderr, "%s: the reordered tree, with packets, answers otherwise: prim %#x t %a, then %#x t %a\n",
			        what, before.h.prim, before.h.t, after.h.prim, after.h.t);
			print_ray(what, &r, tmax);
		}
	}
	CHECK(packed_bad == 0);
	bvh_free(packed);
	free(copy.geo.spheres);
	free(copy.geo.triangles);
	if (getenv("TEST_BVH_VERBOSE"))
		fprintf(stderr, "%s: %ld rays, %ld hits; %ld exact ties named different primitives, %ld near ties "
		        "(within %d ulps) differed\n", what, ty.rays, ty.hits, ty.ties, ty.near, NEAR_ULPS);
	if (ty.fail)
		fprintf(stderr, "%s: %ld of %ld comparisons failed\n", what, ty.fail, ty.rays * 3 * (NANSWERS - 1));
	CHECK(ty.fail == 0);
	if (!(ty.hits >= min_hits * (double)ty.rays))
		fprintf(stderr, "%s: only %ld of %ld rays hit\n", what, ty.hits, ty.rays);
	CHECK(ty.hits >= min_hits * (double)ty.rays);
	accels_free(&a);
}

/* ---- the tests ---- */

static void test_random_scenes(void)
{
	/* the last is big enough for the big trees' build and walk (BVH_BIG_TREE), with few
	 * rays: every one is tested against every primitive twice, by ref and none */
	static const size_t sizes[] = { 1, 2, 100, 10000, BVH_BIG_TREE };
	for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; s++)
		for (int lattice = 0; lattice < 2; lattice++) {
			struct builder b;
			char what[64];
			size_t n = sizes[s];
			if (n == BVH_BIG_TREE && lattice)
				continue;
			random_scene(&b, n, 10, v3s(0), lattice, n == 1 ? 0 : n == 2 ? 1 : 2);
			snprintf(what, sizeof what, "%s scene of %zu", lattice ? "lattice" : "random", n);
			long nrays = n >= BVH_BIG_TREE ? 100 : n >= 10000 ? 1500 : 10000;
			compare_scene(&b.sc, nrays, n == 1 ? 0.05 : 0.3, lattice, 10, v3s(0), what);
			scene_free(&b.sc);
		}
	/* only planes: no BVH nodes at all */
	struct builder b;
	builder_init(&b);
	add_plane(&b, v3(0, 1, 0), 0);
	add_plane(&b, v3(1, 1, 0), 2);
	compare_scene(&b.sc, 2000, 0.2, false, 10, v3s(0), "planes only");
	scene_free(&b.sc);
}

/* A direction with a -0 component and an origin on the face of the root box: the slab
 * test must treat the ray as inside that slab, as it does for +0. */
static void test_signed_zero_on_face(void)
{
	struct builder b;
	builder_init(&b);
	/* edge A-B lies in the planes x = 0 and y = 0, the root box's lo faces */
	add_triangle(&b, v3(0, 0, 0), v3(0, 0, 2), v3(1, 1, 1));
	b.sc.geo.triangles[0].surface = 0;
	struct accels acc;
	accels_build(&b.sc, &acc);
	/* and a denormal x, whose reciprocal overflows */
	static const double zeros[3] = { 0.0, -0.0, 0x1p-1040 };
	for (int sx = 0; sx < 3; sx++)
		for (int sz = 0; sz < 2; sz++) {
			/* in the plane x = 0, crossing the edge at (0, 0, 1); then the same from the
			 * other side: origin on the hi face y = 1, going -y */
			struct ray rays[2] = { { v3(0, -1, 1), v3(zeros[sx], 1, zeros[sz]) },
			                       { v3(0, 1, 1), v3(zeros[sx], -1, zeros[sz]) } };
			for (int i = 0; i < 2; i++)
				for (int k = 0; k < NANSWERS; k++) {
					struct hit h = { .t = INFINITY };
					bool f = answer_hit(&acc, k, &b.sc, &rays[i], &h);
					if (!(f && h.t == 1))
						fprintf(stderr, "d = <%g, %d, %g>: %s %d t %g\n", zeros[sx], i ? -1 : 1, zeros[sz],
						        names[k], f, h.t);
					CHECK(f && h.t == 1);
					CHECK(vzero(answer_filter(&acc, k, &b.sc, &rays[i], INFINITY)));
				}
		}
	accels_free(&acc);
	scene_free(&b.sc);
}

/* All centroids equal: must end in a leaf, not recurse forever. */
static void test_same_centroid(void)
{
	struct builder b;
	builder_init(&b);
	struct vec3 c = v3(1, 2, 3);
	for (int i = 0; i < 500; i++)
		add_sphere(&b, c, (1 + irand(256)) / 64.0);
	for (int i = 0; i < 500; i++) {
		/* box [c - |a|, c + |a|]: its centre is c exactly (dyadic values) */
		struct vec3 a = v3((16 + irand(112)) / 64.0, (16 + irand(112)) / 64.0, (16 + irand(112)) / 64.0);
		struct vec3 s = v3(irand(2) ? 1 : -1, irand(2) ? 1 : -1, irand(2) ? 1 : -1);
		a = vmul(a, s);
		struct vec3 q = v3(a.x * (irand(129) - 64) / 64.0, a.y * (irand(129) - 64) / 64.0, a.z * (irand(129) - 64) / 64.0);
		add_triangle(&b, vadd(c, a), vsub(c, a), vadd(c, q));
	}
	/* and 300 identical spheres */
	for (int i = 0; i < 300; i++)
		add_sphere(&b, c, 0.5);
	struct bvh *bvh = bvh_build(&b.sc.geo, false);
	size_t nodes;
	int depth;
	shape_of(bvh, &nodes, &depth);
	if (depth != 0)
		fprintf(stderr, "same centroid: %zu nodes, depth %d\n", nodes, depth);
	CHECK(depth <= 1);
	bvh_free(bvh);
	compare_scene(&b.sc, 3000, 0.5, false, 2, c, "same centroid");
	scene_free(&b.sc);

	/* identical triangles */
	builder_init(&b);
	for (int i = 0; i < 200; i++)
		add_triangle(&b, v3(0, 0, 0), v3(1, 0, 0), v3(0, 1, 0));
	bvh = bvh_build(&b.sc.geo, false);
	shape_of(bvh, &nodes, &depth);
	CHECK(depth == 0 && nodes == 1);
	bvh_free(bvh);
	compare_scene(&b.sc, 2000, 0.02, false, 1, v3s(0), "identical triangles");
	scene_free(&b.sc);
}

/* One huge triangle over many tiny ones. */
static void test_huge_and_tiny(void)
{
	struct builder b;
	builder_init(&b);
	add_triangle(&b, v3(-1e6, -1, -1e6), v3(1e6, 1, -1e6), v3(0, 0, 1e6));
	for (int i = 0; i < 3000; i++) {
		struct vec3 p = rand_in_box(v3s(-1), v3s(1));
		double s = lrand(1e-6, 1e-2);
		add_triangle(&b, p, vadd(p, vscale(rand_unit(), s)), vadd(p, vscale(rand_unit(), s)));
	}
	for (int i = 0; i < 500; i++)
		add_sphere(&b, rand_in_box(v3s(-1), v3s(1)), lrand(1e-6, 1e-3));
	compare_scene(&b.sc, 2000, 0.3, false, 1, v3s(0), "huge and tiny");
	scene_free(&b.sc);
}

/* Far from the origin: at 1e9 a float has an ulp of 64, so float boxes must be
 * rounded outward; every primitive must still be found. */
static void test_far_offset(void)
{
	static const double offsets[] = { 1e9, -1e9, 3e12 };
	for (size_t k = 0; k < sizeof offsets / sizeof offsets[0]; k++) {
		struct builder b;
		struct vec3 off = v3(offsets[k], -0.5 * offsets[k], 0.25 * offsets[k]);
		random_scene(&b, 1000, 1, off, false, 1);
		char what[64];
		snprintf(what, sizeof what, "offset %g", offsets[k]);
		compare_scene(&b.sc, 3000, 0.3, false, 1, off, what);

		/* aim at every sphere's centre from outside: each ray must hit something */
		struct accels acc;
		accels_build(&b.sc, &acc);
		long missed = 0;
		for (size_t i = 0; i < b.sc.geo.nspheres; i++) {
			struct vec3 c = b.sc.geo.spheres[i].center;
			struct ray r;
			r.o = vadd(c, vscale(rand_unit(), 3));
			r.d = vnorm(vsub(c, r.o));
			for (int k = BVH; k <= GRID; k++) {
				struct hit h = { .t = INFINITY };
				missed += !answer_hit(&acc, k, &b.sc, &r, &h);
			}
		}
		if (missed)
			fprintf(stderr, "%s: %ld of %zu rays aimed at sphere centres missed\n", what, missed, b.sc.geo.nspheres);
		CHECK(missed == 0);
		accels_free(&acc);
		scene_free(&b.sc);
	}
}

/* Centroids in geometric progression: SAH splits off a few at a time, so the tree is
 * as deep as it can get. Depth must stay within the traversal stack. */
static void test_deep(void)
{
	struct builder b;
	builder_init(&b);
	double x = 1;
	for (int i = 0; i < 1500; i++, x *= 1.4)
		add_sphere(&b, v3(x, 0, 0), x * 0.1);
	struct bvh *bvh = bvh_build(&b.sc.geo, false);
	size_t nodes;
	int depth;
	shape_of(bvh, &nodes, &depth);
	CHECK(depth <= 96);
	CHECK(nodes <= 2 * nprims(&b.sc) - 1);
	/* rays along the row visit the deepest leaves */
	for (int i = 0; i < 200; i++) {
		struct ray r = { v3(-1, urange(-0.01, 0.01), urange(-0.01, 0.01)), v3(1, 0, 0) };
		struct hit h = { .t = INFINITY }, h0 = { .t = INFINITY };
		bool f = bvh_intersect(bvh, &b.sc.geo, &r, &h), f0 = ref_intersect(&b.sc, &r, &h0);
		CHECK(f == f0 && h.t == h0.t);
		struct vec3 tr = bvh_transmittance(bvh, &b.sc.geo, &r, INFINITY), tr0 = ref_transmittance(&b.sc, &r, INFINITY);
		CHECK(tr.x == tr0.x && tr.y == tr0.y);
		r.o = v3(x * 2, 0, 0);
		r.d = v3(-1, 0, 0);
		h = h0 = (struct hit){ .t = INFINITY };
		f = bvh_intersect(bvh, &b.sc.geo, &r, &h);
		f0 = ref_intersect(&b.sc, &r, &h0);
		CHECK(f == f0 && h.t == h0.t);
	}
	bvh_free(bvh);
	compare_scene(&b.sc, 2000, 0.05, false, 1, v3s(0), "geometric progression");
	scene_free(&b.sc);

	/* a random scene's tree is shallow */
	random_scene(&b, 20000, 10, v3s(0), false, 0);
	bvh = bvh_build(&b.sc.geo, false);
	shape_of(bvh, &nodes, &depth);
	if (depth > 48)
		fprintf(stderr, "20000 random primitives: depth %d\n", depth);
	CHECK(depth <= 48);
	CHECK(nodes <= 2 * nprims(&b.sc) - 1);
	bvh_free(bvh);
	scene_free(&b.sc);
}

/* The geometry of a hit primitive, which a renumbering must not change. */
/* bvh_reorder: with the scene's primitives renumbered in leaf order, and the triangles
 * of the leaves in packets, each ray still hits the same geometry at the same t and sees
 * the same shadow. */
static void test_reorder(void)
{
	struct builder b;
	random_scene(&b, 3000, 1, v3s(0), false, 1);
	/* spheres and triangles of the same centroid, which no split separates: leaves of
	 * both kinds, which keep their list of ids after the reorder, where every other leaf
	 * points straight at its primitives */
	enum { NPAIRS = 8 };
	struct vec3 pair[NPAIRS];
	for (int i = 0; i < NPAIRS; i++) {
		pair[i] = rand_in_box(v3s(-1), v3s(1));
		add_sphere(&b, pair[i], 0.01);
		add_triangle(&b, vadd(pair[i], v3(-0.02, -0.02, 0)), vadd(pair[i], v3(0.02, -0.02, 0)),
		             vadd(pair[i], v3(0, 0.02, 0)));
	}
	struct bvh *bvh = bvh_build(&b.sc.geo, false);
	enum { NRAYS = 3000 };
	static struct ray rays[NRAYS];
	static struct answer before[NRAYS];
	for (int i = 0; i < NRAYS; i++) {
		rays[i].o = rand_in_box(v3s(-2), v3s(2));
		/* a third of the rays at the pairs */
		rays[i].d = i % 3 ? rand_unit() : vunit(vsub(pair[i % NPAIRS], rays[i].o));
		answer_of(bvh, &b.sc, &rays[i], 3, &before[i]);
	}
	bvh_reorder(bvh, &b.sc.geo);
	CHECK(b.sc.geo.nspheres > 20 && b.sc.geo.ntriangles > 1000);
	/* the leaves of two triangles or more in packets, at most one for two triangles */
	struct bvh_shape shape = bvh_shape(bvh);
	CHECK(shape.packets > b.sc.geo.ntriangles / 8 && shape.packets <= b.sc.geo.ntriangles / 2);
	long hits = 0, differ = 0;
	for (int i = 0; i < NRAYS; i++) {
		struct answer after;
		answer_of(bvh, &b.sc, &rays[i], 3, &after);
		differ += !same_answer(&before[i], &after);
		hits += after.found;
	}
	CHECK(differ == 0);
	CHECK(hits > NRAYS / 4);
	bvh_free(bvh);
	scene_free(&b.sc);
}

int main(void)
{
	rng_seed(0x5eed);
	test_signed_zero_on_face();
	test_random_scenes();
	test_same_centroid();
	test_huge_and_tiny();
	test_far_offset();
	test_deep();
	test_reorder();
	return check_result();
}
