/* lower.c: turns the evaluated scene_desc into the renderer's scene: world-space
 * geometry with transforms baked in, only the materials objects use, mesh files and sky
 * images loaded (each once). The objects, solids, lights and sky are here; meshes in
 * lower_mesh.c, what every object adds in lower_add.c, textures in lower_texture.c. */
#include "lower.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "camera.h"
#include "clock.h"
#include "image_file.h"
#include "light.h"
#include "lower_internal.h"
#include "memory.h"
#include "mesh_import.h"
#include "part_make.h"
#include "shape.h"
#include "xalloc.h"

/* A sphere below this radius, whose r^2 would underflow, is not drawn (with a warning): it
 * is valid, only too small to compute with, and too small to see. */
#define MIN_RADIUS 1e-100

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
		const struct mesh_data *data = o->kind == OBJ_MESH ? lower_mesh_data(lw, o, &inline_data) : NULL;
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
	struct affine x = o->xform >= 0 ? lower_affine_of(&lw->desc->xforms[o->xform]) : affine_identity;
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
	p.surface = lower_add_surface(lw, o);
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
		lower_check_extent(lw, o->span, "this object", extent);
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
		struct sphere s = { lower_xform_point(x, v3a(o->u.sphere.center)), o->u.sphere.radius * scale, 0 };
		lower_check_extent(lw, o->span, "this sphere", lower_extent_of(s.center) + s.radius);
		if (!(s.radius >= MIN_RADIUS)) {
			diag_warning(lw->diag, o->span,
			             "this sphere's radius is %g, below 1e-100, too small to compute with: it is not drawn",
			             s.radius);
			break;
		}
		s.surface = lower_add_surface(lw, o);
		xgrow((void **)&sc->geo.spheres, &lw->cap_spheres, sc->geo.nspheres + 1, sizeof *sc->geo.spheres);
		sc->geo.spheres[sc->geo.nspheres++] = s;
		break;
	}
	case OBJ_PLANE: {
		/* the world normal and offset, as a plane part has them */
		struct part world;
		struct affine xa = lower_affine_of(x);
		part_make_plane(&world, v3a(o->u.plane.normal), o->u.plane.offset, &xa);
		xgrow((void **)&sc->geo.planes, &lw->cap_planes, sc->geo.nplanes + 1, sizeof *sc->geo.planes);
		struct plane *p = &sc->geo.planes[sc->geo.nplanes++];
		p->normal = v3(world.a[0], world.a[1], world.a[2]);
		p->offset = world.a[3];
		p->surface = lower_add_surface(lw, o);
		lower_check_extent(lw, o->span, "this plane", fabs(p->offset));
		break;
	}
	case OBJ_TRIANGLE: {
		uint32_t v[3], n[3] = { TRIANGLE_FLAT, TRIANGLE_FLAT, TRIANGLE_FLAT };
		double extent = 0;
		for (int k = 0; k < 3; k++) {
			v[k] = lower_add_vertex(lw, lower_xform_point(x, v3a(o->u.triangle.v[k])));
			extent = fmax(extent, lower_extent_of(sc->geo.vertices[v[k]]));
		}
		lower_check_extent(lw, o->span, "this triangle", extent);
		if (lower_xform_mirrors(x)) {
			uint32_t t = v[1];
			v[1] = v[2];
			v[2] = t;
		}
		uint32_t surface = lower_add_surface(lw, o);
		if (!lower_add_triangle(lw, v, n, surface, false))
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

/* Light l's area { } into the scene's next area light (out->area_lights holds one per
 * light): its index. */
static int32_t lower_area_light(struct scene *out, const struct light_desc *l)
{
	struct area_light *a = &out->area_lights[out->narea_lights];
	for (int k = 0; k < 2; k++) {
		a->axis[k] = v3a(l->area_axis[k]);
		a->size[k] = l->area_size[k];
		a->inv_span[k] = a->size[k] > 1 ? 1.0 / (a->size[k] - 1) : 0;
		light_area_weights(a->size[k], a->weight[k]);
	}
	a->tests = 0;
	a->weight_sum = 0;
	for (int u = 0; u < a->size[0]; u++)
		for (int v = 0; v < a->size[1]; v++) /* as area_visibility adds them */
			if (a->weight[0][u] * a->weight[1][v] > 0) {
				a->tests++;
				a->weight_sum += a->weight[0][u] * a->weight[1][v];
			}
	a->jitter = l->area_jitter;
	a->orient = l->area_orient;
	a->circular = l->area_circular || l->area_orient; /* POV-Ray makes an oriented light circular */
	out->streams |= a->jitter;
	return (int32_t)out->narea_lights++;
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
	/* an orthographic view's rays start up to half its width and height from location */
	double view = 0;
	if (c->orthographic) {
		camera_set_orthographic(&out->camera, c->view_width);
		view = 0.5 * c->view_width * (1 + (double)c->height / c->width);
	}
	lower_check_extent(&lw, c->span, "the camera",
	                   fmax(lower_extent_of(v3a(c->location)), lower_extent_of(v3a(c->look_at))) + view);
	if (c->aperture > 0) {
		camera_set_lens(&out->camera, c->aperture, v3a(c->focal_point));
		out->streams = true;
	}
	if (desc->fog.given)
		out->fog = (struct fog){ desc->fog.distance, v3a(desc->fog.color) };
	out->lights = xcalloc(desc->nlights, sizeof *out->lights);
	out->area_lights = xcalloc(desc->nlights, sizeof *out->area_lights);
	for (size_t i = 0; i < desc->nlights; i++) {
		const struct light_desc *l = &desc->lights[i];
		struct light *li = &out->lights[out->nlights++];
		li->kind = l->directional ? LIGHT_DIRECTIONAL : LIGHT_POINT;
		li->pos = v3a(l->vec);
		li->to_light = l->directional ? vneg(vunit(v3a(l->vec))) : v3s(0);
		li->color = vscale(v3a(l->color), l->intensity);
		li->shadowless = l->shadowless;
		li->fade_distance = l->fade_distance;
		li->fade_power = l->fade_distance > 0 ? l->fade_power : 0; /* POV-Ray: no distance, no fade */
		li->area = l->area ? lower_area_light(out, l) : -1;
		li->spot = l->spot;
		if (l->spot) {
			li->point_at = v3a(l->point_at);
			li->axis = vunit(vsub(li->point_at, li->pos));
			li->radius = l->radius;
			li->falloff = l->falloff;
			li->cos_radius = cos(l->radius * (M_PI / 180));
			li->cos_falloff = cos(l->falloff * (M_PI / 180));
			li->tightness = l->tightness;
		}
		/* an area light's test points reach past its axes by half a cell when jittered */
		double reach = l->area ? vlen(v3a(l->area_axis[0])) + vlen(v3a(l->area_axis[1])) : 0;
		if (!l->directional)
			lower_check_extent(&lw, l->span, "this light", lower_extent_of(li->pos) + reach);
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

	lower_mesh_release(&lw);
	free(lw.material_map);
	if (out->geo.nspheres + out->geo.ntriangles + out->geo.nplanes + out->geo.nsolids >= (1u << SHAPE_KIND_SHIFT) ||
	    out->geo.nunbounded >= SHAPE_UNBOUNDED) {
		diag_plain(d, DIAG_ERROR, "the scene has more than 2^30 primitives");
		return LOAD_SCENE_ERROR;
	}
	return too_big || lw.too_big ? LOAD_TOO_BIG : d->errors == errors ? LOAD_OK : LOAD_SCENE_ERROR;
}
