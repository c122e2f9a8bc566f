/* shape.c: ray intersection, robust without user-tuned epsilons:
 *  - spheres: Hearn-Baker discriminant and stable roots (Haines, Guenther and
 *    Akenine-Moeller, "Precision Improvements for Ray/Sphere Intersection", Ray Tracing
 *    Gems ch. 7, 2019);
 *  - triangles: the watertight test of Woop, Benthin and Wald (JCGT 2(1), 2013), with
 *    pbrt-v3's conservative t > 0 check;
 *  - hit points from the primitive with pbrt's error bounds (PBRT 3rd ed. section 3.9). */
#include "shape.h"

#include <float.h>
#include <math.h>
#ifdef __SSE2__
#include <emmintrin.h>
#endif

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

bool ray_sphere(const struct sphere *s, const struct ray *r, struct hit *h)
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

int ray_sphere_crossings(const struct sphere *s, const struct ray *r, double tmax, double t[2])
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

void prim_bounds(const struct scene *sc, uint32_t prim, struct vec3 *lo, struct vec3 *hi)
{
	uint32_t i = prim_index(prim);
	if (prim_kind(prim) == PRIM_SPHERE) {
		const struct sphere *s = &sc->spheres[i];
		*lo = vsub(s->center, v3s(s->radius));
		*hi = vadd(s->center, v3s(s->radius));
	} else {
		const uint32_t *v = sc->triangles[i].v;
		struct vec3 a = sc->vertices[v[0]], b = sc->vertices[v[1]], c = sc->vertices[v[2]];
		*lo = vmin(a, vmin(b, c));
		*hi = vmax(a, vmax(b, c));
	}
}

bool ray_plane(const struct plane *pl, const struct ray *r, struct hit *h)
{
	double denom = vdot(pl->normal, r->d);
	if (denom == 0)
		return false; /* parallel: a miss, not a NaN (NUMERICS.md section 7) */
	double t = (pl->offset - vdot(pl->normal, r->o)) / denom;
	if (!(t > 0 && t < h->t))
		return false;
	h->t = t;
	return true;
}

static int max_axis(struct vec3 v)
{
	return v.x > v.y ? (v.x > v.z ? 0 : 2) : (v.y > v.z ? 1 : 2);
}

void tri_ray_init(const struct ray *r, struct tri_ray *tr)
{
	int kz = max_axis(vabs(r->d));
	int kx = kz == 2 ? 0 : kz + 1;
	int ky = kx == 2 ? 0 : kx + 1;
	double dx = vget(&r->d, kx), dy = vget(&r->d, ky), dz = vget(&r->d, kz);
	*tr = (struct tri_ray){ .o = r->o, .k = { kx, ky, kz }, .sx = -dx / dz, .sy = -dy / dz, .sz = 1 / dz };
}

/* Which signs the edge functions take: bit 0 set when one is zero, bit 1 when one is
 * below zero, bit 2 when one is above. With SSE2, a vector compare and a mask for each
 * question, where the scalar comparisons took forty instructions, a third of the test. */
enum { EDGE_ZERO = 1, EDGE_BELOW = 2, EDGE_ABOVE = 4 };
static inline int edge_signs(double e0, double e1, double e2)
{
#ifdef __SSE2__
	__m128d a = _mm_set_pd(e1, e0), b = _mm_set1_pd(e2), z = _mm_setzero_pd();
	int zero = _mm_movemask_pd(_mm_or_pd(_mm_cmpeq_pd(a, z), _mm_cmpeq_pd(b, z)));
	int below = _mm_movemask_pd(_mm_or_pd(_mm_cmplt_pd(a, z), _mm_cmplt_pd(b, z)));
	int above = _mm_movemask_pd(_mm_or_pd(_mm_cmpgt_pd(a, z), _mm_cmpgt_pd(b, z)));
	return (zero != 0) * EDGE_ZERO | (below != 0) * EDGE_BELOW | (above != 0) * EDGE_ABOVE;
#else
	return ((e0 == 0) | (e1 == 0) | (e2 == 0)) * EDGE_ZERO | ((e0 < 0) | (e1 < 0) | (e2 < 0)) * EDGE_BELOW |
	       ((e0 > 0) | (e1 > 0) | (e2 > 0)) * EDGE_ABOVE;
#endif
}

/* The greatest of |a|, |b|, |c|, by comparisons rather than fmax(), which is a call:
 * the values are finite wherever the result matters (a NaN makes t NaN, which the test
 * rejects whatever the bound). */
static inline double max_abs3(double a, double b, double c)
{
	a = fabs(a), b = fabs(b), c = fabs(c);
	double m = a > b ? a : b;
	return m > c ? m : c;
}

/* Vertex v translated to the ray origin and permuted. */
static inline struct vec3 to_ray(const struct tri_ray *tr, const struct vec3 *v)
{
	return v3(vget(v, tr->k[0]) - vget(&tr->o, tr->k[0]), vget(v, tr->k[1]) - vget(&tr->o, tr->k[1]),
	          vget(v, tr->k[2]) - vget(&tr->o, tr->k[2]));
}

bool ray_triangle(const struct scene *sc, uint32_t tri, const struct ray *r, struct hit *h)
{
	struct tri_ray tr;
	tri_ray_init(r, &tr);
	return tri_ray_hit(&tr, sc, tri, h);
}

bool tri_ray_hit(const struct tri_ray *tr, const struct scene *sc, uint32_t tri, struct hit *h)
{
	/* Translate to the ray origin, permute so that z is the ray's largest axis, and
	 * shear so that the ray is the +z axis: the edge functions then depend only on 2-D
	 * coordinates, and an edge shared by two triangles gives both the same values. */
	const uint32_t *v = sc->triangles[tri].v;
	struct vec3 p0 = to_ray(tr, &sc->vertices[v[0]]), p1 = to_ray(tr, &sc->vertices[v[1]]),
	            p2 = to_ray(tr, &sc->vertices[v[2]]);
	double sx = tr->sx, sy = tr->sy, sz = tr->sz;
	p0.x += sx * p0.z;
	p0.y += sy * p0.z;
	p1.x += sx * p1.z;
	p1.y += sy * p1.z;
	p2.x += sx * p2.z;
	p2.y += sy * p2.z;

	double e0 = p1.x * p2.y - p1.y * p2.x;
	double e1 = p2.x * p0.y - p2.y * p0.x;
	double e2 = p0.x * p1.y - p0.y * p1.x;
	int signs = edge_signs(e0, e1, e2);
	if (signs & EDGE_ZERO) {
		/* exactly on an edge in double: decide it in extended precision */
		long double X0 = p0.x, Y0 = p0.y, X1 = p1.x, Y1 = p1.y, X2 = p2.x, Y2 = p2.y;
		e0 = (double)(X1 * Y2 - Y1 * X2);
		e1 = (double)(X2 * Y0 - Y2 * X0);
		e2 = (double)(X0 * Y1 - Y0 * X1);
		signs = edge_signs(e0, e1, e2);
	}
	if ((signs & (EDGE_BELOW | EDGE_ABOVE)) == (EDGE_BELOW | EDGE_ABOVE))
		return false;
	double det = e0 + e1 + e2;
	p0.z *= sz;
	p1.z *= sz;
	p2.z *= sz;
	double tscaled = e0 * p0.z + e1 * p1.z + e2 * p2.z;
	if ((det == 0) | TRI_T_OUTSIDE(det, tscaled, h->t * det, 0.0))
		return false;
	double inv = 1 / det;
	double t = tscaled * inv;

	/* pbrt-v3: make sure t is conservatively greater than zero, given the rounding
	 * errors of everything above */
	double max_x = max_abs3(p0.x, p1.x, p2.x), max_y = max_abs3(p0.y, p1.y, p2.y);
	double max_z = max_abs3(p0.z, p1.z, p2.z), max_e = max_abs3(e0, e1, e2);
	double delta_t = TRI_DELTA_T(max_x, max_y, max_z, max_e, fabs(inv));
	if (!((t > delta_t) & (t < h->t)))
		return false;
	h->t = t;
	h->b1 = e1 * inv;
	h->b2 = e2 * inv;
	return true;
}

void surface_at(const struct scene *sc, const struct ray *r, const struct hit *h, struct surface_point *sp)
{
	switch (prim_kind(h->prim)) {
	case PRIM_SPHERE: {
		const struct sphere *s = &sc->spheres[prim_index(h->prim)];
		struct vec3 p = vmad(r->o, h->t, r->d);
		struct vec3 rel = vsub(p, s->center);
		double len = vlen(rel);
		/* re-project onto the surface: the error no longer grows with t */
		rel = len > 0 ? vscale(rel, s->radius / len) : v3(0, s->radius, 0);
		sp->p = vadd(s->center, rel);
		sp->p_err = vadd(vscale(vabs(rel), err_gamma(5)), vscale(vabs(sp->p), err_gamma(2)));
		sp->ng = vscale(rel, 1 / s->radius);
		sp->ns = sp->ng;
		break;
	}
	case PRIM_PLANE: {
		const struct plane *pl = &sc->planes[prim_index(h->prim)];
		struct vec3 p = vmad(r->o, h->t, r->d);
		/* project onto the plane. The bound is on the magnitudes that entered the
		 * projection, not on the projected point: with a normal whose length is 1 only
		 * to a rounding (a scaled plane's), a coordinate the projection sends to about 0
		 * keeps a residue of the order of the original coordinate's rounding. */
		sp->p = vsub(p, vscale(pl->normal, vdot(pl->normal, p) - pl->offset));
		sp->p_err = vscale(vadd(vmax(vabs(p), vabs(sp->p)), v3s(fabs(pl->offset))), err_gamma(7));
		sp->ng = pl->normal;
		sp->ns = pl->normal;
		break;
	}
	case PRIM_TRIANGLE: {
		const struct triangle *tri = &sc->triangles[prim_index(h->prim)];
		struct vec3 a = sc->vertices[tri->v[0]], b = sc->vertices[tri->v[1]], c = sc->vertices[tri->v[2]];
		double b0 = 1 - h->b1 - h->b2;
		struct vec3 wa = vscale(a, b0), wb = vscale(b, h->b1), wc = vscale(c, h->b2);
		sp->p = vadd(vadd(wa, wb), wc);
		sp->p_err = vscale(vadd(vadd(vabs(wa), vabs(wb)), vabs(wc)), err_gamma(7));
		sp->ng = vunit(vcross(vsub(b, a), vsub(c, a)));
		if (tri->n[0] == NO_NORMALS) {
			sp->ns = sp->ng;
		} else {
			struct vec3 n = vadd(vadd(vscale(sc->normals[tri->n[0]], b0), vscale(sc->normals[tri->n[1]], h->b1)),
			                     vscale(sc->normals[tri->n[2]], h->b2));
			double len = vlen(n);
			sp->ns = len > 0 ? vscale(n, 1 / len) : sp->ng;
		}
		break;
	}
	}
}

struct vec3 offset_origin(const struct surface_point *sp, struct vec3 w)
{
	double dist = vdot(vabs(sp->ng), sp->p_err);
	struct vec3 off = vscale(sp->ng, dist);
	if (vdot(w, sp->ng) < 0)
		off = vneg(off);
	struct vec3 o = vadd(sp->p, off);
	/* round away from the surface: the sum above may have rounded towards it */
	return v3(vstep(o.x, off.x), vstep(o.y, off.y), vstep(o.z, off.z));
}

bool planes_intersect(const struct scene *sc, const struct ray *r, struct hit *h)
{
	bool hit = false;
	for (size_t i = 0; i < sc->nplanes; i++)
		if (ray_plane(&sc->planes[i], r, h)) {
			h->prim = prim_id(PRIM_PLANE, (uint32_t)i);
			hit = true;
		}
	return hit;
}

struct vec3 planes_filter(const struct scene *sc, const struct ray *r, double tmax)
{
	struct vec3 pass = v3s(1);
	for (size_t i = 0; i < sc->nplanes; i++) {
		struct hit h = { .t = tmax };
		if (ray_plane(&sc->planes[i], r, &h)) {
			pass = vmul(pass, transmit_of(sc, sc->planes[i].surface));
			if (vzero(pass))
				return pass;
		}
	}
	return pass;
}
