/* tri_packet.c: the four-lane watertight triangle test (see tri_packet.h), in GCC's
 * generic vectors of four doubles: one AVX instruction a step where there is AVX, two
 * SSE2 ones otherwise. Every lane is tested against the tmax the packet starts with; the
 * lanes are then taken in order, each accepted against tmax as the lanes before it left
 * it, which is what testing them one after another gives (a tmax that falls only rejects
 * more). */
#include "tri_packet.h"

#include <string.h>
#ifdef __AVX__
#include <immintrin.h>
#endif

#include "v4d.h"

/* these functions return a v4d: see v4d.h */
#pragma GCC diagnostic ignored "-Wpsabi"

static inline v4d v4d_load(const double p[PACKET_LANES])
{
	v4d a;
	memcpy(&a, p, sizeof a);
	return a;
}

static inline v4d v4d_set(double x)
{
	return (v4d){ x, x, x, x };
}

/* bit c set when lane c of the mask m is set; a macro, as a function taking m would
 * pass a vector by value */
#ifdef __AVX__
#define LANE_BITS(m) _mm256_movemask_pd((__m256d)(m))
#else
#define LANE_BITS(m) ((int)(((m)[0] & 1) | ((m)[1] & 2) | ((m)[2] & 4) | ((m)[3] & 8)))
#endif

/* max_abs3() of triangle.c over the three vectors of v, lane by lane: the same comparisons,
 * so the same choices */
static inline v4d lanes_max_abs3(const v4d v[3])
{
	v4d a = V4D_ABS(v[0]), b = V4D_ABS(v[1]), c = V4D_ABS(v[2]);
	v4l ab = a > b;
	v4d m = (v4d)((ab & (v4l)a) | (~ab & (v4l)b));
	v4l mc = m > c;
	return (v4d)((mc & (v4l)m) | (~mc & (v4l)c));
}

void tri_packet_fill(struct tri_packet *pk, const struct geometry *geo, uint32_t first, uint32_t n)
{
	memset(pk, 0, sizeof *pk);
	pk->lanes = n;
	for (uint32_t l = 0; l < PACKET_LANES; l++) {
		/* an unused lane repeats lane 0, which keeps its arithmetic finite */
		uint32_t k = first + (l < n ? l : 0);
		pk->tri[l] = k;
		for (int v = 0; v < 3; v++)
			for (int a = 0; a < 3; a++)
				pk->p[v][a][l] = vget(&geo->vertices[geo->triangles[k].v[v]], a);
	}
}

/* What the vector pass leaves for the lanes taken in order. */
struct lanes {
	int hit;      /* lanes hit at some t in (0, tmax) */
	int on_edge;  /* lanes left to triangle_intersect() */
	double det[PACKET_LANES], tscaled[PACKET_LANES], t[PACKET_LANES], b1[PACKET_LANES], b2[PACKET_LANES];
};

/* triangle_intersect()'s arithmetic in each lane, with h->t = tmax; it stops, as the scalar
 * test does, once no lane is left (most packets a ray reaches miss at the edge
 * functions). */
static inline __attribute__((always_inline)) void test_lanes(const struct tri_packet *pk, const struct triangle_ray *tr,
                                                             double tmax, struct lanes *out)
{
	int kx = tr->k[0], ky = tr->k[1], kz = tr->k[2];
	v4d ox = v4d_set(vget(&tr->o, kx)), oy = v4d_set(vget(&tr->o, ky)), oz = v4d_set(vget(&tr->o, kz));
	v4d x[3], y[3], z[3];
#pragma GCC unroll 3 /* kept in registers, where the rolled loop spilled them */
	for (int v = 0; v < 3; v++) {
		x[v] = v4d_load(pk->p[v][kx]) - ox;
		y[v] = v4d_load(pk->p[v][ky]) - oy;
		z[v] = v4d_load(pk->p[v][kz]) - oz;
		x[v] += tr->sx * z[v];
		y[v] += tr->sy * z[v];
	}
	v4d e[3] = { x[1] * y[2] - y[1] * x[2], x[2] * y[0] - y[2] * x[0], x[0] * y[1] - y[0] * x[1] };
	v4d e0 = e[0], e1 = e[1], e2 = e[2];
	const v4d zero = v4d_set(0);
	int used = (1 << pk->lanes) - 1;
	out->on_edge = LANE_BITS((e0 == zero) | (e1 == zero) | (e2 == zero)) & used;
	v4l straddle = ((e0 < zero) | (e1 < zero) | (e2 < zero)) & ((e0 > zero) | (e1 > zero) | (e2 > zero));
	out->hit = ~LANE_BITS(straddle) & ~out->on_edge & used;
	if (!out->hit)
		return;
	v4d det = e0 + e1 + e2;
	for (int v = 0; v < 3; v++)
		z[v] *= tr->sz;
	v4d tscaled = e0 * z[0] + e1 * z[1] + e2 * z[2];
	out->hit &= ~LANE_BITS((det == zero) | TRIANGLE_T_OUTSIDE(det, tscaled, tmax * det, zero));
	if (!out->hit)
		return;
	v4d inv = 1 / det;
	v4d t = tscaled * inv;
	v4d max_x = lanes_max_abs3(x), max_y = lanes_max_abs3(y), max_z = lanes_max_abs3(z);
	v4d delta_t = TRIANGLE_DELTA_T(max_x, max_y, max_z, lanes_max_abs3(e), V4D_ABS(inv));
	out->hit &= LANE_BITS((t > delta_t) & (t < tmax));
	if (!out->hit)
		return;
	v4d b1 = e1 * inv, b2 = e2 * inv;
	memcpy(out->det, &det, sizeof det);
	memcpy(out->tscaled, &tscaled, sizeof tscaled);
	memcpy(out->t, &t, sizeof t);
	memcpy(out->b1, &b1, sizeof b1);
	memcpy(out->b2, &b2, sizeof b2);
}

bool tri_packet_intersect(const struct tri_packet *pk, const struct geometry *geo, const struct triangle_ray *tr,
                          struct hit *h)
{
	struct lanes ln;
	test_lanes(pk, tr, h->t, &ln);
	bool found = false;
	for (int todo = ln.hit | ln.on_edge; todo; todo &= todo - 1) {
		int l = __builtin_ctz((unsigned)todo);
		uint32_t k = pk->tri[l];
		if (ln.on_edge >> l & 1) {
			if (!triangle_intersect(tr, &geo->triangles[k], geo->vertices, h))
				continue;
		} else {
			/* accepted against the tmax the lanes before left */
			if (TRIANGLE_T_OUTSIDE(ln.det[l], ln.tscaled[l], h->t * ln.det[l], 0.0) || !(ln.t[l] < h->t))
				continue;
			h->t = ln.t[l];
			h->b1 = ln.b1[l];
			h->b2 = ln.b2[l];
		}
		h->prim = shape_id(SHAPE_TRIANGLE, k);
		found = true;
	}
	return found;
}

struct vec3 tri_packet_filter(const struct tri_packet *pk, const struct geometry *geo, const struct triangle_ray *tr,
                              double tmax, struct vec3 pass)
{
	struct lanes ln;
	test_lanes(pk, tr, tmax, &ln);
	for (int todo = ln.hit | ln.on_edge; todo; todo &= todo - 1) {
		int l = __builtin_ctz((unsigned)todo);
		uint32_t k = pk->tri[l];
		struct hit h = { .t = tmax };
		if ((ln.on_edge >> l & 1) && !triangle_intersect(tr, &geo->triangles[k], geo->vertices, &h))
			continue;
		pass = vmul(pass, shape_transmit(geo, geo->triangles[k].surface));
		if (vzero(pass))
			break;
	}
	return pass;
}
