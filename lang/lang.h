/* lang.h: the front end's entry points: parse a source into statements. */
#ifndef SCN_LANG_H
#define SCN_LANG_H

#include <stdbool.h>

#include "ast.h"
#include "diag.h"

struct arena;

/* Called with each top-level statement as soon as it is parsed; false stops the parse. */
typedef bool lang_statement_fn(void *arg, struct ast *stmt);

/* State shared by the scanner and the parser of one source file. */
struct lang_ctx {
	struct arena *arena;          /* the syntax tree's nodes */
	struct arena *text;           /* the text of names and strings, which bindings keep */
	lang_statement_fn *each;      /* NULL: the statements are collected in stmts */
	void *each_arg;
	struct diag *diag;
	const struct source *src;
	struct ast_list stmts;        /* the result */
	bool abort;                   /* a fatal lexical error: report nothing more */
	bool too_deep;                /* "nested too deep" was said for this file */
	uint32_t pos;                 /* local offset of the scanner */
	uint32_t read_pos;            /* local offset of what YY_INPUT has handed the scanner */
	unsigned nopen;               /* open brackets, innermost last */
	unsigned nopen_of[4];         /* how many of them are '{', '(', '<' and '[' */
	int prev;                     /* the last token scanned, or 0: whether a '<' compares */
	int prev_kw;                  /* its keyword, or -1 */
	struct {
		struct span sp;
		uint32_t indent;      /* of the line it is on */
		char ch;
	} open[LANG_MAX_NESTING];
	uint32_t indent;              /* bytes of blank before the first token of the current line */
	uint32_t line_first;          /* local offset of that first token */
	/* A '}' that starts its line indented less than the line of the '{' it closed, and
	 * as much as the line of the '{' around that (meant): if that outer '{' is left open
	 * at the end, the '}' was most likely meant for it, and the inner '{' is the one not
	 * closed. Later closers shifted by the same missing '}' move outer outwards. */
	struct { bool seen; struct span inner, closer, meant, outer; } misfit;
};

/* Parses src into its statements, their nodes allocated in nodes and the text of their
 * names and strings in text (which may be the same arena). Syntax errors go to d; the
 * result holds what could be recovered. */
struct ast_list lang_parse(struct arena *nodes, struct arena *text, struct diag *d, const struct source *src);
/* Parses src one top-level statement at a time: each goes to each(arg, stmt) (NULL for
 * one that error recovery dropped), and its nodes are released (arena_reset(nodes))
 * when that returns, so that a file of a million statements never holds more than one
 * tree. Names and strings stay in text. Stops early when each returns false. For a load
 * that gives up at the first message: the lists of expected tokens in its syntax errors
 * may be inexact (parser_quick.c). */
void lang_parse_each(struct arena *nodes, struct arena *text, struct diag *d, const struct source *src,
                     lang_statement_fn *each, void *arg);

#endif
