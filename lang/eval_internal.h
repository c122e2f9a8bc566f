/* eval_internal.h: what the evaluator's files share, and nothing outside them uses: the
 * evaluator's state and the calls between eval.c (statements, loops, the entry points),
 * eval_object.c (objects, CSGs, materials, transforms) and eval_expr.c (expressions and
 * the values of items), each of which calls only those after it. */
#ifndef SCN_EVAL_INTERNAL_H
#define SCN_EVAL_INTERNAL_H

#include <math.h>
#include <stdbool.h>
#include <stdint.h>

#include "ast.h"
#include "builtins.h"
#include "eval.h"

/* A CSG whose members are being evaluated: what they take from it. */
struct csg_frame {
	size_t index;              /* its slot in out->objects, reserved before its members */
	int xform;                 /* its transform to world, which follows each member's own */
	int material;              /* the material of the members without their own, or -1 */
	int pattern_xform;         /* the space of that material's patterns */
	uint64_t failures;         /* evaluator.failures when it started */
	struct csg_frame *outer;
};

struct evaluator {
	struct diag *diag;
	struct scene_desc *out;
	struct value *slots;       /* current value of each binding; a material's is its index */
	bool *bad;                 /* the binding's value could not be computed */
	size_t nslots, cap_slots, cap_bad;
	uint64_t iterations;       /* loop iterations so far, against LANG_MAX_ITERATIONS */
	uint64_t steps;            /* expressions evaluated so far, against LANG_MAX_STEPS */
	/* values that could not be computed, each time (eval_error and the use of a bad
	 * binding), reported or not: a CSG that misses a member is dropped, not cut short */
	uint64_t failures;
	bool exhausted;            /* a limit on the whole evaluation was reached: stop */
	unsigned nloops;
	struct { const struct ast *loop; double i; } loops[LANG_MAX_NESTING];
	struct csg_frame *csg;     /* the innermost CSG being evaluated, or NULL */
};

/* ---- eval_object.c ---- */

/* Evaluates a material block into a new entry of the scene's materials; returns its index. */
int eval_material(struct evaluator *ev, struct ast_block *block, const char *name, struct span sp);
/* Evaluates the object statement s (not a CSG) into out->objects, inside the CSG ev->csg
 * if there is one. */
void eval_shape(struct evaluator *ev, struct ast *s, const struct source *src);
/* A CSG statement s: csg_begin reserves its slot, evaluates its items and makes it
 * ev->csg (frame is its storage), or returns false when the limit on objects is reached;
 * the caller then evaluates its members, and csg_end completes it, or drops it with its
 * members when one of them could not be evaluated. */
bool csg_begin(struct evaluator *ev, struct ast *s, struct csg_frame *frame);
void csg_end(struct evaluator *ev, struct ast *s);

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
