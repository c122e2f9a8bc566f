/* part.c: the leaf parts of part.h in their canonical spaces: crossings by stable
 * quadratics (the sphere's Hearn-Baker form, NUMERICS.md section 4) or slabs, with the
 * origin first moved to the canonical bounding box so that the coefficients stay small;
 * the surface point computed from the shape, with a bound on its error that covers the
 * maps to and from canonical space (NUMERICS.md section 2). */
#include "part.h"

#include <math.h>

#include "torus.h"

/* The ray in p's canonical space: the same t on both. */
static void to_canonical(const struct part *p, const struct ray *r, struct vec3 *o, struct vec3 *d)
{
	if (p->moved) {
		*o = affine_point(&p->to_object, r->o);
		*d = affine_vector(&p->to_object, r->d);
	} else {
		*o = r->o;
		*d = r->d;
	}
}

/* The parameter interval in which o + t d lies in the box [lo, hi], by slabs; false when
 * it misses. A zero direction component keeps the interval when the origin is within that
 * slab: no 0 * inf. */
static bool slabs(struct vec3 o, struct vec3 d, const double lo[3], const double hi[3], double *t0, double *t1)
{
	double near = -INFINITY, far = INFINITY;
	for (int k = 0; k < 3; k++) {
		double ok = vget(&o, k), dk = vget(&d, k);
		if (dk == 0) {
			if (ok < lo[k] || ok > hi[k])
				return false;
			continue;
		}
		double a = (lo[k] - ok) / dk, b = (hi[k] - ok) / dk;
		if (a > b) {
			double s = a;
			a = b;
			b = s;
		}
		near = a > near ? a : near;
		far = b < far ? b : far;
	}
	*t0 = near;
	*t1 = far;
	return near <= far;
}

/* Adds t to the list when it lies in (0, tmax) and is not already its last entry. */
static int keep(double *t, int n, double v, double tmax)
{
	if (v > 0 && v < tmax && (n == 0 || t[n - 1] != v))
		t[n++] = v;
	return n;
}

static void sort(double *t, int n)
{
	for (int i = 1; i < n; i++)
		for (int j = i; j > 0 && t[j - 1] > t[j]; j--) {
			double s = t[j];
			t[j] = t[j - 1];
			t[j - 1] = s;
		}
}

/* The roots of a t^2 + 2 h t + c = 0 in increasing order, stably (no cancellation
 * between h and the square root); false when there are none. a may be 0. */
static bool quadratic(double a, double h, double c, double *r0, double *r1)
{
	if (a == 0) {
		if (h == 0)
			return false;
		*r0 = *r1 = -c / (2 * h);
		return true;
	}
	double disc = h * h - a * c;
	if (disc < 0)
		return false;
	double q = -(h + copysign(sqrt(disc), h));
	if (q == 0) {
		*r0 = *r1 = 0;
		return true;
	}
	double x = q / a, y = c / q;
	*r0 = x < y ? x : y;
	*r1 = x < y ? y : x;
	return true;
}

/* The unit sphere: the Hearn-Baker discriminant along the unit direction. */
static int sphere_cross(struct vec3 o, struct vec3 d, double tmax, double t[4])
{
	double len = vlen(d);
	struct vec3 u = vscale(d, 1 / len);
	double b = vdot(o, u);
	struct vec3 perp = vsub(o, vscale(u, b));
	double disc = 1 - vdot(perp, perp);
	if (disc < 0)
		return 0;
	double q = -(b + copysign(sqrt(disc), b));
	if (q == 0)
		return 0;
	double x = (vdot(o, o) - 1) / q, y = q;
	int n = keep(t, 0, (x < y ? x : y) / len, tmax);
	return keep(t, n, (x < y ? y : x) / len, tmax);
}

static int box_cross(const struct part *p, struct vec3 o, struct vec3 d, double tmax, double t[4])
{
	double t0, t1;
	if (!slabs(o, d, p->a, p->a + 3, &t0, &t1) || !(t0 < t1))
		return 0; /* a miss, or an edge touched */
	int n = keep(t, 0, t0, tmax);
	return keep(t, n, t1, tmax);
}

static const double cone_lo[3] = { -1, 0, -1 }, cone_hi[3] = { 1, 1, 1 };

/* The cone's side x^2 + z^2 = (r0 + k y)^2, 0 <= y <= 1, and its end discs. The origin
 * is moved to where the ray enters the bounding box first. */
static int cone_cross(const struct part *p, struct vec3 o, struct vec3 d, double tmax, double t[4])
{
	double b0, b1;
	if (!slabs(o, d, cone_lo, cone_hi, &b0, &b1) || !(b1 > 0))
		return 0;
	double s = b0 > 0 ? b0 : 0;
	struct vec3 q = vmad(o, s, d);
	double r0 = p->a[0], r1 = p->a[1], k = r1 - r0;
	double roots[4];
	int n = 0;
	double x0, x1;
	if (k == 0) {
		/* the cylinder: Hearn-Baker in the xz plane */
		double len = sqrt(d.x * d.x + d.z * d.z);
		if (len > 0) {
			double ux = d.x / len, uz = d.z / len;
			double b = q.x * ux + q.z * uz;
			double px = q.x - b * ux, pz = q.z - b * uz;
			double disc = r0 * r0 - (px * px + pz * pz);
			double h = -(b + copysign(sqrt(disc > 0 ? disc : 0), b));
			if (disc >= 0 && h != 0) {
				double c = q.x * q.x + q.z * q.z - r0 * r0;
				roots[n++] = c / h / len;
				roots[n++] = h / len;
			}
		}
	} else {
		double rq = r0 + k * q.y;
		if (quadratic(d.x * d.x + d.z * d.z - k * k * d.y * d.y, q.x * d.x + q.z * d.z - rq * k * d.y,
		              q.x * q.x + q.z * q.z - rq * rq, &x0, &x1)) {
			roots[n++] = x0;
			if (x1 != x0)
				roots[n++] = x1;
		}
	}
	/* side roots count only between the end planes */
	int m = 0;
	for (int i = 0; i < n; i++) {
		double y = q.y + roots[i] * d.y;
		if (y >= 0 && y <= 1)
			roots[m++] = roots[i];
	}
	if (!p->open && d.y != 0)
		for (int e = 0; e < 2; e++) {
			double r = e ? r1 : r0;
			double u = (e - q.y) / d.y;
			double x = q.x + u * d.x, z = q.z + u * d.z;
			if (r > 0 && x * x + z * z <= r * r)
				roots[m++] = u;
		}
	sort(roots, m);
	int c = 0;
	for (int i = 0; i < m; i++)
		c = keep(t, c, s + roots[i], tmax);
	return c;
}

static int disc_cross(const struct part *p, struct vec3 o, struct vec3 d, double tmax, double t[4])
{
	if (d.y == 0)
		return 0;
	double u = -o.y / d.y;
	double x = o.x + u * d.x, z = o.z + u * d.z, r2 = x * x + z * z;
	if (r2 > 1 || r2 < p->a[0] * p->a[0])
		return 0;
	return keep(t, 0, u, tmax);
}

/* A plane part keeps its world normal a[0..2] and offset a[3]. */
static int plane_cross(const struct part *p, const struct ray *r, double tmax, double t[4])
{
	struct vec3 n = v3(p->a[0], p->a[1], p->a[2]);
	double denom = vdot(n, r->d);
	if (denom == 0)
		return 0;
	return keep(t, 0, (p->a[3] - vdot(n, r->o)) / denom, tmax);
}

int part_crossings(const struct part *p, const struct ray *r, double tmax, double t[4])
{
	if (p->kind == PART_PLANE)
		return plane_cross(p, r, tmax, t);
	struct vec3 o, d;
	to_canonical(p, r, &o, &d);
	switch (p->kind) {
	case PART_SPHERE: return sphere_cross(o, d, tmax, t);
	case PART_BOX: return box_cross(p, o, d, tmax, t);
	case PART_CONE: return cone_cross(p, o, d, tmax, t);
	case PART_DISC: return disc_cross(p, o, d, tmax, t);
	case PART_TORUS: return torus_roots(p->a[0], p->a[1], o, d, tmax, t);
	default: return 0;
	}
}

bool part_next(const struct part *p, const struct ray *r, double t_after, double tmax, double *t)
{
	if (p->kind == PART_TORUS) {
		struct vec3 o, d;
		to_canonical(p, r, &o, &d);
		return torus_first(p->a[0], p->a[1], o, d, t_after, tmax, t);
	}
	double c[4];
	int n = part_crossings(p, r, tmax, c);
	for (int i = 0; i < n; i++)
		if (c[i] > t_after) {
			*t = c[i];
			return true;
		}
	return false;
}

/* The error of o + t d, coordinate by coordinate. */
static struct vec3 along_error(struct vec3 o, struct vec3 d, double t)
{
	return vscale(vadd(vabs(o), vabs(vscale(d, t))), rounding_gamma(3));
}

/* Which face of the box p's canonical point c lies on: 2 k for lo on axis k, 2 k + 1 for hi. */
static int box_face(const struct part *p, struct vec3 c)
{
	int best = 0;
	double best_gap = INFINITY;
	for (int f = 0; f < 6; f++) {
		double gap = fabs(vget(&c, f / 2) - p->a[f % 2 * 3 + f / 2]);
		if (gap < best_gap) {
			best_gap = gap;
			best = f;
		}
	}
	return best;
}

/* The point of leaf p nearest canonical c (c on the surface but for rounding), its error
 * bound e (from err, c's) and the outward canonical normal. */
static void canonical_surface(const struct part *p, struct vec3 *c, struct vec3 *e, struct vec3 *n)
{
	switch (p->kind) {
	case PART_SPHERE: {
		double len = vlen(*c);
		*n = len > 0 ? vscale(*c, 1 / len) : v3(0, 1, 0);
		*c = *n;
		*e = vscale(vabs(*c), rounding_gamma(5));
		return;
	}
	case PART_BOX: {
		int f = box_face(p, *c), k = f / 2;
		double *cc = &c->x, *ee = &e->x, *nn = &n->x;
		cc[k] = p->a[f % 2 * 3 + k];
		ee[k] = 0;
		*n = v3s(0);
		nn[k] = f % 2 ? 1 : -1;
		return;
	}
	case PART_CONE: {
		double r0 = p->a[0], r1 = p->a[1], k = r1 - r0;
		double rad = sqrt(c->x * c->x + c->z * c->z), ry = r0 + k * c->y;
		double side = fabs(rad - ry);
		bool bottom = !p->open && r0 > 0 && fabs(c->y) < side && fabs(c->y) <= fabs(c->y - 1);
		bool top = !p->open && r1 > 0 && fabs(c->y - 1) < side && fabs(c->y - 1) < fabs(c->y);
		if (bottom || top) {
			c->y = top ? 1 : 0;
			e->y = 0;
			*n = v3(0, top ? 1 : -1, 0);
			return;
		}
		double ux = rad > 0 ? c->x / rad : 1, uz = rad > 0 ? c->z / rad : 0;
		c->x = ux * ry;
		c->z = uz * ry;
		e->x += rounding_gamma(5) * fabs(c->x);
		e->z += rounding_gamma(5) * fabs(c->z);
		*n = vunit(v3(ux, -k, uz));
		return;
	}
	case PART_DISC:
		c->y = 0;
		e->y = 0;
		*n = v3(0, 1, 0);
		return;
	case PART_TORUS: {
		struct vec3 on, on_err;
		torus_surface(p->a[0], p->a[1], *c, &on, &on_err, n);
		*c = on;
		*e = vadd(*e, on_err);
		return;
	}
	default:
		return;
	}
}

void part_surface(const struct part *p, const struct ray *r, double t, struct surface_point *sp)
{
	if (p->kind == PART_PLANE) {
		struct vec3 n = v3(p->a[0], p->a[1], p->a[2]);
		struct vec3 q = vmad(r->o, t, r->d);
		sp->p = vsub(q, vscale(n, vdot(n, q) - p->a[3]));
		sp->p_err = vscale(vadd(vmax(vabs(q), vabs(sp->p)), v3s(fabs(p->a[3]))), rounding_gamma(7));
		sp->ng = n;
	} else {
		struct vec3 o, d;
		to_canonical(p, r, &o, &d);
		struct vec3 c = vmad(o, t, d), e = along_error(o, d, t), n;
		canonical_surface(p, &c, &e, &n);
		if (p->moved) {
			sp->p = affine_point(&p->to_world, c);
			/* the error of the point, and of mapping it back to canonical space, where a
			 * ray spawned from it is tested again */
			struct vec3 back = affine_error(&p->to_object, sp->p, v3s(0));
			sp->p_err = affine_error(&p->to_world, c, vadd(e, back));
			sp->ng = vunit(affine_normal(&p->to_object, n));
		} else {
			sp->p = c;
			sp->p_err = e;
			sp->ng = n;
		}
	}
	if (p->inverse)
		sp->ng = vneg(sp->ng);
	sp->ns = sp->ng;
}

bool part_inside_leaf(const struct part *p, struct vec3 q)
{
	bool in;
	if (p->kind == PART_PLANE) {
		in = p->a[0] * q.x + p->a[1] * q.y + p->a[2] * q.z < p->a[3];
	} else {
		struct vec3 c = p->moved ? affine_point(&p->to_object, q) : q;
		switch (p->kind) {
		case PART_SPHERE:
			in = vdot(c, c) < 1;
			break;
		case PART_BOX:
			in = c.x > p->a[0] && c.x < p->a[3] && c.y > p->a[1] && c.y < p->a[4] && c.z > p->a[2] && c.z < p->a[5];
			break;
		case PART_CONE: {
			double ry = p->a[0] + (p->a[1] - p->a[0]) * c.y;
			in = c.y > 0 && c.y < 1 && c.x * c.x + c.z * c.z < ry * ry;
			break;
		}
		case PART_TORUS:
			in = torus_inside(p->a[0], p->a[1], c);
			break;
		default:
			in = false;
			break;
		}
	}
	return in != p->inverse;
}

/* The world bounds of the canonical circle y = c, x^2 + z^2 = rho^2 under p's to_world:
 * its centre -+ rho times the length of each row's x and z entries, exact (an ellipse's
 * extent along an axis), widened by the rounding of computing it. */
static void circle_bounds(const struct part *p, double c, double rho, struct vec3 *lo, struct vec3 *hi)
{
	struct vec3 w = affine_point(&p->to_world, v3(0, c, 0)), e;
	double *ee = &e.x;
	for (int i = 0; i < 3; i++)
		ee[i] = rho * hypot(p->to_world.m[i][0], p->to_world.m[i][2]);
	e = vadd(e, vscale(vadd(vabs(w), e), rounding_gamma(8)));
	*lo = vmin(*lo, vsub(w, e));
	*hi = vmax(*hi, vadd(w, e));
}

void part_leaf_bounds(const struct part *p, struct vec3 *lo, struct vec3 *hi)
{
	if (p->kind == PART_PLANE) {
		*lo = v3s(-INFINITY);
		*hi = v3s(INFINITY);
		return;
	}
	*lo = v3s(INFINITY);
	*hi = v3s(-INFINITY);
	const struct affine *m = &p->to_world;
	switch (p->kind) {
	case PART_BOX:
		for (int corner = 0; corner < 8; corner++) {
			struct vec3 c = v3(p->a[(corner & 1) * 3], p->a[(corner >> 1 & 1) * 3 + 1], p->a[(corner >> 2) * 3 + 2]);
			struct vec3 w = affine_point(m, c), e = affine_error(m, c, v3s(0));
			*lo = vmin(*lo, vsub(w, e));
			*hi = vmax(*hi, vadd(w, e));
		}
		return;
	case PART_SPHERE: case PART_TORUS: {
		/* the unit ball, or the torus's tube (a ball of the minor radius swept along its
		 * centre circle): an ellipsoid's extent along an axis is its row's length */
		double r = p->kind == PART_SPHERE ? 1 : p->a[1];
		struct vec3 w = affine_point(m, v3s(0)), e;
		double *ee = &e.x;
		for (int i = 0; i < 3; i++)
			ee[i] = r * hypot(hypot(m->m[i][0], m->m[i][1]), m->m[i][2]) * (1 + rounding_gamma(4));
		if (p->kind == PART_TORUS) {
			struct vec3 clo = v3s(INFINITY), chi = v3s(-INFINITY);
			circle_bounds(p, 0, p->a[0], &clo, &chi);
			*lo = vsub(clo, e);
			*hi = vadd(chi, e);
			return;
		}
		e = vadd(e, vscale(vadd(vabs(w), e), rounding_gamma(8)));
		*lo = vsub(w, e);
		*hi = vadd(w, e);
		return;
	}
	case PART_CONE:
		/* the hull of its end circles */
		circle_bounds(p, 0, p->a[0], lo, hi);
		circle_bounds(p, 1, p->a[1], lo, hi);
		return;
	case PART_DISC:
		circle_bounds(p, 0, 1, lo, hi);
		return;
	default:
		return;
	}
}
