/* bvh.c: a binned SAH bounding volume hierarchy (Wald, "On fast Construction of
 * SAH-based Bounding Volume Hierarchies", 2007), built binary and collapsed into
 * eight-wide nodes whose children's boxes one AVX slab test (or two SSE ones) handles at
 * once, nearest child first. Bounds are kept in float, rounded outward, so a box never
 * loses what it holds, and the slab test in float is made conservative by rounding the
 * ray's origin and 1/d outward and widening the exit distance (NUMERICS.md section 1;
 * pbrt 3rd ed. section 3.9.2); it is robust to zero direction components and origins on
 * a slab (Ize, "Robust BVH Ray Traversal", JCGT 2013). After bvh_reorder a leaf of
 * triangles keeps them in packets of four, tested four at once (tri_packet.h).
 *
 * The build splits the top of the tree on one thread and hands the subtrees below a size
 * fixed by the primitive count to worker threads, each node going to a slot fixed by
 * where its split falls; the collapse into wide nodes hands out subtrees the same way.
 * The tree and its layout depend on the scene alone, never on the thread count or on
 * which thread finished first. */
#include "bvh.h"

#include <float.h>
#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "tri_packet.h"
#include "v4d.h"
#include "xalloc.h"

enum {
	NBINS = 16,        /* SAH bins per axis: Wald found 16 as good as a full sweep */
	MAX_LEAF = 8,      /* never more in a leaf unless the primitives cannot be split */
	MAX_DEPTH = 96,    /* below this every node is a leaf; traversal stacks are sized by it */
	MIN_TASK = 4096,   /* primitives in a subtree worth a thread of its own */
	TASKS_PER_TREE = 64, /* subtrees the top split aims for, so that threads share the work evenly */
	CHUNKS = 64,       /* pieces a pass over the primitives or the nodes is cut into, for the same reason */
	MIN_PACKED = 2,    /* triangles in a leaf from which they go to packets: at most n / 2 packets */
};

/* Four floats, with SSE where there is SSE (every x86-64) and GCC's generic vectors
 * elsewhere: a box corner for the build, and one coordinate of four children of a node
 * for the node test without AVX. */
#ifdef __AVX__
#include <immintrin.h>
#endif
#ifdef __SSE2__
#include <emmintrin.h>
typedef __m128 v4f;
static inline v4f v4set(float x) { return _mm_set1_ps(x); }
static inline v4f v4load(const float p[4]) { return _mm_loadu_ps(p); }
static inline void v4store(float p[4], v4f a) { _mm_storeu_ps(p, a); }
static inline v4f v4sub(v4f a, v4f b) { return _mm_sub_ps(a, b); }
static inline v4f v4mul(v4f a, v4f b) { return _mm_mul_ps(a, b); }
static inline v4f v4add(v4f a, v4f b) { return _mm_add_ps(a, b); }
/* a > b ? a : b and a < b ? a : b, lane by lane: a NaN in a gives b */
static inline v4f v4max(v4f a, v4f b) { return _mm_max_ps(a, b); }
static inline v4f v4min(v4f a, v4f b) { return _mm_min_ps(a, b); }
/* bit c set when a[c] <= b[c] */
static inline int v4le(v4f a, v4f b) { return _mm_movemask_ps(_mm_cmple_ps(a, b)); }
/* toward zero, lane by lane */
static inline void v4trunc(v4f a, int out[4]) { _mm_storeu_si128((__m128i *)out, _mm_cvttps_epi32(a)); }
/* m ? a : b, lane by lane, for m all ones or all zeros in each lane */
static inline v4f v4pick(v4f m, v4f a, v4f b) { return _mm_or_ps(_mm_and_ps(m, a), _mm_andnot_ps(m, b)); }
/* all ones in the lanes whose sign bit is set (-0 too), else zeros */
static inline v4f v4signs(v4f a) { return _mm_castsi128_ps(_mm_srai_epi32(_mm_castps_si128(a), 31)); }
/* bit c set when a[c]'s sign bit is */
static inline int v4signbits(v4f a) { return _mm_movemask_ps(a); }
#else
typedef float v4f __attribute__((vector_size(16)));
typedef int v4i __attribute__((vector_size(16)));
static inline v4f v4set(float x) { return (v4f){ x, x, x, x }; }
static inline v4f v4load(const float p[4]) { v4f a; memcpy(&a, p, sizeof a); return a; }
static inline void v4store(float p[4], v4f a) { memcpy(p, &a, sizeof a); }
static inline v4f v4sub(v4f a, v4f b) { return a - b; }
static inline v4f v4mul(v4f a, v4f b) { return a * b; }
static inline v4f v4add(v4f a, v4f b) { return a + b; }
static inline v4f v4max(v4f a, v4f b) { v4i m = a > b; return (v4f)(((v4i)a & m) | ((v4i)b & ~m)); }
static inline v4f v4min(v4f a, v4f b) { v4i m = a < b; return (v4f)(((v4i)a & m) | ((v4i)b & ~m)); }
/* bit c set when lane c of m is set */
static inline int v4bits(v4i m)
{
	return (m[0] & 1) | (m[1] & 2) | (m[2] & 4) | (m[3] & 8);
}
static inline int v4le(v4f a, v4f b) { return v4bits(a <= b); }
static inline void v4trunc(v4f a, int out[4])
{
	for (int i = 0; i < 4; i++)
		out[i] = (int)a[i];
}
static inline v4f v4pick(v4f m, v4f a, v4f b) { return (v4f)(((v4i)m & (v4i)a) | (~(v4i)m & (v4i)b)); }
static inline v4f v4signs(v4f a) { return (v4f)((v4i)a >> 31); }
static inline int v4signbits(v4f a) { return v4bits((v4i)a >> 31); }
#endif

/* The traversal's node: the boxes of up to WIDTH children, coordinate by coordinate so
 * that one vector operation handles them all ([lo x, y, z, hi x, y, z][child]), and what
 * each child is. An unused slot has an empty box (lo +inf, hi -inf), which no ray meets.
 * Eight children measured faster than four on every benchmark scene, with AVX or
 * without (each step of a walk waits on the one before, and a wider node takes fewer
 * steps). 256 bytes, four cache lines. */
enum { WIDTH = BVH_WIDTH };
struct bvh_node {
	float box[6][WIDTH];
	uint32_t index[WIDTH]; /* child c: a node, or a leaf's first primitive (see LEAF_DIRECT) */
	uint32_t count[WIDTH]; /* child c: primitives in the leaf, and LEAF_DIRECT; 0: a node */
};

/* A leaf's count has LEAF_DIRECT set when its index is the prim_id() of its first
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
	uint32_t *prims;   /* prim_id()s in leaf order; NULL once no leaf needs them */
	size_t nprims;
	struct tri_packet *packets; /* of the LEAF_PACKED leaves, in leaf order */
	size_t npackets;
	int depth;
	bool big;                  /* BVH_BIG_TREE primitives or more: see prefetch_nodes() */
};

/* A primitive's bounds, already rounded outward to float, and the centre of its exact
 * bounds, which steers the splits (primitives with the same centre stay together). The
 * fourth lane of each is padding, for the vector code. */
struct build_ref {
	float lo[4], hi[4], centroid[4];
	uint32_t prim, pad[3];
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
	unsigned node, sphere, packet;
};

/* How many spheres and triangles a set holds: what its price as a leaf depends on. */
struct kinds {
	uint32_t n[2]; /* n[PRIM_SPHERE], n[PRIM_TRIANGLE] */
};

static inline void kinds_add(struct kinds *a, struct kinds b)
{
	a->n[0] += b.n[0];
	a->n[1] += b.n[1];
}

static inline uint32_t kinds_total(struct kinds k)
{
	return k.n[0] + k.n[1];
}

static inline double leaf_price(const struct sah *sah, struct kinds k)
{
	return (double)k.n[PRIM_SPHERE] * sah->sphere + (double)leaf_packets(k.n[PRIM_TRIANGLE]) * sah->packet;
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

/* Half the surface area, in float: SAH only compares areas. */
static inline float vbox_area(struct vbox b)
{
	float e[4];
	v4store(e, v4sub(b.hi, b.lo));
	if (e[0] < 0)
		return 0;
	return e[0] * e[1] + e[1] * e[2] + e[2] * e[0];
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
		enum prim_kind kind = prim_kind(refs[i].prim);
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

/* Runs fn(ctx, i) for each i in [0, n) on up to as many threads as there are processors
 * (the calling one among them), each thread taking the next i: what fn does depends on i
 * alone, never on the thread that runs it. */
struct parallel {
	void (*fn)(void *ctx, size_t i);
	void *ctx;
	size_t n;
	atomic_size_t next;
};

static void *parallel_worker(void *arg)
{
	struct parallel *p = arg;
	for (size_t i; (i = atomic_fetch_add(&p->next, 1)) < p->n;)
		p->fn(p->ctx, i);
	return NULL;
}

static void parallel_for(size_t n, void (*fn)(void *ctx, size_t i), void *ctx)
{
	struct parallel p = { .fn = fn, .ctx = ctx, .n = n };
	atomic_init(&p.next, 0);
	long cores = sysconf(_SC_NPROCESSORS_ONLN);
	size_t threads = cores > 1 ? (size_t)cores : 1;
	if (threads > n)
		threads = n;
	pthread_t *tid = xcalloc(threads > 1 ? threads - 1 : 1, sizeof *tid);
	size_t started = 0;
	while (started + 1 < threads && pthread_create(&tid[started], NULL, parallel_worker, &p) == 0)
		started++;
	parallel_worker(&p); /* if no thread could start, this one does it all */
	for (size_t i = 0; i < started; i++)
		pthread_join(tid[i], NULL);
	free(tid);
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

/* The area of a child's box (vbox_area's), for choosing which child to open; a NaN from
 * an infinite box (a scene beyond float range) counts as the largest. */
static float child_area(const struct child *ch)
{
	float lo[4] = { ch->box[0], ch->box[1], ch->box[2], 0 }, hi[4] = { ch->box[3], ch->box[4], ch->box[5], 0 };
	float a = vbox_area((struct vbox){ v4load(lo), v4load(hi) });
	return a == a ? a : INFINITY;
}

/* The area of an interior child, for choosing which to open, and its binary node
 * fetched ahead (the collapse waits on these loads more than on anything else); -1 for
 * a leaf, which is never opened. */
static float open_area(const struct bin_node *bin, const struct child *ch)
{
	if (ch->count)
		return -1;
	__builtin_prefetch(&bin[ch->index]);
	return child_area(ch);
}

/* The children of the wide node that stands for binary node `node`: its two children,
 * then, while there are fewer than WIDTH, the interior one with the largest box
 * replaced by its own two (the area rule of Wald, Benthin and Boulos, "Getting Rid of
 * Packets", 2008: the children most rays enter are the ones worth testing together).
 * Returns how many there are. */
static int gather(const struct bin_node *bin, uint32_t node, struct child out[WIDTH])
{
	float area[WIDTH];
	int n = 0;
	for (int c = 0; c < 2; c++, n++) {
		out[n] = bin[node].kid[c];
		area[n] = open_area(bin, &out[n]);
	}
	while (n < WIDTH) {
		int open = -1;
		for (int i = 0; i < n; i++)
			if (area[i] >= 0 && (open < 0 || area[i] > area[open]))
				open = i;
		if (open < 0)
			break;
		const struct bin_node *b = &bin[out[open].index];
		int at[2] = { open, n++ };
		for (int c = 0; c < 2; c++) {
			out[at[c]] = b->kid[c];
			area[at[c]] = open_area(bin, &out[at[c]]);
		}
	}
	return n;
}

/* A subtree of the wide tree that a thread collapses on its own: below the binary child
 * ch, at the jobs' wide level; its nodes go to [offset, offset + size). */
struct wide_job {
	struct child ch;
	uint32_t offset, size;
	size_t boxes;
	int depth;
};

struct collapse {
	const struct bin_node *bin;
	struct bvh_node *out;      /* NULL: only count the nodes */
	uint32_t next;             /* nodes made so far (in out, where it starts) */
	size_t boxes;
	int depth;
	/* the top of the tree, when the rest goes to jobs: an interior child at job_level is
	 * a job, found by the counting pass and placed by the writing pass, in preorder */
	int job_level;             /* 0: no jobs */
	struct wide_job *jobs;
	size_t njobs, cap_jobs, placed;
};

/* Turns the binary subtree below interior child ch into wide nodes, in preorder;
 * returns ch as its parent sees it now. Counting and writing take the same path, so the
 * counting pass sizes the array exactly. */
static struct child collapse(struct collapse *cl, struct child ch, int level)
{
	if (ch.count)
		return ch;
	if (cl->job_level && level == cl->job_level) {
		if (!cl->out) {
			xgrow((void **)&cl->jobs, &cl->cap_jobs, cl->njobs + 1, sizeof *cl->jobs);
			cl->jobs[cl->njobs++] = (struct wide_job){ .ch = ch };
			return ch;
		}
		/* its subtree, counted by then, takes the next size nodes, its root first */
		struct wide_job *j = &cl->jobs[cl->placed++];
		j->offset = cl->next;
		cl->next += j->size;
		ch.index = j->offset;
		return ch;
	}
	if (level > cl->depth)
		cl->depth = level;
	struct child kid[WIDTH];
	int n = gather(cl->bin, ch.index, kid);
	uint32_t self = cl->next++;
	cl->boxes += (size_t)n;
	for (int c = 0; c < n; c++)
		kid[c] = collapse(cl, kid[c], level + 1);
	if (cl->out) {
		struct bvh_node *nd = &cl->out[self];
		for (int c = 0; c < WIDTH; c++) {
			for (int k = 0; k < 6; k++)
				nd->box[k][c] = c < n ? kid[c].box[k] : k < 3 ? INFINITY : -INFINITY;
			nd->index[c] = c < n ? kid[c].index : 0;
			nd->count[c] = c < n ? kid[c].count : 0;
		}
	}
	ch.index = self;
	return ch;
}

struct wide_jobs {
	const struct bin_node *bin;
	struct bvh_node *out;
	struct wide_job *jobs;
	int level;               /* theirs, the collapse's job_level */
};

static void count_job(void *ctx, size_t i)
{
	struct wide_jobs *w = ctx;
	struct wide_job *j = &w->jobs[i];
	struct collapse cl = { .bin = w->bin };
	collapse(&cl, j->ch, w->level);
	j->size = cl.next;
	j->boxes = cl.boxes;
	j->depth = cl.depth;
}

static void write_job(void *ctx, size_t i)
{
	struct wide_jobs *w = ctx;
	const struct wide_job *j = &w->jobs[i];
	struct collapse cl = { .bin = w->bin, .out = w->out, .next = j->offset };
	collapse(&cl, j->ch, w->level);
}

/* The wide tree of the binary one, which it frees: a pass to count, the array aligned
 * to cache lines, a pass to fill it. With parallel, the top two levels are collapsed on
 * this thread and the subtrees below them on all threads, in both passes (each waits on
 * its loads of binary nodes more than on anything else); the layout is the same. */
static void make_wide(struct bvh *bvh, struct bin_node *bin, bool parallel)
{
	struct collapse cl = { .bin = bin, .job_level = parallel ? 2 : 0 };
	collapse(&cl, bvh->root, 0);
	struct wide_jobs w = { bin, NULL, cl.jobs, cl.job_level };
	parallel_for(cl.njobs, count_job, &w);
	size_t total = cl.next, boxes = cl.boxes;
	int depth = cl.depth;
	for (size_t i = 0; i < cl.njobs; i++) {
		total += cl.jobs[i].size;
		boxes += cl.jobs[i].boxes;
		depth = cl.jobs[i].depth > depth ? cl.jobs[i].depth : depth;
	}
	bvh->nnodes = total;
	bvh->nboxes = boxes + 1;
	bvh->depth = depth;
	if (total) {
		w.out = bvh->nodes = xaligned_alloc(64, total * sizeof *bvh->nodes);
		cl.out = bvh->nodes;
		cl.next = 0;
		bvh->root = collapse(&cl, bvh->root, 0);
		parallel_for(cl.njobs, write_job, &w);
	}
	free(cl.jobs);
	free(bin);
}

/* The pieces a pass over n items is cut into for parallel_for (one when n is small),
 * and the items [lo, hi) of piece c. */
static size_t chunks_of(size_t n)
{
	return n > MIN_TASK ? CHUNKS : 1;
}

static void chunk_items(size_t n, size_t nchunks, size_t c, size_t *lo, size_t *hi)
{
	*lo = n * c / nchunks;
	*hi = n * (c + 1) / nchunks;
}

/* The build record of primitive k of sc (nth_prim's numbering). */
static void make_ref(const struct scene *sc, size_t k, struct build_ref *r)
{
	struct vec3 lo, hi;
	r->prim = nth_prim(sc, k);
	prim_bounds(sc, r->prim, &lo, &hi);
	bool sphere = prim_kind(r->prim) == PRIM_SPHERE;
	for (int a = 0; a < 3; a++) {
		r->lo[a] = float_below(vget(&lo, a));
		r->hi[a] = float_above(vget(&hi, a));
		/* the centre of the exact bounds: a sphere's own, which its rounded bounds
		 * would only approach */
		r->centroid[a] = (float)(sphere ? vget(&sc->spheres[k].center, a) : 0.5 * (vget(&lo, a) + vget(&hi, a)));
	}
}

/* The records of the primitives, made chunk by chunk, each chunk's bounds beside. */
struct ref_chunks {
	const struct scene *sc;
	struct build_ref *refs;
	size_t n, nchunks;
	struct bounds *bounds;
};

static void make_chunk(void *ctx, size_t c)
{
	struct ref_chunks *rc = ctx;
	struct bounds bd = { vbox_empty(), vbox_empty() };
	size_t lo, hi;
	chunk_items(rc->n, rc->nchunks, c, &lo, &hi);
	for (size_t k = lo; k < hi; k++) {
		make_ref(rc->sc, k, &rc->refs[k]);
		bounds_add(&bd, &rc->refs[k]);
	}
	rc->bounds[c] = bd;
}

struct bvh *bvh_build(const struct scene *sc, enum accel kind)
{
	struct bvh *bvh = xcalloc(1, sizeof *bvh);
	size_t n = sc->nspheres + sc->ntriangles;
	bvh->nprims = n;
	bvh->big = n >= BVH_BIG_TREE;
	if (n == 0)
		return bvh;
	struct builder b = { .brute = kind == ACCEL_NONE };
	b.sah = bvh->big ? (struct sah){ 2, 2, 2 } : (struct sah){ 1, 1, 2 };
	b.refs = xmalloc(n * sizeof *b.refs);
	bvh->prims = b.prims = xmalloc(n * sizeof *b.prims);
	/* the records in chunks, on all threads where the build will use them */
	struct bounds chunk_bounds[CHUNKS];
	struct ref_chunks rc = { sc, b.refs, n, chunks_of(n), chunk_bounds };
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
	make_wide(bvh, b.bin, b.ntasks > 1);
	return bvh;
}

/* Makes a leaf (index, count) of prim_id()s of one kind, numbered in leaf order,
 * LEAF_DIRECT; true when the leaf still needs its ids (both kinds in it). Nodes are left
 * alone. */
static bool direct_leaf(const struct bvh *b, uint32_t *index, uint32_t *count)
{
	if (*count == 0)
		return false;
	const uint32_t *ids = b->prims + *index;
	for (uint32_t i = 1; i < *count; i++)
		if (prim_kind(ids[i]) != prim_kind(ids[0]))
			return true;
	*count |= LEAF_DIRECT;
	*index = ids[0];
	return false;
}

/* Whether a leaf's triangles go to packets: a LEAF_DIRECT leaf of MIN_PACKED or more. */
static bool packs(uint32_t index, uint32_t count)
{
	return (count & LEAF_DIRECT) && prim_kind(index) == PRIM_TRIANGLE && leaf_size(count) >= MIN_PACKED;
}

/* Packs the leaf (index, count) from b->packets[*next] on, if it packs. */
static void pack_leaf(struct bvh *b, const struct scene *sc, uint32_t *index, uint32_t *count, size_t *next)
{
	if (!packs(*index, *count))
		return;
	uint32_t first = prim_index(*index), n = leaf_size(*count);
	for (uint32_t i = 0; i < n; i += PACKET_LANES)
		tri_packet_fill(&b->packets[*next + i / PACKET_LANES], sc, first + i,
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
	const struct scene *sc;
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
	chunk_items(b->nnodes, pk->nchunks, c, &lo, &hi);
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
		pack_leaf(b, pk->sc, &b->root.index, &b->root.count, &next);
	chunk_items(b->nnodes, pk->nchunks, c, &lo, &hi);
	for (size_t i = lo; i < hi; i++)
		for (int k = 0; k < WIDTH; k++)
			pack_leaf(b, pk->sc, &b->nodes[i].index[k], &b->nodes[i].count[k], &next);
}

/* The leaves in their final form once the primitives are in leaf order: direct where
 * they can be, in packets where they pack; prims freed if no leaf needs it. */
static void finalize_leaves(struct bvh *b, const struct scene *sc)
{
	size_t first[CHUNKS];
	bool ids_needed[CHUNKS], any_ids = false;
	struct packing pk = { b, sc, chunks_of(b->nnodes), first, ids_needed };
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
 * each chunk's spheres and triangles counted, then copied from where the chunks before
 * it end, each entry of prims renumbered to its primitive's new place. */
struct reordering {
	struct bvh *b;
	const struct scene *sc;       /* the primitives where they were */
	struct sphere *spheres;
	struct triangle *triangles;
	size_t nchunks;
	struct kinds *first;          /* chunk c's first sphere and triangle (its counts, until the sum) */
};

static void count_kinds(void *ctx, size_t c)
{
	struct reordering *ro = ctx;
	struct kinds k = { { 0, 0 } };
	size_t lo, hi;
	chunk_items(ro->b->nprims, ro->nchunks, c, &lo, &hi);
	for (size_t i = lo; i < hi; i++)
		k.n[prim_kind(ro->b->prims[i])]++;
	ro->first[c] = k;
}

static void copy_chunk(void *ctx, size_t c)
{
	struct reordering *ro = ctx;
	uint32_t *prims = ro->b->prims;
	struct kinds next = ro->first[c];
	size_t lo, hi;
	chunk_items(ro->b->nprims, ro->nchunks, c, &lo, &hi);
	for (size_t i = lo; i < hi; i++) {
		enum prim_kind kind = prim_kind(prims[i]);
		uint32_t k = prim_index(prims[i]), to = next.n[kind]++;
		if (kind == PRIM_SPHERE)
			ro->spheres[to] = ro->sc->spheres[k];
		else
			ro->triangles[to] = ro->sc->triangles[k];
		prims[i] = prim_id(kind, to);
	}
}

void bvh_reorder(struct bvh *b, struct scene *sc)
{
	struct kinds first[CHUNKS];
	struct reordering ro = { b, sc, sc->nspheres ? xmalloc(sc->nspheres * sizeof *ro.spheres) : NULL,
		                 sc->ntriangles ? xmalloc(sc->ntriangles * sizeof *ro.triangles) : NULL,
		                 chunks_of(b->nprims), first };
	parallel_for(ro.nchunks, count_kinds, &ro);
	struct kinds sum = { { 0, 0 } };
	for (size_t c = 0; c < ro.nchunks; c++) {
		struct kinds count = first[c];
		first[c] = sum;
		kinds_add(&sum, count);
	}
	parallel_for(ro.nchunks, copy_chunk, &ro);
	free(sc->spheres);
	free(sc->triangles);
	sc->spheres = ro.spheres;
	sc->triangles = ro.triangles;
	finalize_leaves(b, sc);
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

/* What the slab test needs of a ray, worked out once per axis: the box coordinate it
 * enters by (lo, or hi when the direction is negative) and the one it leaves by, and the
 * origin and 1/d in float, rounded each way. The test runs in float on float boxes, so
 * it must stay conservative (NUMERICS.md section 1): the distance to the entry plane is
 * taken from the origin rounded towards that plane and with |1/d| rounded down, the
 * distance to the exit plane with the origin rounded away and |1/d| rounded up and
 * widened, so the two bound the exact distances (before the float arithmetic's own
 * rounding, which the widening covers, see FAR_WIDEN). A zero component keeps a finite
 * |1/d| on the entry side (0 * inf would be NaN there); on the exit side 1/d is infinite,
 * and an origin on a slab plane gives 0 * inf = NaN, which node_hit() discards. */
#ifdef __AVX__
typedef __m256 vray;       /* one value of the ray in every lane of a node test */
static inline vray vray_set(float x) { return _mm256_set1_ps(x); }
/* out[k]: lane k of a in every lane */
static inline void vray_lanes(v4f a, vray out[3])
{
	__m256 aa = _mm256_insertf128_ps(_mm256_castps128_ps256(a), a, 1);
	out[0] = _mm256_permute_ps(aa, 0x00);
	out[1] = _mm256_permute_ps(aa, 0x55);
	out[2] = _mm256_permute_ps(aa, 0xaa);
}
#else
typedef v4f vray;
static inline vray vray_set(float x) { return v4set(x); }
static inline void vray_lanes(v4f a, vray out[3])
{
	float f[4];
	v4store(f, a);
	for (int k = 0; k < 3; k++)
		out[k] = v4set(f[k]);
}
#endif

/* The rows of bvh_node.box a ray enters and leaves a box by on each axis, as byte
 * offsets (the node test then scales no index), for each sign pattern of d: bit k of
 * the pattern set when d's component k is negative (lo x, y, z are rows 0-2, hi 3-5). */
struct box_rows {
	size_t enter[3], leave[3];
};
#define BOX_ROW(k, neg) ((size_t)((k) + 3 * (neg)) * sizeof(float[WIDTH]))
#define BOX_ROWS(b)                                                                         \
	{ { BOX_ROW(0, (b) & 1), BOX_ROW(1, (b) >> 1 & 1), BOX_ROW(2, (b) >> 2 & 1) },         \
	  { BOX_ROW(0, !((b) & 1)), BOX_ROW(1, !((b) >> 1 & 1)), BOX_ROW(2, !((b) >> 2 & 1)) } }
static const struct box_rows box_rows[8] = { BOX_ROWS(0), BOX_ROWS(1), BOX_ROWS(2), BOX_ROWS(3),
	                                     BOX_ROWS(4), BOX_ROWS(5), BOX_ROWS(6), BOX_ROWS(7) };

struct box_ray {
	vray o_near[3], o_far[3], inv_near[3], inv_far[3];
	struct box_rows rows;
};

/* The entry distance of a box comes out at most (1 + u)^2 too large, the exit distance
 * (1 - u)^2 too small (a subtraction and a product, u = 2^-24): widening the exit side's
 * |1/d| by 1 + 8u covers both (pbrt's 1 + 2 gamma(3) on tfar). FAR_SLACK covers products
 * that underflow, whose error is absolute (2^-150 each). */
#define FAR_WIDEN (1 + 8 * 0x1p-24)
#define FAR_SLACK (4 * FLT_TRUE_MIN)
/* Rounding to float to nearest moves a value by at most 2^-24 of itself (or 2^-150, if
 * it underflows): moving it first by 2^-22 of itself (and FLT_TRUE_MIN) in double makes
 * the float fall on the side wanted. Cheaper than exact directed rounding, and without
 * branches, which matters with nine such values per ray; a few ulps wider is harmless. */
#define ROUND_MARGIN 0x1p-22

/* The three axes at once (lane 3 is padding: d 1, o 0), the doubles in GCC's generic
 * vectors (AVX or SSE2 where there is one): the per-ray set-up ran to a hundred and
 * thirty scalar instructions, as much as a node test or two. The clamps to the float
 * range come after the rounding to float, which gives the same values: a double above
 * FLT_MAX rounds to FLT_MAX or to inf, and one below never rounds past it. */
static void box_ray_init(const struct ray *r, struct box_ray *s)
{
	v4d d = { r->d.x, r->d.y, r->d.z, 1 }, o = { r->o.x, r->o.y, r->o.z, 0 };
	v4d inv = 1 / d;
	v4d m = V4D_ABS(o) * ROUND_MARGIN + FLT_TRUE_MIN;
	v4f o_down = v4min(__builtin_convertvector(o - m, v4f), v4set(FLT_MAX));
	v4f o_up = v4max(__builtin_convertvector(o + m, v4f), v4set(-FLT_MAX));
	/* near and far by the sign bit of d (-0 counts as negative), not by comparing the
	 * two distances: with a -0 component and the origin on a face one of them is NaN */
	v4f d_f = __builtin_convertvector(d, v4f), neg = v4signs(d_f);
	v4f inv_f = __builtin_convertvector(inv, v4f);
	/* a zero component keeps a finite |1/d| on the entry side, with the sign of 1/d */
	v4f inv_in = v4min(__builtin_convertvector(V4D_ABS(inv) * (1 - ROUND_MARGIN), v4f),
	                   v4set(FLT_MAX));
	inv_in = v4pick(v4signs(inv_f), v4sub(v4set(0), inv_in), inv_in);
	vray_lanes(v4pick(neg, o_down, o_up), s->o_near);
	vray_lanes(v4pick(neg, o_up, o_down), s->o_far);
	vray_lanes(inv_in, s->inv_near);
	vray_lanes(__builtin_convertvector(inv * (FAR_WIDEN + ROUND_MARGIN), v4f), s->inv_far);
	s->rows = box_rows[v4signbits(d_f) & 7];
}

/* The row of n's boxes at byte offset off. */
static inline const float *box_row(const struct bvh_node *n, size_t off)
{
	return (const float *)((const char *)n->box + off);
}

/* tmax as the traversal compares with it: rounded up to float and widened as the exit
 * distances are, so that an entry distance computed too large still passes. */
static inline float far_bound(double tmax)
{
	return (float)(tmax * (FAR_WIDEN + ROUND_MARGIN)) + FAR_SLACK;
}

/* The slab test of the children of n: bit c of the result is set when the ray may meet
 * child c's box at some t in [0, tmax], from t_enter[c] on. tmax: far_bound(). Axis by
 * axis, max and min keep the accumulated value when the new one is NaN (0 * inf: the
 * origin on a slab plane, the direction parallel to it). */
#ifdef __AVX__
static inline int node_hit(const struct bvh_node *n, const struct box_ray *s, vray tmax, float t_enter[WIDTH])
{
	__m256 tnear = _mm256_setzero_ps(), tfar = tmax;
#pragma GCC unroll 3 /* GCC keeps this short loop rolled at -O2 */
	for (int k = 0; k < 3; k++) {
		__m256 near = _mm256_sub_ps(_mm256_load_ps(box_row(n, s->rows.enter[k])), s->o_near[k]);
		__m256 far = _mm256_sub_ps(_mm256_load_ps(box_row(n, s->rows.leave[k])), s->o_far[k]);
		__m256 t0 = _mm256_mul_ps(near, s->inv_near[k]), t1 = _mm256_mul_ps(far, s->inv_far[k]);
		tnear = _mm256_max_ps(t0, tnear);
		tfar = _mm256_min_ps(t1, tfar);
	}
	_mm256_storeu_ps(t_enter, tnear);
	__m256 far_end = _mm256_add_ps(tfar, _mm256_set1_ps(FAR_SLACK));
	return _mm256_movemask_ps(_mm256_cmp_ps(tnear, far_end, _CMP_LE_OQ));
}
#else
/* four children at a time, from child h on */
static inline int node_hit4(const struct bvh_node *n, const struct box_ray *s, int h, v4f tmax, float t_enter[4])
{
	v4f tnear = v4set(0), tfar = tmax;
	for (int k = 0; k < 3; k++) {
		v4f t0 = v4mul(v4sub(v4load(box_row(n, s->rows.enter[k]) + h), s->o_near[k]), s->inv_near[k]);
		v4f t1 = v4mul(v4sub(v4load(box_row(n, s->rows.leave[k]) + h), s->o_far[k]), s->inv_far[k]);
		tnear = v4max(t0, tnear);
		tfar = v4min(t1, tfar);
	}
	v4store(t_enter, tnear);
	return v4le(tnear, v4add(tfar, v4set(FAR_SLACK)));
}

static inline int node_hit(const struct bvh_node *n, const struct box_ray *s, vray tmax, float t_enter[WIDTH])
{
	return node_hit4(n, s, 0, tmax, t_enter) | node_hit4(n, s, 4, tmax, t_enter + 4) << 4;
}
#endif

/* What a query does with a leaf (index, count), see LEAF_DIRECT: test its primitives against
 * the ray up to *tmax, which a closest-hit query lowers as it finds hits. True ends the
 * walk. */
typedef bool leaf_fn(const struct bvh *b, uint32_t index, uint32_t count, void *query, double *tmax);

/* The ids of a leaf that lists them, NULL for a LEAF_DIRECT one; then the id of its
 * primitive i given its ids. */
static inline const uint32_t *leaf_ids(const struct bvh *b, uint32_t index, uint32_t count)
{
	return count & LEAF_DIRECT ? NULL : b->prims + index;
}
static inline uint32_t leaf_prim(const uint32_t *ids, uint32_t index, uint32_t i)
{
	return ids ? ids[i] : index + i;
}

/* Starts the loads of the nodes among n's children in mask, which the walk goes on to:
 * in a big tree each is a cache miss, which the walk would otherwise wait for when it
 * gets there, after the branches that order the children (which mispredict often). The
 * lines asked for are a node's first, where its boxes start, and its last, where its
 * children are named; asking for all four measured 7% slower than these two. On the
 * 1M-triangle bunny's random rays, with the walk's own fetch of the last line below,
 * 9% and 15% faster (medians of two sets of 16 alternating pairs); on 10^6 spheres'
 * render, 8%. In a small tree, whose nodes stay in cache, it only costs instructions (6%
 * on the small bunny's rays), so the walk does it in big trees alone. */
static inline void prefetch_nodes(const struct bvh *b, const struct bvh_node *n, int mask)
{
	for (; mask; mask &= mask - 1) {
		int m = __builtin_ctz((unsigned)mask);
		if (!n->count[m]) {
			const struct bvh_node *c = &b->nodes[n->index[m]];
			__builtin_prefetch(c->box);
			__builtin_prefetch(c->index);
		}
	}
}

/* Visits every leaf whose box the ray may meet before *tmax and skips a deferred
 * subtree that starts beyond *tmax as it stands when its turn comes. With nearest_first
 * the children hit are visited in order of their entry distance, which lets a
 * closest-hit query lower *tmax early; a shadow query, whose tmax stays, takes them as
 * they come. The root's own box is not tested: its children's are, in the first node.
 * With prefetch, the nodes it goes on to are fetched ahead (prefetch_nodes()).
 * Inlined into each query, so that its leaf test is a direct call, inlined too (the
 * indirect call and its spills took 4% of the instructions on the bunny's rays). */
static inline __attribute__((always_inline)) void walk(const struct bvh *b, const struct ray *r, double *tmax,
                                                       leaf_fn *visit, void *query, bool nearest_first, bool prefetch)
{
	struct box_ray s;
	box_ray_init(r, &s);
	float bound = far_bound(*tmax);
	vray bound_v = vray_set(bound);
	struct entry {
		uint32_t index, count;
		float t;
	} stack[(WIDTH - 1) * MAX_DEPTH + 2 * WIDTH], e = { b->root.index, b->root.count, 0 };
	int sp = 0;
	for (;;) {
		if (e.count) {
			if (visit(b, e.index, e.count, query, tmax))
				return;
			bound = far_bound(*tmax);
			bound_v = vray_set(bound);
		} else {
			const struct bvh_node *n = &b->nodes[e.index];
			/* the line that names the children is read after the branches below: its
			 * miss would come after theirs, not with the boxes' (5% on the random rays) */
			if (prefetch)
				__builtin_prefetch(n->index);
			float t[WIDTH];
			int mask = node_hit(n, &s, bound_v, t);
			if (prefetch)
				prefetch_nodes(b, n, mask);
			if (mask) {
				int c = __builtin_ctz((unsigned)mask);
				mask &= mask - 1;
				if (mask && nearest_first) {
					/* the others wait on the stack, the farthest deepest */
					int order[WIDTH], k = 1;
					order[0] = c;
					for (; mask; mask &= mask - 1, k++) {
						int i = k, m = __builtin_ctz((unsigned)mask);
						for (; i > 0 && t[order[i - 1]] > t[m]; i--)
							order[i] = order[i - 1];
						order[i] = m;
					}
					while (--k > 0)
						stack[sp++] = (struct entry){ n->index[order[k]], n->count[order[k]], t[order[k]] };
					c = order[0];
				}
				for (; mask; mask &= mask - 1) {
					int m = __builtin_ctz((unsigned)mask);
					stack[sp++] = (struct entry){ n->index[m], n->count[m], t[m] };
				}
				e = (struct entry){ n->index[c], n->count[c], t[c] };
				continue;
			}
		}
		do {
			if (sp == 0)
				return;
			e = stack[--sp];
		} while (e.t > bound);
	}
}

struct closest_query {
	const struct scene *sc;
	const struct ray *r;
	struct tri_ray tr;
	struct hit *h;
	bool hit;
};

static inline __attribute__((always_inline)) bool closest_leaf(const struct bvh *b, uint32_t index, uint32_t count,
                                                               void *query, double *tmax)
{
	struct closest_query *q = query;
	if (count & LEAF_PACKED) {
		for (uint32_t p = 0; p < leaf_packets(leaf_size(count)); p++)
			q->hit |= tri_packet_intersect(&b->packets[index + p], q->sc, &q->tr, q->h);
	} else {
		const uint32_t *ids = leaf_ids(b, index, count);
		for (uint32_t i = 0; i < leaf_size(count); i++)
			q->hit |= prim_intersect(q->sc, leaf_prim(ids, index, i), q->r, &q->tr, q->h);
	}
	*tmax = q->h->t;
	return false;
}

static inline __attribute__((always_inline)) bool intersect(const struct bvh *b, const struct scene *sc,
                                                            const struct ray *r, struct hit *h, bool prefetch)
{
	struct closest_query q = { .sc = sc, .r = r, .h = h, .hit = planes_intersect(sc, r, h) };
	if (b->nprims) {
		tri_ray_for(sc, r, &q.tr);
		double tmax = h->t;
		walk(b, r, &tmax, closest_leaf, &q, true, prefetch);
	}
	return q.hit;
}

/* The queries of big trees, which prefetch (this and transmittance_big()), are functions
 * of their own: with both walks in one function, the one small trees take cost 0.6% more
 * instructions on the small bunny's rays and on the headline (GCC allocates registers
 * for a function as a whole). */
static __attribute__((noinline)) bool intersect_big(const struct bvh *b, const struct scene *sc,
                                                    const struct ray *r, struct hit *h)
{
	return intersect(b, sc, r, h, true);
}

bool bvh_intersect(const struct bvh *b, const struct scene *sc, const struct ray *r, struct hit *h)
{
	return b->big ? intersect_big(b, sc, r, h) : intersect(b, sc, r, h, false);
}

struct shadow_query {
	const struct scene *sc;
	const struct ray *r;
	struct tri_ray tr;
	struct vec3 pass;
};

static inline __attribute__((always_inline)) bool shadow_leaf(const struct bvh *b, uint32_t index, uint32_t count,
                                                              void *query, double *tmax)
{
	struct shadow_query *q = query;
	if (count & LEAF_PACKED) {
		for (uint32_t p = 0; p < leaf_packets(leaf_size(count)); p++) {
			q->pass = tri_packet_filter(&b->packets[index + p], q->sc, &q->tr, *tmax, q->pass);
			if (vzero(q->pass))
				return true;
		}
		return false;
	}
	const uint32_t *ids = leaf_ids(b, index, count);
	for (uint32_t i = 0; i < leaf_size(count); i++) {
		q->pass = prim_filter(q->sc, leaf_prim(ids, index, i), q->r, &q->tr, *tmax, q->pass);
		if (vzero(q->pass))
			return true;
	}
	return false;
}

static inline __attribute__((always_inline)) struct vec3 transmittance(const struct bvh *b, const struct scene *sc,
                                                                        const struct ray *r, double tmax,
                                                                        bool prefetch)
{
	struct shadow_query q = { .sc = sc, .r = r, .pass = planes_filter(sc, r, tmax) };
	if (vzero(q.pass) || !b->nprims)
		return q.pass;
	tri_ray_for(sc, r, &q.tr);
	walk(b, r, &tmax, shadow_leaf, &q, false, prefetch);
	return q.pass;
}

static __attribute__((noinline)) struct vec3 transmittance_big(const struct bvh *b, const struct scene *sc,
                                                               const struct ray *r, double tmax)
{
	return transmittance(b, sc, r, tmax, true);
}

struct vec3 bvh_transmittance(const struct bvh *b, const struct scene *sc, const struct ray *r, double tmax)
{
	return b->big ? transmittance_big(b, sc, r, tmax) : transmittance(b, sc, r, tmax, false);
}
