/* mesh_material.h: a mesh file's materials and their textures, from assimp's scene into
 * struct mesh_material (mesh_import.c's helper; the rules are at mesh_import). */
#ifndef SCN_MESH_MATERIAL_H
#define SCN_MESH_MATERIAL_H

#include <stdbool.h>
#include <stdint.h>

#include <assimp/scene.h>

#include "mesh_import.h"

/* Reads the materials of sc (the file at path) that used[] marks, one flag per
 * sc->mMaterials, leaving out those assimp made up. Sets index_of[i], for each of sc's
 * materials, to its index in *out, or to MESH_NO_MATERIAL; returns the number of
 * materials in *out (NULL when 0), which the caller frees with mesh_material_free. */
size_t mesh_material_read(const struct aiScene *sc, const char *path, const bool *used, uint32_t *index_of,
                          struct mesh_material **out);

/* The bytes of sc's embedded images that mesh_material_read may copy: the PNG files. */
uint64_t mesh_material_embedded_bytes(const struct aiScene *sc);

/* Frees the n materials m (NULL if n is 0) and what they own. */
void mesh_material_free(struct mesh_material *m, size_t n);

#endif
