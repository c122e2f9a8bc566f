/* eval.c: runs a checked scene: evaluates every expression (a non-finite result is an
 * error at its place), expands loops and includes, checks every value's range, and
 * builds the scene_desc. Types were settled by check.c; this file only computes. */
#include "eval.h"

#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "builtins.h"
#include "check.h"
#include "file.h"
#include "xalloc.h"

struct evaluator {
	struct diag *diag;
	struct scene_desc *out;
	struct value *slots;       /* current value of each binding; a material's is its index */
	bool *bad;                 /* the binding's value could not be computed */
	size_t nslots, cap_slots, cap_bad;
	uint64_t iterations;       /* loop iterations so far, against LANG_MAX_ITERATIONS */
	uint64_t steps;            /* expressions evaluated so far, against LANG_MAX_STEPS */
	bool exhausted;            /* a limit on the whole evaluation was reached: stop */
	unsigned nloops;
	struct { const struct ast *loop; double i; } loops[LANG_MAX_NESTING];
};

/* A number for a message: the shortest of %.15g to %.17g that reads back as x, so that
 * a value the user wrote (ior -1.33) shows as written. */
static const char *num_text(double x, char buf[32])
{
	for (int prec = 15; prec < 17; prec++) {
		snprintf(buf, 32, "%.*g", prec, x);
		if (strtod(buf, NULL) == x)
			return buf;
	}
	snprintf(buf, 32, "%.17g", x);
	return buf;
}

/* Reports an error once per place (*reported), however many loop iterations reach it,
 * with the loop variables' values that led there. */
static void report_once(struct evaluator *ev, bool *reported, struct span sp, const char *fmt, va_list ap)
{
	if (*reported)
		return;
	*reported = true;
	char msg[512];
	vsnprintf(msg, sizeof msg, fmt, ap);
	diag_error(ev->diag, sp, "%s", msg);
	if (ev->nloops) {
		char where[256];
		size_t used = 0;
		char nb[32];
		for (unsigned i = ev->nloops; i-- > 0 && used < sizeof where;)
			used += (size_t)snprintf(where + used, sizeof where - used, "%s%s = %s",
			                         i + 1 == ev->nloops ? "" : ", ", ev->loops[i].loop->u.loop.var,
			                         num_text(ev->loops[i].i, nb));
		diag_note(ev->diag, ev->loops[ev->nloops - 1].loop->u.loop.var_span, "when %s", where);
	}
}

static void eval_error(struct evaluator *ev, struct ast *at, const char *fmt, ...)
	__attribute__((format(printf, 3, 4)));
static void eval_error(struct evaluator *ev, struct ast *at, const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	report_once(ev, &at->reported, at->span, fmt, ap);
	va_end(ap);
}

/* An error about node at, shown at another span (a part of it). */
static void eval_error_span(struct evaluator *ev, struct ast *at, struct span sp, const char *fmt, ...)
	__attribute__((format(printf, 4, 5)));
static void eval_error_span(struct evaluator *ev, struct ast *at, struct span sp, const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	report_once(ev, &at->reported, sp, fmt, ap);
	va_end(ap);
}

static void broadcast(const struct value *v, enum ast_type t, double out[3])
{
	for (int k = 0; k < 3; k++)
		out[k] = v->v[t == TYPE_VEC ? k : 0];
}

static bool eval_expr(struct evaluator *ev, struct ast *e, struct value *out);

static bool eval_binary(struct evaluator *ev, struct ast *e, struct value *out)
{
	struct value l, r;
	if (!eval_expr(ev, e->u.bin.l, &l) || !eval_expr(ev, e->u.bin.r, &r))
		return false;
	double a[3], b[3];
	broadcast(&l, e->u.bin.l->type, a);
	broadcast(&r, e->u.bin.r->type, b);
	int comps = e->type == TYPE_VEC ? 3 : 1;
	for (int k = 0; k < comps; k++) {
		switch (e->u.bin.op) {
		case '+': out->v[k] = a[k] + b[k]; break;
		case '-': out->v[k] = a[k] - b[k]; break;
		case '*': out->v[k] = a[k] * b[k]; break;
		default:
			if (b[k] == 0) {
				eval_error(ev, e, "division by zero");
				return false;
			}
			out->v[k] = a[k] / b[k];
		}
		if (!isfinite(out->v[k])) {
			eval_error(ev, e, "the result is too large to be a number");
			return false;
		}
	}
	return true;
}

static bool eval_expr(struct evaluator *ev, struct ast *e, struct value *out)
{
	memset(out, 0, sizeof *out);
	if (++ev->steps > LANG_MAX_STEPS) {
		if (!ev->exhausted)
			eval_error(ev, e, "the scene takes more than %d evaluation steps (its loops do too much work)",
			           LANG_MAX_STEPS);
		ev->exhausted = true;
		return false;
	}
	switch (e->kind) {
	case AST_NUM:
		out->v[0] = e->u.num;
		return true;
	case AST_VEC:
		for (int k = 0; k < 3; k++) {
			struct value c;
			if (!eval_expr(ev, e->u.vec[k], &c))
				return false;
			out->v[k] = c.v[0];
		}
		return true;
	case AST_IDENT:
		if (e->u.ident.builtin == CONST_PI) {
			out->v[0] = M_PI;
			return true;
		}
		if (ev->bad[e->u.ident.ref->slot])
			return false;
		*out = ev->slots[e->u.ident.ref->slot];
		return true;
	case AST_NEG:
		if (!eval_expr(ev, e->u.bin.l, out))
			return false;
		for (int k = 0; k < 3; k++)
			out->v[k] = -out->v[k];
		return true;
	case AST_BINARY:
		return eval_binary(ev, e, out);
	case AST_MEMBER: {
		struct value v;
		if (!eval_expr(ev, e->u.member.e, &v))
			return false;
		out->v[0] = v.v[e->u.member.comp];
		return true;
	}
	case AST_CALL: {
		/* min and max take any number of arguments, millions in a big file: more than
		 * a few go on the heap, not the stack */
		size_t n = e->u.call.args.n;
		struct value small_args[4] = { 0 };
		enum ast_type small_types[4] = { 0 };
		struct value *args = n <= 4 ? small_args : xcalloc(n, sizeof *args);
		enum ast_type *types = n <= 4 ? small_types : xcalloc(n, sizeof *types);
		bool ok = true;
		for (size_t i = 0; i < n && ok; i++) {
			ok = eval_expr(ev, e->u.call.args.v[i], &args[i]);
			types[i] = e->u.call.args.v[i]->type;
		}
		const char *why = ok ? builtin_apply(e->u.call.fn, args, types, (int)n, e->type, out) : NULL;
		if (n > 4) {
			free(args);
			free(types);
		}
		if (why)
			eval_error(ev, e, "%s", why);
		return ok && !why;
	}
	default:
		return false;
	}
}

/* ---- values of items ---- */

static bool vec_of(struct evaluator *ev, struct ast *e, double out[3])
{
	struct value v;
	if (!eval_expr(ev, e, &v))
		return false;
	broadcast(&v, e->type, out);
	return true;
}

static bool num_of(struct evaluator *ev, struct ast *e, double *out)
{
	struct value v;
	if (!eval_expr(ev, e, &v))
		return false;
	*out = v.v[0];
	return true;
}

/* A bound of whole_of for a message: 2^53, the end of exact whole numbers, by name. */
static const char *bound_text(double x, char buf[32])
{
	if (fabs(x) == 9007199254740992.0)
		return x < 0 ? "-2^53" : "2^53";
	return num_text(x, buf);
}

/* A whole number in [lo, hi]; what names it in the message. */
static bool whole_of(struct evaluator *ev, struct ast *e, double lo, double hi, const char *what, double *out)
{
	if (!num_of(ev, e, out))
		return false;
	if (*out != floor(*out) || *out < lo || *out > hi) {
		char lo_buf[32], hi_buf[32], nb[32];
		eval_error(ev, e, "%s must be a whole number from %s to %s, not %s", what, bound_text(lo, lo_buf),
		           bound_text(hi, hi_buf), num_text(*out, nb));
		return false;
	}
	return true;
}

static struct ast *arg0(struct ast *item)
{
	return item->u.item.args.v[0];
}

static bool is_zero(const double v[3])
{
	return v[0] == 0 && v[1] == 0 && v[2] == 0;
}

static void cross(const double a[3], const double b[3], double out[3])
{
	out[0] = a[1] * b[2] - a[2] * b[1];
	out[1] = a[2] * b[0] - a[0] * b[2];
	out[2] = a[0] * b[1] - a[1] * b[0];
}

static double norm(const double v[3])
{
	return hypot(hypot(v[0], v[1]), v[2]);
}

/* v / |v| for a nonzero v, divided by its largest component first so that nothing
 * underflows */
static void unit(const double v[3], double out[3])
{
	double big = fmax(fabs(v[0]), fmax(fabs(v[1]), fabs(v[2])));
	for (int k = 0; k < 3; k++)
		out[k] = v[k] / big;
	double len = norm(out);
	for (int k = 0; k < 3; k++)
		out[k] /= len;
}

/* ---- statements ---- */

static void eval_camera(struct evaluator *ev, struct ast *s)
{
	struct camera_desc *c = &ev->out->camera;
	struct ast *at_look = NULL, *at_up = NULL, *at_loc = NULL;
	char nb[32];
	c->given = true;
	c->span = c->resolution_span = s->u.stmt.kw_span;
	struct ast_list *items = &s->u.stmt.block->items;
	for (size_t i = 0; i < items->n; i++) {
		struct ast *it = items->v[i];
		double w, h;
		switch (it->u.item.kw) {
		case KW_LOCATION: at_loc = it; vec_of(ev, arg0(it), c->location); break;
		case KW_LOOK_AT: at_look = it; vec_of(ev, arg0(it), c->look_at); break;
		case KW_UP: at_up = it; vec_of(ev, arg0(it), c->up); break;
		case KW_FOV:
			if (num_of(ev, arg0(it), &c->fov) && !(c->fov > 0 && c->fov < 180))
				eval_error(ev, arg0(it), "fov must be between 0 and 180 degrees (both excluded), not %s",
				           num_text(c->fov, nb));
			break;
		case KW_RESOLUTION:
			c->resolution_span = it->span;
			/* both, so that a bad width does not hide a bad height */
			if (whole_of(ev, it->u.item.args.v[0], 1, 65536, "the width", &w) &
			    whole_of(ev, it->u.item.args.v[1], 1, 65536, "the height", &h)) {
				if (w * h > LANG_MAX_PIXELS)
					eval_error(ev, it, "%.0f x %.0f is more pixels than the limit of 2^28", w, h);
				c->width = (int)w;
				c->height = (int)h;
			}
			break;
		}
	}
	double dir[3] = { c->look_at[0] - c->location[0], c->look_at[1] - c->location[1],
	                  c->look_at[2] - c->location[2] };
	if (is_zero(dir)) {
		eval_error(ev, at_look ? at_look : at_loc ? at_loc : s, "look_at is the same point as location");
		return;
	}
	if (is_zero(c->up)) {
		eval_error(ev, at_up ? at_up : s, "up must not be a zero vector");
		return;
	}
	/* the sine of the angle between unit vectors: scale-free, also for an up or a
	 * direction of 1e-310 whose products would underflow */
	double u[3], d[3], side[3];
	unit(c->up, u);
	unit(dir, d);
	cross(u, d, side);
	if (norm(side) <= 1e-12 && at_up)
		eval_error(ev, at_up, "up is parallel to the viewing direction");
	else if (norm(side) <= 1e-12) /* the default up: blame the direction */
		eval_error(ev, at_look ? at_look : at_loc ? at_loc : s,
		           "the viewing direction is parallel to the default up <0, 1, 0>; give the camera an 'up'");
}

static void eval_light(struct evaluator *ev, struct ast *s)
{
	struct light_desc l = { .color = { 1, 1, 1 }, .intensity = 1, .span = s->u.stmt.kw_span };
	struct ast_list *items = &s->u.stmt.block->items;
	for (size_t i = 0; i < items->n; i++) {
		struct ast *it = items->v[i];
		switch (it->u.item.kw) {
		case KW_POSITION: vec_of(ev, arg0(it), l.vec); break;
		case KW_DIRECTION:
			l.directional = true;
			if (vec_of(ev, arg0(it), l.vec) && is_zero(l.vec))
				eval_error(ev, arg0(it), "a light's direction must not be a zero vector");
			break;
		case KW_COLOR: vec_of(ev, arg0(it), l.color); break;
		case KW_INTENSITY: num_of(ev, arg0(it), &l.intensity); break;
		case KW_SHADOWLESS: l.shadowless = true; break;
		}
	}
	struct scene_desc *o = ev->out;
	xgrow((void **)&o->lights, &o->cap_lights, o->nlights + 1, sizeof *o->lights);
	o->lights[o->nlights++] = l;
}

static void material_defaults(struct material_desc *m)
{
	memset(m, 0, sizeof *m);
	m->diffuse[0] = m->diffuse[1] = m->diffuse[2] = 0.8;
	m->shininess = 50;
	m->ior = 1;
}

/* Evaluates a material block into a new entry of the scene's materials; returns its index. */
static int eval_material(struct evaluator *ev, struct ast_block *block, const char *name, struct span sp)
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

/* Applies one transform item to x. Returns false after reporting a bad value. */
static bool apply_transform(struct evaluator *ev, struct ast *it, struct xform *x, bool sphere)
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
		if (sphere && (fabs(v[0]) != fabs(v[1]) || fabs(v[1]) != fabs(v[2]))) {
			eval_error(ev, arg0(it), "a sphere cannot be scaled unevenly; use a mesh for an ellipsoid");
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

static void eval_object(struct evaluator *ev, struct ast *s, const struct source *src)
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
			ok &= apply_transform(ev, it, &x, kw == KW_SPHERE);
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

static void eval_skybox(struct evaluator *ev, struct ast *s, const struct source *src)
{
	struct skybox_desc *k = &ev->out->skybox;
	k->span = s->u.stmt.kw_span;
	struct ast_list *items = &s->u.stmt.block->items;
	for (size_t i = 0; i < items->n; i++) {
		struct ast *it = items->v[i];
		switch (it->u.item.kw) {
		case KW_COLOR: k->kind = SKY_COLOR; vec_of(ev, arg0(it), k->color); break;
		case KW_ZENITH: k->kind = SKY_GRADIENT; vec_of(ev, arg0(it), k->color); break;
		case KW_HORIZON: k->kind = SKY_GRADIENT; vec_of(ev, arg0(it), k->horizon); break;
		case KW_IMAGE:
			k->kind = SKY_IMAGE;
			k->image = xstrdup(arg0(it)->u.str.text);
			k->image_path = file_resolve(src->dir, k->image);
			break;
		case KW_ROTATE: num_of(ev, arg0(it), &k->rotate); break;
		case KW_INTENSITY: num_of(ev, arg0(it), &k->intensity); break;
		}
	}
}

static void eval_samples(struct evaluator *ev, struct ast *s)
{
	struct samples_desc *sd = &ev->out->samples;
	struct ast *count_at = s->u.stmt.value, *pattern_at = NULL, *target_at = NULL;
	double x;
	char nb[32];
	if (count_at && whole_of(ev, count_at, 1, 65536, "the sample count", &x))
		sd->count = (int)x;
	struct ast_list *items = s->u.stmt.block ? &s->u.stmt.block->items : NULL;
	for (size_t i = 0; items && i < items->n; i++) {
		struct ast *it = items->v[i];
		switch (it->u.item.kw) {
		case KW_COUNT:
			count_at = arg0(it);
			if (whole_of(ev, count_at, 1, 65536, "the sample count", &x))
				sd->count = (int)x;
			break;
		case KW_PATTERN:
			pattern_at = it;
			sd->pattern_given = true;
			sd->pattern = (enum sample_pattern)arg0(it)->u.ident.builtin;
			break;
		case KW_SEED:
			if (whole_of(ev, arg0(it), 0, 9007199254740992.0, "the seed", &x))
				sd->seed = (uint64_t)x;
			break;
		case KW_TARGET_ERROR:
			target_at = arg0(it);
			if (num_of(ev, arg0(it), &sd->target_error) && !(sd->target_error > 0))
				eval_error(ev, arg0(it), "target_error must be positive, not %s", num_text(sd->target_error, nb));
			break;
		}
	}
	if (!sd->pattern_given)
		sd->pattern = sd->count == 1 ? PATTERN_CENTER : PATTERN_JITTERED;
	if (target_at && sd->pattern == PATTERN_GRID)
		/* an adaptive pixel stops after a prefix of its samples, and a grid's prefix is
		 * a band of rows, not the whole pixel */
		eval_error(ev, target_at, "target_error needs a random, jittered or poisson pattern, not grid");
	if (sd->pattern == PATTERN_CENTER && sd->count != 1)
		eval_error(ev, pattern_at, "pattern center takes exactly one sample, but count is %d", sd->count);
	if (sd->pattern == PATTERN_GRID) {
		int n = (int)sqrt((double)sd->count);
		if (n * n != sd->count)
			eval_error(ev, count_at ? count_at : pattern_at,
			           "pattern grid needs a square count (1, 4, 9, 16, ...), not %d", sd->count);
	}
}

static void eval_stmts(struct evaluator *ev, struct ast_list *stmts);

/* Too many errors, or a limit on the whole evaluation reached: nothing more runs. */
static bool stopped(const struct evaluator *ev)
{
	return diag_stopped(ev->diag) || ev->exhausted;
}

static void eval_for(struct evaluator *ev, struct ast *s)
{
	double from, to;
	if (!whole_of(ev, s->u.loop.from, -9007199254740992.0, 9007199254740992.0, "a for loop's start", &from) ||
	    !whole_of(ev, s->u.loop.to, -9007199254740992.0, 9007199254740992.0, "a for loop's end", &to))
		return;
	if (ev->iterations > LANG_MAX_ITERATIONS) /* the limit was hit: no loop runs any more */
		return;
	double n = to > from ? to - from : 0;
	if (n > (double)(LANG_MAX_ITERATIONS - ev->iterations)) {
		eval_error_span(ev, s, diag_span_join(s->u.loop.from->span, s->u.loop.to->span),
		                "the for loops would run more than %d iterations in all", LANG_MAX_ITERATIONS);
		/* once: the enclosing loops' later runs would only say it again, elsewhere */
		ev->iterations = (uint64_t)LANG_MAX_ITERATIONS + 1;
		return;
	}
	ev->iterations += (uint64_t)n;
	unsigned slot = s->u.loop.b->slot;
	ev->loops[ev->nloops].loop = s;
	ev->nloops++;
	for (double i = from; i < to && !stopped(ev); i++) {
		ev->loops[ev->nloops - 1].i = i;
		ev->slots[slot].v[0] = i;
		eval_stmts(ev, &s->u.loop.body);
	}
	ev->nloops--;
}

static void eval_stmt(struct evaluator *ev, struct ast *s)
{
	if (s->failed)                 /* its error is reported; what it would give is unknown */
		return;
	switch (s->kind) {
	case AST_LET: {
		unsigned slot = s->u.let.b->slot;
		ev->bad[slot] = !eval_expr(ev, s->u.let.value, &ev->slots[slot]);
		break;
	}
	case AST_INCLUDE:
		eval_stmts(ev, &s->u.include.body);
		break;
	case AST_FOR:
		eval_for(ev, s);
		break;
	case AST_BLOCK_STMT: {
		const struct source *src = diag_source_at(ev->diag, s->span.start);
		double depth;
		switch (s->u.stmt.kw) {
		case KW_CAMERA: eval_camera(ev, s); break;
		case KW_LIGHT: eval_light(ev, s); break;
		case KW_SKYBOX: eval_skybox(ev, s, src); break;
		case KW_SAMPLES: eval_samples(ev, s); break;
		case KW_MAX_DEPTH:
			if (whole_of(ev, s->u.stmt.value, 1, LANG_MAX_DEPTH, "max_depth", &depth))
				ev->out->max_depth = (int)depth;
			break;
		case KW_MATERIAL:
			ev->slots[s->u.stmt.b->slot].v[0] =
				eval_material(ev, s->u.stmt.block, s->u.stmt.name, s->u.stmt.name_span);
			break;
		default:
			eval_object(ev, s, src);
			break;
		}
		break;
	}
	default:
		break;
	}
}

static void eval_stmts(struct evaluator *ev, struct ast_list *stmts)
{
	for (size_t i = 0; i < stmts->n && !stopped(ev); i++)
		eval_stmt(ev, stmts->v[i]);
}

struct evaluator *eval_new(struct diag *d, struct scene_desc *out)
{
	struct evaluator *ev = xcalloc(1, sizeof *ev);
	ev->diag = d;
	ev->out = out;
	return ev;
}

/* Makes room for nslots bindings; a new one is not bad until its let says so (a loop
 * variable's and a material's never are). */
static void grow_slots(struct evaluator *ev, size_t nslots)
{
	if (nslots <= ev->nslots)
		return;
	xgrow((void **)&ev->slots, &ev->cap_slots, nslots, sizeof *ev->slots);
	xgrow((void **)&ev->bad, &ev->cap_bad, nslots, sizeof *ev->bad);
	memset(ev->bad + ev->nslots, 0, (nslots - ev->nslots) * sizeof *ev->bad);
	ev->nslots = nslots;
}

void eval_statement(struct evaluator *ev, struct ast *stmt, unsigned nslots)
{
	grow_slots(ev, nslots);
	if (!stopped(ev))
		eval_stmt(ev, stmt);
}

void eval_free(struct evaluator *ev)
{
	free(ev->slots);
	free(ev->bad);
	free(ev);
}

void eval_file(struct diag *d, struct ast_list *stmts, unsigned nslots, struct scene_desc *out)
{
	struct evaluator *ev = eval_new(d, out);
	grow_slots(ev, nslots);
	eval_stmts(ev, stmts);
	eval_free(ev);
}
