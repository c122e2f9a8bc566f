/* torus_ref.h: a slow reference for ray/torus roots (test_torus, bench/torus_bench), in
 * long double and independent of the quartic. Along a unit ray the signed distance g to
 * the tube has |g'| <= 1 and |g''| <= 1/del + 1/q (del the distance to the core circle, q
 * to the axis): an interval where these bounds keep g off 0 is dropped, the rest bisected,
 * and each sign change refined to long double precision. */
#ifndef SCN_TEST_TORUS_REF_H
#define SCN_TEST_TORUS_REF_H

#include <math.h>
#include <stdbool.h>

#include "vec.h"

struct ref_roots {
	int n;                  /* roots in (0, tmax) */
	double t[8];
	double slope[8];        /* |dg/ds| at each root, s the unit-speed parameter: the cosine
	                         * between the ray and the normal */
	double scale;           /* |o|/R + 1: the roots' rounding in double is about u scale */
	bool open;              /* the count is undecided at the tolerance asked for: somewhere
	                         * |g| < tol and |g'| < flat, where the ray touches the tube or
	                         * crosses it in a close pair of roots */
	double flat;
};

struct ref_ray {
	long double ox, oy, oz, ux, uy, uz, rho;
	long double tol, flat, leaf;
	int n;
	long double s[8];
};

/* g, g' and a bound on |g''| over [m - half, m + half] (infinite near the axis or the
 * core circle) */
static inline long double ref_g(const struct ref_ray *r, long double s, long double half, long double *dg,
				long double *k)
{
	long double x = r->ox + s * r->ux, y = r->oy + s * r->uy, z = r->oz + s * r->uz;
	long double q = sqrtl(x * x + z * z), dq = q - 1;
	long double del = sqrtl(dq * dq + y * y);
	*dg = ((q > 0 ? dq * (x * r->ux + z * r->uz) / q : 0) + y * r->uy) / del;
	*k = q > half && del > half ? 1 / (del - half) + 1 / (q - half) : INFINITY;
	return del - r->rho;
}

static inline long double ref_slack(const struct ref_ray *r, long double m)
{
	return 0x1p-60L * (fabsl(r->ox) + fabsl(r->oy) + fabsl(r->oz) + fabsl(m) + 2);
}

/* A lower bound on |g| over [m - half, m + half], from g and g' at m. */
static inline long double ref_lower(long double g, long double dg, long double k, long double half)
{
	long double first = fabsl(g) - half;                    /* |g'| <= 1 */
	long double second = fabsl(g) - fabsl(dg) * half - k * half * half / 2;
	return fmaxl(first, second);         /* second is NaN where k is infinite */
}

static inline void ref_roots_in(struct ref_ray *r, long double a, long double b, long double ga)
{
	long double m = 0.5L * (a + b), half = 0.5L * (b - a), dg, k;
	long double gm = ref_g(r, m, half, &dg, &k);
	long double slack = ref_slack(r, m);
	if (ref_lower(gm, dg, k, half) > slack)
		return;
	/* a leaf: narrow enough, or g flat within its rounding over it (a touching ray,
	 * which would otherwise be bisected all through the band where g is rounding noise) */
	if (half <= r->leaf * (1 + fabsl(m)) || fabsl(dg) * half + k * half * half / 2 <= slack) {
		long double d0, k0;
		long double gb = ref_g(r, b, 0, &d0, &k0);
		if ((ga > 0) == (gb > 0))
			return;
		for (int i = 0; i < 80; i++) {
			long double c = 0.5L * (a + b);
			if (c == a || c == b)
				break;
			if ((ref_g(r, c, 0, &d0, &k0) > 0) == (ga > 0))
				a = c;
			else
				b = c;
		}
		if (r->n < 8)
			r->s[r->n++] = 0.5L * (a + b);
		return;
	}
	ref_roots_in(r, a, m, ga);
	ref_roots_in(r, m, b, gm);
}

/* Whether somewhere in [a, b] |g| < tol and |g'| < flat (searched down to leaf width). */
static inline bool ref_open_in(struct ref_ray *r, long double a, long double b)
{
	long double m = 0.5L * (a + b), half = 0.5L * (b - a), dg, k;
	long double gm = ref_g(r, m, half, &dg, &k);
	if (fabsl(gm) < r->tol && fabsl(dg) < r->flat)
		return true;
	if (ref_lower(gm, dg, k, half) > r->tol + ref_slack(r, m) || fabsl(dg) - k * half > r->flat ||
	    half <= r->leaf * (1 + fabsl(m)))
		return false;
	return ref_open_in(r, a, m) || ref_open_in(r, m, b);
}

/* The roots of o + t d on the torus (major, minor) with t in (0, tmax); the count is open
 * when the ray touches the tube, or crosses it in a pair of roots, within tol major. */
static inline struct ref_roots ref_torus(double major, double minor, struct vec3 o, struct vec3 d, double tmax,
					 double tol)
{
	struct ref_roots out = { 0 };
	long double R = major, len = sqrtl((long double)d.x * d.x + (long double)d.y * d.y + (long double)d.z * d.z);
	struct ref_ray r = { .ox = o.x / R, .oy = o.y / R, .oz = o.z / R, .ux = d.x / len, .uy = d.y / len,
			     .uz = d.z / len, .rho = minor / R, .tol = tol, .leaf = 0x1p-48L };
	/* g = G + k s^2 / 2 near a touch, k < 1/rho + 1: where |g| < tol its slope is below
	 * sqrt(4 k tol), and so is a close pair's at its roots */
	r.flat = 2 * sqrtl((1 / r.rho + 1) * tol);
	out.flat = (double)r.flat;
	out.scale = (double)(sqrtl(r.ox * r.ox + r.oy * r.oy + r.oz * r.oz) + 1);
	long double b = r.ox * r.ux + r.oy * r.uy + r.oz * r.uz;
	long double px = r.ox - b * r.ux, py = r.oy - b * r.uy, pz = r.oz - b * r.uz;
	long double big = (1 + r.rho) * (1 + 0x1p-40L);
	long double disc = big * big - (px * px + py * py + pz * pz);
	if (disc < 0)
		return out;
	long double h = sqrtl(disc);
	long double smax = (long double)tmax * len / R;
	long double lo = fmaxl(-b - h, 0), hi = fminl(-b + h, smax);
	if (!(lo < hi))
		return out;
	long double d0, k0;
	ref_roots_in(&r, lo, hi, ref_g(&r, lo, 0, &d0, &k0));
	out.open = ref_open_in(&r, lo, hi);
	for (int i = 0; i < r.n; i++) {
		if (r.s[i] <= 0 || r.s[i] >= smax)
			continue;
		long double dg, k;
		ref_g(&r, r.s[i], 0, &dg, &k);
		out.slope[out.n] = (double)fabsl(dg);
		out.t[out.n++] = (double)(r.s[i] * R / len);
	}
	return out;
}

/* The band, in units of the major radius, within which the reference leaves a ray's count
 * open (ref_torus's tol) for a ray from o: 2^-40 (8 times the noise that torus_roots shows
 * at the thinnest tube, 1e-4, on rays constructed to graze it) and a few ulps of |o|/R (the
 * rounding of the move from a far origin). */
static inline double ref_undecided(struct vec3 o, double major)
{
	return 0x1p-40 + 0x1p-53 * sqrt(vdot(o, o)) / major;
}

/* A camera ray for a torus of major radius 1 and minor rho, from distance dist, looking
 * face-on (down the axis) or edge-on (in the equatorial plane), through the point (a, b)
 * of [0, 1)^2 mapped over the silhouette's near side: across the tube at +-1 +- 1.5 rho
 * (face-on, the outer and inner edges; edge-on, the tube's section, where the ray runs
 * along the core circle's tangent), and along over +-1.5 rho, so that most rays graze or
 * nearly graze. */
static inline void ref_view_ray(double a, double b, double rho, double dist, bool face_on, struct vec3 *o,
				struct vec3 *d)
{
	double across = (a < 0.5 ? 1 : -1) * (1 + rho * 1.5 * (4 * fmod(a, 0.5) - 1));
	double along = rho * 1.5 * (2 * b - 1);
	struct vec3 target = face_on ? v3(across, 0, along) : v3(0, along, across);
	*o = face_on ? v3(0, dist, 0) : v3(-dist, 0, 0);
	*d = vsub(target, *o);
}

/* The sign of dist^2 - minor^2, dist the distance to the core circle; 0 when p is too
 * near the surface for long double to tell (|dist - minor| below 1e-15 major). */
static inline int ref_inside(double major, double minor, struct vec3 p)
{
	long double q = sqrtl((long double)p.x * p.x + (long double)p.z * p.z);
	long double dq = q - major;
	long double v = sqrtl(dq * dq + (long double)p.y * p.y) - minor;
	if (fabsl(v) < 1e-15L * major)
		return 0;
	return v < 0 ? 1 : -1;
}

/* The signed distance of p to the torus's surface, in long double. */
static inline long double ref_distance(double major, double minor, struct vec3 p)
{
	long double q = sqrtl((long double)p.x * p.x + (long double)p.z * p.z);
	long double dq = q - major;
	return sqrtl(dq * dq + (long double)p.y * p.y) - minor;
}

/* How a method's roots t[0..n) differ from the reference's: 0 when they agree (each
 * root within rel (scale + s) / slope of the reference's, s and the tolerance in units of
 * the major radius), else REF_MISSING, REF_SPURIOUS or REF_VALUE. When the reference's
 * count is open, only its roots with a clear slope (twice flat) must be there. */
enum { REF_MISSING = 1, REF_SPURIOUS = 2, REF_VALUE = 4 };

static inline int ref_compare(const struct ref_roots *ref, double major, struct vec3 d, int n, const double *t,
			      double rel)
{
	double to_s = sqrt(vdot(d, d)) / major;
	int bad = 0;
	if (!ref->open) {
		if (n != ref->n)
			return n < ref->n ? REF_MISSING : REF_SPURIOUS;
		for (int i = 0; i < n; i++) {
			double tol = rel * (ref->scale + ref->t[i] * to_s) / fmax(ref->slope[i], 1e-300);
			if (!(fabs(t[i] - ref->t[i]) * to_s <= tol))
				bad |= REF_VALUE;
		}
		return bad;
	}
	for (int j = 0; j < ref->n; j++) {
		if (ref->slope[j] < 2 * ref->flat)
			continue;
		double tol = rel * (ref->scale + ref->t[j] * to_s) / ref->slope[j];
		bool found = false;
		for (int i = 0; i < n; i++)
			found |= fabs(t[i] - ref->t[j]) * to_s <= tol;
		if (!found)
			bad |= REF_MISSING;
	}
	return bad;
}

#endif
