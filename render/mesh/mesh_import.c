/* mesh_import.c: mesh files through assimp's C API, flattened into one triangle list in
 * double precision (assimp stores float, so a file's values keep float precision at best),
 * with the file's materials (mesh_material.c). */
#include <errno.h>
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <assimp/cimport.h>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include "memory.h"
#include "mesh_header.h"
#include "mesh_import.h"
#include "mesh_join.h"
#include "mesh_material.h"
#include "xalloc.h"

/* assimp runs in two stages, because Debian's build keeps assimp's internal assertions on
 * and Triangulate aborts the process (ai_assert in TriangulateProcess.cpp) when a mesh's
 * mPrimitiveTypes claims polygons it does not have, which a truncated PLY produces.
 *
 * The read: the reader, then ValidateDataStructure, which rejects out-of-range indices and
 * the like. Validation must run here and not later: when aiApplyPostProcessing fails,
 * assimp 5.2 crashes (in aiReleaseImport) instead of returning NULL.
 *
 * The rest, after we recompute mPrimitiveTypes from the faces: RemoveComponent drops what
 * we never use (removed_components), so that PreTransformVertices, which merges meshes of
 * one material and one vertex format, neither copies it nor keeps meshes apart for it.
 * SortByPType with AI_CONFIG_PP_SBP_REMOVE drops points and lines. None of these fails
 * on a valid scene that has a polygon. No GenNormals: the renderer computes
 * area-weighted normals itself when the scene asks for smooth. No FindDegenerates: it
 * drops degenerate triangles silently, and the caller warns about them. No
 * JoinIdenticalVertices: mesh_join() joins the corners by position, normal and UV once
 * they are copied (a material boundary does not split a smooth surface, while corners
 * with different normals stay apart and keep the file's hard edges, and a UV seam keeps
 * both sides' coordinates), in a twentieth of the time. */
static const unsigned read_flags = aiProcess_ValidateDataStructure;
static const unsigned post_flags = aiProcess_RemoveComponent | aiProcess_Triangulate |
	aiProcess_PreTransformVertices | aiProcess_SortByPType;

/* Every UV channel but the first goes too; assimp 5.2's flags name channels 0 to 6 only
 * (aiComponent_TEXCOORDSn(7) would shift by 32), and no file we know has an eighth. */
static const unsigned removed_components = aiComponent_TANGENTS_AND_BITANGENTS | aiComponent_COLORS |
	aiComponent_BONEWEIGHTS | aiComponent_ANIMATIONS | aiComponent_LIGHTS | aiComponent_CAMERAS |
	aiComponent_TEXCOORDSn(1) | aiComponent_TEXCOORDSn(2) | aiComponent_TEXCOORDSn(3) |
	aiComponent_TEXCOORDSn(4) | aiComponent_TEXCOORDSn(5) | aiComponent_TEXCOORDSn(6);

/* The length of msg without its trailing blanks and full stop, since our messages end
 * without one; long messages are cut. */
static int trimmed(const char *msg)
{
	size_t n = strlen(msg);
	while (n > 0 && strchr(" \t\r\n.", msg[n - 1]))
		n--;
	return n > 400 ? 400 : (int)n;
}

/* Fills err with assimp's last error, about path, and returns 1. assimp catches its own
 * std::bad_alloc and reports it as an error like any other, its message then being the
 * exception's alone: that one is running out of memory, status 4 (xalloc.h), not a
 * malformed file. The match is exact, as a parse error quotes the file, which can say
 * bad_alloc (found by fuzzing). */
static int malformed(const char *path, char *err, size_t errlen)
{
	const char *msg = aiGetErrorString();
	if (msg && strcmp(msg, "std::bad_alloc") == 0)
		xout_of_memory("reading mesh file '%s'", path);
	if (!msg || !*msg)
		msg = "the reader gives no reason";
	return mesh_header_fail(err, errlen, "malformed mesh file '%s': %.*s", path, trimmed(msg), msg);
}

/* Whether assimp's last error is validation finding no faces, or no mesh: a file of
 * only points, or of nothing, fails validation (which wants a mesh, with faces), and this
 * tells that case apart from a broken file. (Reading the file again without validation
 * to count its faces is not safe: assimp then runs its ScenePreprocessor on what
 * validation would have refused, and reads out of bounds on a face without indices, as
 * in an OFF file found by fuzzing.) */
static bool validation_found_no_faces(void)
{
	const char *msg = aiGetErrorString();
	return msg && strncmp(msg, "Validation failed: ", 19) == 0 &&
	       (strstr(msg, " contains no faces") || strstr(msg, "mNumMeshes is 0"));
}

/* Sets each mesh's mPrimitiveTypes from its faces, so that Triangulate's assertion holds.
 * This writes into the scene that assimp hands out as const, as aiApplyPostProcessing
 * itself does. Returns 0 if some face has 3 or more corners. Else, or if a face has none
 * (validation lets that through, and a PLY cut short in its faces gives it), fills err
 * and returns 1. */
static int set_primitive_types(const struct aiScene *sc, const char *path, char *err, size_t errlen)
{
	bool polygons = false;
	for (unsigned i = 0; i < sc->mNumMeshes; i++) {
		struct aiMesh *m = sc->mMeshes[i];
		unsigned types = 0;
		for (unsigned j = 0; j < m->mNumFaces; j++) {
			unsigned n = m->mFaces[j].mNumIndices;
			if (n == 0)
				return mesh_header_fail(err, errlen, "malformed mesh file '%s': face %u has no vertices "
						 "(is the file cut short?)", path, j + 1);
			types |= n == 1 ? aiPrimitiveType_POINT : n == 2 ? aiPrimitiveType_LINE :
			         n == 3 ? aiPrimitiveType_TRIANGLE : aiPrimitiveType_POLYGON;
		}
		m->mPrimitiveTypes = types;
		polygons = polygons || (types & (aiPrimitiveType_TRIANGLE | aiPrimitiveType_POLYGON));
	}
	return polygons ? 0 : mesh_header_fail(err, errlen, "no triangles in '%s'", path);
}

/* Whether the second stage's memory, and that of copying and joining what it gives,
 * fits the machine (memory.h). When it runs out, aiApplyPostProcessing crashes as
 * described at read_flags, so the bytes are counted before. Measured over the resident
 * memory the first stage leaves: 46 MB for a 1M-vertex, 2M-triangle binary PLY, 58 MB
 * for an OBJ of 480 000 quads with normals (1.9M vertices as assimp reads it). Our own
 * arrays take at most 68 bytes a vertex (position, normal, mesh_join's tables), 16 more
 * with a UV, 4 a corner and 4 a face (its material, within PER_CORNER's margin: those
 * files take less than a third of the estimate); the constants below add assimp's copies
 * (12 bytes a UV) and round up. The embedded PNG images are copied once. If not, fills
 * err and returns false. */
static bool second_stage_fits(const struct aiScene *sc, const char *path, char *err, size_t errlen)
{
	enum { PER_VERTEX = 80, PER_UV = 32, PER_CORNER = 16 };
	uint64_t vertices = 0, uvs = 0, corners = 0;
	for (unsigned i = 0; i < sc->mNumMeshes; i++) {
		const struct aiMesh *m = sc->mMeshes[i];
		vertices += m->mNumVertices;
		uvs += m->mTextureCoords[0] ? m->mNumVertices : 0;
		for (unsigned j = 0; j < m->mNumFaces; j++)
			corners += m->mFaces[j].mNumIndices;
	}
	char msg[160];
	uint64_t need = PER_VERTEX * vertices + PER_UV * uvs + PER_CORNER * corners + mesh_material_embedded_bytes(sc);
	if (memory_fits(need, msg, sizeof msg))
		return true;
	mesh_header_fail(err, errlen, "reading mesh file '%s' (%llu vertices, %llu face corners) %s", path,
		  (unsigned long long)vertices, (unsigned long long)corners, msg);
	return false;
}

/* Imports path in the two stages described at read_flags. Returns the scene, or NULL
 * with err filled and *too_big set when it would need more memory than there is. */
static const struct aiScene *import(const char *path, bool *too_big, char *err, size_t errlen)
{
	struct aiPropertyStore *props = aiCreatePropertyStore();
	aiSetImportPropertyInteger(props, AI_CONFIG_PP_RVC_FLAGS, (int)removed_components);
	aiSetImportPropertyInteger(props, AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
	/* the importer keeps these properties for aiApplyPostProcessing */
	const struct aiScene *sc = aiImportFileExWithProperties(path, read_flags, NULL, props);
	aiReleasePropertyStore(props);
	if (!sc) {
		if (validation_found_no_faces())
			mesh_header_fail(err, errlen, "no triangles in '%s'", path);
		else
			malformed(path, err, errlen);
		return NULL;
	}
	if (set_primitive_types(sc, path, err, errlen)) {
		aiReleaseImport(sc);
		return NULL;
	}
	if (!second_stage_fits(sc, path, err, errlen)) {
		*too_big = true;
		aiReleaseImport(sc);
		return NULL;
	}
	sc = aiApplyPostProcessing(sc, post_flags);
	if (!sc)
		malformed(path, err, errlen);
	return sc;
}

static bool is_triangle_mesh(const struct aiMesh *m)
{
	return (m->mPrimitiveTypes & aiPrimitiveType_TRIANGLE) && m->mNumVertices > 0;
}

static bool usable_normal(struct aiVector3D n)
{
	double len2 = (double)n.x * n.x + (double)n.y * n.y + (double)n.z * n.z;
	return len2 > 0 && isfinite(len2);
}

/* Whether every triangle corner of sc has a usable normal from the file. An OBJ face
 * without vn among faces with it gives zero normals, and a PLY may carry junk; either
 * way the renderer is better off computing all of them than trusting some, and the
 * corners that differed only by their normals then join, so that smoothing runs across
 * them. */
static bool normals_usable(const struct aiScene *sc)
{
	for (unsigned i = 0; i < sc->mNumMeshes; i++) {
		const struct aiMesh *m = sc->mMeshes[i];
		if (!is_triangle_mesh(m))
			continue;
		if (!m->mNormals)
			return false;
		for (unsigned j = 0; j < m->mNumFaces; j++) {
			const struct aiFace *face = &m->mFaces[j];
			for (unsigned k = 0; face->mNumIndices == 3 && k < 3; k++)
				if (!usable_normal(m->mNormals[face->mIndices[k]]))
					return false;
		}
	}
	return true;
}

/* Copies the triangles of sc's triangle meshes into out, which is empty, with normals
 * when keep_normals (then every triangle mesh has usable ones), UVs when some triangle
 * mesh has them, and the materials they use (mesh_material_read; path is the file's).
 * Vertices of each mesh follow those of the one before, so its indices are offset by
 * the count so far. */
static void copy_scene(const struct aiScene *sc, bool keep_normals, const char *path, struct mesh_data *out)
{
	size_t nv = 0, nf = 0;
	bool keep_uvs = false;
	/* validation makes every mesh's mMaterialIndex one of mNumMaterials */
	bool *used = xcalloc(sc->mNumMaterials + 1, sizeof *used);
	for (unsigned i = 0; i < sc->mNumMeshes; i++) {
		const struct aiMesh *m = sc->mMeshes[i];
		if (!is_triangle_mesh(m))
			continue;
		nv += m->mNumVertices;
		for (unsigned j = 0; j < m->mNumFaces; j++)
			nf += m->mFaces[j].mNumIndices == 3;
		keep_uvs = keep_uvs || m->mTextureCoords[0];
		used[m->mMaterialIndex] = true;
	}
	if (nf == 0) {
		free(used);
		return;
	}
	uint32_t *index_of = xmalloc(sc->mNumMaterials * sizeof *index_of + 1);
	out->nmaterials = mesh_material_read(sc, path, used, index_of, &out->materials);
	free(used);
	out->vertices = xmalloc(nv * sizeof *out->vertices);
	out->normals = keep_normals ? xmalloc(nv * sizeof *out->normals) : NULL;
	out->uvs = keep_uvs ? xmalloc(nv * sizeof *out->uvs) : NULL;
	out->faces = xmalloc(nf * sizeof *out->faces);
	out->face_material = out->nmaterials ? xmalloc(nf * sizeof *out->face_material) : NULL;
	size_t base = 0, f = 0;
	for (unsigned i = 0; i < sc->mNumMeshes; i++) {
		const struct aiMesh *m = sc->mMeshes[i];
		if (!is_triangle_mesh(m))
			continue;
		for (unsigned j = 0; j < m->mNumVertices; j++) {
			const struct aiVector3D p = m->mVertices[j];
			double *v = out->vertices[base + j];
			v[0] = p.x, v[1] = p.y, v[2] = p.z;
			if (keep_normals) {
				/* renormalised in double: a file's normals need not be unit, and
				 * assimp's float ones are unit only to about 1e-7 */
				const struct aiVector3D q = m->mNormals[j];
				double len = sqrt((double)q.x * q.x + (double)q.y * q.y + (double)q.z * q.z);
				double *n = out->normals[base + j];
				n[0] = q.x / len, n[1] = q.y / len, n[2] = q.z / len;
			}
			if (keep_uvs) {
				/* (0, 0) for a mesh without UVs; v is 0 for a channel of u alone */
				const struct aiVector3D *t = m->mTextureCoords[0];
				double *uv = out->uvs[base + j];
				uv[0] = t ? t[j].x : 0;
				uv[1] = t && m->mNumUVComponents[0] >= 2 ? t[j].y : 0;
			}
		}
		for (unsigned j = 0; j < m->mNumFaces; j++) {
			const struct aiFace *face = &m->mFaces[j];
			if (face->mNumIndices != 3)
				continue;
			for (int k = 0; k < 3; k++)
				out->faces[f][k] = (uint32_t)(base + face->mIndices[k]);
			if (out->face_material)
				out->face_material[f] = index_of[m->mMaterialIndex];
			f++;
		}
		base += m->mNumVertices;
	}
	free(index_of);
	out->nvertices = nv;
	out->nnormals = keep_normals ? nv : 0;
	out->nuvs = keep_uvs ? nv : 0;
	out->nfaces = nf;
}

/* The number of m's vertices with a coordinate that is not finite. assimp gives them as
 * the file has them (a glTF's float inf), or as it reads a number beyond float's range
 * (an OBJ's 1e39 is inf). Such a vertex has no place, and its triangles no area, so a
 * file of them would render as nothing with only a warning about areas. */
static size_t nonfinite_vertices(const struct mesh_data *m)
{
	size_t n = 0;
	for (size_t i = 0; i < m->nvertices; i++)
		n += !(isfinite(m->vertices[i][0]) && isfinite(m->vertices[i][1]) && isfinite(m->vertices[i][2]));
	return n;
}

/* The number of m's vertices with a UV that is not finite. Such a UV names no texel,
 * and POV-Ray refuses the mesh2 that would carry it, so the file is refused, as it is
 * for a vertex; its UVs are not dropped quietly, as whether the scene looks them up
 * (the file's textures, or a scene material's `map uv`) is not known here. */
static size_t nonfinite_uvs(const struct mesh_data *m)
{
	size_t n = 0;
	for (size_t i = 0; i < m->nuvs; i++)
		n += !(isfinite(m->uvs[i][0]) && isfinite(m->uvs[i][1]));
	return n;
}

int mesh_import(const char *path, struct mesh_data *out, char *err, size_t errlen)
{
	memset(out, 0, sizeof *out);
	if (mesh_header_check(path, err, errlen))
		return 1;
	bool too_big = false;
	const struct aiScene *sc = import(path, &too_big, err, errlen);
	if (!sc)
		return too_big ? ENOMEM : 1;

	/* Indices are 32-bit. assimp's are per mesh, so only the sum can overflow. */
	size_t nv = 0;
	for (unsigned i = 0; i < sc->mNumMeshes; i++)
		if (is_triangle_mesh(sc->mMeshes[i]))
			nv += sc->mMeshes[i]->mNumVertices;
	if (nv > UINT32_MAX) {
		aiReleaseImport(sc);
		return mesh_header_fail(err, errlen, "mesh file '%s' has %zu vertices; at most %lu are supported", path, nv,
				 (unsigned long)UINT32_MAX);
	}
	copy_scene(sc, normals_usable(sc), path, out);
	aiReleaseImport(sc);
	if (out->nfaces == 0)
		return mesh_header_fail(err, errlen, "no triangles in '%s'", path);
	mesh_join(out);
	size_t bad = nonfinite_vertices(out);
	if (bad) {
		size_t n = out->nvertices;
		mesh_import_free(out);
		return mesh_header_fail(err, errlen, "mesh file '%s': %zu of its %zu vertices have coordinates that "
		                        "are not finite (inf or nan, or beyond float's 3.4e38)", path, bad, n);
	}
	bad = nonfinite_uvs(out);
	if (bad) {
		size_t n = out->nvertices;
		mesh_import_free(out);
		return mesh_header_fail(err, errlen, "mesh file '%s': %zu of its %zu vertices have texture coordinates "
		                        "that are not finite (inf or nan, or beyond float's 3.4e38)", path, bad, n);
	}
	return 0;
}

void mesh_import_free(struct mesh_data *m)
{
	free(m->vertices);
	free(m->normals);
	free(m->uvs);
	free(m->faces);
	free(m->face_material);
	mesh_material_free(m->materials, m->nmaterials);
	memset(m, 0, sizeof *m);
}
