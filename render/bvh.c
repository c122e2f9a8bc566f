/* bvh.c: a binned SAH bounding volume hierarchy (Wald, "On fast Construction of
 * SAH-based Bounding Volume Hierarchies", 2007) in 32-byte nodes whose two children sit
 * side by side, so that traversal tests both boxes from one cache line and enters the
 * nearer first. Bounds are kept in float, rounded outward, so a box never loses what it
 * holds (NUMERICS.md section 1); the slab test runs in double and is robust to zero
 * direction components and origins on a slab (Ize, "Robust BVH Ray Traversal", JCGT
 * 2013).
 *
 * The build splits the top of the tree on one thread and hands the subtrees below a size
 * fixed by the primitive count to worker threads, then joins their nodes in the order
 * the top split made them: the tree and its layout depend on the scene alone, never on
 * the thread count or on which thread finished first. */
#include "bvh.h"

#include <float.h>
#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "xalloc.h"

enum {
	NBINS = 16,        /* SAH bins per axis: Wald found 16 as good as a full sweep */
	MAX_LEAF = 8,      /* never more in a leaf unless the primitives cannot be split */
	MAX_DEPTH = 96,    /* below this every node is a leaf; traversal stacks are sized by it */
	MIN_TASK = 4096,   /* primitives in a subtree worth a thread of its own */
	TASKS_PER_TREE = 64, /* subtrees the top split aims for, so that threads share the work evenly */
};

/* Vectors, with SSE2 where there is SSE2 (every x86-64) and GCC's generic vectors
 * elsewhere. v2d: two doubles, one per child of a node, so that the slab test runs on
 * both children at once; v4f: a float box corner, for the build. */
#ifdef __SSE2__
#include <emmintrin.h>
typedef __m128 v4f;
static inline v4f v4set(float x) { return _mm_set1_ps(x); }
static inline v4f v4load(const float p[4]) { return _mm_loadu_ps(p); }
static inline void v4store(float p[4], v4f a) { _mm_storeu_ps(p, a); }
static inline v4f v4min(v4f a, v4f b) { return _mm_min_ps(a, b); }
static inline v4f v4max(v4f a, v4f b) { return _mm_max_ps(a, b); }
static inline v4f v4sub(v4f a, v4f b) { return _mm_sub_ps(a, b); }
typedef __m128d v2d;
static inline v2d v2set(double x) { return _mm_set1_pd(x); }
static inline v2d v2load(const float p[2]) { return _mm_cvtps_pd(_mm_castsi128_ps(_mm_loadl_epi64((const __m128i *)p))); }
static inline v2d v2sub(v2d a, v2d b) { return _mm_sub_pd(a, b); }
static inline v2d v2mul(v2d a, v2d b) { return _mm_mul_pd(a, b); }
/* a > b ? a : b and a < b ? a : b, lane by lane: a NaN in a gives b */
static inline v2d v2max(v2d a, v2d b) { return _mm_max_pd(a, b); }
static inline v2d v2min(v2d a, v2d b) { return _mm_min_pd(a, b); }
/* bit c set when a[c] <= b[c] */
static inline int v2le(v2d a, v2d b) { return _mm_movemask_pd(_mm_cmple_pd(a, b)); }
static inline double v2lane(v2d a, int c) { return c ? _mm_cvtsd_f64(_mm_unpackhi_pd(a, a)) : _mm_cvtsd_f64(a); }
#else
typedef float v4f __attribute__((vector_size(16)));
typedef int v4i __attribute__((vector_size(16)));
static inline v4f v4set(float x) { return (v4f){ x, x, x, x }; }
static inline v4f v4load(const float p[4]) { v4f a; memcpy(&a, p, sizeof a); return a; }
static inline void v4store(float p[4], v4f a) { memcpy(p, &a, sizeof a); }
static inline v4f v4min(v4f a, v4f b) { v4i m = a < b; return (v4f)(((v4i)a & m) | ((v4i)b & ~m)); }
static inline v4f v4max(v4f a, v4f b) { v4i m = a > b; return (v4f)(((v4i)a & m) | ((v4i)b & ~m)); }
static inline v4f v4sub(v4f a, v4f b) { return a - b; }
typedef double v2d __attribute__((vector_size(16)));
typedef long long v2l __attribute__((vector_size(16)));
static inline v2d v2set(double x) { return (v2d){ x, x }; }
static inline v2d v2load(const float p[2]) { return (v2d){ p[0], p[1] }; }
static inline v2d v2sub(v2d a, v2d b) { return a - b; }
static inline v2d v2mul(v2d a, v2d b) { return a * b; }
static inline v2d v2max(v2d a, v2d b) { v2l m = a > b; return (v2d)(((v2l)a & m) | ((v2l)b & ~m)); }
static inline v2d v2min(v2d a, v2d b) { v2l m = a < b; return (v2d)(((v2l)a & m) | ((v2l)b & ~m)); }
static inline int v2le(v2d a, v2d b) { v2l m = a <= b; return (int)(m[0] & 1) | (int)(m[1] & 2); }
static inline double v2lane(v2d a, int c) { return a[c]; }
#endif

/* An interior node holds its two children's boxes, side by side so that one pair of
 * vector operations tests both: [lo x, y, z, hi x, y, z][child]. */
struct bvh_node {
	float box[6][2];
	uint32_t index[2]; /* child c: a node, or for a leaf the first entry of prims */
	uint32_t count[2]; /* child c: primitives in the leaf; 0: a node */
};

/* A subtree as its parent sees it. */
struct child {
	float box[6];
	uint32_t index, count;
};

struct bvh {
	struct child root;
	struct bvh_node *nodes;
	size_t nnodes;
	uint32_t *prims;   /* prim_id()s in leaf order */
	size_t nprims;
	int depth;
};

/* A primitive's bounds, already rounded outward to float, and the centre of its exact
 * bounds, which steers the splits (primitives with the same centre stay together). The
 * fourth lane of each is padding, for the vector code. */
struct build_ref {
	float lo[4], hi[4], centroid[4];
	uint32_t prim, pad[3];
};

struct node_vec {
	struct bvh_node *v;
	size_t n, cap;
};

/* A subtree left to a worker: its primitives are refs[first, +n); it becomes child c of
 * the top node parent (NO_PARENT: the root). */
#define NO_PARENT UINT32_MAX
struct task {
	uint32_t parent, c, first, n;
	int depth;
	struct child result;     /* the worker's result; its node indices are local to nodes */
	struct node_vec nodes;
	int max_depth;
};

struct builder {
	struct build_ref *refs;
	uint32_t *prims;
	bool brute;
	size_t task_size;        /* a subtree this small becomes a task; 0 while inside one */
	struct task *tasks;
	size_t ntasks, cap_tasks;
	atomic_size_t next_task;
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

/* The bin of a centroid coordinate c, for bins of width 1/scale from lo. */
static inline int bin_of(double c, double lo, double scale, int nbins)
{
	int k = (int)((c - lo) * scale);
	return k < 0 ? 0 : k >= nbins ? nbins - 1 : k;
}

struct split {
	int axis;                /* -1: none */
	int bin;                 /* split before this bin */
	int nbins;
	double lo, scale;        /* the binning of that axis */
};

/* Finds the cheapest binned SAH split of refs[0, n) whose centroids span clo..chi, all
 * three axes binned in one pass, in as many bins as there are references up to NBINS
 * (the sweep over the bins would cost small nodes more than the binning). axis -1 when
 * keeping a leaf is cheaper. */
static struct split find_split(const struct build_ref *refs, size_t n, const double clo[3], const double chi[3],
                               double parent_area)
{
	struct split best = { .axis = -1 };
	int nbins = n < NBINS ? (int)n : NBINS;
	double scale[3];
	struct vbox bins[3][NBINS];
	size_t counts[3][NBINS] = { { 0 } };
	for (int axis = 0; axis < 3; axis++) {
		double extent = chi[axis] - clo[axis];
		scale[axis] = extent > 0 ? nbins / extent : 0;
		for (int i = 0; i < nbins; i++)
			bins[axis][i] = vbox_empty();
	}
	for (size_t i = 0; i < n; i++) {
		v4f lo = v4load(refs[i].lo), hi = v4load(refs[i].hi);
		for (int axis = 0; axis < 3; axis++) {
			int k = bin_of(refs[i].centroid[axis], clo[axis], scale[axis], nbins);
			counts[axis][k]++;
			vbox_add(&bins[axis][k], lo, hi);
		}
	}
	double best_cost = (double)n; /* cost of a leaf, in primitive tests */
	for (int axis = 0; axis < 3; axis++) {
		if (scale[axis] == 0)
			continue;
		/* sweep from the right, then from the left */
		double right_area[NBINS];
		size_t right_count[NBINS];
		struct vbox acc = vbox_empty();
		size_t cnt = 0;
		for (int i = nbins - 1; i > 0; i--) {
			vbox_add(&acc, bins[axis][i].lo, bins[axis][i].hi);
			cnt += counts[axis][i];
			right_area[i] = vbox_area(acc);
			right_count[i] = cnt;
		}
		acc = vbox_empty();
		cnt = 0;
		for (int i = 1; i < nbins; i++) {
			vbox_add(&acc, bins[axis][i - 1].lo, bins[axis][i - 1].hi);
			cnt += counts[axis][i - 1];
			if (cnt == 0 || right_count[i] == 0)
				continue;
			/* a node costs a box test (of a pair, done at once) as much as a primitive test */
			double cost = 1.0 + (vbox_area(acc) * (double)cnt + right_area[i] * (double)right_count[i]) / parent_area;
			if (cost < best_cost) {
				best_cost = cost;
				best = (struct split){ axis, i, nbins, clo[axis], scale[axis] };
			}
		}
	}
	return best;
}

/* Puts the references whose centroid falls in a bin before s.bin first; returns how
 * many there are. The binning arithmetic is the same as find_split's. */
static size_t partition(struct build_ref *refs, size_t n, struct split s)
{
	size_t i = 0, j = n;
	while (i < j) {
		if (bin_of(refs[i].centroid[s.axis], s.lo, s.scale, s.nbins) < s.bin) {
			i++;
		} else {
			struct build_ref tmp = refs[i];
			refs[i] = refs[--j];
			refs[j] = tmp;
		}
	}
	return i;
}

static uint32_t push_node(struct node_vec *nv)
{
	xgrow((void **)&nv->v, &nv->cap, nv->n + 1, sizeof *nv->v);
	memset(&nv->v[nv->n], 0, sizeof *nv->v);
	return (uint32_t)nv->n++;
}

static void set_child(struct bvh *bvh, struct node_vec *nv, uint32_t parent, uint32_t c, const struct child *ch)
{
	if (parent == NO_PARENT) {
		bvh->root = *ch;
		return;
	}
	struct bvh_node *nd = &nv->v[parent];
	for (int k = 0; k < 6; k++)
		nd->box[k][c] = ch->box[k];
	nd->index[c] = ch->index;
	nd->count[c] = ch->count;
}

/* Builds the subtree of refs[first, first + n) into nv and returns it as its parent
 * sees it; at the top (b->task_size set) a small enough subtree is left to a worker, and
 * its parent's slot filled in later. *depth: the deepest level reached. */
static struct child build(struct builder *b, struct node_vec *nv, uint32_t parent, uint32_t c, uint32_t first,
                          uint32_t n, int level, int *depth)
{
	struct child ch = { .count = 0 };
	if (b->task_size && n <= b->task_size) {
		xgrow((void **)&b->tasks, &b->cap_tasks, b->ntasks + 1, sizeof *b->tasks);
		b->tasks[b->ntasks++] = (struct task){ .parent = parent, .c = c, .first = first, .n = n, .depth = level };
		return ch;
	}
	if (level > *depth)
		*depth = level;
	struct build_ref *refs = b->refs + first;
	struct vbox box = vbox_empty(), cbox = vbox_empty();
	for (size_t i = 0; i < n; i++) {
		vbox_add(&box, v4load(refs[i].lo), v4load(refs[i].hi));
		v4f c = v4load(refs[i].centroid);
		vbox_add(&cbox, c, c);
	}
	float lo[4], hi[4];
	v4store(lo, box.lo);
	v4store(hi, box.hi);
	memcpy(ch.box, lo, 3 * sizeof *lo);
	memcpy(ch.box + 3, hi, 3 * sizeof *hi);
	v4store(lo, cbox.lo);
	v4store(hi, cbox.hi);
	double clo[3] = { lo[0], lo[1], lo[2] }, chi[3] = { hi[0], hi[1], hi[2] };

	struct split s = { .axis = -1 };
	if (!b->brute && n > 1 && level < MAX_DEPTH)
		s = find_split(refs, n, clo, chi, vbox_area(box));
	size_t mid = 0;
	if (s.axis >= 0) {
		mid = partition(refs, n, s);
	} else if (!b->brute && n > MAX_LEAF && level < MAX_DEPTH) {
		/* a leaf would be cheaper by SAH but is too big: split the widest axis in two
		 * halves, which is binning with two bins */
		double e[3] = { chi[0] - clo[0], chi[1] - clo[1], chi[2] - clo[2] };
		int axis = e[0] >= e[1] && e[0] >= e[2] ? 0 : e[1] >= e[2] ? 1 : 2;
		if (e[axis] > 0)
			mid = partition(refs, n, (struct split){ axis, 1, 2, clo[axis], 2 / e[axis] });
	}
	if (mid == 0 || mid == n) {
		/* a leaf: its primitives go to prims[first, first + n) */
		ch.index = first;
		ch.count = n;
		for (size_t i = 0; i < n; i++)
			b->prims[first + i] = refs[i].prim;
		return ch;
	}
	uint32_t node = push_node(nv);
	ch.index = node;
	struct child l = build(b, nv, node, 0, first, (uint32_t)mid, level + 1, depth);
	set_child(NULL, nv, node, 0, &l);
	struct child r = build(b, nv, node, 1, first + (uint32_t)mid, n - (uint32_t)mid, level + 1, depth);
	set_child(NULL, nv, node, 1, &r);
	return ch;
}

static void *worker(void *arg)
{
	struct builder *b = arg;
	for (;;) {
		size_t i = atomic_fetch_add(&b->next_task, 1);
		if (i >= b->ntasks)
			return NULL;
		struct task *t = &b->tasks[i];
		t->max_depth = t->depth;
		t->result = build(b, &t->nodes, NO_PARENT, 0, t->first, t->n, t->depth, &t->max_depth);
		if (t->nodes.n) /* trimmed: bvh_bytes counts the nodes twice, not four times */
			t->nodes.v = xrealloc(t->nodes.v, t->nodes.n * sizeof *t->nodes.v);
	}
}

/* Runs the tasks on up to threads threads (the calling one among them). */
static void run_tasks(struct builder *b, int threads)
{
	if (threads > (int)b->ntasks)
		threads = (int)b->ntasks;
	pthread_t *tid = xcalloc((size_t)(threads > 1 ? threads - 1 : 1), sizeof *tid);
	int started = 0;
	while (started < threads - 1 && pthread_create(&tid[started], NULL, worker, b) == 0)
		started++;
	worker(b); /* if no thread could start, this one does it all */
	for (int i = 0; i < started; i++)
		pthread_join(tid[i], NULL);
	free(tid);
}

/* Appends each task's nodes to the top nodes, in task order, and puts each subtree in
 * the slot the top split left for it. */
static void join_tasks(struct builder *b, struct bvh *bvh, struct node_vec *top)
{
	size_t total = top->n;
	for (size_t i = 0; i < b->ntasks; i++)
		total += b->tasks[i].nodes.n;
	if (total > top->cap) { /* exactly: this array is the tree's */
		top->v = xrealloc(top->v, total * sizeof *top->v);
		top->cap = total;
	}
	for (size_t i = 0; i < b->ntasks; i++) {
		struct task *t = &b->tasks[i];
		uint32_t base = (uint32_t)top->n;
		for (size_t k = 0; k < t->nodes.n; k++) {
			struct bvh_node nd = t->nodes.v[k];
			for (int c = 0; c < 2; c++)
				if (nd.count[c] == 0)
					nd.index[c] += base;
			top->v[top->n++] = nd;
		}
		if (t->result.count == 0)
			t->result.index += base;
		set_child(bvh, top, t->parent, t->c, &t->result);
		if (t->max_depth > bvh->depth)
			bvh->depth = t->max_depth;
		free(t->nodes.v);
	}
}

struct bvh *bvh_build(const struct scene *sc, enum accel kind)
{
	struct bvh *bvh = xcalloc(1, sizeof *bvh);
	size_t n = sc->nspheres + sc->ntriangles;
	bvh->nprims = n;
	if (n == 0)
		return bvh;
	struct builder b = { .brute = kind == ACCEL_NONE };
	b.refs = xmalloc(n * sizeof *b.refs);
	bvh->prims = b.prims = xmalloc(n * sizeof *b.prims);
	size_t k = 0;
	for (size_t i = 0; i < sc->nspheres; i++, k++) {
		const struct sphere *s = &sc->spheres[i];
		for (int a = 0; a < 3; a++) {
			double c = vget(s->center, a);
			b.refs[k].lo[a] = float_below(c - s->radius);
			b.refs[k].hi[a] = float_above(c + s->radius);
			b.refs[k].centroid[a] = (float)c;
		}
		b.refs[k].prim = prim_id(PRIM_SPHERE, (uint32_t)i);
	}
	for (size_t i = 0; i < sc->ntriangles; i++, k++) {
		const struct triangle *t = &sc->triangles[i];
		struct vec3 p0 = sc->vertices[t->v[0]], p1 = sc->vertices[t->v[1]], p2 = sc->vertices[t->v[2]];
		struct vec3 lo = vmin(p0, vmin(p1, p2)), hi = vmax(p0, vmax(p1, p2));
		for (int a = 0; a < 3; a++) {
			b.refs[k].lo[a] = float_below(vget(lo, a));
			b.refs[k].hi[a] = float_above(vget(hi, a));
			b.refs[k].centroid[a] = (float)(0.5 * (vget(lo, a) + vget(hi, a)));
		}
		b.refs[k].prim = prim_id(PRIM_TRIANGLE, (uint32_t)i);
	}
	size_t task = n / TASKS_PER_TREE;
	b.task_size = task > MIN_TASK ? task : MIN_TASK;
	struct node_vec top = { 0 };
	bvh->root = build(&b, &top, NO_PARENT, 0, 0, (uint32_t)n, 0, &bvh->depth);
	b.task_size = 0;
	long cores = sysconf(_SC_NPROCESSORS_ONLN);
	atomic_init(&b.next_task, 0);
	run_tasks(&b, cores > 0 ? (int)cores : 1);
	join_tasks(&b, bvh, &top);
	free(b.tasks);
	free(b.refs);
	bvh->nodes = top.n ? xrealloc(top.v, top.n * sizeof *top.v) : NULL;
	bvh->nnodes = top.n;
	return bvh;
}

uint64_t bvh_bytes(uint64_t n)
{
	/* build records, prims, and the nodes (one primitive a leaf: n - 1 of them) twice
	 * over: the workers' arrays, each trimmed to its nodes, and the joined one */
	return n * (sizeof(struct build_ref) + sizeof(uint32_t) + 2 * sizeof(struct bvh_node));
}

void bvh_free(struct bvh *b)
{
	if (!b)
		return;
	free(b->nodes);
	free(b->prims);
	free(b);
}

void bvh_shape(const struct bvh *b, size_t *nodes, int *depth)
{
	*nodes = b->nprims ? 2 * b->nnodes + 1 : 0; /* boxes, the root's included */
	*depth = b->depth;
}

/* What the slab test needs of a ray, worked out once: for each axis the box coordinate
 * it enters by (lo, or hi when the direction is negative) and the one it leaves by. */
struct ray_slabs {
	v2d o[3], inv[3];
	int enter[3], leave[3];     /* indices into bvh_node.box */
};

static void ray_slabs(const struct ray *r, struct ray_slabs *s)
{
	for (int k = 0; k < 3; k++) {
		double inv = 1 / vget(r->d, k);
		s->o[k] = v2set(vget(r->o, k));
		s->inv[k] = v2set(inv);
		/* by the sign of 1/d, not by comparing the two distances: with a -0 component and
		 * the origin on a face one of them is NaN, and the comparison would keep -inf as
		 * the far distance */
		bool neg = inv < 0;
		s->enter[k] = k + 3 * neg;
		s->leave[k] = k + 3 * !neg;
	}
}

/* One axis of the slab test: narrows [*tnear, *tfar] to where the ray is between the two
 * planes. The comparisons are ordered so that a NaN from 0 * inf (origin on a slab
 * plane, direction parallel to it) is discarded, and the exit distance is widened by
 * pbrt's 1 + 2 gamma(3) so that rounding never culls a real hit. */
static inline void slab(const struct bvh_node *n, const struct ray_slabs *s, int k, v2d *tnear, v2d *tfar)
{
	v2d t0 = v2mul(v2sub(v2load(n->box[s->enter[k]]), s->o[k]), s->inv[k]);
	v2d t1 = v2mul(v2sub(v2load(n->box[s->leave[k]]), s->o[k]), s->inv[k]);
	t1 = v2mul(t1, v2set(1 + 2 * err_gamma(3)));
	*tnear = v2max(t0, *tnear);
	*tfar = v2min(t1, *tfar);
}

/* Slab test in double against the float boxes of both children of n: bit c of the
 * result is set when the ray meets child c's box at some t in [0, tmax], from t_enter[c]
 * on. */
static inline int pair_hit(const struct bvh_node *n, const struct ray_slabs *s, double tmax, v2d *t_enter)
{
	v2d tnear = v2set(0), tfar = v2set(tmax);
	slab(n, s, 0, &tnear, &tfar);
	slab(n, s, 1, &tnear, &tfar);
	slab(n, s, 2, &tnear, &tfar);
	*t_enter = tnear;
	return v2le(tnear, tfar);
}

/* What a query does with a leaf's primitives prims[first, +count): test them against
 * the ray up to *tmax, which a closest-hit query lowers as it finds hits. True ends the
 * walk. */
typedef bool leaf_fn(const struct bvh *b, uint32_t first, uint32_t count, void *query, double *tmax);

/* Visits every leaf whose box the ray meets before *tmax, the nearer child first, and
 * skips a deferred subtree that starts beyond *tmax as it stands when its turn comes. */
static inline void walk(const struct bvh *b, const struct ray *r, double *tmax, leaf_fn *visit, void *query)
{
	struct ray_slabs s;
	ray_slabs(r, &s);
	/* the root as the only child of a node whose other box is empty */
	struct bvh_node top = { .index = { b->root.index, 0 }, .count = { b->root.count, 0 } };
	for (int k = 0; k < 3; k++) {
		top.box[k][0] = b->root.box[k];
		top.box[k + 3][0] = b->root.box[k + 3];
		top.box[k][1] = INFINITY;
		top.box[k + 3][1] = -INFINITY;
	}
	struct { uint32_t index, count; double t; } stack[MAX_DEPTH + 8];
	int sp = 0;
	const struct bvh_node *n = &top;
	for (;;) {
		v2d t;
		int hit = pair_hit(n, &s, *tmax, &t);
		uint32_t index = 0, count = 0;
		if (hit) {
			int c = hit == 3 ? v2lane(t, 1) < v2lane(t, 0) : hit >> 1; /* the nearer child hit */
			if (hit == 3) {
				stack[sp].index = n->index[!c];
				stack[sp].count = n->count[!c];
				stack[sp].t = v2lane(t, !c);
				sp++;
			}
			index = n->index[c];
			count = n->count[c];
			if (!count) {
				n = &b->nodes[index];
				continue;
			}
		}
		/* a leaf, then what the stack holds: leaves are visited until a node comes */
		for (;;) {
			if (count && visit(b, index, count, query, tmax))
				return;
			do {
				if (sp == 0)
					return;
				sp--;
			} while (stack[sp].t > *tmax);
			index = stack[sp].index;
			count = stack[sp].count;
			if (!count)
				break;
		}
		n = &b->nodes[index];
	}
}

struct closest_query {
	const struct scene *sc;
	const struct ray *r;
	struct hit *h;
	bool hit;
};

static bool closest_leaf(const struct bvh *b, uint32_t first, uint32_t count, void *query, double *tmax)
{
	struct closest_query *q = query;
	for (uint32_t i = 0; i < count; i++)
		q->hit |= prim_intersect(q->sc, b->prims[first + i], q->r, q->h);
	*tmax = q->h->t;
	return false;
}

bool bvh_intersect(const struct bvh *b, const struct scene *sc, const struct ray *r, struct hit *h)
{
	struct closest_query q = { sc, r, h, planes_intersect(sc, r, h) };
	if (b->nprims) {
		double tmax = h->t;
		walk(b, r, &tmax, closest_leaf, &q);
	}
	return q.hit;
}

struct shadow_query {
	const struct scene *sc;
	const struct ray *r;
	struct vec3 pass;
};

static bool shadow_leaf(const struct bvh *b, uint32_t first, uint32_t count, void *query, double *tmax)
{
	struct shadow_query *q = query;
	for (uint32_t i = 0; i < count; i++) {
		q->pass = prim_filter(q->sc, b->prims[first + i], q->r, *tmax, q->pass);
		if (vzero(q->pass))
			return true;
	}
	return false;
}

struct vec3 bvh_transmittance(const struct bvh *b, const struct scene *sc, const struct ray *r, double tmax)
{
	struct shadow_query q = { sc, r, planes_filter(sc, r, tmax) };
	if (!vzero(q.pass) && b->nprims)
		walk(b, r, &tmax, shadow_leaf, &q);
	return q.pass;
}
