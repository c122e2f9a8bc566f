/* eval_object.c: the objects of a scene (LANGUAGE.md section 5) into its description:
 * each shape's values, with every degenerate one an error at its place, its material and
 * its transforms; and materials. */
#include "eval_internal.h"

#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "file.h"
#include "xalloc.h"

static void material_defaults(struct material_desc *m)
{
	memset(m, 0, sizeof *m);
	m->diffuse[0] = m->diffuse[1] = m->diffuse[2] = 0.8;
	m->shininess = 50;
	m->ior = 1;
}

int eval_material(struct evaluator *ev, struct ast_block *block, const char *name, struct span sp)
{
	struct material_desc m;
	char nb[32];
	material_defaults(&m);
	for (size_t i = 0; i < block->items.n; i++) {
		struct ast *it = block->items.v[i];
		switch (it->u.item.kw) {
		case KW_LIKE: {
			struct ast *id = arg0(it);
			m = ev->out->materials[(size_t)ev->slots[id->u.ident.ref->slot].v[0]];
			break;
		}
		case KW_DIFFUSE: {
			struct ast *e = arg0(it);
			if (e->type != TYPE_PIGMENT) {
				m.checker = false;
				vec_of(ev, e, m.diffuse);
				break;
			}
			struct ast_list *a = &e->u.call.args;
			m.checker = vec_of(ev, a->v[0], m.diffuse) && vec_of(ev, a->v[1], m.diffuse2) &&
			            num_of(ev, a->v[2], &m.checker_size);
			if (m.checker && !(m.checker_size > 0))
				eval_error(ev, a->v[2], "the checker's size must be positive, not %s", num_text(m.checker_size, nb));
			break;
		}
		case KW_SPECULAR: vec_of(ev, arg0(it), m.specular); break;
		case KW_SHININESS:
			if (num_of(ev, arg0(it), &m.shininess) && m.shininess < 0)
				eval_error(ev, arg0(it), "shininess must not be negative, not %s", num_text(m.shininess, nb));
			break;
		case KW_REFLECT: vec_of(ev, arg0(it), m.reflect); break;
		case KW_TRANSMIT: vec_of(ev, arg0(it), m.transmit); break;
		case KW_IOR:
			if (num_of(ev, arg0(it), &m.ior) && !(m.ior > 0))
				eval_error(ev, arg0(it), "ior must be positive, not %s", num_text(m.ior, nb));
			break;
		case KW_FRESNEL: m.fresnel = true; break;
		case KW_EMIT: vec_of(ev, arg0(it), m.emit); break;
		}
	}
	m.name = name ? xstrdup(name) : NULL;
	m.used = false;
	m.span = sp;
	struct scene_desc *o = ev->out;
	xgrow((void **)&o->materials, &o->cap_materials, o->nmaterials + 1, sizeof *o->materials);
	o->materials[o->nmaterials] = m;
	return (int)o->nmaterials++;
}

/* sin and cos of an angle in degrees, exact at multiples of 90 so that right-angle
 * rotations keep axis-aligned geometry exactly axis-aligned. */
static void sincos_degrees(double deg, double *s, double *c)
{
	double r = fmod(deg, 360);
	if (r < 0)
		r += 360;
	if (r == 0) { *s = 0; *c = 1; return; }
	if (r == 90) { *s = 1; *c = 0; return; }
	if (r == 180) { *s = 0; *c = -1; return; }
	if (r == 270) { *s = -1; *c = 0; return; }
	*s = sin(deg * (M_PI / 180));
	*c = cos(deg * (M_PI / 180));
}

/* x = t * x: applies the affine map t after x. */
static void compose(struct xform *x, const double t[3][4])
{
	struct xform r;
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 4; j++) {
			double v = j == 3 ? t[i][3] : 0;
			for (int k = 0; k < 3; k++)
				v += t[i][k] * x->m[k][j];
			r.m[i][j] = v;
		}
	*x = r;
}

/* Applies one transform item to x. Returns false after reporting a bad value. Every
 * object takes every transform (LANGUAGE.md section 9): a sphere under an uneven scale is
 * an ellipsoid. */
static bool apply_transform(struct evaluator *ev, struct ast *it, struct xform *x)
{
	double v[3];
	if (!vec_of(ev, arg0(it), v))
		return false;
	double t[3][4] = { { 1, 0, 0, 0 }, { 0, 1, 0, 0 }, { 0, 0, 1, 0 } };
	switch (it->u.item.kw) {
	case KW_TRANSLATE:
		for (int i = 0; i < 3; i++)
			t[i][3] = v[i];
		compose(x, t);
		return true;
	case KW_SCALE:
		if (v[0] == 0 || v[1] == 0 || v[2] == 0) {
			eval_error(ev, arg0(it), "scale must not be zero in any direction");
			return false;
		}
		for (int i = 0; i < 3; i++)
			t[i][i] = v[i];
		compose(x, t);
		return true;
	default: /* rotate: about x, then y, then z, as POV-Ray */
		for (int axis = 0; axis < 3; axis++) {
			double s, c;
			sincos_degrees(v[axis], &s, &c);
			double r[3][4] = { { 1, 0, 0, 0 }, { 0, 1, 0, 0 }, { 0, 0, 1, 0 } };
			int a = (axis + 1) % 3, b = (axis + 2) % 3;
			r[a][a] = c;
			r[a][b] = -s;
			r[b][a] = s;
			r[b][b] = c;
			compose(x, r);
		}
		return true;
	}
}

static void push_object(struct evaluator *ev, struct ast *at, struct object_desc *obj)
{
	struct scene_desc *o = ev->out;
	if (o->nobjects == LANG_MAX_OBJECTS) {
		eval_error(ev, at, "the scene makes more than %d objects", LANG_MAX_OBJECTS);
		ev->exhausted = true;
		return;
	}
	xgrow((void **)&o->objects, &o->cap_objects, o->nobjects + 1, sizeof *o->objects);
	o->objects[o->nobjects++] = *obj;
}

/* Evaluates a mesh's inline lists into a new mesh entry; false after an error. */
static bool eval_mesh_lists(struct evaluator *ev, struct ast *stmt, struct mesh_desc *m)
{
	struct ast *lists[3] = { 0 };
	struct ast_list *items = &stmt->u.stmt.block->items;
	for (size_t i = 0; i < items->n; i++) {
		int kw = items->v[i]->u.item.kw;
		if (kw == KW_VERTICES || kw == KW_FACES || kw == KW_NORMALS)
			lists[kw - KW_VERTICES] = items->v[i];
	}
	struct ast_list *vl = &lists[0]->u.item.block->args, *fl = &lists[1]->u.item.block->args;
	m->nvertices = vl->n;
	m->vertices = xcalloc(vl->n, sizeof *m->vertices);
	bool ok = true;
	for (size_t i = 0; i < vl->n; i++)
		ok &= vec_of(ev, vl->v[i], m->vertices[i]);
	m->nfaces = fl->n;
	m->faces = xcalloc(fl->n, sizeof *m->faces);
	for (size_t i = 0; i < fl->n && ok; i++) {
		double f[3];
		if (!vec_of(ev, fl->v[i], f))
			return false;
		for (int k = 0; k < 3; k++) {
			if (f[k] != floor(f[k]) || f[k] < 0 || f[k] >= (double)vl->n) {
				/* at the index itself when the face is written <i, j, k> */
				struct ast *at = fl->v[i]->kind == AST_VEC ? fl->v[i]->u.vec[k] : fl->v[i];
				char nb[32];
				eval_error(ev, at, "a face's indices must be whole numbers from 0 to %u (0-based), not %s",
				           vl->n - 1, num_text(f[k], nb));
				return false;
			}
			m->faces[i][k] = (uint32_t)f[k];
		}
	}
	if (lists[2] && ok) {
		struct ast_list *nl = &lists[2]->u.item.block->args;
		if (nl->n != vl->n) {
			eval_error(ev, lists[2], "a mesh needs one normal per vertex: %u vert%s, %u normal%s", vl->n,
			           vl->n == 1 ? "ex" : "ices", nl->n, nl->n == 1 ? "" : "s");
			return false;
		}
		m->nnormals = nl->n;
		m->normals = xcalloc(nl->n, sizeof *m->normals);
		for (size_t i = 0; i < nl->n && ok; i++) {
			ok = vec_of(ev, nl->v[i], m->normals[i]);
			if (ok && is_zero(m->normals[i])) {
				eval_error(ev, nl->v[i], "a vertex normal must not be a zero vector");
				return false;
			}
		}
	}
	return ok;
}

void eval_object(struct evaluator *ev, struct ast *s, const struct source *src)
{
	enum kw kw = s->u.stmt.kw;
	struct ast_block *block = s->u.stmt.block;
	struct object_desc obj = { .material = -1, .xform = -1, .span = s->span };
	struct ast_list *args = &block->args;
	bool ok = true;
	switch (kw) {
	case KW_SPHERE:
		obj.kind = OBJ_SPHERE;
		ok = vec_of(ev, args->v[0], obj.u.sphere.center) && num_of(ev, args->v[1], &obj.u.sphere.radius);
		if (ok && !(obj.u.sphere.radius > 0)) {
			char nb[32];
			eval_error(ev, args->v[1], "a sphere's radius must be positive, not %s", num_text(obj.u.sphere.radius, nb));
			ok = false;
		}
		break;
	case KW_PLANE:
		obj.kind = OBJ_PLANE;
		ok = vec_of(ev, args->v[0], obj.u.plane.normal) && num_of(ev, args->v[1], &obj.u.plane.offset);
		if (ok && is_zero(obj.u.plane.normal)) {
			eval_error(ev, args->v[0], "a plane's normal must not be a zero vector");
			ok = false;
		}
		break;
	case KW_TRIANGLE:
		obj.kind = OBJ_TRIANGLE;
		for (int k = 0; k < 3 && ok; k++)
			ok = vec_of(ev, args->v[k], obj.u.triangle.v[k]);
		break;
	default: { /* mesh */
		struct mesh_desc m = { 0 };
		obj.kind = OBJ_MESH;
		if (args->n) {
			m.file = xstrdup(args->v[0]->u.str.text);
			m.path = file_resolve(src->dir, m.file);
			m.file_span = args->v[0]->span;
		} else {
			ok = eval_mesh_lists(ev, s, &m);
		}
		struct scene_desc *o = ev->out;
		xgrow((void **)&o->meshes, &o->cap_meshes, o->nmeshes + 1, sizeof *o->meshes);
		o->meshes[o->nmeshes] = m;
		obj.u.mesh.index = (int)o->nmeshes++;
		break;
	}
	}

	struct xform x = { { { 1, 0, 0, 0 }, { 0, 1, 0, 0 }, { 0, 0, 1, 0 } } };
	bool moved = false;
	for (size_t i = 0; i < block->items.n; i++) {
		struct ast *it = block->items.v[i];
		switch (it->u.item.kw) {
		case KW_MATERIAL:
			if (it->u.item.block)
				obj.material = eval_material(ev, it->u.item.block, NULL, it->span);
			else
				obj.material = (int)ev->slots[arg0(it)->u.ident.ref->slot].v[0];
			break;
		case KW_TRANSLATE: case KW_ROTATE: case KW_SCALE:
			ok &= apply_transform(ev, it, &x);
			moved = true;
			for (int r = 0; r < 12 && ok; r++) /* scale 1e200 scale 1e200 */
				if (!isfinite(x.m[r / 4][r % 4])) {
					eval_error(ev, it, "the transforms make the object too large to be numbers");
					ok = false;
				}
			break;
		case KW_SMOOTH:
			obj.smooth = true;
			break;
		}
	}
	if (!ok)
		return;
	if (obj.material >= 0)
		ev->out->materials[obj.material].used = true;
	if (moved) {
		struct scene_desc *o = ev->out;
		xgrow((void **)&o->xforms, &o->cap_xforms, o->nxforms + 1, sizeof *o->xforms);
		o->xforms[o->nxforms] = x;
		obj.xform = (int)o->nxforms++;
	}
	obj.pattern_xform = obj.xform;
	obj.solid = kw == KW_SPHERE || kw == KW_PLANE;
	if (kw == KW_TRIANGLE) {
		double e1[3], e2[3], n[3];
		for (int k = 0; k < 3; k++) {
			e1[k] = obj.u.triangle.v[1][k] - obj.u.triangle.v[0][k];
			e2[k] = obj.u.triangle.v[2][k] - obj.u.triangle.v[0][k];
		}
		cross(e1, e2, n);
		if (is_zero(n))
			diag_warning(ev->diag, s->u.stmt.kw_span, "this triangle has no area (its corners lie on a line); it is not drawn");
	}
	push_object(ev, s, &obj);
}
