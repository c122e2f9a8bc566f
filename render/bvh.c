/* bvh.c: a binned SAH bounding volume hierarchy (Wald, "On fast Construction of
 * SAH-based Bounding Volume Hierarchies", 2007), flattened depth-first into 32-byte
 * nodes. Bounds are kept in float, rounded outward, so a box never loses what it holds
 * (NUMERICS.md section 1); the slab test runs in double and is robust to zero direction
 * components and origins on a slab (Ize, "Robust BVH Ray Traversal", JCGT 2013). */
#include "bvh.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "xalloc.h"

enum {
	NBINS = 16,        /* SAH bins per axis: Wald found 16 as good as a full sweep */
	MAX_LEAF = 8,      /* never more in a leaf unless the primitives cannot be split */
	MAX_DEPTH = 96,    /* below this every node is a leaf; traversal stacks are sized by it */
};

struct bvh_node {
	float lo[3], hi[3];
	uint32_t index;    /* leaf: first entry of prims; interior: the second child (the first follows the node) */
	uint32_t count : 30; /* leaf: number of primitives; 0: interior */
	uint32_t axis : 2;   /* interior: the split axis, for near-first traversal */
};

struct bvh {
	struct bvh_node *nodes;
	size_t nnodes, cap;
	uint32_t *prims;   /* prim_id()s in leaf order */
	int depth;
};

struct box {
	struct vec3 lo, hi;
};

struct build_ref {
	struct box box;
	struct vec3 centroid;
	uint32_t prim;
};

static struct box box_empty(void)
{
	return (struct box){ v3s(INFINITY), v3s(-INFINITY) };
}

static struct box box_union(struct box a, struct box b)
{
	return (struct box){ vmin(a.lo, b.lo), vmax(a.hi, b.hi) };
}

static double box_area(struct box b)
{
	struct vec3 e = vsub(b.hi, b.lo);
	if (e.x < 0)
		return 0;
	return 2 * (e.x * e.y + e.y * e.z + e.z * e.x);
}

/* float bounds that still contain the double ones */
static float round_down(double x)
{
	float f = (float)x;
	return (double)f > x ? nextafterf(f, -INFINITY) : f;
}

static float round_up(double x)
{
	float f = (float)x;
	return (double)f < x ? nextafterf(f, INFINITY) : f;
}

static uint32_t new_node(struct bvh *b, struct box box)
{
	xgrow((void **)&b->nodes, &b->cap, b->nnodes + 1, sizeof *b->nodes);
	struct bvh_node *n = &b->nodes[b->nnodes];
	memset(n, 0, sizeof *n);
	for (int k = 0; k < 3; k++) {
		n->lo[k] = round_down(vget(box.lo, k));
		n->hi[k] = round_up(vget(box.hi, k));
	}
	return (uint32_t)b->nnodes++;
}

/* The bin of a centroid coordinate c, for bins of width 1/scale from lo. */
static int bin_of(double c, double lo, double scale, int nbins)
{
	int k = (int)((c - lo) * scale);
	return k < 0 ? 0 : k >= nbins ? nbins - 1 : k;
}

/* Finds the cheapest binned SAH split of refs[0, n) whose centroids span cbox.
 * Returns the axis and the bin boundary (split before bin *split), or -1 when keeping
 * a leaf is cheaper. */
static int find_split(const struct build_ref *refs, size_t n, struct box cbox, double parent_area, int *split)
{
	double best = (double)n; /* cost of a leaf, in primitive tests */
	int best_axis = -1;
	for (int axis = 0; axis < 3; axis++) {
		double lo = vget(cbox.lo, axis), extent = vget(cbox.hi, axis) - lo;
		if (!(extent > 0))
			continue;
		struct box bins[NBINS];
		size_t counts[NBINS] = { 0 };
		for (int i = 0; i < NBINS; i++)
			bins[i] = box_empty();
		double scale = NBINS / extent;
		for (size_t i = 0; i < n; i++) {
			int k = bin_of(vget(refs[i].centroid, axis), lo, scale, NBINS);
			counts[k]++;
			bins[k] = box_union(bins[k], refs[i].box);
		}
		/* sweep from the right, then from the left */
		double right_area[NBINS];
		size_t right_count[NBINS];
		struct box acc = box_empty();
		size_t cnt = 0;
		for (int i = NBINS - 1; i > 0; i--) {
			acc = box_union(acc, bins[i]);
			cnt += counts[i];
			right_area[i] = box_area(acc);
			right_count[i] = cnt;
		}
		acc = box_empty();
		cnt = 0;
		for (int i = 1; i < NBINS; i++) {
			acc = box_union(acc, bins[i - 1]);
			cnt += counts[i - 1];
			if (cnt == 0 || right_count[i] == 0)
				continue;
			/* traversal costs one box test against a primitive test of 1 */
			double cost = 0.5 + (box_area(acc) * (double)cnt + right_area[i] * (double)right_count[i]) / parent_area;
			if (cost < best) {
				best = cost;
				best_axis = axis;
				*split = i;
			}
		}
	}
	return best_axis;
}

/* Puts the references whose centroid falls in a bin before 'split' (of nbins) first;
 * returns how many there are. The binning arithmetic is the same as find_split's. */
static size_t partition(struct build_ref *refs, size_t n, int axis, double lo, double scale, int nbins, int split)
{
	size_t i = 0, j = n;
	while (i < j) {
		if (bin_of(vget(refs[i].centroid, axis), lo, scale, nbins) < split) {
			i++;
		} else {
			struct build_ref tmp = refs[i];
			refs[i] = refs[--j];
			refs[j] = tmp;
		}
	}
	return i;
}

static uint32_t build(struct bvh *b, struct build_ref *refs, size_t n, size_t first, int depth, bool brute)
{
	struct box box = box_empty(), cbox = box_empty();
	for (size_t i = 0; i < n; i++) {
		box = box_union(box, refs[i].box);
		cbox = box_union(cbox, (struct box){ refs[i].centroid, refs[i].centroid });
	}
	uint32_t node = new_node(b, box);
	if (depth > b->depth)
		b->depth = depth;

	int split = 0, axis = -1;
	if (!brute && n > 1 && depth < MAX_DEPTH)
		axis = find_split(refs, n, cbox, box_area(box), &split);
	size_t mid = 0;
	if (axis >= 0) {
		mid = partition(refs, n, axis, vget(cbox.lo, axis), NBINS / (vget(cbox.hi, axis) - vget(cbox.lo, axis)),
		                NBINS, split);
	} else if (!brute && n > MAX_LEAF && depth < MAX_DEPTH) {
		/* a leaf would be cheaper by SAH but is too big: split the widest axis in two
		 * halves, which is binning with two bins */
		struct vec3 e = vsub(cbox.hi, cbox.lo);
		axis = e.x >= e.y && e.x >= e.z ? 0 : e.y >= e.z ? 1 : 2;
		if (vget(e, axis) > 0)
			mid = partition(refs, n, axis, vget(cbox.lo, axis), 2 / vget(e, axis), 2, 1);
	}
	if (mid == 0 || mid == n) {
		/* a leaf: its primitives go to prims[first, first + n) */
		b->nodes[node].index = (uint32_t)first;
		b->nodes[node].count = (uint32_t)n;
		for (size_t i = 0; i < n; i++)
			b->prims[first + i] = refs[i].prim;
		return node;
	}
	build(b, refs, mid, first, depth + 1, brute);
	uint32_t right = build(b, refs + mid, n - mid, first + mid, depth + 1, brute);
	b->nodes[node].index = right;
	b->nodes[node].axis = (uint32_t)axis;
	return node;
}

struct bvh *bvh_build(const struct scene *sc, enum accel kind)
{
	struct bvh *b = xcalloc(1, sizeof *b);
	size_t n = sc->nspheres + sc->ntriangles;
	struct build_ref *refs = xcalloc(n, sizeof *refs);
	b->prims = xcalloc(n, sizeof *b->prims);
	size_t k = 0;
	for (size_t i = 0; i < sc->nspheres; i++, k++) {
		const struct sphere *s = &sc->spheres[i];
		refs[k].box = (struct box){ vsub(s->center, v3s(s->radius)), vadd(s->center, v3s(s->radius)) };
		refs[k].prim = prim_id(PRIM_SPHERE, (uint32_t)i);
	}
	for (size_t i = 0; i < sc->ntriangles; i++, k++) {
		const struct triangle *t = &sc->triangles[i];
		struct vec3 a = sc->vertices[t->v[0]], bb = sc->vertices[t->v[1]], c = sc->vertices[t->v[2]];
		refs[k].box = (struct box){ vmin(a, vmin(bb, c)), vmax(a, vmax(bb, c)) };
		refs[k].prim = prim_id(PRIM_TRIANGLE, (uint32_t)i);
	}
	for (size_t i = 0; i < n; i++)
		refs[i].centroid = vscale(vadd(refs[i].box.lo, refs[i].box.hi), 0.5);
	if (n > 0)
		build(b, refs, n, 0, 0, kind == ACCEL_NONE);
	free(refs);
	return b;
}

uint64_t bvh_bytes(uint64_t n)
{
	return n * (sizeof(struct build_ref) + sizeof(uint32_t) + 4 * sizeof(struct bvh_node));
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
	*nodes = b->nnodes;
	*depth = b->depth;
}

/* Slab test in double against float bounds. The comparisons are ordered so that a NaN
 * from 0 * inf (origin on a slab plane, direction parallel to it) is discarded, and
 * tfar is widened by pbrt's 1 + 2 gamma(3) so that rounding never culls a real hit. */
static inline bool box_hit(const struct bvh_node *n, struct vec3 o, struct vec3 inv, double tmax)
{
	double tnear = 0, tfar = tmax;
	for (int k = 0; k < 3; k++) {
		double ok = vget(o, k), ik = vget(inv, k);
		double t0 = ((double)n->lo[k] - ok) * ik;
		double t1 = ((double)n->hi[k] - ok) * ik;
		/* swap by the direction's sign, not by t0 > t1: with a -0 component and the
		 * origin on a face, one of them is NaN and the comparison would keep -inf as
		 * the far distance */
		if (ik < 0) {
			double tmp = t0;
			t0 = t1;
			t1 = tmp;
		}
		t1 *= 1 + 2 * err_gamma(3);
		tnear = t0 > tnear ? t0 : tnear;
		tfar = t1 < tfar ? t1 : tfar;
	}
	return tnear <= tfar;
}

bool bvh_intersect(const struct bvh *b, const struct scene *sc, const struct ray *r, struct hit *h)
{
	bool hit = planes_intersect(sc, r, h);
	if (!b->nnodes)
		return hit;
	struct vec3 inv = v3(1 / r->d.x, 1 / r->d.y, 1 / r->d.z);
	bool neg[3] = { r->d.x < 0, r->d.y < 0, r->d.z < 0 };
	uint32_t stack[2 * MAX_DEPTH + 8];
	int sp = 0;
	uint32_t cur = 0;
	for (;;) {
		const struct bvh_node *n = &b->nodes[cur];
		if (box_hit(n, r->o, inv, h->t)) {
			if (n->count) {
				for (uint32_t i = 0; i < n->count; i++)
					hit |= prim_intersect(sc, b->prims[n->index + i], r, h);
			} else {
				/* visit the child on the ray's near side first */
				uint32_t first = cur + 1, second = n->index;
				if (neg[n->axis]) {
					uint32_t tmp = first;
					first = second;
					second = tmp;
				}
				stack[sp++] = second;
				cur = first;
				continue;
			}
		}
		if (sp == 0)
			break;
		cur = stack[--sp];
	}
	return hit;
}

struct vec3 bvh_transmittance(const struct bvh *b, const struct scene *sc, const struct ray *r, double tmax)
{
	struct vec3 pass = planes_filter(sc, r, tmax);
	if (vzero(pass) || !b->nnodes)
		return pass;
	struct vec3 inv = v3(1 / r->d.x, 1 / r->d.y, 1 / r->d.z);
	uint32_t stack[2 * MAX_DEPTH + 8];
	int sp = 0;
	uint32_t cur = 0;
	for (;;) {
		const struct bvh_node *n = &b->nodes[cur];
		if (box_hit(n, r->o, inv, tmax)) {
			if (!n->count) {
				stack[sp++] = n->index;
				cur = cur + 1;
				continue;
			}
			for (uint32_t i = 0; i < n->count; i++) {
				pass = prim_filter(sc, b->prims[n->index + i], r, tmax, pass);
				if (vzero(pass))
					return pass;
			}
		}
		if (sp == 0)
			break;
		cur = stack[--sp];
	}
	return pass;
}
