/* scene.c: release of a lowered scene, which owns all its arrays and its accelerator. */
#include "scene.h"

#include <stdlib.h>
#include <string.h>

#include "bvh.h"
#include "grid.h"

void scene_free(struct scene *s)
{
	free(s->lights);
	free(s->materials);
	free(s->surfaces);
	free(s->affines);
	free(s->spheres);
	free(s->planes);
	free(s->vertices);
	free(s->normals);
	free(s->triangles);
	free(s->sky.texels);
	bvh_free(s->bvh);
	grid_free(s->grid);
	memset(s, 0, sizeof *s);
}
