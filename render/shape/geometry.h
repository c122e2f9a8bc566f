/* geometry.h: a scene's primitives, in flat arrays by kind, with what each is made of.
 * lower.c fills it; the accelerators and the shapes' dispatch (shape.h) read it, and
 * need nothing else of the scene. */
#ifndef SCN_GEOMETRY_H
#define SCN_GEOMETRY_H

#include <stddef.h>
#include <stdint.h>

#include "csg_tree.h"
#include "part.h"
#include "plane.h"
#include "sphere.h"
#include "triangle.h"

/* What a primitive is made of: a material, and for a textured one (material_textured) the
 * map from world space back to the object's own space, where its patterns are defined. */
struct surface {
	uint32_t material;             /* into scene.materials */
	int32_t to_object;             /* into scene.affines; -1: the identity */
};

struct uv {
	double u, v;
};

struct geometry {
	struct sphere *spheres;
	size_t nspheres;
	struct plane *planes;
	size_t nplanes;
	struct vec3 *vertices;
	size_t nvertices;
	struct vec3 *normals;
	size_t nnormals;
	struct uv *uvs;                /* texture coordinates, one per vertex (NULL when no mesh
	                                * has any; zero for the vertices of those that have none) */
	size_t nuvs;
	struct triangle *triangles;
	size_t ntriangles;
	struct surface *surfaces;
	size_t nsurfaces;
	/* the solids (csg.h): each a tree of parts; the bounded ones are primitives of the
	 * accelerators, the unbounded ones (a plane among their members) are tested beside
	 * them, as planes are */
	struct part *parts;
	size_t nparts;
	uint32_t *members;             /* the CSG nodes' members, into parts */
	struct csg_box *csg_boxes;     /* the hierarchies over large nodes' members (csg_tree.h) */
	size_t ncsg_boxes;
	struct triangle *part_triangles;   /* the triangles of mesh parts, which no accelerator holds */
	size_t npart_triangles;
	size_t nmembers;
	uint32_t *solids;              /* the bounded solids' root parts */
	size_t nsolids;
	uint32_t *unbounded;           /* the unbounded solids' root parts */
	size_t nunbounded;
	/* each material's k_t (scene.materials[m].transmit), for the shadow filter, which
	 * multiplies the k_t of every surface a shadow ray crosses: a copy, so that the
	 * accelerators that filter need no materials */
	struct vec3 *transmit;
	size_t ntransmit;
};

/* Frees g's arrays and empties it. */
void geometry_free(struct geometry *g);

#endif
