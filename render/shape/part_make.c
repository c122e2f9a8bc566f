/* part_make.c: the leaf parts of part.h made from LANGUAGE.md section 9's definitions:
 * the frame that maps each shape's canonical form onto the one written, composed with
 * the object's transforms, and the world bounds. Axis-aligned shapes get frames of exact
 * unit vectors, so that a box or a cylinder along an axis is tested without rounding of
 * its own. */
#include "part_make.h"

#include <math.h>
#include <string.h>

/* Sets p's maps for the canonical-to-object frame f placed by x, and its bounds; false
 * when the map cannot be inverted in double. */
static bool place(struct part *p, const struct affine *f, const struct affine *x)
{
	p->to_world = affine_compose(x, f);
	p->moved = !affine_is_identity(&p->to_world);
	p->to_object = p->moved ? affine_inverse(&p->to_world) : affine_identity;
	if (!affine_finite(&p->to_world) || !affine_finite(&p->to_object))
		return false;
	part_leaf_bounds(p, &p->lo, &p->hi);
	return true;
}

static void start(struct part *p, enum part_kind kind)
{
	memset(p, 0, sizeof *p);
	p->kind = (uint8_t)kind;
}

/* The frame with columns e1, e2, e3 and origin o. */
static struct affine frame(struct vec3 e1, struct vec3 e2, struct vec3 e3, struct vec3 o)
{
	return (struct affine){ { { e1.x, e2.x, e3.x, o.x }, { e1.y, e2.y, e3.y, o.y }, { e1.z, e2.z, e3.z, o.z } } };
}

/* Two unit vectors u, v that with the unit w make an orthonormal frame; exact axes
 * when w is an axis. */
static void perpendicular(struct vec3 w, struct vec3 *u, struct vec3 *v)
{
	struct vec3 a = fabs(w.x) <= fabs(w.y) && fabs(w.x) <= fabs(w.z) ? v3(1, 0, 0)
	              : fabs(w.y) <= fabs(w.z) ? v3(0, 1, 0) : v3(0, 0, 1);
	*u = vunit(vcross(w, a));
	*v = vcross(w, *u);
}

bool part_make_sphere(struct part *p, struct vec3 center, double radius, const struct affine *x)
{
	start(p, PART_SPHERE);
	struct affine f = frame(v3(radius, 0, 0), v3(0, radius, 0), v3(0, 0, radius), center);
	return place(p, &f, x);
}

bool part_make_box(struct part *p, struct vec3 c0, struct vec3 c1, const struct affine *x)
{
	start(p, PART_BOX);
	struct vec3 lo = vmin(c0, c1), hi = vmax(c0, c1);
	memcpy(p->a, &lo, sizeof lo);
	memcpy(p->a + 3, &hi, sizeof hi);
	return place(p, &affine_identity, x);
}

bool part_make_cone(struct part *p, struct vec3 base, double r0, struct vec3 cap, double r1, bool open,
                    const struct affine *x)
{
	start(p, PART_CONE);
	double rmax = fmax(r0, r1);
	p->a[0] = r0 / rmax;
	p->a[1] = r1 / rmax;
	p->open = open;
	struct vec3 axis = vsub(cap, base), u, v;
	perpendicular(vunit(axis), &u, &v);
	struct affine f = frame(vscale(u, rmax), axis, vscale(v, rmax), base);
	return place(p, &f, x);
}

bool part_make_disc(struct part *p, struct vec3 center, struct vec3 normal, double radius, double hole,
                    const struct affine *x)
{
	start(p, PART_DISC);
	p->a[0] = hole / radius;
	struct vec3 w = vunit(normal), u, v;
	perpendicular(w, &u, &v);
	/* a flat shape: its frame's y is scaled as x and z are, for the best conditioned map */
	struct affine f = frame(vscale(u, radius), vscale(w, radius), vscale(v, radius), center);
	return place(p, &f, x);
}

bool part_make_torus(struct part *p, double major, double minor, const struct affine *x)
{
	start(p, PART_TORUS);
	p->a[0] = major;
	p->a[1] = minor;
	return place(p, &affine_identity, x);
}

bool part_make_plane(struct part *p, struct vec3 normal, double offset, const struct affine *x)
{
	start(p, PART_PLANE);
	/* kept in world space: the normal by the inverse transpose, the offset through a
	 * point of the plane */
	struct vec3 n = vunit(normal);
	struct affine inv = affine_inverse(x);
	struct vec3 on = affine_point(x, vscale(n, offset));
	struct vec3 wn = vunit(affine_normal(&inv, n));
	p->a[0] = wn.x;
	p->a[1] = wn.y;
	p->a[2] = wn.z;
	p->a[3] = vdot(wn, on);
	p->to_world = p->to_object = affine_identity;
	part_leaf_bounds(p, &p->lo, &p->hi);
	return isfinite(p->a[3]) && isfinite(wn.x) && isfinite(wn.y) && isfinite(wn.z);
}
