/* torus_bench.c: the cost of torus_roots and torus_first against sphere_intersect on the same rays, and
 * how many rays torus_roots and a closed-form Ferrari solver get wrong on thin and far
 * tori, against the long double reference of tests/unit/torus_ref.h. Built on demand:
 *   make bench/torus_bench && bench/torus_bench [timing rays] [checked rays] */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "clock.h"
#include "sphere.h"
#include "torus.h"
#include "xalloc.h"

#include "random.h"
#include "torus_ref.h"

#define PI 3.14159265358979323846

/* ---- the closed form, for comparison: Ferrari's method by way of the resolvent cubic
 * and Cardano's formula, as ray tracers have long used it (Schwarze, "Cubic and Quartic
 * Roots", Graphics Gems I, 1990), with its absolute tolerance. ---- */

#define EQN_EPS 1e-9
static bool is_zero(double x) { return x > -EQN_EPS && x < EQN_EPS; }

/* x^2 + c1 x + c0 */
static int quadratic(double c1, double c0, double s[2])
{
	double p = c1 / 2, d = p * p - c0;
	if (is_zero(d)) {
		s[0] = -p;
		return 1;
	}
	if (d < 0)
		return 0;
	double sd = sqrt(d);
	s[0] = sd - p;
	s[1] = -sd - p;
	return 2;
}

/* x^3 + a x^2 + b x + c */
static int cubic(double a, double b, double c, double s[3])
{
	double sq = a * a;
	double p = (-sq / 3 + b) / 3;
	double q = (2.0 / 27 * a * sq - a * b / 3 + c) / 2;
	double p3 = p * p * p, d = q * q + p3;
	int n;
	if (is_zero(d)) {
		if (is_zero(q)) {
			s[0] = 0;
			n = 1;
		} else {
			double u = cbrt(-q);
			s[0] = 2 * u;
			s[1] = -u;
			n = 2;
		}
	} else if (d < 0) {
		double phi = acos(-q / sqrt(-p3)) / 3, t = 2 * sqrt(-p);
		s[0] = t * cos(phi);
		s[1] = -t * cos(phi + PI / 3);
		s[2] = -t * cos(phi - PI / 3);
		n = 3;
	} else {
		double sd = sqrt(d);
		s[0] = cbrt(sd - q) - cbrt(sd + q);
		n = 1;
	}
	for (int i = 0; i < n; i++)
		s[i] -= a / 3;
	return n;
}

/* x^4 + a x^3 + b x^2 + c x + d */
static int ferrari(double a, double b, double c, double d, double s[4])
{
	double sq = a * a;
	double p = -3.0 / 8 * sq + b;
	double q = sq * a / 8 - a * b / 2 + c;
	double r = -3.0 / 256 * sq * sq + sq * b / 16 - a * c / 4 + d;
	int n;
	if (is_zero(r)) {
		n = cubic(0, p, q, s);
		s[n++] = 0;
	} else {
		double z3[3];
		cubic(-p / 2, -r, r * p / 2 - q * q / 8, z3);
		double z = z3[0], u = z * z - r, v = 2 * z - p;
		if (is_zero(u))
			u = 0;
		else if (u > 0)
			u = sqrt(u);
		else
			return 0;
		if (is_zero(v))
			v = 0;
		else if (v > 0)
			v = sqrt(v);
		else
			return 0;
		n = quadratic(q < 0 ? -v : v, z - u, s);
		n += quadratic(q < 0 ? v : -v, z + u, s + n);
	}
	for (int i = 0; i < n; i++)
		s[i] -= a / 4;
	return n;
}

/* The torus by Ferrari: the quartic formed at o (shift = false: the usual way) or at the
 * ray's point nearest the centre (shift = true: torus_roots's move, the solver alone
 * compared), in units of the major radius, with a unit d. */
static int ferrari_torus(double major, double minor, struct vec3 o, struct vec3 d, bool shift, double t[4])
{
	double len = vlen(d), rho = minor / major;
	struct vec3 u = vscale(d, 1 / len), on = vscale(o, 1 / major);
	double sm = shift ? -vdot(on, u) : 0;
	struct vec3 p = vmad(on, sm, u);
	double b = vdot(p, u), m = vdot(p, p) + 1 - rho * rho;
	double s[4];
	int n = ferrari(4 * b, 4 * b * b + 2 * m - 4 * (u.x * u.x + u.z * u.z), 4 * b * m - 8 * (p.x * u.x + p.z * u.z),
			m * m - 4 * (p.x * p.x + p.z * p.z), s);
	int k = 0;
	for (int i = 0; i < n; i++) {
		double tt = (s[i] + sm) * major / len;
		if (tt > 0)
			t[k++] = tt;
	}
	for (int i = 1; i < k; i++)
		for (int j = i; j > 0 && t[j] < t[j - 1]; j--) {
			double x = t[j];
			t[j] = t[j - 1];
			t[j - 1] = x;
		}
	return k;
}

/* ---- rays ---- */

struct rays {
	size_t n;
	struct vec3 *o, *d;     /* d unit */
};

/* n rays from random points at distance dist from the centre, aimed at random points of
 * the torus's bounding box. */
static struct rays box_rays(size_t n, double rho, double dist)
{
	struct rays r = { n, xmalloc(n * sizeof *r.o), xmalloc(n * sizeof *r.d) };
	for (size_t i = 0; i < n; i++) {
		struct vec3 target = v3(urange(-1 - rho, 1 + rho), urange(-rho, rho), urange(-1 - rho, 1 + rho));
		r.o[i] = vscale(rand_unit(), dist);
		r.d[i] = vnorm(vsub(target, r.o[i]));
	}
	return r;
}

/* n rays of a camera grid over the silhouette (ref_view_ray), jittered in each cell */
static struct rays view_rays(size_t n, double rho, double dist, bool face_on)
{
	struct rays r = { n, xmalloc(n * sizeof *r.o), xmalloc(n * sizeof *r.d) };
	size_t side = (size_t)sqrt((double)n);
	for (size_t i = 0; i < n; i++) {
		double a = ((double)(i % side) + urand()) / side, b = ((double)(i / side % side) + urand()) / side;
		ref_view_ray(a, b, rho, dist, face_on, &r.o[i], &r.d[i]);
		r.d[i] = vnorm(r.d[i]);
	}
	return r;
}

static void free_rays(struct rays *r)
{
	free(r->o);
	free(r->d);
}

/* ---- timing ---- */

static volatile double sink;

/* ns per test of each method over all rays, the best of 3 passes */
static void timing(const char *name, double rho, double dist, size_t n)
{
	struct rays r = box_rays(n, rho, dist);
	struct sphere sph = { v3(0, 0, 0), 1 + rho, 0 };
	double best[5] = { INFINITY, INFINITY, INFINITY, INFINITY, INFINITY };
	size_t hits[5] = { 0 };
	for (int pass = 0; pass < 3; pass++) {
		for (int m = 0; m < 5; m++) {
			double sum = 0;
			size_t h = 0;
			double t0 = clock_now();
			for (size_t i = 0; i < r.n; i++) {
				double t[4];
				int k;
				if (m == 0) {
					struct ray ray = { r.o[i], r.d[i] };
					struct hit hit = { .t = INFINITY };
					k = sphere_intersect(&sph, &ray, &hit);
					t[0] = hit.t;
				} else if (m == 1) {
					k = torus_roots(1, rho, r.o[i], r.d[i], INFINITY, t);
				} else if (m == 2) {
					k = torus_first(1, rho, r.o[i], r.d[i], 0, INFINITY, t);
				} else {
					k = ferrari_torus(1, rho, r.o[i], r.d[i], m == 4, t);
				}
				if (k > 0) {
					sum += t[0];
					h++;
				}
			}
			double dt = clock_now() - t0;
			sink += sum;
			hits[m] = h;
			if (dt < best[m])
				best[m] = dt;
		}
	}
	printf("%-22s %8.1f %8.1f %8.1f %8.1f %8.1f   %5.2f %5.2f   %5.1f%% %5.1f%%\n", name, best[0] / n * 1e9,
	       best[1] / n * 1e9, best[2] / n * 1e9, best[3] / n * 1e9, best[4] / n * 1e9, best[1] / best[0],
	       best[2] / best[0], 100.0 * hits[0] / n, 100.0 * hits[1] / n);
	if (hits[2] != hits[1])
		printf("  torus_first hit %zu rays, torus_roots %zu\n", hits[2], hits[1]);
	free_rays(&r);
}

/* ---- correctness ---- */

static void wrong(const char *name, struct rays r, double rho)
{
	/* a root is wrong when off the reference's by more than 1e-9 (|o| + t) / slope, in
	 * units of the major radius: nine digits of the position */
	const double rel = 1e-9;
	size_t open = 0, bad[3][3] = { { 0 } };
	for (size_t i = 0; i < r.n; i++) {
		struct ref_roots ref = ref_torus(1, rho, r.o[i], r.d[i], INFINITY, ref_undecided(r.o[i], 1));
		open += ref.open;
		double t[4];
		for (int m = 0; m < 3; m++) {
			int k = m == 0 ? torus_roots(1, rho, r.o[i], r.d[i], INFINITY, t)
				       : ferrari_torus(1, rho, r.o[i], r.d[i], m == 2, t);
			int f = ref_compare(&ref, 1, r.d[i], k, t, rel);
			if (f & REF_MISSING)
				bad[m][0]++;
			else if (f & REF_SPURIOUS)
				bad[m][1]++;
			else if (f & REF_VALUE)
				bad[m][2]++;
		}
	}
	printf("%-30s %7zu %6zu |", name, r.n, open);
	for (int m = 0; m < 3; m++)
		printf(" %6zu %6zu %6zu |", bad[m][0], bad[m][1], bad[m][2]);
	printf("\n");
}

int main(int argc, char **argv)
{
	size_t nt = argc > 1 ? strtoul(argv[1], NULL, 10) : 4000000;
	size_t nc = argc > 2 ? strtoul(argv[2], NULL, 10) : 100000;
	rng_seed(12345);
	printf("ns per ray test, rays from random directions aimed at the torus's bounding box; the\n"
	       "sphere is the torus's bounding sphere; %zu rays; torus: torus_roots (all roots),\n"
	       "first: torus_first (the first root, as a camera ray needs); Ferrari: formed at the\n"
	       "origin / at the ray's point nearest the centre\n", nt);
	printf("%-22s %8s %8s %8s %8s %8s   %5s %5s   %6s %6s\n", "case", "sphere", "torus", "first", "ferrari",
	       "ferr.mv", "t/s", "f/s", "sph.hit", "tor.hit");
	static const double rhos[] = { 0.5, 1e-2, 1e-3, 1e-4 };
	for (int far = 0; far < 2; far++)
		for (int i = 0; i < 4; i++) {
			char name[64];
			snprintf(name, sizeof name, "r/R %g, from %g", rhos[i], far ? 1e6 : 5.0);
			timing(name, rhos[i], far ? 1e6 : 5, nt);
		}
	printf("\nwrong rays against the reference (missing / spurious / value off) for torus_roots,\n"
	       "Ferrari formed at the origin, Ferrari formed at the nearest point; open: rays the\n"
	       "reference finds within its undecided band of a tangent (not counted)\n");
	printf("%-30s %7s %6s | %20s | %20s | %20s |\n", "case", "rays", "open", "torus_roots", "Ferrari",
	       "Ferrari moved");
	for (int i = 0; i < 4; i++)
		for (int far = 0; far < 2; far++) {
			double dist = far ? 1e6 : 5;
			char name[64];
			struct rays r = box_rays(nc, rhos[i], dist);
			snprintf(name, sizeof name, "box r/R %g from %g", rhos[i], dist);
			wrong(name, r, rhos[i]);
			free_rays(&r);
			for (int face = 0; face < 2; face++) {
				r = view_rays(nc, rhos[i], dist, face);
				const char *view = face ? "face-on" : "edge-on";
				snprintf(name, sizeof name, "%s r/R %g from %g", view, rhos[i], dist);
				wrong(name, r, rhos[i]);
				free_rays(&r);
			}
		}
	return 0;
}
