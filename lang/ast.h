/* ast.h: the syntax tree of a scene. Every node lives in the parse's arena and keeps
 * the source span it came from; check.c annotates names and types in place. */
#ifndef SCN_AST_H
#define SCN_AST_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "diag.h"
#include "keywords.h"

struct arena;

enum ast_kind {
	/* expressions */
	AST_NUM, AST_STR, AST_VEC, AST_IDENT, AST_NEG, AST_BINARY, AST_CALL, AST_MEMBER,
	AST_BOOL, AST_ARRAY, AST_INDEX, AST_NOT, AST_COND,
	AST_ERROR,  /* stands for an expression already reported as wrong */
	/* statements */
	AST_LET, AST_INCLUDE, AST_FOR, AST_IF, AST_DEF,
	AST_MACRO_CALL, /* NAME(ARGS) as a statement: u.call */
	AST_BLOCK_STMT, /* camera, light, material NAME, sphere, ..., samples { }, samples N, max_depth N */
	AST_UNKNOWN_STMT, /* a statement that starts with a name: u.item holds it, for the message */
	/* parts of a block */
	AST_ITEM,
};

/* Type of an expression: check.c's static one, or a value's own (struct value). TYPE_ANY
 * is known only when the scene runs: a parameter, an array's element, what a function
 * returns. */
enum ast_type {
	TYPE_NONE, TYPE_NUM, TYPE_VEC, TYPE_STR, TYPE_PIGMENT, TYPE_MATERIAL, TYPE_BOOL, TYPE_ARRAY, TYPE_ANY,
};

/* The operators of AST_BINARY besides + - * /: comparisons and the logical ones. */
enum {
	OP_LT = '<', OP_GT = '>', OP_LE = 'l', OP_GE = 'g', OP_EQ = '=', OP_NE = '!', OP_AND = '&', OP_OR = '|',
};

struct ast_list {
	struct ast **v;
	uint32_t n, cap;
};

/* { ARGS ITEMS }: positional arguments, then attribute items; or a CSG's { MEMBERS ITEMS },
 * its members (and whatever else than items its braces hold) apart from its items. */
struct ast_block {
	struct ast_list args;
	struct ast_list items;
	struct ast_list members;   /* a CSG's: objects, for loops, and statements misplaced there */
	struct span open;      /* the '{' */
	bool broken;           /* a syntax error inside; its content was skipped (in a CSG's,
	                        * only what an AST_ERROR member stands for) */
};

struct binding;

/* A node is allocated only as large as its kind's member of u needs (ast_new): a
 * scene of a million spheres holds tens of millions of nodes. The flags share the
 * header's bytes with kind and type. */
struct ast {
	uint8_t kind;          /* enum ast_kind */
	uint8_t type;          /* enum ast_type: check.c's type of an expression */
	bool reported;         /* eval.c: an error here was reported once already */
	bool failed;           /* check.c, on a statement: it had an error, or uses a name whose
	                        * definition had one; eval.c skips it, so that the value errors
	                        * of the other statements come in the same run, and none that
	                        * follows only from an error already reported */
	uint16_t depth;        /* expression nesting, bounded by LANG_MAX_NESTING (+1 until checked) */
	struct span span;
	union {
		double num;
		struct { char *text; size_t len; } str;
		struct ast *vec[3];
		struct { char *name; struct binding *ref; int builtin; } ident;
		struct { char op; struct ast *l, *r; } bin;   /* AST_NEG and AST_NOT use l; AST_INDEX: l[r] */
		bool truth;                                   /* AST_BOOL */
		struct ast_list elems;                        /* AST_ARRAY */
		struct { char *name; struct span name_span; struct ast_list args; int fn;
		         struct binding *ref; } call;        /* fn: a built-in, or -1 for ref's def */
		struct { struct ast *c, *a, *b; } cond;       /* AST_COND: c ? a : b */
		struct { struct ast *e; int comp; struct span comp_span; char *name; } member;
		struct { char *name; struct span name_span; struct ast *value; struct binding *b; } let;
		struct { char *path; struct span path_span; struct ast_list body; bool loaded; } include;
		struct { char *var; struct span var_span; struct ast *from, *to; /* to NULL: for var in from */
		         struct ast_list body; struct binding *b; } loop;
		struct { struct ast *cond; struct ast_list then, other; } cond_stmt; /* other: else */
		struct {
			char *name;
			struct span name_span;
			struct ast_list params;    /* AST_IDENT nodes; check.c binds them (ident.ref) */
			struct ast *value;         /* a function's expression, or NULL for a macro */
			struct ast_list body;      /* a macro's statements */
			struct binding *b;
			/* check.c: the slots of the bindings inside it, [slot_lo, slot_hi), which a
			 * call that starts while another runs saves and restores; eval.c: how many
			 * calls of it are running */
			unsigned slot_lo, slot_hi;
			unsigned active;
			/* check.c, for a macro: its first statement (through the macros it calls)
			 * that cannot be a CSG's member, or NULL */
			const struct ast *not_member;
		} def;
		struct {
			enum kw kw;            /* which statement */
			struct span kw_span;
			char *name;            /* material NAME */
			struct span name_span;
			struct ast_block *block;
			struct ast *value;     /* samples N, max_depth N */
			struct binding *b;     /* material NAME: its binding */
		} stmt;
		struct {
			int kw;                /* the attribute, or -1 for an unknown name */
			char *name;
			struct span name_span;
			struct ast_list args;
			struct ast_block *block;
		} item;
	} u;
};

/* Expressions nest at most this deep (brackets, operators and blocks alike). */
#define LANG_MAX_NESTING 1000

void ast_list_push(struct arena *a, struct ast_list *l, struct ast *node);

struct ast *ast_new(struct arena *a, enum ast_kind kind, struct span sp);
struct ast *ast_num(struct arena *a, struct span sp, double v);
struct ast *ast_str(struct arena *a, struct span sp, char *text, size_t len);
struct ast *ast_vec(struct arena *a, struct span sp, struct ast *x, struct ast *y, struct ast *z);
struct ast *ast_ident(struct arena *a, struct span sp, char *name);
struct ast *ast_neg(struct arena *a, struct span sp, struct ast *e);
struct ast *ast_binary(struct arena *a, struct span sp, char op, struct ast *l, struct ast *r);
struct ast *ast_call(struct arena *a, struct span sp, char *name, struct span name_span,
                     struct ast_list args);
struct ast *ast_member(struct arena *a, struct span sp, struct ast *e, char *name, struct span comp_span);
struct ast *ast_bool(struct arena *a, struct span sp, bool truth);
struct ast *ast_array(struct arena *a, struct span sp, struct ast_list elems);
struct ast *ast_index(struct arena *a, struct span sp, struct ast *e, struct ast *index);
struct ast *ast_not(struct arena *a, struct span sp, struct ast *e);
struct ast *ast_cond(struct arena *a, struct span sp, struct ast *c, struct ast *x, struct ast *y);
struct ast *ast_if(struct arena *a, struct span sp, struct ast *cond, struct ast_list then, struct ast_list other);
/* value NULL: a macro with body */
struct ast *ast_def(struct arena *a, struct span sp, char *name, struct span name_span, struct ast_list params,
                    struct ast *value, struct ast_list body);
struct ast *ast_macro_call(struct arena *a, struct span sp, char *name, struct span name_span, struct ast_list args);
struct ast *ast_let(struct arena *a, struct span sp, char *name, struct span name_span, struct ast *value);
struct ast *ast_include(struct arena *a, struct span sp, char *path, struct span path_span);
struct ast *ast_for(struct arena *a, struct span sp, char *var, struct span var_span,
                    struct ast *from, struct ast *to, struct ast_list body);
struct ast *ast_block_stmt(struct arena *a, struct span sp, enum kw kw, struct span kw_span,
                           struct ast_block *block, struct ast *value);
struct ast *ast_item(struct arena *a, struct span sp, int kw, char *name, struct span name_span,
                     struct ast_list args, struct ast_block *block);
struct ast_block *ast_block(struct arena *a, struct span open, struct ast_list args, struct ast_list items);
/* A CSG's block: elements split into items (AST_ITEM) and members (the rest, in order). */
struct ast_block *ast_csg_block(struct arena *a, struct span open, struct ast_list elements);
/* A block whose content error recovery skipped: checked no further. */
struct ast_block *ast_broken_block(struct arena *a, struct span open);

#endif
