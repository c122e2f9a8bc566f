/* mesh_import.h: reads a mesh file (OBJ, PLY and the other formats assimp knows) into
 * plain double-precision arrays of vertices, normals and triangles. */
#ifndef SCN_MESH_IMPORT_H
#define SCN_MESH_IMPORT_H

#include <stddef.h>
#include <stdint.h>

struct mesh_data {
	double (*vertices)[3];
	size_t nvertices;
	double (*normals)[3];          /* NULL, or one unit normal per vertex */
	size_t nnormals;               /* 0 or nvertices */
	uint32_t (*faces)[3];          /* indices into vertices (and normals) */
	size_t nfaces;
};

/* Reads the mesh file at path into *out: every triangle of every mesh in the file, with the
 * node transforms applied, polygons triangulated, points and lines left out, and corners
 * that share a position (and normal) joined. Normals come only from the file, and only
 * when every triangle has valid ones; otherwise nnormals is 0. Degenerate triangles are
 * kept (the caller drops them, with a warning); a vertex that a triangle uses and whose
 * coordinates are not finite is an error. Values pass through assimp's float, so they
 * are exact only to float precision.
 * Returns 0, or writes into err a message naming path and the problem and returns nonzero
 * with *out empty: ENOMEM when reading it would need more memory than the machine has
 * (memory.h; found before assimp's post-processing, which would crash), 1 otherwise.
 * For a malformed file the message is the reader's own; assimp 5.2's OBJ and PLY
 * readers give no line number, some others (FBX) do. The caller frees *out with
 * mesh_import_free. Not thread-safe: assimp keeps its last error in a global. */
int mesh_import(const char *path, struct mesh_data *out, char *err, size_t errlen);

/* Frees m's arrays and empties it; m may be empty already. */
void mesh_import_free(struct mesh_data *m);

#endif
