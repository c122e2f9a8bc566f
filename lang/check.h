/* check.h: the static checks of a parsed scene: names and scopes, types, attributes,
 * statement placement, includes. Annotates the AST in place for eval.c. */
#ifndef SCN_CHECK_H
#define SCN_CHECK_H

#include <stdbool.h>

#include "ast.h"
#include "diag.h"

struct arena;
struct checker;

enum binding_kind { BIND_VALUE, BIND_LOOP, BIND_MATERIAL, BIND_PARAM, BIND_FUNCTION, BIND_MACRO };

struct binding {
	const char *name;
	struct span span;
	enum binding_kind kind;
	enum ast_type type;        /* of a value binding */
	unsigned slot;             /* where eval.c keeps its current value */
	unsigned scope;
	struct ast *def;           /* a function's or a macro's definition */
	bool used;
	bool checking;             /* a definition whose body is being checked: a call there is
	                            * recursion, which does not count as a use */
	bool failed;               /* its definition had an error (ast.failed): what uses it is skipped */
	struct binding *shadowed;  /* the outer binding of the same name that this one hides */
	struct binding *scope_next;
	struct name_entry *entry;
};

/* Limits of LANGUAGE.md section 6. */
#define LANG_MAX_INCLUDE_DEPTH 64
/* Files read by includes in all, a file counting each time it is included (not in
 * LANGUAGE.md: without it, includes that fan out read exponentially many files). */
#define LANG_MAX_INCLUDES 10000

/* Checks the statements of src (already parsed into *stmts), reading and parsing the
 * files they include. Reports to d; returns the number of value slots eval.c needs. */
unsigned check_file(struct arena *a, struct diag *d, const struct source *src, struct ast_list *stmts);

/* The same one statement at a time, for a file checked as it is parsed. check_new
 * opens the file's scope: bindings and the symbol table go to keep, which outlives the
 * checker, and included files are parsed into nodes (their names into keep). root is
 * the file's statements, for "defined after its use" notes, or NULL. */
struct checker *check_new(struct arena *nodes, struct arena *keep, struct diag *d, const struct source *src,
                            struct ast_list *root);
void check_statement(struct checker *c, struct ast *stmt);
/* The value slots eval.c needs for the statements checked so far. */
unsigned check_slots(const struct checker *c);
/* Frees c. finished: the file was checked to its end, so its scope is closed and what it
 * bound and never used is warned about (as check_file does); otherwise it is abandoned. */
void check_free(struct checker *c, bool finished);

#endif
