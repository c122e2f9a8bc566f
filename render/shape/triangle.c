/* triangle.c: ray and triangle by the watertight test of Woop, Benthin and Wald (JCGT
 * 2(1), 2013) with pbrt-v3's conservative t > 0 check; the hit point from the barycentric
 * weights, with pbrt's error bound (PBRT 3rd ed. section 3.9). */
#include "triangle.h"

#include <math.h>
#ifdef __SSE2__
#include <emmintrin.h>
#endif

static int max_axis(struct vec3 v)
{
	return v.x > v.y ? (v.x > v.z ? 0 : 2) : (v.y > v.z ? 1 : 2);
}

void triangle_ray_init(const struct ray *r, struct triangle_ray *tr)
{
	int kz = max_axis(vabs(r->d));
	int kx = kz == 2 ? 0 : kz + 1;
	int ky = kx == 2 ? 0 : kx + 1;
	double dx = vget(&r->d, kx), dy = vget(&r->d, ky), dz = vget(&r->d, kz);
	*tr = (struct triangle_ray){ .o = r->o, .k = { kx, ky, kz }, .sx = -dx / dz, .sy = -dy / dz, .sz = 1 / dz };
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
static inline struct vec3 to_ray(const struct triangle_ray *tr, const struct vec3 *v)
{
	return v3(vget(v, tr->k[0]) - vget(&tr->o, tr->k[0]), vget(v, tr->k[1]) - vget(&tr->o, tr->k[1]),
	          vget(v, tr->k[2]) - vget(&tr->o, tr->k[2]));
}

bool triangle_intersect_ray(const struct triangle *tri, const struct vec3 *vertices, const struct ray *r,
                            struct hit *h)
{
	struct triangle_ray tr;
	triangle_ray_init(r, &tr);
	return triangle_intersect(&tr, tri, vertices, h);
}

bool triangle_intersect(const struct triangle_ray *tr, const struct triangle *tri, const struct vec3 *vertices,
                        struct hit *h)
{
	/* Translate to the ray origin, permute so that z is the ray's largest axis, and
	 * shear so that the ray is the +z axis: the edge functions then depend only on 2-D
	 * coordinates, and an edge shared by two triangles gives both the same values. */
	const uint32_t *v = tri->v;
	struct vec3 p0 = to_ray(tr, &vertices[v[0]]), p1 = to_ray(tr, &vertices[v[1]]), p2 = to_ray(tr, &vertices[v[2]]);
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
	if ((det == 0) | TRIANGLE_T_OUTSIDE(det, tscaled, h->t * det, 0.0))
		return false;
	double inv = 1 / det;
	double t = tscaled * inv;

	/* pbrt-v3: make sure t is conservatively greater than zero, given the rounding
	 * errors of everything above */
	double max_x = max_abs3(p0.x, p1.x, p2.x), max_y = max_abs3(p0.y, p1.y, p2.y);
	double max_z = max_abs3(p0.z, p1.z, p2.z), max_e = max_abs3(e0, e1, e2);
	double delta_t = TRIANGLE_DELTA_T(max_x, max_y, max_z, max_e, fabs(inv));
	if (!((t > delta_t) & (t < h->t)))
		return false;
	h->t = t;
	h->b1 = e1 * inv;
	h->b2 = e2 * inv;
	return true;
}

void triangle_bounds(const struct triangle *tri, const struct vec3 *vertices, struct vec3 *lo, struct vec3 *hi)
{
	struct vec3 a = vertices[tri->v[0]], b = vertices[tri->v[1]], c = vertices[tri->v[2]];
	*lo = vmin(a, vmin(b, c));
	*hi = vmax(a, vmax(b, c));
}

void triangle_surface(const struct triangle *tri, const struct vec3 *vertices, const struct vec3 *normals,
                      const struct hit *h, struct surface_point *sp)
{
	struct vec3 a = vertices[tri->v[0]], b = vertices[tri->v[1]], c = vertices[tri->v[2]];
	double b0 = 1 - h->b1 - h->b2;
	struct vec3 wa = vscale(a, b0), wb = vscale(b, h->b1), wc = vscale(c, h->b2);
	sp->p = vadd(vadd(wa, wb), wc);
	sp->p_err = vscale(vadd(vadd(vabs(wa), vabs(wb)), vabs(wc)), rounding_gamma(7));
	sp->ng = vunit(vcross(vsub(b, a), vsub(c, a)));
	if (tri->n[0] == TRIANGLE_FLAT) {
		sp->ns = sp->ng;
	} else {
		struct vec3 n = vadd(vadd(vscale(normals[tri->n[0]], b0), vscale(normals[tri->n[1]], h->b1)),
		                     vscale(normals[tri->n[2]], h->b2));
		double len = vlen(n);
		sp->ns = len > 0 ? vscale(n, 1 / len) : sp->ng;
	}
}

void triangle_lift(const struct triangle *tri, const struct vec3 *vertices, const struct vec3 *normals,
                   const struct hit *h, double side, struct surface_point *sp)
{
	const double b[3] = { 1 - h->b1 - h->b2, h->b1, h->b2 };
	struct vec3 lift = v3s(0), lift_err = v3s(0);
	bool below = false;
	for (int k = 0; k < 3; k++) {
		struct vec3 n = vscale(normals[tri->n[k]], side), to = vsub(sp->p, vertices[tri->v[k]]);
		double d = vdot(to, n);
		if (!(d < 0))
			continue;
		below = true;
		lift = vmad(lift, -b[k] * d, n);
		/* the error of d: of the difference and the dot product, and p's own */
		double d_err = rounding_gamma(5) * vdot(vabs(to), vabs(n)) + vdot(sp->p_err, vabs(n));
		lift_err = vmad(lift_err, b[k] * d_err, vabs(n));
	}
	if (!below)
		return;
	sp->p = vadd(sp->p, lift);
	sp->p_err = vadd(vadd(sp->p_err, lift_err), vadd(vscale(vabs(lift), rounding_gamma(4)),
	                                                  vscale(vabs(sp->p), rounding_gamma(1))));
}
