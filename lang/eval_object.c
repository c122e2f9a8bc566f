/* eval_object.c: the objects of a scene (LANGUAGE.md sections 5 and 9) into its
 * description: each shape's values, with every degenerate one an error at its place; the
 * items every object takes (material, transforms, inverse); CSGs, whose members follow
 * them in preorder and take their transforms and material; and materials, whose patterns,
 * images and normals eval_texture.c makes. */
#include "eval_internal.h"

#include <stdio.h>
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
	m->pattern = m->normal = -1;
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
			int like;
			if (material_of(ev, arg0(it), &like))
				m = ev->out->materials[like];
			break;
		}
		case KW_DIFFUSE: {
			struct ast *e = arg0(it);
			m.pattern = -1; /* what like gave is replaced */
			if (e->kind == AST_ITEM) { /* pattern { ... }, image { ... } */
				bool image = e->u.item.kw == KW_IMAGE;
				m.pattern = image ? eval_image(ev, e) : eval_pattern(ev, e, e->u.item.block, false);
				m.pigment = m.pattern < 0 ? PIGMENT_COLOR : image ? PIGMENT_IMAGE : PIGMENT_PATTERN;
				break;
			}
			if (e->type != TYPE_PIGMENT) {
				m.pigment = PIGMENT_COLOR;
				vec_of(ev, e, m.diffuse);
				break;
			}
			struct ast_list *a = &e->u.call.args;
			bool ok = vec_of(ev, a->v[0], m.diffuse) && vec_of(ev, a->v[1], m.diffuse2) &&
			          num_of(ev, a->v[2], &m.checker_size);
			m.pigment = ok ? PIGMENT_CHECKER : PIGMENT_COLOR;
			if (ok && !(m.checker_size > 0))
				eval_error(ev, a->v[2], "the checker's size must be positive, not %s", value_number_text(m.checker_size, nb));
			break;
		}
		case KW_SPECULAR: vec_of(ev, arg0(it), m.specular); break;
		case KW_SHININESS:
			if (num_of(ev, arg0(it), &m.shininess) && m.shininess < 0)
				eval_error(ev, arg0(it), "shininess must not be negative, not %s", value_number_text(m.shininess, nb));
			break;
		case KW_REFLECT: vec_of(ev, arg0(it), m.reflect); break;
		case KW_TRANSMIT: vec_of(ev, arg0(it), m.transmit); break;
		case KW_IOR:
			positive_of(ev, arg0(it), "ior", false, &m.ior);
			break;
		case KW_FRESNEL: m.fresnel = true; break;
		case KW_EMIT: vec_of(ev, arg0(it), m.emit); break;
		case KW_NORMAL: m.normal = eval_pattern(ev, it, it->u.item.block, true); break;
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

/* Appends obj to the scene's objects; false (reported) past LANG_MAX_OBJECTS. */
static bool push_object(struct evaluator *ev, struct ast *at, const struct object_desc *obj)
{
	struct scene_desc *o = ev->out;
	if (o->nobjects == LANG_MAX_OBJECTS) {
		eval_error(ev, at, "the scene makes more than %d objects", LANG_MAX_OBJECTS);
		ev->exhausted = true;
		return false;
	}
	xgrow((void **)&o->objects, &o->cap_objects, o->nobjects + 1, sizeof *o->objects);
	o->objects[o->nobjects++] = *obj;
	return true;
}

/* A mesh's uvs { ... } (LANGUAGE.md 11): one per vertex, u and v from x and y; false
 * after an error. */
static bool mesh_uvs(struct evaluator *ev, struct ast *stmt, struct mesh_desc *m)
{
	struct ast_list *items = &stmt->u.stmt.block->items;
	struct ast *uvs = NULL;
	for (size_t i = 0; i < items->n; i++)
		if (items->v[i]->u.item.kw == KW_UVS)
			uvs = items->v[i];
	if (!uvs)
		return true;
	struct ast_list *l = &uvs->u.item.block->args;
	if (l->n != m->nvertices) {
		eval_error(ev, uvs, "a mesh needs one uv per vertex: %zu vert%s, %u uv%s", m->nvertices,
		           m->nvertices == 1 ? "ex" : "ices", l->n, l->n == 1 ? "" : "s");
		return false;
	}
	m->nuvs = l->n;
	m->uvs = xcalloc(l->n, sizeof *m->uvs);
	for (size_t i = 0; i < l->n; i++) {
		double v[3];
		if (!vec_of(ev, l->v[i], v))
			return false;
		m->uvs[i][0] = v[0];
		m->uvs[i][1] = v[1];
	}
	return true;
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
				           vl->n - 1, value_number_text(f[k], nb));
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
	return ok && mesh_uvs(ev, stmt, m);
}

static bool same_point(const double a[3], const double b[3])
{
	return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
}

/* A mesh's file or lists into a new mesh entry, which obj refers to; false after an error. */
static bool mesh_values(struct evaluator *ev, struct ast *s, struct object_desc *obj, const struct source *src)
{
	struct ast_list *args = &s->u.stmt.block->args;
	struct mesh_desc m = { 0 };
	bool ok = true;
	obj->kind = OBJ_MESH;
	if (args->n) {
		ok = file_of(ev, args->v[0], src, "mesh file", &m.file, &m.path);
		m.file_span = args->v[0]->span;
	} else {
		ok = eval_mesh_lists(ev, s, &m);
	}
	struct scene_desc *o = ev->out;
	xgrow((void **)&o->meshes, &o->cap_meshes, o->nmeshes + 1, sizeof *o->meshes);
	o->meshes[o->nmeshes] = m;
	obj->u.mesh.index = (int)o->nmeshes++;
	return ok;
}

/* A cylinder's or a cone's values: BASE, CAP, RADIUS or BASE, BASE_RADIUS, CAP, CAP_RADIUS. */
static bool cone_values(struct evaluator *ev, struct ast_list *args, bool cylinder, struct object_desc *obj)
{
	char nb[32];
	struct ast *base = args->v[0], *cap = args->v[cylinder ? 1 : 2];
	struct ast *r[2] = { args->v[cylinder ? 2 : 1], args->v[cylinder ? 2 : 3] };
	double *radius = obj->u.cone.radius;
	obj->kind = cylinder ? OBJ_CYLINDER : OBJ_CONE;
	bool have_base = vec_of(ev, base, obj->u.cone.base), have_cap = vec_of(ev, cap, obj->u.cone.cap);
	bool have_r[2] = { num_of(ev, r[0], &radius[0]), false };
	have_r[1] = cylinder ? have_r[0] : num_of(ev, r[1], &radius[1]);
	if (cylinder)
		radius[1] = radius[0];
	bool ok = have_base && have_cap && have_r[0] && have_r[1];
	if (have_base && have_cap && same_point(obj->u.cone.base, obj->u.cone.cap)) {
		eval_error(ev, cap, "a %s's cap must not be the same point as its base", cylinder ? "cylinder" : "cone");
		ok = false;
	}
	if (cylinder) {
		if (have_r[0] && !(radius[0] > 0)) {
			eval_error(ev, r[0], "a cylinder's radius must be positive, not %s", value_number_text(radius[0], nb));
			ok = false;
		}
		return ok;
	}
	static const char *const which[2] = { "base", "cap" };
	for (int k = 0; k < 2; k++)
		if (have_r[k] && radius[k] < 0) {
			eval_error(ev, r[k], "a cone's %s radius must not be negative, not %s", which[k], value_number_text(radius[k], nb));
			ok = false;
		}
	if (have_r[0] && have_r[1] && radius[0] == 0 && radius[1] == 0) {
		eval_error(ev, r[1], "a cone's radii cannot both be 0 (one of them may be)");
		ok = false;
	}
	return ok;
}

static bool disc_values(struct evaluator *ev, struct ast_list *args, struct object_desc *obj)
{
	char nb[32], nb2[32];
	double *radius = &obj->u.disc.radius, *hole = &obj->u.disc.hole;
	obj->kind = OBJ_DISC;
	bool have_center = vec_of(ev, args->v[0], obj->u.disc.center);
	bool have_normal = vec_of(ev, args->v[1], obj->u.disc.normal);
	bool have_radius = num_of(ev, args->v[2], radius);
	bool have_hole = args->n < 4 || num_of(ev, args->v[3], hole);
	bool ok = have_center && have_normal && have_radius && have_hole;
	if (have_normal && is_zero(obj->u.disc.normal)) {
		eval_error(ev, args->v[1], "a disc's normal must not be a zero vector");
		ok = false;
	}
	if (have_radius && !(*radius > 0)) {
		eval_error(ev, args->v[2], "a disc's radius must be positive, not %s", value_number_text(*radius, nb));
		ok = false;
	}
	if (args->n < 4 || !have_hole)
		return ok;
	if (*hole < 0) {
		eval_error(ev, args->v[3], "a disc's hole radius must not be negative, not %s", value_number_text(*hole, nb));
		ok = false;
	} else if (have_radius && *radius > 0 && *hole >= *radius) {
		eval_error(ev, args->v[3], "a disc's hole radius must be less than its radius, %s, not %s",
		           value_number_text(*radius, nb), value_number_text(*hole, nb2));
		ok = false;
	}
	return ok;
}

static bool torus_values(struct evaluator *ev, struct ast_list *args, struct object_desc *obj)
{
	char nb[32], nb2[32];
	double *major = &obj->u.torus.major, *minor = &obj->u.torus.minor;
	obj->kind = OBJ_TORUS;
	bool have_major = num_of(ev, args->v[0], major), have_minor = num_of(ev, args->v[1], minor);
	bool ok = have_major && have_minor;
	if (have_major && !(*major > 0)) {
		eval_error(ev, args->v[0], "a torus's major radius must be positive, not %s", value_number_text(*major, nb));
		ok = false;
	}
	if (have_minor && !(*minor > 0)) {
		eval_error(ev, args->v[1], "a torus's minor radius must be positive, not %s", value_number_text(*minor, nb));
		ok = false;
	} else if (have_minor && have_major && *major > 0 && *minor >= *major) {
		eval_error(ev, args->v[1], "a torus's minor radius must be less than its major radius, %s, not %s",
		           value_number_text(*major, nb), value_number_text(*minor, nb2));
		ok = false;
	}
	return ok;
}

/* A shape's positional values into obj; false after an error, each reported at its value. */
static bool shape_values(struct evaluator *ev, struct ast *s, struct object_desc *obj, const struct source *src)
{
	struct ast_list *args = &s->u.stmt.block->args;
	char nb[32];
	bool ok = true;
	switch (s->u.stmt.kw) {
	case KW_SPHERE:
		obj->kind = OBJ_SPHERE;
		ok = vec_of(ev, args->v[0], obj->u.sphere.center) && num_of(ev, args->v[1], &obj->u.sphere.radius);
		if (ok && !(obj->u.sphere.radius > 0)) {
			eval_error(ev, args->v[1], "a sphere's radius must be positive, not %s",
			           value_number_text(obj->u.sphere.radius, nb));
			ok = false;
		}
		return ok;
	case KW_PLANE:
		obj->kind = OBJ_PLANE;
		ok = vec_of(ev, args->v[0], obj->u.plane.normal) && num_of(ev, args->v[1], &obj->u.plane.offset);
		if (ok && is_zero(obj->u.plane.normal)) {
			eval_error(ev, args->v[0], "a plane's normal must not be a zero vector");
			ok = false;
		}
		return ok;
	case KW_TRIANGLE:
		obj->kind = OBJ_TRIANGLE;
		for (int k = 0; k < 3 && ok; k++)
			ok = vec_of(ev, args->v[k], obj->u.triangle.v[k]);
		return ok;
	case KW_BOX: {
		/* the corners as written: any two opposite ones, in any order (POV-Ray's box) */
		double (*c)[3] = obj->u.box.corner;
		obj->kind = OBJ_BOX;
		ok = vec_of(ev, args->v[0], c[0]) & vec_of(ev, args->v[1], c[1]);
		char same[128] = "";
		size_t used = 0;
		for (int k = 0; k < 3 && ok; k++)
			if (c[0][k] == c[1][k])
				used += (size_t)snprintf(same + used, sizeof same - used, "%s%c = %s", used ? ", " : "", "xyz"[k],
				                         value_number_text(c[0][k], nb));
		if (used) {
			eval_error(ev, args->v[1], "a box's corners must differ in x, y and z; both have %s", same);
			ok = false;
		}
		return ok;
	}
	case KW_CYLINDER: case KW_CONE:
		return cone_values(ev, args, s->u.stmt.kw == KW_CYLINDER, obj);
	case KW_DISC:
		return disc_values(ev, args, obj);
	case KW_TORUS:
		return torus_values(ev, args, obj);
	default:
		return mesh_values(ev, s, obj, src);
	}
}

/* Whether object s (obj, its values made) can take the material its item it gives,
 * obj->material: an image mapped by uv needs the object's UV coordinates, which a sphere
 * and a torus have (POV-Ray's uv_mapping), an inline mesh has from uvs { ... }, and a mesh
 * file may have (the lowering checks). Reports at the item when not. */
static bool uv_mapped(struct evaluator *ev, struct ast *s, struct ast *it, const struct object_desc *obj)
{
	const struct scene_desc *o = ev->out;
	const struct material_desc *m = obj->material >= 0 ? &o->materials[obj->material] : NULL;
	if (!m || m->pigment != PIGMENT_IMAGE || o->images[m->pattern].map != IMAGE_MAP_UV)
		return true;
	switch (obj->kind) {
	case OBJ_SPHERE: case OBJ_TORUS:
		return true;
	case OBJ_MESH:
		if (o->meshes[obj->u.mesh.index].file || o->meshes[obj->u.mesh.index].uvs)
			return true;
		eval_error(ev, it, "this material's image is mapped by uv, and this mesh has no UV coordinates: "
		           "give it uvs { ... }, one per vertex");
		return false;
	default:
		eval_error(ev, it, "this material's image is mapped by uv, and a %s has no UV coordinates (a sphere, "
		           "a torus and a mesh with uvs have them)", kw_name(s->u.stmt.kw));
		return false;
	}
}

/* The items of object s into obj: the ones every object takes (material, transforms,
 * inverse) and a shape's own (open, smooth, inside_vector); then what the enclosing CSG
 * hands down: its transform, after obj's own, and its material, if it has one, when obj
 * has none (whose patterns then live in the CSG's space: the default material has none).
 * False after an error. */
static bool object_items(struct evaluator *ev, struct ast *s, struct object_desc *obj)
{
	struct ast_block *block = s->u.stmt.block;
	struct scene_desc *o = ev->out;
	struct xform x = { { { 1, 0, 0, 0 }, { 0, 1, 0, 0 }, { 0, 0, 1, 0 } } };
	bool moved = false, own_material = false, ok = true;
	for (size_t i = 0; i < block->items.n; i++) {
		struct ast *it = block->items.v[i];
		switch (it->u.item.kw) {
		case KW_MATERIAL:
			if (it->u.item.block)
				obj->material = eval_material(ev, it->u.item.block, NULL, it->span);
			else
				ok &= material_of(ev, arg0(it), &obj->material);
			own_material = true;
			ok = ok && uv_mapped(ev, s, it, obj);
			break;
		case KW_TRANSLATE: case KW_ROTATE: case KW_SCALE:
			ok &= xform_apply(ev, it, &x);
			moved = true;
			if (ok && !xform_finite(&x)) { /* scale 1e200 scale 1e200 */
				eval_error(ev, it, "the transforms make the object too large to be numbers");
				ok = false;
			}
			break;
		case KW_SMOOTH:
			obj->smooth = true;
			break;
		case KW_OPEN:
			obj->open = true;
			break;
		case KW_INVERSE:
			obj->inverse = true;
			break;
		case KW_INTERPOLATE: /* a mesh file's (check.c): nearest, bilinear */
			o->meshes[obj->u.mesh.index].bilinear = arg0(it)->u.ident.builtin == 1;
			break;
		case KW_INSIDE_VECTOR: { /* a mesh's (check.c), whose entry shape_values made */
			struct mesh_desc *m = &o->meshes[obj->u.mesh.index];
			m->has_inside_vector = true;
			if (!vec_of(ev, arg0(it), m->inside_vector)) {
				ok = false;
			} else if (is_zero(m->inside_vector)) {
				eval_error(ev, arg0(it), "inside_vector must not be a zero vector");
				ok = false;
			}
			break;
		}
		}
	}
	if (!ok)
		return false;
	const struct csg_frame *f = ev->csg;
	if (f && f->xform >= 0 && !moved) {
		obj->xform = f->xform;
	} else if (f && f->xform >= 0) {
		xform_compose(&x, o->xforms[f->xform].m);
		if (!xform_finite(&x)) {
			eval_error_span(ev, s, s->u.stmt.kw_span,
			                "the transforms of this object and of the CSGs around it make it too large to be numbers");
			return false;
		}
	}
	if (moved)
		obj->xform = xform_push(ev, &x);
	obj->pattern_xform = obj->xform;
	if (!own_material && f && f->material >= 0) {
		obj->material = f->material;
		obj->pattern_xform = f->pattern_xform;
		obj->inherited = true;
	}
	if (obj->material >= 0)
		o->materials[obj->material].used = true;
	return true;
}

void eval_shape(struct evaluator *ev, struct ast *s, const struct source *src)
{
	struct object_desc obj = { .material = -1, .xform = -1, .pattern_xform = -1, .span = s->span };
	bool ok = shape_values(ev, s, &obj, src);
	ok = object_items(ev, s, &obj) && ok;
	if (!ok)
		return;
	switch (obj.kind) {
	case OBJ_TRIANGLE: case OBJ_DISC:
		obj.solid = false;
		break;
	case OBJ_CYLINDER: case OBJ_CONE:
		obj.solid = !obj.open;
		break;
	case OBJ_MESH:
		obj.solid = ev->out->meshes[obj.u.mesh.index].has_inside_vector;
		break;
	default:
		obj.solid = true;
		break;
	}
	if (obj.kind == OBJ_TRIANGLE) {
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

bool csg_begin(struct evaluator *ev, struct ast *s, struct csg_frame *frame)
{
	struct object_desc obj = { .kind = OBJ_CSG, .material = -1, .xform = -1, .pattern_xform = -1, .span = s->span };
	obj.u.csg.op = (enum csg_op)(s->u.stmt.kw - KW_UNION);
	*frame = (struct csg_frame){ .index = ev->out->nobjects, .failures = ev->failures, .outer = ev->csg };
	if (!push_object(ev, s, &obj))
		return false;
	/* after an error here the members are still evaluated, for their own errors, as if
	 * the CSG had no items; then csg_end drops it */
	if (object_items(ev, s, &obj))
		ev->out->objects[frame->index] = obj;
	frame->xform = ev->out->objects[frame->index].xform;
	frame->material = ev->out->objects[frame->index].material;
	frame->pattern_xform = ev->out->objects[frame->index].pattern_xform;
	ev->csg = frame;
	return true;
}

void csg_end(struct evaluator *ev, struct ast *s)
{
	struct csg_frame *f = ev->csg;
	struct scene_desc *o = ev->out;
	ev->csg = f->outer;
	if (ev->failures != f->failures) { /* an error of its own or of a member, reported */
		o->nobjects = f->index;
		return;
	}
	size_t size = o->nobjects - f->index - 1;
	if (size == 0) {
		eval_error_span(ev, s, s->u.stmt.kw_span, "this %s has no objects: its for loops made none",
		                kw_name(s->u.stmt.kw));
		o->nobjects = f->index;
		return;
	}
	struct object_desc *csg = &o->objects[f->index];
	csg->u.csg.size = (uint32_t)size;
	/* intersection, difference and merge have solids only (check.c); a union is one when
	 * its direct members are */
	csg->solid = true;
	for (size_t j = f->index + 1; csg->u.csg.op == CSG_UNION && j <= f->index + size;
	     j += o->objects[j].kind == OBJ_CSG ? o->objects[j].u.csg.size + 1 : 1)
		csg->solid &= o->objects[j].solid;
}
