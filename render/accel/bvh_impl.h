/* bvh_impl.h: what the BVH's build (bvh_build.c), collapse (bvh_collapse.c), reordering
 * (bvh_reorder.c) and traversal (bvh_traverse.c) share: the nodes' layout and struct bvh.
 * The rest of the renderer sees bvh.h alone. */
#ifndef SCN_BVH_IMPL_H
#define SCN_BVH_IMPL_H

#include <math.h>

#include "bvh.h"
#include "tri_packet.h"
#include "v4f.h"

/* The traversal's node: the boxes of up to WIDTH children, coordinate by coordinate so
 * that one vector operation handles them all ([lo x, y, z, hi x, y, z][child]), and what
 * each child is. An unused slot has an empty box (lo +inf, hi -inf), which no ray meets.
 * Eight children measured faster than four on every benchmark scene, with AVX or
 * without (each step of a walk waits on the one before, and a wider node takes fewer
 * steps). 256 bytes, four cache lines. */
enum {
	WIDTH = BVH_WIDTH,
	MAX_DEPTH = 96,    /* below this every node is a leaf; traversal stacks are sized by it */
};
struct bvh_node {
	float box[6][WIDTH];
	uint32_t index[WIDTH]; /* child c: a node, or a leaf's first primitive (see LEAF_DIRECT) */
	uint32_t count[WIDTH]; /* child c: primitives in the leaf, and LEAF_DIRECT; 0: a node */
};

/* A leaf's count has LEAF_DIRECT set when its index is the shape_id() of its first
 * primitive and the others follow it: once bvh_reorder has put the scene's primitives in
 * leaf order, true of every leaf of one kind. Otherwise (as built, or both kinds in the
 * leaf) its index is its first entry in prims, which lists the ids. On big scenes the
 * load of the ids was a cache miss of its own on the way to the primitives (a sixth of
 * the traversal's time on the 1M-triangle bunny's random rays). */
#define LEAF_DIRECT (1u << 31)
/* A LEAF_DIRECT leaf of MIN_PACKED triangles or more has LEAF_PACKED set too, once
 * bvh_reorder has copied them into packets (tri_packet.h), PACKET_LANES a packet: its
 * index is then its first packet's in packets, the others following it, and each
 * packet names its triangles. */
#define LEAF_PACKED (1u << 30)

/* The primitives in a leaf. */
static inline uint32_t leaf_size(uint32_t count)
{
	return count & ~(LEAF_DIRECT | LEAF_PACKED);
}
/* The packets n triangles fill, PACKET_LANES a packet. */
static inline uint32_t leaf_packets(uint32_t n)
{
	return (n + PACKET_LANES - 1) / PACKET_LANES;
}

/* A subtree as its parent sees it. */
struct child {
	float box[6];
	uint32_t index, count;
};

/* A node of the binary tree the build makes; the wide tree is collapsed from it. */
struct bin_node {
	struct child kid[2];
};

struct bvh {
	struct child root;
	struct bvh_node *nodes;    /* WIDTH-wide, cache-line aligned */
	size_t nnodes, nboxes;
	uint32_t *prims;   /* shape_id()s in leaf order; NULL once no leaf needs them */
	size_t nprims;
	struct tri_packet *packets; /* of the LEAF_PACKED leaves, in leaf order */
	size_t npackets;
	int depth;
	bool big;                  /* BVH_BIG_TREE primitives or more: see prefetch_nodes() */
};

/* A box under construction: lo and hi as 4-vectors, the fourth lane unused. */
struct vbox {
	v4f lo, hi;
};

static inline struct vbox vbox_empty(void)
{
	return (struct vbox){ v4set(INFINITY), v4set(-INFINITY) };
}

static inline void vbox_add(struct vbox *b, v4f lo, v4f hi)
{
	b->lo = v4min(b->lo, lo);
	b->hi = v4max(b->hi, hi);
}

/* Half the surface area, in float: SAH only compares areas. */
static inline float vbox_area(struct vbox b)
{
	float e[4];
	v4store(e, v4sub(b.hi, b.lo));
	if (e[0] < 0)
		return 0;
	return e[0] * e[1] + e[1] * e[2] + e[2] * e[0];
}

/* How many spheres, triangles and solids a set holds: what its price as a leaf depends on. */
struct kinds {
	uint32_t n[4]; /* by enum shape_kind (planes are never counted) */
};

static inline void kinds_add(struct kinds *a, struct kinds b)
{
	for (int k = 0; k < 4; k++)
		a->n[k] += b.n[k];
}

static inline uint32_t kinds_total(struct kinds k)
{
	return k.n[0] + k.n[1] + k.n[2] + k.n[3];
}

/* The wide tree of the binary one, which it frees: sets bvh's nodes, nnodes, nboxes and
 * depth, and turns bvh->root into the wide root. parallel: on every thread. */
void bvh_make_wide(struct bvh *bvh, struct bin_node *bin, bool parallel);

#endif
