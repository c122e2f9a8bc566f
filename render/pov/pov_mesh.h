/* pov_mesh.h: triangles written as POV-Ray's mesh2 (pov_mesh.c). */
#ifndef SCN_POV_MESH_H
#define SCN_POV_MESH_H

#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>

#include "scene.h"

/* The geometric normal (B-A) x (C-A) of triangle t, unnormalised, in world space or, with
 * own, in the mesh file's own space. */
struct vec3 pov_face_normal(const struct scene *sc, const struct mesh_use *own, const struct triangle *t);
/* Whether the n triangles of sc's triangles from a and those from b are the same faces on
 * the same vertex and normal indices, each counted from its run's first; swap: corners 1
 * and 2 of b's faces swapped (lowering swaps them under a mirroring transform). */
bool pov_same_faces(const struct scene *sc, size_t a, size_t b, size_t n, bool swap);
/* What a mesh2 carries beyond its shape: the vertices' UVs, and a texture per face. */
struct pov_mesh2_extra {
	bool uvs;                      /* uv_vectors from geo.uvs (one per vertex, so no uv_indices) */
	const uint32_t *textures;      /* the surfaces whose textures form its texture_list (each
	                                * face indexes its own surface's); NULL: none */
	size_t ntextures;
};
/* tris[first, last) (sc's triangles or its mesh parts'), of one surface, as "mesh2 { ..."
 * up to its material: in world space, or with own (a mesh file's use) in the file's own
 * space, into which own's to_object map takes the world-space vertices back and the
 * transpose of its to_world map the normals (POV-Ray's matrix brings them out again).
 * With extra (or NULL), its UVs and texture_list; the textures in world space unless own. */
void pov_mesh2_body(FILE *f, const struct scene *sc, const struct triangle *tris, size_t first, size_t last,
                    const struct mesh_use *own, const struct pov_mesh2_extra *extra);

#endif
