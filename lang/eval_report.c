/* eval_report.c: the evaluator's error reports: once per place however many loop
 * iterations and calls reach it, with notes on what led there (the loops' values, the
 * calls on the way); and the context of loops and calls those notes come from. */
#include "eval_internal.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "xalloc.h"

void context_push(struct evaluator *ev, const struct ast *node, const struct value *var)
{
	if (ev->ncontext == ev->cap_context)
		xgrow((void **)&ev->context, &ev->cap_context, ev->ncontext + 1, sizeof *ev->context);
	ev->context[ev->ncontext].node = node;
	if (var)
		ev->context[ev->ncontext].var = *var;
	ev->ncontext++;
}

void context_pop(struct evaluator *ev)
{
	ev->ncontext--;
}

/* A value for a message, in buf. */
static const char *value_text(const struct value *v, char *buf, size_t size)
{
	char a[32], b[32], c[32];
	switch (v->type) {
	case TYPE_VEC:
		snprintf(buf, size, "<%s, %s, %s>", value_number_text(v->v[0], a), value_number_text(v->v[1], b), value_number_text(v->v[2], c));
		break;
	case TYPE_BOOL:
		snprintf(buf, size, "%s", v->truth ? "true" : "false");
		break;
	case TYPE_STR:
		snprintf(buf, size, "\"%.*s%s\"", v->len > 40 ? 40 : (int)v->len, v->s, v->len > 40 ? "..." : "");
		break;
	case TYPE_ARRAY:
		snprintf(buf, size, "an array of %u", v->len);
		break;
	default:
		snprintf(buf, size, "%s", value_number_text(v->v[0], a));
		break;
	}
	return buf;
}

/* Calls shown in an error's notes at most: the innermost and the outermost half each. */
enum { SHOWN_CALLS = 10 };

/* The notes on what led to an error: for each run of loops, the innermost loop's
 * variable with the values of all of them ("when j = 1, i = 3"), and each call on the
 * way ("in call to 'column'"), innermost first. A deep recursion shows its innermost and
 * outermost calls. */
static void context_notes(struct evaluator *ev)
{
	size_t ncalls = 0;
	for (size_t i = 0; i < ev->ncontext; i++)
		ncalls += ev->context[i].node->kind != AST_FOR;
	char where[256];
	size_t used = 0, call = 0;
	const struct ast *loop = NULL;       /* the innermost loop of the current run */
	for (size_t i = ev->ncontext; i-- > 0;) {
		const struct context *x = &ev->context[i];
		bool shown = ncalls <= SHOWN_CALLS || call < SHOWN_CALLS / 2 || call >= ncalls - SHOWN_CALLS / 2;
		if (x->node->kind == AST_FOR) {
			if (!shown)
				continue;
			char vb[64];
			if (!loop)
				loop = x->node;
			if (used < sizeof where)
				used += (size_t)snprintf(where + used, sizeof where - used, "%s%s = %s", loop == x->node ? "" : ", ",
				                         x->node->u.loop.var, value_text(&x->var, vb, sizeof vb));
			continue;
		}
		if (loop)
			diag_note(ev->diag, loop->u.loop.var_span, "when %s", where);
		loop = NULL;
		used = 0;
		if (shown && ncalls > SHOWN_CALLS && call == ncalls - SHOWN_CALLS / 2)
			diag_note(ev->diag, x->node->span, "in call to '%s' (after %zu calls not shown)", x->node->u.call.name,
			          ncalls - SHOWN_CALLS);
		else if (shown)
			diag_note(ev->diag, x->node->span, "in call to '%s'", x->node->u.call.name);
		call++;
	}
	if (loop)
		diag_note(ev->diag, loop->u.loop.var_span, "when %s", where);
}

/* Reports an error once per place (*reported), however many loop iterations and calls
 * reach it, with what led there; counts it each time. */
static void report_once(struct evaluator *ev, bool *reported, struct span sp, const char *fmt, va_list ap)
{
	ev->failures++;
	if (*reported)
		return;
	*reported = true;
	char msg[512];
	vsnprintf(msg, sizeof msg, fmt, ap);
	diag_error(ev->diag, sp, "%s", msg);
	context_notes(ev);
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

