/* quartic.c: the real roots of a monic quartic in an interval, none skipped. The
 * inflection points (roots of the quadratic p'', in closed form) cut the interval into
 * pieces where p is convex or concave; on each, Newton's method started from an end where
 * p p'' > 0 (Fourier's condition) converges monotonically and cannot jump over a root. */
#include "quartic.h"

#include <math.h>
#include <stdbool.h>

/* A cap on Newton's steps: quadratic convergence takes under 10, a double root (a ray
 * tangent to the torus) about one bit a step until rounding noise stops it. */
#define MAX_STEPS 80

/* Newton's steps stop where |p| is within NOISE times the sum of its terms' magnitudes:
 * the evaluation's rounding is gamma(6) of that sum, the coefficients' own a few times
 * more, and the caller polishes the last digits. */
#define NOISE 0x1p-48

/* p and p' at x, and *pa = sum |c_i| |x|^i (c_4 = 1), which bounds the rounding of p
 * (quartic_eval) */
static inline void eval(const double c[4], double x, double *p, double *dp, double *pa)
{
	double ax = fabs(x);
	*p = quartic_eval(c, x, dp);
	*pa = ((ax + fabs(c[3])) * ax + fabs(c[2])) * ax * ax + (fabs(c[1]) * ax + fabs(c[0]));
}

/* A sign change of p between x (where s p > 0) and end (where s p <= 0) narrowed by
 * bisection: the fallback when rounding has broken Newton's guarantee. */
static double bisect(const double c[4], double s, double x, double end)
{
	for (int i = 0; i < 200; i++) {
		double m = 0.5 * (x + end), p, dp, pa;
		if (m == x || m == end)
			break;
		eval(c, m, &p, &dp, &pa);
		if (s * p > 0)
			x = m;
		else
			end = m;
	}
	return end;
}

/* Whether Newton's step after `step` (the one before being `last`; pa and dp are the
 * magnitude sum and p' where step starts) would be within the noise, in x, of the point
 * step leads to: then that point is the root, and Newton's method need not evaluate p
 * there. In quadratic convergence the error after a step is about step^3 / last^2; a
 * double root's linear convergence never passes this test early. torus.c bounds each
 * root's error from p there all the same. */
static inline bool converged(double step, double last, double pa, double dp)
{
	return step * step * fabs(step * dp) <= last * last * NOISE * pa;
}

/* The one root of h = s p, convex on the piece, between x, where h > 0 (hx, dx: h and
 * h' there), and end, where h <= 0: Newton's method from x. Each tangent lies below h, so
 * every step lands short of the root or on it (Fourier's condition). It stops where h is
 * no longer above its rounding noise, or will not be after the next step; should rounding
 * make a step pass end or the slope turn, bisection takes over. */
static double newton(const double c[4], double s, double x, double hx, double dx, double end)
{
	double last = 0, pa = 0;
	for (int i = 0; i < MAX_STEPS; i++) {
		double step = -hx / dx;
		double nx = x + step;
		if (!((end - nx) * step > 0)) /* at or past end, or not a number */
			return bisect(c, s, x, end);
		if (converged(step, last, pa, dx))
			return nx;
		double p, dp;
		eval(c, nx, &p, &dp, &pa);
		hx = s * p;
		if (!(hx > NOISE * pa) || nx == x)
			return nx;
		dx = s * dp;
		if (!(dx * step < 0))
			return bisect(c, s, nx, end);
		x = nx;
		last = step;
	}
	return x;               /* a double root, converging slowly: a touching ray */
}

/* One of newton_pair's two Newton sequences: x, h and h' there, its last step, p's
 * magnitude sum there, and whether it has its root. */
struct side {
	double x, h, d, last, pa;
	bool done;
};

/* A step of side k (dir: +1 rising, -1 falling) towards its root, bounded by the other
 * side's x. Returns false when there is no root: the sides met, or the slope turned,
 * before either reached one. */
static inline bool side_step(const double c[4], double s, struct side *k, struct side *other, double dir)
{
	double step = -k->h / k->d;
	double nx = k->x + step;
	if (!((other->x - nx) * dir > 0)) { /* met the other side */
		k->x = other->x; /* a tangent: the two roots are one */
		k->done = true;
		return other->done;
	}
	if (converged(step, k->last, k->pa, k->d)) {
		k->x = nx;
		k->done = true;
		return true;
	}
	double p, dp;
	eval(c, nx, &p, &dp, &k->pa);
	k->done = !(s * p > NOISE * k->pa) || nx == k->x;
	k->x = nx;
	k->h = s * p;
	k->d = s * dp;
	k->last = step;
	if (!k->done && !(k->d * dir < 0)) { /* the slope turned, still above 0 */
		if (!other->done)
			return false;
		k->x = bisect(c, s, nx, other->x);
		k->done = true;
	}
	return true;
}

/* The two roots, or none, of h = s p, convex on [a, b], positive at both ends, falling at
 * a and rising at b (ha, da, hb, db: h and h' there): Newton's method from both ends at
 * once, the two sequences independent so that their steps overlap in the processor. The
 * left one rises to the first root and the right one falls to the second, neither passing
 * it (Fourier's condition); if they cross, or a slope turns, before either reaches a root,
 * there is none. Once one has its root, the other is sure of one between. Returns 0 or 2. */
static int newton_pair(const double c[4], double s, double a, double ha, double da, double b, double hb, double db,
		       double r[2])
{
	struct side l = { a, ha, da, 0, 0, false }, u = { b, hb, db, 0, 0, false };
	for (int i = 0; i < MAX_STEPS && !(l.done && u.done); i++) {
		if (!l.done && !side_step(c, s, &l, &u, 1))
			return 0;
		if (!u.done && !side_step(c, s, &u, &l, -1))
			return 0;
	}
	r[0] = l.x;             /* or, out of steps, a double root */
	r[1] = u.x;
	return 2;
}

/* The roots of p inside the piece (a, b) on which h = s p is convex; ha, da, hb, db are h
 * and h' at the ends. Returns how many (0, 1 or 2), ascending, in r. */
static int piece_roots(const double c[4], double s, double a, double b, double ha, double da, double hb,
		       double db, double r[2])
{
	/* the sign of h just inside each end: its value's, or where that is 0 its slope's,
	 * or where both are 0, positive (h is convex) */
	bool pa = ha > 0 || (ha == 0 && da >= 0);
	bool pb = hb > 0 || (hb == 0 && db <= 0);
	if (pa && pb) {
		/* 0 or 2 roots. None when h rises from a or falls to b, or when the two end
		 * tangents, which lie below h, cross above 0: most misses stop here. */
		if (da >= 0 || db <= 0)
			return 0;
		double xa = (hb - ha - db * (b - a)) / (da - db);
		if (ha + da * xa > 0)
			return 0;
		return newton_pair(c, s, a, ha, da, b, hb, db, r);
	}
	if (pa) {
		r[0] = newton(c, s, a, ha, da, b);
		return 1;
	}
	if (pb) {
		r[0] = newton(c, s, b, hb, db, a);
		return 1;
	}
	return 0;               /* convex and negative at both ends */
}

void quartic_start(struct quartic_scan *q, const double c[4], double lo, double hi)
{
	/* the piece ends: lo, the inflection points inside (lo, hi), hi */
	int ne = 0;
	q->e[ne++] = lo;
	q->s = 1;               /* +1 where p is convex, -1 where concave */
	double disc = 9 * c[3] * c[3] - 24 * c[2]; /* of p''/2 = 6 x^2 + 3 c3 x + c2 */
	if (disc > 0) {
		double r = -0.5 * (3 * c[3] + copysign(sqrt(disc), c[3]));
		double k0 = r * (1.0 / 6), k1 = c[2] / r;
		if (k0 > k1) {
			double tmp = k0;
			k0 = k1;
			k1 = tmp;
		}
		if (lo >= k0 && lo < k1)
			q->s = -1;
		if (k0 > lo && k0 < hi)
			q->e[ne++] = k0;
		if (k1 > lo && k1 < hi)
			q->e[ne++] = k1;
	}
	q->e[ne++] = hi;
	q->ne = ne;
	q->i = 0;
	q->last = -INFINITY;
	double pa;
	eval(c, lo, &q->p, &q->dp, &pa);
}

int quartic_next(struct quartic_scan *q, const double c[4], double from, double r[4])
{
	double a, b, s, p, dp, pa;
	for (;;) {
		if (q->i + 1 >= q->ne)
			return -1;
		a = q->e[q->i];
		b = q->e[++q->i];
		s = q->s;
		/* p at the piece's far end, evaluated only now: a caller that stops early
		 * saves it */
		eval(c, b, &p, &dp, &pa);
		if (b >= from)
			break;
		q->s = -s;      /* the piece lies before from: passed over unsolved */
		q->p = p;
		q->dp = dp;
	}
	int n = 0;
	if (a == q->e[0] && q->p == 0)
		r[n++] = a;
	n += piece_roots(c, s, a, b, s * q->p, s * q->dp, s * p, s * dp, r + n);
	if (p == 0 && (n > 0 ? r[n - 1] : q->last) < b)
		r[n++] = b;     /* a root exactly at a piece's end, once */
	if (n > 0)
		q->last = r[n - 1];
	q->s = -s;
	q->p = p;
	q->dp = dp;
	return n;
}
