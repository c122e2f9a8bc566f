/* check_solid.c: which objects have an inside (LANGUAGE.md section 9), as their text says:
 * for 'inverse', and for the members of intersection, difference and merge, which take
 * solids only. A for loop counts by its body, whether or not it runs. */
#include "check_internal.h"

#include <stdio.h>

static bool has_item(const struct ast_block *block, enum kw kw)
{
	for (size_t i = 0; i < block->items.n; i++)
		if (block->items.v[i]->u.item.kw == (int)kw)
			return true;
	return false;
}

static bool solid_list(const struct ast_list *members, struct no_inside *why);

bool solid_statement(const struct ast *s, struct no_inside *why)
{
	if (s->kind == AST_FOR)
		return solid_list(&s->u.loop.body, why);
	if (s->kind != AST_BLOCK_STMT || !s->u.stmt.block || s->u.stmt.block->broken)
		return true;
	const struct ast_block *block = s->u.stmt.block;
	why->at = s;
	switch (s->u.stmt.kw) {
	case KW_TRIANGLE:
		why->why = "a triangle is flat and has no inside";
		why->fix = "for a solid made of triangles, use a mesh with inside_vector";
		return false;
	case KW_DISC:
		why->why = "a disc is flat and has no inside";
		why->fix = "for a thin solid, use a cylinder";
		return false;
	case KW_CYLINDER: case KW_CONE:
		why->why = s->u.stmt.kw == KW_CYLINDER ? "an open cylinder has no inside" : "an open cone has no inside";
		why->fix = "remove 'open'";
		return !has_item(block, KW_OPEN);
	case KW_MESH:
		why->why = "a mesh without inside_vector has no inside";
		why->fix = "give it inside_vector <1, 0, 0> (POV-Ray's rule: inside by the parity of crossings along "
		           "that vector)";
		return has_item(block, KW_INSIDE_VECTOR);
	case KW_UNION:
		return solid_list(&block->members, why);
	default: /* sphere, plane, box, torus; merge, intersection and difference, whose members
	          * must be solid; and what is not an object */
		return true;
	}
}

static bool solid_list(const struct ast_list *members, struct no_inside *why)
{
	for (size_t i = 0; i < members->n; i++)
		if (!solid_statement(members->v[i], why))
			return false;
	return true;
}

/* Reports "WHY, so USER cannot ...; FIX" at `at` for object s, which has no inside. */
static void report(struct checker *c, const struct ast *s, struct span at, const struct no_inside *why,
                   const char *cannot)
{
	if (why->at == s) {
		diag_error(c->diag, at, "%s, so %s; %s", why->why, cannot, why->fix);
		return;
	}
	diag_error(c->diag, at, "this %s is not solid (not all its members have an inside), so %s",
	           kw_name(s->u.stmt.kw), cannot);
	diag_note(c->diag, why->at->u.stmt.kw_span, "%s; %s", why->why, why->fix);
}

static void check_members(struct checker *c, const struct ast_list *members, const char *cannot)
{
	for (size_t i = 0; i < members->n; i++) {
		const struct ast *m = members->v[i];
		struct no_inside why;
		if (m->kind == AST_FOR)
			check_members(c, &m->u.loop.body, cannot);
		else if (!solid_statement(m, &why))
			report(c, m, m->u.stmt.kw_span, &why, cannot);
	}
}

void check_solid_members(struct checker *c, const struct ast *csg)
{
	char cannot[64];
	snprintf(cannot, sizeof cannot, "%s cannot use it", kw_name(csg->u.stmt.kw));
	check_members(c, &csg->u.stmt.block->members, cannot);
}

void check_inverse(struct checker *c, const struct ast *s, const struct ast *inverse)
{
	struct no_inside why;
	if (!solid_statement(s, &why))
		report(c, s, inverse->u.item.name_span, &why, "'inverse' cannot apply to it");
}
