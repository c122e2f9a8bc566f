/* bvh_traverse.c: the BVH's queries, closest hit and shadow filter: a walk of the
 * eight-wide nodes whose children's boxes one AVX slab test (or two SSE ones) handles at
 * once, nearest child first. The slab test in float on float boxes is made conservative
 * by rounding the ray's origin and 1/d outward and widening the exit distance (NUMERICS.md
 * section 1; pbrt 3rd ed. section 3.9.2); it is robust to zero direction components and
 * origins on a slab (Ize, "Robust BVH Ray Traversal", JCGT 2013). A leaf of triangles is
 * tested as packets of four (tri_packet.h). */
#include <float.h>
#include <math.h>
#include <string.h>

#include "bvh_impl.h"
#include "v4d.h"

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
	const struct geometry *geo;
	const struct ray *r;
	struct triangle_ray tr;
	struct hit *h;
	bool hit;
};

static inline __attribute__((always_inline)) bool closest_leaf(const struct bvh *b, uint32_t index, uint32_t count,
                                                               void *query, double *tmax)
{
	struct closest_query *q = query;
	if (count & LEAF_PACKED) {
		for (uint32_t p = 0; p < leaf_packets(leaf_size(count)); p++)
			q->hit |= tri_packet_intersect(&b->packets[index + p], q->geo, &q->tr, q->h);
	} else {
		const uint32_t *ids = leaf_ids(b, index, count);
		for (uint32_t i = 0; i < leaf_size(count); i++)
			q->hit |= shape_intersect(q->geo, leaf_prim(ids, index, i), q->r, &q->tr, q->h);
	}
	*tmax = q->h->t;
	return false;
}

static inline __attribute__((always_inline)) bool intersect(const struct bvh *b, const struct geometry *geo,
                                                            const struct ray *r, struct hit *h, bool prefetch)
{
	struct closest_query q = { .geo = geo, .r = r, .h = h, .hit = shape_planes_intersect(geo, r, h) };
	if (b->nprims) {
		shape_triangle_ray(geo, r, &q.tr);
		double tmax = h->t;
		walk(b, r, &tmax, closest_leaf, &q, true, prefetch);
	}
	return q.hit;
}

/* The queries of big trees, which prefetch (this and transmittance_big()), are functions
 * of their own: with both walks in one function, the one small trees take cost 0.6% more
 * instructions on the small bunny's rays and on the headline (GCC allocates registers
 * for a function as a whole). */
static __attribute__((noinline)) bool intersect_big(const struct bvh *b, const struct geometry *geo,
                                                    const struct ray *r, struct hit *h)
{
	return intersect(b, geo, r, h, true);
}

bool bvh_intersect(const struct bvh *b, const struct geometry *geo, const struct ray *r, struct hit *h)
{
	return b->big ? intersect_big(b, geo, r, h) : intersect(b, geo, r, h, false);
}

struct shadow_query {
	const struct geometry *geo;
	const struct ray *r;
	struct triangle_ray tr;
	struct vec3 pass;
};

static inline __attribute__((always_inline)) bool shadow_leaf(const struct bvh *b, uint32_t index, uint32_t count,
                                                              void *query, double *tmax)
{
	struct shadow_query *q = query;
	if (count & LEAF_PACKED) {
		for (uint32_t p = 0; p < leaf_packets(leaf_size(count)); p++) {
			q->pass = tri_packet_filter(&b->packets[index + p], q->geo, &q->tr, *tmax, q->pass);
			if (vzero(q->pass))
				return true;
		}
		return false;
	}
	const uint32_t *ids = leaf_ids(b, index, count);
	for (uint32_t i = 0; i < leaf_size(count); i++) {
		q->pass = shape_filter(q->geo, leaf_prim(ids, index, i), q->r, &q->tr, *tmax, q->pass);
		if (vzero(q->pass))
			return true;
	}
	return false;
}

static inline __attribute__((always_inline)) struct vec3 transmittance(const struct bvh *b, const struct geometry *geo,
                                                                        const struct ray *r, double tmax,
                                                                        bool prefetch)
{
	struct shadow_query q = { .geo = geo, .r = r, .pass = shape_planes_filter(geo, r, tmax) };
	if (vzero(q.pass) || !b->nprims)
		return q.pass;
	shape_triangle_ray(geo, r, &q.tr);
	walk(b, r, &tmax, shadow_leaf, &q, false, prefetch);
	return q.pass;
}

static __attribute__((noinline)) struct vec3 transmittance_big(const struct bvh *b, const struct geometry *geo,
                                                               const struct ray *r, double tmax)
{
	return transmittance(b, geo, r, tmax, true);
}

struct vec3 bvh_transmittance(const struct bvh *b, const struct geometry *geo, const struct ray *r, double tmax)
{
	return b->big ? transmittance_big(b, geo, r, tmax) : transmittance(b, geo, r, tmax, false);
}

/* Whether the box lo..hi lies wholly outside one of region's planes. */
static bool box_outside(const double lo[3], const double hi[3], const struct bvh_region *region)
{
	for (int k = 0; k < region->nplanes; k++) {
		const double *p = region->plane[k];
		/* the box's corner farthest inside the plane */
		double v = p[0] * (p[0] > 0 ? lo[0] : hi[0]) + p[1] * (p[1] > 0 ? lo[1] : hi[1]) +
		           p[2] * (p[2] > 0 ? lo[2] : hi[2]);
		if (v > p[3])
			return true;
	}
	return false;
}

/* A leaf of box lo..hi (floats held in double: exact both ways). */
static struct bvh_leaf leaf_of(const double lo[3], const double hi[3], uint32_t index, uint32_t count)
{
	return (struct bvh_leaf){ { (float)lo[0], (float)lo[1], (float)lo[2] }, { (float)hi[0], (float)hi[1], (float)hi[2] },
		                  index, count };
}

int bvh_gather(const struct bvh *b, const struct bvh_region *region, struct bvh_leaf *leaves, int cap)
{
	if (!b->nprims)
		return 0;
	const float *rb = b->root.box;
	double root_lo[3] = { rb[0], rb[1], rb[2] }, root_hi[3] = { rb[3], rb[4], rb[5] };
	if (box_outside(root_lo, root_hi, region))
		return 0;
	if (b->root.count) {
		leaves[0] = leaf_of(root_lo, root_hi, b->root.index, b->root.count);
		return 1;
	}
	uint32_t stack[(WIDTH - 1) * MAX_DEPTH + WIDTH];
	int sp = 0, n = 0;
	stack[sp++] = b->root.index;
	while (sp > 0) {
		const struct bvh_node *node = &b->nodes[stack[--sp]];
		for (int c = 0; c < WIDTH; c++) {
			double lo[3] = { node->box[0][c], node->box[1][c], node->box[2][c] };
			double hi[3] = { node->box[3][c], node->box[4][c], node->box[5][c] };
			if (!(lo[0] <= hi[0]) || box_outside(lo, hi, region))
				continue; /* an empty slot, or out of the region */
			if (!node->count[c]) {
				stack[sp++] = node->index[c];
			} else {
				if (n == cap)
					return -1;
				leaves[n++] = leaf_of(lo, hi, node->index[c], node->count[c]);
			}
		}
	}
	return n;
}

struct vec3 bvh_transmittance_among(const struct bvh *b, const struct geometry *geo, const struct ray *r, double tmax,
                                    struct bvh_leaf *leaves, int n)
{
	struct shadow_query q = { .geo = geo, .r = r, .pass = shape_planes_filter(geo, r, tmax) };
	if (vzero(q.pass) || n == 0)
		return q.pass;
	shape_triangle_ray(geo, r, &q.tr);
	/* each leaf's box first, in double: the slab test, widened by a relative 2^-20 (the
	 * boxes hold their primitives with room to spare; this only keeps rounding from
	 * losing a leaf whose box the ray grazes) */
	double inv[3] = { 1 / r->d.x, 1 / r->d.y, 1 / r->d.z }, o[3] = { r->o.x, r->o.y, r->o.z };
	for (int i = 0; i < n; i++) {
		double t0 = 0, t1 = tmax;
		for (int k = 0; k < 3; k++) {
			double pad = 0x1p-20 * (fabs(leaves[i].lo[k]) + fabs(leaves[i].hi[k])) + FLT_TRUE_MIN;
			double a = (leaves[i].lo[k] - pad - o[k]) * inv[k], c = (leaves[i].hi[k] + pad - o[k]) * inv[k];
			if (inv[k] < 0) {
				double swap = a;
				a = c;
				c = swap;
			}
			/* NaN (0 * inf: the origin on a slab, d parallel to it) keeps the bound */
			t0 = a > t0 ? a : t0;
			t1 = c < t1 ? c : t1;
		}
		if (!(t0 <= t1 * (1 + 0x1p-20)))
			continue;
		if (shadow_leaf(b, leaves[i].index, leaves[i].count, &q, &tmax)) {
			struct bvh_leaf blocker = leaves[i];
			leaves[i] = leaves[0];
			leaves[0] = blocker;
			break;
		}
	}
	return q.pass;
}

bool bvh_leaves_clear(const struct bvh *b, const struct geometry *geo, const struct bvh_leaf *leaves, int n,
                      const struct bvh_region *region, uint32_t skip)
{
	for (int i = 0; i < n; i++) {
		uint32_t count = leaves[i].count;
		if (count & LEAF_PACKED)
			return false; /* its triangles are in packets, not named one by one */
		const uint32_t *ids = leaf_ids(b, leaves[i].index, count);
		for (uint32_t k = 0; k < leaf_size(count); k++) {
			uint32_t id = leaf_prim(ids, leaves[i].index, k);
			if (id == skip)
				continue;
			struct vec3 lo, hi;
			shape_bounds(geo, id, &lo, &hi);
			if (!box_outside((double[3]){ lo.x, lo.y, lo.z }, (double[3]){ hi.x, hi.y, hi.z }, region))
				return false;
		}
	}
	return true;
}
