/* eval_internal.h: what the evaluator's files share, and nothing outside them uses: the
 * evaluator's state and the calls between eval.c (statements, loops, the entry points),
 * eval_object.c (objects, materials, transforms) and eval_expr.c (expressions and
 * the values of items), each of which calls only those after it. */
#ifndef SCN_EVAL_INTERNAL_H
#define SCN_EVAL_INTERNAL_H

#include <math.h>
#include <stdbool.h>
#include <stdint.h>

#include "ast.h"
#include "builtins.h"
#include "eval.h"

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

/* ---- eval_object.c ---- */

/* Evaluates a material block into a new entry of the scene's materials; returns its index. */
int eval_material(struct evaluator *ev, struct ast_block *block, const char *name, struct span sp);
/* Evaluates the object statement s into out->objects. */
void eval_object(struct evaluator *ev, struct ast *s, const struct source *src);

/* ---- eval_expr.c ---- */

/* A number for a message, in buf. */
const char *num_text(double x, char buf[32]);
/* Reports an error at node at (at span sp), once per place however many loop iterations
 * reach it, with the loop variables' values that led there. */
void eval_error(struct evaluator *ev, struct ast *at, const char *fmt, ...)
	__attribute__((format(printf, 3, 4)));
void eval_error_span(struct evaluator *ev, struct ast *at, struct span sp, const char *fmt, ...)
	__attribute__((format(printf, 4, 5)));
/* The value of e; false after an error. */
bool eval_expr(struct evaluator *ev, struct ast *e, struct value *out);
/* e as a vector (a number promoted), as a number, as a whole number in [lo, hi] (what
 * names it in the message); false after an error. */
bool vec_of(struct evaluator *ev, struct ast *e, double out[3]);
bool num_of(struct evaluator *ev, struct ast *e, double *out);
bool whole_of(struct evaluator *ev, struct ast *e, double lo, double hi, const char *what, double *out);

static inline struct ast *arg0(struct ast *item)
{
	return item->u.item.args.v[0];
}

static inline bool is_zero(const double v[3])
{
	return v[0] == 0 && v[1] == 0 && v[2] == 0;
}

static inline void cross(const double a[3], const double b[3], double out[3])
{
	out[0] = a[1] * b[2] - a[2] * b[1];
	out[1] = a[2] * b[0] - a[0] * b[2];
	out[2] = a[0] * b[1] - a[1] * b[0];
}

static inline double norm(const double v[3])
{
	return hypot(hypot(v[0], v[1]), v[2]);
}

/* v / |v| for a nonzero v, divided by its largest component first so that nothing
 * underflows */
static inline void unit(const double v[3], double out[3])
{
	double big = fmax(fabs(v[0]), fmax(fabs(v[1]), fabs(v[2])));
	for (int k = 0; k < 3; k++)
		out[k] = v[k] / big;
	double len = norm(out);
	for (int k = 0; k < 3; k++)
		out[k] /= len;
}

#endif
