/* value.h: the language's values, and the rules of its operators' types, which check.c
 * applies to static types and eval.c to the values' own: one rule for both, so that a
 * mistake found before the scene runs and one found while it runs read the same. */
#ifndef SCN_VALUE_H
#define SCN_VALUE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "ast.h"

struct value {
	uint8_t type;                  /* enum ast_type: a value's own is never TYPE_ANY */
	uint32_t len;                  /* a string's bytes, an array's elements */
	union {
		double v[3];               /* a number is v[0] */
		bool truth;
		const char *s;             /* NUL-terminated */
		const struct value *elems;
	};
};

/* "a number", "a vector", ...: for messages. */
const char *value_type_name(enum ast_type t);

/* Where a rule puts the blame for a wrong type. */
enum blame { BLAME_LEFT, BLAME_RIGHT, BLAME_WHOLE };

/* The type of l OP r for AST_BINARY's operators (+ - * / and OP_*), or TYPE_NONE with
 * the message in why (size bytes) and the operand to blame. An operand of TYPE_ANY is
 * held to what the operator takes of any operand; the result is then TYPE_ANY unless
 * the operator decides it (a comparison gives a boolean). */
enum ast_type value_type_binary(char op, enum ast_type l, enum ast_type r, char *why, size_t size, enum blame *blame);
/* The same for unary minus (op '-') and not (op '!'). */
enum ast_type value_type_unary(char op, enum ast_type t, char *why, size_t size);
/* Whether t may be a condition (of if, ?:); when not, the message. */
bool value_type_condition(enum ast_type t, char *why, size_t size);

/* str(x), and a number in a message: the shortest decimal that reads back as x (so that
 * a value the user wrote, ior -1.33, shows as written); a whole number below 2^53
 * without a decimal point or an exponent. */
const char *value_number_text(double x, char buf[32]);
/* l == r for values of types that value_type_binary accepts for '=='. */
bool value_equal(const struct value *l, const struct value *r);

#endif
