/* keywords.c: spelling of the reserved words, looked up by binary search. */
#include "keywords.h"

#include <stdlib.h>
#include <string.h>

/* ORDER KEYWORDS */
static const char *const names[KW_COUNT_ALL] = {
	"let", "include", "for", "in", "camera", "light", "material", "sphere",
	"plane", "triangle", "mesh", "skybox", "samples", "max_depth",
	"location", "look_at", "up", "fov", "resolution", "position", "direction",
	"color", "intensity", "shadowless", "like", "diffuse", "specular", "shininess",
	"reflect", "transmit", "ior", "fresnel", "emit", "translate", "rotate", "scale",
	"smooth", "vertices", "faces", "normals", "zenith", "horizon", "image", "count",
	"pattern", "seed", "target_error",
};

static unsigned char sorted[KW_COUNT_ALL]; /* keyword codes in the order of their names */
static int nsorted;

static int by_name(const void *a, const void *b)
{
	return strcmp(names[*(const unsigned char *)a], names[*(const unsigned char *)b]);
}

int kw_lookup(const char *s, unsigned n)
{
	if (!nsorted) { /* first call; the front end runs on one thread */
		for (int i = 0; i < KW_COUNT_ALL; i++)
			sorted[i] = (unsigned char)i;
		qsort(sorted, KW_COUNT_ALL, 1, by_name);
		nsorted = KW_COUNT_ALL;
	}
	int lo = 0, hi = nsorted - 1;
	while (lo <= hi) {
		int mid = (lo + hi) / 2;
		const char *name = names[sorted[mid]];
		int c = strncmp(s, name, n);
		if (c == 0)
			c = name[n] ? -1 : 0;
		if (c == 0)
			return sorted[mid];
		if (c < 0)
			hi = mid - 1;
		else
			lo = mid + 1;
	}
	return -1;
}

const char *kw_name(enum kw k)
{
	return names[k];
}
