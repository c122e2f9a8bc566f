/* test_csg.c: the parts of section 9 (part.h, part_make.h) and their CSG (csg.h): hits
 * against closed forms, no re-hit from a spawned ray, inside tests, and the one answer
 * over a face that a cutter shares. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "csg.h"
#include "geometry.h"
#include "part_make.h"
#include "random.h"

static struct part parts[512];
static uint32_t members[512];
static struct geometry geo = { .parts = parts, .members = members };

static uint32_t add(struct part p)
{
	parts[geo.nparts] = p;
	return (uint32_t)geo.nparts++;
}

static uint32_t node(enum part_op op, uint32_t a, uint32_t b)
{
	members[geo.nmembers] = a;
	members[geo.nmembers + 1] = b;
	struct part p = { .kind = PART_CSG, .op = (uint8_t)op, .first = (uint32_t)geo.nmembers, .count = 2 };
	geo.nmembers += 2;
	uint32_t n = add(p);
	struct vec3 lo, hi;
	csg_bound(&geo, n, &lo, &hi);
	CHECK(csg_tree_build(&geo, &parts[n], NULL, 0) == 0);
	return n;
}

static struct ray ray(struct vec3 o, struct vec3 d)
{
	return (struct ray){ o, vnorm(d) };
}

/* The closest hit of part k along r, or INFINITY. */
static double closest(uint32_t k, struct ray r)
{
	struct csg_hit h;
	return csg_next(&geo, k, &r, 0, INFINITY, &h) ? h.t : INFINITY;
}

static void test_shapes(void)
{
	struct part p;
	struct affine id = affine_identity;
	/* a box hit on its face, from both sides */
	CHECK(part_make_box(&p, v3(1, 1, 1), v3(-1, -1, -1), &id));
	uint32_t box = add(p);
	CHECK_NEAR(closest(box, ray(v3(0.3, 0.2, -5), v3(0, 0, 1))), 4, 1e-15);
	CHECK_NEAR(closest(box, ray(v3(0.3, 0.2, 0), v3(0, 0, 1))), 1, 1e-15);
	CHECK(closest(box, ray(v3(2, 0, -5), v3(0, 0, 1))) == INFINITY);
	/* an ellipsoid: the unit sphere scaled by 1e-3 in x */
	struct affine squash = { { { 1e-3, 0, 0, 0 }, { 0, 1, 0, 0 }, { 0, 0, 1, 0 } } };
	CHECK(part_make_sphere(&p, v3(0, 0, 0), 1, &squash));
	uint32_t ell = add(p);
	CHECK_NEAR(closest(ell, ray(v3(-5, 0.6, 0), v3(1, 0, 0))), 5 - 0.8e-3, 1e-15);
	CHECK(closest(ell, ray(v3(0.00101, -5, 0), v3(0, 1, 0))) == INFINITY);
	/* a cylinder along z and a cone, their sides and end discs */
	CHECK(part_make_cone(&p, v3(0, 0, -1), 0.5, v3(0, 0, 1), 0.5, false, &id));
	uint32_t cyl = add(p);
	CHECK_NEAR(closest(cyl, ray(v3(-3, 0, 0), v3(1, 0, 0))), 2.5, 1e-15);
	CHECK_NEAR(closest(cyl, ray(v3(0.1, 0.2, -4), v3(0, 0, 1))), 3, 1e-15);
	CHECK(part_make_cone(&p, v3(0, 0, 0), 1, v3(0, 2, 0), 0, false, &id));
	uint32_t cone = add(p);
	CHECK_NEAR(closest(cone, ray(v3(-3, 1, 0), v3(1, 0, 0))), 2.5, 1e-15);
	CHECK_NEAR(closest(cone, ray(v3(0.2, -1, 0), v3(0, 1, 0))), 1, 1e-15);
	/* a disc with a hole */
	CHECK(part_make_disc(&p, v3(0, 1, 0), v3(0, 2, 0), 2, 1, &id));
	uint32_t disc = add(p);
	CHECK_NEAR(closest(disc, ray(v3(1.5, 3, 0), v3(0, -1, 0))), 2, 1e-15);
	CHECK(closest(disc, ray(v3(0.5, 3, 0), v3(0, -1, 0))) == INFINITY);
	geo.nparts = 0;
}

/* From every hit of part k, rays leaving to either side never meet the same surface
 * again at t ~ 0. */
static void test_no_rehit(uint32_t k, const char *what)
{
	rng_seed(7);
	int rehits = 0, hits = 0;
	for (int i = 0; i < 20000; i++) {
		struct vec3 o = vscale(v3(urange(-1, 1), urange(-1, 1), urange(-1, 1)), 6);
		struct vec3 target = vscale(v3(urange(-1, 1), urange(-1, 1), urange(-1, 1)), 1.2);
		struct ray r = ray(o, vsub(target, o));
		struct csg_hit h;
		if (!csg_next(&geo, k, &r, 0, INFINITY, &h))
			continue;
		hits++;
		struct surface_point sp;
		part_surface(&geo.parts[h.leaf], &r, h.t, &sp);
		struct vec3 w = vnorm(v3(urange(-1, 1), urange(-1, 1), urange(-1, 1)));
		struct ray out = { ray_offset_origin(&sp, w), w };
		struct csg_hit again;
		if (csg_next(&geo, k, &out, 0, INFINITY, &again) && again.leaf == h.leaf &&
		    vlen(vsub(vmad(out.o, again.t, out.d), sp.p)) < 1e-9)
			rehits++;
	}
	if (rehits)
		fprintf(stderr, "%s: %d re-hits of %d\n", what, rehits, hits);
	CHECK(rehits == 0);
	CHECK(hits > 1000);
}

static void test_rehits(void)
{
	struct part p;
	struct affine tilt = { { { 0.8, -0.6, 0, 0.25 }, { 0.6, 0.8, 0, -0.5 }, { 0, 0, 1, 3e-3 } } };
	CHECK(part_make_box(&p, v3(-1, -1, -1), v3(1, 0.5, 1), &tilt));
	test_no_rehit(add(p), "box");
	CHECK(part_make_cone(&p, v3(0, -1, 0.2), 1, v3(0.3, 1, 0), 0.4, false, &tilt));
	test_no_rehit(add(p), "cone");
	struct affine squash = { { { 1e-3, 0, 0, 0 }, { 0, 1, 0, 0 }, { 0, 0, 1, 0 } } };
	CHECK(part_make_sphere(&p, v3(0.1, 0, 0), 1, &squash));
	test_no_rehit(add(p), "ellipsoid");
	geo.nparts = 0;
}

/* A difference whose cutter is flush with the box's front face: over the whole face the
 * ray goes through the hole (the regularised difference), never the face, and the hole's
 * wall shows the cutter. */
static void test_flush_cutter(void)
{
	struct part p;
	struct affine id = affine_identity;
	CHECK(part_make_box(&p, v3(-1, -1, -1), v3(1, 1, 1), &id));
	uint32_t box = add(p);
	/* a cylinder along z, from the front face z = -1 to beyond the back */
	CHECK(part_make_cone(&p, v3(0, 0, -1), 0.5, v3(0, 0, 3), 0.5, false, &id));
	p.inverse = true;
	uint32_t cutter = add(p);
	uint32_t diff = node(PART_INTERSECT, box, cutter);
	rng_seed(3);
	int face = 0, wall = 0, through = 0;
	for (int i = 0; i < 20000; i++) {
		double a = 2 * M_PI * urand(), rad = 0.49 * sqrt(urand());
		struct vec3 o = v3(rad * cos(a), rad * sin(a), -5);
		struct vec3 target = v3(rad * cos(a) * 0.999, rad * sin(a) * 0.999, -1);
		struct ray r = ray(o, vsub(target, o));
		struct csg_hit h;
		if (!csg_next(&geo, diff, &r, 0, INFINITY, &h))
			through++;
		else if (h.leaf == box)
			face++;
		else
			wall++;
	}
	CHECK(face == 0);
	CHECK(through + wall == 20000);
	/* the same with the cutter in front of the box: flush but outside, the face stays */
	CHECK(part_make_cone(&p, v3(0, 0, -3), 0.5, v3(0, 0, -1), 0.5, false, &id));
	p.inverse = true;
	uint32_t front = add(p);
	uint32_t diff2 = node(PART_INTERSECT, box, front);
	int kept = 0;
	for (int i = 0; i < 2000; i++) {
		double x = 0.45 * urange(-1, 1), y = 0.3 * urange(-1, 1);
		struct csg_hit h;
		struct ray r = ray(v3(x, y, -5), v3(0, 0, 1));
		if (csg_next(&geo, diff2, &r, 0, INFINITY, &h) && h.leaf == box && fabs(h.t - 4) < 1e-12)
			kept++;
	}
	CHECK(kept == 2000);
	geo.nparts = geo.nmembers = 0;
}

/* Coinciding faces of two members, one answer: the first member's. */
static void test_coincident(void)
{
	struct part p;
	struct affine id = affine_identity;
	double c = cos(M_PI / 2), sn = sin(M_PI / 2); /* c is 6e-17, not 0 */
	CHECK(part_make_box(&p, v3(-1, -1, -1), v3(1, 1, 1), &id));
	uint32_t a = add(p);
	/* the same cube, moved and turned a quarter about x, from corners moved back: its
	 * faces coincide with a's up to rounding */
	struct affine x = { { { 1, 0, 0, 0.1 }, { 0, c, -sn, 0.2 }, { 0, sn, c, 0.3 } } };
	struct affine inv = affine_inverse(&x);
	CHECK(part_make_box(&p, affine_point(&inv, v3(-1, -1, -1)), affine_point(&inv, v3(1, 1, 1)), &x));
	uint32_t b = add(p);
	uint32_t both = node(PART_MERGE, b, a); /* the later member first: the order the hits are found in does not decide */
	rng_seed(11);
	CHECK(!affine_is_identity(&x));
	int first = 0, hits = 0;
	for (int i = 0; i < 5000; i++) {
		struct ray r = ray(v3(urange(-0.9, 0.9), 5, urange(-0.9, 0.9)), v3(0.01 * urange(-1, 1), -1, 0.01 * urange(-1, 1)));
		struct csg_hit h;
		if (csg_next(&geo, both, &r, 0, INFINITY, &h)) {
			hits++;
			first += h.leaf == a;
		}
	}
	CHECK(hits == 5000);
	CHECK(first == 5000);
	geo.nparts = geo.nmembers = 0;
}

static void test_inside(void)
{
	struct part p;
	struct affine id = affine_identity;
	CHECK(part_make_sphere(&p, v3(0, 0, 0), 1, &id));
	uint32_t s = add(p);
	CHECK(part_make_box(&p, v3(0, -2, -2), v3(2, 2, 2), &id));
	uint32_t b = add(p);
	uint32_t inter = node(PART_INTERSECT, s, b);
	CHECK(csg_inside(&geo, inter, v3(0.5, 0, 0)));
	CHECK(!csg_inside(&geo, inter, v3(-0.5, 0, 0)));
	/* the half ball's flat face is seen, and from behind its round side */
	CHECK_NEAR(closest(inter, ray(v3(-3, 0.1, 0), v3(1, 0, 0))), 3, 1e-15);
	CHECK_NEAR(closest(inter, ray(v3(3, 0, 0), v3(-1, 0, 0))), 2, 1e-15);
	geo.nparts = geo.nmembers = 0;
}

/* A closed mesh as a solid: the unit cube's twelve triangles, inside by parity along an
 * inside_vector, minus a ball. */
static void test_mesh(void)
{
	static struct vec3 vertices[8];
	static struct triangle tris[12];
	static const uint32_t faces[12][3] = { { 0, 2, 1 }, { 1, 2, 3 }, { 4, 5, 6 }, { 5, 7, 6 }, { 0, 1, 4 }, { 1, 5, 4 },
	                                       { 2, 6, 3 }, { 3, 6, 7 }, { 0, 4, 2 }, { 2, 4, 6 }, { 1, 3, 5 }, { 3, 7, 5 } };
	for (int i = 0; i < 8; i++)
		vertices[i] = v3(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
	for (int f = 0; f < 12; f++)
		tris[f] = (struct triangle){ { faces[f][0], faces[f][1], faces[f][2] },
		                             { TRIANGLE_FLAT, TRIANGLE_FLAT, TRIANGLE_FLAT }, 0 };
	geo.vertices = vertices;
	geo.part_triangles = tris;
	uint32_t cube = add((struct part){ .kind = PART_MESH, .first = 0, .count = 12, .a = { 0.6, 0.48, 0.64 } });
	struct vec3 lo, hi;
	csg_bound(&geo, cube, &lo, &hi);
	CHECK(csg_inside(&geo, cube, v3(0.3, -0.2, 0.9)));
	CHECK(!csg_inside(&geo, cube, v3(1.3, -0.2, 0.9)));
	CHECK_NEAR(closest(cube, ray(v3(0.2, 0.1, -4), v3(0, 0, 1))), 3, 1e-15);
	/* its outward normals: the front face's points to -z */
	struct ray r = ray(v3(0.2, 0.1, -4), v3(0, 0, 1));
	struct surface_point sp;
	csg_surface(&geo, cube, &r, 3, &sp);
	CHECK_NEAR(sp.ng.z, -1, 1e-15);
	struct part ball;
	struct affine id = affine_identity;
	CHECK(part_make_sphere(&ball, v3(0, 0, -1), 0.5, &id));
	ball.inverse = true;
	uint32_t dent = node(PART_INTERSECT, cube, add(ball));
	/* through the dent: the ball's surface at z = -0.5, not the cube's face */
	CHECK_NEAR(closest(dent, ray(v3(0, 0, -4), v3(0, 0, 1))), 3.5, 1e-15);
	CHECK_NEAR(closest(dent, ray(v3(0.8, 0.8, -4), v3(0, 0, 1))), 3, 1e-15);
	geo.nparts = geo.nmembers = 0;
}

/* Inside the box minus the balls, by the leaves' own tests. */
static bool cheese_inside(uint32_t box, uint32_t nballs, struct vec3 q)
{
	if (!part_inside_leaf(&parts[box], q))
		return false;
	for (uint32_t i = 1; i <= nballs; i++)
		if (!part_inside_leaf(&parts[box + i], q)) /* the balls are inverted */
			return false;
	return true;
}

/* A box minus 300 balls, a node large enough for a hierarchy: its closest surfaces and
 * inside tests against the set operation done point by point. */
static void test_many_members(void)
{
	struct affine id = affine_identity;
	struct part p;
	enum { NBALLS = 300 };
	CHECK(part_make_box(&p, v3(-2, -1, -1), v3(2, 1, 1), &id));
	uint32_t box = add(p);
	rng_seed(5);
	for (int i = 0; i < NBALLS; i++) {
		CHECK(part_make_sphere(&p, v3(urange(-2, 2), urange(-1, 1), urange(-1, 1)), urange(0.02, 0.2), &id));
		p.inverse = true;
		add(p);
	}
	for (uint32_t i = 0; i <= NBALLS; i++)
		members[geo.nmembers + i] = box + i;
	uint32_t n = add((struct part){ .kind = PART_CSG, .op = PART_INTERSECT, .first = (uint32_t)geo.nmembers,
	                                .count = NBALLS + 1 });
	geo.nmembers += NBALLS + 1;
	struct vec3 lo, hi;
	csg_bound(&geo, n, &lo, &hi);
	static struct csg_box boxes[2 * (NBALLS + 1)];
	geo.csg_boxes = boxes;
	CHECK(csg_tree_build(&geo, &parts[n], boxes, 0) > 0);
	CHECK(parts[n].hard == 1 && parts[n].tree == 0);
	int wrong_inside = 0, wrong_hit = 0, hits = 0;
	for (int i = 0; i < 4000; i++) {
		struct vec3 q = v3(urange(-2.5, 2.5), urange(-1.5, 1.5), urange(-1.5, 1.5));
		wrong_inside += csg_inside(&geo, n, q) != cheese_inside(box, NBALLS, q);
		struct vec3 o = v3(urange(-6, 6), urange(-6, 6), -6);
		struct ray r = ray(o, vsub(v3(urange(-2, 2), urange(-1, 1), urange(-1, 1)), o));
		/* the first crossing of a leaf where the point by point set changes */
		double want = INFINITY;
		for (uint32_t k = 0; k <= NBALLS; k++) {
			double t[4];
			int c = part_crossings(&parts[box + k], &r, INFINITY, t);
			for (int j = 0; j < c; j++)
				if (t[j] < want && cheese_inside(box, NBALLS, vmad(r.o, t[j] * (1 - 1e-9), r.d)) !=
				                       cheese_inside(box, NBALLS, vmad(r.o, t[j] * (1 + 1e-9), r.d)))
					want = t[j];
		}
		double got = closest(n, r);
		hits += got < INFINITY;
		wrong_hit += !(got == want || fabs(got - want) <= 1e-12 * want);
	}
	CHECK(wrong_inside == 0);
	CHECK(wrong_hit == 0);
	CHECK(hits > 1000);
	geo.nparts = geo.nmembers = 0;
}

int main(void)
{
	test_shapes();
	test_rehits();
	test_flush_cutter();
	test_coincident();
	test_inside();
	test_mesh();
	test_many_members();
	return check_result();
}
