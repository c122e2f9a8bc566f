/* eval_expr.c: the evaluator's expressions: every value computed, a non-finite result an
 * error at its place, a type that check.c could not know checked by value.h's rules;
 * calls of the scene's functions; the heap that strings and arrays live on; and the
 * values of items as numbers, vectors, strings, materials and whole numbers. */
#include "eval_internal.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "file.h"
#include "xalloc.h"

/* ---- the heap ---- */

void heap_release_to(struct evaluator *ev, struct heap_mark m)
{
	arena_release(ev->heap, m.arena);
	ev->elements = m.elements;
	ev->heap_now = m.arena;
}

static void broadcast(const struct value *v, double out[3])
{
	for (int k = 0; k < 3; k++)
		out[k] = v->v[v->type == TYPE_VEC ? k : 0];
}

/* Room for n more elements on the heap (a string's bytes count as elements); false
 * (reported at e, and the evaluation stopped) past LANG_MAX_ELEMENTS. */
static void *heap_alloc(struct evaluator *ev, struct ast *e, uint64_t n, size_t size)
{
	if (n > LANG_MAX_ELEMENTS - ev->elements) {
		eval_error(ev, e, "the scene's arrays and strings would hold more than %d elements at once",
		           LANG_MAX_ELEMENTS);
		ev->exhausted = true;
		return NULL;
	}
	ev->elements += n;
	void *p = arena_alloc(ev->heap, n * size);
	ev->heap_now = arena_mark(ev->heap);
	return p;
}

/* A string of len bytes on the heap, joined from a and b; false after an error. */
static bool make_string(struct evaluator *ev, struct ast *e, const char *a, uint32_t alen, const char *b,
                        uint32_t blen, struct value *out)
{
	char *s = heap_alloc(ev, e, (uint64_t)alen + blen + 1, 1);
	if (!s)
		return false;
	memcpy(s, a, alen);
	memcpy(s + alen, b, blen);
	s[alen + blen] = '\0';
	out->type = TYPE_STR;
	out->s = s;
	out->len = alen + blen;
	return true;
}

static bool make_array(struct evaluator *ev, struct ast *e, const struct value *a, uint32_t alen,
                       const struct value *b, uint32_t blen, struct value *out)
{
	struct value *v = alen + blen ? heap_alloc(ev, e, (uint64_t)alen + blen, sizeof *v) : NULL;
	if (alen + blen && !v)
		return false;
	if (alen)
		memcpy(v, a, alen * sizeof *v);
	if (blen)
		memcpy(v + alen, b, blen * sizeof *v);
	out->type = TYPE_ARRAY;
	out->elems = v;
	out->len = alen + blen;
	return true;
}

/* eval_expr, with the leaves (numbers and bindings: most operands) taken here rather
 * than through its dispatch: the cost of a call of a macro is mostly its arguments'. */
static inline bool operand(struct evaluator *ev, struct ast *e, struct value *out)
{
	if (e->kind == AST_NUM) {
		ev->steps++;
		out->type = TYPE_NUM;
		out->v[0] = e->u.num;
		return true;
	}
	if (e->kind == AST_IDENT && e->u.ident.builtin < 0 && ev->slots[e->u.ident.ref->slot].type != TYPE_NONE) {
		ev->steps++;
		*out = ev->slots[e->u.ident.ref->slot];
		return true;
	}
	return eval_expr(ev, e, out);
}

/* Reports a type rule's message at the operand it blames. */
static bool type_error(struct evaluator *ev, struct ast *e, enum blame blame, const char *why)
{
	eval_error(ev, blame == BLAME_LEFT ? e->u.bin.l : blame == BLAME_RIGHT ? e->u.bin.r : e, "%s", why);
	return false;
}

/* A value that must be a boolean (a condition, an operand of and, or, not): the rule's
 * message at e when it is not. */
static bool boolean(struct evaluator *ev, struct ast *e, const struct value *v, char op)
{
	char why[160];
	if (v->type == TYPE_BOOL)
		return true;
	if (op == '?')
		value_type_condition(v->type, why, sizeof why);
	else if (op == '!')
		value_type_unary('!', v->type, why, sizeof why);
	else {
		enum blame blame;
		value_type_binary(op, v->type, TYPE_BOOL, why, sizeof why, &blame);
	}
	eval_error(ev, e, "%s", why);
	return false;
}

/* a op b for + - * /; false (reported at e) when the result is not a finite number. */
static inline bool arithmetic(struct evaluator *ev, struct ast *e, char op, double a, double b, double *out)
{
	switch (op) {
	case '+': *out = a + b; break;
	case '-': *out = a - b; break;
	case '*': *out = a * b; break;
	default:
		if (b == 0) {
			eval_error(ev, e, "division by zero");
			return false;
		}
		*out = a / b;
	}
	if (isfinite(*out))
		return true;
	eval_error(ev, e, "the result is too large to be a number");
	return false;
}

/* The same componentwise, for vectors (a number promoted). */
static bool eval_arithmetic(struct evaluator *ev, struct ast *e, const struct value *l, const struct value *r,
                            struct value *out)
{
	double a[3], b[3];
	broadcast(l, a);
	broadcast(r, b);
	for (int k = 0; k < 3; k++)
		if (!arithmetic(ev, e, e->u.bin.op, a[k], b[k], &out->v[k]))
			return false;
	return true;
}

static bool eval_binary(struct evaluator *ev, struct ast *e, struct value *out)
{
	char op = e->u.bin.op;
	struct value l, r;
	if (!operand(ev, e->u.bin.l, &l))
		return false;
	if (op == OP_AND || op == OP_OR) { /* the right operand only when it decides */
		if (!boolean(ev, e->u.bin.l, &l, op))
			return false;
		if (l.truth == (op == OP_OR)) {
			*out = l;
			return true;
		}
		if (!operand(ev, e->u.bin.r, &r) || !boolean(ev, e->u.bin.r, &r, op))
			return false;
		*out = r;
		return true;
	}
	if (!operand(ev, e->u.bin.r, &r))
		return false;
	bool arith = op == '+' || op == '-' || op == '*' || op == '/';
	if (arith && l.type == TYPE_NUM && r.type == TYPE_NUM) { /* the most common case */
		out->type = TYPE_NUM;
		return arithmetic(ev, e, op, l.v[0], r.v[0], &out->v[0]);
	}
	enum ast_type t = TYPE_BOOL; /* a comparison of two numbers */
	if (l.type != TYPE_NUM || r.type != TYPE_NUM) {
		char why[160];
		enum blame blame;
		if ((t = value_type_binary(op, l.type, r.type, why, sizeof why, &blame)) == TYPE_NONE)
			return type_error(ev, e, blame, why);
	}
	out->type = (uint8_t)t;
	switch (op) {
	case '<': out->truth = l.v[0] < r.v[0]; return true;
	case '>': out->truth = l.v[0] > r.v[0]; return true;
	case OP_LE: out->truth = l.v[0] <= r.v[0]; return true;
	case OP_GE: out->truth = l.v[0] >= r.v[0]; return true;
	case OP_EQ: out->truth = value_equal(&l, &r); return true;
	case OP_NE: out->truth = !value_equal(&l, &r); return true;
	default: break;
	}
	if (t == TYPE_STR)
		return make_string(ev, e, l.s, l.len, r.s, r.len, out);
	if (t == TYPE_ARRAY)
		return make_array(ev, e, l.elems, l.len, r.elems, r.len, out);
	return eval_arithmetic(ev, e, &l, &r, out);
}

static bool eval_index(struct evaluator *ev, struct ast *e, struct value *out)
{
	struct value a, i;
	if (!eval_expr(ev, e->u.bin.l, &a) || !eval_expr(ev, e->u.bin.r, &i))
		return false;
	char nb[32];
	if (a.type != TYPE_ARRAY) {
		eval_error(ev, e->u.bin.l, "only an array can be indexed, found %s%s", value_type_name(a.type),
		           a.type == TYPE_VEC ? " (a vector's components are .x, .y and .z)" : "");
		return false;
	}
	if (i.type != TYPE_NUM) {
		eval_error(ev, e->u.bin.r, "an index must be a number, found %s", value_type_name(i.type));
		return false;
	}
	double k = i.v[0];
	if (k != floor(k)) {
		eval_error(ev, e->u.bin.r, "an index must be a whole number, not %s", value_number_text(k, nb));
		return false;
	}
	if (k < 0 || k >= a.len) {
		eval_error(ev, e->u.bin.r, "index %s is out of range: the array has %u element%s%s", value_number_text(k, nb), a.len,
		           a.len == 1 ? "" : "s", a.len ? " (the first is 0)" : "");
		return false;
	}
	*out = a.elems[(size_t)k];
	return true;
}

/* The type of a call of a built-in function whose arguments check.c did not all know
 * (TYPE_ANY): value.h's rules on the values' own types, reported as check.c would. */
static enum ast_type dynamic_type(struct evaluator *ev, struct ast *e, const struct value *args, size_t n)
{
	enum ast_type small[4] = { 0 };
	enum ast_type *types = n <= 4 ? small : xmalloc(n * sizeof *types);
	for (size_t i = 0; i < n; i++)
		types[i] = (enum ast_type)args[i].type;
	int bad = -1;
	const char *why = NULL;
	enum ast_type t = builtin_type(e->u.call.fn, types, (int)n, &bad, &why);
	if (t == TYPE_NONE)
		eval_error(ev, e->u.call.args.v[bad], "%s, found %s", why, value_type_name(types[bad]));
	if (types != small)
		free(types);
	return t;
}

static bool eval_builtin(struct evaluator *ev, struct ast *e, struct value *out)
{
	/* min and max take any number of arguments, millions in a big file: more than a few
	 * go on the heap, not the stack */
	size_t n = e->u.call.args.n;
	struct value small[4];
	struct value *args = n <= 4 ? small : xmalloc(n * sizeof *args);
	bool ok = true, as_checked = e->type != TYPE_ANY; /* every argument of the type check.c saw */
	for (size_t i = 0; i < n && ok; i++) {
		ok = operand(ev, e->u.call.args.v[i], &args[i]);
		as_checked &= args[i].type == e->u.call.args.v[i]->type;
	}
	enum ast_type t = !ok ? TYPE_NONE : as_checked ? (enum ast_type)e->type : dynamic_type(ev, e, args, n);
	char text[32];
	const char *fail = t != TYPE_NONE ? builtin_apply(e->u.call.fn, args, (int)n, t, out, text) : NULL;
	if (args != small)
		free(args);
	if (fail)
		eval_error(ev, e, "%s", fail);
	if (t == TYPE_NONE || fail)
		return false;
	return t != TYPE_STR || make_string(ev, e, out->s, out->len, "", 0, out);
}

/* Arguments a call keeps on the stack; more go on the heap (recursion keeps up to
 * LANG_MAX_CALL_DEPTH calls' arguments at once). */
enum { SMALL_ARGS = 6 };

bool call_enter(struct evaluator *ev, struct ast *site, struct call *call)
{
	/* the arguments, where the call is: before the parameters hide anything */
	size_t n = site->u.call.args.n;
	struct value small[SMALL_ARGS];
	struct value *args = n <= SMALL_ARGS ? small : xmalloc(n * sizeof *args);
	bool ok = true;
	for (size_t i = 0; i < n && ok; i++)
		ok = operand(ev, site->u.call.args.v[i], &args[i]);
	ok = ok && call_begin(ev, site, args, call);
	if (args != small)
		free(args);
	return ok;
}

/* A call of a function of the scene's: its value is its expression's, with its
 * parameters bound to the arguments. */
static bool eval_function(struct evaluator *ev, struct ast *e, struct value *out)
{
	struct call call;
	if (!call_enter(ev, e, &call))
		return false;
	bool ok = eval_expr(ev, e->u.call.ref->def->u.def.value, out);
	call_end(ev, &call);
	return ok;
}

bool eval_expr(struct evaluator *ev, struct ast *e, struct value *out)
{
	if (++ev->steps > LANG_MAX_STEPS) {
		if (!ev->exhausted)
			eval_error(ev, e, "the scene takes more than %d evaluation steps (its loops and calls do too much work)",
			           LANG_MAX_STEPS);
		ev->exhausted = true;
		return false;
	}
	char why[160];
	switch (e->kind) {
	case AST_NUM:
		out->type = TYPE_NUM;
		out->v[0] = e->u.num;
		return true;
	case AST_STR:
		out->type = TYPE_STR;
		out->s = e->u.str.text;
		out->len = (uint32_t)e->u.str.len;
		return true;
	case AST_BOOL:
		out->type = TYPE_BOOL;
		out->truth = e->u.truth;
		return true;
	case AST_VEC:
		out->type = TYPE_VEC;
		for (int k = 0; k < 3; k++) {
			struct value c;
			if (!operand(ev, e->u.vec[k], &c))
				return false;
			if (c.type != TYPE_NUM) {
				eval_error(ev, e->u.vec[k], "a vector's components must be numbers, found %s", value_type_name(c.type));
				return false;
			}
			out->v[k] = c.v[0];
		}
		return true;
	case AST_ARRAY: {
		uint32_t n = e->u.elems.n;
		struct value *v = n ? heap_alloc(ev, e, n, sizeof *v) : NULL;
		if (n && !v)
			return false;
		for (uint32_t i = 0; i < n; i++)
			if (!eval_expr(ev, e->u.elems.v[i], &v[i]))
				return false;
		out->type = TYPE_ARRAY;
		out->elems = v;
		out->len = n;
		return true;
	}
	case AST_IDENT:
		if (e->u.ident.builtin >= CONST_PI) {
			out->type = TYPE_NUM;
			out->v[0] = e->u.ident.builtin == CONST_PI ? M_PI : e->u.ident.builtin == CONST_CLOCK
			          ? ev->out->clock : (double)ev->out->frame;
			return true;
		}
		if (ev->slots[e->u.ident.ref->slot].type == TYPE_NONE) { /* its let failed */
			ev->failures++;
			return false;
		}
		*out = ev->slots[e->u.ident.ref->slot];
		return true;
	case AST_NEG: {
		if (!eval_expr(ev, e->u.bin.l, out))
			return false;
		if (value_type_unary('-', out->type, why, sizeof why) == TYPE_NONE) {
			eval_error(ev, e->u.bin.l, "%s", why);
			return false;
		}
		for (int k = 0; k < 3; k++)
			out->v[k] = -out->v[k];
		return true;
	}
	case AST_NOT:
		if (!eval_expr(ev, e->u.bin.l, out) || !boolean(ev, e->u.bin.l, out, '!'))
			return false;
		out->truth = !out->truth;
		return true;
	case AST_BINARY:
		return eval_binary(ev, e, out);
	case AST_COND: {
		struct value c;
		if (!eval_expr(ev, e->u.cond.c, &c) || !boolean(ev, e->u.cond.c, &c, '?'))
			return false;
		return eval_expr(ev, c.truth ? e->u.cond.a : e->u.cond.b, out);
	}
	case AST_INDEX:
		return eval_index(ev, e, out);
	case AST_MEMBER: {
		struct value v;
		if (!eval_expr(ev, e->u.member.e, &v))
			return false;
		if (v.type != TYPE_VEC) {
			eval_error(ev, e->u.member.e, "'.%s' selects from a vector, but this is %s", e->u.member.name,
			           value_type_name(v.type));
			return false;
		}
		out->type = TYPE_NUM;
		out->v[0] = v.v[e->u.member.comp];
		return true;
	}
	case AST_CALL:
		return e->u.call.fn >= 0 ? eval_builtin(ev, e, out) : eval_function(ev, e, out);
	default:
		return false;
	}
}

/* ---- values of items ---- */

/* e's value, of one of the types in want (a mask of 1 << type); what names them in the
 * message when it is of another (only a value that check.c knew as TYPE_ANY can be). */
static bool value_of(struct evaluator *ev, struct ast *e, unsigned want, const char *what, struct value *v)
{
	if (!eval_expr(ev, e, v))
		return false;
	if (want & 1u << v->type)
		return true;
	eval_error(ev, e, "expected %s, found %s", what, value_type_name(v->type));
	return false;
}

bool vec_of(struct evaluator *ev, struct ast *e, double out[3])
{
	struct value v;
	if (!value_of(ev, e, 1u << TYPE_NUM | 1u << TYPE_VEC, "a vector or colour", &v))
		return false;
	broadcast(&v, out);
	return true;
}

bool num_of(struct evaluator *ev, struct ast *e, double *out)
{
	struct value v;
	if (!value_of(ev, e, 1u << TYPE_NUM, "a number", &v))
		return false;
	*out = v.v[0];
	return true;
}

bool str_of(struct evaluator *ev, struct ast *e, const char **out)
{
	struct value v;
	if (!value_of(ev, e, 1u << TYPE_STR, "a string", &v))
		return false;
	*out = v.s;
	return true;
}

bool material_of(struct evaluator *ev, struct ast *e, int *out)
{
	struct value v;
	if (!value_of(ev, e, 1u << TYPE_MATERIAL, "a material", &v))
		return false;
	*out = (int)v.v[0];
	return true;
}

bool truth_of(struct evaluator *ev, struct ast *e, bool *out)
{
	struct value v;
	if (!eval_expr(ev, e, &v) || !boolean(ev, e, &v, '?'))
		return false;
	*out = v.truth;
	return true;
}

/* A bound of whole_of for a message: 2^53, the end of exact whole numbers, by name. */
static const char *bound_text(double x, char buf[32])
{
	if (fabs(x) == 9007199254740992.0)
		return x < 0 ? "-2^53" : "2^53";
	return value_number_text(x, buf);
}

/* A whole number in [lo, hi]; what names it in the message. */
bool whole_of(struct evaluator *ev, struct ast *e, double lo, double hi, const char *what, double *out)
{
	if (!num_of(ev, e, out))
		return false;
	if (*out != floor(*out) || *out < lo || *out > hi) {
		char lo_buf[32], hi_buf[32], nb[32];
		eval_error(ev, e, "%s must be a whole number from %s to %s, not %s", what, bound_text(lo, lo_buf),
		           bound_text(hi, hi_buf), value_number_text(*out, nb));
		return false;
	}
	return true;
}

bool positive_of(struct evaluator *ev, struct ast *e, const char *what, bool zero, double *out)
{
	if (!num_of(ev, e, out))
		return false;
	if (zero ? *out >= 0 : *out > 0)
		return true;
	char nb[32];
	eval_error(ev, e, "%s must be %s, not %s", what, zero ? "0 or more" : "positive", value_number_text(*out, nb));
	return false;
}

bool file_of(struct evaluator *ev, struct ast *e, const struct source *src, const char *what, char **name,
             char **path)
{
	const char *text;
	if (!str_of(ev, e, &text))
		return false;
	char *resolved = file_resolve(src->dir, text);
	const char *why = e->kind == AST_STR ? NULL : *text ? file_unreadable(resolved) : "an empty name";
	if (why) {
		eval_error(ev, e, "cannot read %s '%s': %s", what, text, why);
		free(resolved);
		return false;
	}
	*name = xstrdup(text);
	*path = resolved;
	return true;
}
