/* lower_internal.h: what the lowering's files share (lower.c: objects, solids, lights and
 * sky; lower_add.c: the scene's materials, surfaces, vertices and triangles; lower_mesh.c:
 * meshes, their files and the files' own materials; lower_texture.c: textures). lower.c
 * calls lower_mesh.c, both call lower_add.c, which calls lower_texture.c. */
#ifndef SCN_LOWER_INTERNAL_H
#define SCN_LOWER_INTERNAL_H

#include <stdbool.h>
#include <stdint.h>

#include "lower_texture.h"
#include "mesh_import.h"
#include "part.h"
#include "scene.h"
#include "scene_desc.h"

struct mesh_cache_entry {
	const char *path;
	struct mesh_data data;
	bool ok;
	int32_t source[2];             /* its scene mesh number, flat and smooth; -1: none yet */
	int32_t *materials[2];         /* the scene material of each of the file's materials, its
	                                * textures looked up nearest and bilinear; -1: none yet */
};

struct lowering {
	struct diag *diag;
	const struct scene_desc *desc;
	struct scene *sc;
	size_t cap_surfaces, cap_uvs, cap_affines, cap_spheres, cap_planes, cap_vertices, cap_normals, cap_triangles;
	size_t cap_materials, cap_mesh_uses, cap_parts, cap_members, cap_solids, cap_unbounded, cap_part_triangles, cap_csg_boxes;
	int *material_map;             /* desc material -> scene material, or -1 */
	int default_material;          /* the scene material for objects without one, or -1 */
	struct mesh_cache_entry *mesh_cache;
	size_t nmesh_cache, cap_mesh_cache;
	double mesh_seconds;
	bool too_big;                  /* a mesh file or the sky image needs more memory than there is */
	struct texture_lowering tex;
};

/* lower_add.c */
/* The scene description's transform as the renderer's affine map (the same layout), a
 * point under it, its inverse, and whether it mirrors space (a triangle's corners then go
 * the other way round, and are swapped so that (B-A) x (C-A) still points to the side that
 * was the outside: a mirrored closed mesh stays solid). */
struct affine lower_affine_of(const struct xform *x);
struct vec3 lower_xform_point(const struct xform *x, struct vec3 p);
struct affine lower_xform_inverse(const struct xform *x);
bool lower_xform_mirrors(const struct xform *x);
/* The scene material of description material desc_index (-1: the default material): used
 * materials only, in first-use order. */
uint32_t lower_material_of(struct lowering *lw, int desc_index);
/* A surface of object o made of scene material mat; of its own material. */
uint32_t lower_add_surface_of(struct lowering *lw, const struct object_desc *o, uint32_t mat);
uint32_t lower_add_surface(struct lowering *lw, const struct object_desc *o);
uint32_t lower_add_vertex(struct lowering *lw, struct vec3 v);
/* Reports what at `at` when it reaches extent from the origin (after its transforms),
 * beyond which its arithmetic would overflow; returns whether it stays within the limit. */
bool lower_check_extent(struct lowering *lw, struct span at, const char *what, double extent);
/* p's greatest coordinate magnitude, as lower_check_extent takes it. */
double lower_extent_of(struct vec3 p);
/* Adds a triangle unless it has no area (NUMERICS.md section 5), to the scene's or, with
 * part, to the mesh parts' triangles; returns whether it did. */
bool lower_add_triangle(struct lowering *lw, const uint32_t v[3], const uint32_t n[3], uint32_t surface, bool part);

/* lower_mesh.c */
/* The data of mesh object o: its file's (read once) or its inline arrays in *inline_data;
 * NULL after an error. */
const struct mesh_data *lower_mesh_data(struct lowering *lw, const struct object_desc *o,
                                        struct mesh_data *inline_data);
/* Mesh object o's triangles (its vertices, normals, UVs and surfaces), or, with part, a
 * CSG's mesh part in *part; false after an error reported at `at` (or when the part has
 * no triangles). */
bool lower_mesh(struct lowering *lw, const struct object_desc *o, const struct span *at, struct part *part);
/* Frees the mesh files' data, once lowering is done with them. */
void lower_mesh_release(struct lowering *lw);

#endif
