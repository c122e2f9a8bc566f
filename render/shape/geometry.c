/* geometry.c: release of a scene's primitives (geometry.h). */
#include "geometry.h"

#include <stdlib.h>
#include <string.h>

void geometry_free(struct geometry *g)
{
	free(g->spheres);
	free(g->planes);
	free(g->vertices);
	free(g->normals);
	free(g->uvs);
	free(g->triangles);
	free(g->surfaces);
	free(g->parts);
	free(g->members);
	free(g->csg_boxes);
	free(g->part_triangles);
	free(g->solids);
	free(g->unbounded);
	free(g->transmit);
	memset(g, 0, sizeof *g);
}
