/* lower_add.c: the scene's parts that every kind of object adds: materials (only those
 * objects use, textures with them), surfaces, vertices and triangles, with the checks of
 * their extent. */
#include "lower_internal.h"

#include <math.h>
#include <string.h>

#include "xalloc.h"

/* The scene description's transform as the renderer's affine map (the same layout). */
struct affine lower_affine_of(const struct xform *x)
{
	struct affine a;
	memcpy(a.m, x->m, sizeof a.m);
	return a;
}

struct vec3 lower_xform_point(const struct xform *x, struct vec3 p)
{
	struct affine a = lower_affine_of(x);
	return affine_point(&a, p);
}

struct affine lower_xform_inverse(const struct xform *x)
{
	struct affine a = lower_affine_of(x);
	return affine_inverse(&a);
}

/* Whether x mirrors space: a triangle's corners then go the other way round, and are
 * swapped so that (B-A) x (C-A) still points to the side that was the outside (a
 * mirrored closed mesh stays solid). */
bool lower_xform_mirrors(const struct xform *x)
{
	struct affine a = lower_affine_of(x);
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
uint32_t lower_material_of(struct lowering *lw, int desc_index)
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
uint32_t lower_add_surface_of(struct lowering *lw, const struct object_desc *o, uint32_t mat)
{
	struct scene *sc = lw->sc;
	int32_t to_object = -1;
	if (material_textured(&sc->materials[mat]) && o->pattern_xform >= 0) {
		xgrow((void **)&sc->affines, &lw->cap_affines, sc->naffines + 1, sizeof *sc->affines);
		sc->affines[sc->naffines] = lower_xform_inverse(&lw->desc->xforms[o->pattern_xform]);
		to_object = (int32_t)sc->naffines++;
	}
	xgrow((void **)&sc->geo.surfaces, &lw->cap_surfaces, sc->geo.nsurfaces + 1, sizeof *sc->geo.surfaces);
	sc->geo.surfaces[sc->geo.nsurfaces] = (struct surface){ mat, to_object };
	return (uint32_t)sc->geo.nsurfaces++;
}

/* A surface of object o made of its material. */
uint32_t lower_add_surface(struct lowering *lw, const struct object_desc *o)
{
	return lower_add_surface_of(lw, o, lower_material_of(lw, o->material));
}

uint32_t lower_add_vertex(struct lowering *lw, struct vec3 v)
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

/* Reports what at `at` when it reaches extent from the origin (after its transforms);
 * returns whether it stays within the limit. */
bool lower_check_extent(struct lowering *lw, struct span at, const char *what, double extent)
{
	if (extent <= MAX_EXTENT)
		return true;
	diag_error(lw->diag, at, "%s reaches %g from the origin, beyond the limit of 1e100 (its arithmetic would overflow)",
	           what, extent);
	return false;
}

double lower_extent_of(struct vec3 p)
{
	return vmaxc(vabs(p));
}

/* Adds a triangle unless it has no area (NUMERICS.md section 5), to the scene's or, with
 * part, to the mesh parts' triangles; returns whether it did. */
bool lower_add_triangle(struct lowering *lw, const uint32_t v[3], const uint32_t n[3], uint32_t surface, bool part)
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
