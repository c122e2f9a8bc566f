/* bvh.h: the acceleration structure over a scene's bounded primitives (spheres and
 * triangles); planes, being unbounded, are tested beside it. The two queries are the
 * closest hit and the shadow filter. */
#ifndef SCN_BVH_H
#define SCN_BVH_H

#include "shape.h"

/* Children per node of the traversal's tree; and the primitives from which a tree is
 * taken to be too big for the caches, which changes how it is built and walked
 * (bvh_build.c's struct sah, bvh_traverse.c's prefetch_nodes()). */
enum { BVH_WIDTH = 8, BVH_BIG_TREE = 1 << 18 };

/* Builds over geo's spheres and triangles, on every core; the tree is the same whatever
 * their number. one_leaf makes one leaf of everything: brute force through the same
 * code, for tests and the scaling study (--accel none). */
struct bvh *bvh_build(const struct geometry *geo, bool one_leaf);
void bvh_free(struct bvh *b);
/* Puts geo's spheres and triangles in the order b's leaves list them (b built on geo) and
 * renumbers the leaves to match: the primitives a ray tests one after another then share
 * cache lines, where a scene in random order costs a cache miss per primitive tested.
 * Then copies each leaf of two triangles or more into packets of four (tri_packet.h),
 * which the traversal tests four at once. The image stays the same: the same primitives
 * are tested in the same order, with the same arithmetic. Any other accelerator built on
 * geo is left pointing at the old numbers. */
void bvh_reorder(struct bvh *b, struct geometry *geo);
/* The most bytes bvh_build and bvh_reorder hold at once for n primitives of which
 * ntriangles are triangles (the build records, the nodes of a tree with one primitive a
 * leaf, the triangle packets). */
uint64_t bvh_bytes(uint64_t n, uint64_t ntriangles);

/* Closest hit with 0 < t < h->t over every primitive, planes included; updates h. */
bool bvh_intersect(const struct bvh *b, const struct geometry *geo, const struct ray *r, struct hit *h);

/* The light that passes along r from its origin to tmax: the product of k_t over every
 * surface crossed (POV-Ray's filtered shadow). Stops early once it is black. */
struct vec3 bvh_transmittance(const struct bvh *b, const struct geometry *geo, const struct ray *r, double tmax);

/* A convex region, as the planes that bound it: x is inside when dot(n, x) <= d for every
 * plane (n, d), each row n.x, n.y, n.z, d. */
struct bvh_region {
	double plane[6][4];
	int nplanes;
};
/* A leaf of the tree, as the traversal names it, and its box. */
struct bvh_leaf {
	float lo[3], hi[3];
	uint32_t index, count;
};
/* The leaves whose boxes meet region, for many shadow rays that all stay inside it (an
 * area light's, from one point): at most cap of them into leaves, and their number; -1
 * when there are more. A segment inside region meets no primitive outside them. */
int bvh_gather(const struct bvh *b, const struct bvh_region *region, struct bvh_leaf *leaves, int cap);
/* Whether no primitive of leaves[0 .. n) but skip has bounds that meet region (a leaf of
 * triangle packets, whose triangles are not named, counts as meeting it). */
bool bvh_leaves_clear(const struct bvh *b, const struct geometry *geo, const struct bvh_leaf *leaves, int n,
                      const struct bvh_region *region, uint32_t skip);
/* bvh_transmittance of a ray that stays inside the region leaves[0 .. n) were gathered
 * for, which it walks in place of the tree. The same filters multiply, in the leaves'
 * order, which puts first the leaf that last turned a ray black: its neighbour rays are
 * often blocked by the same object. */
struct vec3 bvh_transmittance_among(const struct bvh *b, const struct geometry *geo, const struct ray *r, double tmax,
                                    struct bvh_leaf *leaves, int n);

/* The tree's shape, for --stats and the tests: every node (the wide interior ones and
 * the leaves), the interior ones alone, the triangle packets, and the depth. */
struct bvh_shape {
	size_t nodes, interior, packets;
	int depth;
};
struct bvh_shape bvh_shape(const struct bvh *b);

#endif
