/* scene_desc.c: defaults, release and the canonical dump of an evaluated scene. */
#include "scene_desc.h"

#include <stdlib.h>
#include <string.h>

static const char *const pattern_names[PATTERN_COUNT] = {
	"center", "grid", "random", "jittered", "poisson",
};

const char *scene_desc_pattern_name(enum sample_pattern p)
{
	return pattern_names[p];
}

/* ORDER PATTERN_NAME */
static const char *const texture_names[PAT_COUNT] = {
	"gradient", "radial", "onion", "wood", "marble", "leopard", "agate", "bozo", "granite", "spotted",
	"bumps", "dents", "ripples", "waves", "wrinkles",
};

const char *scene_desc_texture_name(enum pattern_name p)
{
	return texture_names[p];
}

int scene_desc_texture_lookup(const char *name)
{
	for (int p = 0; p < PAT_COUNT; p++)
		if (strcmp(name, texture_names[p]) == 0)
			return p;
	return -1;
}

/* ORDER IMAGE_MAP */
static const char *const map_names[IMAGE_MAP_UV + 1] = { "planar", "spherical", "cylindrical", "uv" };

const char *scene_desc_map_name(enum image_map_kind k)
{
	return map_names[k];
}

static void set3(double v[3], double x, double y, double z)
{
	v[0] = x;
	v[1] = y;
	v[2] = z;
}

void scene_desc_init(struct scene_desc *s)
{
	memset(s, 0, sizeof *s);
	struct camera_desc *c = &s->camera;
	set3(c->location, 0, 0, -5);
	set3(c->look_at, 0, 0, 0);
	set3(c->focal_point, 0, 0, 0);  /* look_at's */
	set3(c->up, 0, 1, 0);
	c->fov = 60;
	c->width = 640;
	c->height = 480;
	s->samples.count = 1;
	s->samples.pattern = PATTERN_CENTER;
	s->max_depth = 5;
	s->skybox.intensity = 1;
}

void scene_desc_free(struct scene_desc *s)
{
	for (size_t i = 0; i < s->nmaterials; i++)
		free(s->materials[i].name);
	for (size_t i = 0; i < s->nmeshes; i++) {
		struct mesh_desc *m = &s->meshes[i];
		free(m->file);
		free(m->path);
		free(m->vertices);
		free(m->faces);
		free(m->normals);
		free(m->uvs);
	}
	for (size_t i = 0; i < s->nimages; i++) {
		free(s->images[i].file);
		free(s->images[i].path);
	}
	free(s->patterns);
	free(s->color_maps);
	free(s->images);
	free(s->skybox.image);
	free(s->skybox.image_path);
	free(s->lights);
	free(s->materials);
	free(s->objects);
	free(s->xforms);
	free(s->meshes);
	memset(s, 0, sizeof *s);
}

/* Where a dump goes and how it writes numbers. */
struct dumper {
	FILE *out;
	bool exact;                    /* every number with 17 digits, which tell doubles apart */
};

/* %.10g, readable in golden files, or %.17g when exact; -0 shown as 0 so that dumps do
 * not depend on the sign of zero */
static void num(const struct dumper *d, double x)
{
	fprintf(d->out, d->exact ? "%.17g" : "%.10g", x == 0 ? 0.0 : x);
}

static void vec(const struct dumper *d, const double v[3])
{
	FILE *out = d->out;
	fputc('<', out);
	for (int k = 0; k < 3; k++) {
		if (k)
			fputs(", ", out);
		num(d, v[k]);
	}
	fputc('>', out);
}

static void field_vec(const struct dumper *d, const char *name, const double v[3])
{
	FILE *out = d->out;
	fprintf(out, " %s ", name);
	vec(d, v);
}

static void field_num(const struct dumper *d, const char *name, double x)
{
	FILE *out = d->out;
	fprintf(out, " %s ", name);
	num(d, x);
}

static void dump_material(const struct material_desc *m, size_t i, const struct dumper *d)
{
	FILE *out = d->out;
	fprintf(out, "material %zu", i);
	if (m->name)
		fprintf(out, " '%s'", m->name);
	if (m->pigment == PIGMENT_CHECKER) {
		fputs(" diffuse checker(", out);
		vec(d, m->diffuse);
		fputs(", ", out);
		vec(d, m->diffuse2);
		fputs(", ", out);
		num(d, m->checker_size);
		fputc(')', out);
	} else if (m->pigment == PIGMENT_PATTERN) {
		fprintf(out, " diffuse pattern %d", m->pattern);
	} else if (m->pigment == PIGMENT_IMAGE) {
		fprintf(out, " diffuse image %d", m->pattern);
	} else {
		field_vec(d, "diffuse", m->diffuse);
	}
	if (m->normal >= 0)
		fprintf(out, " normal %d", m->normal);
	field_vec(d, "specular", m->specular);
	field_num(d, "shininess", m->shininess);
	field_vec(d, "reflect", m->reflect);
	field_vec(d, "transmit", m->transmit);
	field_num(d, "ior", m->ior);
	if (m->fresnel)
		fputs(" fresnel", out);
	field_vec(d, "emit", m->emit);
	fputs(m->used ? "\n" : " unused\n", out);
}

static void dump_mesh(const struct mesh_desc *m, const struct dumper *d)
{
	FILE *out = d->out;
	if (m->file) {
		fprintf(out, " file \"%s\"%s", m->file, m->bilinear ? " interpolate bilinear" : "");
		return;
	}
	fputs(" vertices {", out);
	for (size_t i = 0; i < m->nvertices; i++) {
		fputs(i ? ", " : " ", out);
		vec(d, m->vertices[i]);
	}
	fputs(" } faces {", out);
	for (size_t i = 0; i < m->nfaces; i++)
		fprintf(out, "%s<%u, %u, %u>", i ? ", " : " ", m->faces[i][0], m->faces[i][1], m->faces[i][2]);
	fputs(" }", out);
	if (m->normals) {
		fputs(" normals {", out);
		for (size_t i = 0; i < m->nnormals; i++) {
			fputs(i ? ", " : " ", out);
			vec(d, m->normals[i]);
		}
		fputs(" }", out);
	}
	if (m->uvs) {
		fputs(" uvs {", out);
		for (size_t i = 0; i < m->nuvs; i++) {
			fputs(i ? ", " : " ", out);
			num(d, m->uvs[i][0]);
			fputc(' ', out);
			num(d, m->uvs[i][1]);
		}
		fputs(" }", out);
	}
}

static void dump_xform(const struct scene_desc *s, const char *name, int index, const struct dumper *d)
{
	FILE *out = d->out;
	if (index < 0) {
		fprintf(out, " %s identity", name);
		return;
	}
	const struct xform *x = &s->xforms[index];
	fprintf(out, " %s [", name);
	for (int r = 0; r < 3; r++)
		for (int c = 0; c < 4; c++) {
			if (r || c)
				fputs(c ? " " : "; ", out);
			num(d, x->m[r][c]);
		}
	fputc(']', out);
}

/* A pattern (a diffuse one or a normal) on its line, its colour map written out. */
static void dump_pattern(const struct scene_desc *s, const struct pattern_desc *p, size_t i, const struct dumper *d)
{
	FILE *out = d->out;
	fprintf(out, "pattern %zu %s", i, scene_desc_texture_name(p->name));
	if (p->name == PAT_GRADIENT) {
		fputc(' ', out);
		vec(d, p->vector);
	}
	if (p->name >= PAT_FIRST_NORMAL)
		field_num(d, "amount", p->amount);
	if (p->nmap) {
		fputs(" colors [", out);
		for (uint32_t k = 0; k < p->nmap; k++) {
			const struct color_map_entry *e = &s->color_maps[p->map + k];
			fputs(k ? ", [" : "[", out);
			num(d, e->position);
			fputs(", ", out);
			vec(d, e->color);
			fputc(']', out);
		}
		fputc(']', out);
	}
	field_num(d, "frequency", p->frequency);
	field_num(d, "phase", p->phase);
	field_vec(d, "turbulence", p->turbulence);
	fprintf(out, " octaves %d", p->octaves);
	field_num(d, "omega", p->omega);
	field_num(d, "lambda", p->lambda);
	if (p->xform >= 0)
		dump_xform(s, "transform", p->xform, d);
	fputc('\n', out);
}

static void dump_image(const struct scene_desc *s, const struct image_desc *im, size_t i, const struct dumper *d)
{
	FILE *out = d->out;
	fprintf(out, "image %zu \"%s\" map %s interpolate %s%s", i, im->file, scene_desc_map_name(im->map),
	        im->bilinear ? "bilinear" : "nearest", im->once ? " once" : "");
	if (im->xform >= 0)
		dump_xform(s, "transform", im->xform, d);
	fputc('\n', out);
}

/* One object on its line, indented two spaces for each CSG around it. */
static void dump_object(const struct scene_desc *s, const struct object_desc *o, size_t i, unsigned depth, const struct dumper *d)
{
	FILE *out = d->out;
	static const char *const kinds[] = {
		[OBJ_SPHERE] = "sphere", [OBJ_PLANE] = "plane", [OBJ_TRIANGLE] = "triangle", [OBJ_MESH] = "mesh",
		[OBJ_BOX] = "box", [OBJ_CYLINDER] = "cylinder", [OBJ_CONE] = "cone", [OBJ_DISC] = "disc",
		[OBJ_TORUS] = "torus", [OBJ_CSG] = "csg",
	};
	static const char *const ops[] = {
		[CSG_UNION] = "union", [CSG_MERGE] = "merge", [CSG_INTERSECTION] = "intersection",
		[CSG_DIFFERENCE] = "difference",
	};
	fprintf(out, "%*s%s %zu", 2 * (int)depth, "", o->kind == OBJ_CSG ? ops[o->u.csg.op] : kinds[o->kind], i);
	switch (o->kind) {
	case OBJ_SPHERE:
		field_vec(d, "center", o->u.sphere.center);
		field_num(d, "radius", o->u.sphere.radius);
		break;
	case OBJ_PLANE:
		field_vec(d, "normal", o->u.plane.normal);
		field_num(d, "offset", o->u.plane.offset);
		break;
	case OBJ_TRIANGLE:
		for (int k = 0; k < 3; k++)
			field_vec(d, "vertex", o->u.triangle.v[k]);
		break;
	case OBJ_MESH:
		dump_mesh(&s->meshes[o->u.mesh.index], d);
		break;
	case OBJ_BOX:
		field_vec(d, "corner", o->u.box.corner[0]);
		field_vec(d, "corner", o->u.box.corner[1]);
		break;
	case OBJ_CYLINDER:
		field_vec(d, "base", o->u.cone.base);
		field_vec(d, "cap", o->u.cone.cap);
		field_num(d, "radius", o->u.cone.radius[0]);
		break;
	case OBJ_CONE:
		field_vec(d, "base", o->u.cone.base);
		field_num(d, "base_radius", o->u.cone.radius[0]);
		field_vec(d, "cap", o->u.cone.cap);
		field_num(d, "cap_radius", o->u.cone.radius[1]);
		break;
	case OBJ_DISC:
		field_vec(d, "center", o->u.disc.center);
		field_vec(d, "normal", o->u.disc.normal);
		field_num(d, "radius", o->u.disc.radius);
		if (o->u.disc.hole > 0)
			field_num(d, "hole", o->u.disc.hole);
		break;
	case OBJ_TORUS:
		field_num(d, "major", o->u.torus.major);
		field_num(d, "minor", o->u.torus.minor);
		break;
	case OBJ_CSG:
		fprintf(out, " size %u", (unsigned)o->u.csg.size);
		break;
	}
	if (o->smooth)
		fputs(" smooth", out);
	if (o->open)
		fputs(" open", out);
	if (o->kind == OBJ_MESH && s->meshes[o->u.mesh.index].has_inside_vector)
		field_vec(d, "inside_vector", s->meshes[o->u.mesh.index].inside_vector);
	if (o->inverse)
		fputs(" inverse", out);
	if (o->solid)
		fputs(" solid", out);
	if (o->material >= 0)
		fprintf(out, " material %d%s", o->material, o->inherited ? " inherited" : "");
	else
		fputs(" material default", out);
	if (o->xform >= 0)
		dump_xform(s, "transform", o->xform, d);
	if (o->pattern_xform != o->xform) /* a material a CSG handed down lives in its space */
		dump_xform(s, "pattern_transform", o->pattern_xform, d);
	fputc('\n', out);
}

/* Objects [from, to) of s, a CSG's members after it, one level deeper. */
static void dump_objects(const struct scene_desc *s, size_t from, size_t to, unsigned depth, const struct dumper *d)
{
	for (size_t i = from; i < to; i++) {
		const struct object_desc *o = &s->objects[i];
		dump_object(s, o, i, depth, d);
		if (o->kind == OBJ_CSG) {
			dump_objects(s, i + 1, i + 1 + o->u.csg.size, depth + 1, d);
			i += o->u.csg.size;
		}
	}
}

static void dump(const struct scene_desc *s, const struct dumper *d)
{
	FILE *out = d->out;
	const struct camera_desc *c = &s->camera;
	fputs("camera", out);
	field_vec(d, "location", c->location);
	field_vec(d, "look_at", c->look_at);
	field_vec(d, "up", c->up);
	if (c->orthographic) {
		fputs(" orthographic", out);
		field_num(d, "width", c->view_width);
	} else {
		field_num(d, "fov", c->fov);
	}
	if (c->aperture > 0) {
		field_num(d, "aperture", c->aperture);
		field_vec(d, "focal_point", c->focal_point);
	}
	fprintf(out, " resolution %d %d%s\n", c->width, c->height, c->given ? "" : " (default)");

	fprintf(out, "max_depth %d\n", s->max_depth);
	fprintf(out, "samples count %d pattern %s seed %llu", s->samples.count,
	        scene_desc_pattern_name(s->samples.pattern), (unsigned long long)s->samples.seed);
	if (s->samples.target_error > 0)
		field_num(d, "target_error", s->samples.target_error);
	fputc('\n', out);

	const struct skybox_desc *k = &s->skybox;
	switch (k->kind) {
	case SKY_NONE:
		fputs("skybox none\n", out);
		break;
	case SKY_COLOR:
		fputs("skybox", out);
		field_vec(d, "color", k->color);
		fputc('\n', out);
		break;
	case SKY_GRADIENT:
		fputs("skybox", out);
		field_vec(d, "zenith", k->color);
		field_vec(d, "horizon", k->horizon);
		fputc('\n', out);
		break;
	case SKY_IMAGE:
		fprintf(out, "skybox image \"%s\"", k->image);
		field_num(d, "rotate", k->rotate);
		field_num(d, "intensity", k->intensity);
		fputc('\n', out);
		break;
	}
	if (s->fog.given) {
		fputs("fog", out);
		field_num(d, "distance", s->fog.distance);
		field_vec(d, "color", s->fog.color);
		fputc('\n', out);
	}

	for (size_t i = 0; i < s->nlights; i++) {
		const struct light_desc *l = &s->lights[i];
		fprintf(out, "light %zu", i);
		field_vec(d, l->directional ? "direction" : "position", l->vec);
		field_vec(d, "color", l->color);
		field_num(d, "intensity", l->intensity);
		if (l->fade_distance > 0 || l->fade_power > 0) {
			field_num(d, "fade_distance", l->fade_distance);
			field_num(d, "fade_power", l->fade_power);
		}
		if (l->spot) {
			fputs(" spotlight", out);
			field_vec(d, "point_at", l->point_at);
			field_num(d, "radius", l->radius);
			field_num(d, "falloff", l->falloff);
			field_num(d, "tightness", l->tightness);
		}
		if (l->area) {
			fputs(" area", out);
			field_vec(d, "axis1", l->area_axis[0]);
			field_vec(d, "axis2", l->area_axis[1]);
			fprintf(out, " size %d %d%s%s%s", l->area_size[0], l->area_size[1], l->area_jitter ? " jitter" : "",
			        l->area_circular ? " circular" : "", l->area_orient ? " orient" : "");
		}
		fputs(l->shadowless ? " shadowless\n" : "\n", out);
	}
	for (size_t i = 0; i < s->nmaterials; i++)
		dump_material(&s->materials[i], i, d);
	for (size_t i = 0; i < s->npatterns; i++)
		dump_pattern(s, &s->patterns[i], i, d);
	for (size_t i = 0; i < s->nimages; i++)
		dump_image(s, &s->images[i], i, d);
	dump_objects(s, 0, s->nobjects, 0, d);
}

void scene_desc_dump(const struct scene_desc *s, FILE *out)
{
	dump(s, &(struct dumper){ out, false });
}

void scene_desc_dump_exact(const struct scene_desc *s, FILE *out)
{
	dump(s, &(struct dumper){ out, true });
}
