/* eval_call.c: calls of the scene's functions and macros. Bindings keep their values in
 * slots, one per binding (check.c numbers them), so a definition's parameters and the
 * bindings in its body have slots of their own, [slot_lo, slot_hi). A call binds them
 * there; a call that starts while another call of the same definition runs (recursion)
 * first saves the values it would overwrite and puts them back when it returns. That is
 * lexical scope: a body can see only the innermost running call's bindings of its
 * definition, as functions are never values that could outlive or leave their scope.
 * The arguments are evaluated by the caller (eval_expr.c, eval.c), which then runs the
 * body between call_begin and call_end. */
#include "eval_internal.h"

#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "xalloc.h"

/* Saves the slots [lo, hi) on the evaluator's stack of hidden values. */
static void save_slots(struct evaluator *ev, unsigned lo, unsigned hi)
{
	size_t n = hi - lo;
	xgrow((void **)&ev->saved, &ev->cap_saved, ev->nsaved + n, sizeof *ev->saved);
	xgrow((void **)&ev->saved_bad, &ev->cap_saved_bad, ev->nsaved + n, sizeof *ev->saved_bad);
	memcpy(ev->saved + ev->nsaved, ev->slots + lo, n * sizeof *ev->saved);
	memcpy(ev->saved_bad + ev->nsaved, ev->bad + lo, n * sizeof *ev->saved_bad);
	ev->nsaved += n;
}

static void restore_slots(struct evaluator *ev, unsigned lo, unsigned hi)
{
	size_t n = hi - lo;
	ev->nsaved -= n;
	memcpy(ev->slots + lo, ev->saved + ev->nsaved, n * sizeof *ev->saved);
	memcpy(ev->bad + lo, ev->saved_bad + ev->nsaved, n * sizeof *ev->saved_bad);
}

bool call_begin(struct evaluator *ev, struct ast *site, const struct value *args, struct call *call)
{
	struct ast *def = site->u.call.ref->def;
	if (ev->calls == LANG_MAX_CALL_DEPTH) {
		eval_error_span(ev, site, site->u.call.name_span, "calls nested more than %d deep (does a recursion end?)",
		                LANG_MAX_CALL_DEPTH);
		return false;
	}
	call->def = def;
	call->recursive = def->u.def.active > 0;
	if (call->recursive)
		save_slots(ev, def->u.def.slot_lo, def->u.def.slot_hi);
	for (size_t i = 0; i < def->u.def.params.n; i++) {
		unsigned slot = def->u.def.params.v[i]->u.ident.ref->slot;
		ev->slots[slot] = args[i];
		ev->bad[slot] = false;
	}
	def->u.def.active++;
	ev->calls++;
	context_push(ev, site, NULL);
	return true;
}

void call_end(struct evaluator *ev, const struct call *call)
{
	context_pop(ev);
	ev->calls--;
	call->def->u.def.active--;
	if (call->recursive)
		restore_slots(ev, call->def->u.def.slot_lo, call->def->u.def.slot_hi);
}
