/* test_light.c: the area light's weights and test points (render/light.c) against POV-Ray's
 * rule, the region their tests share a walk of the tree over, the spotlight factor, and
 * the sample streams (render/stream.c) that jittered lights and the lens draw from: range,
 * stratification over a pixel's samples, independence of cells and dimensions,
 * determinism, and the disc. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "light.h"
#include "stream.h"

/* POV-Ray's recursion as its trace.cpp writes it, in two dimensions at once, crediting the
 * weight each corner ends with: an independent statement of the rule that
 * light_area_weights factors into one axis at a time. */
static void pov_recursion(int u1, int v1, int u2, int v2, double share, int n2, double *w)
{
	if (u2 - u1 > 1 || v2 - v1 > 1) {
		int um = (int)floor((u1 + u2) / 2.0), uc = (int)ceil((u1 + u2) / 2.0);
		int vm = (int)floor((v1 + v2) / 2.0), vc = (int)ceil((v1 + v2) / 2.0);
		pov_recursion(u1, v1, um, vm, share / 4, n2, w);
		pov_recursion(uc, v1, u2, vm, share / 4, n2, w);
		pov_recursion(u1, vc, um, v2, share / 4, n2, w);
		pov_recursion(uc, vc, u2, v2, share / 4, n2, w);
		return;
	}
	w[u1 * n2 + v1] += share / 4;
	w[u2 * n2 + v1] += share / 4;
	w[u1 * n2 + v2] += share / 4;
	w[u2 * n2 + v2] += share / 4;
}

static void test_weights(void)
{
	double w[AREA_MAX];
	light_area_weights(1, w);
	CHECK(w[0] == 1);
	light_area_weights(3, w);
	CHECK(w[0] == 0.25 && w[1] == 0.5 && w[2] == 0.25);
	light_area_weights(5, w);
	CHECK(w[0] == 0.125 && w[1] == 0.25 && w[2] == 0.25 && w[3] == 0.25 && w[4] == 0.125);
	static const int uniform[] = { 2, 4, 8, 16, 32, 64 };
	for (size_t k = 0; k < sizeof uniform / sizeof uniform[0]; k++) {
		light_area_weights(uniform[k], w);
		for (int i = 0; i < uniform[k]; i++)
			CHECK(w[i] == 1.0 / uniform[k]);
	}
	for (int n = 1; n <= AREA_MAX; n++) {
		light_area_weights(n, w);
		double sum = 0;
		for (int i = 0; i < n; i++) {
			CHECK(w[i] >= 0);
			sum += w[i];
		}
		CHECK_NEAR(sum, 1, 1e-15);
	}
	/* the product of the axes' weights is POV-Ray's two-dimensional recursion */
	static double grid[AREA_MAX * AREA_MAX];
	double w1[AREA_MAX], w2[AREA_MAX];
	for (int n1 = 1; n1 <= 13; n1++)
		for (int n2 = 1; n2 <= 13; n2++) {
			memset(grid, 0, sizeof grid);
			pov_recursion(0, 0, n1 - 1, n2 - 1, 1, n2, grid);
			light_area_weights(n1, w1);
			light_area_weights(n2, w2);
			for (int u = 0; u < n1; u++)
				for (int v = 0; v < n2; v++)
					CHECK_NEAR(w1[u] * w2[v], grid[u * n2 + v], 1e-15);
		}
}

static void test_offsets(void)
{
	struct area_light a = { .axis = { { 2, 0, 0 }, { 0, 0, 4 } }, .size = { 3, 5 }, .inv_span = { 0.5, 0.25 } };
	struct vec3 axes[2];
	light_area_axes(&a, v3(0, 1, 0), axes);
	struct vec3 o = light_area_offset(&a, axes, 0, 0);
	CHECK(o.x == -1 && o.y == 0 && o.z == -2);
	o = light_area_offset(&a, axes, 2, 4);
	CHECK(o.x == 1 && o.z == 2);
	o = light_area_offset(&a, axes, 1, 1);
	CHECK(o.x == 0 && o.z == -1);
	/* one point along an axis: no extent there */
	a.size[1] = 1;
	a.inv_span[1] = 0;
	o = light_area_offset(&a, axes, 2, 0);
	CHECK(o.x == 1 && o.z == 0);
	/* circular: the corner of the square pulled in onto the circle, 0.001 off centre */
	a.size[1] = 3;
	a.inv_span[1] = 0.5;
	a.circular = true;
	o = light_area_offset(&a, axes, 0, 0);
	double c = -0.499 / sqrt(2.0);
	CHECK_NEAR(o.x, 2 * c, 1e-15);
	CHECK_NEAR(o.z, 4 * c, 1e-15);
	o = light_area_offset(&a, axes, 1, 1);   /* the middle, POV-Ray's 0.001 off */
	CHECK_NEAR(o.x, 2 * 0.001 / sqrt(2.0), 1e-15);
	/* orient: square to the direction of the light, both axes as long as the first */
	a.orient = true;
	struct vec3 l = vunit(v3(1, 2, 3));
	light_area_axes(&a, l, axes);
	CHECK_NEAR(vdot(axes[0], l), 0, 1e-15);
	CHECK_NEAR(vdot(axes[1], l), 0, 1e-15);
	CHECK_NEAR(vdot(axes[0], axes[1]), 0, 1e-15);
	CHECK_NEAR(vlen(axes[0]), 2, 1e-15);
	CHECK_NEAR(vlen(axes[1]), 2, 1e-15);
	light_area_axes(&a, v3(0, 0, -1), axes);  /* along z: y takes z's place */
	CHECK_NEAR(vlen(axes[0]), 2, 1e-15);
	CHECK_NEAR(vlen(axes[1]), 2, 1e-15);
}

/* Every point of every test's segment, from the apex to a test point anywhere its jitter
 * may put it, lies inside the region the tests share their walk over; a point beyond the
 * light or off to the side does not. Over random lights, apexes and the three layouts. */
static void test_region(void)
{
	uint64_t k = 12345;
	for (int trial = 0; trial < 2000; trial++) {
		double r[12];
		for (int i = 0; i < 12; i++) {
			k = k * 6364136223846793005u + 1442695040888963407u;
			r[i] = (double)(k >> 11) * 0x1.0p-53 * 2 - 1;
		}
		struct area_light a = { .axis = { v3(r[0] * 3, r[1], r[2]), v3(r[3], r[4] * 3, r[5]) },
		                        .size = { 2 + trial % 7, 2 + trial % 5 }, .jitter = trial % 2,
		                        .circular = trial % 3 == 0, .orient = trial % 6 == 0 };
		for (int i = 0; i < 2; i++)
			a.inv_span[i] = 1.0 / (a.size[i] - 1);
		struct vec3 centre = v3(r[6] * 10, 5 + r[7], r[8] * 10), apex = v3(r[9] * 4, r[10], r[11] * 4);
		struct vec3 axes[2];
		light_area_axes(&a, vunit(vsub(centre, apex)), axes);
		struct bvh_region region;
		struct vec3 corner[4];
		if (!light_area_region(&a, axes, centre, apex, 1e-9, &region, corner))
			continue; /* the light's plane through the apex: no bounded region */
		for (int s = 0; s < 50; s++) {
			/* grid corners, and the jitter's farthest reach */
			double u = (s % 5 == 0) ? -0.5 : (s % 5 == 1) ? a.size[0] - 0.5 : (s * 0.37) - floor(s * 0.37);
			double v = (s % 7 == 0) ? -0.5 : (s % 7 == 1) ? a.size[1] - 0.5 : (s * 0.61) - floor(s * 0.61);
			if (!a.jitter) {
				u = fmin(fmax(u, 0), a.size[0] - 1);
				v = fmin(fmax(v, 0), a.size[1] - 1);
			}
			struct vec3 q = vadd(centre, light_area_offset(&a, axes, u, v));
			for (int t = 0; t <= 4; t++) {
				struct vec3 x = vadd(apex, vscale(vsub(q, apex), t / 4.0));
				for (int pl = 0; pl < region.nplanes; pl++) {
					const double *pp = region.plane[pl];
					CHECK(pp[0] * x.x + pp[1] * x.y + pp[2] * x.z <= pp[3] + 1e-9);
				}
			}
		}
		/* past the light's plane, and far off to the side of the pyramid */
		struct vec3 beyond = vadd(centre, vscale(vsub(centre, apex), 0.5));
		struct vec3 side = vadd(apex, vscale(vcross(vsub(centre, apex), vadd(axes[0], axes[1])), 100));
		bool out_beyond = false, out_side = false;
		for (int pl = 0; pl < region.nplanes; pl++) {
			const double *pp = region.plane[pl];
			out_beyond |= pp[0] * beyond.x + pp[1] * beyond.y + pp[2] * beyond.z > pp[3];
			out_side |= pp[0] * side.x + pp[1] * side.y + pp[2] * side.z > pp[3];
		}
		CHECK(out_beyond);
		CHECK(out_side);
	}
}

static void test_spot(void)
{
	struct light li = { .axis = { 0, -1, 0 }, .tightness = 0 };
	li.cos_radius = cos(10 * M_PI / 180);
	li.cos_falloff = cos(20 * M_PI / 180);
	CHECK(light_spot(&li, v3(0, 1, 0)) == 1);
	double c = cos(15 * M_PI / 180), s = (c - li.cos_falloff) / (li.cos_radius - li.cos_falloff);
	CHECK_NEAR(light_spot(&li, v3(sin(15 * M_PI / 180), c, 0)), s * s * (3 - 2 * s), 1e-15);
	CHECK(light_spot(&li, v3(sin(25 * M_PI / 180), cos(25 * M_PI / 180), 0)) == 0);
	CHECK(light_spot(&li, v3(0, -1, 0)) == 0);
}

/* Over a pixel's count samples, the points of one dimension and cell: each of count equal
 * slices of u, and of v, holds one (a power-of-two count: the Sobol set is a (0,m,2)-net,
 * which its Owen scramble and the shuffle of its order keep). */
static void test_strata(uint32_t count, uint64_t dim, uint32_t cell, bool boxes)
{
	int *su = calloc(count, sizeof *su), *sv = calloc(count, sizeof *sv), *sb = calloc(count, sizeof *sb);
	uint32_t side = (uint32_t)sqrt((double)count);
	for (uint32_t px = 0; px < 5; px++) {
		memset(su, 0, count * sizeof *su);
		memset(sv, 0, count * sizeof *sv);
		memset(sb, 0, count * sizeof *sb);
		struct sample_stream s = { stream_pixel_key(7, px, 3, 0), 0, count, false };
		for (uint32_t i = 0; i < count; i++) {
			s.index = i;
			struct stream_dim d;
			double u, v;
			stream_dim(&s, dim, &d);
			stream_point(&d, cell, &u, &v);
			CHECK(u > 0 && u < 1 && v > 0 && v < 1);
			su[(int)(u * count)]++;
			sv[(int)(v * count)]++;
			sb[(int)(u * side) * side + (int)(v * side)]++;
		}
		for (uint32_t k = 0; k < count; k++) {
			CHECK(su[k] == 1);
			CHECK(sv[k] == 1);
			if (boxes)
				CHECK(sb[k] == 1);
		}
	}
	free(su);
	free(sv);
	free(sb);
}

/* The correlation over many pixels of the u of two cells, or of two dimensions, of one
 * sample: near 0 (1 / sqrt(n) is 0.0025 here). */
static double correlation(uint64_t dim_a, uint32_t cell_a, uint64_t dim_b, uint32_t cell_b)
{
	double sa = 0, sb = 0, sab = 0, saa = 0, sbb = 0;
	int n = 0;
	for (uint32_t px = 0; px < 10000; px++)
		for (uint32_t i = 0; i < 16; i++) {
			struct sample_stream s = { stream_pixel_key(1, px, 0, 0), i, 16, false };
			struct stream_dim da, db;
			double ua, va, ub, vb;
			stream_dim(&s, dim_a, &da);
			stream_dim(&s, dim_b, &db);
			stream_point(&da, cell_a, &ua, &va);
			stream_point(&db, cell_b, &ub, &vb);
			sa += ua;
			sb += ub;
			sab += ua * ub;
			saa += ua * ua;
			sbb += ub * ub;
			n++;
		}
	double cov = sab / n - (sa / n) * (sb / n);
	return cov / sqrt((saa / n - (sa / n) * (sa / n)) * (sbb / n - (sb / n) * (sb / n)));
}

static void test_streams(void)
{
	test_strata(16, 0, 0, true);
	test_strata(64, 12345, 7, true);
	test_strata(256, 99, 4095, true);
	test_strata(32, 5, 1, false);
	CHECK(fabs(correlation(3, 0, 3, 1)) < 0.01);  /* two cells of an area light */
	CHECK(fabs(correlation(0, 0, 3, 0)) < 0.01);  /* the lens and an area light */
	/* the same key, the same numbers; another replica, others */
	struct sample_stream s = { stream_pixel_key(9, 4, 5, 0), 3, 16, false }, r = s;
	r.key = stream_pixel_key(9, 4, 5, 1);
	struct stream_dim d1, d2, d3;
	double u1, v1, u2, v2, u3, v3;
	stream_dim(&s, 42, &d1);
	stream_dim(&s, 42, &d2);
	stream_dim(&r, 42, &d3);
	stream_point(&d1, 5, &u1, &v1);
	stream_point(&d2, 5, &u2, &v2);
	stream_point(&d3, 5, &u3, &v3);
	CHECK(u1 == u2 && v1 == v2);
	CHECK(u1 != u3 && v1 != v3);
	/* the random pattern's numbers: uniform, unstratified, still in range */
	s.independent = true;
	double mean = 0;
	for (uint32_t i = 0; i < 100000; i++) {
		s.index = i;
		stream_dim(&s, 1, &d1);
		stream_point(&d1, 0, &u1, &v1);
		CHECK(u1 > 0 && u1 < 1 && v1 > 0 && v1 < 1);
		mean += u1 + v1;
	}
	CHECK_NEAR(mean / 200000, 0.5, 0.003);
}

/* The concentric map: inside the disc, onto its rim from the square's edge, and keeping
 * area: a quarter of the square's area lands in each quarter of the disc's, and the share
 * within radius 1/2 is 1/4. */
static void test_disc(void)
{
	double x, y;
	stream_disc(0.5, 0.5, &x, &y);
	CHECK(x == 0 && y == 0);
	stream_disc(1, 0.5, &x, &y);
	CHECK_NEAR(x, 1, 1e-15);
	CHECK_NEAR(y, 0, 1e-15);
	int inner = 0, quadrant = 0, n = 0;
	for (int i = 0; i < 200; i++)
		for (int j = 0; j < 200; j++) {
			stream_disc((i + 0.5) / 200, (j + 0.5) / 200, &x, &y);
			CHECK(x * x + y * y <= 1 + 1e-12);
			inner += x * x + y * y < 0.25;
			quadrant += x > 0 && y > 0;
			n++;
		}
	CHECK_NEAR((double)inner / n, 0.25, 0.01);
	CHECK_NEAR((double)quadrant / n, 0.25, 0.01);
}

int main(void)
{
	test_weights();
	test_offsets();
	test_region();
	test_spot();
	test_streams();
	test_disc();
	return check_result();
}
