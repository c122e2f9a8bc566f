/* lower.c: turns the evaluated scene_desc into the renderer's scene: world-space
 * geometry with transforms baked in, only the materials objects use, mesh files and sky
 * images loaded (each once). */
#include "lower.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "camera.h"
#include "clock.h"
#include "image_file.h"
#include "lower_texture.h"
#include "memory.h"
#include "mesh_import.h"
#include "part_make.h"
#include "shape.h"
#include "xalloc.h"

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

/* The scene description's transform as the renderer's affine map (the same layout). */
static struct affine affine_of(const struct xform *x)
{
	struct affine a;
	memcpy(a.m, x->m, sizeof a.m);
	return a;
}

static struct vec3 xform_point(const struct xform *x, struct vec3 p)
{
	struct affine a = affine_of(x);
	return affine_point(&a, p);
}

static struct affine xform_inverse(const struct xform *x)
{
	struct affine a = affine_of(x);
	return affine_inverse(&a);
}

/* Whether x mirrors space: a triangle's corners then go the other way round, and are
 * swapped so that (B-A) x (C-A) still points to the side that was the outside (a
 * mirrored closed mesh stays solid). */
static bool xform_mirrors(const struct xform *x)
{
	struct affine a = affine_of(x);
	return affine_mirrors(&a);
}

static struct material lower_material(struct lowering *lw, const struct material_desc *m)
{
	/* ORDER: enum pigment_kind and enum material_pigment alike */
	static const uint8_t pigments[] = {
		[PIGMENT_COLOR] = MATERIAL_COLOR, [PIGMENT_CHECKER] = MATERIAL_CHECKER,
		[PIGMENT_PATTERN] = MATERIAL_PATTERN, [PIGMENT_IMAGE] = MATERIAL_IMAGE,
	};
	struct material out = {
		.diffuse = v3a(m->diffuse), .diffuse2 = v3a(m->diffuse2), .checker_size = m->checker_size,
		.pigment = pigments[m->pigment], .texture = -1, .bump = -1, .fresnel = m->fresnel,
		.specular = v3a(m->specular), .reflect = v3a(m->reflect), .transmit = v3a(m->transmit),
		.emit = v3a(m->emit), .shininess = m->shininess, .ior = m->ior,
	};
	if (m->pigment == PIGMENT_PATTERN)
		out.texture = lower_texture_pattern(&lw->tex, m->pattern);
	if (m->pigment == PIGMENT_IMAGE) {
		out.texture = lower_texture_image(&lw->tex, m->pattern);
		if (out.texture < 0) /* reported; the render does not happen */
			out.pigment = MATERIAL_COLOR;
	}
	if (m->normal >= 0)
		out.bump = lower_texture_pattern(&lw->tex, m->normal);
	return out;
}

/* The scene material of an object: used materials only, in first-use order. */
static uint32_t material_of(struct lowering *lw, int desc_index)
{
	struct scene *sc = lw->sc;
	int *slot = desc_index >= 0 ? &lw->material_map[desc_index] : &lw->default_material;
	if (*slot < 0) {
		/* LANGUAGE.md's default material: diffuse 0.8 grey, nothing else */
		static const struct material default_material = { .texture = -1, .bump = -1,
			.diffuse = { 0.8, 0.8, 0.8 }, .shininess = 50, .ior = 1,
		};
		/* doubling: 100000 inline materials must not be copied 100000 times */
		xgrow((void **)&sc->materials, &lw->cap_materials, sc->nmaterials + 1, sizeof *sc->materials);
		sc->materials[sc->nmaterials] = desc_index >= 0 ? lower_material(lw, &lw->desc->materials[desc_index])
		                                                : default_material;
		*slot = (int)sc->nmaterials++;
	}
	return (uint32_t)*slot;
}

/* A surface of object o made of scene material mat. */
static uint32_t add_surface_of(struct lowering *lw, const struct object_desc *o, uint32_t mat)
{
	struct scene *sc = lw->sc;
	int32_t to_object = -1;
	if (material_textured(&sc->materials[mat]) && o->pattern_xform >= 0) {
		xgrow((void **)&sc->affines, &lw->cap_affines, sc->naffines + 1, sizeof *sc->affines);
		sc->affines[sc->naffines] = xform_inverse(&lw->desc->xforms[o->pattern_xform]);
		to_object = (int32_t)sc->naffines++;
	}
	xgrow((void **)&sc->geo.surfaces, &lw->cap_surfaces, sc->geo.nsurfaces + 1, sizeof *sc->geo.surfaces);
	sc->geo.surfaces[sc->geo.nsurfaces] = (struct surface){ mat, to_object };
	return (uint32_t)sc->geo.nsurfaces++;
}

/* A surface of object o made of its material. */
static uint32_t add_surface(struct lowering *lw, const struct object_desc *o)
{
	return add_surface_of(lw, o, material_of(lw, o->material));
}

static uint32_t add_vertex(struct lowering *lw, struct vec3 v)
{
	struct scene *sc = lw->sc;
	xgrow((void **)&sc->geo.vertices, &lw->cap_vertices, sc->geo.nvertices + 1, sizeof *sc->geo.vertices);
	sc->geo.vertices[sc->geo.nvertices] = v;
	return (uint32_t)sc->geo.nvertices++;
}

/* Geometry beyond this distance from the origin is refused: the intersection tests
 * square coordinates (a sphere's r^2 and |o - c|^2) and multiply three (a triangle's
 * scaled t), which overflow a double from about 1e102, and an overflow would be a
 * silently missing object. */
#define MAX_EXTENT 1e100
/* ... and a sphere below this radius, whose r^2 would underflow, is not drawn (with a
 * warning): it is valid, only too small to compute with, and too small to see. */
#define MIN_RADIUS 1e-100

/* Reports what at `at` when it reaches extent from the origin (after its transforms);
 * returns whether it stays within the limit. */
static bool check_extent(struct lowering *lw, struct span at, const char *what, double extent)
{
	if (extent <= MAX_EXTENT)
		return true;
	diag_error(lw->diag, at, "%s reaches %g from the origin, beyond the limit of 1e100 (its arithmetic would overflow)",
	           what, extent);
	return false;
}

static double extent_of(struct vec3 p)
{
	return vmaxc(vabs(p));
}

/* Adds a triangle unless it has no area (NUMERICS.md section 5), to the scene's or, with
 * part, to the mesh parts' triangles; returns whether it did. */
static bool add_triangle(struct lowering *lw, const uint32_t v[3], const uint32_t n[3], uint32_t surface, bool part)
{
	struct scene *sc = lw->sc;
	struct vec3 a = sc->geo.vertices[v[0]], b = sc->geo.vertices[v[1]], c = sc->geo.vertices[v[2]];
	struct vec3 area = vcross(vsub(b, a), vsub(c, a));
	if (vzero(area) || !isfinite(area.x) || !isfinite(area.y) || !isfinite(area.z))
		return false;
	struct triangle **list = part ? &sc->geo.part_triangles : &sc->geo.triangles;
	size_t *n_list = part ? &sc->geo.npart_triangles : &sc->geo.ntriangles;
	xgrow((void **)list, part ? &lw->cap_part_triangles : &lw->cap_triangles, *n_list + 1, sizeof **list);
	struct triangle *t = &(*list)[(*n_list)++];
	memcpy(t->v, v, sizeof t->v);
	memcpy(t->n, n, sizeof t->n);
	t->surface = surface;
	return true;
}

/* The cache entry of a file already read, or NULL. */
static struct mesh_cache_entry *mesh_cached(struct lowering *lw, const char *path)
{
	for (size_t i = 0; i < lw->nmesh_cache; i++)
		if (strcmp(lw->mesh_cache[i].path, path) == 0)
			return &lw->mesh_cache[i];
	return NULL;
}

/* The mesh data of a file (read once however many objects use it), or NULL after an error. */
static const struct mesh_data *mesh_file(struct lowering *lw, const struct mesh_desc *m)
{
	struct mesh_cache_entry *entry = mesh_cached(lw, m->path);
	if (entry)
		return entry->ok ? &entry->data : NULL;
	xgrow((void **)&lw->mesh_cache, &lw->cap_mesh_cache, lw->nmesh_cache + 1, sizeof *lw->mesh_cache);
	entry = &lw->mesh_cache[lw->nmesh_cache++];
	memset(entry, 0, sizeof *entry);
	entry->path = m->path;
	entry->source[0] = entry->source[1] = -1;
	char err[512];
	double t0 = clock_now();
	int rc = mesh_import(m->path, &entry->data, err, sizeof err);
	entry->ok = rc == 0;
	lw->too_big = lw->too_big || rc == ENOMEM;
	lw->mesh_seconds += clock_now() - t0;
	if (!entry->ok)
		diag_error(lw->diag, m->file_span, "%s", err);
	return entry->ok ? &entry->data : NULL;
}

/* The data of mesh object o: its file's (read once) or its inline arrays in *inline_data;
 * NULL after an error. */
static const struct mesh_data *mesh_data_of(struct lowering *lw, const struct object_desc *o,
                                            struct mesh_data *inline_data)
{
	const struct mesh_desc *m = &lw->desc->meshes[o->u.mesh.index];
	*inline_data = (struct mesh_data){
		.vertices = m->vertices, .nvertices = m->nvertices, .normals = m->normals,
		.nnormals = m->nnormals, .faces = m->faces, .nfaces = m->nfaces, .uvs = m->uvs,
	};
	return m->file ? mesh_file(lw, m) : inline_data;
}

/* Whether the render fits the machine's memory: other_bytes, the objects, and each mesh
 * object's triangles and vertices (every file read here, once), with the BVH over them,
 * counted before any of it is built. If not, an error at the mesh object where the count
 * passes what there is (or about the scene, when it is not a mesh), saying what the whole
 * needs and what there is. */
static bool scene_fits(struct lowering *lw, int64_t other_bytes)
{
	const struct scene_desc *desc = lw->desc;
	const char *limit_is;
	uint64_t limit = memory_available(&limit_is);
	uint64_t total = (uint64_t)other_bytes + scene_bytes(desc->nobjects, 0, 0);
	const struct object_desc *at = NULL;
	size_t triangles = 0, vertices = 0;
	for (size_t i = 0; i < desc->nobjects; i++) {
		const struct object_desc *o = &desc->objects[i];
		struct mesh_data inline_data;
		const struct mesh_data *data = o->kind == OBJ_MESH ? mesh_data_of(lw, o, &inline_data) : NULL;
		if (!data)
			continue;
		triangles += data->nfaces;
		vertices += data->nvertices;
		total = (uint64_t)other_bytes + scene_bytes(desc->nobjects + triangles, triangles, vertices);
		if (!at && total > limit)
			at = o;
	}
	if (lw->too_big)
		return false;
	if (total <= limit)
		return true;
	char need[32], have[32];
	memory_text(total, need, sizeof need);
	memory_text(limit, have, sizeof have);
	if (at)
		diag_error(lw->diag, at->span, "the render needs %s for %zu triangles, their BVH and the image; %s %s "
		           "(this mesh passes it)", need, triangles, limit_is, have);
	else
		diag_plain(lw->diag, DIAG_ERROR, "the render needs %s for %zu objects, their BVH and the image; %s %s",
		           need, desc->nobjects, limit_is, have);
	return false;
}

/* Records that mesh file object o made surface, placed by x (inverse inv). */
static void add_mesh_use(struct lowering *lw, const struct object_desc *o, uint32_t surface, const struct xform *x,
                         const struct affine *inv, bool mirrored, size_t first)
{
	struct scene *sc = lw->sc;
	int32_t *source = &mesh_cached(lw, lw->desc->meshes[o->u.mesh.index].path)->source[o->smooth];
	if (*source < 0)
		*source = (int32_t)sc->nmesh_sources++;
	xgrow((void **)&sc->mesh_uses, &lw->cap_mesh_uses, sc->nmesh_uses + 1, sizeof *sc->mesh_uses);
	struct mesh_use *u = &sc->mesh_uses[sc->nmesh_uses++];
	*u = (struct mesh_use){ .surface = surface, .mesh = (uint32_t)*source, .mirrored = mirrored, .to_object = *inv,
	                        .first = first, .last = sc->geo.ntriangles };
	memcpy(u->to_world.m, x->m, sizeof u->to_world.m);
}

/* Whether two of a triangle's corners are one point; a triangle without area whose
 * corners are apart has them on one line. */
static bool corners_coincide(struct vec3 a, struct vec3 b, struct vec3 c)
{
	return vzero(vsub(a, b)) || vzero(vsub(b, c)) || vzero(vsub(c, a));
}

/* Warns at `at` that dropped of a mesh's nfaces triangles have no area: coinciding of
 * them because two corners are one point (a file's face that repeats a vertex, as assimp
 * makes of an OFF face line without its indices), the others because their corners are on
 * one line. When none is left, it says that the mesh is not drawn, since the image then
 * simply lacks it. */
static void warn_no_area(struct lowering *lw, struct span at, size_t dropped, size_t coinciding, size_t nfaces)
{
	char why[96] = "", line[64] = "";
	size_t apart = dropped - coinciding;
	if (apart)
		snprintf(line, sizeof line, "%zu %s corners on one line", apart, apart == 1 ? "has its" : "have their");
	if (coinciding)
		snprintf(why, sizeof why, "%zu %s coinciding corners%s%s", coinciding, coinciding == 1 ? "has" : "have",
		         apart ? ", " : "", line);
	else
		snprintf(why, sizeof why, "%s", line);
	if (dropped == nfaces)
		diag_warning(lw->diag, at, "this mesh is not drawn: none of its %zu triangles has an area (%s)", nfaces, why);
	else
		diag_warning(lw->diag, at, "%zu of this mesh's %zu triangles have no area and are not drawn (%s)", dropped,
		             nfaces, why);
}

/* Mesh object o, as triangles of the scene, or with part (a solid's part, whose inside
 * its inside_vector decides) as the triangles of that mesh part, whose range it sets;
 * false when it is not drawn. */
/* The scene material of a mesh file's material mm (LANGUAGE.md 11): its colours, its
 * opacity as transmit, and its diffuse texture, if any, looked up by the file's UVs; the
 * texture replaces the diffuse colour, as in POV-Ray's twin (an image map cannot be
 * multiplied by a colour there). */
static struct material file_material(struct lowering *lw, const struct mesh_desc *m, const struct mesh_data *data,
                                     const struct mesh_material *mm, struct span at)
{
	struct material out = {
		.diffuse = v3a(mm->diffuse), .pigment = MATERIAL_COLOR, .texture = -1, .bump = -1,
		.specular = v3a(mm->specular), .shininess = mm->exponent, .transmit = v3s(1 - mm->opacity),
		.ior = mm->ior, .emit = v3a(mm->emission),
	};
	if (!mm->texture)
		return out;
	if (!data->uvs) {
		diag_warning(lw->diag, at, "mesh file '%s' gives texture '%s' but no texture coordinates: its diffuse "
		             "colour is used instead", m->file, mm->texture);
		return out;
	}
	if (!mm->texture_path && !mm->texture_data) {
		diag_error(lw->diag, at, "cannot read texture '%s' of mesh file '%s': it is embedded as %s, and only "
		           "PNG can be", mm->texture, m->file, *mm->texture_format ? mm->texture_format : "raw texels");
		return out;
	}
	/* an embedded texture is known by its file and its name there */
	char *key = NULL;
	if (mm->texture_data) {
		key = xmalloc(strlen(m->path) + strlen(mm->texture) + 2);
		sprintf(key, "%s#%s", m->path, mm->texture);
	}
	int32_t im = lower_texture_mesh_image(&lw->tex, key ? key : mm->texture_path, mm->texture_data, mm->texture_size,
	                                      mm->texture, m->file, m->bilinear, at);
	free(key);
	if (im >= 0) {
		out.pigment = MATERIAL_IMAGE;
		out.texture = im;
	}
	return out;
}

/* The scene material of material k of the file of mesh object o, made on first use. */
static uint32_t file_material_of(struct lowering *lw, const struct object_desc *o, uint32_t k)
{
	const struct mesh_desc *m = &lw->desc->meshes[o->u.mesh.index];
	struct mesh_cache_entry *entry = mesh_cached(lw, m->path);
	int32_t **slots = &entry->materials[m->bilinear];
	if (!*slots) {
		*slots = xmalloc(entry->data.nmaterials * sizeof **slots);
		for (size_t i = 0; i < entry->data.nmaterials; i++)
			(*slots)[i] = -1;
	}
	if ((*slots)[k] < 0) {
		struct scene *sc = lw->sc;
		xgrow((void **)&sc->materials, &lw->cap_materials, sc->nmaterials + 1, sizeof *sc->materials);
		sc->materials[sc->nmaterials] = file_material(lw, m, &entry->data, &entry->data.materials[k], m->file_span);
		(*slots)[k] = (int32_t)sc->nmaterials++;
	}
	return (uint32_t)(*slots)[k];
}

/* Whether object o's material is an image map looked up by UV coordinates. */
static bool maps_uv(const struct lowering *lw, const struct object_desc *o)
{
	if (o->material < 0)
		return false;
	const struct material_desc *m = &lw->desc->materials[o->material];
	return m->pigment == PIGMENT_IMAGE && lw->desc->images[m->pattern].map == IMAGE_MAP_UV;
}

/* The texture coordinates of mesh data (its vertices from base on) into geo.uvs, the
 * vertices before them without any; false, after an error at o, when o's material needs
 * them and there are none, or the mesh is a CSG's part, whose hits carry no triangle. */
static bool mesh_uvs(struct lowering *lw, const struct object_desc *o, const struct mesh_data *data, uint32_t base,
                     bool part)
{
	struct geometry *g = &lw->sc->geo;
	if (maps_uv(lw, o) && (part || !data->uvs)) {
		const struct mesh_desc *m = &lw->desc->meshes[o->u.mesh.index];
		if (part)
			diag_error(lw->diag, o->span, "'map uv' is not available on a mesh inside a CSG; use another map");
		else
			diag_error(lw->diag, o->span, "'map uv' needs texture coordinates, and mesh file '%s' has none", m->file);
		return false;
	}
	if (!data->uvs || part)
		return true;
	xgrow((void **)&g->uvs, &lw->cap_uvs, g->nvertices, sizeof *g->uvs);
	memset(&g->uvs[g->nuvs], 0, (base - g->nuvs) * sizeof *g->uvs);
	for (size_t i = 0; i < data->nvertices; i++)
		g->uvs[base + i] = (struct uv){ data->uvs[i][0], data->uvs[i][1] };
	g->nuvs = g->nvertices;
	return true;
}

static bool lower_mesh(struct lowering *lw, const struct object_desc *o, const struct span *at, struct part *part)
{
	struct mesh_data inline_data;
	const struct mesh_data *data = mesh_data_of(lw, o, &inline_data);
	if (!data)
		return false;
	struct scene *sc = lw->sc;
	static const struct xform identity = { { { 1, 0, 0, 0 }, { 0, 1, 0, 0 }, { 0, 0, 1, 0 } } };
	const struct xform *x = o->xform >= 0 ? &lw->desc->xforms[o->xform] : &identity;
	struct affine inv = xform_inverse(x);
	bool mirrored = xform_mirrors(x);
	uint32_t surface = add_surface(lw, o);
	/* a file's own materials, unless the mesh statement gives one: a surface for each
	 * (LANGUAGE.md 11), made when a face first uses it */
	bool own = data->face_material && (o->material < 0 || o->inherited) && !part;
	uint32_t *file_surfaces = NULL;
	if (own) {
		file_surfaces = xmalloc(data->nmaterials * sizeof *file_surfaces);
		for (size_t k = 0; k < data->nmaterials; k++)
			file_surfaces[k] = UINT32_MAX;
	}
	uint32_t base = (uint32_t)sc->geo.nvertices;
	double extent = 0;
	for (size_t i = 0; i < data->nvertices; i++) {
		uint32_t v = add_vertex(lw, xform_point(x, v3a(data->vertices[i])));
		extent = fmax(extent, extent_of(sc->geo.vertices[v]));
	}
	/* beyond it, its triangles' areas are lost to rounding: not the file's fault */
	if (!check_extent(lw, *at, "this mesh", extent) || !mesh_uvs(lw, o, data, base, part != NULL)) {
		free(file_surfaces);
		return false;
	}

	uint32_t nbase = (uint32_t)sc->geo.nnormals;
	if (o->smooth) {
		xgrow((void **)&sc->geo.normals, &lw->cap_normals, sc->geo.nnormals + data->nvertices, sizeof *sc->geo.normals);
		struct vec3 *normals = &sc->geo.normals[nbase];
		if (data->nnormals == data->nvertices && data->normals) {
			for (size_t i = 0; i < data->nvertices; i++)
				normals[i] = affine_normal(&inv, v3a(data->normals[i]));
		} else {
			/* area-weighted: the unnormalised face normal is twice the face's area */
			memset(normals, 0, data->nvertices * sizeof *normals);
			for (size_t f = 0; f < data->nfaces; f++) {
				const uint32_t *v = data->faces[f];
				struct vec3 a = sc->geo.vertices[base + v[0]], b = sc->geo.vertices[base + v[1]], c = sc->geo.vertices[base + v[2]];
				struct vec3 fn = vcross(vsub(b, a), vsub(c, a));
				if (mirrored)
					fn = vneg(fn);
				for (int k = 0; k < 3; k++)
					normals[v[k]] = vadd(normals[v[k]], fn);
			}
		}
		for (size_t i = 0; i < data->nvertices; i++) {
			double len = vlen(normals[i]);
			normals[i] = len > 0 && isfinite(len) ? vscale(normals[i], 1 / len) : v3s(0);
		}
		sc->geo.nnormals += data->nvertices;
	}
	size_t dropped = 0, coinciding = 0, first = part ? sc->geo.npart_triangles : sc->geo.ntriangles;
	for (size_t f = 0; f < data->nfaces; f++) {
		uint32_t v[3], n[3] = { TRIANGLE_FLAT, TRIANGLE_FLAT, TRIANGLE_FLAT };
		for (int k = 0; k < 3; k++) {
			v[k] = base + data->faces[f][k];
			if (o->smooth)
				n[k] = nbase + data->faces[f][k];
		}
		/* a vertex without a usable normal (all its faces degenerate): shade the face flat */
		if (o->smooth && (vzero(sc->geo.normals[n[0]]) || vzero(sc->geo.normals[n[1]]) || vzero(sc->geo.normals[n[2]])))
			n[0] = n[1] = n[2] = TRIANGLE_FLAT;
		if (mirrored) {
			uint32_t t = v[1], tn = n[1];
			v[1] = v[2], n[1] = n[2];
			v[2] = t, n[2] = tn;
		}
		uint32_t face_surface = surface;
		uint32_t k = own ? data->face_material[f] : MESH_NO_MATERIAL;
		if (k != MESH_NO_MATERIAL) {
			if (file_surfaces[k] == UINT32_MAX)
				file_surfaces[k] = add_surface_of(lw, o, file_material_of(lw, o, k));
			face_surface = file_surfaces[k];
		}
		if (!add_triangle(lw, v, n, face_surface, part != NULL)) {
			dropped++;
			coinciding += corners_coincide(sc->geo.vertices[v[0]], sc->geo.vertices[v[1]], sc->geo.vertices[v[2]]);
		}
	}
	free(file_surfaces);
	if (dropped)
		warn_no_area(lw, *at, dropped, coinciding, data->nfaces);
	if (part) {
		const struct mesh_desc *m = &lw->desc->meshes[o->u.mesh.index];
		struct affine xa = affine_of(x);
		struct vec3 w = vunit(affine_vector(&xa, v3a(m->inside_vector)));
		*part = (struct part){ .kind = PART_MESH, .surface = surface, .first = (uint32_t)first,
		                       .count = (uint32_t)(sc->geo.npart_triangles - first), .a = { w.x, w.y, w.z } };
		return part->count > 0;
	}
	if (lw->desc->meshes[o->u.mesh.index].file)
		add_mesh_use(lw, o, surface, x, &inv, mirrored, first);
	return true;
}

/* The index of the object after object i and its members. */
static size_t next_object(const struct scene_desc *d, size_t i)
{
	return i + 1 + (d->objects[i].kind == OBJ_CSG ? d->objects[i].u.csg.size : 0);
}

static const char *const object_names[] = {
	[OBJ_SPHERE] = "sphere", [OBJ_PLANE] = "plane", [OBJ_BOX] = "box", [OBJ_CYLINDER] = "cylinder",
	[OBJ_CONE] = "cone", [OBJ_DISC] = "disc", [OBJ_TORUS] = "torus", [OBJ_CSG] = "CSG",
	[OBJ_TRIANGLE] = "triangle", [OBJ_MESH] = "mesh",
};

static uint32_t add_part(struct lowering *lw, const struct part *p)
{
	struct geometry *g = &lw->sc->geo;
	xgrow((void **)&g->parts, &lw->cap_parts, g->nparts + 1, sizeof *g->parts);
	g->parts[g->nparts] = *p;
	return (uint32_t)g->nparts++;
}

static int64_t lower_part(struct lowering *lw, size_t i, bool invert);

/* The CSG node of object i, with inversion pushed down to its leaves as POV-Ray inverts a
 * CSG (De Morgan): an inverse union or merge is the intersection of its inverted members,
 * an inverse intersection the merge of its inverted members, and a difference the
 * intersection of its first member and its other members inverted. -1 when it is empty. */
static int64_t lower_csg(struct lowering *lw, size_t i, bool invert)
{
	const struct scene_desc *d = lw->desc;
	const struct object_desc *o = &d->objects[i];
	bool inv = o->inverse != invert;
	struct part node = { .kind = PART_CSG };
	switch (o->u.csg.op) {
	case CSG_UNION: node.op = inv ? PART_INTERSECT : PART_ALL; break;
	case CSG_MERGE: node.op = inv ? PART_INTERSECT : PART_MERGE; break;
	case CSG_INTERSECTION: node.op = inv ? PART_MERGE : PART_INTERSECT; break;
	case CSG_DIFFERENCE: node.op = inv ? PART_MERGE : PART_INTERSECT; break;
	}
	uint32_t *kids = xmalloc(o->u.csg.size * sizeof *kids), n = 0;
	bool empty = false;
	for (size_t j = i + 1; j < next_object(d, i); j = next_object(d, j)) {
		bool cutter = o->u.csg.op == CSG_DIFFERENCE && j != i + 1;
		int64_t k = lower_part(lw, j, cutter != inv);
		if (k >= 0)
			kids[n++] = (uint32_t)k;
		else
			empty |= node.op == PART_INTERSECT; /* nothing intersected with something */
	}
	int64_t index = -1;
	if (n && !empty) {
		struct geometry *g = &lw->sc->geo;
		xgrow((void **)&g->members, &lw->cap_members, g->nmembers + n, sizeof *g->members);
		memcpy(g->members + g->nmembers, kids, n * sizeof *kids);
		node.first = (uint32_t)g->nmembers;
		node.count = n;
		g->nmembers += n;
		index = add_part(lw, &node);
	}
	free(kids);
	return index;
}

/* The part tree of object i (a solid, or a disc or an open cylinder or cone at the top),
 * inverted when invert; its root's index, or -1 when it is not drawn (with a warning when
 * a transform makes it too small or too large to compute with). */
static int64_t lower_part(struct lowering *lw, size_t i, bool invert)
{
	const struct object_desc *o = &lw->desc->objects[i];
	struct affine x = o->xform >= 0 ? affine_of(&lw->desc->xforms[o->xform]) : affine_identity;
	struct part p;
	bool ok = true;
	switch (o->kind) {
	case OBJ_SPHERE:
		ok = part_make_sphere(&p, v3a(o->u.sphere.center), o->u.sphere.radius, &x);
		break;
	case OBJ_PLANE:
		ok = part_make_plane(&p, v3a(o->u.plane.normal), o->u.plane.offset, &x);
		break;
	case OBJ_BOX:
		ok = part_make_box(&p, v3a(o->u.box.corner[0]), v3a(o->u.box.corner[1]), &x);
		break;
	case OBJ_CYLINDER: case OBJ_CONE:
		ok = part_make_cone(&p, v3a(o->u.cone.base), o->u.cone.radius[0], v3a(o->u.cone.cap), o->u.cone.radius[1],
		                    o->open, &x);
		break;
	case OBJ_DISC:
		ok = part_make_disc(&p, v3a(o->u.disc.center), v3a(o->u.disc.normal), o->u.disc.radius, o->u.disc.hole, &x);
		break;
	case OBJ_TORUS:
		ok = part_make_torus(&p, o->u.torus.major, o->u.torus.minor, &x);
		break;
	case OBJ_CSG:
		return lower_csg(lw, i, invert);
	case OBJ_MESH:
		if (!lower_mesh(lw, o, &o->span, &p))
			return -1;
		p.inverse = o->inverse != invert;
		return add_part(lw, &p);
	case OBJ_TRIANGLE: /* not a solid: the checks let none through */
		return -1;
	}
	if (!ok) {
		diag_warning(lw->diag, o->span, "this %s's transforms make it too small or too large to compute with: "
		             "it is not drawn", object_names[o->kind]);
		return -1;
	}
	p.inverse = o->inverse != invert;
	p.surface = add_surface(lw, o);
	return add_part(lw, &p);
}

/* Object i as a solid of the scene: its part tree, bounded or not. */
static void lower_solid(struct lowering *lw, size_t i)
{
	const struct object_desc *o = &lw->desc->objects[i];
	struct geometry *g = &lw->sc->geo;
	size_t first_part = g->nparts;
	int64_t root = lower_part(lw, i, false);
	if (root < 0)
		return;
	struct vec3 slo, shi;
	csg_bound(g, (uint32_t)root, &slo, &shi);
	/* the nodes' member orders and hierarchies, members before the nodes they are in (the
	 * order lower_part made them in) */
	for (size_t k = first_part; k < g->nparts; k++)
		if (g->parts[k].kind == PART_CSG) {
			size_t room = 2 * (size_t)g->parts[k].count;
			xgrow((void **)&g->csg_boxes, &lw->cap_csg_boxes, g->ncsg_boxes + room, sizeof *g->csg_boxes);
			g->ncsg_boxes += csg_tree_build(g, &g->parts[k], g->csg_boxes + g->ncsg_boxes, (uint32_t)g->ncsg_boxes);
		}
	struct vec3 lo = g->parts[root].lo, hi = g->parts[root].hi;
	if (lo.x > hi.x || lo.y > hi.y || lo.z > hi.z) {
		diag_warning(lw->diag, o->span, "this %s is empty: its members do not overlap", object_names[o->kind]);
		return;
	}
	double extent = fmax(vmaxc(vabs(lo)), vmaxc(vabs(hi)));
	if (isfinite(extent)) {
		check_extent(lw, o->span, "this object", extent);
		xgrow((void **)&g->solids, &lw->cap_solids, g->nsolids + 1, sizeof *g->solids);
		g->solids[g->nsolids++] = (uint32_t)root;
	} else {
		xgrow((void **)&g->unbounded, &lw->cap_unbounded, g->nunbounded + 1, sizeof *g->unbounded);
		g->unbounded[g->nunbounded++] = (uint32_t)root;
	}
}

/* Whether x scales every direction alike (rotations, mirrors and uniform scales): its
 * columns orthogonal and of one length, up to rounding. A sphere under it stays a sphere. */
static bool conformal(const struct xform *x)
{
	double c[3][3], len[3];
	for (int j = 0; j < 3; j++) {
		for (int i = 0; i < 3; i++)
			c[j][i] = x->m[i][j];
		len[j] = sqrt(c[j][0] * c[j][0] + c[j][1] * c[j][1] + c[j][2] * c[j][2]);
	}
	const double tol = 1e-12;
	for (int j = 0; j < 3; j++) {
		int k = (j + 1) % 3;
		if (fabs(len[j] - len[k]) > tol * len[j] ||
		    fabs(c[j][0] * c[k][0] + c[j][1] * c[k][1] + c[j][2] * c[k][2]) > tol * len[j] * len[k])
			return false;
	}
	return true;
}

/* Object i of the scene's top level, or of a union there: a union is not an object of
 * its own (POV-Ray's split_union), but a union under inverse is a solid. */
static void lower_object(struct lowering *lw, size_t i)
{
	struct scene *sc = lw->sc;
	const struct object_desc *o = &lw->desc->objects[i];
	static const struct xform identity = { { { 1, 0, 0, 0 }, { 0, 1, 0, 0 }, { 0, 0, 1, 0 } } };
	const struct xform *x = o->xform >= 0 ? &lw->desc->xforms[o->xform] : &identity;
	bool solid = o->inverse || (o->kind == OBJ_SPHERE && !conformal(x)) ||
	             (o->kind != OBJ_SPHERE && o->kind != OBJ_PLANE && o->kind != OBJ_TRIANGLE && o->kind != OBJ_MESH);
	if (o->kind == OBJ_CSG && o->u.csg.op == CSG_UNION && !o->inverse) {
		for (size_t j = i + 1; j < next_object(lw->desc, i); j = next_object(lw->desc, j))
			lower_object(lw, j);
		return;
	}
	if (solid) {
		lower_solid(lw, i);
		return;
	}
	switch (o->kind) {
	case OBJ_SPHERE: {
		/* a scale alike in every direction: any column's length is the scale */
		double scale = hypot(hypot(x->m[0][0], x->m[1][0]), x->m[2][0]); /* no underflow at 1e-250 */
		struct sphere s = { xform_point(x, v3a(o->u.sphere.center)), o->u.sphere.radius * scale, 0 };
		check_extent(lw, o->span, "this sphere", extent_of(s.center) + s.radius);
		if (!(s.radius >= MIN_RADIUS)) {
			diag_warning(lw->diag, o->span,
			             "this sphere's radius is %g, below 1e-100, too small to compute with: it is not drawn",
			             s.radius);
			break;
		}
		s.surface = add_surface(lw, o);
		xgrow((void **)&sc->geo.spheres, &lw->cap_spheres, sc->geo.nspheres + 1, sizeof *sc->geo.spheres);
		sc->geo.spheres[sc->geo.nspheres++] = s;
		break;
	}
	case OBJ_PLANE: {
		/* the world normal and offset, as a plane part has them */
		struct part world;
		struct affine xa = affine_of(x);
		part_make_plane(&world, v3a(o->u.plane.normal), o->u.plane.offset, &xa);
		xgrow((void **)&sc->geo.planes, &lw->cap_planes, sc->geo.nplanes + 1, sizeof *sc->geo.planes);
		struct plane *p = &sc->geo.planes[sc->geo.nplanes++];
		p->normal = v3(world.a[0], world.a[1], world.a[2]);
		p->offset = world.a[3];
		p->surface = add_surface(lw, o);
		check_extent(lw, o->span, "this plane", fabs(p->offset));
		break;
	}
	case OBJ_TRIANGLE: {
		uint32_t v[3], n[3] = { TRIANGLE_FLAT, TRIANGLE_FLAT, TRIANGLE_FLAT };
		double extent = 0;
		for (int k = 0; k < 3; k++) {
			v[k] = add_vertex(lw, xform_point(x, v3a(o->u.triangle.v[k])));
			extent = fmax(extent, extent_of(sc->geo.vertices[v[k]]));
		}
		check_extent(lw, o->span, "this triangle", extent);
		if (xform_mirrors(x)) {
			uint32_t t = v[1];
			v[1] = v[2];
			v[2] = t;
		}
		uint32_t surface = add_surface(lw, o);
		if (!add_triangle(lw, v, n, surface, false))
			sc->geo.nvertices -= 3; /* eval.c warned already */
		break;
	}
	case OBJ_MESH:
		lower_mesh(lw, o, &o->span, NULL);
		break;
	default:
		break;
	}
}

static bool lower_sky(struct lowering *lw)
{
	const struct skybox_desc *k = &lw->desc->skybox;
	struct sky *sky = &lw->sc->sky;
	sky->intensity = k->intensity;
	switch (k->kind) {
	case SKY_NONE:
		sky->kind = SKY_BLACK;
		return true;
	case SKY_COLOR:
		sky->kind = SKY_CONSTANT;
		sky->color = v3a(k->color);
		return true;
	case SKY_GRADIENT:
		sky->kind = SKY_ZENITH_HORIZON;
		sky->color = v3a(k->color);
		sky->horizon = v3a(k->horizon);
		return true;
	case SKY_IMAGE: {
		struct image *img;
		char err[512];
		int e = image_read(k->image_path, &img, err, sizeof err);
		if (e != 0) {
			lw->too_big = lw->too_big || e == ENOMEM;
			diag_error(lw->diag, k->span, "cannot read the skybox image: %s", err);
			return false;
		}
		sky->kind = SKY_LATLONG;
		sky->width = img->width;
		sky->height = img->height;
		sky->texels = img->rgb;
		sky->file = img->source;
		img->rgb = NULL;
		image_free(img);
		sky->rot_sin = sin(k->rotate * (M_PI / 180));
		sky->rot_cos = cos(k->rotate * (M_PI / 180));
		return true;
	}
	}
	return true;
}

/* Warns about point lights inside a sphere or another solid: they light nothing outside
 * it unless it transmits. */
static void warn_enclosed_lights(struct lowering *lw)
{
	const struct scene_desc *d = lw->desc;
	const struct scene *sc = lw->sc;
	for (size_t i = 0; i < d->nlights; i++) {
		if (d->lights[i].directional)
			continue;
		struct vec3 p = v3a(d->lights[i].vec);
		bool warned = false;
		for (size_t s = 0; s < sc->geo.nspheres && !warned; s++)
			if (vlen(vsub(p, sc->geo.spheres[s].center)) < sc->geo.spheres[s].radius) {
				diag_warning(lw->diag, d->lights[i].span, "this light is inside a sphere");
				warned = true;
			}
		for (size_t s = 0; s < sc->geo.nsolids + sc->geo.nunbounded && !warned; s++) {
			uint32_t root = s < sc->geo.nsolids ? sc->geo.solids[s] : sc->geo.unbounded[s - sc->geo.nsolids];
			const struct part *top = &sc->geo.parts[root];
			bool flat = top->kind == PART_DISC || (top->kind == PART_CONE && top->open); /* no inside */
			if (!flat && csg_inside(&sc->geo, root, p)) {
				diag_warning(lw->diag, d->lights[i].span, "this light is inside a solid object");
				warned = true;
			}
		}
	}
}

/* For a render: warns when the image can show nothing but the sky, as an empty scene or
 * one without light would otherwise render black without a word. */
static void warn_dark(struct lowering *lw)
{
	const struct scene *sc = lw->sc;
	if (!sc->geo.nspheres && !sc->geo.nplanes && !sc->geo.ntriangles && !sc->geo.nsolids && !sc->geo.nunbounded) {
		diag_plain(lw->diag, DIAG_WARNING, "the scene has no objects: its image is the sky alone");
		return;
	}
	if (sc->nlights)
		return;
	for (size_t i = 0; i < sc->nmaterials; i++)
		if (!vzero(sc->materials[i].emit))
			return;
	diag_plain(lw->diag, DIAG_WARNING,
	           "the scene has no lights and no material emits: its objects show only the sky they reflect"
	           " or transmit");
}

enum load_status lower_scene(struct diag *d, const struct scene_desc *desc, struct scene *out,
                            struct lower_times *times, int64_t other_bytes)
{
	memset(out, 0, sizeof *out);
	memset(times, 0, sizeof *times);
	struct lowering lw = { .diag = d, .desc = desc, .sc = out, .default_material = -1 };
	int errors = d->errors;
	bool too_big = other_bytes >= 0 && !scene_fits(&lw, other_bytes);

	const struct camera_desc *c = &desc->camera;
	camera_setup(&out->camera, v3a(c->location), v3a(c->look_at), v3a(c->up), c->fov, c->width, c->height);
	check_extent(&lw, c->span, "the camera", fmax(extent_of(v3a(c->location)), extent_of(v3a(c->look_at))));
	out->lights = xcalloc(desc->nlights, sizeof *out->lights);
	for (size_t i = 0; i < desc->nlights; i++) {
		const struct light_desc *l = &desc->lights[i];
		struct light *li = &out->lights[out->nlights++];
		li->kind = l->directional ? LIGHT_DIRECTIONAL : LIGHT_POINT;
		li->pos = v3a(l->vec);
		li->to_light = l->directional ? vneg(vunit(v3a(l->vec))) : v3s(0);
		li->color = vscale(v3a(l->color), l->intensity);
		li->shadowless = l->shadowless;
		if (!l->directional)
			check_extent(&lw, l->span, "this light", extent_of(li->pos));
	}

	lower_texture_begin(&lw.tex, d, desc, out);
	lw.material_map = xmalloc((desc->nmaterials ? desc->nmaterials : 1) * sizeof *lw.material_map);
	for (size_t i = 0; i < desc->nmaterials; i++)
		lw.material_map[i] = -1;
	for (size_t i = 0; i < desc->nobjects && !too_big; i = next_object(desc, i))
		lower_object(&lw, i);
	/* the vertices added after the last mesh with UVs have none */
	if (out->geo.uvs) {
		xgrow((void **)&out->geo.uvs, &lw.cap_uvs, out->geo.nvertices, sizeof *out->geo.uvs);
		memset(&out->geo.uvs[out->geo.nuvs], 0, (out->geo.nvertices - out->geo.nuvs) * sizeof *out->geo.uvs);
		out->geo.nuvs = out->geo.nvertices;
	}
	out->geo.transmit = xcalloc(out->nmaterials, sizeof *out->geo.transmit);
	for (size_t m = 0; m < out->nmaterials; m++)
		out->geo.transmit[m] = out->materials[m].transmit;
	out->geo.ntransmit = out->nmaterials;
	times->load_meshes = lw.mesh_seconds;
	double t0 = clock_now();
	lower_sky(&lw);
	times->load_images = clock_now() - t0 + lw.tex.seconds;
	lw.too_big = lw.too_big || lw.tex.too_big;
	lower_texture_end(&lw.tex);

	static const enum sample_kind kinds[PATTERN_COUNT] = {
		[PATTERN_CENTER] = SAMPLE_CENTER, [PATTERN_GRID] = SAMPLE_GRID, [PATTERN_RANDOM] = SAMPLE_RANDOM,
		[PATTERN_JITTERED] = SAMPLE_JITTERED, [PATTERN_POISSON] = SAMPLE_POISSON,
	};
	out->sampling = (struct sampling){ desc->samples.count, kinds[desc->samples.pattern], desc->samples.seed,
	                                   desc->samples.target_error };
	out->max_depth = desc->max_depth;
	warn_enclosed_lights(&lw);
	if (other_bytes >= 0 && d->errors == errors)
		warn_dark(&lw);

	for (size_t i = 0; i < lw.nmesh_cache; i++) {
		mesh_import_free(&lw.mesh_cache[i].data);
		free(lw.mesh_cache[i].materials[0]);
		free(lw.mesh_cache[i].materials[1]);
	}
	free(lw.mesh_cache);
	free(lw.material_map);
	if (out->geo.nspheres + out->geo.ntriangles + out->geo.nplanes + out->geo.nsolids >= (1u << SHAPE_KIND_SHIFT) ||
	    out->geo.nunbounded >= SHAPE_UNBOUNDED) {
		diag_plain(d, DIAG_ERROR, "the scene has more than 2^30 primitives");
		return LOAD_SCENE_ERROR;
	}
	return too_big || lw.too_big ? LOAD_TOO_BIG : d->errors == errors ? LOAD_OK : LOAD_SCENE_ERROR;
}
