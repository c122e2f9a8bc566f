/* pattern.c: POV-Ray's colour patterns (their values, frequency, phase and wrap), colour
 * map lookup, and the bump patterns that perturb a shading normal, on scn's noise. Read in
 * POV-Ray 3.7.0.10's pattern.cpp, texture.cpp, warps.cpp and normal.cpp; no code copied. */
#include <math.h>

#include "texture.h"

#define TWO_PI 6.283185307179586

/* POV-Ray's cycloidal, sin(2 pi v), for the noisy patterns (wood's turbulence, ripples,
 * waves), which have no exact twin: v reduced to [0, 1), folded onto [-1/4, 1/4] by the
 * sine's symmetries, and the sine's odd Taylor series to x^13 there (|x| <= pi/2: error
 * below 7e-10). Four times cheaper than libm's sin, and without it the same bits come from
 * every C library. */
static double cycloidal(double v)
{
	double t = v - floor(v);
	t = t > 0.75 ? t - 1 : t > 0.25 ? 0.5 - t : t;
	double x = t * TWO_PI, x2 = x * x;
	return x * (1 + x2 * (-1 / 6.0 + x2 * (1 / 120.0 + x2 * (-1 / 5040.0 + x2 * (1 / 362880.0 +
	       x2 * (-1 / 39916800.0 + x2 * (1 / 6227020800.0)))))));
}

/* POV-Ray's triangle wave on a wrapped value (v >= 0 here, which spares its branch for
 * negative values): up from 0 to 1 over [0, 0.5), back down over [0.5, 1). */
static double triangle_wave(double v)
{
	double offset = v - floor(v);
	return offset >= 0.5 ? 2 * (1 - offset) : 2 * offset;
}

/* The pattern's raw value at q, q already displaced by turbulence for the patterns that
 * take it so. */
static double raw_value(const struct pattern *pt, struct vec3 q)
{
	switch (pt->kind) {
	case TEXTURE_GRADIENT: {
		double d = vdot(q, pt->vector);
		return d > 1 ? fmod(d, 1) : d;        /* negative values are kept */
	}
	case TEXTURE_RADIAL:
		/* POV-Ray's: 0.25 on the y axis's neighbourhood, else 0.25..1.25, unwrapped */
		if (fabs(q.x) < 0.001 && fabs(q.z) < 0.001)
			return 0.25;
		return 0.25 + (atan2(q.x, q.z) + M_PI) / TWO_PI;
	case TEXTURE_ONION:
		return fmod(vlen(q), 1);              /* 3.7.0.10's: 0 at every whole radius */
	case TEXTURE_WOOD: {
		double x = q.x, y = q.y;
		if (pt->turbulent) {
			/* POV-Ray's wood bends its rings by the displacement through a sine of
			 * its own, in x and y only */
			struct vec3 d = noise_turbulence(q, pt->octaves, pt->omega, pt->lambda);
			x += cycloidal((q.x + d.x) * pt->turbulence.x);
			y += cycloidal((q.y + d.y) * pt->turbulence.y);
		}
		return sqrt(x * x + y * y);
	}
	case TEXTURE_MARBLE:
		return pt->turbulent ? q.x + pt->turbulence.x * noise_fbm(q, pt->octaves, pt->omega, pt->lambda)
		                     : q.x;
	case TEXTURE_LEOPARD: {
		double s = (sin(q.x) + sin(q.y) + sin(q.z)) / 3;
		return s * s;
	}
	case TEXTURE_AGATE: {
		/* always turbulent through its own scalar turbulence (agate_turb 1) */
		double t = noise_fbm(q, pt->octaves, pt->omega, pt->lambda);
		double v = 0.5 * (cycloidal(1.3 * t + 1.1 * q.z) + 1);
		return v < 0 ? 0 : pow(fmin(v, 1), 0.77);
	}
	case TEXTURE_BOZO:
	case TEXTURE_SPOTTED:                     /* POV-Ray's spotted is bozo's value */
		return noise_value(q);
	case TEXTURE_GRANITE: {
		/* six octaves of |1 - 2 noise| capped at 0.5, at 4 q doubling, weights halving */
		double v = 0, f = 1;
		for (int i = 0; i < 6; i++, f *= 2) {
			double t = fabs(1 - 2 * noise_value(vscale(q, 4 * f)));
			v += fmin(t, 0.5) / f;
		}
		return v;
	}
	default:                                  /* the bump patterns have no colour */
		return 0;
	}
}

/* POV-Ray applies a pattern's turbulence as a displacement of the point, except wood's and
 * marble's, which use it inside the pattern (agate takes both). */
static struct vec3 displaced(const struct pattern *pt, struct vec3 q)
{
	if (!pt->turbulent || pt->kind == TEXTURE_WOOD || pt->kind == TEXTURE_MARBLE)
		return q;
	return vadd(q, vmul(pt->turbulence, noise_turbulence(q, pt->octaves, pt->omega, pt->lambda)));
}

double pattern_value(const struct pattern *pt, struct vec3 q)
{
	double v = raw_value(pt, displaced(pt, q));
	/* POV-Ray's wrap: 1.00001 rather than 1, so that 1.0 stays at the top of the map */
	if (pt->frequency != 0)
		v = fmod(v * pt->frequency + pt->phase, 1.00001);
	if (v < 0)
		v -= floor(v);
	/* a value past double's range (an absurd frequency, phase or turbulence: inf, or NaN
	 * from inf - inf) has no place in the map: its start, rather than a NaN in the image */
	if (!isfinite(v))
		v = 0;
	if (pt->kind == TEXTURE_WOOD || pt->kind == TEXTURE_MARBLE)
		v = triangle_wave(v);
	return v;
}

/* POV-Ray's Search_Blend_Map: at or past the last stop its colour; else between the stop
 * before and the first stop at or past v (that stop's own colour when v is on it), so that
 * two stops at one position make a sharp edge. */
struct vec3 pattern_map(const struct pattern *pt, double v)
{
	if (pt->nmap == 0) {
		double g = v < 0 ? 0 : v > 1 ? 1 : v;
		return v3s(g);
	}
	const struct colour_stop *m = pt->map;
	uint32_t last = pt->nmap - 1;
	if (v >= m[last].position)
		return m[last].colour;
	uint32_t i = 0;
	while (v > m[i].position)
		i++;
	if (i == 0 || v == m[i].position)
		return m[i].colour;
	double w = (v - m[i - 1].position) / (m[i].position - m[i - 1].position);
	return vadd(vscale(m[i - 1].colour, 1 - w), vscale(m[i].colour, w));
}

/* POV-Ray's ripples and waves spread from 10 sources; these are scn's own (POV-Ray takes
 * its sources from its noise): a Fibonacci lattice of 10 points on the unit sphere
 * (y = 1 - (2i + 1)/10, longitude i times the golden angle), each with a frequency in
 * [0.01, 1.01) drawn from splitmix64 seeded 0x736e6e7761766573 ("snnwaves"). */
#define WAVE_SOURCES 10
static const struct {
	struct vec3 at;
	double frequency;
} wave[WAVE_SOURCES] = {
	{ { 0.43588989435406728, 0.90000000000000002, 0 }, 0.48775721491282753 },
	{ { -0.52658670682312592, 0.69999999999999996, 0.48239655906440215 }, 0.66389954497697579 },
	{ { 0.075712898549152349, 0.5, -0.86270942790332694 }, 0.61569737907030431 },
	{ { 0.58041368115321224, 0.30000000000000004, 0.75704686693108858 }, 0.34429341325246365 },
	{ { -0.97977754703832565, 0.099999999999999978, -0.17330885239814375 }, 0.42561991725021642 },
	{ { 0.83952591833052759, -0.10000000000000009, -0.53403766950589193 }, 0.44110405041271339 },
	{ { -0.24764672330212728, -0.30000000000000004, 0.92123346684633622 }, 0.51863259115473859 },
	{ { -0.39915719218447976, -0.5, -0.76855288427498736 }, 0.071851989218806631 },
	{ { 0.67080958091047793, -0.69999999999999996, 0.2449785830612729 }, 0.33227990270331254 },
	{ { -0.40291288681155957, -0.89999999999999991, 0.16631658258025742 }, 0.45790013596249135 },
};

/* ripples (waves false) and waves: a sine of the distance to each source, pushing the
 * normal along the direction from it; waves give each source its frequency and scale its
 * amplitude by 1 / frequency. */
static struct vec3 wave_sum(const struct pattern *pt, struct vec3 q, bool waves)
{
	struct vec3 r = v3s(0);
	for (int i = 0; i < WAVE_SOURCES; i++) {
		struct vec3 d = vsub(q, wave[i].at);
		double len = vlen(d);
		if (len == 0)
			len = 1;
		double f = waves ? wave[i].frequency : 1;
		double s = cycloidal(len * pt->frequency * f + pt->phase) * pt->amount / f;
		r = vmad(r, s / (len * WAVE_SOURCES), d);
	}
	return r;
}

struct vec3 pattern_bump(const struct pattern *pt, struct vec3 q)
{
	q = displaced(pt, q);
	switch (pt->kind) {
	case TEXTURE_BUMPS:
		/* the noise as a height above the surface: the normal leans down its slope */
		return vscale(noise_gradient(q), -pt->amount);
	case TEXTURE_DENTS: {
		/* bumps weighted by the cube of the noise: deep only where it is high */
		double n = noise_value(q);
		return vscale(noise_gradient(q), -pt->amount * n * n * n);
	}
	case TEXTURE_RIPPLES:
		return wave_sum(pt, q, false);
	case TEXTURE_WAVES:
		return wave_sum(pt, q, true);
	case TEXTURE_WRINKLES: {
		/* POV-Ray's: 10 octaves of the vector noise's magnitudes, each half the last */
		struct vec3 r = v3s(0);
		double s = 1;
		for (int i = 0; i < 10; i++, s *= 2)
			r = vmad(r, 1 / s, vabs(noise_vector(vscale(q, s))));
		return vscale(r, pt->amount);
	}
	default:                                  /* the colour patterns perturb nothing */
		return v3s(0);
	}
}

/* POV-Ray's rule (Warp_Normal, UnWarp_Normal): the unit normal taken into the pattern's
 * space and made unit again, the perturbation added there, the sum brought back and made
 * unit. Normals go into the pattern's space by the inverse transpose of to_pattern's linear
 * part L, whose direction is that of L's cofactor matrix times the sign of det L, and
 * come back by L's transpose. So a uniform scale of the pattern leaves the depth of its
 * bumps alone. */
struct vec3 pattern_bump_normal(const struct pattern *pt, const struct affine *to, struct vec3 q, struct vec3 n)
{
	const double (*m)[4] = to->m;
	struct vec3 r0 = v3(m[0][0], m[0][1], m[0][2]), r1 = v3(m[1][0], m[1][1], m[1][2]),
	            r2 = v3(m[2][0], m[2][1], m[2][2]);
	/* the cofactor matrix's rows are the cross products of L's rows */
	struct vec3 c0 = vcross(r1, r2), c1 = vcross(r2, r0), c2 = vcross(r0, r1);
	double sign = vdot(r0, c0) < 0 ? -1 : 1;
	struct vec3 np = vnorm(vscale(v3(vdot(c0, n), vdot(c1, n), vdot(c2, n)), sign));
	struct vec3 w = affine_normal(to, vadd(np, pattern_bump(pt, q)));
	double len = vlen(w);
	return len > 0 ? vscale(w, 1 / len) : n;  /* a bump that cancels the normal: none */
}
