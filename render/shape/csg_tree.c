/* csg_tree.c: the members of a large CSG node ordered hard ones first, and the binary
 * hierarchy over the others' bounds (csg_tree.h), split at the median centroid of the
 * longest axis. */
#include "csg_tree.h"

#include <math.h>

#include "csg.h"
#include "geometry.h"

enum { LEAF_MEMBERS = 4 };

/* The answer of member m's inside test outside the bounds of its surfaces (where it has
 * one answer), or -1 when they are unbounded or empty. */
static int outside_answer(const struct geometry *g, uint32_t m)
{
	struct vec3 lo = g->parts[m].lo, hi = g->parts[m].hi;
	if (!(isfinite(lo.x) && isfinite(lo.y) && isfinite(lo.z) && isfinite(hi.x) && isfinite(hi.y) && isfinite(hi.z)))
		return -1;
	return csg_inside(g, m, v3(hi.x + fabs(hi.x) + 1, hi.y + fabs(hi.y) + 1, hi.z + fabs(hi.z) + 1));
}

static double centre(const struct geometry *g, uint32_t m, int axis)
{
	return 0.5 * (vget(&g->parts[m].lo, axis) + vget(&g->parts[m].hi, axis));
}

/* Puts the members m[0, n) in an order where m[k] has the k-th smallest centre on axis,
 * those before it none larger and those after it none smaller (Hoare's selection). */
static void select_nth(const struct geometry *g, uint32_t *m, uint32_t n, uint32_t k, int axis)
{
	int64_t lo = 0, hi = (int64_t)n - 1;
	while (lo < hi) {
		double pivot = centre(g, m[lo + (hi - lo) / 2], axis);
		int64_t i = lo, j = hi;
		while (i <= j) {
			while (centre(g, m[i], axis) < pivot)
				i++;
			while (centre(g, m[j], axis) > pivot)
				j--;
			if (i <= j) {
				uint32_t s = m[i];
				m[i++] = m[j];
				m[j--] = s;
			}
		}
		if ((int64_t)k <= j)
			hi = j;
		else if ((int64_t)k >= i)
			lo = i;
		else
			return;
	}
}

/* Fills boxes[slot] for the members at positions [pos, pos + n) of the node's range m. */
static void build(const struct geometry *g, uint32_t *m, uint32_t pos, uint32_t n, struct csg_box *boxes,
                  size_t slot, size_t *used, uint32_t first)
{
	struct vec3 lo = v3s(INFINITY), hi = v3s(-INFINITY), clo = v3s(INFINITY), chi = v3s(-INFINITY);
	for (uint32_t i = pos; i < pos + n; i++) {
		lo = vmin(lo, g->parts[m[i]].lo);
		hi = vmax(hi, g->parts[m[i]].hi);
		struct vec3 c = v3(centre(g, m[i], 0), centre(g, m[i], 1), centre(g, m[i], 2));
		clo = vmin(clo, c);
		chi = vmax(chi, c);
	}
	if (n <= LEAF_MEMBERS) {
		boxes[slot] = (struct csg_box){ lo, hi, pos, n };
		return;
	}
	struct vec3 ext = vsub(chi, clo);
	int axis = ext.x >= ext.y && ext.x >= ext.z ? 0 : ext.y >= ext.z ? 1 : 2;
	uint32_t half = n / 2;
	select_nth(g, m + pos, n, half, axis);
	size_t kids = *used;
	*used += 2;
	boxes[slot] = (struct csg_box){ lo, hi, (uint32_t)(first + kids), 0 };
	build(g, m, pos, half, boxes, kids, used, first);
	build(g, m, pos + half, n - half, boxes, kids + 1, used, first);
}

size_t csg_tree_build(struct geometry *g, struct part *p, struct csg_box *boxes, uint32_t first)
{
	uint32_t *m = g->members + p->first;
	int wanted = p->op == PART_INTERSECT;
	/* hard members first, in their order (the tie rule goes by leaf, not by position) */
	uint32_t hard = 0;
	for (uint32_t k = 0; k < p->count; k++)
		if (outside_answer(g, m[k]) != wanted) {
			uint32_t s = m[k];
			for (uint32_t j = k; j > hard; j--)
				m[j] = m[j - 1];
			m[hard++] = s;
		}
	p->hard = hard;
	p->tree = CSG_NO_TREE;
	if (p->count - hard <= CSG_TREE_MIN)
		return 0;
	size_t used = 1;
	build(g, m, hard, p->count - hard, boxes, 0, &used, first);
	p->tree = first;
	return used;
}
