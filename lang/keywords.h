/* keywords.h: the reserved words of the scene language (LANGUAGE.md sections 2, 5, 9, 10, 11 and 12). */
#ifndef SCN_KEYWORDS_H
#define SCN_KEYWORDS_H

#include <stdbool.h>

/* ORDER KEYWORDS: keep in step with names[] in keywords.c. */
enum kw {
	/* statements */
	KW_LET, KW_INCLUDE, KW_FOR, KW_IN, KW_CAMERA, KW_LIGHT, KW_MATERIAL, KW_SPHERE,
	KW_PLANE, KW_TRIANGLE, KW_MESH, KW_SKYBOX, KW_SAMPLES, KW_MAX_DEPTH,
	KW_BOX, KW_CYLINDER, KW_CONE, KW_DISC, KW_TORUS,
	KW_UNION, KW_MERGE, KW_INTERSECTION, KW_DIFFERENCE,   /* ORDER CSG: as enum csg_op */
	KW_IF, KW_ELSE, KW_DEF, KW_FOG,
	/* operators and constants */
	KW_AND, KW_OR, KW_NOT, KW_TRUE, KW_FALSE,
	/* attributes */
	KW_LOCATION, KW_LOOK_AT, KW_UP, KW_FOV, KW_RESOLUTION, KW_POSITION, KW_DIRECTION,
	KW_COLOR, KW_INTENSITY, KW_SHADOWLESS, KW_LIKE, KW_DIFFUSE, KW_SPECULAR, KW_SHININESS,
	KW_REFLECT, KW_TRANSMIT, KW_IOR, KW_FRESNEL, KW_EMIT, KW_TRANSLATE, KW_ROTATE, KW_SCALE,
	KW_SMOOTH, KW_VERTICES, KW_FACES, KW_NORMALS, KW_ZENITH, KW_HORIZON, KW_IMAGE, KW_COUNT,
	KW_PATTERN, KW_SEED, KW_TARGET_ERROR, KW_OPEN, KW_INVERSE, KW_INSIDE_VECTOR,
	KW_FREQUENCY, KW_PHASE, KW_TURBULENCE, KW_OCTAVES, KW_OMEGA, KW_LAMBDA, KW_COLORS, KW_MAP,
	KW_INTERPOLATE, KW_ONCE, KW_NORMAL, KW_UVS, KW_FADE_DISTANCE, KW_FADE_POWER,
	KW_SPOTLIGHT, KW_POINT_AT, KW_FALLOFF, KW_TIGHTNESS,
	KW_ORTHOGRAPHIC, KW_WIDTH, KW_DISTANCE,
	KW_AREA, KW_JITTER, KW_CIRCULAR, KW_ORIENT, KW_APERTURE, KW_FOCAL_POINT,
	KW_COUNT_ALL
};

/* The statements that make an object: a shape, a mesh or a CSG (LANGUAGE.md 5 and 9). */
static inline bool kw_is_object(int k)
{
	return k == KW_SPHERE || k == KW_PLANE || k == KW_TRIANGLE || k == KW_MESH || (k >= KW_BOX && k <= KW_DIFFERENCE);
}

/* The attributes that take no value. */
static inline bool kw_is_flag(int k)
{
	return k == KW_SHADOWLESS || k == KW_FRESNEL || k == KW_SMOOTH || k == KW_OPEN || k == KW_INVERSE || k == KW_ONCE ||
	       k == KW_ORTHOGRAPHIC || k == KW_JITTER || k == KW_CIRCULAR || k == KW_ORIENT;
}

static inline bool kw_is_csg(int k)
{
	return k >= KW_UNION && k <= KW_DIFFERENCE;
}

/* The keyword spelt s[0, n), or -1. */
int kw_lookup(const char *s, unsigned n);
const char *kw_name(enum kw k);

#endif
