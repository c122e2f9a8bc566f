/* mesh_import.h: reads a mesh file (OBJ, PLY and the other formats assimp knows) into
 * plain double-precision arrays of vertices, normals, texture coordinates and triangles,
 * with the file's materials. */
#ifndef SCN_MESH_IMPORT_H
#define SCN_MESH_IMPORT_H

#include <stddef.h>
#include <stdint.h>

/* A face's material index when its material is one assimp made up (see mesh_import): the
 * face takes the scene's material, as a file without materials does. */
#define MESH_NO_MATERIAL UINT32_MAX

/* A material of a mesh file (LANGUAGE.md section 11), as assimp reads it. A value the
 * file does not give is that of scn's default material: diffuse 0.8 grey, specular 0,
 * exponent 50 (the default shininess), opacity 1, ior 1, emission 0. */
struct mesh_material {
	char *name;                    /* as in the file; "" when it has none */
	double diffuse[3];             /* OBJ Kd, glTF baseColorFactor (which scales its texture) */
	/* The diffuse texture (glTF: base colour) as the file writes it, for messages: a
	 * path, or assimp's "*N" for the file's Nth embedded image; NULL when there is none. */
	char *texture;
	char *texture_path;            /* texture resolved against the mesh file's directory,
	                                * '\' read as '/'; NULL for an embedded texture */
	/* An embedded texture that is a PNG file: its bytes (materials that use the same
	 * image share them), else NULL. Other embedded images (JPEG, or assimp's decoded
	 * texels) have texture set and neither texture_path nor texture_data. */
	unsigned char *texture_data;
	size_t texture_size;
	char texture_format[9];        /* an embedded texture's format as assimp guesses it
	                                * ("png", "jpg"; "" for decoded texels), else "" */
	double specular[3];            /* OBJ Ks, times the file's specular strength if any */
	double exponent;               /* OBJ Ns, the specular exponent */
	double opacity;                /* OBJ d (or 1 - Tr), glTF's alpha in BLEND mode (in MASK
	                                * mode 0 or 1 by the cutoff, in OPAQUE mode 1); the
	                                * lowering's transmit is 1 - opacity */
	double ior;                    /* OBJ Ni */
	double emission[3];            /* OBJ Ke, glTF emissiveFactor */
};

struct mesh_data {
	double (*vertices)[3];
	size_t nvertices;
	double (*normals)[3];          /* NULL, or one unit normal per vertex */
	size_t nnormals;               /* 0 or nvertices */
	/* NULL, or one (u, v) per vertex from assimp's first UV channel, with v up: (0, 0)
	 * is the image's lower left corner, as OBJ's vt and POV-Ray's uv_vectors have it
	 * (assimp turns glTF's v, which runs down, over). The vertices of a part of the
	 * file without UVs, in a file where other parts have them, get (0, 0). */
	double (*uvs)[2];
	size_t nuvs;                   /* 0 or nvertices */
	uint32_t (*faces)[3];          /* indices into vertices (and normals, uvs) */
	size_t nfaces;
	/* NULL when the file has no materials of its own; else per face an index into
	 * materials, or MESH_NO_MATERIAL */
	uint32_t *face_material;
	struct mesh_material *materials;   /* those the triangles use, in the file's order */
	size_t nmaterials;
};

/* Reads the mesh file at path into *out: every triangle of every mesh in the file, with the
 * node transforms applied, polygons triangulated, points and lines left out, and corners
 * that share a position (and normal and UV) joined. Normals come only from the file, and
 * only when every triangle has valid ones; otherwise nnormals is 0. Degenerate triangles
 * are kept (the caller drops them, with a warning); a vertex that a triangle uses and
 * whose coordinates or UVs are not finite is an error. Values pass through assimp's
 * float, so they are exact only to float precision.
 * Materials: assimp gives every face a material, making one up for a file that has
 * none ("DefaultMaterial" for OBJ, STL and most others, "%%%DEFAULT" for 3DS, a nameless
 * one for PLY, OFF and a glTF primitive without a material). So a material named so, or
 * nameless, and without a diffuse texture, is taken as made up: its faces get
 * MESH_NO_MATERIAL, and a file with only such materials has none (face_material NULL,
 * nmaterials 0), and keeps the scene's. A file's own nameless material without a texture
 * (glTF and X allow them) is taken as made up too.
 * Returns 0, or writes into err a message naming path and the problem and returns nonzero
 * with *out empty: ENOMEM when reading it would need more memory than the machine has
 * (memory.h; found before assimp's post-processing, which would crash), 1 otherwise.
 * For a malformed file the message is the reader's own; assimp 5.2's OBJ and PLY
 * readers give no line number, some others (FBX) do. A texture file is not opened here.
 * The caller frees *out with mesh_import_free. Not thread-safe: assimp keeps its last
 * error in a global. */
int mesh_import(const char *path, struct mesh_data *out, char *err, size_t errlen);

/* Frees m's arrays and materials and empties it; m may be empty already. */
void mesh_import_free(struct mesh_data *m);

#endif
