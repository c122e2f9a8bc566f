/* check_expr.c: the checker's expressions (check.c has the rest): every name resolves,
 * with "did you mean" or a note on a definition that comes too late when it does not,
 * and every expression gets its type. */
#include "check_internal.h"

#include <stdio.h>
#include <string.h>

#include "builtins.h"
#include "suggest.h"

/* The name a statement defines (let, material, def), or NULL, and where. */
static const char *defined_name(const struct ast *s, struct span *at)
{
	switch (s->kind) {
	case AST_LET: *at = s->u.let.name_span; return s->u.let.name;
	case AST_DEF: *at = s->u.def.name_span; return s->u.def.name;
	case AST_BLOCK_STMT:
		*at = s->u.stmt.name_span;
		return s->u.stmt.kw == KW_MATERIAL ? s->u.stmt.name : NULL;
	default: return NULL;
	}
}

/* The definition of that name after offset 'after' in the same file, outside includes,
 * or NULL: for "defined later" notes. */
static const struct ast *later_definition(const struct ast_list *stmts, const char *name, uint32_t after,
                                          const struct source *src, const struct diag *d)
{
	for (size_t i = 0; i < stmts->n; i++) {
		const struct ast *s = stmts->v[i];
		struct span at;
		const char *defined = defined_name(s, &at);
		if (defined && strcmp(defined, name) == 0 && s->span.start > after && diag_source_at(d, s->span.start) == src)
			return s;
		const struct ast *found = NULL;
		if (s->kind == AST_FOR)
			found = later_definition(&s->u.loop.body, name, after, src, d);
		if (s->kind == AST_IF && !(found = later_definition(&s->u.cond_stmt.then, name, after, src, d)))
			found = later_definition(&s->u.cond_stmt.other, name, after, src, d);
		if (found)
			return found;
	}
	return NULL;
}

/* Reports a name that means nothing here, with the most useful hint. */
void unknown_name(struct checker *c, struct span at, const char *name, enum name_class what_class)
{
	bool material = what_class == NAMES_MATERIALS;
	/* it may well be defined in a file that could not be read; and once the run has
	 * stopped nothing prints, so the searches below (all names, all statements) are skipped */
	if (c->include_failed || diag_stopped(c->diag))
		return;
	const char *what = material ? "material" : what_class == NAMES_FUNCTIONS ? "function"
	                 : what_class == NAMES_MACROS ? "macro" : "name";
	if (what_class == NAMES_VALUES && (strcmp(name, "x") == 0 || strcmp(name, "y") == 0 || strcmp(name, "z") == 0)) {
		diag_error(c->diag, at, "unknown name '%s' (scn has no x, y, z vectors: write <1, 0, 0>, <0, 1, 0>, <0, 0, 1>)",
		           name);
		return;
	}
	if (material && c->defining && strcmp(name, c->defining) == 0) {
		diag_error(c->diag, at, "a material cannot be like itself");
		return;
	}
	struct suggestion s;
	char buf[96];
	suggest_init(&s, name);
	names_suggest_visible(c, &s, what_class);
	char pov[160];
	const char *hint = what_class == NAMES_MACROS || what_class == NAMES_FUNCTIONS
	                   ? suggest_pov_hint(name, pov, sizeof pov) : NULL;
	diag_error(c->diag, at, "unknown %s '%s'%s", what, name, hint ? hint : suggest_text(&s, buf, sizeof buf));
	const struct ast *later = c->root ? later_definition(c->root, name, at.start, diag_source_at(c->diag, at.start), c->diag)
	                                  : NULL;
	struct span later_at;
	if (later && defined_name(later, &later_at))
		diag_note(c->diag, later_at, "'%s' is defined here, after its use; a name is visible only after its definition",
		          name);
}

/* A definition's binding, used: a call from inside its own body is recursion, not a use. */
static void use(struct checker *c, struct binding *b)
{
	b->used |= !b->checking;
	c->tainted |= b->failed;
}

static enum ast_type check_ident(struct checker *c, struct ast *e)
{
	const char *name = e->u.ident.name;
	struct binding *b = names_lookup(c, name);
	int fn = b ? -1 : builtin_lookup(name);
	if (b) {
		use(c, b);
		e->u.ident.ref = b;
	}
	if (b ? b->kind == BIND_FUNCTION : fn >= 0 && builtin_is_function(fn)) {
		diag_error(c->diag, e->span, "'%s' is a function; call it as %s(...)", name, name);
		return TYPE_NONE;
	}
	if (b) {
		switch (b->kind) {
		case BIND_MATERIAL: /* a value to pass on: to a macro, into an array */
			return TYPE_MATERIAL;
		case BIND_MACRO:
			diag_error(c->diag, e->span, "'%s' is a macro: it makes objects where it is called as a statement, "
			           "%s(...), and has no value", name, name);
			return TYPE_NONE;
		default:
			return b->type;
		}
	}
	if (fn >= 0) { /* pi, clock, frame */
		e->u.ident.builtin = fn;
		return TYPE_NUM;
	}
	unknown_name(c, e->span, name, NAMES_VALUES);
	c->tainted = true; /* also when unknown_name says nothing (a name an unread include may define) */
	return TYPE_NONE;
}

/* The number of arguments against a definition's parameters. */
static bool arg_count(struct checker *c, struct ast *call, const char *name, int lo, int hi)
{
	int n = (int)call->u.call.args.n;
	if (n >= lo && (hi < 0 || n <= hi))
		return true;
	if (lo == hi)
		diag_error(c->diag, call->span, "%s takes %d argument%s, not %d", name, lo, lo == 1 ? "" : "s", n);
	else
		diag_error(c->diag, call->span, "%s takes at least %d arguments, not %d", name, lo, n);
	return false;
}

/* A value handed to a function or a macro: anything a binding may hold. */
static bool check_argument(struct checker *c, struct ast *e)
{
	enum ast_type t = check_expr(c, e);
	if (t == TYPE_PIGMENT) {
		diag_error(c->diag, e->span, "checker(...) can only be the value of diffuse");
		return false;
	}
	return t != TYPE_NONE;
}

void check_user_call(struct checker *c, struct ast *call, struct binding *b)
{
	use(c, b);
	call->u.call.ref = b;
	int nparams = (int)b->def->u.def.params.n;
	bool ok = arg_count(c, call, call->u.call.name, nparams, nparams);
	for (size_t i = 0; i < call->u.call.args.n; i++)
		ok &= check_argument(c, call->u.call.args.v[i]);
	if (!ok)
		c->tainted = true;
}

static enum ast_type check_call(struct checker *c, struct ast *e)
{
	const char *name = e->u.call.name;
	struct ast_list *args = &e->u.call.args;
	struct binding *b = names_lookup(c, name);
	if (b && b->kind == BIND_FUNCTION) {
		check_user_call(c, e, b);
		return TYPE_ANY;
	}
	/* functions are only ever called: a value or a material may share a built-in
	 * function's name (LANGUAGE.md's own scene names a material floor) */
	int fn = builtin_lookup(name);
	if (fn < 0 || !builtin_is_function(fn)) {
		if (b && b->kind == BIND_MACRO)
			diag_error(c->diag, e->u.call.name_span, "'%s' is a macro: call it as a statement; it has no value", name);
		else if (b || fn >= 0)
			diag_error(c->diag, e->u.call.name_span, "'%s' is not a function", name);
		else
			unknown_name(c, e->u.call.name_span, name, NAMES_FUNCTIONS);
		for (size_t i = 0; i < args->n; i++)
			check_expr(c, args->v[i]);
		c->tainted = true;
		return TYPE_NONE;
	}
	e->u.call.fn = fn;
	if (!arg_count(c, e, name, builtin_min_args(fn), builtin_max_args(fn)))
		return TYPE_NONE;
	int n = (int)args->n;
	enum ast_type types[64];
	bool ok = true;
	for (int i = 0; i < n; i++) {
		enum ast_type t = check_expr(c, args->v[i]);
		ok &= t != TYPE_NONE;
		/* min, max: the last slot is the most telling of the arguments past it */
		if (i < 64 || t == TYPE_VEC || (t != TYPE_NUM && t != TYPE_ANY))
			types[i < 64 ? i : 63] = t;
	}
	if (!ok)
		return TYPE_NONE;
	int bad = -1;
	const char *why = NULL;
	enum ast_type t = builtin_type(fn, types, n < 64 ? n : 64, &bad, &why);
	if (t == TYPE_NONE)
		diag_error(c->diag, args->v[bad]->span, "%s, found %s", why, value_type_name(types[bad]));
	return t;
}

/* The message of a value rule (value.h) at its place. */
static enum ast_type reported(struct checker *c, struct span at, const char *why)
{
	diag_error(c->diag, at, "%s", why);
	return TYPE_NONE;
}

static enum ast_type check_expr_inner(struct checker *c, struct ast *e)
{
	char why[160];
	switch (e->kind) {
	case AST_NUM:
		return TYPE_NUM;
	case AST_STR:
		return TYPE_STR;
	case AST_BOOL:
		return TYPE_BOOL;
	case AST_ERROR:                /* a syntax error, reported where it is */
		c->tainted = true;
		return TYPE_NONE;
	case AST_IDENT:
		return check_ident(c, e);
	case AST_VEC: {
		bool ok = true;
		for (int k = 0; k < 3; k++) {
			enum ast_type t = check_expr(c, e->u.vec[k]);
			if (t == TYPE_NONE)
				ok = false;
			else if (t != TYPE_NUM && t != TYPE_ANY) {
				diag_error(c->diag, e->u.vec[k]->span, "a vector's components must be numbers, found %s",
				           value_type_name(t));
				ok = false;
			}
		}
		return ok ? TYPE_VEC : TYPE_NONE;
	}
	case AST_ARRAY: {
		bool ok = true;
		for (size_t i = 0; i < e->u.elems.n; i++)
			ok &= check_argument(c, e->u.elems.v[i]);
		return ok ? TYPE_ARRAY : TYPE_NONE;
	}
	case AST_NEG: case AST_NOT: {
		enum ast_type t = check_expr(c, e->u.bin.l);
		if (t == TYPE_NONE)
			return TYPE_NONE;
		t = value_type_unary(e->u.bin.op, t, why, sizeof why);
		return t == TYPE_NONE ? reported(c, e->u.bin.l->span, why) : t;
	}
	case AST_BINARY: {
		enum ast_type l = check_expr(c, e->u.bin.l);
		enum ast_type r = check_expr(c, e->u.bin.r);
		if (l == TYPE_NONE || r == TYPE_NONE)
			return TYPE_NONE;
		enum blame blame;
		enum ast_type t = value_type_binary(e->u.bin.op, l, r, why, sizeof why, &blame);
		if (t == TYPE_NONE)
			reported(c, blame == BLAME_LEFT ? e->u.bin.l->span : blame == BLAME_RIGHT ? e->u.bin.r->span : e->span, why);
		return t;
	}
	case AST_COND: {
		enum ast_type t = check_expr(c, e->u.cond.c);
		enum ast_type a = check_expr(c, e->u.cond.a);
		enum ast_type b = check_expr(c, e->u.cond.b);
		if (t != TYPE_NONE && !value_type_condition(t, why, sizeof why))
			return reported(c, e->u.cond.c->span, why);
		if (t == TYPE_NONE || a == TYPE_NONE || b == TYPE_NONE)
			return TYPE_NONE;
		if (a == TYPE_PIGMENT || b == TYPE_PIGMENT)
			return reported(c, (a == TYPE_PIGMENT ? e->u.cond.a : e->u.cond.b)->span,
			                "checker(...) can only be the value of diffuse");
		return a == b ? a : TYPE_ANY;
	}
	case AST_INDEX: {
		enum ast_type t = check_expr(c, e->u.bin.l);
		enum ast_type i = check_expr(c, e->u.bin.r);
		if (t != TYPE_NONE && t != TYPE_ARRAY && t != TYPE_ANY) {
			snprintf(why, sizeof why, "only an array can be indexed, found %s%s", value_type_name(t),
			         t == TYPE_VEC ? " (a vector's components are .x, .y and .z)" : "");
			return reported(c, e->u.bin.l->span, why);
		}
		if (i != TYPE_NONE && i != TYPE_NUM && i != TYPE_ANY) {
			snprintf(why, sizeof why, "an index must be a number, found %s", value_type_name(i));
			return reported(c, e->u.bin.r->span, why);
		}
		return t == TYPE_NONE || i == TYPE_NONE ? TYPE_NONE : TYPE_ANY;
	}
	case AST_MEMBER: {
		enum ast_type t = check_expr(c, e->u.member.e);
		const char *name = e->u.member.name;
		int comp = strcmp(name, "x") == 0 ? 0 : strcmp(name, "y") == 0 ? 1 : strcmp(name, "z") == 0 ? 2 : -1;
		if (comp < 0) {
			diag_error(c->diag, e->u.member.comp_span, "unknown component '.%s'; a vector has .x, .y and .z", name);
			return TYPE_NONE;
		}
		e->u.member.comp = comp;
		if (t == TYPE_NONE)
			return TYPE_NONE;
		if (t != TYPE_VEC && t != TYPE_ANY) {
			diag_error(c->diag, e->u.member.e->span, "'.%s' selects from a vector, but this is %s", name,
			           value_type_name(t));
			return TYPE_NONE;
		}
		return TYPE_NUM;
	}
	case AST_CALL:
		return check_call(c, e);
	default:
		return TYPE_NONE;
	}
}

enum ast_type check_expr(struct checker *c, struct ast *e)
{
	return e->type = check_expr_inner(c, e);
}
