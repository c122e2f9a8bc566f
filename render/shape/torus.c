/* torus.c: ray and torus. The ray is clipped, in units of the major radius, to the slab and
 * cylinders that bound the torus; the quartic is formed at each clipped piece's start, where
 * its coefficients are small, and solved by quartic.c; each root is polished on the distance
 * to the tube, which is accurate where the quartic cancels (thin tori). */
#include "torus.h"

#include <math.h>

#include "quartic.h"
#include "rounding.h"

/* How much the bounding sphere's radius is widened, relative: far above its rounding, so
 * that a ray tangent to it at the torus's equator is not lost. */
#define SPHERE_WIDEN 0x1p-32
/* How much the bounding slab and cylinders stand off the torus, relative to the minor
 * radius. A ray crossing the torus where it touches one of them (its top and bottom
 * circles, its outer and inner equators) has a root at the clip's end if they touch, and
 * the quartic's sign there is rounding noise: the root can be lost. Standing off by r/1024,
 * the clipped piece starts where the quartic is at least 8 r^2 / 1024 (in units of R),
 * far above its rounding (a few ulps of 1) for the thin tori of LANGUAGE.md. */
#define SHELL_WIDEN 0x1p-10

/* fmax and fmin without their NaN rules, which gcc keeps out of line */
static inline double max2(double a, double b) { return a > b ? a : b; }
static inline double min2(double a, double b) { return a < b ? a : b; }

/* The interval of x where o + x u is within radius k of the y axis, a 2-D Hearn-Baker
 * discriminant (NUMERICS.md section 4): a = u.x^2 + u.z^2 > 0, ia = 1/a, b = o.x u.x + o.z
 * u.z, h = o.x u.z - o.z u.x (a times the squared distance of the line from the axis is
 * h^2). False when the line stays outside. */
static bool cylinder(double a, double ia, double b, double h, double k, double *x0, double *x1)
{
	double disc = a * k * k - h * h;
	if (disc < 0)
		return false;
	double s = sqrt(disc);
	*x0 = (-b - s) * ia;
	*x1 = (-b + s) * ia;
	return true;
}

/* Newton's method from x, a root of the quartic on o + x u, on g, the signed distance to
 * the tube (|P - c| - rho, c the core circle's point nearest P). g's rounding is a few ulps
 * of |P| and 1, where the quartic's, for a thin torus, is larger by 1/rho. pos_err bounds
 * the error of the point o + x u against the exact ray. Returns the root; *err bounds its
 * error. */
static double polish(struct vec3 o, struct vec3 u, double rho, double x, double pos_err, double *err)
{
	for (int i = 0; i < 2; i++) {
		struct vec3 p = vmad(o, x, u);
		double q = sqrt(p.x * p.x + p.z * p.z);
		double dq = q - 1;
		double del = sqrt(dq * dq + p.y * p.y);
		double g = del - rho;
		/* dg/dx, the unit vector from c to P dotted with u, is num / (q del) */
		double num = dq * (p.x * u.x + p.z * u.z) + p.y * u.y * q;
		double qd = q * del, inv = 1 / num;
		double e = pos_err + rounding_gamma(8) * (q + del + rho);
		double step = -g * qd * inv, idg = fabs(qd * inv);
		/* |g''| < k along a unit ray, so after the step |g| < k step^2 / 2. Where that
		 * is not well below the step's own size, the ray is tangent to the tube within
		 * the quartic's rounding and Newton's step is not to be trusted: keep the root.
		 * The factors 2 cover the change of dg over the error bound. */
		double k = (q + del) / qd;
		if (!(4 * k * fabs(step) * idg <= 1)) {
			*err = 2 * (fabs(g) + e) * idg;
			return x;
		}
		x += step;
		double rest = k * step * step;
		*err = (2 * e + rest) * idg;
		if (rest <= e)
			break;  /* a second step would gain nothing */
	}
	return x;
}

/* torus_roots() and torus_first(): the roots in (t_after, tmax) that pass the error
 * bound's test, ascending, at most 4; with first, only the smallest is sought (in t[0]):
 * the pieces are solved in ray order and the search stops after the first that has one. */
static int roots(double major, double minor, struct vec3 o, struct vec3 d, double t_after, double tmax, bool first,
		 double t[4])
{
	double len = vlen(d);
	if (!(len > 0) || !(tmax > 0))
		return 0;
	/* units of the major radius, and a unit direction: x in these is t len / major */
	double inv = 1 / major, ilen = 1 / len;
	double rho = minor * inv, to_t = major * ilen;
	struct vec3 u = vscale(d, ilen);
	struct vec3 on = vscale(o, inv);

	/* Move the origin to the ray's point nearest the centre, where |o1| is at most the
	 * torus's size if the ray meets its bounding sphere: from there on no value is large,
	 * however far the ray came from. The move's rounding, a few ulps of |on|, shifts the
	 * line: a far ray's inherent uncertainty. */
	/* the reciprocals the clip needs, here: their divisions overlap the work below
	 * instead of waiting at its end (an infinity, for u.y or a 0, is not used) */
	double a = u.x * u.x + u.z * u.z;
	double iy = 1 / u.y, ia = 1 / a;
	double sm = -vdot(on, u);
	struct vec3 o1 = vmad(on, sm, u);
	double big = 1 + rho;
	if (vdot(o1, o1) > big * big * (1 + SPHERE_WIDEN))
		return 0;
	/* o1 + x u for x in [lo, hi] is the ray's part with t in (0, tmax) */
	double lo = -sm, hi = tmax / to_t - sm;

	/* the slab |y| <= rho, stood off */
	double slab = rho * (1 + SHELL_WIDEN);
	if (u.y == 0) {
		if (fabs(o1.y) > slab)
			return 0;
	} else {
		double y0 = (-slab - o1.y) * iy, y1 = (slab - o1.y) * iy;
		lo = max2(lo, min2(y0, y1));
		hi = min2(hi, max2(y0, y1));
		if (!(lo <= hi))
			return 0;
	}
	/* the cylinders of radius 1 + rho (outer) and 1 - rho (the hole), stood off */
	double b = o1.x * u.x + o1.z * u.z;
	double h = o1.x * u.z - o1.z * u.x;
	double kout = 1 + slab, kin = 1 - slab;
	/* Most rays that miss a thin torus cross the slab away from the tube: the squared
	 * distance to the axis, convex in x, stays outside [kin^2, kout^2] over [lo, hi].
	 * Its largest value is at an end, its least at an end or at the line's nearest point
	 * to the axis (h^2 / a there). Checked without a division or a root. */
	double xl = o1.x + lo * u.x, zl = o1.z + lo * u.z, xh = o1.x + hi * u.x, zh = o1.z + hi * u.z;
	double ql = xl * xl + zl * zl, qh = xh * xh + zh * zh;
	if (hi < INFINITY && max2(ql, qh) < kin * kin)
		return 0;       /* in the hole throughout */
	bool vertex_in = a * lo + b < 0 && a * hi + b > 0;
	if (vertex_in ? h * h > kout * kout * a : min2(ql, qh) > kout * kout)
		return 0;       /* outside throughout */

	double plo[2], phi[2];
	int np = 0;
	if (a == 0) {           /* along the axis: the distance to it stays o1's */
		plo[np] = lo;
		phi[np++] = hi;
	} else {
		double x0, x1;
		if (!cylinder(a, ia, b, h, kout, &x0, &x1))
			return 0;
		lo = max2(lo, x0);
		hi = min2(hi, x1);
		if (!(lo <= hi))
			return 0;
		if (h * h < kin * kin * a && cylinder(a, ia, b, h, kin, &x0, &x1)) {
			if (lo < x0) {
				plo[np] = lo;
				phi[np++] = min2(hi, x0);
			}
			if (x1 < hi) {
				plo[np] = max2(lo, x1);
				phi[np++] = hi;
			}
		} else {
			plo[np] = lo;
			phi[np++] = hi;
		}
	}

	/* t_after in x (from o1), less a margin that holds every root a later piece of the
	 * clip or of the quartic could report before it: a root stays within its piece but
	 * for the polish, whose steps are each under a quarter of the tube's radius (see
	 * polish()), and the conversion's rounding */
	double x_after = t_after / to_t - sm;
	x_after -= rho + rounding_gamma(8) * (fabs(x_after) + fabs(sm) + 1);
	int n = 0;
	for (int k = 0; k < np; k++) {
		if (phi[k] < x_after)
			continue;
		/* the quartic in x on o2 + x u, x in [0, w]: (|P|^2 + 1 - rho^2)^2 - 4 (P.x^2 +
		 * P.z^2), the torus's implicit function, negative inside */
		double start = plo[k], w = phi[k] - start;
		struct vec3 o2 = vmad(o1, start, u);
		double bb = vdot(o2, u);
		double m = vdot(o2, o2) + (1 - rho) * (1 + rho);
		double b2 = o2.x * u.x + o2.z * u.z;
		double c2 = o2.x * o2.x + o2.z * o2.z;
		double c[4] = { m * m - 4 * c2, 4 * bb * m - 8 * b2, 4 * bb * bb + 2 * m - 4 * a, 4 * bb };
		/* sums of the magnitudes of each coefficient's terms: gamma(8) of each bounds its
		 * rounding (the move's is in pos_err below) */
		double ab = fabs(o2.x * u.x) + fabs(o2.y * u.y) + fabs(o2.z * u.z);
		double am = vdot(o2, o2) + 1 + rho * rho;
		double mag[4] = { m * m + 4 * c2, 4 * ab * am + 8 * (fabs(o2.x * u.x) + fabs(o2.z * u.z)),
				  4 * ab * ab + 2 * am + 4 * a, 4 * ab };
		/* the rounding of o2 against the exact ray: of on, of the two moves, of u's
		 * direction over the distance travelled */
		double base = fabs(on.x) + fabs(on.y) + fabs(on.z) + fabs(sm) + fabs(start) + 2;
		double grad = 2 * rho * (2 + rho) * (2 + rho) * (1 + 0x1p-3);
		struct quartic_scan scan;
		quartic_start(&scan, c, 0, w);
		double x[4], best = INFINITY;
		for (int nx; (nx = quartic_next(&scan, c, x_after - start, x)) >= 0;) {
			for (int i = 0; i < nx && n < 4; i++) {
				double xi = x[i], ax = fabs(xi), pos_err = rounding_gamma(8) * (base + ax);
				/* The quartic's own error bound at its root: its residual and
				 * rounding (the evaluation's gamma(6) and the coefficients'
				 * gamma(8), both of the magnitudes), and the point's error times
				 * |grad F| <= 2 rho (2 + rho)^2 on the surface, over the slope.
				 * Where it is within 16 times the point's error alone, as for a
				 * fat torus, the root stands; else the quartic has cancelled (a
				 * thin torus) and the root is polished on the tube's distance. */
				double dp, dm;
				double p = quartic_eval(c, xi, &dp), pm = quartic_eval(mag, ax, &dm);
				double noise = fabs(p) + rounding_gamma(16) * pm, err, xr = xi;
				if (noise <= 16 * grad * pos_err)
					err = 2 * (noise + grad * pos_err) / fabs(dp);
				else
					xr = polish(o2, u, rho, xi, pos_err, &err);
				double s = sm + start + xr;
				double tt = s * to_t;
				double terr = (err + rounding_gamma(3) * (fabs(sm) + fabs(start) + fabs(xr))) * to_t +
					      rounding_gamma(6) * fabs(tt);
				if (tt > terr && tt > t_after && tt < tmax) {
					t[n++] = tt;
					best = min2(best, xr);
				}
			}
			/* A later piece's roots (of the quartic or of the clip) lie beyond this
			 * one's end, and the polish moves one below the best only for a
			 * tangent pair astride it: then the search goes on. */
			if (first && n > 0 && best < scan.e[scan.i])
				goto sort;
		}
	}
sort:
	/* ascending: the polish can swap a pair of roots of a tangent ray */
	for (int i = 1; i < n; i++)
		for (int j = i; j > 0 && t[j] < t[j - 1]; j--) {
			double tmp = t[j];
			t[j] = t[j - 1];
			t[j - 1] = tmp;
		}
	return n;
}

int torus_roots(double major, double minor, struct vec3 o, struct vec3 d, double tmax, double t[4])
{
	return roots(major, minor, o, d, 0, tmax, false, t);
}

bool torus_first(double major, double minor, struct vec3 o, struct vec3 d, double t_after, double tmax, double *t)
{
	double r[4];
	if (!roots(major, minor, o, d, max2(t_after, 0), tmax, true, r))
		return false;
	*t = r[0];
	return true;
}

void torus_surface(double major, double minor, struct vec3 p, struct vec3 *on, struct vec3 *p_err,
		   struct vec3 *normal)
{
	double q = sqrt(p.x * p.x + p.z * p.z);
	/* the horizontal unit vector from the axis towards p (any one on the axis) */
	double hx = 1, hz = 0;
	if (q > 0) {
		hx = p.x / q;
		hz = p.z / q;
	}
	/* p - c for the core circle's point c = major (hx, 0, hz) nearest p, from q - major:
	 * p.x - c.x would cancel */
	double dq = q - major;
	struct vec3 v = v3(dq * hx, p.y, dq * hz);
	double len = vlen(v);
	/* on the core circle every direction in the meridian plane is as near: outward */
	struct vec3 n = len > 0 ? vscale(v, 1 / len) : v3(hx, 0, hz);
	struct vec3 c = v3(major * hx, 0, major * hz);
	*on = vmad(c, minor, n);
	*normal = n;
	/* c + minor n lies on the torus for any unit n in the meridian plane: the error is
	 * the rounding of h's and n's lengths and directions, a few ulps of c and of minor,
	 * and of the sum */
	double common = rounding_gamma(7) * minor;
	*p_err = vadd(vadd(vscale(vabs(c), rounding_gamma(7)), vscale(vabs(*on), rounding_gamma(3))), v3s(common));
}

/* ---- exact arithmetic for torus_inside's undecided case: Shewchuk's expansions
 * ("Adaptive Precision Floating-Point Arithmetic and Fast Robust Geometric Predicates",
 * 1997). An expansion is a sum of doubles, nonoverlapping, in increasing magnitude; its
 * sign is its last component's. ---- */

#define EXP_MAX 256

static inline void two_sum(double a, double b, double *x, double *y)
{
	double s = a + b, bv = s - a, av = s - bv;
	*x = s;
	*y = (a - av) + (b - bv);
}

static inline void split(double a, double *hi, double *lo)
{
	double c = 134217729.0 * a; /* 2^27 + 1 */
	double big = c - a;
	*hi = c - big;
	*lo = a - *hi;
}

static inline void two_product(double a, double b, double *x, double *y)
{
	double p = a * b, ah, al, bh, bl;
	split(a, &ah, &al);
	split(b, &bh, &bl);
	double err = ((p - ah * bh) - al * bh) - ah * bl;
	*x = p;
	*y = al * bl - err;
}

static inline void fast_two_sum(double a, double b, double *x, double *y) /* |a| >= |b| */
{
	double s = a + b;
	*x = s;
	*y = b - (s - a);
}

/* e in fewer components, in place (Shewchuk's compress): keeps the products short */
static int compress(int n, double *e)
{
	double g[EXP_MAX], q = e[n - 1], qn, small;
	int bottom = n - 1;
	for (int i = n - 2; i >= 0; i--) {
		fast_two_sum(q, e[i], &qn, &small);
		if (small != 0) {
			g[bottom--] = qn;
			q = small;
		} else {
			q = qn;
		}
	}
	int top = 0;
	for (int i = bottom + 1; i < n; i++) {
		fast_two_sum(g[i], q, &qn, &small);
		if (small != 0)
			e[top++] = small;
		q = qn;
	}
	e[top++] = q;
	return top;
}

/* h = e + b (Shewchuk's grow_expansion_zeroelim; h may be e); returns h's length */
static int grow(int n, const double *e, double b, double *h)
{
	double q = b;
	int k = 0;
	for (int i = 0; i < n; i++) {
		double hh;
		two_sum(q, e[i], &q, &hh);
		if (hh != 0)
			h[k++] = hh;
	}
	if (q != 0 || k == 0)
		h[k++] = q;
	return k;
}

/* e += f, compressed (in place, e has room for EXP_MAX); returns e's length */
static int add(int n, double *e, int m, const double *f)
{
	for (int j = 0; j < m; j++)
		n = grow(n, e, f[j], e);
	return compress(n, e);
}

/* h = e b (Shewchuk's scale_expansion_zeroelim) */
static int scale(int n, const double *e, double b, double *h)
{
	double q, hh, p1, p0, sum;
	int k = 0;
	two_product(e[0], b, &q, &hh);
	if (hh != 0)
		h[k++] = hh;
	for (int i = 1; i < n; i++) {
		two_product(e[i], b, &p1, &p0);
		two_sum(q, p0, &sum, &hh);
		if (hh != 0)
			h[k++] = hh;
		two_sum(p1, sum, &q, &hh);
		if (hh != 0)
			h[k++] = hh;
	}
	if (q != 0 || k == 0)
		h[k++] = q;
	return k;
}

/* h = e f */
static int mul(int n, const double *e, int m, const double *f, double *h)
{
	double tmp[EXP_MAX];
	int k = scale(n, e, f[0], h);
	for (int j = 1; j < m; j++) {
		int l = scale(n, e, f[j], tmp);
		k = add(k, h, l, tmp);
	}
	return k;
}

/* The exact sign of (x^2 + y^2 + z^2 + R^2 - r^2)^2 - 4 R^2 (x^2 + z^2). The lengths stay
 * below EXP_MAX: 5 squares of 2 parts make S of at most 10 parts, S^2 at most 200 (and
 * compression makes them a few). */
static int exact_sign(double major, double minor, struct vec3 p)
{
	double sq[5][2];
	double in[5] = { p.x, p.z, p.y, major, minor };
	for (int i = 0; i < 5; i++)
		two_product(in[i], in[i], &sq[i][1], &sq[i][0]);
	double a[EXP_MAX], s[EXP_MAX], s2[EXP_MAX], r2a[EXP_MAX];
	int na = grow(1, &sq[0][0], sq[0][1], a);
	na = add(na, a, 2, sq[1]);
	int ns = na;
	for (int i = 0; i < na; i++)
		s[i] = a[i];
	ns = add(ns, s, 2, sq[2]);
	ns = add(ns, s, 2, sq[3]);
	double neg[2] = { -sq[4][0], -sq[4][1] };
	ns = add(ns, s, 2, neg);
	int ns2 = mul(ns, s, ns, s, s2);
	double four_r2[2] = { -4 * sq[3][0], -4 * sq[3][1] };
	int nr = mul(na, a, 2, four_r2, r2a);
	ns2 = add(ns2, s2, nr, r2a);
	double top = s2[ns2 - 1];
	return (top > 0) - (top < 0);
}

bool torus_inside(double major, double minor, struct vec3 p)
{
	/* The sign is that of dist^2 - r^2, dist the distance to the core circle, as the
	 * implicit function is (dist^2 - r^2) ((q + R)^2 + y^2 - r^2), q the distance to the
	 * axis, and its second factor positive. (q - R)^2 + (y - r)(y + r) cancels only in q
	 * - R, by a few ulps of q: the bound below, from Higham's rules, decides all but the
	 * points within a few ulps of the surface, and those go to exact arithmetic. */
	double q = sqrt(p.x * p.x + p.z * p.z);
	double dq = q - major;
	double w = (p.y - minor) * (p.y + minor);
	double v = dq * dq + w;
	double ed = rounding_gamma(3) * (q + fabs(dq));
	double bound = 2 * (ed * (2 * fabs(dq) + ed) + rounding_gamma(4) * (dq * dq + fabs(w) + fabs(v)));
	if (v < -bound)
		return true;
	if (v > bound)
		return false;
	return exact_sign(major, minor, p) < 0;
}
