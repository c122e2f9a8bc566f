/* sphere.c: ray and sphere by the Hearn-Baker discriminant and stable roots (Haines,
 * Guenther and Akenine-Moeller, "Precision Improvements for Ray/Sphere Intersection", Ray
 * Tracing Gems ch. 7, 2019); the hit point re-projected onto the sphere, with pbrt's
 * error bound (PBRT 3rd ed. section 3.9). */
#include "sphere.h"

#include <math.h>

#include "rounding.h"

/* Roots of |o + t d - c| = r with unit d, in increasing order; false when the ray
 * misses the sphere. */
static bool sphere_roots(const struct sphere *s, const struct ray *r, double *t0, double *t1)
{
	struct vec3 f = vsub(r->o, s->center);
	double b = vdot(f, r->d);
	double c = vdot(f, f) - s->radius * s->radius;
	/* r^2 - |f - (f.d) d|^2: the squared half-chord, free of the cancellation in
	 * b^2 - (f.f - r^2) when the sphere is small or far */
	struct vec3 perp = vsub(f, vscale(r->d, b));
	double disc = s->radius * s->radius - vdot(perp, perp);
	/* a miss, or the origin outside and the sphere behind it (the roots' product c
	 * positive, their sum -2b negative, as the roots below would come out): decided
	 * before the square root and the division, and in one branch, which a ray that
	 * hits or misses at random mispredicts less often than three */
	if (((c > 0) & (b > 0)) | (disc < 0))
		return false;
	double q = -(b + copysign(sqrt(disc), b));
	if (q == 0)
		return false; /* origin on the sphere and the ray tangent to it */
	double a = c / q, z = q;
	*t0 = a < z ? a : z;
	*t1 = a < z ? z : a;
	return true;
}

bool sphere_intersect(const struct sphere *s, const struct ray *r, struct hit *h)
{
	double t0, t1;
	if (!sphere_roots(s, r, &t0, &t1))
		return false;
	double t = t0 > 0 ? t0 : t1;
	if (!((t > 0) & (t < h->t)))
		return false;
	h->t = t;
	return true;
}

int sphere_crossings(const struct sphere *s, const struct ray *r, double tmax, double t[2])
{
	double t0, t1;
	int n = 0;
	if (!sphere_roots(s, r, &t0, &t1))
		return 0;
	if (t0 > 0 && t0 < tmax)
		t[n++] = t0;
	if (t1 > 0 && t1 < tmax && t1 != t0)
		t[n++] = t1;
	return n;
}

void sphere_bounds(const struct sphere *s, struct vec3 *lo, struct vec3 *hi)
{
	*lo = vsub(s->center, v3s(s->radius));
	*hi = vadd(s->center, v3s(s->radius));
}

void sphere_surface(const struct sphere *s, const struct ray *r, const struct hit *h, struct surface_point *sp)
{
	struct vec3 p = vmad(r->o, h->t, r->d);
	struct vec3 rel = vsub(p, s->center);
	double len = vlen(rel);
	/* re-project onto the surface: the error no longer grows with t */
	rel = len > 0 ? vscale(rel, s->radius / len) : v3(0, s->radius, 0);
	sp->p = vadd(s->center, rel);
	sp->p_err = vadd(vscale(vabs(rel), rounding_gamma(5)), vscale(vabs(sp->p), rounding_gamma(2)));
	sp->ng = vscale(rel, 1 / s->radius);
	sp->ns = sp->ng;
}
