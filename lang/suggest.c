/* suggest.c: what a message adds to a name that means nothing: the closest known name
 * ("did you mean"), or what scn writes for a word POV-Ray users bring along. */
#include "suggest.h"

#include <stdio.h>
#include <string.h>

/* Edit distance (with a swap of two neighbours as one edit), for "did you mean"; gives up
 * (returns limit + 1) beyond limit. */
static unsigned edit_distance(const char *a, const char *b, unsigned limit)
{
	size_t la = strlen(a), lb = strlen(b);
	if (la > 64 || lb > 64 || (la > lb ? la - lb : lb - la) > limit)
		return limit + 1;
	unsigned rows[3][65], *older = rows[0], *prev = rows[1], *row = rows[2];
	for (size_t j = 0; j <= lb; j++)
		prev[j] = (unsigned)j;
	for (size_t i = 1; i <= la; i++) {
		row[0] = (unsigned)i;
		for (size_t j = 1; j <= lb; j++) {
			unsigned best = prev[j - 1] + (a[i - 1] != b[j - 1]);
			if (prev[j] + 1 < best)
				best = prev[j] + 1;
			if (row[j - 1] + 1 < best)
				best = row[j - 1] + 1;
			/* two letters swapped ("aera" for "area") are one slip */
			if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] && older[j - 2] + 1 < best)
				best = older[j - 2] + 1;
			row[j] = best;
		}
		unsigned *t = older;
		older = prev;
		prev = row;
		row = t;
	}
	return prev[lb];
}

void suggest_init(struct suggestion *s, const char *name)
{
	size_t len = strlen(name);
	s->name = name;
	s->best = NULL;
	/* the most edits still worth suggesting: none for one or two letters ('r' is not 'i') */
	s->dist = len <= 2 ? 0 : len <= 4 ? 1 : len <= 8 ? 2 : 3;
	s->dist++;
}

void suggest_consider(struct suggestion *s, const char *candidate)
{
	unsigned d = edit_distance(s->name, candidate, s->dist - 1);
	if (d < s->dist) {
		s->dist = d;
		s->best = candidate;
	}
}

/* "; did you mean 'x'?" or "" */
const char *suggest_text(const struct suggestion *s, char *buf, size_t size)
{
	if (!s->best)
		return "";
	snprintf(buf, size, "; did you mean '%s'?", s->best);
	return buf;
}

/* POV-Ray's words that users bring along, with what scn writes instead. */
static const char *const pov_words[][2] = {
	{ "light_source", "scn writes light { position P  color C }" },
	{ "background", "scn writes skybox { color C }" },
	{ "sky_sphere", "scn writes skybox { zenith C  horizon C } or skybox { image \"FILE\" }" },
	{ "global_settings", "scn writes max_depth N and samples { ... } as statements" },
	{ "max_trace_level", "scn writes max_depth N" },
	{ "smooth_triangle", "scn writes mesh { vertices { ... } faces { ... } normals { ... } smooth }" },
	{ "mesh2", "scn writes mesh { vertices { ... } faces { ... } }" },
	{ "pigment", "scn writes material { diffuse C }" },
	{ "texture", "scn writes material { diffuse C  specular S ... }" },
	{ "finish", "scn writes material { specular S  shininess N  reflect R ... }" },
	{ "interior", "scn writes material { transmit T  ior N }" },
	{ "normal", "scn has no normal perturbation" },
	{ "ambient", "scn has no ambient term; emit adds a constant colour" },
	{ "phong", "scn's highlight is Blinn-Phong: specular and shininess" },
	{ "roughness", "scn writes shininess, the Blinn-Phong exponent (1 / roughness)" },
	{ "reflection", "scn writes reflect" },
	{ "filter", "scn's transparency is transmit" },
	{ "angle", "scn's camera writes fov, the horizontal field of view" },
	{ "sky", "scn's camera writes up" },
	{ "right", "scn's camera takes its aspect from resolution" },
	{ "colour", "scn writes color" },
	{ "object", "scn has no object statement; write the shape itself" },
	{ "range", "a for loop over numbers is written for i in A .. B" },
	{ "array", "scn writes an array as [A, B, C]" },
	{ "dimension_size", "scn writes len(xs)" },
	{ "concat", "scn joins strings with +" },
	{ "val", "scn has no conversion of a string to a number" },
	{ "mod", "scn writes mod(a, b)" },
};

/* Shapes POV-Ray has and scn has not. */
static const char *const pov_shapes[] = {
	"blob", "lathe", "sor", "prism", "superellipsoid", "height_field", "isosurface", "text", "polygon",
	"bicubic_patch", "quadric", "poly", "cubic", "quartic", "ovus", "parametric",
};

/* "; HINT" for a name POV-Ray users write, or NULL. */
const char *suggest_pov_hint(const char *name, char *buf, size_t size)
{
	for (size_t i = 0; i < sizeof pov_words / sizeof pov_words[0]; i++)
		if (strcmp(name, pov_words[i][0]) == 0) {
			snprintf(buf, size, " (%s)", pov_words[i][1]);
			return buf;
		}
	for (size_t i = 0; i < sizeof pov_shapes / sizeof pov_shapes[0]; i++)
		if (strcmp(name, pov_shapes[i]) == 0) {
			snprintf(buf, size, " (scn has spheres, planes, triangles, meshes, boxes, cylinders, cones, discs, "
			         "tori and their CSG: model it with those, or as a mesh)");
			return buf;
		}
	return NULL;
}

