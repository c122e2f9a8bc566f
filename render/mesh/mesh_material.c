/* mesh_material.c: a mesh file's materials through assimp's material API: the values
 * LANGUAGE.md section 11 takes from a file, the diffuse texture's path resolved, and an
 * embedded PNG's bytes copied for the lowering to decode. */
#include "mesh_material.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <assimp/GltfMaterial.h>
#include <assimp/material.h>
#include <assimp/texture.h>

#include "xalloc.h"

static const unsigned char png_signature[8] = { 0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n' };

/* Whether embedded image t is a PNG file: compressed (mHeight 0, mWidth bytes) and
 * starting with the signature, whatever assimp's format hint says. */
static bool is_png(const struct aiTexture *t)
{
	return t->mHeight == 0 && t->mWidth >= sizeof png_signature &&
	       memcmp(t->pcData, png_signature, sizeof png_signature) == 0;
}

uint64_t mesh_material_embedded_bytes(const struct aiScene *sc)
{
	uint64_t n = 0;
	for (unsigned i = 0; i < sc->mNumTextures; i++)
		n += is_png(sc->mTextures[i]) ? sc->mTextures[i]->mWidth : 0;
	return n;
}

/* s as a new C string: an aiString may hold a NUL before its length, and is cut there. */
static char *string_of(const struct aiString *s)
{
	size_t n = strnlen(s->data, s->length < MAXLEN ? s->length : MAXLEN - 1);
	char *c = xmalloc(n + 1);
	memcpy(c, s->data, n);
	c[n] = '\0';
	return c;
}

/* The part of a path after its last '/' or '\'. */
static const char *short_name(const char *path)
{
	const char *s = strrchr(path, '/'), *b = strrchr(path, '\\');
	s = !s || (b && b > s) ? b : s;
	return s ? s + 1 : path;
}

/* The index into sc->mTextures of the embedded image that a texture path names, or -1:
 * "*N" is the Nth, any other path one with the same file name (FBX names them so), as
 * assimp's aiScene::GetEmbeddedTexture, which C cannot call, finds them. */
static int embedded_index(const struct aiScene *sc, const char *name)
{
	if (name[0] == '*') {
		char *end;
		long i = strtol(name + 1, &end, 10);
		if (end != name + 1 && *end == '\0')
			return i >= 0 && i < (long)sc->mNumTextures ? (int)i : -1;
	}
	const char *base = short_name(name);
	for (unsigned i = 0; *base && i < sc->mNumTextures; i++)
		if (strcmp(short_name(sc->mTextures[i]->mFilename.data), base) == 0)
			return (int)i;
	return -1;
}

/* texture, as a mesh file at mesh_path writes it, resolved against the file's directory
 * unless absolute, with '\' read as '/': files written on Windows use it (assimp's OBJ
 * reader keeps it), and no texture file scn reads has one in its name. A leading "//"
 * is Blender's mark of a path relative to the file. */
static char *resolve(const char *mesh_path, const char *texture)
{
	bool blender = strncmp(texture, "//", 2) == 0;
	texture += blender ? 2 : 0;
	const char *slash = strrchr(mesh_path, '/');
	bool absolute = !blender && (texture[0] == '/' || texture[0] == '\\');
	size_t dir = absolute || !slash ? 0 : (size_t)(slash - mesh_path) + 1;
	size_t n = strlen(texture);
	char *p = xmalloc(dir + n + 1);
	memcpy(p, mesh_path, dir);
	for (size_t i = 0; i <= n; i++)
		p[dir + i] = texture[i] == '\\' ? '/' : texture[i];
	return p;
}

/* The first diffuse texture of mat, or else its first base colour one (glTF gives both,
 * the same), into *s. Returns false if it has none, or only one with an empty path. */
static bool diffuse_texture(const struct aiMaterial *mat, struct aiString *s)
{
	static const enum aiTextureType types[] = { aiTextureType_DIFFUSE, aiTextureType_BASE_COLOR };
	for (size_t i = 0; i < sizeof types / sizeof *types; i++)
		if (aiGetMaterialTextureCount(mat, types[i]) > 0 &&
		    aiGetMaterialTexture(mat, types[i], 0, s, NULL, NULL, NULL, NULL, NULL, NULL) == aiReturn_SUCCESS &&
		    s->length > 0 && s->data[0])
			return true;
	return false;
}

/* Reads the colour of key into rgb; false, and rgb unchanged, if mat has none or one
 * that is not finite. */
static bool get_color(const struct aiMaterial *mat, const char *key, unsigned type, unsigned index, double rgb[3])
{
	struct aiColor4D c;
	if (aiGetMaterialColor(mat, key, type, index, &c) != aiReturn_SUCCESS ||
	    !(isfinite(c.r) && isfinite(c.g) && isfinite(c.b)))
		return false;
	rgb[0] = c.r, rgb[1] = c.g, rgb[2] = c.b;
	return true;
}

/* As get_color, for a number. (aiGetMaterialFloat is C++'s, or a C inline function
 * without an external definition.) */
static bool get_float(const struct aiMaterial *mat, const char *key, unsigned type, unsigned index, double *x)
{
	ai_real f;
	unsigned n = 1;
	if (aiGetMaterialFloatArray(mat, key, type, index, &f, &n) != aiReturn_SUCCESS || n < 1 || !isfinite(f))
		return false;
	*x = f;
	return true;
}

/* The opacity of mat, whose alpha (glTF's base colour alpha, OBJ's d) is alpha: glTF's
 * alpha mode says whether that alpha counts (BLEND), is a cutoff (MASK), or is ignored
 * (OPAQUE, glTF's default). Clamped to [0, 1]. */
static double opacity_of(const struct aiMaterial *mat, double alpha)
{
	struct aiString mode;
	if (aiGetMaterialString(mat, AI_MATKEY_GLTF_ALPHAMODE, &mode) == aiReturn_SUCCESS) {
		if (strcmp(mode.data, "OPAQUE") == 0)
			return 1;
		if (strcmp(mode.data, "MASK") == 0) {
			double cutoff = 0.5; /* glTF's default */
			get_float(mat, AI_MATKEY_GLTF_ALPHACUTOFF, &cutoff);
			return alpha >= cutoff ? 1 : 0;
		}
	}
	return fmin(fmax(alpha, 0), 1);
}

/* Fills m from mat, given its name and diffuse texture path (NULL if none), copying an
 * embedded PNG into copies[index] once for every material that uses it. */
static void read_material(const struct aiScene *sc, const struct aiMaterial *mat, const char *path, char *name,
                          const struct aiString *texture, unsigned char **copies, struct mesh_material *m)
{
	*m = (struct mesh_material){
		.name = name, .diffuse = { 0.8, 0.8, 0.8 }, .exponent = 50, .opacity = 1, .ior = 1,
	};
	if (!get_color(mat, AI_MATKEY_COLOR_DIFFUSE, m->diffuse))
		get_color(mat, AI_MATKEY_BASE_COLOR, m->diffuse);
	double strength;
	if (get_color(mat, AI_MATKEY_COLOR_SPECULAR, m->specular) && get_float(mat, AI_MATKEY_SHININESS_STRENGTH, &strength))
		for (int k = 0; k < 3; k++)
			m->specular[k] *= strength;
	get_float(mat, AI_MATKEY_SHININESS, &m->exponent);
	double alpha = 1, ior;
	get_float(mat, AI_MATKEY_OPACITY, &alpha);
	m->opacity = opacity_of(mat, alpha);
	if (get_float(mat, AI_MATKEY_REFRACTI, &ior) && ior > 0)
		m->ior = ior;
	get_color(mat, AI_MATKEY_COLOR_EMISSIVE, m->emission);
	if (!texture)
		return;
	m->texture = string_of(texture);
	int e = embedded_index(sc, m->texture);
	if (e < 0) {
		m->texture_path = resolve(path, m->texture);
		return;
	}
	const struct aiTexture *t = sc->mTextures[e];
	snprintf(m->texture_format, sizeof m->texture_format, "%.*s", (int)sizeof m->texture_format - 1,
	         t->mHeight == 0 ? t->achFormatHint : "");
	if (!is_png(t))
		return;
	if (!copies[e]) {
		copies[e] = xmalloc(t->mWidth);
		memcpy(copies[e], t->pcData, t->mWidth);
	}
	m->texture_data = copies[e];
	m->texture_size = t->mWidth;
}

size_t mesh_material_read(const struct aiScene *sc, const char *path, const bool *used, uint32_t *index_of,
                          struct mesh_material **out)
{
	*out = NULL;
	size_t n = 0, cap = 0;
	unsigned char **copies = xcalloc(sc->mNumTextures + 1, sizeof *copies);
	for (unsigned i = 0; i < sc->mNumMaterials; i++) {
		index_of[i] = MESH_NO_MATERIAL;
		if (!used[i])
			continue;
		const struct aiMaterial *mat = sc->mMaterials[i];
		struct aiString name = { 0 }, texture;
		aiGetMaterialString(mat, AI_MATKEY_NAME, &name);
		bool textured = diffuse_texture(mat, &texture);
		/* the names assimp gives the material it makes up (mesh_import.h) */
		if (!textured && (name.data[0] == '\0' || strcmp(name.data, AI_DEFAULT_MATERIAL_NAME) == 0 ||
		                  strcmp(name.data, "%%%DEFAULT") == 0))
			continue;
		xgrow((void **)out, &cap, n + 1, sizeof **out);
		read_material(sc, mat, path, string_of(&name), textured ? &texture : NULL, copies, &(*out)[n]);
		index_of[i] = (uint32_t)n++;
	}
	free(copies);
	return n;
}

void mesh_material_free(struct mesh_material *m, size_t n)
{
	for (size_t i = 0; i < n; i++) {
		free(m[i].name);
		free(m[i].texture);
		free(m[i].texture_path);
		/* shared bytes: freed with the first material that has them */
		bool first = true;
		for (size_t j = 0; j < i && first; j++)
			first = m[j].texture_data != m[i].texture_data;
		if (first)
			free(m[i].texture_data);
	}
	free(m);
}
