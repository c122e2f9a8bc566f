/* parser.y: the grammar of the scene language (LANGUAGE.md sections 2, 4, 5, 9, 10, 11 and 12) -> AST.
 * Every statement starts with a keyword. Blocks are generic (positional arguments, then
 * attribute items) so that check.c, not the grammar, knows which attribute belongs where
 * and can say "unknown attribute 'radus' in sphere; did you mean 'radius'?". A CSG block
 * is as generic: its members and items in any order, and any statement besides, which
 * check.c then says does not belong there. */

%code top {
#include "config.h"
}

%code requires {
#include "ast.h"
#include "diag.h"
typedef void *yyscan_t;
struct lang_ctx;
}

%code {
#include <ctype.h>
#include <math.h>
#include <string.h>

#include "arena.h"
#include "lang.h"

int yylex(YYSTYPE *yylval, YYLTYPE *yylloc, yyscan_t scanner);
static struct ast *bounded(struct lang_ctx *ctx, struct ast *e);
static struct ast *string_node(struct lang_ctx *ctx, struct span sp, char *text, size_t len);
static struct ast *not_a_vector(struct lang_ctx *ctx, struct span sp);
static struct ast *compare(struct lang_ctx *ctx, struct span sp, char op, struct ast *l, struct span lsp,
                           struct ast *r, struct span rsp);
static char *reserved(struct lang_ctx *ctx, struct span sp);
static struct span span_join(struct span a, struct span b);
static struct ast_list list1(struct lang_ctx *ctx, struct ast *e);
static struct ast_list append(struct lang_ctx *ctx, struct ast_list l, struct ast *e);
static bool statement(struct lang_ctx *ctx, struct ast_list *list, struct ast *stmt, bool file_level);
/* Whether the statement being reduced is one of the file's, not of a loop's body: then
 * bison's state stack (of its yacc.c skeleton) holds the start state, the file's list
 * and the statement, and nothing else. The grammar itself cannot tell the two lists
 * apart without changing the automaton, and with it how errors are recovered from. */
#define FILE_LEVEL (yyssp - yyss == 2)
static const struct ast_list no_list;
static void yyerror(YYLTYPE *loc, yyscan_t scanner, struct lang_ctx *ctx, const char *msg);
#define A (ctx->arena)
}

%define api.pure full                       /* reentrant: no globals */
%define api.location.type {struct span}     /* byte spans; diag.c finds line and column */
%define parse.error custom                  /* yyreport_syntax_error below */
%define parse.lac full                      /* exact "expected" lists despite default reductions */
%locations
%lex-param {yyscan_t scanner}
%parse-param {yyscan_t scanner} {struct lang_ctx *ctx}
%expect 0

/* A rule's span runs from its first symbol to its last; an empty rule sits where the
 * previous symbol ended. */
%code requires {
#define YYLLOC_DEFAULT(Cur, Rhs, N) do { \
	if (N) { (Cur).start = YYRHSLOC(Rhs, 1).start; (Cur).end = YYRHSLOC(Rhs, N).end; } \
	else { (Cur).start = (Cur).end = YYRHSLOC(Rhs, 0).end; } \
} while (0)
}

%union {
	double num;
	struct { char *text; size_t len; } str;
	char *name;
	int kw;
	struct ast *node;
	struct ast_list list;
	struct ast_block *block;
}

%token <num> NUMBER "number"
%token <str> STRING "string"
%token <name> IDENT "identifier"
%token <name> NAME_VALUE "name"  /* a name followed by a value: it starts an attribute */
%token POV_COLOUR "rgb"               /* POV-Ray's rgb, rgbf, ...: reserved for a message */
%token <kw> ATTR "attribute name"
%token <kw> ITEMS_KW "statement keyword"   /* camera light skybox fog: { ITEMS } */
%token <kw> ARGS_KW "shape keyword"    /* sphere plane triangle box cylinder cone disc torus: { ARGS ITEMS } */
%token <kw> CSG_KW "CSG keyword"       /* union merge intersection difference: { MEMBERS ITEMS } */
%token <kw> PIGMENT_KW "'pattern' or 'image'"  /* right after diffuse: diffuse pattern { ITEMS } */
/* normal { ITEMS }, spotlight { ITEMS }: apart from ATTR, whose '{' opens a list */
%token <kw> BLOCK_ATTR "'normal' or 'spotlight'"
%token <kw> ARGS_ATTR "'area'"         /* area { ARGS ITEMS }: a block attribute with positional arguments */
%token <kw> MATERIAL "'material'" MESH "'mesh'" SAMPLES "'samples'" MAX_DEPTH "'max_depth'"
%token <kw> LET "'let'" INCLUDE "'include'" FOR "'for'" IN "'in'"
%token DOTDOT "'..'"
%token IF "'if'" ELSE "'else'" DEF "'def'" AND "'and'" OR "'or'" NOT "'not'"
%token <num> BOOL "'true' or 'false'"
%token EQ "'=='" NE "'!='" LT "'<' comparison" GT "'>' comparison" LE "'<='" GE "'>='"
%token BAD "invalid character"   /* the lexer has reported it; the parser only recovers */

%type <node> stmt object member expr vexpr postfix primary arg item attr_item if_stmt if_member def mesh_file
%type <name> name binder
%type <list> stmts items members args opt_args call_args params else_stmts else_members
%type <block> items_block args_block mesh_block list_block csg_block

/* An attribute followed by an identifier takes it as its value (`material glass`,
 * `pattern grid`) rather than ending with no value: shift, by this precedence. */
%precedence NAME_VALUE
%precedence NO_ARGS
%precedence IDENT
%precedence '('
%right '?' ':'
%left OR
%left AND
%precedence NOT
%left EQ NE LT GT LE GE
%left '+' '-'
%left '*' '/'
%precedence NEG

%%

scene:
	stmts                               { ctx->stmts = $1; }
;
stmts:
	%empty                              { $$ = no_list; }
|	stmts stmt                          { $$ = $1; if (!statement(ctx, &$$, $2, FILE_LEVEL)) YYABORT; }
;
stmt:
	object
|	LET binder '=' expr                 { $$ = ast_let(A, @$, $2, @2, $4); }
|	LET binder '=' error                { $$ = ast_let(A, @$, $2, @2, ast_new(A, AST_ERROR, @4)); } /* still binds */
|	INCLUDE STRING                      { $$ = $2.text ? ast_include(A, @$, $2.text, @2) : NULL; }
|	FOR IDENT IN expr DOTDOT expr '{' stmts '}'
	                                    { $$ = ast_for(A, @$, $2, @2, $4, $6, $8); }
|	FOR IDENT IN expr '{' stmts '}'     { $$ = ast_for(A, @$, $2, @2, $4, NULL, $6); }
|	FOR IDENT error '{' stmts '}'       { $$ = ast_for(A, @$, $2, @2, ast_new(A, AST_ERROR, @3),
	                                                   ast_new(A, AST_ERROR, @3), $5); } /* still binds */
|	if_stmt
|	def
|	IDENT '(' ')'                       { $$ = ast_macro_call(A, @$, $1, @1, no_list); }
|	IDENT '(' call_args ')'             { $$ = ast_macro_call(A, @$, $1, @1, $3); }
|	MATERIAL binder items_block         { $$ = ast_block_stmt(A, @$, $1, @1, $3, NULL);
	                                      $$->u.stmt.name = $2; $$->u.stmt.name_span = @2; }
|	ITEMS_KW items_block                { $$ = ast_block_stmt(A, @$, $1, @1, $2, NULL); }
|	SAMPLES items_block                 { $$ = ast_block_stmt(A, @$, $1, @1, $2, NULL); }
|	SAMPLES expr                        { $$ = ast_block_stmt(A, @$, $1, @1, NULL, $2); }
|	MAX_DEPTH expr                      { $$ = ast_block_stmt(A, @$, $1, @1, NULL, $2); }
|	IDENT soup_block                    { $$ = ast_item(A, @$, -1, $1, @1, no_list, NULL); $$->kind = AST_UNKNOWN_STMT; }
|	name opt_args                       { $$ = ast_item(A, @$, -1, $1, @1, $2, NULL); $$->kind = AST_UNKNOWN_STMT; }
|	error                               { $$ = NULL; }
;
if_stmt:
	IF expr '{' stmts '}' else_stmts    { $$ = ast_if(A, @$, $2, $4, $6); }
|	IF error '{' stmts '}' else_stmts   { $$ = ast_if(A, @$, ast_new(A, AST_ERROR, @2), $4, $6); } /* its body still read */
;
else_stmts:
	%empty                              { $$ = no_list; }
|	ELSE '{' stmts '}'                  { $$ = $3; }
|	ELSE if_stmt                        { $$ = list1(ctx, $2); }
;
/* A definition: a function (= EXPR) or a macro ({ STATEMENTS }). */
def:
	DEF binder '(' params ')' '=' expr  { $$ = ast_def(A, @$, $2, @2, $4, $7, no_list); }
|	DEF binder '(' params ')' '=' error { $$ = ast_def(A, @$, $2, @2, $4, ast_new(A, AST_ERROR, @7), no_list); }
|	DEF binder '(' params ')' '{' stmts '}'
	                                    { $$ = ast_def(A, @$, $2, @2, $4, NULL, $7); }
;
params:
	%empty                              { $$ = no_list; }
|	IDENT                               { $$ = list1(ctx, ast_ident(A, @1, $1)); }
|	params ',' IDENT                    { $$ = append(ctx, $1, ast_ident(A, @3, $3)); }
;
object:
	ARGS_KW args_block                  { $$ = ast_block_stmt(A, @$, $1, @1, $2, NULL); }
|	MESH mesh_block                     { $$ = ast_block_stmt(A, @$, $1, @1, $2, NULL); }
|	CSG_KW csg_block                    { $$ = ast_block_stmt(A, @$, $1, @1, $2, NULL); }
;

/* A CSG block, and the body of a for loop in one: members (objects, for loops) and items
 * in any order. The other statements are read as they are elsewhere, for check.c to say
 * what a CSG holds; an unknown name is a statement, which check.c may read as a misspelt
 * attribute or object. An error skips to the next member or item, or to the '}'; a block
 * that comes next is skipped whole, its inner '}' with it. */
csg_block:
	'{' members '}'                     { $$ = ast_csg_block(A, @1, $2); }
;
members:
	%empty                              { $$ = no_list; }
|	members member                      { $$ = append(ctx, $1, $2); }
;
member:
	object
|	attr_item
|	FOR IDENT IN expr DOTDOT expr '{' members '}'
	                                    { $$ = ast_for(A, @$, $2, @2, $4, $6, $8); }
|	FOR IDENT IN expr '{' members '}'   { $$ = ast_for(A, @$, $2, @2, $4, NULL, $6); }
|	FOR IDENT error '{' members '}'     { $$ = ast_for(A, @$, $2, @2, ast_new(A, AST_ERROR, @3),
	                                                   ast_new(A, AST_ERROR, @3), $5); }
|	if_member
|	def
|	IDENT '(' ')'                       { $$ = ast_macro_call(A, @$, $1, @1, no_list); }
|	IDENT '(' call_args ')'             { $$ = ast_macro_call(A, @$, $1, @1, $3); }
|	LET binder '=' expr                 { $$ = ast_let(A, @$, $2, @2, $4); }
|	LET binder '=' error                { $$ = ast_let(A, @$, $2, @2, ast_new(A, AST_ERROR, @4)); }
|	INCLUDE STRING                      { $$ = $2.text ? ast_include(A, @$, $2.text, @2) : NULL; }
|	MATERIAL IDENT items_block          { $$ = ast_block_stmt(A, @$, $1, @1, $3, NULL);
	                                      $$->u.stmt.name = $2; $$->u.stmt.name_span = @2; }
|	ITEMS_KW items_block                { $$ = ast_block_stmt(A, @$, $1, @1, $2, NULL); }
|	SAMPLES items_block                 { $$ = ast_block_stmt(A, @$, $1, @1, $2, NULL); }
|	SAMPLES expr                        { $$ = ast_block_stmt(A, @$, $1, @1, NULL, $2); }
|	MAX_DEPTH expr                      { $$ = ast_block_stmt(A, @$, $1, @1, NULL, $2); }
|	IDENT soup_block                    { $$ = ast_item(A, @$, -1, $1, @1, no_list, NULL); $$->kind = AST_UNKNOWN_STMT; }
|	name opt_args                       { $$ = ast_item(A, @$, -1, $1, @1, $2, NULL); $$->kind = AST_UNKNOWN_STMT; }
|	error                               { $$ = ast_new(A, AST_ERROR, @$); } /* the block is broken */
|	error soup_block                    { $$ = ast_new(A, AST_ERROR, @$); } /* skipped whole: not read as members */
;

if_member:
	IF expr '{' members '}' else_members
	                                    { $$ = ast_if(A, @$, $2, $4, $6); }
|	IF error '{' members '}' else_members
	                                    { $$ = ast_if(A, @$, ast_new(A, AST_ERROR, @2), $4, $6); }
;
else_members:
	%empty                              { $$ = no_list; }
|	ELSE '{' members '}'                { $$ = $3; }
|	ELSE if_member                      { $$ = list1(ctx, $2); }
;

/* Recovery: an error inside braces skips to the closing brace. */
items_block:
	'{' items '}'                       { $$ = ast_block(A, @1, no_list, $2); }
|	'{' error '}'                       { $$ = ast_broken_block(A, @1); yyerrok; }
;
args_block:
	'{' args items '}'                  { $$ = ast_block(A, @1, $2, $3); }
|	'{' error '}'                       { $$ = ast_broken_block(A, @1); yyerrok; }
;
/* A mesh's file name: a string expression that starts with a string or a bracket (a
 * name alone reads as an attribute, which check.c takes for the file name when it names
 * a value; a name with more goes in brackets). */
mesh_block:
	items_block
|	'{' mesh_file items '}'             { $$ = ast_block(A, @1, list1(ctx, $2), $3); }
;
mesh_file:
	STRING                              { $$ = string_node(ctx, @1, $1.text, $1.len); }
|	'(' expr ')'                        { $$ = $2; }
|	mesh_file '+' expr                  { $$ = bounded(ctx, ast_binary(A, @$, '+', $1, $3)); }
;
list_block:
	'{' args '}'                        { $$ = ast_block(A, @1, $2, no_list); }
|	'{' error '}'                       { $$ = ast_broken_block(A, @1); yyerrok; }
;

items:
	%empty                              { $$ = no_list; }
|	items item                          { $$ = append(ctx, $1, $2); }
;
item:
	attr_item
|	name opt_args                       { $$ = ast_item(A, @$, -1, $1, @1, $2, NULL); }
|	IDENT soup_block                    { $$ = ast_item(A, @$, -1, $1, @1, no_list, NULL); } /* pigment { ... } */
;
attr_item:
	ATTR opt_args                       { $$ = ast_item(A, @$, $1, NULL, @1, $2, NULL); }
|	ATTR list_block                     { $$ = ast_item(A, @$, $1, NULL, @1, no_list, $2); }
|	MATERIAL opt_args                   { $$ = ast_item(A, @$, $1, NULL, @1, $2, NULL); }
|	MATERIAL items_block                { $$ = ast_item(A, @$, $1, NULL, @1, no_list, $2); }
|	BLOCK_ATTR opt_args                 { $$ = ast_item(A, @$, $1, NULL, @1, $2, NULL); }
|	BLOCK_ATTR items_block              { $$ = ast_item(A, @$, $1, NULL, @1, no_list, $2); }
|	ARGS_ATTR opt_args                  { $$ = ast_item(A, @$, $1, NULL, @1, $2, NULL); }
|	ARGS_ATTR args_block                { $$ = ast_item(A, @$, $1, NULL, @1, no_list, $2); }
	/* diffuse pattern { ... } or image { "FILE" ... }: diffuse's one argument is an item
	 * that holds the block; an image's file comes first, as a mesh's does */
|	ATTR PIGMENT_KW mesh_block          { $$ = ast_item(A, @$, $1, NULL, @1, list1(ctx, ast_item(A, span_join(@2, @3), $2,
	                                      NULL, @2, no_list, $3)), NULL); }
;
name:
	IDENT
|	NAME_VALUE
;
/* The name a let or a material binds. A keyword there is reported, and bound all the
 * same, so that the statement is not lost and the ones after it are read as written. */
binder:
	IDENT
|	ATTR                                { $$ = reserved(ctx, @1); }
|	ITEMS_KW                            { $$ = reserved(ctx, @1); }
|	ARGS_KW                             { $$ = reserved(ctx, @1); }
|	CSG_KW                              { $$ = reserved(ctx, @1); }
|	MATERIAL                            { $$ = reserved(ctx, @1); }
|	BLOCK_ATTR                          { $$ = reserved(ctx, @1); }
|	ARGS_ATTR                           { $$ = reserved(ctx, @1); }
|	MESH                                { $$ = reserved(ctx, @1); }
|	SAMPLES                             { $$ = reserved(ctx, @1); }
|	MAX_DEPTH                           { $$ = reserved(ctx, @1); }
;

/* What an unknown name's braces hold is skipped whole, so that one message names the
 * unknown word (pigment, texture, light_source, a misspelt keyword) and nothing inside
 * it is reported. */
soup_block:
	'{' soup '}'
;
soup:
	%empty
|	soup soup_token
|	soup '{' soup '}'
;
soup_token:
	NUMBER {} | STRING {} | IDENT {} | NAME_VALUE {} | ATTR {} | ITEMS_KW {} | ARGS_KW {} | CSG_KW {}
|	MATERIAL {} | BLOCK_ATTR {} | ARGS_ATTR {} | PIGMENT_KW {} | MESH {} | SAMPLES {} | MAX_DEPTH {} | LET {} | INCLUDE {} | FOR {} | IN {}
|	DOTDOT | BAD | POV_COLOUR | '(' | ')' | '<' | '>' | ',' | '.' | '=' | '+' | '-' | '*' | '/'
|	IF | ELSE | DEF | AND | OR | NOT | BOOL {} | EQ | NE | LT | GT | LE | GE | '?' | ':' | '[' | ']'
;
opt_args:
	%empty %prec NO_ARGS                { $$ = no_list; }
|	args
;
args:
	arg                                 { $$ = list1(ctx, $1); }
|	args ',' arg                        { $$ = append(ctx, $1, $3); }
;
arg:
	expr
;

/* Expressions (LANGUAGE.md 4 and 10). A vector's components (vexpr) are the same less the
 * comparisons, whose '<' and '>' would be the vector's own: there they go in brackets. */
expr:
	expr '+' expr                       { $$ = bounded(ctx, ast_binary(A, @$, '+', $1, $3)); }
|	expr '-' expr                       { $$ = bounded(ctx, ast_binary(A, @$, '-', $1, $3)); }
|	expr '*' expr                       { $$ = bounded(ctx, ast_binary(A, @$, '*', $1, $3)); }
|	expr '/' expr                       { $$ = bounded(ctx, ast_binary(A, @$, '/', $1, $3)); }
|	'-' expr %prec NEG                  { $$ = bounded(ctx, ast_neg(A, @$, $2)); }
|	expr LT expr                        { $$ = compare(ctx, @$, OP_LT, $1, @1, $3, @3); }
|	expr GT expr                        { $$ = compare(ctx, @$, OP_GT, $1, @1, $3, @3); }
|	expr LE expr                        { $$ = compare(ctx, @$, OP_LE, $1, @1, $3, @3); }
|	expr GE expr                        { $$ = compare(ctx, @$, OP_GE, $1, @1, $3, @3); }
|	expr EQ expr                        { $$ = compare(ctx, @$, OP_EQ, $1, @1, $3, @3); }
|	expr NE expr                        { $$ = compare(ctx, @$, OP_NE, $1, @1, $3, @3); }
|	expr AND expr                       { $$ = bounded(ctx, ast_binary(A, @$, OP_AND, $1, $3)); }
|	expr OR expr                        { $$ = bounded(ctx, ast_binary(A, @$, OP_OR, $1, $3)); }
|	NOT expr                            { $$ = bounded(ctx, ast_not(A, @$, $2)); }
|	expr '?' expr ':' expr              { $$ = bounded(ctx, ast_cond(A, @$, $1, $3, $5)); }
|	postfix
;
vexpr:
	vexpr '+' vexpr                     { $$ = bounded(ctx, ast_binary(A, @$, '+', $1, $3)); }
|	vexpr '-' vexpr                     { $$ = bounded(ctx, ast_binary(A, @$, '-', $1, $3)); }
|	vexpr '*' vexpr                     { $$ = bounded(ctx, ast_binary(A, @$, '*', $1, $3)); }
|	vexpr '/' vexpr                     { $$ = bounded(ctx, ast_binary(A, @$, '/', $1, $3)); }
|	'-' vexpr %prec NEG                 { $$ = bounded(ctx, ast_neg(A, @$, $2)); }
|	vexpr AND vexpr                     { $$ = bounded(ctx, ast_binary(A, @$, OP_AND, $1, $3)); }
|	vexpr OR vexpr                      { $$ = bounded(ctx, ast_binary(A, @$, OP_OR, $1, $3)); }
|	NOT vexpr                           { $$ = bounded(ctx, ast_not(A, @$, $2)); }
|	vexpr '?' vexpr ':' vexpr           { $$ = bounded(ctx, ast_cond(A, @$, $1, $3, $5)); }
|	postfix
;
postfix:
	primary
|	postfix '.' name                    { $$ = bounded(ctx, ast_member(A, @$, $1, $3, @3)); }
|	postfix '[' expr ']'                { $$ = bounded(ctx, ast_index(A, @$, $1, $3)); }
;
primary:
	NUMBER                              { $$ = isnan($1) ? ast_new(A, AST_ERROR, @$) : ast_num(A, @$, $1); }
|	STRING                              { $$ = string_node(ctx, @$, $1.text, $1.len); }
|	BOOL                                { $$ = ast_bool(A, @$, $1 != 0); }
|	name                                { $$ = ast_ident(A, @$, $1); }
|	IDENT '(' ')'                       { $$ = ast_call(A, @$, $1, @1, no_list); }
|	IDENT '(' call_args ')'             { $$ = bounded(ctx, ast_call(A, @$, $1, @1, $3)); }
|	'(' expr ')'                        { $$ = $2; }
|	'<' vexpr ',' vexpr ',' vexpr '>'   { $$ = bounded(ctx, ast_vec(A, @$, $2, $4, $6)); }
|	'<' vexpr ',' vexpr '>'             { $$ = not_a_vector(ctx, @$); }
|	'<' vexpr '>'                       { $$ = not_a_vector(ctx, @$); }
|	'[' ']'                             { $$ = ast_array(A, @$, no_list); }
|	'[' call_args ']'                   { $$ = bounded(ctx, ast_array(A, @$, $2)); }
|	POV_COLOUR primary                  { $$ = $2; diag_error(ctx->diag, @1, "'%.*s' is POV-Ray's; an scn colour is a plain vector, like <1, 0.5, 0>",
	                                      (int)(@1.end - @1.start), ctx->src->text + (@1.start - ctx->src->base)); }
;
call_args:
	expr                                { $$ = list1(ctx, $1); }
|	call_args ',' expr                  { $$ = append(ctx, $1, $3); }
;

%%

/* A string token's node; a string with a bad escape (text NULL) was reported already. */
static struct ast *string_node(struct lang_ctx *ctx, struct span sp, char *text, size_t len)
{
	return text ? ast_str(ctx->arena, sp, text, len) : ast_new(ctx->arena, AST_ERROR, sp);
}

static struct span span_join(struct span a, struct span b)
{
	return (struct span){ a.start, b.end };
}

static char *reserved(struct lang_ctx *ctx, struct span sp)
{
	char *word = arena_strndup(ctx->text, ctx->src->text + (sp.start - ctx->src->base), sp.end - sp.start);
	diag_error(ctx->diag, sp, "'%s' is a reserved word; it cannot be a name", word);
	return word;
}

/* A '<' ... '>' of fewer than three components; when an operand follows its '>', most
 * likely a comparison inside a vector closed it. */
static struct ast *not_a_vector(struct lang_ctx *ctx, struct span sp)
{
	const char *p = ctx->src->text + (sp.end - ctx->src->base), *end = ctx->src->text + ctx->src->len;
	while (p < end && (*p == ' ' || *p == '\t'))
		p++;
	bool operand = p < end && (isalnum((unsigned char)*p) || *p == '_' || *p == '(' || *p == '.');
	diag_error(ctx->diag, sp, "a vector has three components: <x, y, z>%s",
	           operand ? " (inside < > a comparison goes in brackets: <(a > b) ? 1 : 0, 0, 0>)" : "");
	return ast_new(ctx->arena, AST_ERROR, sp);
}

/* A comparison. Comparisons do not chain: a < b < c would compare a boolean. An operand
 * that is a comparison is one only when its span is the operand's whole text, which
 * brackets around it would widen. */
static struct ast *compare(struct lang_ctx *ctx, struct span sp, char op, struct ast *l, struct span lsp,
                           struct ast *r, struct span rsp)
{
	(void)r;
	(void)rsp;
	bool chained = l->kind == AST_BINARY && strchr("<>lg=!", l->u.bin.op) && l->span.start == lsp.start &&
	               l->span.end == lsp.end;
	if (chained) {
		diag_error(ctx->diag, sp, "comparisons do not chain: write a < b and b < c");
		return ast_new(ctx->arena, AST_ERROR, sp);
	}
	return bounded(ctx, ast_binary(ctx->arena, sp, op, l, r));
}

static struct ast_list list1(struct lang_ctx *ctx, struct ast *e)
{
	struct ast_list l = no_list;
	ast_list_push(ctx->arena, &l, e);
	return l;
}

static struct ast_list append(struct lang_ctx *ctx, struct ast_list l, struct ast *e)
{
	ast_list_push(ctx->arena, &l, e);
	return l;
}

/* A statement goes on the list, or, when it is the file's and they are handed on, to
 * ctx->each and is then released (but a definition). Nothing the parser still holds is in the node arena
 * then: the statements before it went the same way, and a lookahead token's text is in
 * the text arena. Returns false to stop the parse. */
static bool statement(struct lang_ctx *ctx, struct ast_list *list, struct ast *stmt, bool file_level)
{
	if (!ctx->each || !file_level) {
		ast_list_push(ctx->arena, list, stmt);
		if (file_level) /* so far: a block left open at the end of the file ends the parse
		                 * (YYABORT) before the file's list is reduced */
			ctx->stmts = *list;
		return true;
	}
	bool go_on = ctx->each(ctx->each_arg, stmt);
	/* a definition's tree runs at each call, to the end of the file; an include's holds
	 * the definitions of its file */
	if (stmt && (stmt->kind == AST_DEF || stmt->kind == AST_INCLUDE))
		arena_keep(ctx->arena);
	else
		arena_reset(ctx->arena);
	return go_on;
}

/* Long operator chains nest without brackets; evaluation recurses on them, so they
 * obey the same bound as brackets. */
static struct ast *bounded(struct lang_ctx *ctx, struct ast *e)
{
	if (e->depth <= LANG_MAX_NESTING)
		return e;
	if (!ctx->too_deep) /* once: the expressions around this one would say it again */
		diag_error(ctx->diag, e->span, "expression nested more than %d deep", LANG_MAX_NESTING);
	ctx->too_deep = true;
	return ast_new(ctx->arena, AST_ERROR, e->span);
}

/* How an expected token is named in a message, or NULL to leave it out: the classes
 * that start a value or an attribute are named once, and operators are left out (an
 * operator is seldom what is missing). */
static const char *expected_name(yysymbol_kind_t k, bool value, bool attribute)
{
	switch (k) {
	case YYSYMBOL_NUMBER: return value ? "a value" : "a number";
	case YYSYMBOL_ATTR: return "an attribute";
	case YYSYMBOL_IDENT: case YYSYMBOL_NAME_VALUE: return value || attribute ? NULL : "a name";
	case YYSYMBOL_MATERIAL: return attribute ? NULL : "'material'";
	case YYSYMBOL_BLOCK_ATTR: return attribute ? NULL : "'normal' or 'spotlight'";
	case YYSYMBOL_ARGS_ATTR: return attribute ? NULL : "'area'";
	case YYSYMBOL_PIGMENT_KW: return NULL; /* only ever after diffuse, where a value is due */
	case YYSYMBOL_STRING: return value ? NULL : "a string"; /* a string where a value may stand is rare */
	case YYSYMBOL_POV_COLOUR: case YYSYMBOL_BAD: return NULL;
	case YYSYMBOL_LT: case YYSYMBOL_GT: case YYSYMBOL_LE: case YYSYMBOL_GE: case YYSYMBOL_EQ: case YYSYMBOL_NE:
	case YYSYMBOL_AND: case YYSYMBOL_OR: case YYSYMBOL_NOT: case YYSYMBOL_BOOL: return NULL;
	default: break;
	}
	const char *name = yysymbol_name(k);
	if (strlen(name) == 3 && name[0] == '\'') {
		if (strchr("+-*/.(<[?", name[1]))
			return NULL;
	}
	return name;
}

/* "unexpected 'x'; expected A, B or C", and a note at the bracket left open when the
 * parser wanted its closer. A BAD token was reported by the lexer already. */
/* Whether the word right before the brace at brace (blanks between) is kw. */
static bool brace_of(const struct lang_ctx *ctx, struct span brace, const char *kw)
{
	const char *text = ctx->src->text;
	uint32_t i = brace.start - ctx->src->base;
	while (i > 0 && strchr(" \t\r\n", text[i - 1]))
		i--;
	uint32_t word = i;
	while (word > 0 && (isalnum((unsigned char)text[word - 1]) || text[word - 1] == '_'))
		word--;
	return i - word == strlen(kw) && memcmp(text + word, kw, i - word) == 0;
}

/* POV-Ray's light_source { <0, 5, 0> ... } as scn's light { <0, 5, 0> }: the hint, in buf,
 * for the vector at vec that opens the block at brace. */
static void light_position_hint(const struct lang_ctx *ctx, struct span brace, struct span vec, char *buf, size_t size)
{
	const char *text = ctx->src->text;
	uint32_t open = brace.start - ctx->src->base, at = vec.start - ctx->src->base;
	bool first = true;
	for (uint32_t j = open + 1; j < at; j++)
		first &= strchr(" \t\r\n", text[j]) != NULL;
	if (!first || !brace_of(ctx, brace, "light"))
		return;
	uint32_t end = at;
	while (end < ctx->src->len && end - at < 60 && text[end] != '>' && text[end] >= ' ' && text[end] < 0x7f)
		end++;
	if (end < ctx->src->len && text[end] == '>')
		snprintf(buf, size, " (POV-Ray's light_source starts with its position; scn writes position %.*s)",
		         (int)(end + 1 - at), text + at);
	else
		snprintf(buf, size, " (POV-Ray's light_source starts with its position; scn writes position <x, y, z>)");
}

/* The note on the bracket left open, open[k]; for a '{', the innermost one by the
 * indentation when a '}' indented for it closed a '{' inside it instead (lang_ctx.misfit),
 * as that is where a '}' is missing, however far from the end. */
static void note_unclosed(struct lang_ctx *ctx, unsigned k)
{
	char open = ctx->open[k].ch;
	if (open != '{' || !ctx->misfit.seen || ctx->misfit.outer.start != ctx->open[k].sp.start) {
		diag_note(ctx->diag, ctx->open[k].sp, "to match this '%c'", open);
		return;
	}
	unsigned inner_line, outer_line, col;
	diag_line_col(ctx->diag, ctx->misfit.inner.start, &inner_line, &col);
	diag_line_col(ctx->diag, ctx->misfit.meant.start, &outer_line, &col);
	diag_note(ctx->diag, ctx->misfit.inner, "to match this '{'");
	diag_note(ctx->diag, ctx->misfit.closer, "this '}', indented as line %u is, was read as closing line %u's '{'",
	          outer_line, inner_line);
}

/* Whether the token at `at` is an operator right after a name: name + ... where a block
 * takes attributes, which read the name as one. */
static bool after_name(const struct lang_ctx *ctx, struct span at)
{
	const char *text = ctx->src->text, *p = text + (at.start - ctx->src->base);
	if (!strchr("+-*/[.?", *p))
		return false;
	while (p > text && (p[-1] == ' ' || p[-1] == '\t'))
		p--;
	return p > text && (isalnum((unsigned char)p[-1]) || p[-1] == '_');
}

static int yyreport_syntax_error(const yypcontext_t *pc, yyscan_t scanner, struct lang_ctx *ctx)
{
	(void)scanner;
	yysymbol_kind_t got = yypcontext_token(pc);
	if (ctx->abort || got == YYSYMBOL_BAD)
		return 0;
	enum { MAX_LISTED = 5 };
	yysymbol_kind_t expected[YYNTOKENS];
	int n = yypcontext_expected_tokens(pc, expected, YYNTOKENS);
	struct span at = *yypcontext_location(pc);

	char what[96];
	if (got == YYSYMBOL_YYEOF) {
		snprintf(what, sizeof what, "end of file");
	} else {
		const char *text = ctx->src->text + (at.start - ctx->src->base);
		int len = (int)(at.end - at.start);
		const char *kind = got == YYSYMBOL_NUMBER ? "number " : got == YYSYMBOL_IDENT || got == YYSYMBOL_NAME_VALUE
		                 ? "name " : got == YYSYMBOL_STRING ? "string " : "";
		snprintf(what, sizeof what, "%s'%.*s%s'", kind, len > 40 ? 40 : len, text, len > 40 ? "..." : "");
	}

	bool statement = false, value = false, attribute = false, name = false;
	for (int i = 0; i < n; i++) {
		statement |= expected[i] == YYSYMBOL_LET;
		value |= expected[i] == YYSYMBOL_NUMBER;
		attribute |= expected[i] == YYSYMBOL_ATTR;
		name |= expected[i] == YYSYMBOL_IDENT;
	}
	bool keyword = got == YYSYMBOL_ATTR || got == YYSYMBOL_ITEMS_KW || got == YYSYMBOL_ARGS_KW || got == YYSYMBOL_CSG_KW
	            || got == YYSYMBOL_MATERIAL || got == YYSYMBOL_BLOCK_ATTR || got == YYSYMBOL_ARGS_ATTR || got == YYSYMBOL_PIGMENT_KW
	            || got == YYSYMBOL_MESH || got == YYSYMBOL_SAMPLES || got == YYSYMBOL_MAX_DEPTH || got == YYSYMBOL_LET
	            || got == YYSYMBOL_INCLUDE || got == YYSYMBOL_FOR || got == YYSYMBOL_IN || got == YYSYMBOL_IF
	            || got == YYSYMBOL_ELSE || got == YYSYMBOL_DEF || got == YYSYMBOL_AND || got == YYSYMBOL_OR
	            || got == YYSYMBOL_NOT || got == YYSYMBOL_BOOL;
	if (keyword && name && !value && !attribute) { /* let count = 3: a new name was wanted */
		diag_error(ctx->diag, at, "%s is a reserved word; it cannot be a name", what);
		return 0;
	}
	const char *names[YYNTOKENS];
	int m = 0;
	for (int i = 0; i < n; i++) {
		const char *listed = expected_name(expected[i], value, attribute);
		bool dup = false;
		for (int j = 0; j < m && listed; j++)
			dup |= strcmp(names[j], listed) == 0;
		if (listed && !dup)
			names[m++] = listed;
	}
	char list[512] = "";
	if (statement && attribute) { /* in a CSG block */
		snprintf(list, sizeof list, "; expected an object or an attribute");
	} else if (statement) {
		snprintf(list, sizeof list, "; expected a statement");
	} else if (m > 0 && m <= MAX_LISTED) {
		size_t used = 0;
		for (int i = 0; i < m && used < sizeof list; i++)
			used += (size_t)snprintf(list + used, sizeof list - used, "%s%s",
			                         i == 0 ? "; expected " : i == m - 1 ? " or " : ", ", names[i]);
	}
	/* The innermost bracket open before the error. (The lexer has already pushed an
	 * unexpected opener.) */
	unsigned k = ctx->nopen;
	while (k > 0 && ctx->open[k - 1].sp.start >= at.start)
		k--;
	char hint[160] = "";
	bool comparison = got == YYSYMBOL_LT || got == YYSYMBOL_GT || got == YYSYMBOL_LE || got == YYSYMBOL_GE ||
	                  got == YYSYMBOL_EQ || got == YYSYMBOL_NE;
	if (k > 0 && strcmp(yysymbol_name(got), "'<'") == 0)
		light_position_hint(ctx, ctx->open[k - 1].sp, at, hint, sizeof hint);
	else if (k > 0 && comparison && ctx->open[k - 1].ch == '<')
		snprintf(hint, sizeof hint, " (inside < > a comparison goes in brackets: <(a > b) ? 1 : 0, 0, 0>)");
	else if (k > 0 && ctx->open[k - 1].ch == '{' && value && !attribute && brace_of(ctx, ctx->open[k - 1].sp, "area"))
		snprintf(hint, sizeof hint, " (an area starts with its four values, then its flags: "
		         "area { AXIS1, AXIS2, N1, N2 [jitter] [circular] [orient] })");
	else if (k > 0 && ctx->open[k - 1].ch == '{' && attribute && after_name(ctx, at))
		snprintf(hint, sizeof hint, " (in a block, a value that starts with a name and goes on goes in brackets: "
		         "mesh { (name + \".obj\") })");
	diag_error(ctx->diag, at, "unexpected %s%s%s", what, list, hint);

	/* The note names that bracket when its closer was expected and what came instead
	 * looks like what follows a missing closer: the end, a statement, another closer. */
	const char *got_name = yysymbol_name(got);
	bool missing = got == YYSYMBOL_YYEOF || got == YYSYMBOL_LET || got == YYSYMBOL_INCLUDE || got == YYSYMBOL_FOR
	            || got == YYSYMBOL_IF || got == YYSYMBOL_DEF
	            || got == YYSYMBOL_ITEMS_KW || got == YYSYMBOL_ARGS_KW || got == YYSYMBOL_CSG_KW || got == YYSYMBOL_MESH
	            || got == YYSYMBOL_SAMPLES || got == YYSYMBOL_MAX_DEPTH
	            || strcmp(got_name, "'}'") == 0 || strcmp(got_name, "')'") == 0 || strcmp(got_name, "'>'") == 0
	            || strcmp(got_name, "']'") == 0;
	if (k > 0 && missing) {
		char open = ctx->open[k - 1].ch;
		char closer[4] = { '\'', open == '{' ? '}' : open == '(' ? ')' : open == '[' ? ']' : '>', '\'', '\0' };
		for (int i = 0; i < n; i++)
			if (strcmp(yysymbol_name(expected[i]), closer) == 0) {
				note_unclosed(ctx, k - 1);
				break;
			}
	}
	return 0;
}

/* Bison's own failure: "memory exhausted" when its stack would pass YYMAXDEPTH (10000).
 * Brackets stop at 1000 deep and each holds fewer than ten symbols that are not
 * operators, so only a run of pending operators (`- - - - 1`, thousands long) gets
 * there, and that is an expression nested deeper than the limit. */
static void yyerror(YYLTYPE *loc, yyscan_t scanner, struct lang_ctx *ctx, const char *msg)
{
	(void)scanner;
	if (strcmp(msg, "memory exhausted") == 0)
		diag_error(ctx->diag, *loc, "expression nested more than %d deep", LANG_MAX_NESTING);
	else
		diag_error(ctx->diag, *loc, "%s", msg);
}
