/* eval_expr.c: the evaluator's expressions: every value computed, a non-finite result an
 * error at its place; the values of items as numbers, vectors and whole numbers; and the
 * evaluator's error reports, once per place with the loop values that led there. */
#include "eval_internal.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "xalloc.h"

/* A number for a message: the shortest of %.15g to %.17g that reads back as x, so that
 * a value the user wrote (ior -1.33) shows as written. */
const char *num_text(double x, char buf[32])
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
 * with the loop variables' values that led there; counts it each time. */
static void report_once(struct evaluator *ev, bool *reported, struct span sp, const char *fmt, va_list ap)
{
	ev->failures++;
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

void eval_error(struct evaluator *ev, struct ast *at, const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	report_once(ev, &at->reported, at->span, fmt, ap);
	va_end(ap);
}

/* An error about node at, shown at another span (a part of it). */
void eval_error_span(struct evaluator *ev, struct ast *at, struct span sp, const char *fmt, ...)
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

bool eval_expr(struct evaluator *ev, struct ast *e, struct value *out)
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
		if (e->u.ident.builtin >= CONST_PI) {
			out->v[0] = e->u.ident.builtin == CONST_PI ? M_PI : e->u.ident.builtin == CONST_CLOCK
			          ? ev->out->clock : (double)ev->out->frame;
			return true;
		}
		if (ev->bad[e->u.ident.ref->slot]) {
			ev->failures++;
			return false;
		}
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

bool vec_of(struct evaluator *ev, struct ast *e, double out[3])
{
	struct value v;
	if (!eval_expr(ev, e, &v))
		return false;
	broadcast(&v, e->type, out);
	return true;
}

bool num_of(struct evaluator *ev, struct ast *e, double *out)
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
bool whole_of(struct evaluator *ev, struct ast *e, double lo, double hi, const char *what, double *out)
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
