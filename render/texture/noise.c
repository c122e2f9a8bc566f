/* noise.c: scn's own gradient noise (Ken Perlin's improved noise, 2002, over a permutation
 * of our own), its analytic gradient, and POV-Ray's two turbulences (a displacement vector
 * and a scalar sum) built on it. doc/noise.md says what it is and why it is not POV-Ray's. */
#include <math.h>
#include <stdint.h>

#include "texture.h"

/* The lattice hash: a permutation of 0..255, drawn by Fisher-Yates (for i from 255 down to
 * 1: j = splitmix64() % (i + 1), swap entries i and j) from splitmix64 seeded with
 * 0x73636e6e6f697365 ("scnnoise"). A literal, so that it is the same on every build and
 * needs no initialisation; a change of it changes every noisy image (the unit tests hold
 * golden values). */
static const uint8_t perm[256] = {
	229, 236, 218, 164, 160, 104,  67,  96, 176,  82, 146,  66, 161,  94, 239,  40,
	197, 153,  75,  60, 249,  30, 188, 121,  45, 172,  58, 167, 118,  42, 131, 102,
	255, 250,   7, 163, 150,  10,  84,  44, 251, 213,  64,  55, 193, 171,  59, 122,
	143,   3, 162,  62,  76,  78,  28, 168, 183, 190,  48,  22, 177, 184, 169, 245,
	 93, 234,  49,  61,  71,  23, 247, 129, 112,  89, 216,  50, 182, 219,  69,  24,
	 18,   8,  36,  83, 105, 215,  41, 201, 253,  98, 144, 198,  32, 194, 228, 117,
	174, 217, 178,  39, 199,  73, 186,  26, 202, 200, 136,  87, 130,  12, 126,  47,
	231,  19,  74, 159,  29,  95, 141, 114,   6, 113,   0, 233, 195, 100, 225, 124,
	 57,  68,  25,  34,  70, 221,   9, 138, 242, 196, 241,  97,  14, 205, 211, 212,
	223, 103,  86, 240,  79, 152, 237,  20, 142, 156, 208,  51, 209, 140,  16, 151,
	139, 125, 175, 222, 101,  91, 137, 224, 155,  37, 204,  11,  52, 123,  38, 119,
	181, 254, 149, 252,  56, 107,  53, 192, 165,  92, 185, 226, 243, 248, 135, 246,
	157,   1,  99, 127,   4,  88, 207, 232, 170, 158, 230, 134,  46, 110, 191, 227,
	 35,  15,  43,  17, 179,  31, 116,  72, 203, 206, 166,  63, 238, 132,  85, 111,
	145, 154, 187,  80, 235,   5, 128, 173, 214,  54,  81,  77, 148, 189,  13, 133,
	220, 109, 244, 210, 180,   2,  27, 147,  65, 106,  90,  21, 108, 115, 120,  33,
};

/* Perlin's 12 gradients, the midpoints of a cube's edges: no axis is preferred, and a dot
 * product with one is two additions (products by 0 and 1 are exact). A corner picks one
 * by its hash modulo 12 (256 = 21 * 12 + 4: four of them are 1/21 likelier, where
 * Perlin's hash & 15 doubles four). */
static const double grad[12][3] = {
	{ 1, 1, 0 }, { -1, 1, 0 }, { 1, -1, 0 }, { -1, -1, 0 },
	{ 1, 0, 1 }, { -1, 0, 1 }, { 1, 0, -1 }, { -1, 0, -1 },
	{ 0, 1, 1 }, { 0, -1, 1 }, { 0, 1, -1 }, { 0, -1, -1 },
};

/* Each hash's gradient, hash % 12, as a table: a load where the division by 12 took a
 * multiplication, a shift and a subtraction per corner. */
#define MOD12(h) ((h) % 12)
#define MOD12_16(b) MOD12(b), MOD12(b + 1), MOD12(b + 2), MOD12(b + 3), MOD12(b + 4), MOD12(b + 5), \
	MOD12(b + 6), MOD12(b + 7), MOD12(b + 8), MOD12(b + 9), MOD12(b + 10), MOD12(b + 11), MOD12(b + 12), \
	MOD12(b + 13), MOD12(b + 14), MOD12(b + 15)
static const uint8_t grad_of[256] = {
	MOD12_16(0), MOD12_16(16), MOD12_16(32), MOD12_16(48), MOD12_16(64), MOD12_16(80), MOD12_16(96),
	MOD12_16(112), MOD12_16(128), MOD12_16(144), MOD12_16(160), MOD12_16(176), MOD12_16(192), MOD12_16(208),
	MOD12_16(224), MOD12_16(240),
};
#undef MOD12_16
#undef MOD12

/* The value is 0.5 + NOISE_SCALE * raw noise, clamped into [0, 1]. The raw noise has a
 * standard deviation of 0.27 and stays within +-1 but for tiny regions around rare
 * extrema (a search by gradient ascent from 2 10^5 points found 1.029; none of 10^7
 * random points passed 0.995): there the clamp flattens the noise, which stays continuous
 * (and its gradient is 0). The spread is close to POV-Ray's default noise (a standard
 * deviation of 0.135 in [0, 1] against its 0.126), so that twins look alike. */
#define NOISE_SCALE 0.5

/* noise_vector's second and third components pick their corners' gradients by the hash
 * of the first mixed once more through perm (with these salts), so that the three share one
 * lattice walk and fade yet are unrelated. */
#define VECTOR_SALT_1 0x5a
#define VECTOR_SALT_2 0xc3

/* The lattice cell of f = floor(x) modulo 256. Every double of magnitude 2^62 or more is a
 * multiple of 1024 (cell 0), and below that the conversion is exact. */
static inline unsigned cell(double f)
{
	return fabs(f) < 0x1p62 ? (unsigned)((uint64_t)(int64_t)f & 255) : 0;
}

/* Perlin's quintic fade 6t^5 - 15t^4 + 10t^3 and its derivative 30t^2(t - 1)^2: C2 at the
 * lattice, so that the noise's gradient is continuous. */
static inline double fade(double t) { return t * t * t * (t * (t * 6 - 15) + 10); }
static inline double fade_slope(double t) { return 30 * t * t * (t - 1) * (t - 1); }

static inline double lerp(double t, double a, double b) { return a + t * (b - a); }

/* One lattice cube around p: the fractions of p in it and its 8 corners' hashes, corner c
 * at bit 0 = x, bit 1 = y, bit 2 = z. A corner's gradient is grad[grad_of[hash]]. */
struct cube {
	double fx, fy, fz;
	uint8_t h[8];
};

static inline void cube_at(struct vec3 p, struct cube *c)
{
	double xf = floor(p.x), yf = floor(p.y), zf = floor(p.z);
	unsigned x = cell(xf), y = cell(yf), z = cell(zf);
	c->fx = p.x - xf;
	c->fy = p.y - yf;
	c->fz = p.z - zf;
	unsigned a = perm[x], b = perm[(x + 1) & 255];
	unsigned h[4] = { perm[(a + y) & 255], perm[(b + y) & 255], perm[(a + y + 1) & 255],
	                  perm[(b + y + 1) & 255] };
	for (int i = 0; i < 4; i++) {
		c->h[i] = perm[(h[i] + z) & 255];
		c->h[i + 4] = perm[(h[i] + z + 1) & 255];
	}
}

/* The gradient index of corner hash h for the component that salt names (0: the first). */
static inline unsigned gradient_of(uint8_t h, unsigned salt)
{
	return grad_of[salt ? perm[h ^ salt] : h];
}

/* The raw noise of one component: the corners' dots (gradients chosen by salt: 0 for the
 * first component, else the hash mixed through perm with it) blended by the fades u, v, w.
 * Written out corner by corner: as a loop, GCC kept the corner number a variable; and
 * always inlined, with salt a constant (GCC called it, 14% of a textured scene's time). */
static inline __attribute__((always_inline)) double blend(const struct cube *c, unsigned salt, double u, double v,
                                                          double w)
{
	double x0 = c->fx, y0 = c->fy, z0 = c->fz, x1 = x0 - 1, y1 = y0 - 1, z1 = z0 - 1;
	const double *g;
#define DOT(i, x, y, z) (g = grad[gradient_of(c->h[i], salt)], g[0] * (x) + g[1] * (y) + g[2] * (z))
	double n0 = DOT(0, x0, y0, z0), n1 = DOT(1, x1, y0, z0), n2 = DOT(2, x0, y1, z0), n3 = DOT(3, x1, y1, z0);
	double n4 = DOT(4, x0, y0, z1), n5 = DOT(5, x1, y0, z1), n6 = DOT(6, x0, y1, z1), n7 = DOT(7, x1, y1, z1);
#undef DOT
	return lerp(w, lerp(v, lerp(u, n0, n1), lerp(u, n2, n3)), lerp(v, lerp(u, n4, n5), lerp(u, n6, n7)));
}

static inline double clamp01(double v) { return v < 0 ? 0 : v > 1 ? 1 : v; }

double noise_value(struct vec3 p)
{
	struct cube c;
	cube_at(p, &c);
	return clamp01(0.5 + NOISE_SCALE * blend(&c, 0, fade(c.fx), fade(c.fy), fade(c.fz)));
}

/* The derivative of the trilinear blend of the corners' linear functions: the blend's
 * weights' derivatives times the corner values, plus the blend of the corner gradients;
 * 0 where noise_value is clamped. */
struct vec3 noise_gradient(struct vec3 p)
{
	struct cube c;
	cube_at(p, &c);
	double x0 = c.fx, y0 = c.fy, z0 = c.fz, x1 = x0 - 1, y1 = y0 - 1, z1 = z0 - 1;
	double u = fade(x0), v = fade(y0), w = fade(z0);
	const double *g[8];
	for (int i = 0; i < 8; i++)
		g[i] = grad[grad_of[c.h[i]]];
#define DOT(i, x, y, z) (g[i][0] * (x) + g[i][1] * (y) + g[i][2] * (z))
	double n0 = DOT(0, x0, y0, z0), n1 = DOT(1, x1, y0, z0), n2 = DOT(2, x0, y1, z0), n3 = DOT(3, x1, y1, z0);
	double n4 = DOT(4, x0, y0, z1), n5 = DOT(5, x1, y0, z1), n6 = DOT(6, x0, y1, z1), n7 = DOT(7, x1, y1, z1);
#undef DOT
	double k0 = lerp(u, n0, n1), k1 = lerp(u, n2, n3), k2 = lerp(u, n4, n5), k3 = lerp(u, n6, n7);
	double l0 = lerp(v, k0, k1), l1 = lerp(v, k2, k3);
	if (fabs(NOISE_SCALE * lerp(w, l0, l1)) > 0.5)
		return v3(0, 0, 0);
	double d[3];
	for (int k = 0; k < 3; k++)
		d[k] = lerp(w, lerp(v, lerp(u, g[0][k], g[1][k]), lerp(u, g[2][k], g[3][k])),
		               lerp(v, lerp(u, g[4][k], g[5][k]), lerp(u, g[6][k], g[7][k])));
	d[0] += fade_slope(x0) * lerp(w, lerp(v, n1 - n0, n3 - n2), lerp(v, n5 - n4, n7 - n6));
	d[1] += fade_slope(y0) * lerp(w, k1 - k0, k3 - k2);
	d[2] += fade_slope(z0) * (l1 - l0);
	return v3(NOISE_SCALE * d[0], NOISE_SCALE * d[1], NOISE_SCALE * d[2]);
}

/* Each component 2 n - 1 = 2 NOISE_SCALE raw, clamped as noise_value clamps. */
struct vec3 noise_vector(struct vec3 p)
{
	struct cube c;
	cube_at(p, &c);
	double u = fade(c.fx), v = fade(c.fy), w = fade(c.fz);
	return v3(2 * clamp01(0.5 + NOISE_SCALE * blend(&c, 0, u, v, w)) - 1,
	          2 * clamp01(0.5 + NOISE_SCALE * blend(&c, VECTOR_SALT_1, u, v, w)) - 1,
	          2 * clamp01(0.5 + NOISE_SCALE * blend(&c, VECTOR_SALT_2, u, v, w)) - 1);
}

/* POV-Ray's DTurbulence: octave 1 at weight 1, octave i at frequency lambda^(i-1) and
 * weight omega^(i-1). */
struct vec3 noise_turbulence(struct vec3 p, int octaves, double omega, double lambda)
{
	struct vec3 r = noise_vector(p);
	double l = lambda, o = omega;
	for (int i = 2; i <= octaves; i++) {
		r = vmad(r, o, noise_vector(vscale(p, l)));
		l *= lambda;
		o *= omega;
	}
	return r;
}

/* POV-Ray's Turbulence with its default noise generator (2): the first octave's
 * 2 n - 0.5 clamped into [0, 1], then each further octave's 2 n - 0.5 unclamped. */
double noise_fbm(struct vec3 p, int octaves, double omega, double lambda)
{
	double r = clamp01(2 * noise_value(p) - 0.5);
	double l = lambda, o = omega;
	for (int i = 2; i <= octaves; i++) {
		r += o * (2 * noise_value(vscale(p, l)) - 0.5);
		l *= lambda;
		o *= omega;
	}
	return r;
}
