/* test_shape.c: the ray/primitive tests of render/shape/ at the edges of precision
 * (NUMERICS.md sections 2, 4, 5, 7):
 *  - watertightness: rays aimed exactly at the shared edges and vertices of a 64 x 64
 *    grid and of triangle fans hit at least one of the triangles that share them;
 *  - spheres: a 0.01 sphere at distance 1e6 and a 5e-6 sphere show their exact disc; a
 *    ground sphere of radius 1e12 is hit by grazing rays from 1 unit above, at the right t;
 *  - self-intersection: rays spawned with ray_offset_origin (reflected, refracted, towards a
 *    light) never re-hit the surface they leave on the same side;
 *  - planes: a parallel ray is a miss, never a NaN;
 *  - triangle packets (render/tri_packet.c): on the rays at the grids' shared edges and
 *    vertices, the packet test gives the scalar test's hits and shadows to the bit. */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bvh.h"
#include "check.h"
#include "shape.h"
#include "tri_packet.h"
#include "xalloc.h"

#include "random.h"

#define PI 3.14159265358979323846

/* A unit vector perpendicular to u. */
static struct vec3 perp_unit(struct vec3 u)
{
	for (;;) {
		struct vec3 w = vcross(u, rand_unit());
		if (vlen(w) > 0.1)
			return vnorm(w);
	}
}

/* A random rotation: the columns of m are an orthonormal basis. */
struct rot {
	struct vec3 a, b, c;
};

static struct rot rand_rot(void)
{
	struct vec3 a = rand_unit(), b = perp_unit(a);
	return (struct rot){ a, b, vcross(a, b) };
}

static struct vec3 rot_apply(const struct rot *m, struct vec3 p)
{
	return vadd(vadd(vscale(m->a, p.x), vscale(m->b, p.y)), vscale(m->c, p.z));
}

/* ---- a scene holding only what the tests put in it ---- */

struct mini {
	struct geometry geo;
	size_t cap_v, cap_t;
};

static void mini_init(struct mini *m)
{
	memset(m, 0, sizeof *m);
}

static uint32_t add_vertex(struct mini *m, struct vec3 v)
{
	xgrow((void **)&m->geo.vertices, &m->cap_v, m->geo.nvertices + 1, sizeof *m->geo.vertices);
	m->geo.vertices[m->geo.nvertices] = v;
	return (uint32_t)m->geo.nvertices++;
}

static uint32_t add_tri(struct mini *m, uint32_t i, uint32_t j, uint32_t k)
{
	xgrow((void **)&m->geo.triangles, &m->cap_t, m->geo.ntriangles + 1, sizeof *m->geo.triangles);
	m->geo.triangles[m->geo.ntriangles] =
		(struct triangle){ { i, j, k }, { TRIANGLE_FLAT, TRIANGLE_FLAT, TRIANGLE_FLAT }, 0 };
	return (uint32_t)m->geo.ntriangles++;
}

static struct vec3 tri_normal(const struct geometry *geo, uint32_t t)
{
	const struct triangle *tr = &geo->triangles[t];
	struct vec3 a = geo->vertices[tr->v[0]], b = geo->vertices[tr->v[1]], c = geo->vertices[tr->v[2]];
	return vnorm(vcross(vsub(b, a), vsub(c, a)));
}

static bool hits_tri(const struct geometry *geo, uint32_t t, const struct ray *r)
{
	struct hit h = { .t = INFINITY };
	return triangle_intersect_ray(&geo->triangles[t], geo->vertices, r, &h);
}

/* ---- watertightness ---- */

struct water {
	long rays, misses, doubles, folded, mesh_misses;
};

/* A ray from o aimed exactly at x must hit at least one of the triangles tris[0, n)
 * that share x (all facing the ray the same way, so their projections do not fold). */
static void aim(const struct geometry *geo, const struct bvh *bvh, struct vec3 o, struct vec3 x, const uint32_t *tris,
                int n, struct water *w, const char *what)
{
	struct ray r = { o, vnorm(vsub(x, o)) };
	double s0 = vdot(r.d, tri_normal(geo, tris[0]));
	for (int i = 1; i < n; i++)
		if (!(s0 * vdot(r.d, tri_normal(geo, tris[i])) > 0)) {
			w->folded++;
			return;
		}
	int hits = 0;
	for (int i = 0; i < n; i++)
		hits += hits_tri(geo, tris[i], &r);
	w->rays++;
	if (hits == 0 && w->misses++ < 5)
		fprintf(stderr, "%s: ray o = <%a, %a, %a> d = <%a, %a, %a> passes between %d triangles\n", what, r.o.x,
		        r.o.y, r.o.z, r.d.x, r.d.y, r.d.z, n);
	w->doubles += hits > 1;
	if (bvh) {
		struct hit h = { .t = INFINITY };
		if (!bvh_intersect(bvh, geo, &r, &h) && w->mesh_misses++ < 5)
			fprintf(stderr, "%s: ray o = <%a, %a, %a> d = <%a, %a, %a> misses the whole mesh\n", what, r.o.x,
			        r.o.y, r.o.z, r.d.x, r.d.y, r.d.z);
	}
}

static void report(const struct water *w, const char *what)
{
	if (w->misses || w->mesh_misses || getenv("TEST_SHAPE_VERBOSE"))
		fprintf(stderr, "%s: %ld rays, %ld missed, %ld hit two or more, %ld skipped (folded), %ld missed the mesh\n",
		        what, w->rays, w->misses, w->doubles, w->folded, w->mesh_misses);
	CHECK(w->misses == 0);
	CHECK(w->mesh_misses == 0);
	CHECK(w->rays > 1000);
}

enum { GRID = 64 };

/* A GRID x GRID height field of quads split along one diagonal, mapped by to_world;
 * flat: every height 0, so that edges and vertices are exact in an axis-aligned frame. */
static void build_grid(struct mini *m, const struct rot *rot, struct vec3 offset, double cell, bool flat)
{
	mini_init(m);
	for (int j = 0; j <= GRID; j++)
		for (int i = 0; i <= GRID; i++) {
			struct vec3 p = v3(i * cell, flat ? 0 : urange(-0.3, 0.3) * cell, j * cell);
			add_vertex(m, rot ? vadd(rot_apply(rot, p), offset) : vadd(p, offset));
		}
	for (int j = 0; j < GRID; j++)
		for (int i = 0; i < GRID; i++) {
			uint32_t v00 = (uint32_t)(j * (GRID + 1) + i), v10 = v00 + 1;
			uint32_t v01 = v00 + GRID + 1, v11 = v01 + 1;
			/* triangles 2q and 2q+1 of quad q = j * GRID + i; both wind the same way */
			add_tri(m, v00, v11, v10);
			add_tri(m, v00, v01, v11);
		}
}

static uint32_t vid(int i, int j) { return (uint32_t)(j * (GRID + 1) + i); }
static uint32_t quad_lo(int i, int j) { return (uint32_t)(2 * (j * GRID + i)); }     /* v00 v11 v10 */
static uint32_t quad_hi(int i, int j) { return (uint32_t)(2 * (j * GRID + i) + 1); } /* v00 v01 v11 */

/* ---- triangle packets ---- */

/* A material that lets part of the light through, for the shadow filters compared. */
static void give_transmit(struct mini *m)
{
	m->geo.transmit = xcalloc(1, sizeof *m->geo.transmit);
	m->geo.transmit[0] = v3(0.5, 0.25, 0.75);
	m->geo.ntransmit = 1;
	m->geo.surfaces = xcalloc(1, sizeof *m->geo.surfaces);
	m->geo.surfaces[0] = (struct surface){ 0, -1 };
	m->geo.nsurfaces = 1;
}

struct packet_tally {
	long rays, hits, bad;
};

/* The packet of triangles [first, first + n) against the scalar test of each in turn
 * (shape_intersect and shape_filter, as a leaf of the BVH does without packets): from h->t
 * = tmax, the same hit or none, the same t, b1, b2 and triangle; the same light through
 * (0, tmax). */
static void packet_agrees(const struct geometry *geo, uint32_t first, uint32_t n, const struct ray *r, double tmax,
                          struct packet_tally *pt)
{
	struct tri_packet pk;
	tri_packet_fill(&pk, geo, first, n);
	struct triangle_ray tr;
	triangle_ray_init(r, &tr);
	struct hit a = { .t = tmax, .prim = UINT32_MAX }, b = a;
	bool fa = false;
	for (uint32_t i = 0; i < n; i++)
		fa |= shape_intersect(geo, shape_id(SHAPE_TRIANGLE, first + i), r, &tr, &a);
	bool fb = tri_packet_intersect(&pk, geo, &tr, &b);
	struct vec3 pa = v3s(1);
	for (uint32_t i = 0; i < n && !vzero(pa); i++)
		pa = shape_filter(geo, shape_id(SHAPE_TRIANGLE, first + i), r, &tr, tmax, pa);
	struct vec3 pb = tri_packet_filter(&pk, geo, &tr, tmax, v3s(1));
	pt->rays++;
	pt->hits += fa;
	bool same = fa == fb && a.t == b.t && a.prim == b.prim && (!fa || (a.b1 == b.b1 && a.b2 == b.b2)) &&
	            pa.x == pb.x && pa.y == pb.y && pa.z == pb.z;
	if (!same && pt->bad++ < 5)
		fprintf(stderr, "packet of %u from triangle %u: scalar %s %#x t %a, packet %s %#x t %a; "
		        "light <%g, %g, %g> against <%g, %g, %g>; ray o = <%a, %a, %a> d = <%a, %a, %a>, tmax %a\n",
		        n, first, fa ? "hit" : "miss", a.prim, a.t, fb ? "hit" : "miss", b.prim, b.t, pa.x, pa.y, pa.z,
		        pb.x, pb.y, pb.z, r->o.x, r->o.y, r->o.z, r->d.x, r->d.y, r->d.z, tmax);
}

/* An edge function that is -2^-60 in fact and rounds to exactly 0 in double: the ray
 * passes a hair outside the triangle, as the scalar test's extended-precision step finds,
 * and the packet test must leave that lane to it. */
static void test_packet_edge(void)
{
	struct mini m;
	mini_init(&m);
	add_tri(&m, add_vertex(&m, v3(1, -1, 1)), add_vertex(&m, v3(1 + 0x1p-30, 1 + 0x1p-29, 1)),
	        add_vertex(&m, v3(-1, -(1 + 0x1p-30), 1)));
	give_transmit(&m);
	struct ray r = { v3(0, 0, 0), v3(0, 0, 1) };
	struct packet_tally pt = { 0 };
	packet_agrees(&m.geo, 0, 1, &r, INFINITY, &pt);
	CHECK(pt.bad == 0);
	if (LDBL_MANT_DIG > DBL_MANT_DIG)
		CHECK(!hits_tri(&m.geo, 0, &r));
	geometry_free(&m.geo);
}

/* Rays at the shared edges and vertices of the grid, from origins above it. */
static void grid_rays(const struct mini *m, const struct rot *rot, double cell, bool axis_rays, const char *what,
                      struct packet_tally *pt)
{
	const struct geometry *geo = &m->geo;
	struct bvh *bvh = bvh_build(geo, false);
	struct water w = { 0 };
	struct vec3 up = rot ? rot->b : v3(0, 1, 0);
	for (int j = 1; j < GRID; j++)
		for (int i = 1; i < GRID; i++) {
			for (int k = 0; k < 4; k++) {
				/* the origin: above the grid, at most 5 cells aside, 10 to 100 cells up;
				 * for axis_rays straight above the point aimed at */
				struct vec3 at = geo->vertices[vid(i, j)];
				struct vec3 o = axis_rays ? vadd(at, v3(0, 50 * cell, 0))
				                          : vadd(vadd(at, vscale(up, lrand(10, 100) * cell)),
				                                 vscale(perp_unit(up), urange(0, 5) * cell));
				/* the shared vertex (i, j): six triangles around it */
				uint32_t fan[6] = { quad_lo(i, j), quad_hi(i, j), quad_lo(i - 1, j), quad_hi(i - 1, j - 1),
				                    quad_lo(i - 1, j - 1), quad_hi(i, j - 1) };
				/* (i, j) is v00 of lo(i,j) and hi(i,j), v10 of lo(i-1,j), v11 of lo(i-1,j-1)
				 * and hi(i-1,j-1), v01 of hi(i,j-1) */
				aim(geo, bvh, o, at, fan, 6, &w, what);
				/* the eight triangles of the four quads around (i, j), as two packets of
				 * four, and as packets of three, two and one; to infinity and to a tmax
				 * just past (i, j), where each hit ties with the others */
				struct ray r = { o, vnorm(vsub(at, o)) };
				double t_at = vlen(vsub(at, o));
				for (int row = 0; row < 2; row++) {
					uint32_t first = quad_lo(i - 1, j - row);
					for (uint32_t n = 1; n <= PACKET_LANES; n++) {
						packet_agrees(geo, first + PACKET_LANES - n, n, &r, INFINITY, pt);
						packet_agrees(geo, first, n, &r, t_at * (1 + 0x1p-40), pt);
					}
				}
				/* points on the three edges that leave (i, j) towards +x, +z and the diagonal */
				double s = k == 0 ? 0.5 : urand();
				if (axis_rays)
					s = (1 + irand(63)) / 64.0;
				struct vec3 px = geo->vertices[vid(i + 1, j)], pz = geo->vertices[vid(i, j + 1)],
				            pd = geo->vertices[vid(i + 1, j + 1)];
				struct vec3 ex = vadd(at, vscale(vsub(px, at), s));
				struct vec3 ez = vadd(at, vscale(vsub(pz, at), s));
				struct vec3 ed = vadd(at, vscale(vsub(pd, at), s));
				uint32_t sx[2] = { quad_lo(i, j), quad_hi(i, j - 1) };  /* edge (i,j)-(i+1,j) */
				uint32_t sz[2] = { quad_hi(i, j), quad_lo(i - 1, j) };  /* edge (i,j)-(i,j+1) */
				uint32_t sd[2] = { quad_lo(i, j), quad_hi(i, j) };      /* edge (i,j)-(i+1,j+1) */
				struct vec3 oo[3] = { o, o, o };
				if (axis_rays) {
					oo[0] = vadd(ex, v3(0, 50 * cell, 0));
					oo[1] = vadd(ez, v3(0, 50 * cell, 0));
					oo[2] = vadd(ed, v3(0, 50 * cell, 0));
				}
				aim(geo, bvh, oo[0], ex, sx, 2, &w, what);
				aim(geo, bvh, oo[1], ez, sz, 2, &w, what);
				aim(geo, bvh, oo[2], ed, sd, 2, &w, what);
				if (axis_rays)
					break;
			}
		}
	report(&w, what);
	bvh_free(bvh);
}

static void test_grid(void)
{
	struct mini m;
	struct packet_tally pt = { 0 };
	/* flat, axis-aligned, integer coordinates: rays straight down hit edges and
	 * vertices exactly, so the edge functions are exactly 0 */
	build_grid(&m, NULL, v3(-32, 0, -32), 1, true);
	give_transmit(&m);
	grid_rays(&m, NULL, 1, true, "flat grid, vertical rays", &pt);
	grid_rays(&m, NULL, 1, false, "flat grid, oblique rays", &pt);
	geometry_free(&m.geo);
	/* a bumpy grid in a random frame, near the origin and far from it */
	static const double offsets[] = { 0, 1e3, 1e6 };
	static const double cells[] = { 1, 1e-3, 10 };
	for (size_t k = 0; k < 3; k++) {
		struct rot rot = rand_rot();
		struct vec3 off = vscale(rand_unit(), offsets[k]);
		char what[64];
		build_grid(&m, &rot, off, cells[k], false);
		give_transmit(&m);
		snprintf(what, sizeof what, "bumpy grid at %g, cell %g", offsets[k], cells[k]);
		grid_rays(&m, &rot, cells[k], false, what, &pt);
		geometry_free(&m.geo);
	}
	if (pt.bad || getenv("TEST_SHAPE_VERBOSE"))
		fprintf(stderr, "triangle packets: %ld rays, %ld hits, %ld differ from the scalar test\n", pt.rays,
		        pt.hits, pt.bad);
	CHECK(pt.bad == 0);
	CHECK(pt.hits > pt.rays / 4);
}

/* Fans of n triangles around a raised centre: rays at the centre and at the spokes. */
static void test_fans(void)
{
	struct water w = { 0 };
	for (int f = 0; f < 200; f++) {
		struct mini m;
		mini_init(&m);
		int n = 3 + irand(62);
		double radius = lrand(1e-3, 1e3);
		struct rot rot = rand_rot();
		struct vec3 off = vscale(rand_unit(), f % 3 == 0 ? 0 : lrand(1, 1e6));
		struct vec3 up = rot.b;
		uint32_t c = add_vertex(&m, vadd(rot_apply(&rot, v3(0, radius * urange(-0.5, 0.5), 0)), off));
		double a0 = urange(0, 2 * PI);
		for (int i = 0; i < n; i++) {
			double a = a0 + 2 * PI * (i + urange(-0.3, 0.3)) / n;
			add_vertex(&m, vadd(rot_apply(&rot, v3(radius * cos(a), 0, radius * sin(a))), off));
		}
		uint32_t tris[64];
		for (int i = 0; i < n; i++)
			tris[i] = add_tri(&m, c, (uint32_t)(1 + (i + 1) % n), (uint32_t)(1 + i));
		struct bvh *bvh = bvh_build(&m.geo, false);
		struct vec3 centre = m.geo.vertices[c];
		for (int k = 0; k < 40; k++) {
			/* from above or below, within 30 degrees of the axis */
			struct vec3 dir = vadd(vscale(up, irand(2) ? 1 : -1), vscale(perp_unit(up), urange(0, 0.5)));
			struct vec3 o = vadd(centre, vscale(vnorm(dir), radius * lrand(2, 1e3)));
			aim(&m.geo, bvh, o, centre, tris, n, &w, "fan centre");
			/* a point on spoke i, shared by triangles i-1 and i */
			int i = irand(n);
			struct vec3 rim = m.geo.vertices[1 + i];
			struct vec3 x = vadd(centre, vscale(vsub(rim, centre), k == 0 ? 0.5 : urange(0, 1)));
			uint32_t pair[2] = { tris[(i + n - 1) % n], tris[i] };
			aim(&m.geo, bvh, o, x, pair, 2, &w, "fan spoke");
		}
		bvh_free(bvh);
		geometry_free(&m.geo);
	}
	report(&w, "fans");
}

/* ---- spheres ---- */

static bool sphere_t(const struct sphere *s, const struct ray *r, double *t)
{
	struct hit h = { .t = INFINITY };
	bool hit = sphere_intersect(s, r, &h);
	*t = h.t;
	return hit;
}

/* Rays from o through points at distance rho * radius from the centre, across the view
 * direction: inside the disc (rho <= 1 - tol) they hit, outside (rho >= 1 + tol) they miss. */
static void disc_boundary(const struct sphere *s, struct vec3 o, double tol, const char *what)
{
	static const double inside[] = { 0, 0.25, 0.5, 0.9, 0.99, 0.999 };
	static const double outside[] = { 1.001, 1.01, 1.5, 3, 100 };
	struct vec3 axis = vnorm(vsub(s->center, o));
	double dist = vlen(vsub(s->center, o));
	long bad_in = 0, bad_out = 0, n = 0;
	double worst_t = 0;
	for (int k = 0; k < 200; k++) {
		struct vec3 w = perp_unit(axis);
		for (size_t i = 0; i < sizeof inside / sizeof inside[0] + 1; i++) {
			double rho = i < sizeof inside / sizeof inside[0] ? inside[i] : 1 - tol;
			struct ray r = { o, vnorm(vsub(vadd(s->center, vscale(w, rho * s->radius)), o)) };
			double t;
			n++;
			if (!sphere_t(s, &r, &t)) {
				if (bad_in++ < 3)
					fprintf(stderr, "%s: a ray at %.9g radii from the centre missed\n", what, rho);
				continue;
			}
			/* the near root: dist * cos - radius * sqrt(1 - rho^2 ...) ~ dist - radius sqrt(1 - rho^2) */
			double want = dist - s->radius * sqrt(1 - rho * rho);
			double err = fabs(t - want) / s->radius;
			if (rho < 0.999 && err > worst_t)
				worst_t = err;
		}
		for (size_t i = 0; i < sizeof outside / sizeof outside[0] + 1; i++) {
			double rho = i < sizeof outside / sizeof outside[0] ? outside[i] : 1 + tol;
			struct ray r = { o, vnorm(vsub(vadd(s->center, vscale(w, rho * s->radius)), o)) };
			double t;
			n++;
			if (sphere_t(s, &r, &t) && bad_out++ < 3)
				fprintf(stderr, "%s: a ray at %.9g radii from the centre hit at t = %.17g\n", what, rho, t);
		}
	}
	if (bad_in || bad_out || getenv("TEST_SHAPE_VERBOSE"))
		fprintf(stderr, "%s: %ld rays, %ld inside missed, %ld outside hit; worst t error %.3g radii\n", what, n,
		        bad_in, bad_out, worst_t);
	CHECK(bad_in == 0);
	CHECK(bad_out == 0);
	/* t to a small fraction of the radius: the near side, not the far one nor a blob */
	CHECK(worst_t < 1e-3);
}

static void test_small_far_spheres(void)
{
	/* 0.01 at 1e6, along an axis and along a random direction, from near the origin */
	for (int k = 0; k < 4; k++) {
		struct vec3 o = k < 2 ? v3s(0) : vscale(rand_unit(), 10);
		struct vec3 dir = k % 2 == 0 ? v3(0, 0, 1) : rand_unit();
		struct sphere s = { vadd(o, vscale(dir, 1e6)), 0.01, 0 };
		struct ray r = { o, vnorm(vsub(s.center, o)) };
		double t;
		CHECK(sphere_t(&s, &r, &t));
		CHECK_NEAR(t, vlen(vsub(s.center, o)) - 0.01, 1e-6);
		disc_boundary(&s, o, 1e-6, "radius 0.01 at 1e6");
	}
	/* 5e-6, near and far */
	static const double dists[] = { 1, 1e3 };
	for (int k = 0; k < 2; k++) {
		struct vec3 o = v3(0.3, -0.2, 0.1);
		struct sphere s = { vadd(o, vscale(rand_unit(), dists[k])), 5e-6, 0 };
		struct ray r = { o, vnorm(vsub(s.center, o)) };
		double t;
		CHECK(sphere_t(&s, &r, &t));
		CHECK_NEAR(t, dists[k] - 5e-6, 1e-9 * dists[k]);
		disc_boundary(&s, o, 1e-6, dists[k] == 1 ? "radius 5e-6 at 1" : "radius 5e-6 at 1e3");
		/* from its centre: t = radius */
		r.o = s.center;
		r.d = rand_unit();
		CHECK(sphere_t(&s, &r, &t));
		CHECK_NEAR(t, 5e-6, 1e-18);
		/* the hit point is on the sphere */
		struct geometry geo = { 0 };
		geo.spheres = &s;
		geo.nspheres = 1;
		struct hit h = { .t = t, .prim = shape_id(SHAPE_SPHERE, 0) };
		struct surface_point sp;
		shape_surface_at(&geo, &r, &h, &sp);
		CHECK_NEAR(vlen(vsub(sp.p, s.center)), 5e-6, 1e-15 + 4 * sp.p_err.x);
	}
}

/* A ground sphere of radius 1e12 under an eye 1 unit above it. */
static void test_ground_sphere(void)
{
	const double R = 1e12;
	struct sphere s = { v3(0, -R, 0), R, 0 };
	struct geometry geo = { 0 };
	geo.spheres = &s;
	geo.nspheres = 1;
	/* slopes from steep to just over the horizon's, about sqrt(2 / R) = 1.414e-6 */
	static const double slopes[] = { 1, 0.1, 1e-2, 1e-3, 1e-4, 1e-5, 3e-6, 1.5e-6 };
	for (size_t k = 0; k < sizeof slopes / sizeof slopes[0]; k++) {
		double az = urange(0, 2 * PI);
		struct ray r = { v3(urange(-1e3, 1e3), 1, urange(-1e3, 1e3)), vnorm(v3(cos(az), -slopes[k], sin(az))) };
		/* the reference: f = o - c, b = f.d, c = f.f - R^2 computed without cancellation
		 * as x^2 + z^2 + (1 + 2R) (o.y = 1 exactly), near root c / (-b + sqrt(b^2 - c)) */
		double b = r.o.x * r.d.x + (1 + R) * r.d.y + r.o.z * r.d.z;
		double c = r.o.x * r.o.x + r.o.z * r.o.z + (1 + 2 * R);
		double want = c / (-b + sqrt(b * b - c));
		double t;
		bool hit = sphere_t(&s, &r, &t);
		if (!hit)
			fprintf(stderr, "ground sphere: slope %g missed (want t = %.17g)\n", slopes[k], want);
		CHECK(hit);
		if (!hit)
			continue;
		/* the height of the hit point: within a few ulps of R, the precision to which
		 * the sphere's surface exists at all */
		double dy = fabs(t - want) * slopes[k];
		if (dy > 8 * 0x1p-13 || getenv("TEST_SHAPE_VERBOSE"))
			fprintf(stderr, "ground sphere: slope %g: t = %.17g, want %.17g (rel %.3g, height error %.3g)\n",
			        slopes[k], t, want, fabs(t - want) / want, dy);
		CHECK(dy <= 8 * 0x1p-13); /* ulp(1e12) = 2^-13 */

		/* the hit point and what leaves it */
		struct hit h = { .t = t, .prim = shape_id(SHAPE_SPHERE, 0) };
		struct surface_point sp;
		shape_surface_at(&geo, &r, &h, &sp);
		CHECK(sp.ng.y > 0.99);
		struct vec3 mirror = vsub(r.d, vscale(sp.ng, 2 * vdot(r.d, sp.ng)));
		struct ray rr = { ray_offset_origin(&sp, mirror), vnorm(mirror) };
		double t2;
		bool again = sphere_t(&s, &rr, &t2);
		if (again)
			fprintf(stderr, "ground sphere: slope %g: the reflected ray re-hits at t = %g\n", slopes[k], t2);
		CHECK(!again);
		/* towards a light high up */
		struct vec3 l = vnorm(v3(0.3, 1, 0.2));
		struct ray sr = { ray_offset_origin(&sp, l), l };
		double ts[2];
		CHECK(sphere_crossings(&s, &sr, INFINITY, ts) == 0);
	}
	/* above the horizon: a miss */
	struct ray up = { v3(0, 1, 0), vnorm(v3(1, 1e-6, 0)) };
	double t;
	CHECK(!sphere_t(&s, &up, &t));
	struct ray level = { v3(0, 1, 0), v3(1, 0, 0) };
	CHECK(!sphere_t(&s, &level, &t));
}

/* ---- self-intersection ---- */

static struct vec3 reflect(struct vec3 d, struct vec3 n)
{
	return vsub(d, vscale(n, 2 * vdot(d, n)));
}

/* Refraction of unit d at normal n (either side) into a medium of relative index
 * eta = n_t / n_i; false on total internal reflection. */
static bool refract(struct vec3 d, struct vec3 n, double eta, struct vec3 *w)
{
	if (vdot(d, n) > 0)
		n = vneg(n);
	double cos_i = -vdot(d, n), e = 1 / eta;
	double k = 1 - e * e * (1 - cos_i * cos_i);
	if (k < 0)
		return false;
	*w = vnorm(vadd(vscale(d, e), vscale(n, e * cos_i - sqrt(k))));
	return true;
}

struct selfhit {
	long tests, bad;
};

static void self_fail(struct selfhit *st, const char *what, const struct ray *r, double t)
{
	if (st->bad++ < 8)
		fprintf(stderr, "%s: spawned ray o = <%a, %a, %a> d = <%a, %a, %a> re-hit at t = %g\n", what, r->o.x, r->o.y,
		        r->o.z, r->d.x, r->d.y, r->d.z, t);
}

/* A direction hitting the sphere from o, sometimes grazing. */
static struct vec3 aim_at_sphere(const struct sphere *s, struct vec3 o)
{
	struct vec3 axis = vnorm(vsub(s->center, o));
	double rho = irand(4) == 0 ? 1 - lrand(1e-9, 1e-3) : urand() * 0.999;
	return vnorm(vsub(vadd(s->center, vscale(perp_unit(axis), rho * s->radius)), o));
}

static void test_self_spheres(void)
{
	struct selfhit st = { 0 };
	for (int k = 0; k < 20000; k++) {
		double radius = lrand(1e-4, 1e4);
		double off = irand(4) == 0 ? 0 : lrand(1, 1e9);
		/* no sphere smaller than 1e-6 of its distance from the origin: below that its
		 * surface is a handful of representable points */
		if (radius < 1e-6 * off)
			radius = 1e-6 * off;
		struct sphere s = { vscale(rand_unit(), off), radius, 0 };
		struct geometry geo = { 0 };
		geo.spheres = &s;
		geo.nspheres = 1;
		struct ray r;
		r.o = vadd(s.center, vscale(rand_unit(), radius * lrand(1.01, 1e3)));
		r.d = aim_at_sphere(&s, r.o);
		struct hit h = { .t = INFINITY };
		if (!sphere_intersect(&s, &r, &h))
			continue; /* a grazing aim can miss */
		h.prim = shape_id(SHAPE_SPHERE, 0);
		struct surface_point sp;
		shape_surface_at(&geo, &r, &h, &sp);
		double t;

		/* reflected, outside: a convex surface is not hit again */
		struct vec3 m = reflect(r.d, sp.ng);
		struct ray rr = { ray_offset_origin(&sp, m), vnorm(m) };
		st.tests++;
		if (sphere_t(&s, &rr, &t))
			self_fail(&st, "sphere, reflected outside", &rr, t);

		/* refracted into it: hits the far side, a chord -2 r (w . n) away */
		struct vec3 w;
		double ior = irand(2) ? 1.5 : lrand(1.0001, 3);
		if (!refract(r.d, sp.ng, ior, &w))
			continue;
		struct ray rt = { ray_offset_origin(&sp, w), w };
		double chord = -2 * radius * vdot(w, sp.ng);
		st.tests++;
		if (!sphere_t(&s, &rt, &t) || fabs(t - chord) > 1e-6 * chord + 8 * vlen(sp.p_err)) {
			if (st.bad++ < 8)
				fprintf(stderr, "sphere, refracted inside: t = %.17g, chord %.17g (r %g at %g)\n", t, chord, radius,
				        off);
			continue;
		}
		/* at the far side, from inside: reflected stays inside and hits the sphere
		 * again further on; refracted out (if it can) never comes back */
		struct hit h2 = { .t = t, .prim = h.prim };
		struct surface_point sp2;
		shape_surface_at(&geo, &rt, &h2, &sp2);
		struct vec3 m2 = reflect(rt.d, sp2.ng);
		struct ray rr2 = { ray_offset_origin(&sp2, m2), vnorm(m2) };
		double chord2 = 2 * radius * vdot(rr2.d, sp2.ng) * -1;
		st.tests++;
		if (!sphere_t(&s, &rr2, &t) || !(t > 0.5 * chord2)) {
			if (st.bad++ < 8)
				fprintf(stderr, "sphere, reflected inside: t = %.17g, chord %.17g (r %g at %g)\n", t, chord2, radius,
				        off);
		}
		struct vec3 w2;
		if (refract(rt.d, sp2.ng, 1 / ior, &w2)) {
			struct ray out = { ray_offset_origin(&sp2, w2), w2 };
			st.tests++;
			if (sphere_t(&s, &out, &t))
				self_fail(&st, "sphere, refracted out", &out, t);
		}
	}
	if (st.bad || getenv("TEST_SHAPE_VERBOSE"))
		fprintf(stderr, "spheres: %ld spawned rays, %ld re-hit\n", st.tests, st.bad);
	CHECK(st.bad == 0);
	CHECK(st.tests > 40000);
}

static void test_self_triangles(void)
{
	struct selfhit st = { 0 };
	for (int k = 0; k < 20000; k++) {
		double size = lrand(1e-4, 1e4);
		double off = irand(4) == 0 ? 0 : lrand(1, 1e9);
		if (size < 1e-6 * off)
			size = 1e-6 * off;
		struct mini m;
		mini_init(&m);
		struct vec3 c = vscale(rand_unit(), off);
		uint32_t a = add_vertex(&m, vadd(c, vscale(rand_unit(), size)));
		uint32_t b = add_vertex(&m, vadd(c, vscale(rand_unit(), size)));
		uint32_t d = add_vertex(&m, vadd(c, vscale(rand_unit(), size)));
		add_tri(&m, a, b, d);
		struct vec3 pa = m.geo.vertices[a], pb = m.geo.vertices[b], pd = m.geo.vertices[d];
		struct vec3 nrm = vcross(vsub(pb, pa), vsub(pd, pa));
		if (vlen(nrm) < 1e-3 * size * size) {
			geometry_free(&m.geo);
			continue;
		}
		/* aim at an interior point from either side, sometimes grazing */
		double u = urand(), v = urand();
		if (u + v > 1)
			u = 1 - u, v = 1 - v;
		struct vec3 x = vadd(pa, vadd(vscale(vsub(pb, pa), u), vscale(vsub(pd, pa), v)));
		struct vec3 n = vnorm(nrm), dir = rand_unit();
		if (irand(4) == 0) /* grazing: almost in the plane */
			dir = vnorm(vadd(vsub(dir, vscale(n, vdot(dir, n))), vscale(n, lrand(1e-6, 1e-2))));
		struct ray r = { vadd(x, vscale(dir, size * lrand(0.1, 1e3))), v3s(0) };
		r.d = vnorm(vsub(x, r.o));
		struct hit h = { .t = INFINITY };
		if (!triangle_intersect_ray(&m.geo.triangles[0], m.geo.vertices, &r, &h)) {
			geometry_free(&m.geo);
			continue;
		}
		h.prim = shape_id(SHAPE_TRIANGLE, 0);
		struct surface_point sp;
		shape_surface_at(&m.geo, &r, &h, &sp);
		struct vec3 outs[3];
		int nout = 0;
		outs[nout++] = reflect(r.d, sp.ng);
		outs[nout++] = r.d; /* transmitted straight on */
		struct vec3 w;
		if (refract(r.d, sp.ng, irand(2) ? 1.5 : 1 / 1.5, &w))
			outs[nout++] = w;
		for (int i = 0; i < nout; i++) {
			struct ray s2 = { ray_offset_origin(&sp, outs[i]), vnorm(outs[i]) };
			struct hit h2 = { .t = INFINITY };
			st.tests++;
			if (triangle_intersect_ray(&m.geo.triangles[0], m.geo.vertices, &s2, &h2))
				self_fail(&st, i == 0 ? "triangle, reflected" : "triangle, transmitted", &s2, h2.t);
		}
		geometry_free(&m.geo);
	}
	if (st.bad || getenv("TEST_SHAPE_VERBOSE"))
		fprintf(stderr, "triangles: %ld spawned rays, %ld re-hit\n", st.tests, st.bad);
	CHECK(st.bad == 0);
	CHECK(st.tests > 30000);
}

static void test_self_planes(void)
{
	struct selfhit st = { 0 };
	for (int k = 0; k < 20000; k++) {
		struct plane pl = { k % 5 == 0 ? v3(0, 1, 0) : rand_unit(), irand(3) ? lrand(1e-3, 1e9) : 0, 0 };
		if (irand(2))
			pl.offset = -pl.offset;
		struct geometry geo = { 0 };
		geo.planes = &pl;
		geo.nplanes = 1;
		struct vec3 base = vscale(pl.normal, pl.offset);
		struct vec3 x = vadd(base, vscale(perp_unit(pl.normal), lrand(1e-3, fmax(1, fabs(pl.offset)))));
		struct vec3 dir = rand_unit();
		if (irand(4) == 0)
			dir = vnorm(vadd(vsub(dir, vscale(pl.normal, vdot(dir, pl.normal))), vscale(pl.normal, lrand(1e-6, 1e-2))));
		struct ray r = { vadd(x, vscale(dir, lrand(1e-2, 1e4))), v3s(0) };
		r.d = vnorm(vsub(x, r.o));
		struct hit h = { .t = INFINITY };
		if (!plane_intersect(&pl, &r, &h))
			continue;
		h.prim = shape_id(SHAPE_PLANE, 0);
		struct surface_point sp;
		shape_surface_at(&geo, &r, &h, &sp);
		struct vec3 outs[2] = { reflect(r.d, sp.ng), r.d };
		for (int i = 0; i < 2; i++) {
			struct ray s2 = { ray_offset_origin(&sp, outs[i]), vnorm(outs[i]) };
			struct hit h2 = { .t = INFINITY };
			st.tests++;
			if (plane_intersect(&pl, &s2, &h2))
				self_fail(&st, i == 0 ? "plane, reflected" : "plane, transmitted", &s2, h2.t);
		}
	}
	if (st.bad || getenv("TEST_SHAPE_VERBOSE"))
		fprintf(stderr, "planes: %ld spawned rays, %ld re-hit\n", st.tests, st.bad);
	CHECK(st.bad == 0);
	CHECK(st.tests > 30000);
}

/* ---- planes ---- */

static void test_plane_parallel(void)
{
	struct plane pl = { v3(0, 1, 0), 2, 0 };
	struct hit h = { .t = INFINITY, .prim = 7 };
	/* parallel, off the plane and in it, with +0 and -0 */
	bool hit;
	struct ray r = { v3(0, 0, 0), v3(1, 0, 0) };
	CHECK(!plane_intersect(&pl, &r, &h));
	r.d = v3(0, -0.0, 1);
	CHECK(!plane_intersect(&pl, &r, &h));
	r.o = v3(5, 2, 5);
	CHECK(!plane_intersect(&pl, &r, &h));
	CHECK(h.t == INFINITY && h.prim == 7);
	/* a slanted normal with d . n exactly 0 (the products are exact, so even a build
	 * that contracts them into fused multiply-adds sees 0) */
	double a = 1 / sqrt(2.0);
	struct plane sl = { v3(a, a, 0), 1, 0 };
	r = (struct ray){ v3(1, 2, 3), v3(0, -0.0, 1) };
	CHECK(!plane_intersect(&sl, &r, &h));
	CHECK(h.t == INFINITY);
	r.d = v3(a, -a, 0); /* 0 in plain IEEE arithmetic */
	hit = plane_intersect(&sl, &r, &h);
	CHECK(!isnan(h.t));
	if (vdot(sl.normal, r.d) == 0)
		CHECK(!hit && h.t == INFINITY);
	/* nearly parallel: a finite t or a miss, never NaN */
	r = (struct ray){ v3(0, 0, 0), vnorm(v3(1, 1e-300, 0)) };
	h.t = INFINITY;
	hit = plane_intersect(&pl, &r, &h);
	CHECK(!isnan(h.t));
	CHECK(!hit || (h.t > 0 && isfinite(h.t)));
	/* the same through the BVH's plane loop and the shadow filter */
	struct vec3 opaque = v3s(0);
	struct surface srf = { 0, -1 };
	struct geometry geo = { 0 };
	geo.planes = &pl;
	geo.nplanes = 1;
	geo.transmit = &opaque;
	geo.ntransmit = 1;
	geo.surfaces = &srf;
	geo.nsurfaces = 1;
	struct bvh *bvh = bvh_build(&geo, false);
	r = (struct ray){ v3(0, 0, 0), v3(0, 0, -1) };
	h = (struct hit){ .t = INFINITY };
	CHECK(!bvh_intersect(bvh, &geo, &r, &h));
	CHECK(h.t == INFINITY);
	struct vec3 tr = bvh_transmittance(bvh, &geo, &r, INFINITY);
	CHECK(tr.x == 1 && tr.y == 1 && tr.z == 1);
	/* and a ray that does cross it is blocked */
	r.d = v3(0, 1, 0);
	tr = bvh_transmittance(bvh, &geo, &r, INFINITY);
	CHECK(vzero(tr));
	tr = bvh_transmittance(bvh, &geo, &r, 1.5); /* a segment that stops short */
	CHECK(tr.x == 1);
	bvh_free(bvh);

	/* a triangle seen edge-on (the ray in its plane) is a miss, not a NaN */
	struct mini m;
	mini_init(&m);
	add_tri(&m, add_vertex(&m, v3(0, 0, 0)), add_vertex(&m, v3(1, 0, 0)), add_vertex(&m, v3(0, 0, 1)));
	r = (struct ray){ v3(-1, 0, 0.25), v3(1, 0, 0) };
	h = (struct hit){ .t = INFINITY };
	CHECK(!triangle_intersect_ray(&m.geo.triangles[0], m.geo.vertices, &r, &h));
	CHECK(h.t == INFINITY);
	geometry_free(&m.geo);
}

int main(void)
{
	rng_seed(0x54a9e);
	test_grid();
	test_packet_edge();
	test_fans();
	test_small_far_spheres();
	test_ground_sphere();
	test_self_spheres();
	test_self_triangles();
	test_self_planes();
	test_plane_parallel();
	return check_result();
}
