/* builtins.c: the language's functions. Unary and binary arithmetic functions work
 * componentwise on vectors, as + - * / do; every domain error names itself so that the
 * checker can say why a value is not finite. */
#include "builtins.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

struct fn_info {
	const char *name;
	int min_args, max_args;
};

/* ORDER BUILTINS */
static const struct fn_info table[BUILTIN_COUNT] = {
	{ "sqrt", 1, 1 }, { "exp", 1, 1 }, { "log", 1, 1 }, { "abs", 1, 1 }, { "floor", 1, 1 },
	{ "ceil", 1, 1 }, { "sin", 1, 1 }, { "cos", 1, 1 }, { "tan", 1, 1 }, { "asin", 1, 1 },
	{ "acos", 1, 1 }, { "radians", 1, 1 }, { "degrees", 1, 1 },
	{ "pow", 2, 2 }, { "mod", 2, 2 }, { "atan2", 2, 2 },
	{ "min", 2, -1 }, { "max", 2, -1 },
	{ "dot", 2, 2 }, { "cross", 2, 2 }, { "normalize", 1, 1 }, { "length", 1, 1 },
	{ "rand", 1, 1 },
	{ "len", 1, 1 }, { "str", 1, 1 },
	{ "checker", 3, 3 },
	{ "pi", 0, 0 }, { "clock", 0, 0 }, { "frame", 0, 0 },
};

int builtin_lookup(const char *name)
{
	for (int i = 0; i < BUILTIN_COUNT; i++)
		if (strcmp(table[i].name, name) == 0)
			return i;
	return -1;
}

const char *builtin_name(enum builtin b) { return table[b].name; }
bool builtin_is_function(enum builtin b) { return b < CONST_PI; }
int builtin_min_args(enum builtin b) { return table[b].min_args; }
int builtin_max_args(enum builtin b) { return table[b].max_args; }

enum ast_type builtin_type(enum builtin b, const enum ast_type *args, int nargs, int *bad_arg,
                           const char **why)
{
	if (b == FN_LEN) {
		if (args[0] == TYPE_ARRAY || args[0] == TYPE_STR || args[0] == TYPE_ANY)
			return TYPE_NUM;
		*bad_arg = 0;
		*why = "len takes an array or a string";
		return TYPE_NONE;
	}
	bool any_vec = false, any_unknown = false;
	for (int i = 0; i < nargs; i++) {
		if (args[i] != TYPE_NUM && args[i] != TYPE_VEC && args[i] != TYPE_ANY) {
			*bad_arg = i;
			*why = "expected a number or a vector";
			return TYPE_NONE;
		}
		any_vec |= args[i] == TYPE_VEC;
		any_unknown |= args[i] == TYPE_ANY;
	}
	switch (b) {
	case FN_DOT: case FN_LENGTH:
		return TYPE_NUM;
	case FN_CROSS: case FN_NORMALIZE:
		return TYPE_VEC;
	case FN_RAND: case FN_STR:
		if (args[0] == TYPE_VEC) {
			*bad_arg = 0;
			*why = b == FN_RAND ? "rand takes a number" : "str takes a number (write str(v.x) for a component)";
			return TYPE_NONE;
		}
		return b == FN_RAND ? TYPE_NUM : TYPE_STR;
	case FN_CHECKER:
		if (args[2] == TYPE_VEC) {
			*bad_arg = 2;
			*why = "the checker's size must be a number";
			return TYPE_NONE;
		}
		return TYPE_PIGMENT;
	default:
		return any_vec ? TYPE_VEC : any_unknown ? TYPE_ANY : TYPE_NUM;
	}
}

static void broadcast(const struct value *in, double out[3])
{
	for (int k = 0; k < 3; k++)
		out[k] = in->v[in->type == TYPE_VEC ? k : 0];
}

/* One component of a componentwise function; *why is set on a domain error. */
static double apply1(enum builtin b, double x, const char **why)
{
	switch (b) {
	case FN_SQRT:
		if (x < 0) *why = "sqrt of a negative number";
		return sqrt(x);
	case FN_EXP: return exp(x);
	case FN_LOG:
		if (x <= 0) *why = "log of a number that is not positive";
		return log(x);
	case FN_ABS: return fabs(x);
	case FN_FLOOR: return floor(x);
	case FN_CEIL: return ceil(x);
	case FN_SIN: return sin(x);
	case FN_COS: return cos(x);
	case FN_TAN: return tan(x);
	case FN_ASIN:
		if (x < -1 || x > 1) *why = "asin of a number outside [-1, 1]";
		return asin(x);
	case FN_ACOS:
		if (x < -1 || x > 1) *why = "acos of a number outside [-1, 1]";
		return acos(x);
	case FN_RADIANS: return x * (M_PI / 180);
	case FN_DEGREES: return x * (180 / M_PI);
	default: return NAN;
	}
}

static double apply2(enum builtin b, double x, double y, const char **why)
{
	switch (b) {
	case FN_POW:
		if (x < 0 && y != floor(y)) *why = "pow of a negative number to a fractional power";
		if (x == 0 && y < 0) *why = "pow of zero to a negative power";
		return pow(x, y);
	case FN_MOD:
		if (y == 0) *why = "mod by zero";
		return fmod(x, y);
	case FN_ATAN2: return atan2(x, y);
	case FN_MIN: return x < y ? x : y;
	case FN_MAX: return x > y ? x : y;
	default: return NAN;
	}
}

double builtin_rand(double k)
{
	/* splitmix64 of the number's bits; -0 hashes as 0 so equal numbers agree */
	uint64_t z;
	double key = k == 0 ? 0 : k;
	memcpy(&z, &key, sizeof z);
	z += 0x9e3779b97f4a7c15u;
	z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
	z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
	z ^= z >> 31;
	return (double)(z >> 11) * 0x1.0p-53;
}

const char *builtin_apply(enum builtin b, const struct value *args, int nargs, enum ast_type result,
                          struct value *out, char text[32])
{
	const char *why = NULL;
	double a[3], c[3];
	int comps = result == TYPE_VEC ? 3 : 1;
	memset(out, 0, sizeof *out);
	out->type = (uint8_t)result;
	switch (b) {
	case FN_LEN:
		out->v[0] = args[0].len;
		return NULL;
	case FN_STR:
		out->s = value_number_text(args[0].v[0], text);
		out->len = (uint32_t)strlen(out->s);
		return NULL;
	case FN_DOT:
		broadcast(&args[0], a);
		broadcast(&args[1], c);
		out->v[0] = a[0] * c[0] + a[1] * c[1] + a[2] * c[2];
		break;
	case FN_CROSS:
		broadcast(&args[0], a);
		broadcast(&args[1], c);
		out->v[0] = a[1] * c[2] - a[2] * c[1];
		out->v[1] = a[2] * c[0] - a[0] * c[2];
		out->v[2] = a[0] * c[1] - a[1] * c[0];
		break;
	case FN_LENGTH:
		broadcast(&args[0], a);
		out->v[0] = hypot(hypot(a[0], a[1]), a[2]);
		break;
	case FN_NORMALIZE: {
		broadcast(&args[0], a);
		double len = hypot(hypot(a[0], a[1]), a[2]);
		if (len == 0)
			return "normalize of a zero vector";
		for (int k = 0; k < 3; k++)
			out->v[k] = a[k] / len;
		break;
	}
	case FN_RAND:
		out->v[0] = builtin_rand(args[0].v[0]);
		break;
	case FN_POW: case FN_MOD: case FN_ATAN2: case FN_MIN: case FN_MAX:
		broadcast(&args[0], a);
		for (int i = 1; i < nargs; i++) {
			broadcast(&args[i], c);
			for (int k = 0; k < comps; k++)
				a[k] = apply2(b, a[k], c[k], &why);
		}
		memcpy(out->v, a, sizeof a);
		break;
	default:
		broadcast(&args[0], a);
		for (int k = 0; k < comps; k++)
			out->v[k] = apply1(b, a[k], &why);
		break;
	}
	if (why)
		return why;
	for (int k = 0; k < comps; k++)
		if (!isfinite(out->v[k]))
			return "the result is too large to be a number";
	return NULL;
}
