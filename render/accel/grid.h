/* grid.h: a uniform grid over a scene's spheres and triangles, the alternative to the
 * BVH (--accel grid) with the same two queries; planes stay outside it, as with the BVH. */
#ifndef SCN_GRID_H
#define SCN_GRID_H

#include "shape.h"

struct grid *grid_build(const struct geometry *geo);
void grid_free(struct grid *g);
/* The most bytes grid_build holds at once for n primitives: its cells at the most its
 * resolution rule and cap allow, the boxes, and the references at their cap. */
uint64_t grid_bytes(uint64_t n);

/* Closest hit with 0 < t < h->t over every primitive, planes included; updates h. */
bool grid_intersect(const struct grid *g, const struct geometry *geo, const struct ray *r, struct hit *h);

/* The product of k_t over every surface r crosses in (0, tmax), as bvh_transmittance. */
struct vec3 grid_transmittance(const struct grid *g, const struct geometry *geo, const struct ray *r, double tmax);

/* Cells along each axis and primitive references held, for --stats. */
void grid_shape(const struct grid *g, int cells[3], size_t *refs);

#endif
