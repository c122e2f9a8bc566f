/* ast.c: constructors for syntax tree nodes; the grammar's actions call nothing else. */
#include "ast.h"

#include <string.h>

#include "arena.h"

void ast_list_push(struct arena *a, struct ast_list *l, struct ast *node)
{
	if (!node)
		return;
	if (l->n == l->cap) {
		/* the old array stays in the arena: amortised, a list costs at most twice its
		 * size; most lists hold one or two nodes */
		uint32_t cap = l->cap ? 2 * l->cap : 1;
		struct ast **v = arena_alloc(a, cap * sizeof *v);
		if (l->n)
			memcpy(v, l->v, l->n * sizeof *v);
		l->v = v;
		l->cap = cap;
	}
	l->v[l->n++] = node;
}

/* The bytes a node of each kind needs: the header and its member of the union. */
#define NODE_SIZE(member) (offsetof(struct ast, u) + sizeof(((struct ast *)0)->u.member))
static const size_t node_size[] = {
	[AST_NUM] = NODE_SIZE(num), [AST_STR] = NODE_SIZE(str), [AST_VEC] = NODE_SIZE(vec),
	[AST_IDENT] = NODE_SIZE(ident), [AST_NEG] = NODE_SIZE(bin), [AST_BINARY] = NODE_SIZE(bin),
	[AST_CALL] = NODE_SIZE(call), [AST_MEMBER] = NODE_SIZE(member), [AST_ERROR] = offsetof(struct ast, u),
	[AST_BOOL] = NODE_SIZE(truth), [AST_ARRAY] = NODE_SIZE(elems), [AST_INDEX] = NODE_SIZE(bin),
	[AST_NOT] = NODE_SIZE(bin), [AST_COND] = NODE_SIZE(cond),
	[AST_LET] = NODE_SIZE(let), [AST_INCLUDE] = NODE_SIZE(include), [AST_FOR] = NODE_SIZE(loop),
	[AST_IF] = NODE_SIZE(cond_stmt), [AST_DEF] = NODE_SIZE(def), [AST_MACRO_CALL] = NODE_SIZE(call),
	[AST_BLOCK_STMT] = NODE_SIZE(stmt), [AST_UNKNOWN_STMT] = NODE_SIZE(item), [AST_ITEM] = NODE_SIZE(item),
};

struct ast *ast_new(struct arena *a, enum ast_kind kind, struct span sp)
{
	struct ast *n = arena_alloc(a, node_size[kind]);
	n->kind = kind;
	n->span = sp;
	n->depth = 1;
	return n;
}

static unsigned deeper(const struct ast *e, unsigned d)
{
	return e && e->depth + 1u > d ? e->depth + 1u : d;
}

struct ast *ast_num(struct arena *a, struct span sp, double v)
{
	struct ast *n = ast_new(a, AST_NUM, sp);
	n->u.num = v;
	return n;
}

struct ast *ast_str(struct arena *a, struct span sp, char *text, size_t len)
{
	struct ast *n = ast_new(a, AST_STR, sp);
	n->u.str.text = text;
	n->u.str.len = len;
	return n;
}

struct ast *ast_vec(struct arena *a, struct span sp, struct ast *x, struct ast *y, struct ast *z)
{
	struct ast *n = ast_new(a, AST_VEC, sp);
	n->u.vec[0] = x;
	n->u.vec[1] = y;
	n->u.vec[2] = z;
	n->depth = deeper(z, deeper(y, deeper(x, 1)));
	return n;
}

struct ast *ast_ident(struct arena *a, struct span sp, char *name)
{
	struct ast *n = ast_new(a, AST_IDENT, sp);
	n->u.ident.name = name;
	n->u.ident.builtin = -1;
	return n;
}

struct ast *ast_neg(struct arena *a, struct span sp, struct ast *e)
{
	struct ast *n = ast_new(a, AST_NEG, sp);
	n->u.bin.op = '-';
	n->u.bin.l = e;
	n->depth = deeper(e, 1);
	return n;
}

struct ast *ast_binary(struct arena *a, struct span sp, char op, struct ast *l, struct ast *r)
{
	struct ast *n = ast_new(a, AST_BINARY, sp);
	n->u.bin.op = op;
	n->u.bin.l = l;
	n->u.bin.r = r;
	n->depth = deeper(r, deeper(l, 1));
	return n;
}

struct ast *ast_call(struct arena *a, struct span sp, char *name, struct span name_span,
                     struct ast_list args)
{
	struct ast *n = ast_new(a, AST_CALL, sp);
	n->u.call.name = name;
	n->u.call.name_span = name_span;
	n->u.call.args = args;
	n->u.call.fn = -1;
	for (size_t i = 0; i < args.n; i++)
		n->depth = deeper(args.v[i], n->depth);
	return n;
}

struct ast *ast_member(struct arena *a, struct span sp, struct ast *e, char *name, struct span comp_span)
{
	struct ast *n = ast_new(a, AST_MEMBER, sp);
	n->u.member.e = e;
	n->u.member.name = name;
	n->u.member.comp_span = comp_span;
	n->u.member.comp = -1;
	n->depth = deeper(e, 1);
	return n;
}

struct ast *ast_bool(struct arena *a, struct span sp, bool truth)
{
	struct ast *n = ast_new(a, AST_BOOL, sp);
	n->u.truth = truth;
	return n;
}

struct ast *ast_array(struct arena *a, struct span sp, struct ast_list elems)
{
	struct ast *n = ast_new(a, AST_ARRAY, sp);
	n->u.elems = elems;
	for (size_t i = 0; i < elems.n; i++)
		n->depth = deeper(elems.v[i], n->depth);
	return n;
}

struct ast *ast_index(struct arena *a, struct span sp, struct ast *e, struct ast *index)
{
	struct ast *n = ast_binary(a, sp, '[', e, index);
	n->kind = AST_INDEX;
	return n;
}

struct ast *ast_not(struct arena *a, struct span sp, struct ast *e)
{
	struct ast *n = ast_neg(a, sp, e);
	n->kind = AST_NOT;
	n->u.bin.op = '!';
	return n;
}

struct ast *ast_cond(struct arena *a, struct span sp, struct ast *c, struct ast *x, struct ast *y)
{
	struct ast *n = ast_new(a, AST_COND, sp);
	n->u.cond.c = c;
	n->u.cond.a = x;
	n->u.cond.b = y;
	n->depth = deeper(y, deeper(x, deeper(c, 1)));
	return n;
}

struct ast *ast_if(struct arena *a, struct span sp, struct ast *cond, struct ast_list then, struct ast_list other)
{
	struct ast *n = ast_new(a, AST_IF, sp);
	n->u.cond_stmt.cond = cond;
	n->u.cond_stmt.then = then;
	n->u.cond_stmt.other = other;
	return n;
}

struct ast *ast_def(struct arena *a, struct span sp, char *name, struct span name_span, struct ast_list params,
                    struct ast *value, struct ast_list body)
{
	struct ast *n = ast_new(a, AST_DEF, sp);
	n->u.def.name = name;
	n->u.def.name_span = name_span;
	n->u.def.params = params;
	n->u.def.value = value;
	n->u.def.body = body;
	return n;
}

struct ast *ast_macro_call(struct arena *a, struct span sp, char *name, struct span name_span, struct ast_list args)
{
	struct ast *n = ast_call(a, sp, name, name_span, args);
	n->kind = AST_MACRO_CALL;
	return n;
}

struct ast *ast_let(struct arena *a, struct span sp, char *name, struct span name_span, struct ast *value)
{
	struct ast *n = ast_new(a, AST_LET, sp);
	n->u.let.name = name;
	n->u.let.name_span = name_span;
	n->u.let.value = value;
	return n;
}

struct ast *ast_include(struct arena *a, struct span sp, char *path, struct span path_span)
{
	struct ast *n = ast_new(a, AST_INCLUDE, sp);
	n->u.include.path = path;
	n->u.include.path_span = path_span;
	return n;
}

struct ast *ast_for(struct arena *a, struct span sp, char *var, struct span var_span,
                    struct ast *from, struct ast *to, struct ast_list body)
{
	struct ast *n = ast_new(a, AST_FOR, sp);
	n->u.loop.var = var;
	n->u.loop.var_span = var_span;
	n->u.loop.from = from;
	n->u.loop.to = to;
	n->u.loop.body = body;
	return n;
}

struct ast *ast_block_stmt(struct arena *a, struct span sp, enum kw kw, struct span kw_span,
                           struct ast_block *block, struct ast *value)
{
	struct ast *n = ast_new(a, AST_BLOCK_STMT, sp);
	n->u.stmt.kw = kw;
	n->u.stmt.kw_span = kw_span;
	n->u.stmt.block = block;
	n->u.stmt.value = value;
	return n;
}

struct ast *ast_item(struct arena *a, struct span sp, int kw, char *name, struct span name_span,
                     struct ast_list args, struct ast_block *block)
{
	struct ast *n = ast_new(a, AST_ITEM, sp);
	n->u.item.kw = kw;
	n->u.item.name = name;
	n->u.item.name_span = name_span;
	n->u.item.args = args;
	n->u.item.block = block;
	return n;
}

struct ast_block *ast_block(struct arena *a, struct span open, struct ast_list args, struct ast_list items)
{
	struct ast_block *b = arena_alloc(a, sizeof *b);
	b->open = open;
	b->args = args;
	b->items = items;
	return b;
}

struct ast_block *ast_csg_block(struct arena *a, struct span open, struct ast_list elements)
{
	struct ast_list none = { 0 };
	struct ast_block *b = ast_block(a, open, none, none);
	for (uint32_t i = 0; i < elements.n; i++) {
		struct ast *e = elements.v[i];
		ast_list_push(a, e->kind == AST_ITEM ? &b->items : &b->members, e);
		b->broken |= e->kind == AST_ERROR;
	}
	return b;
}

struct ast_block *ast_broken_block(struct arena *a, struct span open)
{
	struct ast_list none = { 0 };
	struct ast_block *b = ast_block(a, open, none, none);
	b->broken = true;
	return b;
}
