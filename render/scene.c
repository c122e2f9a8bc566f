/* scene.c: release of a lowered scene, which owns all its arrays and its accelerator,
 * and a bound on their size. */
#include "scene.h"

#include <stdlib.h>
#include <string.h>

uint64_t scene_bytes(uint64_t nprims, uint64_t ntriangles, uint64_t nvertices)
{
	size_t prim = sizeof(struct triangle) > sizeof(struct sphere) ? sizeof(struct triangle) : sizeof(struct sphere);
	return 2 * (nprims * prim + nvertices * 2 * sizeof(struct vec3)) + accel_bytes(nprims, ntriangles);
}

void scene_free(struct scene *s)
{
	free(s->lights);
	free(s->area_lights);
	free(s->materials);
	free(s->affines);
	free(s->mesh_uses);
	geometry_free(&s->geo);
	free(s->sky.texels);
	free(s->patterns);
	free(s->colour_stops);
	free(s->image_maps);
	for (size_t i = 0; i < s->nimages; i++) {
		image_free(s->images[i]);
		free(s->image_paths[i]);
	}
	free(s->images);
	free(s->image_paths);
	accel_free(&s->accel);
	memset(s, 0, sizeof *s);
}
