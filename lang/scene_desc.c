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
	}
	free(s->skybox.image);
	free(s->skybox.image_path);
	free(s->lights);
	free(s->materials);
	free(s->objects);
	free(s->xforms);
	free(s->meshes);
	memset(s, 0, sizeof *s);
}

/* %.10g, with -0 shown as 0 so that dumps do not depend on the sign of zero */
static void num(FILE *out, double x)
{
	fprintf(out, "%.10g", x == 0 ? 0.0 : x);
}

static void vec(FILE *out, const double v[3])
{
	fputc('<', out);
	for (int k = 0; k < 3; k++) {
		if (k)
			fputs(", ", out);
		num(out, v[k]);
	}
	fputc('>', out);
}

static void field_vec(FILE *out, const char *name, const double v[3])
{
	fprintf(out, " %s ", name);
	vec(out, v);
}

static void field_num(FILE *out, const char *name, double x)
{
	fprintf(out, " %s ", name);
	num(out, x);
}

static void dump_material(const struct material_desc *m, size_t i, FILE *out)
{
	fprintf(out, "material %zu", i);
	if (m->name)
		fprintf(out, " '%s'", m->name);
	if (m->checker) {
		fputs(" diffuse checker(", out);
		vec(out, m->diffuse);
		fputs(", ", out);
		vec(out, m->diffuse2);
		fputs(", ", out);
		num(out, m->checker_size);
		fputc(')', out);
	} else {
		field_vec(out, "diffuse", m->diffuse);
	}
	field_vec(out, "specular", m->specular);
	field_num(out, "shininess", m->shininess);
	field_vec(out, "reflect", m->reflect);
	field_vec(out, "transmit", m->transmit);
	field_num(out, "ior", m->ior);
	if (m->fresnel)
		fputs(" fresnel", out);
	field_vec(out, "emit", m->emit);
	fputs(m->used ? "\n" : " unused\n", out);
}

static void dump_mesh(const struct mesh_desc *m, FILE *out)
{
	if (m->file) {
		fprintf(out, " file \"%s\"", m->file);
		return;
	}
	fputs(" vertices {", out);
	for (size_t i = 0; i < m->nvertices; i++) {
		fputs(i ? ", " : " ", out);
		vec(out, m->vertices[i]);
	}
	fputs(" } faces {", out);
	for (size_t i = 0; i < m->nfaces; i++)
		fprintf(out, "%s<%u, %u, %u>", i ? ", " : " ", m->faces[i][0], m->faces[i][1], m->faces[i][2]);
	fputs(" }", out);
	if (m->normals) {
		fputs(" normals {", out);
		for (size_t i = 0; i < m->nnormals; i++) {
			fputs(i ? ", " : " ", out);
			vec(out, m->normals[i]);
		}
		fputs(" }", out);
	}
}

static void dump_object(const struct scene_desc *s, const struct object_desc *o, size_t i, FILE *out)
{
	static const char *const kinds[] = { "sphere", "plane", "triangle", "mesh" };
	fprintf(out, "%s %zu", kinds[o->kind], i);
	switch (o->kind) {
	case OBJ_SPHERE:
		field_vec(out, "center", o->u.sphere.center);
		field_num(out, "radius", o->u.sphere.radius);
		break;
	case OBJ_PLANE:
		field_vec(out, "normal", o->u.plane.normal);
		field_num(out, "offset", o->u.plane.offset);
		break;
	case OBJ_TRIANGLE:
		for (int k = 0; k < 3; k++)
			field_vec(out, "vertex", o->u.triangle.v[k]);
		break;
	case OBJ_MESH:
		dump_mesh(&s->meshes[o->u.mesh.index], out);
		break;
	}
	if (o->smooth)
		fputs(" smooth", out);
	if (o->material >= 0)
		fprintf(out, " material %d", o->material);
	else
		fputs(" material default", out);
	if (o->xform >= 0) {
		const struct xform *x = &s->xforms[o->xform];
		fputs(" transform [", out);
		for (int r = 0; r < 3; r++)
			for (int c = 0; c < 4; c++) {
				if (r || c)
					fputs(c ? " " : "; ", out);
				num(out, x->m[r][c]);
			}
		fputc(']', out);
	}
	fputc('\n', out);
}

void scene_desc_dump(const struct scene_desc *s, FILE *out)
{
	const struct camera_desc *c = &s->camera;
	fputs("camera", out);
	field_vec(out, "location", c->location);
	field_vec(out, "look_at", c->look_at);
	field_vec(out, "up", c->up);
	field_num(out, "fov", c->fov);
	fprintf(out, " resolution %d %d%s\n", c->width, c->height, c->given ? "" : " (default)");

	fprintf(out, "max_depth %d\n", s->max_depth);
	fprintf(out, "samples count %d pattern %s seed %llu", s->samples.count,
	        scene_desc_pattern_name(s->samples.pattern), (unsigned long long)s->samples.seed);
	if (s->samples.target_error > 0)
		field_num(out, "target_error", s->samples.target_error);
	fputc('\n', out);

	const struct skybox_desc *k = &s->skybox;
	switch (k->kind) {
	case SKY_NONE:
		fputs("skybox none\n", out);
		break;
	case SKY_COLOR:
		fputs("skybox", out);
		field_vec(out, "color", k->color);
		fputc('\n', out);
		break;
	case SKY_GRADIENT:
		fputs("skybox", out);
		field_vec(out, "zenith", k->color);
		field_vec(out, "horizon", k->horizon);
		fputc('\n', out);
		break;
	case SKY_IMAGE:
		fprintf(out, "skybox image \"%s\"", k->image);
		field_num(out, "rotate", k->rotate);
		field_num(out, "intensity", k->intensity);
		fputc('\n', out);
		break;
	}

	for (size_t i = 0; i < s->nlights; i++) {
		const struct light_desc *l = &s->lights[i];
		fprintf(out, "light %zu", i);
		field_vec(out, l->directional ? "direction" : "position", l->vec);
		field_vec(out, "color", l->color);
		field_num(out, "intensity", l->intensity);
		fputs(l->shadowless ? " shadowless\n" : "\n", out);
	}
	for (size_t i = 0; i < s->nmaterials; i++)
		dump_material(&s->materials[i], i, out);
	for (size_t i = 0; i < s->nobjects; i++)
		dump_object(s, &s->objects[i], i, out);
}
