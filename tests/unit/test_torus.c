/* test_torus.c: render/shape/torus.c against a long double reference (torus_ref.h):
 *  - roots: random rays, rays tangent to the tube, along the axis and edge-on in the
 *    equatorial plane, for minor/major 0.5 to 1e-4, at the origin and moved 1e6 away (the
 *    ray mapped into object space as a caller would), rays from 1e6 away, and camera
 *    grids over thin tori's silhouettes, face-on and edge-on, near and from 1e6;
 *  - torus_first: the first of torus_roots's roots beyond t_after, on the same rays;
 *  - torus_inside: the exact sign, also on points exactly on the surface;
 *  - torus_surface: the point on the torus within its error bound, the normal unit and
 *    outward;
 *  - self-intersection: rays spawned from hits with ray_offset_origin do not meet the
 *    surface they leave at t ~ 0. */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "ray.h"
#include "torus.h"

#include "random.h"
#include "torus_ref.h"

#define PI 3.14159265358979323846

/* The tolerance. Counts must be the reference's except where it finds the ray within
 * ref_undecided (2^-40 R + 2^-53 |o|) of touching the tube. Each root must be within
 * REL (|o|/R + 1 + s) / slope of the reference's, in units of the major radius R (s the
 * distance to the root, slope the cosine between ray and normal there): a relative error
 * of the position, conditioned by the slope. REL = 2^-42 (2.3e-13); torus_roots passes at
 * 2^-44 and fails at 2^-46 (fat tori, whose roots the quartic alone decides). */
#define REL 0x1p-42

struct stats {
	int rays, open, hits, bad;
};

/* Whether torus_first() fails to give, bit for bit, the first of torus_roots()'s n roots t
 * beyond t_after, for t_after 0, each root (as CSG steps from surface to surface), just
 * below each, and between two. */
static bool first_wrong(double major, double minor, struct vec3 o, struct vec3 d, double tmax, int n,
			const double t[4])
{
	double after[13];
	int na = 0;
	after[na++] = 0;
	for (int i = 0; i < n; i++) {
		after[na++] = t[i];
		after[na++] = nextafter(t[i], 0);
		after[na++] = i > 0 ? 0.5 * (t[i - 1] + t[i]) : 0.5 * t[i];
	}
	for (int k = 0; k < na; k++) {
		int j = 0;
		while (j < n && !(t[j] > after[k]))
			j++;
		double f = NAN;
		bool got = torus_first(major, minor, o, d, after[k], tmax, &f);
		if (got != (j < n) || (got && f != t[j]))
			return true;
	}
	return false;
}

/* One ray against the torus, compared with the reference; returns the count of roots
 * and puts them in t. */
static int check_ray(double major, double minor, struct vec3 o, struct vec3 d, double tmax, double t[4],
		     struct stats *st, const char *what)
{
	int n = torus_roots(major, minor, o, d, tmax, t);
	struct ref_roots ref = ref_torus(major, minor, o, d, tmax, ref_undecided(o, major));
	int bad = ref_compare(&ref, major, d, n, t, REL);
	st->rays++;
	st->open += ref.open;
	st->hits += n > 0;
	for (int i = 0; i + 1 < n; i++)
		bad |= !(t[i] <= t[i + 1]) * 8;
	for (int i = 0; i < n; i++)
		bad |= !(t[i] > 0 && t[i] < tmax) * 8;
	bad |= first_wrong(major, minor, o, d, tmax, n, t) * 16;
	if (bad) {
		st->bad++;
		if (st->bad <= 5) {
			fprintf(stderr, "%s: R %g r %g o <%.17g, %.17g, %.17g> d <%.17g, %.17g, %.17g>", what, major,
				minor, o.x, o.y, o.z, d.x, d.y, d.z);
			fprintf(stderr, " tmax %g: fault %d\n", tmax, bad);
			fprintf(stderr, "  got %d:", n);
			for (int i = 0; i < n; i++)
				fprintf(stderr, " %.17g", t[i]);
			fprintf(stderr, "\n  ref %d%s:", ref.n, ref.open ? " (open)" : "");
			for (int i = 0; i < ref.n; i++)
				fprintf(stderr, " %.17g (slope %.3g)", ref.t[i], ref.slope[i]);
			fprintf(stderr, "\n");
		}
	}
	return n;
}

/* The torus point at angles th (around the axis) and ph (around the tube), and the
 * outward normal there. */
static struct vec3 torus_point(double major, double minor, double th, double ph, struct vec3 *n)
{
	*n = v3(cos(ph) * cos(th), sin(ph), cos(ph) * sin(th));
	return v3((major + minor * cos(ph)) * cos(th), minor * sin(ph), (major + minor * cos(ph)) * sin(th));
}

static struct vec3 perp_unit(struct vec3 a)
{
	for (;;) {
		struct vec3 w = vcross(a, rand_unit());
		if (vlen(w) > 0.1)
			return vnorm(w);
	}
}

static const double ratios[] = { 0.5, 1e-2, 1e-3, 1e-4 };
static const double majors[] = { 1, 3.7e-3, 2.9e4 };

/* Random rays from 1.5 to 10 major radii away, aimed near random points of the torus,
 * with direction lengths from 1e-3 to 1e3; at the origin, and with the torus and the ray
 * moved by 1e6 (the object-space origin then carries the move's rounding). */
static void random_rays(void)
{
	for (int moved = 0; moved < 2; moved++)
		for (size_t i = 0; i < sizeof ratios / sizeof *ratios; i++)
			for (size_t j = 0; j < sizeof majors / sizeof *majors; j++) {
				double R = majors[j], r = R * ratios[i];
				struct vec3 shift = moved ? v3(1e6, -0.7e6, 0.3e6) : v3(0, 0, 0);
				struct stats st = { 0 };
				for (int k = 0; k < 3000; k++) {
					struct vec3 n;
					struct vec3 target = torus_point(R, r, urange(0, 2 * PI), urange(0, 2 * PI), &n);
					target = vadd(target, vscale(rand_unit(), r * urange(0, 2)));
					struct vec3 ow = vadd(shift, vscale(rand_unit(), R * urange(1.5, 10)));
					struct vec3 tw = vadd(shift, target);
					struct vec3 d = vscale(vsub(tw, ow), lrand(1e-3, 1e3));
					struct vec3 o = vsub(ow, shift); /* object space, rounded as a caller's */
					double tmax = INFINITY;
					if (k % 4 == 0)
						tmax = urange(0.2, 1.5) * vlen(vsub(tw, ow)) / vlen(d);
					double t[4];
					check_ray(R, r, o, d, tmax, t, &st, "random");
				}
				printf("random%s r/R %g R %g: %d rays, %d hit, %d open, %d wrong\n",
				       moved ? " (moved 1e6)" : "", ratios[i], R, st.rays, st.hits, st.open, st.bad);
				CHECK(st.bad == 0);
			}
}

/* Rays from 1e6 major radii away (the torus small and far) aimed at the torus. */
static void far_rays(void)
{
	for (size_t i = 0; i < sizeof ratios / sizeof *ratios; i++) {
		double R = 1, r = ratios[i];
		struct stats st = { 0 };
		for (int k = 0; k < 2000; k++) {
			struct vec3 n;
			struct vec3 target = torus_point(R, r, urange(0, 2 * PI), urange(0, 2 * PI), &n);
			target = vadd(target, vscale(rand_unit(), r * urange(0, 2)));
			struct vec3 o = vscale(rand_unit(), 1e6);
			double t[4];
			check_ray(R, r, o, vsub(target, o), INFINITY, t, &st, "far");
		}
		printf("far (1e6) r/R %g: %d rays, %d hit, %d open, %d wrong\n", ratios[i], st.rays, st.hits, st.open,
		       st.bad);
		CHECK(st.bad == 0);
	}
}

/* Rays tangent to the tube at a random point, moved off it along the normal by +-1e-3,
 * 1e-6, 1e-7 and 1e-9 of the minor radius (a near miss and a shallow pair), and exactly
 * tangent (where only the reference's clear roots must be found). */
static void grazing_rays(void)
{
	static const double offs[] = { 1e-3, -1e-3, 1e-6, -1e-6, 1e-7, -1e-7, 1e-9, -1e-9, 0 };
	for (size_t i = 0; i < sizeof ratios / sizeof *ratios; i++) {
		double R = 1.3, r = R * ratios[i];
		struct stats st = { 0 };
		for (int k = 0; k < 900; k++) {
			struct vec3 n;
			struct vec3 p = torus_point(R, r, urange(0, 2 * PI), urange(0, 2 * PI), &n);
			struct vec3 w = perp_unit(n);
			struct vec3 q = vmad(p, offs[k % 9] * r, n);
			struct vec3 o = vmad(q, -R * urange(0.5, 4), w);
			double t[4];
			check_ray(R, r, o, vscale(w, urange(0.5, 2)), INFINITY, t, &st, "grazing");
		}
		printf("grazing r/R %g: %d rays, %d hit, %d open, %d wrong\n", ratios[i], st.rays, st.hits, st.open,
		       st.bad);
		CHECK(st.bad == 0);
	}
}

/* Along the axis (through the hole: no root), parallel to it through the tube, and
 * edge-on in the equatorial plane and parallel to it (4 roots through both sides). */
static void axis_and_edge_rays(void)
{
	static const double ys[] = { 0, 0.5, -0.5, 0.999, -0.999, 0.999999 };
	for (size_t i = 0; i < sizeof ratios / sizeof *ratios; i++) {
		double R = 2.1, r = R * ratios[i];
		struct stats st = { 0 };
		double t[4];
		for (int s = -1; s <= 1; s += 2) {
			int n = check_ray(R, r, v3(0, 5 * s * R, 0), v3(0, -s, 0), INFINITY, t, &st, "axis");
			CHECK(n == 0);
			n = check_ray(R, r, v3(1e-300, 5 * s * R, 0), v3(0, -s * 1e-3, 0), INFINITY, t, &st, "axis");
			CHECK(n == 0);
			for (size_t j = 0; j < sizeof ys / sizeof *ys; j++) {
				/* parallel to the axis at R + ys r: two roots */
				double th = urange(0, 2 * PI), q = R + ys[j] * r;
				struct vec3 o = v3(q * cos(th), 5 * s * R, q * sin(th));
				n = check_ray(R, r, o, v3(0, -s, 0), INFINITY, t, &st, "axis-parallel");
				CHECK(n == 2);
				/* edge-on: in the plane y = ys r, through the centre: four roots */
				struct vec3 dir = v3(cos(th), 0, sin(th));
				o = vmad(v3(0, ys[j] * r, 0), -5 * R, dir);
				n = check_ray(R, r, o, vscale(dir, 3.3), INFINITY, t, &st, "edge-on");
				CHECK(n == 4);
				/* edge-on, missing the centre by up to R - r: four roots; by R: two */
				struct vec3 side = v3(-sin(th), 0, cos(th));
				struct vec3 os = vmad(o, urange(0, 0.9) * (R - r), side);
				n = check_ray(R, r, os, dir, INFINITY, t, &st, "edge-on");
				CHECK(n == 4);
				n = check_ray(R, r, vmad(o, R, side), dir, INFINITY, t, &st, "edge-on");
				CHECK(n == 2);
				/* edge-on from 1e6 away */
				o = vmad(v3(0, ys[j] * r, 0), -1e6 * R, dir);
				n = check_ray(R, r, o, dir, INFINITY, t, &st, "edge-on far");
				CHECK(n == 4);
			}
		}
		printf("axis and edge-on r/R %g: %d rays, %d open, %d wrong\n", ratios[i], st.rays, st.open, st.bad);
		CHECK(st.bad == 0);
	}
}

/* Camera grids over the silhouettes of thin tori, face-on and edge-on, from 5 and from
 * 1e6 major radii: every pixel's ray as the reference has it (the brief's "no missing or
 * speckled silhouette pixel"). */
static void silhouettes(void)
{
	static const double thin[] = { 1e-3, 1e-4 };
	for (size_t i = 0; i < 2; i++)
		for (int far = 0; far < 2; far++)
			for (int face = 0; face < 2; face++) {
				struct stats st = { 0 };
				for (int k = 0; k < 96 * 96; k++) {
					struct vec3 o, d;
					double a = (k % 96 + urand()) / 96, b = (k / 96 + urand()) / 96;
					ref_view_ray(a, b, thin[i], far ? 1e6 : 5, face, &o, &d);
					double t[4];
					check_ray(1, thin[i], o, d, INFINITY, t, &st, "silhouette");
				}
				const char *view = face ? "face-on" : "edge-on";
				printf("silhouette %s r/R %g from %g: ", view, thin[i], far ? 1e6 : 5.0);
				printf("%d rays, %d hit, %d open, %d wrong\n", st.rays, st.hits, st.open, st.bad);
				CHECK(st.bad == 0);
			}
}

/* torus_inside against the reference near the surface, and on points whose implicit
 * function is exactly 0 (on the surface: not inside) or one ulp to either side. */
static void inside(void)
{
	int wrong = 0, n = 0;
	for (size_t i = 0; i < sizeof ratios / sizeof *ratios; i++)
		for (int k = 0; k < 20000; k++) {
			double R = lrand(1e-3, 1e3), r = R * ratios[i];
			struct vec3 nn;
			struct vec3 p = torus_point(R, r, urange(0, 2 * PI), urange(0, 2 * PI), &nn);
			p = vadd(p, vscale(rand_unit(), r * lrand(1e-12, 2)));
			int want = ref_inside(R, r, p);
			if (want == 0)
				continue;
			n++;
			wrong += torus_inside(R, r, p) != (want > 0);
		}
	printf("inside: %d points, %d wrong\n", n, wrong);
	CHECK(wrong == 0);
	/* R = 2, r = 1: (3,0,0), (1,0,0), (2,1,0), (2,-1,0), and (0,0,3)... are on it exactly */
	CHECK(!torus_inside(2, 1, v3(3, 0, 0)));
	CHECK(!torus_inside(2, 1, v3(1, 0, 0)));
	CHECK(!torus_inside(2, 1, v3(2, 1, 0)));
	CHECK(!torus_inside(2, 1, v3(0, -1, 2)));
	CHECK(!torus_inside(2, 1, v3(0, 0, -3)));
	CHECK(torus_inside(2, 1, v3(nextafter(3, 0), 0, 0)));
	CHECK(!torus_inside(2, 1, v3(nextafter(3, 4), 0, 0)));
	CHECK(torus_inside(2, 1, v3(nextafter(1, 2), 0, 0)));
	CHECK(!torus_inside(2, 1, v3(nextafter(1, 0), 0, 0)));
	CHECK(torus_inside(2, 1, v3(2, nextafter(1, 0), 0)));
	CHECK(!torus_inside(2, 1, v3(2, nextafter(1, 2), 0)));
	/* R = 5, r = 3: (5 + 3 * 3/5, 3 * 4/5) = (6.8, 2.4) is on it, but 6.8 and 2.4 are not
	 * doubles; (8, 0, 0) and (4, 0, 3) (q = 5, y = 0... r = 3 up) are */
	CHECK(!torus_inside(5, 3, v3(4, 3, 3)));
	CHECK(torus_inside(5, 3, v3(4, nextafter(3, 0), 3)));
	CHECK(!torus_inside(5, 3, v3(4, nextafter(3, 4), 3)));
	/* a thin torus: (R + r, 0, 0) exactly with r = 2^-20 R */
	CHECK(!torus_inside(1, 0x1p-20, v3(1 + 0x1p-20, 0, 0)));
	CHECK(torus_inside(1, 0x1p-20, v3(nextafter(1 + 0x1p-20, 0), 0, 0)));
	CHECK(!torus_inside(1, 0x1p-20, v3(nextafter(1 + 0x1p-20, 2), 0, 0)));
}

/* torus_surface at hit points: the point lies on the torus within its error bound
 * (along the normal), the normal is unit and outward, and the point is about the
 * nearest to p. Then rays spawned from it (reflected, outward, inward, grazing at 1e-3)
 * with ray_offset_origin meet the reference's roots and none at t ~ 0. */
static void surface_and_spawn(void)
{
	for (int moved = 0; moved < 2; moved++)
		for (size_t i = 0; i < sizeof ratios / sizeof *ratios; i++) {
			double R = 1.7, r = R * ratios[i];
			struct vec3 shift = moved ? v3(1e6, 0, -1e6) : v3(0, 0, 0);
			struct stats st = { 0 };
			int surf_bad = 0, near0 = 0, hits = 0;
			for (int k = 0; k < 1500; k++) {
				struct vec3 nn;
				struct vec3 target = torus_point(R, r, urange(0, 2 * PI), urange(0, 2 * PI), &nn);
				struct vec3 ow = vadd(shift, vscale(rand_unit(), R * urange(1.5, 5)));
				struct vec3 o = vsub(ow, shift), d = vsub(vadd(shift, target), ow);
				o = vsub(ow, shift);
				double t[4];
				int n = torus_roots(R, r, o, d, INFINITY, t);
				if (n == 0)
					continue;
				hits++;
				struct surface_point sp;
				torus_surface(R, r, vmad(o, t[0], d), &sp.p, &sp.p_err, &sp.ng);
				sp.ns = sp.ng;
				long double dist = ref_distance(R, r, sp.p);
				double allowed = vdot(vabs(sp.ng), sp.p_err);
				bool ok = fabsl(dist) <= allowed;
				ok &= fabs(vlen(sp.ng) - 1) < 4e-16;
				/* outward: along p - c, c the core circle's nearest point */
				double q = sqrt(sp.p.x * sp.p.x + sp.p.z * sp.p.z);
				struct vec3 out = v3(sp.p.x * (1 - R / q), sp.p.y, sp.p.z * (1 - R / q));
				ok &= vdot(out, sp.ng) > 0.999 * vlen(out);
				if (!ok && ++surf_bad <= 5)
					fprintf(stderr, "surface: R %g r %g p <%.17g %.17g %.17g> dist %Lg bound %g\n",
						R, r, sp.p.x, sp.p.y, sp.p.z, dist, allowed);
				/* spawned rays */
				struct vec3 dn = vnorm(d);
				struct vec3 ws[4];
				ws[0] = vsub(dn, vscale(sp.ng, 2 * vdot(dn, sp.ng)));
				ws[1] = vnorm(vadd(sp.ng, vscale(rand_unit(), 0.9)));
				ws[2] = vnorm(vsub(vscale(rand_unit(), 0.9), sp.ng));
				struct vec3 tan = perp_unit(sp.ng);
				ws[3] = vnorm(vmad(tan, (k & 1 ? 1e-3 : -1e-3), sp.ng));
				for (int j = 0; j < 4; j++) {
					if (fabs(vdot(ws[j], sp.ng)) < 1e-4)
						continue;
					struct vec3 os = ray_offset_origin(&sp, ws[j]);
					struct vec3 ds = vscale(ws[j], lrand(0.1, 10));
					double ts[4];
					int ns = check_ray(R, r, os, ds, INFINITY, ts, &st, "spawned");
					/* no root within 1e-6 r: a legitimate one there needs a ray
					 * within 1e-6 of tangent, and these are not */
					if (ns > 0 && ts[0] * vlen(ds) < 1e-6 * r && ++near0 <= 5)
						fprintf(stderr, "spawned: root at %g (r %g)\n", ts[0] * vlen(ds), r);
				}
			}
			printf("surface and spawned%s r/R %g: %d hits, %d surface wrong; ", moved ? " (moved 1e6)" : "",
			       ratios[i], hits, surf_bad);
			printf("spawned: %d rays, %d open, %d wrong, %d near 0\n", st.rays, st.open, st.bad, near0);
			CHECK(surf_bad == 0);
			CHECK(st.bad == 0);
			CHECK(near0 == 0);
		}
}

int main(void)
{
	rng_seed(20240611);
	random_rays();
	far_rays();
	grazing_rays();
	axis_and_edge_rays();
	silhouettes();
	inside();
	surface_and_spawn();
	return check_result();
}
