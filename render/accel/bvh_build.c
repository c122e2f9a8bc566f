/* bvh_build.c: a binned SAH bounding volume hierarchy (Wald, "On fast Construction of
 * SAH-based Bounding Volume Hierarchies", 2007), built binary, then collapsed into the
 * traversal's wide nodes (bvh_collapse.c). Bounds are kept in float, rounded outward, so
 * a box never loses what it holds (NUMERICS.md section 1).
 *
 * The build splits the top of the tree on one thread and hands the subtrees below a size
 * fixed by the primitive count to worker threads, each node going to a slot fixed by
 * where its split falls; the collapse into wide nodes hands out subtrees the same way.
 * The tree and its layout depend on the scene alone, never on the thread count or on
 * which thread finished first. */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bvh_impl.h"
#include "parallel.h"
#include "xalloc.h"

enum {
	NBINS = 16,        /* SAH bins per axis: Wald found 16 as good as a full sweep */
	MAX_LEAF = 8,      /* never more in a leaf unless the primitives cannot be split */
	MIN_TASK = 4096,   /* primitives in a subtree worth a thread of its own */
	TASKS_PER_TREE = 64, /* subtrees the top split aims for, so that threads share the work evenly */
};

/* A primitive's bounds, already rounded outward to float, and the centre of its exact
 * bounds, which steers the splits (primitives with the same centre stay together). The
 * fourth lane of each is padding, for the vector code. */
struct build_ref {
	float lo[4], hi[4], centroid[4];
	uint32_t prim, pad[3];
};

/* What the build knows of a set of references before it splits them: the box of their
 * bounds and the box of their centroids. Each split's partition works out its two
 * sides', so no node needs a pass of its own over its references. */
struct bounds {
	struct vbox box, cbox;
};

static inline void bounds_add(struct bounds *b, const struct build_ref *r)
{
	v4f c = v4load(r->centroid);
	vbox_add(&b->box, v4load(r->lo), v4load(r->hi));
	vbox_add(&b->cbox, c, c);
}

/* A subtree left to a worker: its primitives are refs[first, +n); it becomes child c of
 * the top node parent (NO_PARENT: the root). */
#define NO_PARENT UINT32_MAX
struct task {
	uint32_t parent, c, first, n;
	int depth;               /* its level in the tree */
	struct bounds bounds;    /* of its references */
};

/* The SAH's prices, in units: a node visit, a sphere test, and a test of a packet of up
 * to four triangles (tri_packet.h), a leaf's triangles being priced by the packets they
 * fill, so that leaves come in fours. In small trees a node visit and a sphere test cost
 * 1 and a packet 2 (a packet at 1 cost the bunny's rays 3% more instructions). In a tree
 * of BVH_BIG_TREE primitives or more, whose lower nodes no longer stay in cache, a node
 * visit costs a packet test, a cache miss each: there the leaves grow and the node array
 * shrinks (1M-triangle bunny: 3.8 triangles a packet, 12 MB of nodes; 54 MB at a node
 * price of 1 and one triangle a unit). The spheres keep the node's price: at three times
 * it, 10^6 spheres' leaves held 3.3 spheres and their camera rays tested 11.8 spheres
 * each instead of 1.5 (a leaf's box around small spheres far apart is mostly empty), with
 * no faster a render. */
struct sah {
	unsigned node, sphere, packet, solid;
};

static inline double leaf_price(const struct sah *sah, struct kinds k)
{
	return (double)k.n[SHAPE_SPHERE] * sah->sphere + (double)leaf_packets(k.n[SHAPE_TRIANGLE]) * sah->packet +
	       (double)k.n[SHAPE_SOLID] * sah->solid;
}

/* The binary tree goes to bin, one slot per place a split can fall: the node that
 * splits refs[first, +n) before refs[first + mid] is bin[first + mid - 1], a slot no
 * other node can take. So every subtree, a worker's too, has its slots known before it
 * is built, and the tree needs no joining of per-thread arrays. */
struct builder {
	struct build_ref *refs;
	uint32_t *prims;
	struct bin_node *bin;    /* n - 1 slots; the ones inside leaves stay unused */
	struct child root;
	bool brute;
	struct sah sah;
	size_t task_size;        /* a subtree this small becomes a task; 0 while inside one */
	struct task *tasks;
	size_t ntasks, cap_tasks;
};

/* Float bounds that still contain the double ones, with room for x's own rounding
 * error: a float equal to x steps one more ulp out (x - r and x + r of a sphere are
 * rounded; a float strictly beyond x is beyond x's error too, as x's neighbours in double
 * lie between). */
static float float_below(double x)
{
	float f = (float)x;
	if ((double)f < x || f == -INFINITY)
		return f;
	if (f == 0)
		return -FLT_TRUE_MIN;
	uint32_t u;
	memcpy(&u, &f, sizeof u);
	u = f > 0 ? u - 1 : u + 1; /* the next float down, by its bits */
	memcpy(&f, &u, sizeof f);
	return f;
}

static float float_above(double x)
{
	return -float_below(-x);
}

/* The bins of a set of centroids, on the three axes at once: lane a of (c - lo) * scale,
 * clamped to [0, top] and truncated, in float; find_split() and partition() share it,
 * so a centroid falls in the same bin in both. A NaN (the centroids of a scene beyond
 * float range) falls in bin 0. */
struct binning {
	v4f lo, scale, top;
};

static struct binning binning_of(struct vbox cbox, int nbins)
{
	float lo[4], hi[4], scale[4] = { 0 };
	v4store(lo, cbox.lo);
	v4store(hi, cbox.hi);
	for (int a = 0; a < 3; a++) {
		float extent = hi[a] - lo[a];
		scale[a] = extent > 0 ? (float)nbins / extent : 0;
	}
	return (struct binning){ cbox.lo, v4load(scale), v4set((float)(nbins - 1)) };
}

static inline void bins_of(const struct binning *bn, const float centroid[4], int k[4])
{
	v4f f = v4mul(v4sub(v4load(centroid), bn->lo), bn->scale);
	v4trunc(v4min(v4max(f, v4set(0)), bn->top), k);
}

struct split {
	int axis;                /* -1: none */
	int bin;                 /* split before this bin */
	struct binning bn;
};

/* Finds the cheapest binned SAH split of refs[0, n) whose centroids span cbox, all
 * three axes binned in one pass, in as many bins as there are references up to NBINS
 * (the sweep over the bins would cost small nodes more than the binning). axis -1 when
 * keeping a leaf is cheaper. */
static struct split find_split(const struct build_ref *refs, size_t n, struct vbox cbox, double parent_area,
                               const struct sah *sah)
{
	struct split best = { .axis = -1 };
	int nbins = n < NBINS ? (int)n : NBINS;
	struct binning bn = binning_of(cbox, nbins);
	float scale[4];
	v4store(scale, bn.scale);
	struct vbox bins[3][NBINS];
	struct kinds counts[3][NBINS] = { { { { 0 } } } }, leaf = { { 0 } };
	for (int axis = 0; axis < 3; axis++)
		for (int i = 0; i < nbins; i++)
			bins[axis][i] = vbox_empty();
	for (size_t i = 0; i < n; i++) {
		v4f lo = v4load(refs[i].lo), hi = v4load(refs[i].hi);
		int k[4];
		bins_of(&bn, refs[i].centroid, k);
		enum shape_kind kind = shape_kind(refs[i].prim);
		leaf.n[kind]++;
		for (int axis = 0; axis < 3; axis++) {
			counts[axis][k[axis]].n[kind]++;
			vbox_add(&bins[axis][k[axis]], lo, hi);
		}
	}
	double best_cost = leaf_price(sah, leaf);
	for (int axis = 0; axis < 3; axis++) {
		if (scale[axis] == 0)
			continue;
		/* sweep from the right, then from the left */
		double right_area[NBINS], right_price[NBINS];
		uint32_t right_n[NBINS];
		struct vbox acc = vbox_empty();
		struct kinds cnt = { { 0 } };
		for (int i = nbins - 1; i > 0; i--) {
			vbox_add(&acc, bins[axis][i].lo, bins[axis][i].hi);
			kinds_add(&cnt, counts[axis][i]);
			right_area[i] = vbox_area(acc);
			right_price[i] = leaf_price(sah, cnt);
			right_n[i] = kinds_total(cnt);
		}
		acc = vbox_empty();
		cnt = (struct kinds){ { 0 } };
		for (int i = 1; i < nbins; i++) {
			vbox_add(&acc, bins[axis][i - 1].lo, bins[axis][i - 1].hi);
			kinds_add(&cnt, counts[axis][i - 1]);
			if (kinds_total(cnt) == 0 || right_n[i] == 0)
				continue;
			double cost = sah->node + (vbox_area(acc) * leaf_price(sah, cnt) + right_area[i] * right_price[i]) / parent_area;
			if (cost < best_cost) {
				best_cost = cost;
				best = (struct split){ axis, i, bn };
			}
		}
	}
	return best;
}

static inline bool goes_left(const struct split *s, const struct build_ref *r)
{
	int k[4];
	bins_of(&s->bn, r->centroid, k);
	return k[s->axis] < s->bin;
}

/* Puts the references whose centroid falls in a bin before s->bin first (Hoare's
 * partition: only references on the wrong side move); returns how many there are, and
 * the bounds of each side in side[0] and side[1]. */
static size_t partition(struct build_ref *refs, size_t n, const struct split *s, struct bounds side[2])
{
	side[0] = side[1] = (struct bounds){ vbox_empty(), vbox_empty() };
	size_t i = 0, j = n;
	for (;;) {
		while (i < j && goes_left(s, &refs[i]))
			bounds_add(&side[0], &refs[i++]);
		while (i < j && !goes_left(s, &refs[j - 1]))
			bounds_add(&side[1], &refs[--j]);
		if (i == j)
			return i;
		struct build_ref tmp = refs[i];
		refs[i] = refs[j - 1];
		refs[j - 1] = tmp;
		bounds_add(&side[0], &refs[i++]);
		bounds_add(&side[1], &refs[--j]);
	}
}

/* Builds the subtree of refs[first, first + n) into b->bin and returns it as its parent
 * sees it; at the top (b->task_size set) a small enough subtree is left to a worker,
 * which fills in its parent's slot. */
static struct child build(struct builder *b, uint32_t parent, uint32_t c, uint32_t first, uint32_t n, int level,
                          struct bounds bd)
{
	struct child ch = { .count = 0 };
	if (b->task_size && n <= b->task_size) {
		xgrow((void **)&b->tasks, &b->cap_tasks, b->ntasks + 1, sizeof *b->tasks);
		b->tasks[b->ntasks++] = (struct task){ .parent = parent, .c = c, .first = first, .n = n, .depth = level,
		                                       .bounds = bd };
		return ch;
	}
	struct build_ref *refs = b->refs + first;
	float lo[4], hi[4];
	v4store(lo, bd.box.lo);
	v4store(hi, bd.box.hi);
	memcpy(ch.box, lo, 3 * sizeof *lo);
	memcpy(ch.box + 3, hi, 3 * sizeof *hi);

	struct split s = { .axis = -1 };
	if (!b->brute && n > 1 && level < MAX_DEPTH)
		s = find_split(refs, n, bd.cbox, vbox_area(bd.box), &b->sah);
	if (s.axis < 0 && !b->brute && n > MAX_LEAF && level < MAX_DEPTH) {
		/* a leaf would be cheaper by SAH but is too big: split the widest axis in two
		 * halves, which is binning with two bins */
		s = (struct split){ -1, 1, binning_of(bd.cbox, 2) };
		float scale[4];
		v4store(scale, s.bn.scale);
		for (int a = 0; a < 3; a++) /* the widest has the smallest nonzero scale */
			if (scale[a] > 0 && (s.axis < 0 || scale[a] < scale[s.axis]))
				s.axis = a;
	}
	size_t mid = 0;
	struct bounds side[2];
	if (s.axis >= 0)
		mid = partition(refs, n, &s, side);
	if (mid == 0 || mid == n) {
		/* a leaf: its primitives go to prims[first, first + n) */
		ch.index = first;
		ch.count = n;
		for (size_t i = 0; i < n; i++)
			b->prims[first + i] = refs[i].prim;
		return ch;
	}
	uint32_t node = first + (uint32_t)mid - 1;
	ch.index = node;
	b->bin[node].kid[0] = build(b, node, 0, first, (uint32_t)mid, level + 1, side[0]);
	b->bin[node].kid[1] = build(b, node, 1, first + (uint32_t)mid, n - (uint32_t)mid, level + 1, side[1]);
	return ch;
}

/* Builds task i and puts it in the slot its parent left for it. */
static void run_task(void *ctx, size_t i)
{
	struct builder *b = ctx;
	const struct task *t = &b->tasks[i];
	struct child ch = build(b, t->parent, t->c, t->first, t->n, t->depth, t->bounds);
	if (t->parent == NO_PARENT)
		b->root = ch;
	else
		b->bin[t->parent].kid[t->c] = ch;
}

/* The build record of primitive k of geo (shape_nth's numbering). */
static void make_ref(const struct geometry *geo, size_t k, struct build_ref *r)
{
	struct vec3 lo, hi;
	r->prim = shape_nth(geo, k);
	shape_bounds(geo, r->prim, &lo, &hi);
	bool sphere = shape_kind(r->prim) == SHAPE_SPHERE;
	for (int a = 0; a < 3; a++) {
		r->lo[a] = float_below(vget(&lo, a));
		r->hi[a] = float_above(vget(&hi, a));
		/* the centre of the exact bounds: a sphere's own, which its rounded bounds
		 * would only approach */
		r->centroid[a] = (float)(sphere ? vget(&geo->spheres[k].center, a) : 0.5 * (vget(&lo, a) + vget(&hi, a)));
	}
}

/* The records of the primitives, made chunk by chunk, each chunk's bounds beside. */
struct ref_chunks {
	const struct geometry *geo;
	struct build_ref *refs;
	size_t n, nchunks;
	struct bounds *bounds;
};

static void make_chunk(void *ctx, size_t c)
{
	struct ref_chunks *rc = ctx;
	struct bounds bd = { vbox_empty(), vbox_empty() };
	size_t lo, hi;
	parallel_chunk_items(rc->n, rc->nchunks, c, &lo, &hi);
	for (size_t k = lo; k < hi; k++) {
		make_ref(rc->geo, k, &rc->refs[k]);
		bounds_add(&bd, &rc->refs[k]);
	}
	rc->bounds[c] = bd;
}

struct bvh *bvh_build(const struct geometry *geo, bool one_leaf)
{
	struct bvh *bvh = xcalloc(1, sizeof *bvh);
	size_t n = shape_count(geo);
	bvh->nprims = n;
	bvh->big = n >= BVH_BIG_TREE;
	if (n == 0)
		return bvh;
	struct builder b = { .brute = one_leaf };
	/* a solid's test maps the ray into its own space first: two or three spheres' worth */
	b.sah = bvh->big ? (struct sah){ 2, 2, 2, 4 } : (struct sah){ 1, 1, 2, 2 };
	b.refs = xmalloc(n * sizeof *b.refs);
	bvh->prims = b.prims = xmalloc(n * sizeof *b.prims);
	/* the records in chunks, on all threads where the build will use them */
	struct bounds chunk_bounds[MAX_CHUNKS];
	struct ref_chunks rc = { geo, b.refs, n, parallel_chunks(n), chunk_bounds };
	parallel_for(rc.nchunks, make_chunk, &rc);
	struct bounds root = { vbox_empty(), vbox_empty() };
	for (size_t c = 0; c < rc.nchunks; c++) {
		vbox_add(&root.box, chunk_bounds[c].box.lo, chunk_bounds[c].box.hi);
		vbox_add(&root.cbox, chunk_bounds[c].cbox.lo, chunk_bounds[c].cbox.hi);
	}
	b.bin = xmalloc((n > 1 ? n - 1 : 1) * sizeof *b.bin);
	size_t task = n / TASKS_PER_TREE;
	b.task_size = task > MIN_TASK ? task : MIN_TASK;
	b.root = build(&b, NO_PARENT, 0, 0, (uint32_t)n, 0, root);
	b.task_size = 0;
	parallel_for(b.ntasks, run_task, &b);
	free(b.tasks);
	free(b.refs);
	bvh->root = b.root;
	bvh_make_wide(bvh, b.bin, b.ntasks > 1);
	return bvh;
}

uint64_t bvh_bytes(uint64_t n, uint64_t ntriangles)
{
	/* the n - 1 slots of the binary nodes, beside the build records; then beside the
	 * wide nodes. Of those, a node with fewer than WIDTH children has only leaves below
	 * it, two at least, so I nodes over L <= n leaves hold (I - 1) + L >= WIDTH (I - F) +
	 * 2F children with F <= L / 2 such nodes: I <= L WIDTH / (2 (WIDTH - 1)). */
	uint64_t build = n * (sizeof(struct build_ref) + sizeof(struct bin_node));
	uint64_t wide_nodes = (n * WIDTH + 2 * (WIDTH - 1) - 1) / (2 * (WIDTH - 1));
	uint64_t wide = n * sizeof(struct bin_node) + wide_nodes * sizeof(struct bvh_node);
	/* then the nodes and the packets, at most one for two triangles (MIN_PACKED), in
	 * whole huge pages (xbig_alloc) */
	uint64_t packets = ntriangles / 2 * sizeof(struct tri_packet);
	packets += packets ? XBIG_PAGE : 0;
	uint64_t packed = wide_nodes * sizeof(struct bvh_node) + packets;
	uint64_t most = build > wide ? build : wide;
	return n * sizeof(uint32_t) + (most > packed ? most : packed);
}

void bvh_free(struct bvh *b)
{
	if (!b)
		return;
	free(b->nodes);
	free(b->prims);
	free(b->packets);
	free(b);
}

struct bvh_shape bvh_shape(const struct bvh *b)
{
	return (struct bvh_shape){ b->nprims ? b->nboxes : 0, b->nnodes, b->npackets, b->depth };
}
