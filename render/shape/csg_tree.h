/* csg_tree.h: what lets a CSG node of many members cost what its members cost on a ray,
 * not their number. Outside the bounds of its surfaces a member's inside test has one
 * answer, so an inside test of the node needs to ask only the members whose bounds hold
 * the point, once those whose answer outside would decide it (the "hard" ones: a
 * difference's first member) are put first and always asked; and a ray needs only the
 * members whose bounds it meets. A binary hierarchy over the other members' bounds finds
 * both. */
#ifndef SCN_CSG_TREE_H
#define SCN_CSG_TREE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "vec.h"

#define CSG_NO_TREE UINT32_MAX
/* Nodes with more members than this, not counting the hard ones, get a hierarchy. */
#define CSG_TREE_MIN 8

/* A box of the hierarchy: an interior one's children are boxes index and index + 1; a
 * leaf's members are the node's members index .. index + count - 1 (positions in its
 * range of geometry.members). */
struct csg_box {
	struct vec3 lo, hi;
	uint32_t index, count;         /* count 0: interior */
};

struct geometry;
struct part;

/* Orders the members of node p (a CSG part of g whose members' bounds are set), hard ones
 * first, and sets p->hard; when more than CSG_TREE_MIN others remain, builds their
 * hierarchy into boxes (room for 2 n - 1 of them, n the node's count), sets p->tree to
 * first, the index of boxes[0] in geometry.csg_boxes, and returns the boxes used; else
 * sets p->tree to CSG_NO_TREE and returns 0. */
size_t csg_tree_build(struct geometry *g, struct part *p, struct csg_box *boxes, uint32_t first);

/* Whether q lies within [lo, hi]. */
static inline bool csg_box_holds(struct vec3 lo, struct vec3 hi, struct vec3 q)
{
	return q.x >= lo.x && q.x <= hi.x && q.y >= lo.y && q.y <= hi.y && q.z >= lo.z && q.z <= hi.z;
}

#endif
