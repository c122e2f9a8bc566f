/* light.c: POV-Ray's spotlight, fade and area light, as read in its 3.7 sources (trace.cpp:
 * TraceAreaLightShadowRay and TraceAreaLightSubsetShadowRay) and measured against it. */
#include "light.h"

#include <math.h>

/* c^tightness, c the cosine between the axis and -l (0 when c <= 0), times 1 inside the
 * radius, 0 beyond the falloff, and the smoothstep of the cosine between them. A radius
 * equal to the falloff is a hard edge, with no 0 / 0. */
double light_spot(const struct light *li, struct vec3 l)
{
	double c = -vdot(l, li->axis);
	if (!(c > 0) || c < li->cos_falloff)
		return 0;
	double f = pow(c, li->tightness);
	if (c < li->cos_radius) {
		double s = (c - li->cos_falloff) / (li->cos_radius - li->cos_falloff);
		f *= s * s * (3 - 2 * s);
	}
	return f;
}

double light_fade(const struct light *li, double dist)
{
	return 2 / (1 + pow(dist / li->fade_distance, li->fade_power));
}

/* POV-Ray averages the four corners of a span of the grid, and while the span is more
 * than one cell across, replaces each corner by the average of a quarter of the span,
 * split at floor and ceil of the middle (so a middle point is shared). Along one axis
 * this gives each end of a span half its weight; the two axes' weights multiply. */
static void span_weights(int lo, int hi, double share, double *w)
{
	if (hi - lo <= 1) {
		w[lo] += share / 2;
		w[hi] += share / 2;
		return;
	}
	span_weights(lo, (lo + hi) / 2, share / 2, w);
	span_weights((lo + hi + 1) / 2, hi, share / 2, w);
}

void light_area_weights(int n, double *w)
{
	for (int i = 0; i < n; i++)
		w[i] = 0;
	span_weights(0, n - 1, 1, w);
}

void light_area_axes(const struct area_light *a, struct vec3 l, struct vec3 axes[2])
{
	if (!a->orient) {
		axes[0] = a->axis[0];
		axes[1] = a->axis[1];
		return;
	}
	/* POV-Ray's: the first axis across l and z (y when l is within 0.01 of z) */
	double len = vlen(a->axis[0]);
	struct vec3 across = fabs(fabs(l.z) - 1) < 0.01 ? v3(0, 1, 0) : v3(0, 0, 1);
	axes[0] = vunit(vcross(l, across));
	axes[1] = vscale(vunit(vcross(l, axes[0])), len);
	axes[0] = vscale(axes[0], len);
}

struct vec3 light_area_offset(const struct area_light *a, const struct vec3 axes[2], double u, double v)
{
	if (a->circular) {
		/* POV-Ray's: onto [-0.5, 0.5] (and 0.001 off centre, which keeps the middle
		 * point off 0 / 0), then each square shell of the grid pulled in onto a circle */
		u = u * a->inv_span[0] - 0.5 + 0.001;
		v = v * a->inv_span[1] - 0.5 + 0.001;
		double r = sqrt(u * u + v * v);
		double k = r > 0 ? fmax(fabs(u), fabs(v)) / r : 1;  /* 0 only for a jittered point */
		return vadd(vscale(axes[0], u * k), vscale(axes[1], v * k));
	}
	struct vec3 off = v3s(0);
	if (a->size[0] > 1)
		off = vscale(axes[0], u * a->inv_span[0] - 0.5);
	if (a->size[1] > 1)
		off = vadd(off, vscale(axes[1], v * a->inv_span[1] - 0.5));
	return off;
}

/* Adds the plane with normal n (any length) through point at to region, turned so that
 * inside lies on the side of `inside`; nothing when n is too short to have a direction. */
static bool add_plane(struct bvh_region *region, struct vec3 n, struct vec3 at, struct vec3 inside, double margin)
{
	double len = vlen(n);
	if (!(len > 0))
		return false;
	n = vscale(n, 1 / len);
	if (vdot(n, vsub(inside, at)) > 0)
		n = vneg(n);
	double *p = region->plane[region->nplanes++];
	p[0] = n.x;
	p[1] = n.y;
	p[2] = n.z;
	p[3] = vdot(n, at) + margin;
	return true;
}

bool light_area_region(const struct area_light *a, const struct vec3 axes[2], struct vec3 centre, struct vec3 apex,
                       double margin, struct bvh_region *region, struct vec3 corner[4])
{
	if (a->size[0] < 2 || a->size[1] < 2)
		return false;
	/* how far the test points reach along each axis, in its lengths: half of it, POV-Ray's
	 * 0.001 of circular, and half a cell more when jittered */
	struct vec3 half[2];
	for (int k = 0; k < 2; k++)
		half[k] = vscale(axes[k], 0.501 + (a->jitter ? 0.5 * a->inv_span[k] : 0));
	corner[0] = vsub(vsub(centre, half[0]), half[1]);
	corner[1] = vsub(vadd(centre, half[0]), half[1]);
	corner[2] = vadd(vadd(centre, half[0]), half[1]);
	corner[3] = vadd(vsub(centre, half[0]), half[1]);
	region->nplanes = 0;
	for (int i = 0; i < 4; i++) {
		struct vec3 n = vcross(vsub(corner[i], apex), vsub(corner[(i + 1) % 4], apex));
		if (!add_plane(region, n, apex, centre, margin))
			return false;
	}
	/* and the light's plane, where every test ends */
	return add_plane(region, vcross(axes[0], axes[1]), centre, apex, margin);
}
