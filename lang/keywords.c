/* keywords.c: spelling of the reserved words, looked up in a hash table: every name in
 * a scene is looked up, millions of them in a large one. */
#include "keywords.h"

#include <stdbool.h>
#include <stdint.h>
#include <string.h>

/* ORDER KEYWORDS */
static const char *const names[KW_COUNT_ALL] = {
	"let", "include", "for", "in", "camera", "light", "material", "sphere",
	"plane", "triangle", "mesh", "skybox", "samples", "max_depth",
	"box", "cylinder", "cone", "disc", "torus",
	"union", "merge", "intersection", "difference",
	"if", "else", "def", "fog",
	"and", "or", "not", "true", "false",
	"location", "look_at", "up", "fov", "resolution", "position", "direction",
	"color", "intensity", "shadowless", "like", "diffuse", "specular", "shininess",
	"reflect", "transmit", "ior", "fresnel", "emit", "translate", "rotate", "scale",
	"smooth", "vertices", "faces", "normals", "zenith", "horizon", "image", "count",
	"pattern", "seed", "target_error", "open", "inverse", "inside_vector",
	"frequency", "phase", "turbulence", "octaves", "omega", "lambda", "colors", "map",
	"interpolate", "once", "normal", "uvs", "fade_distance", "fade_power",
	"spotlight", "point_at", "falloff", "tightness",
	"orthographic", "width", "distance",
	"area", "jitter", "circular", "orient", "aperture", "focal_point",
};

enum { TABLE_SIZE = 512 }; /* a power of two, over five times the keyword count */

static signed char table[TABLE_SIZE]; /* keyword code + 1, or 0 for an empty slot */
static bool filled;

/* FNV-1a over the n bytes of s */
static uint32_t hash(const char *s, unsigned n)
{
	uint32_t h = 2166136261u;
	for (unsigned i = 0; i < n; i++)
		h = (h ^ (unsigned char)s[i]) * 16777619u;
	return h;
}

int kw_lookup(const char *s, unsigned n)
{
	if (!filled) { /* first call; the front end runs on one thread */
		for (int i = 0; i < KW_COUNT_ALL; i++) {
			uint32_t k = hash(names[i], (unsigned)strlen(names[i]));
			while (table[k & (TABLE_SIZE - 1)])
				k++;
			table[k & (TABLE_SIZE - 1)] = (signed char)(i + 1);
		}
		filled = true;
	}
	for (uint32_t k = hash(s, n);; k++) {
		int code = table[k & (TABLE_SIZE - 1)] - 1;
		if (code < 0)
			return -1;
		if (strncmp(names[code], s, n) == 0 && names[code][n] == '\0')
			return code;
	}
}

const char *kw_name(enum kw k)
{
	return names[k];
}
