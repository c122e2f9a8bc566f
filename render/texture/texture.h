/* texture.h: what a surface's colour and shading normal vary with (LANGUAGE.md section 11):
 * scn's own gradient noise and turbulence, POV-Ray's patterns and their colour maps, image
 * maps with their planar, spherical, cylindrical and UV lookups, and the bump patterns that
 * perturb a shading normal. Everything here is a pure function of its arguments, evaluated
 * in double, so that a point gives the same bits on every thread and every build. */
#ifndef SCN_TEXTURE_H
#define SCN_TEXTURE_H

#include <stdbool.h>
#include <stdint.h>

#include "affine.h"
#include "image.h"
#include "vec.h"

/* ORDER TEXTURE_PATTERN: as lang's enum pattern_name (lower.c maps one to the other). */
enum texture_pattern {
	TEXTURE_GRADIENT, TEXTURE_RADIAL, TEXTURE_ONION, TEXTURE_WOOD, TEXTURE_MARBLE, TEXTURE_LEOPARD,
	TEXTURE_AGATE, TEXTURE_BOZO, TEXTURE_GRANITE, TEXTURE_SPOTTED,
	TEXTURE_BUMPS, TEXTURE_DENTS, TEXTURE_RIPPLES, TEXTURE_WAVES, TEXTURE_WRINKLES,
};

struct colour_stop {
	double position;               /* rising, in [0, 1] */
	struct vec3 colour;
};

/* A pattern and its parameters, as LANGUAGE.md section 11 and POV-Ray define them. */
struct pattern {
	uint8_t kind;                  /* enum texture_pattern */
	bool turbulent;                /* turbulence is not zero */
	bool moved;                    /* to_pattern is not the identity */
	struct vec3 vector;            /* gradient: unit */
	double amount;                 /* a bump pattern's depth */
	double frequency, phase;
	struct vec3 turbulence;
	int octaves;
	double omega, lambda;
	const struct colour_stop *map; /* nmap stops; nmap 0: black at 0 to white at 1 */
	uint32_t nmap;
	struct affine to_pattern;      /* the object's own space -> the pattern's */
};

/* scn's gradient noise at p: Perlin's improved noise (2002) over scn's own permutation,
 * scaled into [0, 1], 0.5 on every lattice point; continuous, and C1 but where rare
 * extrema are clamped into [0, 1] (doc/noise.md). */
double noise_value(struct vec3 p);
/* The noise's gradient at p (the derivative of noise_value). */
struct vec3 noise_gradient(struct vec3 p);
/* A vector noise: each component 2 noise_value - 1 (in [-1, 1], 0 on average) at p plus an
 * offset of its own, the role POV-Ray's DNoise plays. */
struct vec3 noise_vector(struct vec3 p);
/* POV-Ray's DTurbulence on noise_vector: the sum over octaves i = 1..octaves of
 * omega^(i-1) noise_vector(lambda^(i-1) p), a displacement that pattern_value scales by
 * pt->turbulence and adds to q when pt->turbulent (wood has its own use of it). */
struct vec3 noise_turbulence(struct vec3 p, int octaves, double omega, double lambda);
/* POV-Ray's scalar Turbulence (marble's and agate's): clamp(2 noise - 0.5, 0, 1) at p plus
 * omega^(i-1) (2 noise(lambda^(i-1) p) - 0.5) for octaves i = 2..octaves. */
double noise_fbm(struct vec3 p, int octaves, double omega, double lambda);

/* The value of a colour pattern at q, a point in the pattern's space (after to_pattern):
 * turbulence, the pattern, then frequency, phase and POV-Ray's wrap, in [0, 1]. */
double pattern_value(const struct pattern *pt, struct vec3 q);
/* The colour of map at v (pattern_value's result): linear between stops, the end stops'
 * colours beyond them. */
struct vec3 pattern_map(const struct pattern *pt, double v);
/* The shading normal's perturbation at q (pattern space) for a bump pattern: a vector in
 * pattern space to be mapped to world space as a normal is (the transpose of the map from
 * world to pattern space) and added to the unit shading normal before renormalising. */
struct vec3 pattern_bump(const struct pattern *pt, struct vec3 q);
/* The unit shading normal that POV-Ray's rule gives n (a unit normal in the space that
 * `to` maps into the pattern's: pt->to_pattern, or it after the object's own map) under
 * pt's bumps at q (pattern space): n taken into the pattern's space and normalised,
 * pattern_bump added, the sum brought back and normalised. Unlike adding pattern_bump
 * mapped back to n, it leaves the bumps' depth alone when the pattern or the object is
 * scaled (`normal { bumps 0.6  scale 0.1 }` is as deep as without the scale). */
struct vec3 pattern_bump_normal(const struct pattern *pt, const struct affine *to, struct vec3 q, struct vec3 n);

/* Image maps: map_type 0, 1, 2 and uv_mapping. */
enum texture_map { TEXTURE_MAP_PLANAR, TEXTURE_MAP_SPHERICAL, TEXTURE_MAP_CYLINDRICAL, TEXTURE_MAP_UV };

struct image_map {
	const struct image *image;     /* shared by every image_map of the same file */
	uint8_t map;                   /* enum texture_map */
	bool bilinear, once, moved;
	struct affine to_pattern;      /* the object's own space -> the image's */
};

/* The texel colour of im at q (the image's space; for TEXTURE_MAP_UV q.x, q.y are u, v),
 * as POV-Ray's image_map (povray-equivalence.md section 15): false when `once` puts q
 * outside the image (the caller then uses the default diffuse). */
bool image_map_lookup(const struct image_map *im, struct vec3 q, struct vec3 *colour);

/* POV-Ray's uv_mapping of a sphere (p relative to its centre) and of a torus (p in its own
 * space, major radius R about the y axis): u and v in [0, 1]. */
void texture_uv_sphere(struct vec3 p, double *u, double *v);
void texture_uv_torus(struct vec3 p, double major, double *u, double *v);

#endif
