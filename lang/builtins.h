/* builtins.h: the language's functions and constants (LANGUAGE.md section 4): their
 * names, their static types and their evaluation, in one table. */
#ifndef SCN_BUILTINS_H
#define SCN_BUILTINS_H

#include <stdbool.h>

#include "ast.h"

enum builtin {
	/* ORDER BUILTINS: keep in step with the table in builtins.c */
	FN_SQRT, FN_EXP, FN_LOG, FN_ABS, FN_FLOOR, FN_CEIL, FN_SIN, FN_COS, FN_TAN, FN_ASIN,
	FN_ACOS, FN_RADIANS, FN_DEGREES,            /* one argument, componentwise on vectors */
	FN_POW, FN_MOD, FN_ATAN2,                   /* two arguments, componentwise */
	FN_MIN, FN_MAX,                             /* two or more, componentwise */
	FN_DOT, FN_CROSS, FN_NORMALIZE, FN_LENGTH,  /* vector functions; numbers are promoted */
	FN_RAND,                                    /* number -> number in [0, 1) */
	FN_CHECKER,                                 /* checker(C1, C2, SIZE): only as a diffuse colour */
	CONST_PI, CONST_CLOCK, CONST_FRAME,         /* constants, not functions */
	BUILTIN_COUNT
};

struct value {
	double v[3];                                /* a number is v[0] */
};

/* The built-in spelt name, or -1. */
int builtin_lookup(const char *name);
const char *builtin_name(enum builtin b);
bool builtin_is_function(enum builtin b);
int builtin_min_args(enum builtin b);
int builtin_max_args(enum builtin b);           /* -1: no upper bound */

/* Static type of a call; args' types are known and are numbers or vectors.
 * Returns TYPE_NONE after writing a reason into why when an argument has the wrong type. */
enum ast_type builtin_type(enum builtin b, const enum ast_type *args, int nargs, int *bad_arg,
                           const char **why);

/* Evaluates a call (not checker). Numbers among args are broadcast where a vector is
 * needed. Returns NULL, or a description of why the result would not be finite. */
const char *builtin_apply(enum builtin b, const struct value *args, const enum ast_type *types,
                          int nargs, enum ast_type result, struct value *out);

/* rand(k): a deterministic hash of k into [0, 1). */
double builtin_rand(double k);

#endif
