/* test_texture.c: scn's noise (range, continuity, gradient, golden bits, the same bits on
 * four threads), the patterns against POV-Ray's formulas and wrap rules, colour maps, image
 * map lookups on a 3x2 image, and the UV coordinates of spheres and tori. */
#include <math.h>
#include <pthread.h>
#include <stdint.h>
#include <string.h>

#include "check.h"
#include "texture.h"

static uint64_t rng_state = 0x9e3779b97f4a7c15u;

/* A uniform double in [0, 1) (splitmix64). */
static double rnd(void)
{
	uint64_t z = (rng_state += 0x9e3779b97f4a7c15u);
	z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
	z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
	return (double)((z ^ (z >> 31)) >> 11) * 0x1p-53;
}

static struct vec3 rnd_point(double extent)
{
	return v3((rnd() - 0.5) * extent, (rnd() - 0.5) * extent, (rnd() - 0.5) * extent);
}

static void test_noise_range(void)
{
	double lo = 1, hi = 0, sum = 0;
	int n = 1000000;
	for (int i = 0; i < n; i++) {
		double v = noise_value(rnd_point(2000));
		lo = fmin(lo, v);
		hi = fmax(hi, v);
		sum += v;
	}
	CHECK(lo >= 0 && hi <= 1);
	CHECK(lo < 0.05 && hi > 0.95);          /* it spans the range */
	CHECK_NEAR(sum / n, 0.5, 0.005);
	for (int x = -3; x <= 3; x++)           /* 0.5 on the lattice, far out too */
		CHECK(noise_value(v3(x, 2 * x, -7 * x)) == 0.5 && noise_value(v3(1e12, -x, 5)) == 0.5);
}

/* |n(p + e) - n(p)| <= L |e| with L = 2 (the largest |gradient| found over 10^6 points is
 * 1.52), and the analytic gradient against central differences. */
static void test_noise_continuity(void)
{
	int lipschitz_fail = 0, gradient_fail = 0;
	for (int i = 0; i < 100000; i++) {
		struct vec3 p = rnd_point(100), e = vscale(vnorm(rnd_point(2)), 1e-4);
		if (fabs(noise_value(vadd(p, e)) - noise_value(p)) > 2 * 1e-4)
			lipschitz_fail++;
		struct vec3 g = noise_gradient(p);
		double h = 1e-5, fd[3];
		for (int k = 0; k < 3; k++) {
			struct vec3 d = v3(k == 0 ? h : 0, k == 1 ? h : 0, k == 2 ? h : 0);
			fd[k] = (noise_value(vadd(p, d)) - noise_value(vsub(p, d))) / (2 * h);
		}
		if (fabs(fd[0] - g.x) > 1e-6 || fabs(fd[1] - g.y) > 1e-6 || fabs(fd[2] - g.z) > 1e-6)
			gradient_fail++;
	}
	CHECK(lipschitz_fail == 0);
	CHECK(gradient_fail == 0);
}

static const struct vec3 golden_point[8] = {
	{ 0.53, 0.27, 0.131 }, { -1.75, 2.375, 0.0625 }, { 10.1, -3.3, 7.7 }, { 123.456, 78.9, -0.001 },
	{ -1000.23, 0.51, 333.77 }, { 0.1, 0.2, 0.3 }, { 1e6 + 0.37, -2e5 + 0.61, 0.83 }, { -0.9, -0.8, -0.7 },
};

/* At each golden point: noise, its gradient, turbulence (6 octaves, omega 0.5, lambda 2),
 * fbm, agate, granite, marble and wood with turbulence 0.6. A change of the noise shows. */
#define GOLDEN_VALUES 12
static const double golden[8][GOLDEN_VALUES] = {
	{ 0x1.514f48e1d12e2p-1, -0x1.df4c1a4e09d9ap-2, 0x1.6254cc15386fp-6, -0x1.4a2c7bd13e2f5p-4, 0x1.91b906c46fe3dp-3, -0x1.32b1da4a9568ap-2, -0x1.786a15969bbp-1,
	  0x1.2e3720d88dfc7p+0, 0x1.9303baf81f689p-4, 0x1.80652a54c1136p-2, 0x1.e80d9cec518dp-2, 0x1.0318d8c05ffap-3 },
	{ 0x1.15b5b2ac9b94p-1, -0x1.cbb7398ae72p-2, 0x1.efec608bc24p-2, -0x1.674c6d93ap-3, 0x1.d8fd22c9b94p-4, -0x1.85bfccd2148p-5, 0x1.69abc80e85c8p-1,
	  0x1.198fd22c9b94p+0, 0x1.2e57506b9714ap-1, 0x1.f7p-3, 0x1.70f73b929934p-3, 0x1.9650613248cd8p-1 },
	{ 0x1.d8a04928eacbdp-2, -0x1.102cb2dff7b3cp-4, 0x1.648c2af8f5a68p-1, -0x1.19c3df9bf2a7dp-1, -0x1.8ac054975a496p-3, -0x1.45c828ee1e19bp-2, 0x1.1a56f7bce4c2fp-2,
	  0x1.954feada296dbp-1, 0x1.2d88901e6b5ap-1, 0x1.7be9120676b0bp-1, 0x1.b353e9dd1fcdp-1, 0x1.8aae82b77303p-1 },
	{ 0x1.04ad451c63e25p-1, -0x1.cc26c50f52c6cp-3, 0x1.07ca5724921dfp-3, -0x1.469c3295b0f43p-9, 0x1.11e5bcc97d764p-5, 0x1.c24623cbe8012p-3, 0x1.a6f10c383be01p-3,
	  0x1.048f2de64bebbp+0, 0x1.ec06575850726p-1, 0x1.8bcd49b8c0968p-2, 0x1.0c10f1681c48p-3, 0x1.3615ea27fc8ap-3 },
	{ 0x1.300f56f448b2bp-1, 0x1.2c86a61915d8ap-4, -0x1.c509633deb54ep-1, -0x1.007af265c26e1p-3, -0x1.6a6c63808a4c2p-4, -0x1.24c692baabccbp-2, -0x1.1b557d54fb429p-5,
	  0x1.cab2738feeb68p-1, 0x1.f153c6924bd2cp-1, 0x1.006023d87ddd9p-2, 0x1.452570b4bfb78p-1, 0x1.3974a7018d1fp-2 },
	{ 0x1.863dc4c016ad2p-1, -0x1.8a5c158752db2p-4, 0x1.b99f7df14b4ddp-2, 0x1.31efba34f877ep-2, 0x1.4ba0802b5acc3p-1, -0x1.f70c2c4a072adp-3, -0x1.64fe8ca422bc7p-1,
	  0x1.9b927b5596b9p+0, 0x1.9666e09c0e8f7p-1, 0x1.8ed9ef2ca376ep-2, 0x1.08a6f0747c18p-3, 0x1.ac4082d6a2ca8p-1 },
	{ 0x1.9f8c2fd63074cp-2, -0x1.43eca62073894p-5, 0x1.05d081252a6bcp-1, -0x1.093b7f4756bap-3, -0x1.b7258698bd6e9p-3, -0x1.6750f46f3c518p-5, -0x1.fa89e2eeab0c2p-6,
	  0x1.8a369e59d0a46p-1, 0x1.58153967e51f4p-2, 0x1.52bb0172fadcp-2, 0x1.57ec53a46a06p-2, 0x1.4ca9f5a4923fp-1 },
	{ 0x1.0d78381982727p-1, 0x1.9648330f8a76fp-2, -0x1.058fd1d0a034p-7, -0x1.3c0c6d2447b34p-1, 0x1.1c8456833f301p-2, -0x1.618fed54b226ap-1, -0x1.fd051eac9e887p-5,
	  0x1.432115a0cfcbfp+0, 0x1.bc4af4c695fefp-3, 0x1.8597b26bb217cp-1, 0x1.242dfe95b42d4p-2, 0x1.7fec9067e97e4p-1 },
};

static double pattern_at(int kind, struct vec3 p)
{
	struct pattern pt = { .kind = (uint8_t)kind, .octaves = 6, .omega = 0.5, .lambda = 2, .frequency = 1 };
	if (kind == TEXTURE_MARBLE || kind == TEXTURE_WOOD) {
		pt.turbulent = true;
		pt.turbulence = v3s(0.6);
	}
	return pattern_value(&pt, p);
}

static void golden_values(double out[8][GOLDEN_VALUES])
{
	for (int i = 0; i < 8; i++) {
		struct vec3 p = golden_point[i];
		struct vec3 g = noise_gradient(p), t = noise_turbulence(p, 6, 0.5, 2);
		double v[GOLDEN_VALUES] = { noise_value(p), g.x, g.y, g.z, t.x, t.y, t.z,
		                            noise_fbm(p, 6, 0.5, 2), pattern_at(TEXTURE_AGATE, p),
		                            pattern_at(TEXTURE_GRANITE, p), pattern_at(TEXTURE_MARBLE, p),
		                            pattern_at(TEXTURE_WOOD, p) };
		memcpy(out[i], v, sizeof v);
	}
}

static void *thread_values(void *out)
{
	golden_values(out);
	return NULL;
}

static void test_golden(void)
{
	double mine[8][GOLDEN_VALUES];
	golden_values(mine);
	for (int i = 0; i < 8; i++)
		for (int k = 0; k < GOLDEN_VALUES; k++)
			if (mine[i][k] != golden[i][k]) {
				fprintf(stderr, "golden point %d value %d: %a, expected %a\n", i, k, mine[i][k], golden[i][k]);
				CHECK(mine[i][k] == golden[i][k]);
			}
	/* bozo and spotted are the noise itself */
	CHECK(pattern_at(TEXTURE_BOZO, golden_point[0]) == golden[0][0]);
	CHECK(pattern_at(TEXTURE_SPOTTED, golden_point[3]) == golden[3][0]);
	/* the same bits from four threads at once */
	pthread_t th[4];
	static double theirs[4][8][GOLDEN_VALUES];
	for (int t = 0; t < 4; t++)
		CHECK(pthread_create(&th[t], NULL, thread_values, theirs[t]) == 0);
	for (int t = 0; t < 4; t++) {
		pthread_join(th[t], NULL);
		CHECK(memcmp(theirs[t], mine, sizeof mine) == 0);
	}
}

static double value(int kind, struct vec3 q, double frequency, double phase)
{
	struct pattern pt = { .kind = (uint8_t)kind, .vector = v3(0, 1, 0), .frequency = frequency,
	                      .phase = phase, .octaves = 6, .omega = 0.5, .lambda = 2 };
	return pattern_value(&pt, q);
}

/* povray-equivalence.md 15 and POV-Ray 3.7.0.10's pattern.cpp, point by point. */
static void test_analytic_patterns(void)
{
	/* gradient <0, 1, 0>: d > 1 -> fmod(d, 1), then fmod(v F + phase, 1.00001) */
	CHECK(value(TEXTURE_GRADIENT, v3(9, 0.25, 9), 1, 0) == 0.25);
	CHECK(value(TEXTURE_GRADIENT, v3(0, 1, 0), 1, 0) == 1);            /* 1.0 stays on top */
	CHECK(value(TEXTURE_GRADIENT, v3(0, 1.5, 0), 1, 0) == 0.5);
	CHECK(value(TEXTURE_GRADIENT, v3(0, 3, 0), 1, 0) == 0);
	CHECK(value(TEXTURE_GRADIENT, v3(0, -0.25, 0), 1, 0) == 0.75);     /* negatives kept, then wrapped */
	double w = fmod(-1.25, 1.00001);                                    /* -0.24999: the drift */
	CHECK(value(TEXTURE_GRADIENT, v3(0, -1.25, 0), 1, 0) == w - floor(w));
	CHECK(value(TEXTURE_GRADIENT, v3(0, 0.3, 0), 2, 0.1) == fmod(0.3 * 2 + 0.1, 1.00001));
	CHECK(value(TEXTURE_GRADIENT, v3(0, 0.9, 0), 1.5, 0) == fmod(0.9 * 1.5, 1.00001));
	CHECK(value(TEXTURE_GRADIENT, v3(0, 0.9, 0), -1, 0) == 1 + fmod(-0.9, 1.00001));
	/* frequency 0 skips phase and wrap, not the lift of a negative value */
	CHECK(value(TEXTURE_GRADIENT, v3(0, 0.5, 0), 0, 0.3) == 0.5);
	CHECK(value(TEXTURE_GRADIENT, v3(0, -0.25, 0), 0, 0.3) == 0.75);
	CHECK(value(TEXTURE_RADIAL, v3(0, 0, -1), 0, 0) == 1.25);

	/* radial: 0.25 + (atan2(x, z) + pi) / 2 pi in [0.25, 1.25], 0.25 near the y axis */
	CHECK(value(TEXTURE_RADIAL, v3(0, 0, 1), 0, 0) == 0.75);
	CHECK(value(TEXTURE_RADIAL, v3(1, 0, 0), 0, 0) == 1);
	CHECK(value(TEXTURE_RADIAL, v3(0.0009, 5, -0.0009), 0, 0) == 0.25);
	CHECK(value(TEXTURE_RADIAL, v3(-1, 0, 0), 0, 0) == 0.5);
	CHECK(value(TEXTURE_RADIAL, v3(0, 0, -1), 1, 0) == fmod(1.25, 1.00001));
	double lo = 2, hi = -1;
	for (int i = 0; i < 1000; i++) {
		double v = value(TEXTURE_RADIAL, rnd_point(10), 0, 0);
		lo = fmin(lo, v);
		hi = fmax(hi, v);
	}
	CHECK(lo >= 0.25 && hi <= 1.25 && lo < 0.26 && hi > 1.24);

	/* onion: fmod(|q|, 1) */
	CHECK(value(TEXTURE_ONION, v3(0.3, 0.4, 0), 1, 0) == fmod(sqrt(0.3 * 0.3 + 0.4 * 0.4), 1));
	CHECK(value(TEXTURE_ONION, v3(3, 4, 0), 1, 0) == 0);
	CHECK(value(TEXTURE_ONION, v3(1, 2, 2), 2, 0.25) == 0.25);

	/* wood: |(x, y)| through the triangle wave; marble: x so */
	CHECK(value(TEXTURE_WOOD, v3(0.3, 0.4, 7), 1, 0) == 1);             /* 0.5: the peak */
	CHECK(value(TEXTURE_WOOD, v3(0.15, 0.2, -3), 1, 0) == 0.5);
	CHECK(value(TEXTURE_WOOD, v3(0.6, 0.8, 0), 1, 0) == 0);             /* 1.0: back at 0 */
	CHECK(value(TEXTURE_MARBLE, v3(0.25, 5, 5), 1, 0) == 0.5);
	CHECK(value(TEXTURE_MARBLE, v3(-0.25, 5, 5), 1, 0) == 0.5);         /* 0.75 -> 0.5 */
	CHECK(value(TEXTURE_MARBLE, v3(-0.1, 0, 0), 1, 0) == 2 * (1 - (-0.1 - floor(-0.1))));
	CHECK(value(TEXTURE_MARBLE, v3(0.1, 0, 0), 2, 0.05) == 2 * fmod(0.25, 1.00001));

	/* leopard: ((sin x + sin y + sin z) / 3)^2 */
	CHECK(value(TEXTURE_LEOPARD, v3(0, 0, 0), 1, 0) == 0);
	double s = (sin(0.5) + sin(1.5) + sin(-2.5)) / 3;
	CHECK(value(TEXTURE_LEOPARD, v3(0.5, 1.5, -2.5), 1, 0) == fmod(s * s, 1.00001));
	CHECK_NEAR(value(TEXTURE_LEOPARD, v3(M_PI / 2, M_PI / 2, M_PI / 2), 0, 0), 1, 1e-15);

	/* turbulence displaces the point by turbulence * noise_turbulence, except in wood and
	 * marble; the noise patterns stay in [0, 1] */
	struct pattern bozo = { .kind = TEXTURE_BOZO, .turbulent = true, .turbulence = v3(0.5, 0.25, 1),
	                        .frequency = 1, .octaves = 3, .omega = 0.6, .lambda = 2.5 };
	struct vec3 q = v3(1.3, -2.7, 0.4);
	double n = noise_value(vadd(q, vmul(bozo.turbulence, noise_turbulence(q, 3, 0.6, 2.5))));
	CHECK(pattern_value(&bozo, q) == fmod(n, 1.00001));
	for (int kind = TEXTURE_GRADIENT; kind <= TEXTURE_SPOTTED; kind++)
		for (int i = 0; i < 2000; i++) {
			double v = pattern_at(kind, rnd_point(50));
			CHECK(v >= 0 && v < 1.00001);
		}
}

static void test_colour_map(void)
{
	static const struct colour_stop stops[] = {
		{ 0.2, { 1, 0, 0 } }, { 0.5, { 0, 1, 0 } }, { 0.5, { 0, 0, 1 } }, { 1, { 1, 1, 1 } },
	};
	struct pattern pt = { .map = stops, .nmap = 4 };
	struct vec3 c = pattern_map(&pt, 0.35);                            /* halfway, red to green */
	CHECK_NEAR(c.x, 0.5, 1e-15);
	CHECK_NEAR(c.y, 0.5, 1e-15);
	CHECK(c.x + c.y == 1 && c.z == 0);
	c = pattern_map(&pt, 0.1);                                          /* before the first stop */
	CHECK(c.x == 1 && c.y == 0 && c.z == 0);
	c = pattern_map(&pt, 0.5);                                          /* on a double stop: the first */
	CHECK(c.x == 0 && c.y == 1 && c.z == 0);
	c = pattern_map(&pt, 0.75);                                         /* past it: from the second */
	CHECK(c.x == 0.5 && c.y == 0.5 && c.z == 1);
	c = pattern_map(&pt, 1);
	CHECK(c.x == 1 && c.y == 1 && c.z == 1);
	c = pattern_map(&pt, 1.000005);                                     /* the wrap's top */
	CHECK(c.x == 1 && c.y == 1 && c.z == 1);
	struct pattern grey = { .nmap = 0 };
	c = pattern_map(&grey, 0.3);
	CHECK(c.x == 0.3 && c.y == 0.3 && c.z == 0.3);
	CHECK(pattern_map(&grey, 1.2).x == 1 && pattern_map(&grey, -0.5).x == 0);
}

/* A 3 x 2 image: texel (x, y) is (x, y, 10 x + y), row 0 at the top. */
static float texels[2 * 3 * 3];
static struct image img = { .width = 3, .height = 2, .rgb = texels };

static bool lookup(uint8_t map, bool bilinear, bool once, struct vec3 q, struct vec3 *c)
{
	struct image_map im = { .image = &img, .map = map, .bilinear = bilinear, .once = once };
	return image_map_lookup(&im, q, c);
}

static bool is_texel(struct vec3 c, int x, int y, double tol)
{
	return fabs(c.x - x) <= tol && fabs(c.y - y) <= tol && fabs(c.z - (10 * x + y)) <= tol;
}

static void test_image_map(void)
{
	for (int y = 0; y < 2; y++)
		for (int x = 0; x < 3; x++) {
			float *t = texels + 3 * (y * 3 + x);
			t[0] = (float)x;
			t[1] = (float)y;
			t[2] = (float)(10 * x + y);
		}
	struct vec3 c;
	/* planar: column x W, row H (1 - y); texel centres give the texel, nearest exactly,
	 * bilinear within POV-Ray's 1e-10 offset */
	for (int y = 0; y < 2; y++)
		for (int x = 0; x < 3; x++) {
			struct vec3 q = v3((x + 0.5) / 3, 1 - (y + 0.5) / 2, 7);
			CHECK(lookup(TEXTURE_MAP_PLANAR, false, false, q, &c) && is_texel(c, x, y, 0));
			CHECK(lookup(TEXTURE_MAP_PLANAR, true, false, q, &c) && is_texel(c, x, y, 1e-8));
			CHECK(lookup(TEXTURE_MAP_PLANAR, true, true, q, &c) && is_texel(c, x, y, 1e-8));
			CHECK(lookup(TEXTURE_MAP_UV, false, true, q, &c) && is_texel(c, x, y, 0));
			/* repeats: one image further on in x, two down in y */
			CHECK(lookup(TEXTURE_MAP_PLANAR, false, false, vadd(q, v3(1, -2, 0)), &c) && is_texel(c, x, y, 0));
		}
	/* bilinear halfway between the centres of columns 0 and 1 in the top row */
	CHECK(lookup(TEXTURE_MAP_PLANAR, true, false, v3(1.0 / 3, 0.75, 0), &c));
	CHECK_NEAR(c.x, 0.5, 1e-8);
	CHECK_NEAR(c.z, 5, 1e-8);
	/* left of column 0's centre: wraps to column 2, or with once stays on column 0 */
	CHECK(lookup(TEXTURE_MAP_PLANAR, true, false, v3(0.5 / 6, 0.75, 0), &c));
	CHECK_NEAR(c.x, 0.5, 1e-8);                                         /* 3/4 of 0, 1/4 of 2 */
	CHECK(lookup(TEXTURE_MAP_PLANAR, true, true, v3(0.5 / 6, 0.75, 0), &c));
	CHECK_NEAR(c.x, 0, 1e-8);
	/* once: outside the unit square nothing; x = 1 is column 0 as in POV-Ray */
	CHECK(!lookup(TEXTURE_MAP_PLANAR, false, true, v3(1.2, 0.5, 0), &c));
	CHECK(!lookup(TEXTURE_MAP_PLANAR, false, true, v3(-0.01, 0.5, 0), &c));
	CHECK(!lookup(TEXTURE_MAP_PLANAR, false, true, v3(0.5, 1.01, 0), &c));
	CHECK(lookup(TEXTURE_MAP_PLANAR, false, true, v3(1, 0.75, 0), &c) && is_texel(c, 0, 0, 0));
	CHECK(lookup(TEXTURE_MAP_PLANAR, false, false, v3(1.2, 0.75, 0), &c) && is_texel(c, 0, 0, 0));
	/* spherical: the angle from +x towards +z, the latitude from the bottom */
	CHECK(lookup(TEXTURE_MAP_SPHERICAL, false, false, v3(2, 0.1, 0), &c) && is_texel(c, 0, 0, 0));
	CHECK(lookup(TEXTURE_MAP_SPHERICAL, false, false, v3(0, -0.1, 2), &c) && is_texel(c, 0, 1, 0));
	CHECK(lookup(TEXTURE_MAP_SPHERICAL, false, false, v3(-2, 0.1, 0), &c) && is_texel(c, 1, 0, 0));
	CHECK(lookup(TEXTURE_MAP_SPHERICAL, false, false, v3(0, 0.1, -2), &c) && is_texel(c, 2, 0, 0));
	CHECK(!lookup(TEXTURE_MAP_SPHERICAL, false, false, v3(0, 0, 0), &c));
	/* cylindrical: the same angle, y repeating with the height; once tests y only */
	CHECK(lookup(TEXTURE_MAP_CYLINDRICAL, false, false, v3(1, 0.25, 0), &c) && is_texel(c, 0, 1, 0));
	CHECK(lookup(TEXTURE_MAP_CYLINDRICAL, false, false, v3(0, 0.75, 1), &c) && is_texel(c, 0, 0, 0));
	CHECK(lookup(TEXTURE_MAP_CYLINDRICAL, false, false, v3(0, 1.75, -1), &c) && is_texel(c, 2, 0, 0));
	CHECK(lookup(TEXTURE_MAP_CYLINDRICAL, false, true, v3(-5, 0.75, 0), &c) && is_texel(c, 1, 0, 0));
	CHECK(!lookup(TEXTURE_MAP_CYLINDRICAL, false, true, v3(1, 1.5, 0), &c));
	CHECK(!lookup(TEXTURE_MAP_CYLINDRICAL, false, false, v3(0, 0.5, 0), &c));   /* on the axis */
}

static void test_uv(void)
{
	double u, v;
	texture_uv_sphere(v3(2, 0, 0), &u, &v);
	CHECK(u == 0 && v == 0.5);
	texture_uv_sphere(v3(0, 0, 3), &u, &v);
	CHECK(u == 0.25 && v == 0.5);
	texture_uv_sphere(v3(-1, 0, 0), &u, &v);
	CHECK(u == 0.5);
	texture_uv_sphere(v3(0, 0, -1), &u, &v);
	CHECK(u == 0.75);
	texture_uv_sphere(v3(1, 0, -1e-3), &u, &v);                         /* the seam */
	CHECK_NEAR(u, 1 - 1e-3 / (2 * M_PI), 1e-9);
	texture_uv_sphere(v3(1, 0, -1e-9), &u, &v);                         /* acos rounds to 1 */
	CHECK(u == 1);
	texture_uv_sphere(v3(0, 5, 0), &u, &v);                             /* the poles */
	CHECK(u == 0 && v == 1);
	texture_uv_sphere(v3(0, -5, 0), &u, &v);
	CHECK(u == 0 && v == 0);
	texture_uv_sphere(v3(1e-6, -5, 1e-6), &u, &v);                      /* POV-Ray's pole test */
	CHECK(u == 0 && v < 1e-6);
	texture_uv_sphere(v3(1, 1, 0), &u, &v);
	CHECK_NEAR(v, 0.75, 1e-15);
	texture_uv_sphere(v3(0, 0, 0), &u, &v);
	CHECK(u == 0 && v == 0);

	/* torus, major radius 2: u = 1 - (atan2(z, x) + pi) / 2 pi, v around the tube */
	texture_uv_torus(v3(2.5, 0, 0), 2, &u, &v);
	CHECK(u == 0.5 && v == 0.5);
	texture_uv_torus(v3(2, 0.5, 0), 2, &u, &v);
	CHECK(v == 0.75);
	texture_uv_torus(v3(2, -0.5, 0), 2, &u, &v);
	CHECK(v == 0.25);
	texture_uv_torus(v3(1.5, 0, 0), 2, &u, &v);                         /* inner equator: the seam */
	CHECK(v == 1);
	texture_uv_torus(v3(1.5, -0.0, 0), 2, &u, &v);                     /* atan2's -pi */
	CHECK(v == 0);
	texture_uv_torus(v3(1.5, -1e-12, 0), 2, &u, &v);
	CHECK(v < 1e-12);
	texture_uv_torus(v3(0, 0, 2.5), 2, &u, &v);
	CHECK(u == 0.25);
	texture_uv_torus(v3(-2.5, 0, 0), 2, &u, &v);
	CHECK(u == 0);
	texture_uv_torus(v3(-2.5, 0, -1e-12), 2, &u, &v);
	CHECK(u > 0.999999 && u <= 1);
}

static void test_bumps(void)
{
	struct pattern pt = { .kind = TEXTURE_BUMPS, .amount = 0.6, .frequency = 1, .to_pattern = affine_identity };
	struct vec3 q = v3(0.37, 1.21, -2.9), g = noise_gradient(q);
	struct vec3 b = pattern_bump(&pt, q);
	CHECK(b.x == -0.6 * g.x && b.y == -0.6 * g.y && b.z == -0.6 * g.z);
	pt.kind = TEXTURE_DENTS;
	double n = noise_value(q);
	CHECK(pattern_bump(&pt, q).x == -0.6 * n * n * n * g.x);
	/* ripples and waves: bounded by the amount (waves by amount / their least frequency) */
	for (int i = 0; i < 1000; i++) {
		struct vec3 p = rnd_point(20);
		pt.kind = TEXTURE_RIPPLES;
		CHECK(vlen(pattern_bump(&pt, p)) <= 0.6 + 1e-12);
		pt.kind = TEXTURE_WAVES;
		CHECK(vlen(pattern_bump(&pt, p)) <= 0.6 / 0.07 + 1e-12);
		pt.kind = TEXTURE_WRINKLES;
		b = pattern_bump(&pt, p);
		CHECK(b.x >= 0 && b.y >= 0 && b.z >= 0 && vmaxc(b) <= 0.6 * 2);
	}
	/* a colour pattern perturbs nothing */
	pt.kind = TEXTURE_BOZO;
	CHECK(vzero(pattern_bump(&pt, q)));

	/* POV-Ray's rule: a uniform scale of the pattern leaves the bumps' depth alone; a
	 * rotation turns the perturbation with it */
	pt.kind = TEXTURE_BUMPS;
	struct vec3 nrm = vnorm(v3(0.2, 1, -0.3));
	struct vec3 plain = pattern_bump_normal(&pt, &pt.to_pattern, q, nrm);
	struct vec3 want = vnorm(vadd(nrm, pattern_bump(&pt, q)));
	CHECK_NEAR(vlen(vsub(plain, want)), 0, 1e-15);
	pt.to_pattern = (struct affine){ { { 10, 0, 0, 3 }, { 0, 10, 0, -1 }, { 0, 0, 10, 2 } } };
	struct vec3 scaled = pattern_bump_normal(&pt, &pt.to_pattern, q, nrm);
	CHECK_NEAR(vlen(vsub(scaled, want)), 0, 1e-14);
	pt.to_pattern = (struct affine){ { { 0, -1, 0, 0 }, { 1, 0, 0, 0 }, { 0, 0, 1, 0 } } };
	struct vec3 turned = pattern_bump_normal(&pt, &pt.to_pattern, q, nrm);
	want = vnorm(vadd(nrm, affine_normal(&pt.to_pattern, pattern_bump(&pt, q))));
	CHECK_NEAR(vlen(vsub(turned, want)), 0, 1e-15);
	/* a mirror keeps the normal on its side */
	pt.to_pattern = (struct affine){ { { -1, 0, 0, 0 }, { 0, 1, 0, 0 }, { 0, 0, 1, 0 } } };
	pt.amount = 0;
	struct vec3 same = pattern_bump_normal(&pt, &pt.to_pattern, q, nrm);
	CHECK_NEAR(vlen(vsub(same, nrm)), 0, 1e-15);
}

int main(void)
{
	test_noise_range();
	test_noise_continuity();
	test_golden();
	test_analytic_patterns();
	test_colour_map();
	test_image_map();
	test_uv();
	test_bumps();
	return check_result();
}
