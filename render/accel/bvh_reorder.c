/* bvh_reorder.c: bvh_reorder() (bvh.h): the scene's primitives put in the order of the
 * tree's leaves, each leaf renumbered to name its primitives directly, and the leaves
 * of triangles copied into packets of four (tri_packet.h), on every thread. */
#include <stdlib.h>

#include "bvh_impl.h"
#include "parallel.h"
#include "xalloc.h"

enum {
	MIN_PACKED = 2,    /* triangles in a leaf from which they go to packets: at most n / 2 packets */
};

/* Makes a leaf (index, count) of shape_id()s of one kind, numbered in leaf order,
 * LEAF_DIRECT; true when the leaf still needs its ids (both kinds in it). Nodes are left
 * alone. */
static bool direct_leaf(const struct bvh *b, uint32_t *index, uint32_t *count)
{
	if (*count == 0)
		return false;
	const uint32_t *ids = b->prims + *index;
	for (uint32_t i = 1; i < *count; i++)
		if (shape_kind(ids[i]) != shape_kind(ids[0]))
			return true;
	*count |= LEAF_DIRECT;
	*index = ids[0];
	return false;
}

/* Whether a leaf's triangles go to packets: a LEAF_DIRECT leaf of MIN_PACKED or more. */
static bool packs(uint32_t index, uint32_t count)
{
	return (count & LEAF_DIRECT) && shape_kind(index) == SHAPE_TRIANGLE && leaf_size(count) >= MIN_PACKED;
}

/* Packs the leaf (index, count) from b->packets[*next] on, if it packs. */
static void pack_leaf(struct bvh *b, const struct geometry *geo, uint32_t *index, uint32_t *count, size_t *next)
{
	if (!packs(*index, *count))
		return;
	uint32_t first = shape_index(*index), n = leaf_size(*count);
	for (uint32_t i = 0; i < n; i += PACKET_LANES)
		tri_packet_fill(&b->packets[*next + i / PACKET_LANES], geo, first + i,
		                n - i < PACKET_LANES ? n - i : PACKET_LANES);
	*index = (uint32_t)*next;
	*count |= LEAF_PACKED;
	*next += leaf_packets(n);
}

static size_t packets_of(uint32_t index, uint32_t count)
{
	return packs(index, count) ? leaf_packets(leaf_size(count)) : 0;
}

/* The leaves made direct where they can be (direct_leaf()) and their triangles put in
 * packets, leaf by leaf in the nodes' order, on every thread: the nodes cut into chunks
 * (the first with the root), each chunk's leaves made direct and its packets counted,
 * then filled from where the chunks before it end. */
struct packing {
	struct bvh *b;
	const struct geometry *geo;
	size_t nchunks;
	size_t *first;     /* chunk c's first packet (its count, until the sum) */
	bool *ids_needed;  /* chunk c has a leaf that still needs its ids */
};

/* Leaf (index, count) made direct if it can be, its packets added to *n. */
static void count_leaf(const struct bvh *b, uint32_t *index, uint32_t *count, size_t *n, bool *ids_needed)
{
	*ids_needed |= direct_leaf(b, index, count);
	*n += packets_of(*index, *count);
}

static void count_packets(void *ctx, size_t c)
{
	struct packing *pk = ctx;
	struct bvh *b = pk->b;
	size_t lo, hi, n = 0;
	bool ids_needed = false;
	if (c == 0)
		count_leaf(b, &b->root.index, &b->root.count, &n, &ids_needed);
	parallel_chunk_items(b->nnodes, pk->nchunks, c, &lo, &hi);
	for (size_t i = lo; i < hi; i++)
		for (int k = 0; k < WIDTH; k++)
			count_leaf(b, &b->nodes[i].index[k], &b->nodes[i].count[k], &n, &ids_needed);
	pk->first[c] = n;
	pk->ids_needed[c] = ids_needed;
}

static void fill_packets(void *ctx, size_t c)
{
	struct packing *pk = ctx;
	struct bvh *b = pk->b;
	size_t lo, hi, next = pk->first[c];
	if (c == 0)
		pack_leaf(b, pk->geo, &b->root.index, &b->root.count, &next);
	parallel_chunk_items(b->nnodes, pk->nchunks, c, &lo, &hi);
	for (size_t i = lo; i < hi; i++)
		for (int k = 0; k < WIDTH; k++)
			pack_leaf(b, pk->geo, &b->nodes[i].index[k], &b->nodes[i].count[k], &next);
}

/* The leaves in their final form once the primitives are in leaf order: direct where
 * they can be, in packets where they pack; prims freed if no leaf needs it. */
static void finalize_leaves(struct bvh *b, const struct geometry *geo)
{
	size_t first[MAX_CHUNKS];
	bool ids_needed[MAX_CHUNKS], any_ids = false;
	struct packing pk = { b, geo, parallel_chunks(b->nnodes), first, ids_needed };
	parallel_for(pk.nchunks, count_packets, &pk);
	size_t n = 0;
	for (size_t c = 0; c < pk.nchunks; c++) {
		size_t count = first[c];
		first[c] = n;
		n += count;
		any_ids |= ids_needed[c];
	}
	if (!any_ids) {
		free(b->prims);
		b->prims = NULL;
	}
	if (n == 0)
		return;
	/* in huge pages: a random ray reads one packet or two in a big mesh, each a TLB miss
	 * of its own in 4 KiB pages (the 1M-triangle bunny's packets take 78 MB); its random
	 * rays were 7% and 14% faster (medians of two sets of 16 alternating pairs). This
	 * VM zeroes a fresh huge page slowly, which made that build 0.319 -> 0.345 s (medians
	 * of 10 runs). The nodes gained nothing so (12 MB there, within the TLB's reach);
	 * 10^6 spheres' nodes (76 MB) 2% on camera rays, against a build a fifth slower
	 * (622f9bd). */
	b->packets = xbig_alloc(n * sizeof *b->packets);
	b->npackets = n;
	parallel_for(pk.nchunks, fill_packets, &pk);
}

/* The scene's primitives copied in leaf order, on every thread: prims cut into chunks,
 * each chunk's spheres, triangles and solids counted, then copied from where the chunks before
 * it end, each entry of prims renumbered to its primitive's new place. */
struct reordering {
	struct bvh *b;
	const struct geometry *geo;       /* the primitives where they were */
	struct sphere *spheres;
	struct triangle *triangles;
	uint32_t *solids;
	size_t nchunks;
	struct kinds *first;          /* chunk c's first of each kind (its counts, until the sum) */
};

static void count_kinds(void *ctx, size_t c)
{
	struct reordering *ro = ctx;
	struct kinds k = { { 0 } };
	size_t lo, hi;
	parallel_chunk_items(ro->b->nprims, ro->nchunks, c, &lo, &hi);
	for (size_t i = lo; i < hi; i++)
		k.n[shape_kind(ro->b->prims[i])]++;
	ro->first[c] = k;
}

static void copy_chunk(void *ctx, size_t c)
{
	struct reordering *ro = ctx;
	uint32_t *prims = ro->b->prims;
	struct kinds next = ro->first[c];
	size_t lo, hi;
	parallel_chunk_items(ro->b->nprims, ro->nchunks, c, &lo, &hi);
	for (size_t i = lo; i < hi; i++) {
		enum shape_kind kind = shape_kind(prims[i]);
		uint32_t k = shape_index(prims[i]), to = next.n[kind]++;
		if (kind == SHAPE_SPHERE)
			ro->spheres[to] = ro->geo->spheres[k];
		else if (kind == SHAPE_TRIANGLE)
			ro->triangles[to] = ro->geo->triangles[k];
		else
			ro->solids[to] = ro->geo->solids[k];
		prims[i] = shape_id(kind, to);
	}
}

void bvh_reorder(struct bvh *b, struct geometry *geo)
{
	struct kinds first[MAX_CHUNKS];
	struct reordering ro = { b, geo, geo->nspheres ? xmalloc(geo->nspheres * sizeof *ro.spheres) : NULL,
		                 geo->ntriangles ? xmalloc(geo->ntriangles * sizeof *ro.triangles) : NULL,
		                 geo->nsolids ? xmalloc(geo->nsolids * sizeof *ro.solids) : NULL,
		                 parallel_chunks(b->nprims), first };
	parallel_for(ro.nchunks, count_kinds, &ro);
	struct kinds sum = { { 0 } };
	for (size_t c = 0; c < ro.nchunks; c++) {
		struct kinds count = first[c];
		first[c] = sum;
		kinds_add(&sum, count);
	}
	parallel_for(ro.nchunks, copy_chunk, &ro);
	free(geo->spheres);
	free(geo->triangles);
	free(geo->solids);
	geo->spheres = ro.spheres;
	geo->triangles = ro.triangles;
	geo->solids = ro.solids;
	finalize_leaves(b, geo);
}
