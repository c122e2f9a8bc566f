/* check_expr.c: the checker's expressions (check.c has the rest): every name resolves,
 * with "did you mean" or a note on a definition that comes too late when it does not,
 * and every expression gets its type. */
#include "check_internal.h"

#include <string.h>

#include "builtins.h"
#include "suggest.h"

const char *type_name(enum ast_type t)
{
	switch (t) {
	case TYPE_NUM: return "a number";
	case TYPE_VEC: return "a vector";
	case TYPE_STR: return "a string";
	case TYPE_PIGMENT: return "a checker pattern";
	case TYPE_MATERIAL: return "a material";
	default: return "nothing";
	}
}

/* An operand of arithmetic must be a number or a vector. */
static bool arithmetic(struct checker *c, struct ast *e, enum ast_type t)
{
	if (t == TYPE_NUM || t == TYPE_VEC)
		return true;
	if (t != TYPE_NONE)
		diag_error(c->diag, e->span, "expected a number or a vector, found %s", type_name(t));
	return false;
}

/* The let or material of that name defined after offset 'after' in the same file,
 * outside includes, or NULL: for "defined later" notes. */
static const struct ast *later_definition(const struct ast_list *stmts, const char *name, uint32_t after,
                                          const struct source *src, const struct diag *d)
{
	for (size_t i = 0; i < stmts->n; i++) {
		const struct ast *s = stmts->v[i];
		const char *defined = s->kind == AST_LET ? s->u.let.name
		                    : s->kind == AST_BLOCK_STMT && s->u.stmt.kw == KW_MATERIAL ? s->u.stmt.name : NULL;
		if (defined && strcmp(defined, name) == 0 && s->span.start > after && diag_source_at(d, s->span.start) == src)
			return s;
		if (s->kind == AST_FOR) {
			const struct ast *found = later_definition(&s->u.loop.body, name, after, src, d);
			if (found)
				return found;
		}
	}
	return NULL;
}

/* Reports a name that means nothing here, with the most useful hint. */
void unknown_name(struct checker *c, struct span at, const char *name, bool material)
{
	/* it may well be defined in a file that could not be read; and once the run has
	 * stopped nothing prints, so the searches below (all names, all statements) are skipped */
	if (c->include_failed || diag_stopped(c->diag))
		return;
	const char *what = material ? "material" : "name";
	if (!material && (strcmp(name, "x") == 0 || strcmp(name, "y") == 0 || strcmp(name, "z") == 0)) {
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
	names_suggest_visible(c, &s, material);
	diag_error(c->diag, at, "unknown %s '%s'%s", what, name, suggest_text(&s, buf, sizeof buf));
	const struct ast *later = c->root ? later_definition(c->root, name, at.start, diag_source_at(c->diag, at.start), c->diag)
	                                  : NULL;
	if (later)
		diag_note(c->diag, later->kind == AST_LET ? later->u.let.name_span : later->u.stmt.name_span,
		          "'%s' is defined here, after its use; a name is visible only after its definition", name);
}

static enum ast_type check_ident(struct checker *c, struct ast *e)
{
	const char *name = e->u.ident.name;
	struct binding *b = names_lookup(c, name);
	if (b) {
		b->used = true;
		e->u.ident.ref = b;
		c->tainted |= b->failed;
		if (b->kind == BIND_MATERIAL) {
			diag_error(c->diag, e->span, "'%s' is a material, not a value", name);
			return TYPE_NONE;
		}
		return b->kind == BIND_LOOP ? TYPE_NUM : b->type;
	}
	int fn = builtin_lookup(name);
	if (fn >= CONST_PI) {
		e->u.ident.builtin = fn;
		return TYPE_NUM;
	}
	if (fn >= 0) {
		diag_error(c->diag, e->span, "'%s' is a function; call it as %s(...)", name, name);
		return TYPE_NONE;
	}
	unknown_name(c, e->span, name, false);
	c->tainted = true; /* also when unknown_name says nothing (a name an unread include may define) */
	return TYPE_NONE;
}

static enum ast_type check_call(struct checker *c, struct ast *e)
{
	const char *name = e->u.call.name;
	struct ast_list *args = &e->u.call.args;
	int fn = builtin_lookup(name);
	if (fn < 0 || !builtin_is_function(fn)) {
		struct suggestion s;
		char buf[96];
		suggest_init(&s, name);
		for (int b = 0; b < BUILTIN_COUNT; b++)
			if (builtin_is_function(b))
				suggest_consider(&s, builtin_name(b));
		if (names_lookup(c, name) || fn >= 0)
			diag_error(c->diag, e->u.call.name_span, "'%s' is not a function", name);
		else
			diag_error(c->diag, e->u.call.name_span, "unknown function '%s'%s", name,
			           suggest_text(&s, buf, sizeof buf));
		for (size_t i = 0; i < args->n; i++)
			check_expr(c, args->v[i]);
		return TYPE_NONE;
	}
	e->u.call.fn = fn;
	int lo = builtin_min_args(fn), hi = builtin_max_args(fn);
	int n = (int)args->n;
	if (n < lo || (hi >= 0 && n > hi)) {
		if (lo == hi)
			diag_error(c->diag, e->span, "%s takes %d argument%s, not %d", name, lo, lo == 1 ? "" : "s", n);
		else
			diag_error(c->diag, e->span, "%s takes at least %d arguments, not %d", name, lo, n);
		return TYPE_NONE;
	}
	enum ast_type types[64];
	bool ok = true;
	for (int i = 0; i < n; i++) {
		enum ast_type t = check_expr(c, args->v[i]);
		ok &= arithmetic(c, args->v[i], t);
		if (i < 64 || t == TYPE_VEC) /* min, max: the last slot is a vector if any later one is */
			types[i < 64 ? i : 63] = t;
	}
	if (!ok)
		return TYPE_NONE;
	int bad = -1;
	const char *why = NULL;
	enum ast_type t = builtin_type(fn, types, n < 64 ? n : 64, &bad, &why);
	if (t == TYPE_NONE)
		diag_error(c->diag, args->v[bad]->span, "%s, found %s", why, type_name(types[bad]));
	return t;
}

static enum ast_type check_expr_inner(struct checker *c, struct ast *e)
{
	switch (e->kind) {
	case AST_NUM:
		return TYPE_NUM;
	case AST_STR:
		return TYPE_STR;
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
			else if (t != TYPE_NUM) {
				diag_error(c->diag, e->u.vec[k]->span, "a vector's components must be numbers, found %s",
				           type_name(t));
				ok = false;
			}
		}
		return ok ? TYPE_VEC : TYPE_NONE;
	}
	case AST_NEG: {
		enum ast_type t = check_expr(c, e->u.bin.l);
		return arithmetic(c, e->u.bin.l, t) ? t : TYPE_NONE;
	}
	case AST_BINARY: {
		enum ast_type l = check_expr(c, e->u.bin.l);
		enum ast_type r = check_expr(c, e->u.bin.r);
		bool ok = arithmetic(c, e->u.bin.l, l);
		ok &= arithmetic(c, e->u.bin.r, r);
		if (!ok)
			return TYPE_NONE;
		return l == TYPE_VEC || r == TYPE_VEC ? TYPE_VEC : TYPE_NUM;
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
		if (t != TYPE_VEC) {
			diag_error(c->diag, e->u.member.e->span, "'.%s' selects from a vector, but this is %s", name,
			           type_name(t));
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
