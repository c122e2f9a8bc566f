/* check.c: static checks of a scene, before anything is evaluated: every name resolves
 * (with "did you mean" when it does not), every expression has a type, every attribute
 * belongs to its block and has the right shape, camera-like statements appear once and
 * outside loops, includes are read, parsed and checked in place. The checks are static so
 * that a mistake in a loop body is found whether or not the loop runs. This file holds
 * the statements, includes and the entry points; check_expr.c the expressions,
 * check_names.c the symbol table, check_block.c the blocks' attributes. */
#include "check_internal.h"

#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "builtins.h"
#include "file.h"
#include "lang.h"
#include "suggest.h"
#include "xalloc.h"

/* ---- statements ---- */

static void check_stmts(struct checker *c, struct ast_list *stmts);

/* Items a and b (either may be NULL) exclude each other: reports at the later one.
 * Returns whether it reported. */
static bool exclusive(struct checker *c, struct ast *a, struct ast *b, const char *why)
{
	if (!a || !b)
		return false;
	diag_error(c->diag, (a->span.start > b->span.start ? a : b)->u.item.name_span, "%s", why);
	return true;
}

/* What a statement's attributes must satisfy together. When the block had an unknown
 * attribute (!complete), what it lacks goes unreported: the unknown one may be it, misspelt. */
static void check_combination(struct checker *c, struct ast *stmt, struct ast *seen[], bool complete)
{
	struct span at = stmt->u.stmt.kw_span;
	switch (stmt->u.stmt.kw) {
	case KW_CAMERA:
		/* LANGUAGE.md 12: the orthographic view's size is its width; it has no angle */
		if (seen[KW_ORTHOGRAPHIC] && !seen[KW_WIDTH] && complete)
			diag_error(c->diag, at, "an orthographic camera needs a width (the view's width in scene units)");
		if (seen[KW_WIDTH] && !seen[KW_ORTHOGRAPHIC])
			diag_error(c->diag, seen[KW_WIDTH]->u.item.name_span, "'width' applies only to an orthographic camera");
		if (seen[KW_FOV] && seen[KW_ORTHOGRAPHIC])
			diag_error(c->diag, seen[KW_FOV]->u.item.name_span,
			           "an orthographic camera has no fov: its width gives the view");
		break;
	case KW_FOG:
		if (!seen[KW_DISTANCE] && complete)
			diag_error(c->diag, at, "a fog needs a distance");
		break;
	case KW_LIGHT: {
		if (!seen[KW_POSITION] && !seen[KW_DIRECTION] && complete)
			diag_error(c->diag, at, "a light needs a position or a direction");
		exclusive(c, seen[KW_POSITION], seen[KW_DIRECTION], "a light has a position or a direction, not both");
		/* what a light with a direction has no point for */
		static const struct { enum kw kw; const char *why; } placed_only[] = {
			{ KW_SPOTLIGHT, "no point to shine from" }, { KW_AREA, "no point to centre its area on" },
		};
		for (size_t i = 0; i < sizeof placed_only / sizeof placed_only[0]; i++)
			if (seen[placed_only[i].kw] && seen[KW_DIRECTION])
				diag_error(c->diag, seen[placed_only[i].kw]->u.item.name_span, "'%s' applies only to a light with a "
				           "position: a light with a direction has %s", kw_name(placed_only[i].kw), placed_only[i].why);
		struct ast *dist = seen[KW_FADE_DISTANCE], *power = seen[KW_FADE_POWER];
		struct ast *fade = dist && (!power || dist->span.start < power->span.start) ? dist : power;
		if (fade && seen[KW_DIRECTION])
			diag_error(c->diag, fade->u.item.name_span, "'%s' applies only to a light with a position: a light "
			           "with a direction has no distance to fade with", item_name(fade));
		/* POV-Ray's defaults (fade_distance 0, fade_power 0) turn the fade off, which a
		 * scene that names one of the two hardly means */
		else if (!dist != !power)
			diag_warning(c->diag, fade->u.item.name_span, "'%s' without '%s' does not fade: POV-Ray's %s is 0",
			             item_name(fade), dist ? "fade_power" : "fade_distance", dist ? "fade_power" : "fade_distance");
		break;
	}
	case KW_SKYBOX: {
		/* three kinds of sky; one error for the first clash is enough */
		struct ast *zenith = seen[KW_ZENITH], *horizon = seen[KW_HORIZON];
		struct ast *gradient = zenith && (!horizon || zenith->span.start < horizon->span.start) ? zenith : horizon;
		if (!exclusive(c, seen[KW_COLOR], gradient, "a skybox has a color, or a zenith and a horizon, not both") &&
		    !exclusive(c, seen[KW_COLOR], seen[KW_IMAGE], "a skybox has a color or an image, not both"))
			exclusive(c, seen[KW_IMAGE], gradient, "a skybox has an image, or a zenith and a horizon, not both");
		if (!seen[KW_COLOR] && !gradient && !seen[KW_IMAGE]) {
			if (complete)
				diag_error(c->diag, at, "a skybox needs a color, a zenith and a horizon, or an image");
		} else if (!seen[KW_IMAGE] && !seen[KW_COLOR] && (!zenith || !horizon) && complete) {
			diag_error(c->diag, gradient->u.item.name_span, "a skybox gradient needs both a zenith and a horizon");
		}
		static const enum kw image_only[] = { KW_ROTATE, KW_INTENSITY };
		for (size_t i = 0; i < sizeof image_only / sizeof image_only[0]; i++)
			if (seen[image_only[i]] && !seen[KW_IMAGE])
				diag_error(c->diag, seen[image_only[i]]->u.item.name_span,
				           "'%s' applies only to an image skybox", kw_name(image_only[i]));
		break;
	}
	case KW_MESH: {
		bool file = stmt->u.stmt.block->args.n > 0;
		if (file)
			check_value(c, stmt->u.stmt.block->args.v[0], S_STR, "a mesh's file name");
		if (file && (seen[KW_VERTICES] || seen[KW_FACES] || seen[KW_NORMALS] || seen[KW_UVS])) {
			struct ast *x = seen[KW_VERTICES] ? seen[KW_VERTICES] : seen[KW_FACES] ? seen[KW_FACES]
			              : seen[KW_NORMALS] ? seen[KW_NORMALS] : seen[KW_UVS];
			diag_error(c->diag, x->u.item.name_span, "a mesh read from a file takes no '%s'", item_name(x));
		} else if (!file && (!seen[KW_VERTICES] || !seen[KW_FACES]) && complete) {
			diag_error(c->diag, at, "a mesh needs a file name, or vertices { ... } and faces { ... }");
		}
		if (!file && seen[KW_INTERPOLATE]) /* an inline mesh has no textures of its own */
			diag_error(c->diag, seen[KW_INTERPOLATE]->u.item.name_span,
			           "'interpolate' applies to the textures of a mesh file; an image { ... } takes its own");
		break;
	}
	default:
		break;
	}
	if (kw_is_object(stmt->u.stmt.kw) && seen[KW_INVERSE])
		check_inverse(c, stmt, seen[KW_INVERSE]);
}

/* A CSG: its items, then its members, each a statement of its own (a for loop's body is
 * checked as anywhere else); then what the members must be. Any error inside fails the
 * whole CSG. */
static void check_csg(struct checker *c, struct ast *s)
{
	enum kw kw = s->u.stmt.kw;
	struct ast_block *block = s->u.stmt.block;
	struct ast *seen[KW_COUNT_ALL] = { 0 };
	check_block(c, spec_of(kw), block, s->u.stmt.kw_span, seen);
	struct ast *outer = c->csg;
	unsigned outer_loops = c->csg_loops;
	bool outer_failed = c->csg_failed;
	c->csg = s;
	c->csg_loops = 0;
	c->csg_failed = false;
	for (size_t i = 0; i < block->members.n && !diag_stopped(c->diag); i++)
		check_statement(c, block->members.v[i]);
	c->tainted |= c->csg_failed || block->broken;
	c->csg = outer;
	c->csg_loops = outer_loops;
	c->csg_failed = outer_failed;
	if (block->members.n == 0)
		diag_error(c->diag, s->u.stmt.kw_span, "%s %s needs at least one object: %s { OBJECT ...  ITEMS }",
		           kw == KW_INTERSECTION ? "an" : "a", kw_name(kw), kw_name(kw));
	if (kw != KW_UNION)
		check_solid_members(c, s);
	if (seen[KW_INVERSE])
		check_inverse(c, s, seen[KW_INVERSE]);
}

static void check_block_stmt(struct checker *c, struct ast *s)
{
	enum kw kw = s->u.stmt.kw;
	if (kw_is_csg(kw)) {
		check_csg(c, s);
		return;
	}
	if (kw == KW_CAMERA || kw == KW_SKYBOX || kw == KW_SAMPLES || kw == KW_MAX_DEPTH || kw == KW_FOG) {
		if (c->def_depth)
			diag_error(c->diag, s->u.stmt.kw_span, "'%s' cannot be inside a definition: it is one per scene",
			           kw_name(kw));
		else if (c->loop_depth)
			diag_error(c->diag, s->u.stmt.kw_span, "'%s' cannot be inside a for loop", kw_name(kw));
		else if (c->once[kw].seen) {
			diag_error(c->diag, s->u.stmt.kw_span, "a scene has at most one '%s'", kw_name(kw));
			diag_note(c->diag, c->once[kw].at, "the first '%s' is here", kw_name(kw));
		} else {
			c->once[kw].seen = true;
			c->once[kw].at = s->u.stmt.kw_span;
		}
	}
	if (s->u.stmt.value) {   /* samples N, max_depth N */
		if (s->u.stmt.value->kind != AST_ERROR)
			check_value(c, s->u.stmt.value, S_NUM, kw_name(kw));
		else
			c->tainted = true;
		return;
	}
	if (s->u.stmt.block->broken) { /* a syntax error was reported inside */
		c->tainted = true;
		if (kw == KW_MATERIAL)
			s->u.stmt.b = names_bind(c, s->u.stmt.name, s->u.stmt.name_span, BIND_MATERIAL, TYPE_MATERIAL);
		return;
	}
	if (kw == KW_LIGHT && c->macro && !c->macro->u.def.not_member)
		c->macro->u.def.not_member = s;
	if (kw == KW_MESH)
		block_file_name(c, s->u.stmt.block);
	struct ast *seen[KW_COUNT_ALL] = { 0 };
	c->defining = kw == KW_MATERIAL ? s->u.stmt.name : NULL;
	bool complete = check_block(c, spec_of(kw), s->u.stmt.block, s->u.stmt.kw_span, seen);
	c->defining = NULL;
	check_combination(c, s, seen, complete);
	const struct source *src = diag_source_at(c->diag, s->span.start);
	if (kw == KW_MESH && s->u.stmt.block->args.n && s->u.stmt.block->args.v[0]->kind == AST_STR)
		check_readable(c, src, s->u.stmt.block->args.v[0], "mesh file");
	if (kw == KW_SKYBOX && seen[KW_IMAGE] && seen[KW_IMAGE]->u.item.args.n == 1 &&
	    seen[KW_IMAGE]->u.item.args.v[0]->kind == AST_STR)
		check_readable(c, src, seen[KW_IMAGE]->u.item.args.v[0], "skybox image");
	if (kw == KW_MATERIAL)
		s->u.stmt.b = names_bind(c, s->u.stmt.name, s->u.stmt.name_span, BIND_MATERIAL, TYPE_MATERIAL);
}

static void check_include(struct checker *c, struct ast *inc)
{
	const struct source *from = diag_source_at(c->diag, inc->span.start);
	const char *name = inc->u.include.path;
	struct span at = inc->u.include.path_span;
	if (c->include_depth >= LANG_MAX_INCLUDE_DEPTH) {
		diag_error(c->diag, at, "includes nested more than %d deep", LANG_MAX_INCLUDE_DEPTH);
		return;
	}
	/* two includes of the next file in each of 30 files would read 2^30 files */
	if (c->nincludes >= LANG_MAX_INCLUDES) {
		if (c->nincludes++ == LANG_MAX_INCLUDES) /* once; the includes after it are skipped */
			diag_error(c->diag, at, "more than %d files included in all (each include of a file counts)",
			           LANG_MAX_INCLUDES);
		return;
	}
	char *path = file_resolve(from->dir, name);
	const char *why = file_not_regular(path);
	if (why) {
		diag_error(c->diag, at, "cannot read included file '%s': %s", name, why);
		free(path);
		return;
	}
	char *real = realpath(path, NULL);
	for (int i = 0; real && i <= c->include_depth; i++)
		if (c->include_stack[i] && strcmp(c->include_stack[i], real) == 0) {
			diag_error(c->diag, at, "include cycle: '%s' is already being read", name);
			free(real);
			free(path);
			return;
		}
	char *text;
	uint32_t len;
	c->nincludes++;
	int err = file_read(path, &text, &len);
	if (err) {
		diag_error(c->diag, at, "cannot read included file '%s': %s", name,
		           err == EFBIG ? "the scene's files exceed 256 MiB in all" : strerror(err));
		free(real);
		free(path);
		return;
	}
	const struct source *src = diag_add_source(c->diag, path, text, len, from, at);
	free(path);
	if (!src) {
		diag_error(c->diag, at, "cannot read included file '%s': the scene's files exceed 256 MiB in all", name);
		free(real);
		return;
	}
	inc->u.include.body = lang_parse(c->nodes, c->arena, c->diag, src);
	inc->u.include.loaded = true;
	c->include_stack[++c->include_depth] = real;
	check_stmts(c, &inc->u.include.body);
	c->include_stack[c->include_depth--] = NULL;
	free(real);
}

/* The objects' keywords, which a CSG's members start with. */
static const enum kw objects[] = {
	KW_SPHERE, KW_PLANE, KW_TRIANGLE, KW_MESH, KW_BOX, KW_CYLINDER, KW_CONE, KW_DISC, KW_TORUS,
	KW_UNION, KW_MERGE, KW_INTERSECTION, KW_DIFFERENCE,
};
#define NOBJECTS (sizeof objects / sizeof objects[0])

/* An unknown name inside a CSG, or in a for loop there: a misspelt object, or (in the
 * CSG itself) a misspelt item; the closer guess says which. */
static void unknown_in_csg(struct checker *c, struct ast *s)
{
	static const enum kw items[] = { KW_MATERIAL, KW_TRANSLATE, KW_ROTATE, KW_SCALE, KW_INVERSE };
	const char *name = s->u.item.name, *csg = kw_name(c->csg->u.stmt.kw);
	bool loop = c->csg_loops > 0;
	char buf[160];
	const char *hint = suggest_pov_hint(name, buf, sizeof buf);
	if (hint) {
		diag_error(c->diag, s->u.item.name_span, "unknown name '%s' in %s%s", name, csg, hint);
		return;
	}
	struct suggestion sg;
	suggest_init(&sg, name);
	for (size_t i = 0; i < NOBJECTS; i++)
		suggest_consider(&sg, kw_name(objects[i]));
	suggest_consider(&sg, kw_name(KW_FOR));
	if (loop)
		suggest_consider(&sg, kw_name(KW_LET));
	const char *statement = sg.best;
	for (size_t i = 0; i < sizeof items / sizeof items[0] && !loop; i++)
		suggest_consider(&sg, kw_name(items[i]));
	/* written with braces, a name that suggests nothing is an object's */
	bool braces = s->u.item.args.n == 0 && s->span.end > s->u.item.name_span.end;
	bool object = loop || (sg.best ? sg.best == statement : braces);
	hint = suggest_text(&sg, buf, sizeof buf);
	if (loop)
		diag_error(c->diag, s->u.item.name_span, "unknown statement '%s' in %s inside %s %s%s", name, c->csg_body,
		           c->csg->u.stmt.kw == KW_INTERSECTION ? "an" : "a", csg, hint);
	else
		diag_error(c->diag, s->u.item.name_span, "unknown %s '%s' in %s%s", object ? "object" : "attribute", name, csg,
		           hint);
}

static void unknown_statement(struct checker *c, struct ast *s)
{
	static const enum kw statements[] = {
		KW_LET, KW_INCLUDE, KW_FOR, KW_IF, KW_DEF, KW_CAMERA, KW_LIGHT, KW_MATERIAL, KW_SKYBOX, KW_SAMPLES,
		KW_MAX_DEPTH, KW_FOG,
	};
	if (c->csg) {
		unknown_in_csg(c, s);
		return;
	}
	const char *name = s->u.item.name;
	char buf[160];
	const char *hint = suggest_pov_hint(name, buf, sizeof buf);
	if (!hint) {
		struct suggestion sg;
		suggest_init(&sg, name);
		for (size_t i = 0; i < sizeof statements / sizeof statements[0]; i++)
			suggest_consider(&sg, kw_name(statements[i]));
		for (size_t i = 0; i < NOBJECTS; i++)
			suggest_consider(&sg, kw_name(objects[i]));
		names_suggest_visible(c, &sg, NAMES_MACROS);
		hint = suggest_text(&sg, buf, sizeof buf);
	}
	diag_error(c->diag, s->u.item.name_span, "unknown statement '%s'%s", name, hint);
}

/* A keyword's span: the first len bytes of sp. */
static struct span first_bytes(struct span sp, uint32_t len)
{
	return (struct span){ sp.start, sp.start + len };
}

/* Whether s may stand in the CSG c->csg, or in a for loop or an if there; reports it
 * when not, saying what may. Returns false when s is to be checked no further: not a
 * misplaced let or material, which are still bound, so that their uses say nothing more. */
static bool placed(struct checker *c, struct ast *s)
{
	const char *name = kw_name(c->csg->u.stmt.kw);
	char csg[32];
	snprintf(csg, sizeof csg, "%s %s", c->csg->u.stmt.kw == KW_INTERSECTION ? "an" : "a", name);
	bool body = c->csg_loops > 0;
	char what[64];
	struct span at;
	switch (s->kind) {
	case AST_LET: case AST_DEF:
		if (body) /* a loop's or an if's body is a scope */
			return true;
		at = first_bytes(s->span, 3);
		snprintf(what, sizeof what, "'%s'", s->kind == AST_LET ? "let" : "def");
		break;
	case AST_INCLUDE:
		at = first_bytes(s->span, 7);
		snprintf(what, sizeof what, "'include'");
		break;
	case AST_ITEM: /* an item in a for loop's or an if's body: the CSG's own are apart */
		diag_error(c->diag, s->u.item.name_span, "'%s' cannot be in %s inside %s; give it to the %s, "
		           "or to each object", item_name(s), c->csg_body, csg, name);
		return false;
	case AST_BLOCK_STMT:
		if (kw_is_object(s->u.stmt.kw))
			return true;
		at = s->u.stmt.kw_span;
		if (s->u.stmt.kw == KW_MATERIAL) {
			diag_error(c->diag, at, "a material definition cannot be inside %s: define it before the %s (%s takes "
			           "material NAME or material { ... })", csg, name, csg);
			return true;
		}
		snprintf(what, sizeof what, "'%s'", kw_name(s->u.stmt.kw));
		break;
	default: /* a for loop, an if, a macro call; an unknown name, a syntax error: each says so */
		return true;
	}
	if (body)
		diag_error(c->diag, at, "%s cannot be in %s inside %s; there it holds objects, for loops, ifs, macro "
		           "calls and let", what, c->csg_body, csg);
	else
		diag_error(c->diag, at, "%s cannot be inside %s; a CSG holds objects (or for loops, ifs and macro calls "
		           "that make them), material, transforms and inverse", what, csg);
	return s->kind == AST_LET || s->kind == AST_DEF;
}

/* Whether another scope fits (a loop's takes two); includes can nest bodies past one
 * file's brackets. Reports at `at` when not. */
static bool room_for_scopes(struct checker *c, struct span at)
{
	if (c->scope + 2 < sizeof c->scope_bindings / sizeof c->scope_bindings[0])
		return true;
	diag_error(c->diag, at, "blocks nested more than %d deep", LANG_MAX_NESTING);
	return false;
}

/* A body of statements in a scope of its own: a for loop's or an if's (what, for messages). */
static void check_body(struct checker *c, struct ast_list *body, const char *what)
{
	const char *outer = c->csg_body;
	names_push_scope(c);
	c->csg_loops += c->csg != NULL;
	c->csg_body = what;
	check_stmts(c, body);
	c->csg_body = outer;
	c->csg_loops -= c->csg != NULL;
	names_pop_scope(c);
}

/* The statements a scene has at most one of. */
static const enum kw once_kws[] = { KW_CAMERA, KW_SKYBOX, KW_SAMPLES, KW_MAX_DEPTH, KW_FOG };
#define NONCE (sizeof once_kws / sizeof once_kws[0])

static void check_if(struct checker *c, struct ast *s)
{
	char why[160];
	struct ast *cond = s->u.cond_stmt.cond;
	enum ast_type t = check_expr(c, cond);
	if (t != TYPE_NONE && !value_type_condition(t, why, sizeof why))
		diag_error(c->diag, cond->span, "%s", why);
	/* the branches are alternatives: each may hold the scene's one camera */
	struct { bool seen; struct span at; } before[NONCE], then[NONCE];
	for (size_t k = 0; k < NONCE; k++) {
		before[k].seen = c->once[once_kws[k]].seen;
		before[k].at = c->once[once_kws[k]].at;
	}
	if (!room_for_scopes(c, first_bytes(s->span, 2)))
		return;
	check_body(c, &s->u.cond_stmt.then, "an if");
	for (size_t k = 0; k < NONCE; k++) {
		then[k].seen = c->once[once_kws[k]].seen;
		then[k].at = c->once[once_kws[k]].at;
		c->once[once_kws[k]].seen = before[k].seen;
		c->once[once_kws[k]].at = before[k].at;
	}
	check_body(c, &s->u.cond_stmt.other, "an if");
	for (size_t k = 0; k < NONCE; k++)
		if (then[k].seen && !c->once[once_kws[k]].seen) {
			c->once[once_kws[k]].seen = true;
			c->once[once_kws[k]].at = then[k].at;
		}
}

/* A function or a macro: bound before its body, which may call it; the body is checked
 * once, where it is defined, its parameters of types known only at each call. */
static void check_def(struct checker *c, struct ast *s)
{
	struct ast *value = s->u.def.value;
	bool macro = !value;
	const char *name = s->u.def.name;
	int fn = builtin_lookup(name);
	if (fn >= 0)
		diag_error(c->diag, s->u.def.name_span, "'%s' is a built-in %s; give yours another name", name,
		           builtin_is_function(fn) ? "function" : "constant");
	struct binding *b = names_bind(c, name, s->u.def.name_span, macro ? BIND_MACRO : BIND_FUNCTION, TYPE_NONE);
	s->u.def.b = b;
	if (b)
		b->def = s;
	if (!room_for_scopes(c, s->u.def.name_span))
		return;
	if (b)
		b->checking = true;
	struct ast *outer_csg = c->csg, *outer_macro = c->macro;
	unsigned outer_loops = c->csg_loops;
	bool outer_failed = c->csg_failed;
	c->csg = NULL; /* its statements are a CSG's members only where a call puts them */
	c->csg_loops = 0;
	c->macro = macro ? s : outer_macro;
	c->def_depth++;
	s->u.def.slot_lo = c->nslots; /* the parameters' slots come first: eval_call.c */
	names_push_scope(c);
	for (size_t i = 0; i < s->u.def.params.n; i++) {
		struct ast *p = s->u.def.params.v[i];
		p->u.ident.ref = names_bind(c, p->u.ident.name, p->span, BIND_PARAM, TYPE_ANY);
	}
	if (macro) {
		check_stmts(c, &s->u.def.body);
	} else if (check_expr(c, value) == TYPE_PIGMENT) {
		diag_error(c->diag, value->span, "checker(...) can only be the value of diffuse");
	}
	names_pop_scope(c);
	s->u.def.slot_hi = c->nslots;
	c->def_depth--;
	c->macro = outer_macro;
	c->csg = outer_csg;
	c->csg_loops = outer_loops;
	c->csg_failed = outer_failed;
	if (b)
		b->checking = false;
}

static void check_macro_call(struct checker *c, struct ast *s)
{
	const char *name = s->u.call.name;
	struct binding *b = names_lookup(c, name);
	if (b && b->kind == BIND_MACRO) {
		check_user_call(c, s, b);
		const struct ast *light = b->def->u.def.not_member;
		if (light && c->csg) {
			diag_error(c->diag, s->u.call.name_span, "'%s' makes a light, which cannot be inside %s %s", name,
			           c->csg->u.stmt.kw == KW_INTERSECTION ? "an" : "a", kw_name(c->csg->u.stmt.kw));
			diag_note(c->diag, light->u.stmt.kw_span, "the light is here");
		}
		if (light && c->macro && !c->macro->u.def.not_member)
			c->macro->u.def.not_member = light;
		return;
	}
	for (size_t i = 0; i < s->u.call.args.n; i++)
		check_expr(c, s->u.call.args.v[i]);
	c->tainted = true;
	int fn = builtin_lookup(name);
	if (b && b->kind == BIND_FUNCTION)
		diag_error(c->diag, s->u.call.name_span, "'%s' is a function: its value goes in an expression, as in "
		           "let v = %s(...); a statement calls a macro", name, name);
	else if (b)
		diag_error(c->diag, s->u.call.name_span, "'%s' is not a macro", name);
	else if (fn >= 0 && builtin_is_function(fn))
		diag_error(c->diag, s->u.call.name_span, "'%s' is a built-in function: its value goes in an expression",
		           name);
	else
		unknown_name(c, s->u.call.name_span, name, NAMES_MACROS);
}

static void check_parts(struct checker *c, struct ast *s)
{
	if (c->csg && !placed(c, s))
		return;
	switch (s->kind) {
	case AST_LET: {
		enum ast_type t = check_expr(c, s->u.let.value);
		if (t == TYPE_PIGMENT) {
			diag_error(c->diag, s->u.let.value->span, "checker(...) can only be the value of diffuse");
			t = TYPE_NONE;
		}
		s->u.let.b = names_bind(c, s->u.let.name, s->u.let.name_span, BIND_VALUE, t);
		if (s->u.let.b && t == TYPE_NONE)
			s->u.let.b->used = true; /* already reported; no "never used" on top */
		break;
	}
	case AST_INCLUDE:
		check_include(c, s);
		c->include_failed |= !s->u.include.loaded;
		break;
	case AST_FOR: {
		enum ast_type var = TYPE_NUM;
		if (s->u.loop.to) {
			check_value(c, s->u.loop.from, S_NUM, "the for loop's start");
			check_value(c, s->u.loop.to, S_NUM, "the for loop's end");
		} else {
			enum ast_type t = check_expr(c, s->u.loop.from);
			if (t != TYPE_NONE && t != TYPE_ARRAY && t != TYPE_ANY)
				diag_error(c->diag, s->u.loop.from->span, "a for loop runs over a range A .. B or an array, "
				           "found %s", value_type_name(t));
			var = TYPE_ANY;
		}
		if (c->loop_depth == LANG_MAX_NESTING) { /* includes can nest loops past one file's brackets */
			diag_error(c->diag, s->u.loop.var_span, "for loops nested more than %d deep", LANG_MAX_NESTING);
			break;
		}
		if (!room_for_scopes(c, s->u.loop.var_span))
			break;
		/* the loop variable has a scope of its own, around the body's: the body may
		 * rebind its name (let i = i * 10) */
		names_push_scope(c);
		c->loop_depth++;
		s->u.loop.b = names_bind(c, s->u.loop.var, s->u.loop.var_span, BIND_LOOP, var);
		check_body(c, &s->u.loop.body, "a for loop");
		c->loop_depth--;
		names_pop_scope(c);
		break;
	}
	case AST_IF:
		check_if(c, s);
		break;
	case AST_DEF:
		check_def(c, s);
		break;
	case AST_MACRO_CALL:
		check_macro_call(c, s);
		break;
	case AST_UNKNOWN_STMT:
		unknown_statement(c, s);
		break;
	case AST_BLOCK_STMT:
		check_block_stmt(c, s);
		break;
	case AST_ERROR: /* a syntax error in a CSG's for loop, reported */
		c->tainted = true;
		break;
	default:
		break;
	}
}

/* The binding a statement makes, if any. */
static struct binding *binding_of(struct ast *s)
{
	switch (s->kind) {
	case AST_LET: return s->u.let.b;
	case AST_FOR: return s->u.loop.b;
	case AST_DEF: return s->u.def.b;
	case AST_BLOCK_STMT: return s->u.stmt.kw == KW_MATERIAL ? s->u.stmt.b : NULL;
	default: return NULL;
	}
}

/* Checks s, and marks it failed when it reported an error of its own (not one of the
 * statements in its body: a loop or an include whose body has an error still runs the
 * rest of its body) or uses what failed. */
void check_statement(struct checker *c, struct ast *s)
{
	int before = c->diag->errors, nested_before = c->nested_errors;
	bool tainted = c->tainted;
	c->tainted = false;
	check_parts(c, s);
	int own = c->diag->errors - before - (c->nested_errors - nested_before);
	s->failed = own > 0 || c->tainted;
	c->csg_failed |= s->failed && c->csg;
	struct binding *b = binding_of(s);
	if (b)
		b->failed = s->failed;
	c->tainted = tainted;
	c->nested_errors = nested_before + (c->diag->errors - before);
}

static void check_stmts(struct checker *c, struct ast_list *stmts)
{
	for (size_t i = 0; i < stmts->n && !diag_stopped(c->diag); i++)
		check_statement(c, stmts->v[i]);
}

struct checker *check_new(struct arena *nodes, struct arena *keep, struct diag *d, const struct source *src,
                            struct ast_list *root)
{
	struct checker *c = xcalloc(1, sizeof *c);
	c->arena = keep;
	c->nodes = nodes;
	c->diag = d;
	c->nbuckets = 256;
	c->buckets = xcalloc(c->nbuckets, sizeof *c->buckets);
	c->include_stack[0] = realpath(src->path, NULL); /* NULL for standard input */
	c->root = root;
	names_push_scope(c);
	return c;
}

unsigned check_slots(const struct checker *c)
{
	return c->nslots;
}

void check_free(struct checker *c, bool finished)
{
	if (finished && !diag_stopped(c->diag))
		names_pop_scope(c);
	free(c->include_stack[0]);
	free(c->buckets);
	free(c);
}

unsigned check_file(struct arena *a, struct diag *d, const struct source *src, struct ast_list *stmts)
{
	struct checker *c = check_new(a, a, d, src, stmts);
	check_stmts(c, stmts);
	unsigned nslots = check_slots(c);
	check_free(c, true);
	return nslots;
}
