/* parser_quick.c: the grammar's twin without LAC, under the name yyparse_quick, for the
 * statement-at-a-time load (lang_parse_each). LAC (lookahead correction) only makes the
 * "expected ..." lists of syntax errors exact, and costs a fifth of the parse; that load
 * gives up at the first message, and the scene is parsed again by yyparse, with LAC.
 * parser_nolac.c is generated from parser.y (lang/local.mk). */
#define yyparse yyparse_quick
#include "parser_nolac.c"
