/* scene.c: release of a lowered scene, which owns all its arrays and its accelerator,
 * and a bound on their size. */
#include "scene.h"

#include <stdlib.h>
#include <string.h>

#include "bvh.h"
#include "grid.h"

uint64_t scene_bytes(uint64_t nprims, uint64_t ntriangles, uint64_t nvertices)
{
	size_t prim = sizeof(struct triangle) > sizeof(struct sphere) ? sizeof(struct triangle) : sizeof(struct sphere);
	uint64_t bvh = bvh_bytes(nprims, ntriangles), grid = grid_bytes(nprims);
	return 2 * (nprims * prim + nvertices * 2 * sizeof(struct vec3)) + (bvh > grid ? bvh : grid);
}

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
