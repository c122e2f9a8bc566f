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

#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>

#include "check.h"
#include "xalloc.h"

/* Saves the slots [lo, hi) on the evaluator's stack of hidden values. */
static void save_slots(struct evaluator *ev, unsigned lo, unsigned hi)
{
	size_t n = hi - lo;
	if (ev->nsaved + n > ev->cap_saved)
		xgrow((void **)&ev->saved, &ev->cap_saved, ev->nsaved + n, sizeof *ev->saved);
	memcpy(ev->saved + ev->nsaved, ev->slots + lo, n * sizeof *ev->saved);
	ev->nsaved += n;
}

static void restore_slots(struct evaluator *ev, unsigned lo, unsigned hi)
{
	size_t n = hi - lo;
	ev->nsaved -= n;
	memcpy(ev->slots + lo, ev->saved + ev->nsaved, n * sizeof *ev->saved);
}

/* The bytes of stack the evaluation may use: the machine's limit less a margin for what
 * one body nests between two calls (expressions and blocks, each bounded by
 * LANG_MAX_NESTING) and for what runs after. */
static size_t stack_budget(void)
{
	const size_t margin = 4u << 20;
	struct rlimit r;
	if (getrlimit(RLIMIT_STACK, &r) != 0 || r.rlim_cur == RLIM_INFINITY || r.rlim_cur > (256u << 20))
		return 256u << 20;
	return r.rlim_cur > 2 * margin ? (size_t)r.rlim_cur - margin : (size_t)r.rlim_cur / 2;
}

bool call_begin(struct evaluator *ev, struct ast *site, const struct value *args, struct call *call)
{
	struct ast *def = site->u.call.ref->def;
	/* a recursion this deep has not ended; with two calls of itself a body, the calls
	 * after the failing one would double at every level back up: nothing more runs */
	if (ev->calls == LANG_MAX_CALL_DEPTH) {
		eval_error_span(ev, site, site->u.call.name_span, "calls nested more than %d deep (does a recursion end?)",
		                LANG_MAX_CALL_DEPTH);
		ev->exhausted = true;
		return false;
	}
	/* 256 calls of bodies that nest 1000 deep would outgrow the stack: the depth in
	 * bytes is checked too */
	uintptr_t here = (uintptr_t)__builtin_frame_address(0);
	if (!ev->stack_budget)
		ev->stack_budget = stack_budget();
	if (ev->stack_base > here && ev->stack_base - here > ev->stack_budget) {
		eval_error_span(ev, site, site->u.call.name_span, "calls nested too deep for the stack: each holds "
		                "deeply nested expressions or blocks");
		ev->exhausted = true;
		return false;
	}
	call->def = def;
	call->recursive = def->u.def.active > 0;
	if (call->recursive)
		save_slots(ev, def->u.def.slot_lo, def->u.def.slot_hi);
	/* check.c binds the parameters first, in order, from slot_lo */
	memcpy(ev->slots + def->u.def.slot_lo, args, def->u.def.params.n * sizeof *args);
	def->u.def.active++;
	ev->calls++;
	ev->ncalls++;
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
