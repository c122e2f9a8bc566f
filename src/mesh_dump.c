/* mesh_dump.c: scn check --dump's listing of the materials taken from mesh files. */
#include "config.h"

#include "mesh_dump.h"

#include <errno.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

#include "mesh_import.h"

/* %.10g, with -0 shown as 0, as scene_desc_dump writes numbers */
static void num(FILE *out, const char *name, double x)
{
	fprintf(out, " %s %.10g", name, x == 0 ? 0.0 : x);
}

static void rgb(FILE *out, const char *name, const double c[3])
{
	fprintf(out, " %s <", name);
	for (int k = 0; k < 3; k++)
		fprintf(out, "%s%.10g", k ? ", " : "", c[k] == 0 ? 0.0 : c[k]);
	fputc('>', out);
}

/* One line: the file as the scene writes it, the material's index among the file's
 * (mesh_import.h), and its values. */
static void dump_material(const char *file, size_t i, const struct mesh_material *m, FILE *out)
{
	fprintf(out, "mesh_material \"%s\" %zu '%s'", file, i, m->name);
	rgb(out, "diffuse", m->diffuse);
	if (m->texture) {
		fprintf(out, " texture \"%s\"", m->texture);
		if (!m->texture_path)
			fprintf(out, " embedded %s", m->texture_format[0] ? m->texture_format : "texels");
	}
	rgb(out, "specular", m->specular);
	num(out, "exponent", m->exponent);
	num(out, "opacity", m->opacity);
	num(out, "ior", m->ior);
	rgb(out, "emission", m->emission);
	fputc('\n', out);
}

/* Whether an object before the nth uses the mesh file at path without its own material:
 * its materials are listed already. */
static bool listed(const struct scene_desc *desc, size_t n, const char *path)
{
	for (size_t i = 0; i < n; i++) {
		const struct object_desc *o = &desc->objects[i];
		const struct mesh_desc *m = o->kind == OBJ_MESH ? &desc->meshes[o->u.mesh.index] : NULL;
		if (m && m->file && (o->material < 0 || o->inherited) && strcmp(m->path, path) == 0)
			return true;
	}
	return false;
}

enum load_status mesh_dump_materials(const struct scene_desc *desc, FILE *out)
{
	enum load_status status = LOAD_OK;
	for (size_t i = 0; i < desc->nobjects; i++) {
		const struct object_desc *o = &desc->objects[i];
		if (o->kind != OBJ_MESH || !(o->material < 0 || o->inherited))
			continue;
		const struct mesh_desc *m = &desc->meshes[o->u.mesh.index];
		if (!m->file || listed(desc, i, m->path))
			continue;
		struct mesh_data data;
		char err[512];
		int rc = mesh_import(m->path, &data, err, sizeof err);
		if (rc != 0) {
			fprintf(stderr, "scn: %s\n", err);
			status = rc == ENOMEM ? LOAD_TOO_BIG : LOAD_IO_ERROR;
			continue;
		}
		for (size_t k = 0; k < data.nmaterials; k++)
			dump_material(m->file, k, &data.materials[k], out);
		mesh_import_free(&data);
	}
	return status;
}
