/* value.c: the operators' type rules (value.h) and what values need besides: their
 * equality and the text of a number. */
#include "value.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const char *value_type_name(enum ast_type t)
{
	switch (t) {
	case TYPE_NUM: return "a number";
	case TYPE_VEC: return "a vector";
	case TYPE_STR: return "a string";
	case TYPE_PIGMENT: return "a checker pattern";
	case TYPE_MATERIAL: return "a material";
	case TYPE_BOOL: return "a boolean";
	case TYPE_ARRAY: return "an array";
	case TYPE_ANY: return "a value";
	default: return "nothing";
	}
}

static const char *op_text(char op)
{
	switch (op) {
	case OP_LE: return "<=";
	case OP_GE: return ">=";
	case OP_EQ: return "==";
	case OP_NE: return "!=";
	case OP_AND: return "and";
	case OP_OR: return "or";
	case '<': return "<";
	case '>': return ">";
	case '+': return "+";
	case '-': return "-";
	case '*': return "*";
	default: return "/";
	}
}

static bool arithmetic(enum ast_type t)
{
	return t == TYPE_NUM || t == TYPE_VEC;
}

/* The message for a condition that is not a boolean, after its first words. */
static void not_boolean(char *why, size_t size, const char *what, enum ast_type t)
{
	snprintf(why, size, "%s must be true or false, found %s%s", what, value_type_name(t),
	         t == TYPE_NUM ? "; compare it, as in x != 0" : "");
}

/* One operand of op on its own: whether op takes a value of type t. */
static bool operand_ok(char op, enum ast_type t, char *why, size_t size)
{
	if (t == TYPE_ANY)
		return true;
	switch (op) {
	case '+':
		if (arithmetic(t) || t == TYPE_STR || t == TYPE_ARRAY)
			return true;
		snprintf(why, size, "'+' adds numbers and vectors and joins strings or arrays, found %s", value_type_name(t));
		return false;
	case '-': case '*': case '/':
		if (arithmetic(t))
			return true;
		snprintf(why, size, "expected a number or a vector, found %s%s", value_type_name(t),
		         t == TYPE_STR || t == TYPE_ARRAY ? " (only '+' joins strings and arrays)" : "");
		return false;
	case '<': case '>': case OP_LE: case OP_GE:
		if (t == TYPE_NUM)
			return true;
		snprintf(why, size, "'%s' compares numbers, found %s", op_text(op), value_type_name(t));
		return false;
	case OP_EQ: case OP_NE:
		if (t != TYPE_ARRAY && t != TYPE_PIGMENT && t != TYPE_MATERIAL)
			return true;
		snprintf(why, size, "'%s' compares numbers, vectors, strings and booleans, found %s", op_text(op),
		         value_type_name(t));
		return false;
	default: { /* and, or */
		if (t == TYPE_BOOL)
			return true;
		char what[32];
		snprintf(what, sizeof what, "an operand of '%s'", op_text(op));
		not_boolean(why, size, what, t);
		return false;
	}
	}
}

enum ast_type value_type_binary(char op, enum ast_type l, enum ast_type r, char *why, size_t size, enum blame *blame)
{
	if (!operand_ok(op, l, why, size)) {
		*blame = BLAME_LEFT;
		return TYPE_NONE;
	}
	if (!operand_ok(op, r, why, size)) {
		*blame = BLAME_RIGHT;
		return TYPE_NONE;
	}
	bool compares = op == '<' || op == '>' || op == OP_LE || op == OP_GE || op == OP_EQ || op == OP_NE;
	if (compares || op == OP_AND || op == OP_OR) {
		/* == and != take a number and a vector (promoted), or two of one kind */
		bool mixed = (op == OP_EQ || op == OP_NE) && l != TYPE_ANY && r != TYPE_ANY && l != r &&
		             !(arithmetic(l) && arithmetic(r));
		if (mixed) {
			*blame = BLAME_WHOLE;
			snprintf(why, size, "'%s' compares values of one kind, not %s and %s", op_text(op), value_type_name(l),
			         value_type_name(r));
			return TYPE_NONE;
		}
		return TYPE_BOOL;
	}
	if (l == TYPE_ANY || r == TYPE_ANY)
		return TYPE_ANY;
	if (arithmetic(l) && arithmetic(r))
		return l == TYPE_VEC || r == TYPE_VEC ? TYPE_VEC : TYPE_NUM;
	if (l == r) /* '+' of two strings or two arrays */
		return l;
	/* '+' of a string or an array and something else */
	bool left = l != TYPE_STR && l != TYPE_ARRAY; /* the odd one out */
	enum ast_type joined = left ? r : l, odd = left ? l : r;
	*blame = left ? BLAME_LEFT : BLAME_RIGHT;
	if (joined == TYPE_STR)
		snprintf(why, size, "'+' joins a string only to a string, found %s%s", value_type_name(odd),
		         odd == TYPE_NUM ? "; write str(x) for a number's text" : "");
	else
		snprintf(why, size, "'+' joins an array only to an array, found %s; write [x] for an array of one",
		         value_type_name(odd));
	return TYPE_NONE;
}

enum ast_type value_type_unary(char op, enum ast_type t, char *why, size_t size)
{
	if (op == '!') {
		if (t == TYPE_BOOL || t == TYPE_ANY)
			return TYPE_BOOL;
		not_boolean(why, size, "the operand of 'not'", t);
		return TYPE_NONE;
	}
	if (arithmetic(t) || t == TYPE_ANY)
		return t;
	snprintf(why, size, "expected a number or a vector, found %s", value_type_name(t));
	return TYPE_NONE;
}

bool value_type_condition(enum ast_type t, char *why, size_t size)
{
	if (t == TYPE_BOOL || t == TYPE_ANY)
		return true;
	not_boolean(why, size, "a condition", t);
	return false;
}

const char *value_number_text(double x, char buf[32])
{
	if (x == floor(x) && fabs(x) < 9007199254740992.0) {
		snprintf(buf, 32, "%.0f", x); /* -0 stays "-0": it reads back as itself */
		return buf;
	}
	for (int prec = 1; prec < 17; prec++) {
		snprintf(buf, 32, "%.*g", prec, x);
		if (strtod(buf, NULL) == x)
			return buf;
	}
	snprintf(buf, 32, "%.17g", x);
	return buf;
}

bool value_equal(const struct value *l, const struct value *r)
{
	switch (l->type) {
	case TYPE_BOOL:
		return l->truth == r->truth;
	case TYPE_STR:
		return l->len == r->len && memcmp(l->s, r->s, l->len) == 0;
	default: /* numbers and vectors, a number promoted */
		for (int k = 0; k < 3; k++)
			if (l->v[l->type == TYPE_VEC ? k : 0] != r->v[r->type == TYPE_VEC ? k : 0])
				return false;
		return true;
	}
}
