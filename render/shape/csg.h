/* csg.h: the solids of a scene (geometry.solids): trees of parts (part.h) whose leaves are
 * shapes and whose nodes are CSG operations with POV-Ray's rules (LANGUAGE.md section 9),
 * asked for their closest visible surface, every visible surface a shadow ray crosses, and
 * whether a point is inside. */
#ifndef SCN_CSG_H
#define SCN_CSG_H

#include <stdbool.h>
#include <stdint.h>

#include "ray.h"

struct geometry;

/* A visible surface of a part along a ray: where, and which leaf's surface it is. */
struct csg_hit {
	double t;
	uint32_t leaf;                 /* into geometry.parts */
};

/* The closest visible surface of part `part` with t_after < t < tmax along r; false when
 * there is none. Surfaces shared by two members (a cutter flush with a face) count by the
 * regularised set operation, decided at a point moved off the surface into the member
 * whose surface it is or out of it (so that the whole face gets one answer), and of two
 * members' surfaces at one place the earlier member's is the one seen. */
bool csg_next(const struct geometry *g, uint32_t part, const struct ray *r, double t_after, double tmax,
              struct csg_hit *out);
/* The surface of leaf `leaf` where r meets it at t (part_surface(), and for a mesh the
 * triangle there). */
void csg_surface(const struct geometry *g, uint32_t leaf, const struct ray *r, double t, struct surface_point *sp);
/* Whether world point q lies inside part `part`. */
bool csg_inside(const struct geometry *g, uint32_t part, struct vec3 q);

/* Sets the bounds of part `part` and of every node below it from their leaves' (the
 * surfaces of a union or merge lie within its members', an intersection's also within
 * the solid of every member), and gives the bounds of its solid: infinite for a plane or
 * an inverse part, empty (lo above hi) for an intersection of disjoint members. */
void csg_bound(struct geometry *g, uint32_t part, struct vec3 *solid_lo, struct vec3 *solid_hi);

#endif
