/* lang.h: the front end's entry points: parse a source into statements. */
#ifndef SCN_LANG_H
#define SCN_LANG_H

#include <stdbool.h>

#include "ast.h"
#include "diag.h"

struct arena;

/* State shared by the scanner and the parser of one source file. */
struct lang_ctx {
	struct arena *arena;
	struct diag *diag;
	const struct source *src;
	struct ast_list stmts;        /* the result */
	bool abort;                   /* a fatal lexical error: report nothing more */
	bool too_deep;                /* "nested too deep" was said for this file */
	uint32_t pos;                 /* local offset of the scanner */
	uint32_t read_pos;            /* local offset of what YY_INPUT has handed the scanner */
	unsigned nopen;               /* open brackets, innermost last */
	unsigned nopen_of[3];         /* how many of them are '{', '(' and '<' */
	struct { struct span sp; char ch; } open[LANG_MAX_NESTING];
};

/* Parses src into its statements, allocated in a. Syntax errors go to d; the result
 * holds what could be recovered. */
struct ast_list lang_parse(struct arena *a, struct diag *d, const struct source *src);

#endif
