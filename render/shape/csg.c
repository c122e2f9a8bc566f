/* csg.c: the CSG of part.h's nodes (csg.h). A node's visible surfaces are found member by
 * member, each member's surfaces in order along the ray until one counts; for a node of
 * PART_INTERSECT a member's surface counts where the other members hold the point just
 * inside it, for PART_MERGE where none holds the point just outside it (POV-Ray's
 * Inside_Object tests at the point itself, which on a shared face is decided by rounding:
 * speckle). */
#include "csg.h"

#include <math.h>

#include "geometry.h"

/* How far the point of an inside test is moved off a surface, in multiples of the hit
 * point's error bound: far enough that rounding cannot put it on the wrong side of a
 * surface that coincides with this one, and far below a pixel's footprint. */
#define NUDGE 1024.0
/* Two members' surfaces closer than this many times their error bounds (along the
 * normal) are one surface, shown by the earlier member. */
#define SAME_SURFACE 1024.0
/* How far past the closest surface so far a member's surface is still looked at, for
 * that rule: a relative margin far above the t of two coinciding surfaces' difference. */
#define TIE_MARGIN 0x1p-20

/* Whether the ray from o with inverse direction inv may meet the box [lo, hi] at a t in
 * [t0, t1]: slabs in double. A NaN (a zero direction on a slab plane: 0 * inf) fails the
 * comparisons, which keep t0 and t1 as they were. */
static bool box_meets(struct vec3 lo, struct vec3 hi, struct vec3 o, struct vec3 inv, double t0, double t1)
{
	for (int k = 0; k < 3; k++) {
		double ik = vget(&inv, k), ok = vget(&o, k);
		double a = (vget(&lo, k) - ok) * ik, b = (vget(&hi, k) - ok) * ik;
		if (a > b) {
			double s = a;
			a = b;
			b = s;
		}
		b *= 1 + 2 * rounding_gamma(3);
		t0 = a > t0 ? a : t0;
		t1 = b < t1 ? b : t1;
	}
	return t0 <= t1;
}

/* The mesh part p's triangle that r meets first with t_after < t < tmax, or -1; *t set.
 * Every triangle is tested (a mesh in a CSG has no accelerator of its own). */
static int64_t mesh_next(const struct geometry *g, const struct part *p, const struct ray *r, double t_after,
                         double tmax, double *t)
{
	struct triangle_ray tr;
	triangle_ray_init(r, &tr);
	int64_t best = -1;
	*t = tmax;
	for (uint32_t i = p->first; i < p->first + p->count; i++) {
		struct hit h = { .t = INFINITY };
		if (triangle_intersect(&tr, &g->part_triangles[i], g->vertices, &h) && h.t > t_after && h.t < *t) {
			*t = h.t;
			best = i;
		}
	}
	return best;
}

void csg_surface(const struct geometry *g, uint32_t leaf, const struct ray *r, double t, struct surface_point *sp)
{
	const struct part *p = &g->parts[leaf];
	if (p->kind != PART_MESH) {
		part_surface(p, r, t, sp);
		return;
	}
	/* the triangle hit at t: the one whose test gives that very t */
	struct triangle_ray tr;
	triangle_ray_init(r, &tr);
	for (uint32_t i = p->first; i < p->first + p->count; i++) {
		struct hit h = { .t = INFINITY };
		if (triangle_intersect(&tr, &g->part_triangles[i], g->vertices, &h) && h.t == t) {
			triangle_surface(&g->part_triangles[i], g->vertices, g->normals, &h, sp);
			break;
		}
	}
	if (p->inverse) {
		sp->ng = vneg(sp->ng);
		sp->ns = vneg(sp->ns);
	}
}

/* Whether q is inside the mesh part p: an odd number of its triangles along a[0..2]. */
static bool mesh_inside(const struct geometry *g, const struct part *p, struct vec3 q)
{
	struct ray r = { q, v3(p->a[0], p->a[1], p->a[2]) };
	struct triangle_ray tr;
	triangle_ray_init(&r, &tr);
	bool in = false;
	for (uint32_t i = p->first; i < p->first + p->count; i++) {
		struct hit h = { .t = INFINITY };
		in ^= triangle_intersect(&tr, &g->part_triangles[i], g->vertices, &h);
	}
	return in != p->inverse;
}

/* Whether member m's bounds, widened by w, hold q. */
static bool member_near(const struct geometry *g, uint32_t m, struct vec3 w, struct vec3 q)
{
	return csg_box_holds(vsub(g->parts[m].lo, w), vadd(g->parts[m].hi, w), q);
}

/* Whether each member at positions [from, to) of node p, but the one at skip, whose bounds
 * widened by w hold q, passes: with test, when its inside test at q answers wanted;
 * without, never. */
static bool range_pass(const struct geometry *g, const struct part *p, uint32_t from, uint32_t to, uint32_t skip,
                       struct vec3 w, struct vec3 q, bool test, bool wanted)
{
	const uint32_t *m = g->members + p->first;
	for (uint32_t j = from; j < to; j++)
		if (j != skip && member_near(g, m[j], w, q) && (!test || csg_inside(g, m[j], q) != wanted))
			return false;
	return true;
}

/* range_pass() over node p's members after the hard ones, through the hierarchy when the
 * node has one: then for only the leaves whose boxes, widened by slack, hold q. */
static bool soft_members_pass(const struct geometry *g, const struct part *p, uint32_t skip, struct vec3 q,
                              double slack, bool test, bool wanted)
{
	struct vec3 w = v3s(slack);
	if (p->tree == CSG_NO_TREE)
		return range_pass(g, p, p->hard, p->count, skip, w, q, test, wanted);
	uint32_t stack[64], sp = 0;
	stack[sp++] = p->tree;
	while (sp) {
		const struct csg_box *b = &g->csg_boxes[stack[--sp]];
		if (!csg_box_holds(vsub(b->lo, w), vadd(b->hi, w), q))
			continue;
		if (!b->count) {
			stack[sp++] = b->index;
			stack[sp++] = b->index + 1;
		} else if (!range_pass(g, p, b->index, b->index + b->count, skip, w, q, test, wanted)) {
			return false;
		}
	}
	return true;
}

/* Whether every member of node p but the one at position skip answers `wanted` to the
 * inside test at q: the hard members always asked, the others only where their bounds
 * hold q (outside, their answer is `wanted`: csg_tree.h). */
static bool members_all(const struct geometry *g, const struct part *p, uint32_t skip, struct vec3 q, bool wanted)
{
	const uint32_t *m = g->members + p->first;
	for (uint32_t j = 0; j < p->hard; j++)
		if (j != skip && (!member_near(g, m[j], v3s(0), q) || csg_inside(g, m[j], q) != wanted))
			return false;
	return soft_members_pass(g, p, skip, q, 0, true, wanted);
}

bool csg_inside(const struct geometry *g, uint32_t part, struct vec3 q)
{
	const struct part *p = &g->parts[part];
	if (p->kind == PART_MESH)
		return mesh_inside(g, p, q);
	if (p->kind != PART_CSG)
		return part_inside_leaf(p, q);
	/* an intersection: inside all members; a union or merge: not outside all */
	bool all = p->op == PART_INTERSECT;
	return members_all(g, p, UINT32_MAX, q, all) == all;
}

/* Whether the surface sp of the member at position k of node p counts: see the file's
 * comment. */
static bool counts(const struct geometry *g, const struct part *p, uint32_t k, const struct surface_point *sp)
{
	if (p->op == PART_ALL)
		return true;
	double nudge = NUDGE * vmaxc(sp->p_err) + 0x1p-1000;
	bool intersect = p->op == PART_INTERSECT;
	return members_all(g, p, k, vmad(sp->p, intersect ? -nudge : nudge, sp->ng), intersect);
}

/* The search of csg_next() in node p: the closest counted surface so far. */
struct csg_search {
	const struct ray *r;
	struct vec3 inv;               /* 1 / r->d, for the members' boxes */
	double t_after, tmax;
	struct csg_hit best;
	double best_err;               /* the best surface's error along its normal */
	bool found;
};

/* How far the members are searched: past the best so far by the margin of the tie rule. */
static double search_limit(const struct csg_search *s)
{
	return s->found ? fmin(s->tmax, s->best.t * (1 + TIE_MARGIN)) : s->tmax;
}

/* Whether every member of node p but the one at position k is one whose bounds decide
 * (not hard) and whose bounds, widened by slack, do not hold q: then every inside test
 * near q gives the node's wanted answer, and a surface at q counts without being computed. */
static bool alone(const struct geometry *g, const struct part *p, uint32_t k, struct vec3 q, double slack)
{
	return p->hard <= (k < p->hard ? 1u : 0u) && soft_members_pass(g, p, k, q, slack, false, false);
}

/* A surface's error along its normal, the measure of the tie rule. */
static double normal_error(const struct surface_point *sp)
{
	return vdot(vabs(sp->ng), sp->p_err);
}

/* Looks at the member at position k of node p: its first surface that counts, if any,
 * against the best so far. A surface point is computed only where it is needed: for the
 * inside tests near other members, and for the tie rule when two surfaces count. */
static void visit_member(const struct geometry *g, const struct part *p, uint32_t k, struct csg_search *s)
{
	uint32_t m = g->members[p->first + k];
	double limit = search_limit(s);
	if (!box_meets(g->parts[m].lo, g->parts[m].hi, s->r->o, s->inv, s->t_after, limit))
		return;
	struct csg_hit c;
	for (double t0 = s->t_after; csg_next(g, m, s->r, t0, limit, &c); t0 = c.t) {
		struct surface_point sp;
		/* far above the nudge of counts() and the error of o + t d */
		struct vec3 q = vmad(s->r->o, c.t, s->r->d);
		bool computed = !(p->op == PART_ALL || alone(g, p, k, q, 0x1p-20 * (vmaxc(vabs(q)) + c.t)));
		if (computed) {
			csg_surface(g, c.leaf, s->r, c.t, &sp);
			if (!counts(g, p, k, &sp))
				continue;
		}
		if (!s->found) {
			s->best = c;
			s->best_err = computed ? normal_error(&sp) : NAN;
			s->found = true;
			return;
		}
		if (!computed)
			csg_surface(g, c.leaf, s->r, c.t, &sp);
		if (isnan(s->best_err)) {
			struct surface_point best;
			csg_surface(g, s->best.leaf, s->r, s->best.t, &best);
			s->best_err = normal_error(&best);
		}
		double err = normal_error(&sp);
		/* one surface when closer along the normal than their error bounds allow */
		bool same = fabs(s->best.t - c.t) * fabs(vdot(s->r->d, sp.ng)) <= SAME_SURFACE * (err + s->best_err);
		if (same ? c.leaf < s->best.leaf : c.t < s->best.t) {
			s->best = c;
			s->best_err = err;
		}
		return;
	}
}

bool csg_next(const struct geometry *g, uint32_t part, const struct ray *r, double t_after, double tmax,
              struct csg_hit *out)
{
	const struct part *p = &g->parts[part];
	if (p->kind == PART_MESH) {
		double t;
		if (mesh_next(g, p, r, t_after, tmax, &t) < 0)
			return false;
		*out = (struct csg_hit){ t, part };
		return true;
	}
	if (p->kind != PART_CSG) {
		double t;
		if (!part_next(p, r, t_after, tmax, &t))
			return false;
		*out = (struct csg_hit){ t, part };
		return true;
	}
	struct csg_search s = { .r = r, .inv = v3(1 / r->d.x, 1 / r->d.y, 1 / r->d.z), .t_after = t_after, .tmax = tmax };
	for (uint32_t k = 0; k < p->hard; k++)
		visit_member(g, p, k, &s);
	if (p->tree == CSG_NO_TREE) {
		for (uint32_t k = p->hard; k < p->count; k++)
			visit_member(g, p, k, &s);
	} else {
		uint32_t stack[64], sp = 0;
		stack[sp++] = p->tree;
		while (sp) {
			const struct csg_box *b = &g->csg_boxes[stack[--sp]];
			if (!box_meets(b->lo, b->hi, r->o, s.inv, t_after, search_limit(&s)))
				continue;
			if (!b->count) {
				stack[sp++] = b->index;
				stack[sp++] = b->index + 1;
				continue;
			}
			for (uint32_t k = b->index; k < b->index + b->count; k++)
				visit_member(g, p, k, &s);
		}
	}
	if (s.found)
		*out = s.best;
	return s.found;
}

void csg_bound(struct geometry *g, uint32_t part, struct vec3 *solid_lo, struct vec3 *solid_hi)
{
	struct part *p = &g->parts[part];
	if (p->kind != PART_CSG) {
		bool everywhere = p->inverse || p->kind == PART_PLANE;
		if (p->kind == PART_MESH) { /* its bounds, from its triangles' */
			p->lo = v3s(INFINITY);
			p->hi = v3s(-INFINITY);
			for (uint32_t i = p->first; i < p->first + p->count; i++) {
				struct vec3 lo, hi;
				triangle_bounds(&g->part_triangles[i], g->vertices, &lo, &hi);
				p->lo = vmin(p->lo, lo);
				p->hi = vmax(p->hi, hi);
			}
		}
		*solid_lo = everywhere ? v3s(-INFINITY) : p->lo;
		*solid_hi = everywhere ? v3s(INFINITY) : p->hi;
		return;
	}
	bool intersect = p->op == PART_INTERSECT;
	struct vec3 lo = v3s(INFINITY), hi = v3s(-INFINITY);
	*solid_lo = v3s(intersect ? -INFINITY : INFINITY);
	*solid_hi = v3s(intersect ? INFINITY : -INFINITY);
	for (uint32_t k = 0; k < p->count; k++) {
		uint32_t m = g->members[p->first + k];
		struct vec3 slo, shi;
		csg_bound(g, m, &slo, &shi);
		p = &g->parts[part];
		lo = vmin(lo, g->parts[m].lo);
		hi = vmax(hi, g->parts[m].hi);
		*solid_lo = intersect ? vmax(*solid_lo, slo) : vmin(*solid_lo, slo);
		*solid_hi = intersect ? vmin(*solid_hi, shi) : vmax(*solid_hi, shi);
	}
	/* an intersection's surfaces lie within every member */
	p->lo = intersect ? vmax(lo, *solid_lo) : lo;
	p->hi = intersect ? vmin(hi, *solid_hi) : hi;
}
