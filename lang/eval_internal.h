/* eval_internal.h: what the evaluator's files share, and nothing outside them uses: the
 * evaluator's state and the calls between eval.c (statements, loops, macro calls, the
 * entry points), eval_object.c (objects, CSGs, materials), eval_texture.c (a material's
 * patterns, images and normals), eval_xform.c (transforms), eval_expr.c (expressions,
 * function calls, the values of items), eval_call.c (the bindings of a call) and
 * eval_report.c (errors and their notes), each of which calls only those after it. */
#ifndef SCN_EVAL_INTERNAL_H
#define SCN_EVAL_INTERNAL_H

#include <math.h>
#include <stdbool.h>
#include <stdint.h>

#include "arena.h"
#include "ast.h"
#include "builtins.h"
#include "eval.h"
#include "value.h"

struct call;

/* A CSG whose members are being evaluated: what they take from it. */
struct csg_frame {
	size_t index;              /* its slot in out->objects, reserved before its members */
	int xform;                 /* its transform to world, which follows each member's own */
	int material;              /* the material of the members without their own, or -1 */
	int pattern_xform;         /* the space of that material's patterns */
	uint64_t failures;         /* evaluator.failures when it started */
	struct csg_frame *outer;
};

/* What led to the statement being evaluated, for the notes of its errors: a for loop
 * (node, with its variable's value) or a call (node). */
struct context {
	const struct ast *node;
	struct value var;
};

/* The values' memory at a moment, to go back to (heap_mark, heap_release). */
struct heap_mark {
	struct arena_mark arena;
	uint64_t elements;
};

struct evaluator {
	struct diag *diag;
	struct scene_desc *out;
	/* current value of each binding (a material's is its index); TYPE_NONE when it could
	 * not be computed */
	struct value *slots;
	size_t nslots, cap_slots;
	/* the strings and arrays that values point to, released at the end of each statement
	 * and loop iteration that binds nothing beyond itself; their elements (a string's
	 * bytes count as elements) against LANG_MAX_ELEMENTS */
	struct arena *heap;
	uint64_t elements;
	struct arena_mark heap_now;  /* the heap's state: marked often, changed seldom */
	/* the values of the running calls' bindings that a call of the same definition hid */
	struct value *saved;
	size_t nsaved, cap_saved;
	unsigned calls;            /* calls running, against LANG_MAX_CALL_DEPTH */
	uint64_t ncalls;           /* calls made */
	uintptr_t stack_base;      /* the stack where the evaluation began, and how far below */
	size_t stack_budget;       /* it calls may go (eval_call.c) */
	uint64_t iterations;       /* loop iterations so far, against LANG_MAX_ITERATIONS */
	uint64_t steps;            /* expressions evaluated so far, against LANG_MAX_STEPS */
	/* values that could not be computed, each time (eval_error and the use of a bad
	 * binding), reported or not: a CSG that misses a member is dropped, not cut short */
	uint64_t failures;
	bool exhausted;            /* a limit on the whole evaluation was reached: stop */
	struct context *context;   /* innermost last */
	size_t ncontext, cap_context;
	struct csg_frame *csg;     /* the innermost CSG being evaluated, or NULL */
};

/* ---- eval.c ---- */

/* Runs statements in order, each skipped when check.c failed it, until the evaluation
 * stops. */
void eval_stmts(struct evaluator *ev, struct ast_list *stmts);

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

/* ---- eval_texture.c ---- */

/* diffuse pattern { ... } (normal false) or normal { ... } (normal true): a new entry of
 * the scene's patterns, its colour map into color_maps; its index, or -1 after an error. */
int eval_pattern(struct evaluator *ev, struct ast *sub, struct ast_block *block, bool normal);
/* diffuse image { ... }, which the item sub holds: a new entry of the scene's images; its
 * index, or -1 after an error. */
int eval_image(struct evaluator *ev, struct ast *sub);

/* ---- eval_xform.c ---- */

/* x = t * x: applies the affine map t after x. */
void xform_compose(struct xform *x, const double t[3][4]);
/* Applies the transform item it (translate, rotate, scale) to x. Returns false after
 * reporting a bad value. */
bool xform_apply(struct evaluator *ev, struct ast *it, struct xform *x);
/* Whether every entry of x is a number (scale 1e200 twice overflows). */
bool xform_finite(const struct xform *x);
/* Appends x to the scene's xforms; its index. */
int xform_push(struct evaluator *ev, const struct xform *x);

/* ---- eval_expr.c ---- */

/* Evaluates a call's arguments (site: an AST_CALL or AST_MACRO_CALL of the scene's
 * definition) and begins the call (call_begin); false after an error. The caller runs
 * the body, then call_end. */
bool call_enter(struct evaluator *ev, struct ast *site, struct call *call);

/* The heap's state, and a return to it: what was allocated since is released. */
static inline struct heap_mark heap_mark(const struct evaluator *ev)
{
	return (struct heap_mark){ ev->heap_now, ev->elements };
}
void heap_release_to(struct evaluator *ev, struct heap_mark m);
static inline void heap_release(struct evaluator *ev, struct heap_mark m)
{
	if (ev->elements != m.elements) /* every allocation counts at least one element */
		heap_release_to(ev, m);
}

/* The value of e; false after an error. */
bool eval_expr(struct evaluator *ev, struct ast *e, struct value *out);
/* e as a vector (a number promoted), as a number, as a string, as a boolean, as a whole
 * number in [lo, hi] (what names it in the message); false after an error (a value of
 * another type can reach them only through what check.c knew as TYPE_ANY). */
bool vec_of(struct evaluator *ev, struct ast *e, double out[3]);
bool num_of(struct evaluator *ev, struct ast *e, double *out);
bool str_of(struct evaluator *ev, struct ast *e, const char **out);
bool truth_of(struct evaluator *ev, struct ast *e, bool *out);
/* e as a material: its index in the scene's materials. */
bool material_of(struct evaluator *ev, struct ast *e, int *out);
/* A file's name, e's string, and its path from src's folder (both malloc'd); false after
 * an error. A name that check.c could not see (not written as a literal) is checked for
 * reading here, with what the file is for in the message. */
bool file_of(struct evaluator *ev, struct ast *e, const struct source *src, const char *what, char **name,
             char **path);
bool whole_of(struct evaluator *ev, struct ast *e, double lo, double hi, const char *what, double *out);
/* num_of for a value that must be positive, or with zero 0 or more: else an error at e,
 * "WHAT must be positive, not V" ("must be 0 or more"), and false. */
bool positive_of(struct evaluator *ev, struct ast *e, const char *what, bool zero, double *out);

/* ---- eval_call.c ---- */

/* A running call of a definition of the scene's. */
struct call {
	struct ast *def;
	bool recursive;            /* another call of def ran when it began */
};
/* Binds def's parameters (site is the call) to args, saving what a running call of it
 * had there; false (reported) when calls nest too deep. */
bool call_begin(struct evaluator *ev, struct ast *site, const struct value *args, struct call *call);
void call_end(struct evaluator *ev, const struct call *call);

/* ---- eval_report.c ---- */

/* Reports an error at node at (at span sp), once per place however many loop iterations
 * and calls reach it, with notes on the loops' values and the calls that led there. */
void eval_error(struct evaluator *ev, struct ast *at, const char *fmt, ...)
	__attribute__((format(printf, 3, 4)));
void eval_error_span(struct evaluator *ev, struct ast *at, struct span sp, const char *fmt, ...)
	__attribute__((format(printf, 4, 5)));
/* Enters a loop or a call into the context of the notes; leaves it. */
void context_push(struct evaluator *ev, const struct ast *node, const struct value *var);
void context_pop(struct evaluator *ev);

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
