/* eval_xform.c: the transforms translate, rotate and scale (LANGUAGE.md sections 5, 9 and
 * 11) into the affine maps of the scene's xforms, for objects and for patterns alike. */
#include "eval_internal.h"

#include "xalloc.h"

/* sin and cos of an angle in degrees, exact at multiples of 90 so that right-angle
 * rotations keep axis-aligned geometry exactly axis-aligned. */
static void sincos_degrees(double deg, double *s, double *c)
{
	double r = fmod(deg, 360);
	if (r < 0)
		r += 360;
	if (r == 0) { *s = 0; *c = 1; return; }
	if (r == 90) { *s = 1; *c = 0; return; }
	if (r == 180) { *s = 0; *c = -1; return; }
	if (r == 270) { *s = -1; *c = 0; return; }
	*s = sin(deg * (M_PI / 180));
	*c = cos(deg * (M_PI / 180));
}

void xform_compose(struct xform *x, const double t[3][4])
{
	struct xform r;
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 4; j++) {
			double v = j == 3 ? t[i][3] : 0;
			for (int k = 0; k < 3; k++)
				v += t[i][k] * x->m[k][j];
			r.m[i][j] = v;
		}
	*x = r;
}

/* Every object takes every transform (LANGUAGE.md section 9): a sphere under an uneven
 * scale is an ellipsoid; and so does a pattern (section 11). */
bool xform_apply(struct evaluator *ev, struct ast *it, struct xform *x)
{
	double v[3];
	if (!vec_of(ev, arg0(it), v))
		return false;
	double t[3][4] = { { 1, 0, 0, 0 }, { 0, 1, 0, 0 }, { 0, 0, 1, 0 } };
	switch (it->u.item.kw) {
	case KW_TRANSLATE:
		for (int i = 0; i < 3; i++)
			t[i][3] = v[i];
		xform_compose(x, t);
		return true;
	case KW_SCALE:
		if (v[0] == 0 || v[1] == 0 || v[2] == 0) {
			eval_error(ev, arg0(it), "scale must not be zero in any direction");
			return false;
		}
		for (int i = 0; i < 3; i++)
			t[i][i] = v[i];
		xform_compose(x, t);
		return true;
	default: /* rotate: about x, then y, then z, as POV-Ray */
		for (int axis = 0; axis < 3; axis++) {
			double s, c;
			sincos_degrees(v[axis], &s, &c);
			double r[3][4] = { { 1, 0, 0, 0 }, { 0, 1, 0, 0 }, { 0, 0, 1, 0 } };
			int a = (axis + 1) % 3, b = (axis + 2) % 3;
			r[a][a] = c;
			r[a][b] = -s;
			r[b][a] = s;
			r[b][b] = c;
			xform_compose(x, r);
		}
		return true;
	}
}

bool xform_finite(const struct xform *x)
{
	for (int r = 0; r < 12; r++)
		if (!isfinite(x->m[r / 4][r % 4]))
			return false;
	return true;
}

int xform_push(struct evaluator *ev, const struct xform *x)
{
	struct scene_desc *o = ev->out;
	xgrow((void **)&o->xforms, &o->cap_xforms, o->nxforms + 1, sizeof *o->xforms);
	o->xforms[o->nxforms] = *x;
	return (int)o->nxforms++;
}
