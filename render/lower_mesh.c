/* lower_mesh.c: meshes into the scene: each file read once however many objects use it,
 * vertices and normals placed by the object's transforms, the file's UVs, and the file's
 * own materials per face when the mesh statement gives none (LANGUAGE.md 11). */
#include "lower_internal.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "clock.h"
#include "xalloc.h"

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
const struct mesh_data *lower_mesh_data(struct lowering *lw, const struct object_desc *o,
                                            struct mesh_data *inline_data)
{
	const struct mesh_desc *m = &lw->desc->meshes[o->u.mesh.index];
	*inline_data = (struct mesh_data){
		.vertices = m->vertices, .nvertices = m->nvertices, .normals = m->normals,
		.nnormals = m->nnormals, .faces = m->faces, .nfaces = m->nfaces, .uvs = m->uvs,
	};
	return m->file ? mesh_file(lw, m) : inline_data;
}

/* Records that mesh file object o made surface (and its faces triangles [first, the
 * current end)), placed by x (inverse inv). */
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

bool lower_mesh(struct lowering *lw, const struct object_desc *o, const struct span *at, struct part *part)
{
	struct mesh_data inline_data;
	const struct mesh_data *data = lower_mesh_data(lw, o, &inline_data);
	if (!data)
		return false;
	struct scene *sc = lw->sc;
	static const struct xform identity = { { { 1, 0, 0, 0 }, { 0, 1, 0, 0 }, { 0, 0, 1, 0 } } };
	const struct xform *x = o->xform >= 0 ? &lw->desc->xforms[o->xform] : &identity;
	struct affine inv = lower_xform_inverse(x);
	bool mirrored = lower_xform_mirrors(x);
	uint32_t surface = lower_add_surface(lw, o);
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
		uint32_t v = lower_add_vertex(lw, lower_xform_point(x, v3a(data->vertices[i])));
		extent = fmax(extent, lower_extent_of(sc->geo.vertices[v]));
	}
	/* beyond it, its triangles' areas are lost to rounding: not the file's fault */
	if (!lower_check_extent(lw, *at, "this mesh", extent) || !mesh_uvs(lw, o, data, base, part != NULL)) {
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
				file_surfaces[k] = lower_add_surface_of(lw, o, file_material_of(lw, o, k));
			face_surface = file_surfaces[k];
		}
		if (!lower_add_triangle(lw, v, n, face_surface, part != NULL)) {
			dropped++;
			coinciding += corners_coincide(sc->geo.vertices[v[0]], sc->geo.vertices[v[1]], sc->geo.vertices[v[2]]);
		}
	}
	free(file_surfaces);
	if (dropped)
		warn_no_area(lw, *at, dropped, coinciding, data->nfaces);
	if (part) {
		const struct mesh_desc *m = &lw->desc->meshes[o->u.mesh.index];
		struct affine xa = lower_affine_of(x);
		struct vec3 w = vunit(affine_vector(&xa, v3a(m->inside_vector)));
		*part = (struct part){ .kind = PART_MESH, .surface = surface, .first = (uint32_t)first,
		                       .count = (uint32_t)(sc->geo.npart_triangles - first), .a = { w.x, w.y, w.z } };
		return part->count > 0;
	}
	if (lw->desc->meshes[o->u.mesh.index].file)
		add_mesh_use(lw, o, surface, x, &inv, mirrored, first);
	return true;
}

void lower_mesh_release(struct lowering *lw)
{
	for (size_t i = 0; i < lw->nmesh_cache; i++) {
		mesh_import_free(&lw->mesh_cache[i].data);
		free(lw->mesh_cache[i].materials[0]);
		free(lw->mesh_cache[i].materials[1]);
	}
	free(lw->mesh_cache);
}
