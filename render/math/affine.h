/* affine.h: affine maps of 3-space (a linear part and a translation), as lowering bakes an
 * object's transforms and as the shapes that are intersected in their own space use them;
 * with bounds on the rounding error of applying one (pbrt 3rd ed. section 3.9.4). */
#ifndef SCN_AFFINE_H
#define SCN_AFFINE_H

#include <stdbool.h>

#include "rounding.h"
#include "vec.h"

/* An affine map p -> m[.][0..2] p + m[.][3]. */
struct affine {
	double m[3][4];
};

/* p under a. */
static inline struct vec3 affine_point(const struct affine *a, struct vec3 p)
{
	return v3(a->m[0][0] * p.x + a->m[0][1] * p.y + a->m[0][2] * p.z + a->m[0][3],
	          a->m[1][0] * p.x + a->m[1][1] * p.y + a->m[1][2] * p.z + a->m[1][3],
	          a->m[2][0] * p.x + a->m[2][1] * p.y + a->m[2][2] * p.z + a->m[2][3]);
}

/* v under a's linear part: a direction, which the translation does not move. */
static inline struct vec3 affine_vector(const struct affine *a, struct vec3 v)
{
	return v3(a->m[0][0] * v.x + a->m[0][1] * v.y + a->m[0][2] * v.z,
	          a->m[1][0] * v.x + a->m[1][1] * v.y + a->m[1][2] * v.z,
	          a->m[2][0] * v.x + a->m[2][1] * v.y + a->m[2][2] * v.z);
}

/* n under the transpose of a's linear part: a normal under the map whose inverse is a
 * (normals transform by the inverse transpose); not normalised. */
static inline struct vec3 affine_normal(const struct affine *a, struct vec3 n)
{
	return v3(a->m[0][0] * n.x + a->m[1][0] * n.y + a->m[2][0] * n.z,
	          a->m[0][1] * n.x + a->m[1][1] * n.y + a->m[2][1] * n.z,
	          a->m[0][2] * n.x + a->m[1][2] * n.y + a->m[2][2] * n.z);
}

/* e (a bound on the error of each coordinate of a point) under |a|'s linear part, plus
 * the rounding of applying a to p: a bound on the error of affine_point(a, p') for any p'
 * within e of p (pbrt's transformed pError, with its gamma(3) for the three products and
 * sums, one more for the translation). */
static inline struct vec3 affine_error(const struct affine *a, struct vec3 p, struct vec3 e)
{
	struct vec3 r;
	double *out = &r.x;
	for (int i = 0; i < 3; i++) {
		double abs_p = fabs(a->m[i][0] * p.x) + fabs(a->m[i][1] * p.y) + fabs(a->m[i][2] * p.z) + fabs(a->m[i][3]);
		double abs_e = fabs(a->m[i][0]) * e.x + fabs(a->m[i][1]) * e.y + fabs(a->m[i][2]) * e.z;
		out[i] = (1 + rounding_gamma(4)) * abs_e + rounding_gamma(4) * abs_p;
	}
	return r;
}

static const struct affine affine_identity = { { { 1, 0, 0, 0 }, { 0, 1, 0, 0 }, { 0, 0, 1, 0 } } };

/* a after b: p -> a(b(p)). */
static inline struct affine affine_compose(const struct affine *a, const struct affine *b)
{
	struct affine r;
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 4; j++) {
			double v = j == 3 ? a->m[i][3] : 0;
			for (int k = 0; k < 3; k++)
				v += a->m[i][k] * b->m[k][j];
			r.m[i][j] = v;
		}
	return r;
}

static inline bool affine_is_identity(const struct affine *a)
{
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 4; j++)
			if (a->m[i][j] != (i == j))
				return false;
	return true;
}

/* Whether every entry is a finite number. */
static inline bool affine_finite(const struct affine *a)
{
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 4; j++)
			if (!isfinite(a->m[i][j]))
				return false;
	return true;
}

/* The linear part of x divided by its largest entry (returned), so that its cofactors
 * and determinant neither underflow nor overflow for a scale of 1e-250 or 1e90. */
static inline double affine_scaled_linear(const struct affine *x, double a[3][3])
{
	double big = 0;
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 3; j++)
			big = fmax(big, fabs(x->m[i][j]));
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 3; j++)
			a[i][j] = x->m[i][j] / big;
	return big;
}

static inline double affine_det3(const double a[3][3])
{
	return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
	       a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
}

/* The inverse of an affine map whose linear part is invertible; its entries are not
 * finite when that part is singular in double (see affine_finite). */
static inline struct affine affine_inverse(const struct affine *x)
{
	double a[3][3];
	double big = affine_scaled_linear(x, a);
	double c[3][3] = {
		{ a[1][1] * a[2][2] - a[1][2] * a[2][1], a[0][2] * a[2][1] - a[0][1] * a[2][2], a[0][1] * a[1][2] - a[0][2] * a[1][1] },
		{ a[1][2] * a[2][0] - a[1][0] * a[2][2], a[0][0] * a[2][2] - a[0][2] * a[2][0], a[0][2] * a[1][0] - a[0][0] * a[1][2] },
		{ a[1][0] * a[2][1] - a[1][1] * a[2][0], a[0][1] * a[2][0] - a[0][0] * a[2][1], a[0][0] * a[1][1] - a[0][1] * a[1][0] },
	};
	double det = affine_det3(a);
	struct affine inv;
	for (int i = 0; i < 3; i++) {
		for (int j = 0; j < 3; j++)
			inv.m[i][j] = c[i][j] / det / big; /* (M / big)^-1 = big M^-1 */
		inv.m[i][3] = -(inv.m[i][0] * x->m[0][3] + inv.m[i][1] * x->m[1][3] + inv.m[i][2] * x->m[2][3]);
	}
	return inv;
}

/* Whether x mirrors space (its linear part has a negative determinant). */
static inline bool affine_mirrors(const struct affine *x)
{
	double a[3][3];
	affine_scaled_linear(x, a);
	return affine_det3(a) < 0;
}

#endif
