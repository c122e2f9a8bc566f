/* check_internal.h: what the checker's files share, and nothing outside them uses:
 * the checker's state and the calls between check.c (statements, CSGs, the entry points),
 * check_solid.c (which objects have an inside), check_block.c (the blocks' attributes),
 * check_expr.c (expressions) and check_names.c (the symbol table), each of which calls
 * only those after it. */
#ifndef SCN_CHECK_INTERNAL_H
#define SCN_CHECK_INTERNAL_H

#include <stdbool.h>

#include "ast.h"
#include "check.h"
#include "keywords.h"
#include "lang.h"
#include "suggest.h"
#include "value.h"

struct name_entry {
	const char *name;
	struct binding *top;
	struct name_entry *next;
};

struct checker {
	struct arena *arena;       /* bindings and the symbol table: kept for the whole load */
	struct arena *nodes;       /* the syntax trees of included files */
	struct diag *diag;
	struct name_entry **buckets;
	size_t nbuckets, nentries;
	unsigned scope;            /* depth of the current scope; the file scope is 1 */
	struct binding *scope_bindings[2 * LANG_MAX_NESTING + 2]; /* a loop opens two */
	unsigned nslots;
	unsigned loop_depth;
	unsigned def_depth;        /* definitions whose bodies are being checked */
	struct ast *macro;         /* the innermost macro being defined, or NULL */
	int include_depth;
	unsigned nincludes;        /* files read by includes so far, against LANG_MAX_INCLUDES */
	char *include_stack[LANG_MAX_INCLUDE_DEPTH + 1]; /* real paths of the files being read */
	/* camera, skybox, samples, max_depth seen so far, by place: the statement itself
	 * may be gone when the file is checked one statement at a time */
	struct { bool seen; struct span at; } once[KW_COUNT_ALL];
	struct ast_list *root;     /* the scene file's statements, to find definitions that come late, or NULL */
	const char *defining;      /* the material whose block is being checked, or NULL */
	bool include_failed;       /* an include could not be read: its names are unknown, not wrong */
	/* for ast.failed: the statement being checked uses a failed name or holds a syntax
	 * error; the errors reported inside the statements nested in it, which are theirs */
	bool tainted;
	int nested_errors;
	/* the innermost CSG whose members are being checked, or NULL; the for loops entered
	 * inside it; whether a statement inside it failed (then the whole CSG has: evaluated
	 * without that member, it would be another shape) */
	struct ast *csg;
	unsigned csg_loops;
	const char *csg_body;      /* "a for loop" or "an if": the innermost of them, for messages */
	bool csg_failed;
};

enum shape {
	S_FLAG,       /* no value */
	S_NUM, S_VEC, /* one expression; a number is promoted to a vector */
	S_INT2,       /* two numbers: resolution W, H */
	S_STR,        /* one string */
	S_MATERIAL,   /* a material's name, or an inline material { } */
	S_LIKE,       /* a material's name */
	S_WORD,       /* a word of the attribute's own list: samples' pattern, an image's map,
	               * interpolate */
	S_PIGMENT,    /* a colour, checker(...), pattern { ... } or image { ... } */
	S_LIST,       /* { V, V, ... } */
	S_BLOCK,      /* a block of attributes: normal { ... }, spotlight { ... } */
	S_COLORS,     /* an array of [position, colour] pairs */
};

/* ---- check_solid.c ---- */

/* Why an object has no inside, and what to do about it. */
struct no_inside {
	const struct ast *at;      /* the object statement without one: the one asked about, or a
	                            * member (of a member ...) of that union */
	const char *why, *fix;
};
/* Whether statement s, an object or a for loop of them, has an inside as its text says
 * (LANGUAGE.md section 9); when not, *why. What is not an object, or is broken by a
 * syntax error, counts as having one: it has its error already. */
bool solid_statement(const struct ast *s, struct no_inside *why);
/* Reports each member of csg (an intersection, difference or merge) without an inside, at
 * its keyword, through for loops. */
void check_solid_members(struct checker *c, const struct ast *csg);
/* Reports the item 'inverse' of object s when s has no inside. */
void check_inverse(struct checker *c, const struct ast *s, const struct ast *inverse);

/* ---- check_names.c ---- */

/* The innermost binding of name, or NULL. */
struct binding *names_lookup(struct checker *c, const char *name);
/* What a name may stand for where it is used, for "did you mean". */
enum name_class { NAMES_VALUES, NAMES_MATERIALS, NAMES_FUNCTIONS, NAMES_MACROS };
enum name_class names_class(enum binding_kind kind);
/* Offers s every visible name of that class, the built-in ones with the scene's. */
void names_suggest_visible(struct checker *c, struct suggestion *s, enum name_class what);
/* A scope opens; one closes, warning about what it bound and never used. */
void names_push_scope(struct checker *c);
void names_pop_scope(struct checker *c);
/* Binds name in the current scope (a redefinition there is an error); the new binding. */
struct binding *names_bind(struct checker *c, const char *name, struct span sp, enum binding_kind kind,
                           enum ast_type type);

/* ---- check_expr.c ---- */

/* Reports an unknown name of that class at `at`, with a suggestion or a note on a later
 * definition. */
void unknown_name(struct checker *c, struct span at, const char *name, enum name_class what);
/* Checks e and annotates it with its type. */
enum ast_type check_expr(struct checker *c, struct ast *e);
/* Checks a call (an expression's or a statement's) of the function or macro b. */
void check_user_call(struct checker *c, struct ast *call, struct binding *b);

/* ---- check_block.c ---- */

struct block_spec;
/* The attributes of a block statement's keyword, or NULL. */
const struct block_spec *spec_of(enum kw kw);
/* Checks a block's positional arguments and items; records the first item of each
 * attribute in seen[] for the statement's own rules. Returns false when an attribute
 * was unknown: what the block lacks may then be only misspelt. */
bool check_block(struct checker *c, const struct block_spec *spec, struct ast_block *block, struct span where,
                 struct ast *seen[KW_COUNT_ALL]);
/* Checks a value of the given shape for attribute attr. */
void check_value(struct checker *c, struct ast *e, enum shape shape, const char *attr);
/* An item's keyword as written. */
const char *item_name(const struct ast *item);
/* mesh { NAME ... }, image { NAME ... }: the grammar reads a leading name as an attribute;
 * when it names a value, it is moved to the block's arguments as the file name. */
void block_file_name(struct checker *c, struct ast_block *block);
/* Reports a literal file name str (what the file is for) that cannot be read from src's folder. */
void check_readable(struct checker *c, const struct source *src, struct ast *str, const char *what);

#endif
