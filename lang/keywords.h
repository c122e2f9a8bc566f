/* keywords.h: the reserved words of the scene language (LANGUAGE.md sections 2 and 5). */
#ifndef SCN_KEYWORDS_H
#define SCN_KEYWORDS_H

/* ORDER KEYWORDS: keep in step with keyword_names in keywords.c (sorted there by name). */
enum kw {
	/* statements */
	KW_LET, KW_INCLUDE, KW_FOR, KW_IN, KW_CAMERA, KW_LIGHT, KW_MATERIAL, KW_SPHERE,
	KW_PLANE, KW_TRIANGLE, KW_MESH, KW_SKYBOX, KW_SAMPLES, KW_MAX_DEPTH,
	/* attributes */
	KW_LOCATION, KW_LOOK_AT, KW_UP, KW_FOV, KW_RESOLUTION, KW_POSITION, KW_DIRECTION,
	KW_COLOR, KW_INTENSITY, KW_SHADOWLESS, KW_LIKE, KW_DIFFUSE, KW_SPECULAR, KW_SHININESS,
	KW_REFLECT, KW_TRANSMIT, KW_IOR, KW_FRESNEL, KW_EMIT, KW_TRANSLATE, KW_ROTATE, KW_SCALE,
	KW_SMOOTH, KW_VERTICES, KW_FACES, KW_NORMALS, KW_ZENITH, KW_HORIZON, KW_IMAGE, KW_COUNT,
	KW_PATTERN, KW_SEED, KW_TARGET_ERROR,
	KW_COUNT_ALL
};

/* The keyword spelt s[0, n), or -1. */
int kw_lookup(const char *s, unsigned n);
const char *kw_name(enum kw k);

#endif
