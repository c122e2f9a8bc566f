/* builtins.h: the language's functions and constants (LANGUAGE.md section 4): their
 * names, their static types and their evaluation, in one table. */
#ifndef SCN_BUILTINS_H
#define SCN_BUILTINS_H

#include <stdbool.h>

#include "ast.h"
#include "value.h"

enum builtin {
	/* ORDER BUILTINS: keep in step with the table in builtins.c */
	FN_SQRT, FN_EXP, FN_LOG, FN_ABS, FN_FLOOR, FN_CEIL, FN_SIN, FN_COS, FN_TAN, FN_ASIN,
	FN_ACOS, FN_RADIANS, FN_DEGREES,            /* one argument, componentwise on vectors */
	FN_POW, FN_MOD, FN_ATAN2,                   /* two arguments, componentwise */
	FN_MIN, FN_MAX,                             /* two or more, componentwise */
	FN_DOT, FN_CROSS, FN_NORMALIZE, FN_LENGTH,  /* vector functions; numbers are promoted */
	FN_RAND,                                    /* number -> number in [0, 1) */
	FN_LEN, FN_STR,                             /* an array's or a string's length; a number's text */
	FN_CHECKER,                                 /* checker(C1, C2, SIZE): only as a diffuse colour */
	CONST_PI, CONST_CLOCK, CONST_FRAME,         /* constants, not functions */
	BUILTIN_COUNT
};

/* The built-in spelt name, or -1. */
int builtin_lookup(const char *name);
const char *builtin_name(enum builtin b);
bool builtin_is_function(enum builtin b);
int builtin_min_args(enum builtin b);
int builtin_max_args(enum builtin b);           /* -1: no upper bound */

/* The type of a call with arguments of these types (static ones, with TYPE_ANY, or the
 * values' own); nargs is within the function's bounds. Returns TYPE_NONE after writing
 * the reason into why ("..., found" and the argument's type follow it) and the argument
 * to blame into bad_arg when an argument has the wrong type. */
enum ast_type builtin_type(enum builtin b, const enum ast_type *args, int nargs, int *bad_arg,
                           const char **why);

/* Evaluates a call (not checker) whose arguments builtin_type accepted, with the result
 * type it gave. Numbers among args are broadcast where a vector is needed. A string
 * result is written in text. Returns NULL, or a description of why the result would not
 * be finite. */
const char *builtin_apply(enum builtin b, const struct value *args, int nargs, enum ast_type result,
                          struct value *out, char text[32]);

/* rand(k): a deterministic hash of k into [0, 1). */
double builtin_rand(double k);

#endif
