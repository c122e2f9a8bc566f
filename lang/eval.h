/* eval.h: evaluation of a checked scene into a scene_desc. */
#ifndef SCN_EVAL_H
#define SCN_EVAL_H

#include <stdint.h>

#include "ast.h"
#include "diag.h"
#include "scene_desc.h"

/* Limits of LANGUAGE.md section 6. */
#define LANG_MAX_ITERATIONS 10000000
#define LANG_MAX_DEPTH 256
#define LANG_MAX_PIXELS (1 << 28)
/* Not in LANGUAGE.md: the iteration limit bounds loops, but a loop multiplies the work
 * and the objects of its body; these bound the whole evaluation. */
#define LANG_MAX_OBJECTS 10000000
#define LANG_MAX_STEPS 500000000
/* LANGUAGE.md section 10: calls nest at most this deep; the arrays and strings alive at
 * once hold at most this many elements (a string's bytes count as elements). */
#define LANG_MAX_CALL_DEPTH 256
#define LANG_MAX_ELEMENTS 10000000

#ifdef FUZZING_BUILD_MODE_UNSAFE_FOR_PRODUCTION
/* A macro that calls itself twice reaches the limit on steps from a few lines, in 20 s,
 * and loops and objects theirs in seconds under the sanitizers: past the fuzzer's timeout
 * for one input. There the limits on the whole evaluation come a hundred times sooner. */
#undef LANG_MAX_ITERATIONS
#undef LANG_MAX_OBJECTS
#undef LANG_MAX_STEPS
#define LANG_MAX_ITERATIONS 100000
#define LANG_MAX_OBJECTS 100000
#define LANG_MAX_STEPS 1000000
#endif

/* What an evaluation did, for --stats: expressions evaluated (the steps that
 * LANG_MAX_STEPS bounds) and calls of the scene's functions and macros. */
struct eval_counts {
	uint64_t steps, calls;
};

/* Evaluates statements that check_file accepted without errors (nslots is what it
 * returned) into out, which scene_desc_init prepared. Range errors go to d. Adds what it
 * did to *counts. */
void eval_file(struct diag *d, struct ast_list *stmts, unsigned nslots, struct scene_desc *out,
               struct eval_counts *counts);

/* The same one statement at a time, for a file evaluated as it is parsed: each
 * statement after check_statement accepted it, with check_slots' count. */
struct evaluator;
struct evaluator *eval_new(struct diag *d, struct scene_desc *out);
void eval_statement(struct evaluator *ev, struct ast *stmt, unsigned nslots);
/* Adds what ev did to *counts, and frees it. */
void eval_free(struct evaluator *ev, struct eval_counts *counts);

#endif
