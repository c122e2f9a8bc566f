/* probe_hit.c: the exact ray tests of the probe's `hit` and `lambert` checks (probe_hit.h).
 * They are written apart from the renderer's: the ellipsoid by Hearn and Baker's
 * discriminant in its own space, the torus as the tube of radius MINOR about its core
 * circle (a ray meets it where it passes within MINOR of a point of the circle: a
 * minimum over the circle's angle, bounded by branch and bound, no quartic), the disc and
 * the box by their planes. */
#include "probe_hit.h"

#include <math.h>

static real dot(const real a[3], const real b[3])
{
	return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void unit(real v[3])
{
	real n = sqrt(dot(v, v));
	for (int k = 0; k < 3; k++)
		v[k] /= n;
}

static void cross(const real a[3], const real b[3], real out[3])
{
	real x = a[1] * b[2] - a[2] * b[1], y = a[2] * b[0] - a[0] * b[2], z = a[0] * b[1] - a[1] * b[0];
	out[0] = x;
	out[1] = y;
	out[2] = z;
}

void probe_camera_setup(struct probe_camera *c, const double eye[3], const double look_at[3], const double up[3],
                        double fov, int width, int height, int grid)
{
	real u[3];
	for (int k = 0; k < 3; k++) {
		c->eye[k] = eye[k];
		c->dir[k] = (real)look_at[k] - eye[k];
		u[k] = up[k];
	}
	unit(c->dir);
	unit(u);
	cross(u, c->dir, c->right);
	unit(c->right);
	cross(c->dir, c->right, c->up);
	c->tan_half = tan(fov * (3.14159265358979323846 / 360));
	c->width = width;
	c->height = height;
	c->grid = grid;
}

void probe_camera_ray(const struct probe_camera *c, int px, int py, int a, int b, real d[3])
{
	int g = c->grid;
	real u = ((real)g * px + a + 0.5) / ((real)g * c->width);
	real v = ((real)g * py + b + 0.5) / ((real)g * c->height);
	real sx = (2 * u - 1) * c->tan_half, sy = (1 - 2 * v) * c->tan_half * ((real)c->height / c->width);
	for (int k = 0; k < 3; k++)
		d[k] = c->dir[k] + c->right[k] * sx + c->up[k] * sy;
}

/* The ray in the ellipsoid's own space, where it is the unit sphere: o', d'. */
static void ellipsoid_space(const struct probe_shape *s, const real o[3], const real d[3], real g, real oc[3],
                            real dc[3])
{
	for (int k = 0; k < 3; k++) {
		oc[k] = (o[k] - s->c[k]) / (s->a[k] * g);
		dc[k] = d[k] / (s->a[k] * g);
	}
}

/* The t where the ray meets the unit sphere first at t > 0 (Hearn-Baker), or -1. */
static real sphere_t(const real oc[3], const real dc[3])
{
	real dd = dot(dc, dc), b = dot(oc, dc) / dd, f[3];
	for (int k = 0; k < 3; k++)
		f[k] = oc[k] - b * dc[k];
	real disc = 1 - dot(f, f);
	if (disc < 0)
		return -1;
	real h = sqrt(disc / dd);
	return -b - h > 0 ? -b - h : -b + h > 0 ? -b + h : -1;
}

bool probe_ellipsoid_normal(const struct probe_shape *s, const real o[3], const real d[3], real g, real n[3])
{
	real oc[3], dc[3];
	ellipsoid_space(s, o, d, g, oc, dc);
	real t = sphere_t(oc, dc);
	if (t < 0)
		return false;
	/* the gradient of the ellipsoid's equation: the unit sphere's normal under the
	 * inverse transpose of the scale */
	for (int k = 0; k < 3; k++)
		n[k] = (oc[k] + t * dc[k]) / (s->a[k] * g);
	unit(n);
	return true;
}

/* The squared distance from the torus's core circle at the angle whose cosine and sine
 * are (cs, sn) to the ray from o along the unit d (to o itself where the point lies
 * behind it). w0 = centre - o. */
static real circle_dist2(const struct probe_shape *s, const real w0[3], const real d[3], real cs, real sn)
{
	real w[3] = { w0[0] + s->major * cs, w0[1], w0[2] + s->major * sn };
	real t = dot(w, d);
	if (t <= 0)
		return dot(w, w);
	real r[3] = { w[0] - t * d[0], w[1] - t * d[1], w[2] - t * d[2] };
	return dot(r, r);
}

/* An arc [a, b] of the core circle: its ends' cosines and sines and distances squared. */
struct arc {
	real h, ca, sa, cb, sb, fa, fb;
};

/* How the ray stands with the tube of radii minor * lo and minor * hi about the core
 * circle: the least squared distance F(phi) from the circle to the ray, against those
 * radii squared, by branch and bound over arcs. |F''| <= m (m below), so on an arc of
 * width h F is at least min(F(a), F(b)) - m h^2 / 8: an arc is dropped when that is
 * above the outer radius squared, halved otherwise (its middle's cosine and sine are
 * its ends' mean, normalised: no trigonometry in the loop); a value below the inner
 * radius squared is a hit. An arc too short to tell the two radii apart, and not
 * dropped, makes the ray PROBE_EDGE unless some value is a hit. */
static enum probe_side torus_side(const struct probe_shape *s, const real o[3], const real dir[3], real lo, real hi)
{
	real d[3] = { dir[0], dir[1], dir[2] }, w0[3];
	unit(d);
	for (int k = 0; k < 3; k++)
		w0[k] = s->c[k] - o[k];
	real big = s->major, in2 = s->minor * lo * s->minor * lo, out2 = s->minor * hi * s->minor * hi;
	/* With u = (cos phi, 0, sin phi), w = w0 + R u and s = w.d = s0 + R (p cos + q sin):
	 * |w|^2 = const + 2 R (w0x cos + w0z sin), and where s > 0
	 * F = |w|^2 - s^2 = const + 2 R ((w0x - sd p) cos + (w0z - sd q) sin)
	 *                   - R^2 ((p^2 - q^2) / 2 cos 2phi + p q sin 2phi),
	 * trigonometric polynomials whose second derivatives are at most their first
	 * harmonic's amplitude plus 4 times their second's; F is C^1 where s changes sign. */
	real sd = dot(w0, d), p = d[0], q = d[2];
	real a1 = 2 * big * hypot(w0[0] - sd * p, w0[2] - sd * q), a2 = big * big * (p * p + q * q) / 2;
	real m = fmax(a1 + 4 * a2, 2 * big * hypot(w0[0], w0[2]));
	m = fmax(m * (1 + 1e-12), 1e-300);    /* rounding of the bound itself; never 0 */
	if (!isfinite(m) || !isfinite(dot(d, d)))
		return PROBE_EDGE;        /* no NaN into the search, which would never drop an arc */
	real h_stop = fmax(sqrt(2 * (out2 - in2) / m), 1e-15);
	enum { START = 16, STACK = 256 };   /* each halving adds one arc: 16 + 50 levels */
	struct arc stack[STACK];
	int top = 0;
	bool edge = false;
	const real two_pi = 6.28318530717958647692;
	static real cosines[START + 1], sines[START + 1];
	if (sines[START / 4] == 0)
		for (int i = 0; i <= START; i++) {
			cosines[i] = i == START ? 1 : cos(two_pi * i / START);
			sines[i] = i == START ? 0 : sin(two_pi * i / START);
		}
	real c0 = 1, s0 = 0, f0 = circle_dist2(s, w0, d, 1, 0);
	if (f0 < in2)
		return PROBE_IN;
	for (int i = 0; i < START; i++) {
		real cb = cosines[i + 1], sb = sines[i + 1];
		real fb = circle_dist2(s, w0, d, cb, sb);
		if (fb < in2)
			return PROBE_IN;
		stack[top++] = (struct arc){ two_pi / START, c0, s0, cb, sb, f0, fb };
		c0 = cb, s0 = sb, f0 = fb;
	}
	while (top > 0) {
		struct arc q = stack[--top];
		real least = q.fa < q.fb ? q.fa : q.fb;
		if (least - m * q.h * q.h / 8 >= out2)
			continue;
		if (least < out2)
			edge = true;           /* at most PROBE_EDGE: a point within the outer radius */
		if (q.h < h_stop || top + 2 > STACK) {
			edge = true;
			continue;
		}
		real cm = q.ca + q.cb, sm = q.sa + q.sb, n = sqrt(cm * cm + sm * sm);
		cm /= n;
		sm /= n;
		real fm = circle_dist2(s, w0, d, cm, sm);
		if (fm < in2)
			return PROBE_IN;
		struct arc first = { q.h / 2, q.ca, q.sa, cm, sm, q.fa, fm };
		struct arc second = { q.h / 2, cm, sm, q.cb, q.sb, fm, q.fb };
		/* the half with the lower end on top, so the search goes down towards the least
		 * distance first */
		stack[top++] = q.fa < q.fb ? second : first;
		stack[top++] = q.fa < q.fb ? first : second;
	}
	return edge ? PROBE_EDGE : PROBE_OUT;
}

static bool box_hit(const struct probe_shape *s, const real o[3], const real d[3], real g)
{
	real t0 = 0, t1 = INFINITY;
	for (int k = 0; k < 3; k++) {
		real mid = (s->lo[k] + s->hi[k]) / 2, half = (s->hi[k] - s->lo[k]) / 2 * g;
		real lo = mid - half, hi = mid + half;
		if (d[k] == 0) {
			if (o[k] < lo || o[k] > hi)
				return false;
			continue;
		}
		real a = (lo - o[k]) / d[k], b = (hi - o[k]) / d[k];
		if (a > b) {
			real x = a;
			a = b;
			b = x;
		}
		t0 = a > t0 ? a : t0;
		t1 = b < t1 ? b : t1;
	}
	return t0 <= t1 && t1 > 0;
}

static bool disc_hit(const struct probe_shape *s, const real o[3], const real d[3], real g)
{
	real nd = dot(s->n, d);
	if (nd == 0)
		return false;
	real w[3] = { s->c[0] - o[0], s->c[1] - o[1], s->c[2] - o[2] };
	real t = dot(s->n, w) / nd;
	if (t <= 0)
		return false;
	real p[3] = { o[0] + t * d[0] - s->c[0], o[1] + t * d[1] - s->c[1], o[2] + t * d[2] - s->c[2] };
	return dot(p, p) <= s->radius * g * s->radius * g;
}

bool probe_shape_hit(const struct probe_shape *s, const real o[3], const real d[3], real g)
{
	switch (s->kind) {
	case PROBE_ELLIPSOID: {
		real oc[3], dc[3];
		ellipsoid_space(s, o, d, g, oc, dc);
		return sphere_t(oc, dc) > 0;
	}
	case PROBE_TORUS:
		return torus_side(s, o, d, g, g) == PROBE_IN;
	case PROBE_DISC:
		return disc_hit(s, o, d, g);
	case PROBE_BOX:
		return box_hit(s, o, d, g);
	}
	return false;
}

enum probe_side probe_shape_side(const struct probe_shape *s, const real o[3], const real d[3])
{
	if (s->kind == PROBE_TORUS)
		return torus_side(s, o, d, 1 - PROBE_MARGIN, 1 + PROBE_MARGIN);
	if (probe_shape_hit(s, o, d, 1 - PROBE_MARGIN))
		return PROBE_IN;
	return probe_shape_hit(s, o, d, 1 + PROBE_MARGIN) ? PROBE_EDGE : PROBE_OUT;
}
