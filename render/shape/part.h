/* part.h: the shapes that are intersected in a space of their own (LANGUAGE.md section 9):
 * the ellipsoid (a sphere under any transform), box, cylinder and cone, disc, torus and
 * plane as parts of a CSG, and the CSG nodes over them (csg.h). Each leaf keeps the map
 * from world space to a canonical space where its test is simple and exact, and back; a
 * ray is mapped there with its parameter t unchanged (the direction is not renormalised),
 * so hits of parts in different spaces compare directly. */
#ifndef SCN_PART_H
#define SCN_PART_H

#include <stdbool.h>
#include <stdint.h>

#include "affine.h"
#include "ray.h"

/* The canonical shapes:
 * PART_SPHERE  the unit sphere about the origin
 * PART_BOX     the box lo <= p <= hi (a[0..2] lo, a[3..5] hi)
 * PART_CONE    0 <= y <= 1, x^2 + z^2 <= r(y)^2 with r(y) = a[0] + (a[1] - a[0]) y, the larger
 *              radius 1 (a cylinder has both 1); end discs unless open
 * PART_DISC    y = 0, a[0]^2 <= x^2 + z^2 <= 1 (a[0] the hole's radius)
 * PART_TORUS   about the y axis: major radius a[0], minor a[1]
 * PART_PLANE   in world space: p . n < a[3] is inside, n = a[0..2]
 * PART_MESH    in world space: the closed mesh part_triangles[first .. first + count),
 *              inside by the parity of its crossings along a[0..2] (POV-Ray's inside_vector)
 * PART_CSG     members[first .. first + count) combined by op */
enum part_kind { PART_SPHERE, PART_BOX, PART_CONE, PART_DISC, PART_TORUS, PART_PLANE, PART_MESH, PART_CSG };

/* How a CSG node counts its members' surfaces, with inversion pushed down to the leaves
 * (De Morgan, as POV-Ray inverts a CSG): a difference is an intersection whose members
 * after the first are inverted. */
enum part_op {
	PART_ALL,          /* union: every member's surface; inside: inside any member */
	PART_INTERSECT,    /* a member's surface where it is inside every other member; inside all */
	PART_MERGE,        /* a member's surface where it is outside every other member; inside any */
};

struct part {
	uint8_t kind;                  /* enum part_kind */
	uint8_t op;                    /* PART_CSG: enum part_op */
	bool inverse;                  /* a leaf's inside and outside swapped, its normal turned */
	bool open;                     /* PART_CONE: no end discs */
	bool moved;                    /* to_object is not the identity */
	uint32_t surface;              /* a leaf's, into geometry.surfaces */
	uint32_t first, count;         /* PART_CSG: its members, into geometry.members;
	                                * PART_MESH: its triangles, into geometry.part_triangles */
	uint32_t hard;                 /* PART_CSG: its first `hard` members are those an inside test
	                                * must always ask (csg_tree.h); the others, only at points
	                                * within their bounds */
	uint32_t tree;                 /* PART_CSG: the root of the hierarchy over its other members,
	                                * into geometry.csg_boxes, or CSG_NO_TREE */
	double a[6];                   /* the canonical shape's numbers, above */
	struct affine to_object;       /* world -> canonical space (when moved) */
	struct affine to_world;        /* canonical -> world space (when moved) */
	struct vec3 lo, hi;            /* world bounds, rounded outward; infinite when unbounded */
};

/* The t in (0, tmax) where r crosses leaf p's surface (not a mesh: see csg.h), ascending
 * (at most 4); how many.
 * A ray that starts on the surface (its origin offset by ray_offset_origin()) does not
 * cross it again at t ~ 0. */
int part_crossings(const struct part *p, const struct ray *r, double tmax, double t[4]);
/* The first of part_crossings()'s t beyond t_after (the same t), in *t; false when there is
 * none. A torus's later roots are not solved for. */
bool part_next(const struct part *p, const struct ray *r, double t_after, double tmax, double *t);
/* The surface of leaf p where r crosses it at t: the point computed from the shape, its
 * error bound, the outward normal (turned inward for an inverse leaf); shading normal
 * the same. */
void part_surface(const struct part *p, const struct ray *r, double t, struct surface_point *sp);
/* Whether world point q lies inside leaf p (a solid); exact in canonical space, without
 * tolerance: CSG asks it only at points moved off the surfaces (csg.c). */
bool part_inside_leaf(const struct part *p, struct vec3 q);
/* The world bounds of leaf p's surface from its canonical ones and to_world, rounded
 * outward; infinite for a plane. */
void part_leaf_bounds(const struct part *p, struct vec3 *lo, struct vec3 *hi);

#endif
