/* check_block.c: which attributes each block statement takes (camera, light, material,
 * the objects and CSGs, skybox, samples), the shape of each attribute's value, and the
 * check of a block against them. */
#include "check_internal.h"

#include <string.h>

#include "scene_desc.h"

struct attr_spec {
	unsigned char kw, shape;
	bool repeat;               /* transforms: any number, applied in order */
};

#define TRANSFORMS { KW_TRANSLATE, S_VEC, true }, { KW_ROTATE, S_VEC, true }, { KW_SCALE, S_VEC, true }

static const struct attr_spec camera_attrs[] = {
	{ KW_LOCATION, S_VEC, false }, { KW_LOOK_AT, S_VEC, false }, { KW_UP, S_VEC, false },
	{ KW_FOV, S_NUM, false }, { KW_RESOLUTION, S_INT2, false },
};
static const struct attr_spec light_attrs[] = {
	{ KW_POSITION, S_VEC, false }, { KW_DIRECTION, S_VEC, false }, { KW_COLOR, S_VEC, false },
	{ KW_INTENSITY, S_NUM, false }, { KW_SHADOWLESS, S_FLAG, false },
};
static const struct attr_spec material_attrs[] = {
	{ KW_LIKE, S_LIKE, false }, { KW_DIFFUSE, S_PIGMENT, false }, { KW_SPECULAR, S_VEC, false },
	{ KW_SHININESS, S_NUM, false }, { KW_REFLECT, S_VEC, false }, { KW_TRANSMIT, S_VEC, false },
	{ KW_IOR, S_NUM, false }, { KW_FRESNEL, S_FLAG, false }, { KW_EMIT, S_VEC, false },
};
/* every object takes 'inverse'; check.c says when it has no inside to swap */
static const struct attr_spec shape_attrs[] = {
	{ KW_MATERIAL, S_MATERIAL, false }, TRANSFORMS, { KW_INVERSE, S_FLAG, false },
};
static const struct attr_spec open_shape_attrs[] = {   /* cylinder, cone */
	{ KW_MATERIAL, S_MATERIAL, false }, TRANSFORMS, { KW_INVERSE, S_FLAG, false }, { KW_OPEN, S_FLAG, false },
};
static const struct attr_spec mesh_attrs[] = {
	{ KW_MATERIAL, S_MATERIAL, false }, TRANSFORMS, { KW_INVERSE, S_FLAG, false }, { KW_SMOOTH, S_FLAG, false },
	{ KW_VERTICES, S_LIST, false }, { KW_FACES, S_LIST, false }, { KW_NORMALS, S_LIST, false },
	{ KW_INSIDE_VECTOR, S_VEC, false },
};
static const struct attr_spec skybox_attrs[] = {
	{ KW_COLOR, S_VEC, false }, { KW_ZENITH, S_VEC, false }, { KW_HORIZON, S_VEC, false },
	{ KW_IMAGE, S_STR, false }, { KW_ROTATE, S_NUM, false }, { KW_INTENSITY, S_NUM, false },
};
static const struct attr_spec samples_attrs[] = {
	{ KW_COUNT, S_NUM, false }, { KW_PATTERN, S_PATTERN, false }, { KW_SEED, S_NUM, false },
	{ KW_TARGET_ERROR, S_NUM, false },
};

struct block_spec {
	const char *what;
	const struct attr_spec *attrs;
	size_t nattrs;
	const char *positional;    /* shapes of the positional arguments, as S_ codes + '0' */
	const char *signature;     /* how the positional arguments are written, for messages */
	const char *names[4];      /* what each positional argument is, for messages */
	unsigned optional;         /* how many of the last positional arguments may be left out */
};

#define SPEC(what, attrs, pos, sig, ...) { what, attrs, sizeof attrs / sizeof attrs[0], pos, sig, { __VA_ARGS__ }, 0 }
static const struct block_spec camera_spec = SPEC("camera", camera_attrs, "", NULL, NULL);
static const struct block_spec light_spec = SPEC("light", light_attrs, "", NULL, NULL);
static const struct block_spec material_spec = SPEC("material", material_attrs, "", NULL, NULL);
static const struct block_spec sphere_spec = SPEC("sphere", shape_attrs, "21", "sphere { CENTER, RADIUS ... }",
                                                  "the sphere's center", "the sphere's radius");
static const struct block_spec plane_spec = SPEC("plane", shape_attrs, "21", "plane { NORMAL, OFFSET ... }",
                                                 "the plane's normal", "the plane's offset");
static const struct block_spec triangle_spec = SPEC("triangle", shape_attrs, "222", "triangle { A, B, C ... }",
                                                    "a triangle's corner", "a triangle's corner", "a triangle's corner");
static const struct block_spec box_spec = SPEC("box", shape_attrs, "22", "box { CORNER1, CORNER2 ... }",
                                               "a box's corner", "a box's corner");
static const struct block_spec cylinder_spec = SPEC("cylinder", open_shape_attrs, "221",
                                                    "cylinder { BASE, CAP, RADIUS ... }", "the cylinder's base",
                                                    "the cylinder's cap", "the cylinder's radius");
static const struct block_spec cone_spec = SPEC("cone", open_shape_attrs, "2121",
                                                "cone { BASE, BASE_RADIUS, CAP, CAP_RADIUS ... }", "the cone's base",
                                                "the cone's base radius", "the cone's cap", "the cone's cap radius");
static const struct block_spec disc_spec = {
	"disc", shape_attrs, sizeof shape_attrs / sizeof shape_attrs[0], "2211",
	"disc { CENTER, NORMAL, RADIUS [, HOLE_RADIUS] ... }",
	{ "the disc's center", "the disc's normal", "the disc's radius", "the disc's hole radius" }, 1,
};
static const struct block_spec torus_spec = SPEC("torus", shape_attrs, "11", "torus { MAJOR, MINOR ... }",
                                                 "the torus's major radius", "the torus's minor radius");
static const struct block_spec mesh_spec = SPEC("mesh", mesh_attrs, "", NULL, NULL);
/* a CSG's items; its members are statements, which check.c checks */
static const struct block_spec union_spec = SPEC("union", shape_attrs, "", NULL, NULL);
static const struct block_spec merge_spec = SPEC("merge", shape_attrs, "", NULL, NULL);
static const struct block_spec intersection_spec = SPEC("intersection", shape_attrs, "", NULL, NULL);
static const struct block_spec difference_spec = SPEC("difference", shape_attrs, "", NULL, NULL);
static const struct block_spec skybox_spec = SPEC("skybox", skybox_attrs, "", NULL, NULL);
static const struct block_spec samples_spec = SPEC("samples", samples_attrs, "", NULL, NULL);

static const struct attr_spec *find_attr(const struct block_spec *spec, int kw)
{
	for (size_t i = 0; i < spec->nattrs; i++)
		if (spec->attrs[i].kw == kw)
			return &spec->attrs[i];
	return NULL;
}

const char *item_name(const struct ast *item)
{
	return item->u.item.kw >= 0 ? kw_name(item->u.item.kw) : item->u.item.name;
}

/* Checks one expression against the shape S_NUM or S_VEC (or S_PIGMENT). */
void check_value(struct checker *c, struct ast *e, enum shape shape, const char *attr)
{
	enum ast_type t = check_expr(c, e);
	if (t == TYPE_NONE || t == TYPE_ANY) /* TYPE_ANY: eval.c checks the value */
		return;
	if (shape == S_STR ? t == TYPE_STR
	                   : t == TYPE_NUM || (t == TYPE_VEC && shape != S_NUM) || (t == TYPE_PIGMENT && shape == S_PIGMENT))
		return;
	const char *want = shape == S_NUM ? "a number" : shape == S_STR ? "a string" : "a vector or colour";
	if (t == TYPE_PIGMENT)
		diag_error(c->diag, e->span, "checker(...) can only be the value of diffuse");
	else if (strchr(attr, ' ')) /* a phrase ("the sphere's radius"), not an attribute's name */
		diag_error(c->diag, e->span, "%s must be %s, found %s", attr, want, value_type_name(t));
	else
		diag_error(c->diag, e->span, "'%s' takes %s, found %s", attr, want, value_type_name(t));
}

/* A name argument (material, like, pattern): a lone identifier. */
static struct ast *name_arg(struct checker *c, struct ast *item, const char *what)
{
	struct ast_list *args = &item->u.item.args;
	if (args->n > 1 && args->v[0]->kind == AST_IDENT) {
		diag_error(c->diag, args->v[1]->span, "'%s' takes one name", item_name(item));
		return NULL;
	}
	if (args->n == 1 && args->v[0]->kind == AST_IDENT)
		return args->v[0];
	diag_error(c->diag, args->n ? args->v[0]->span : item->u.item.name_span, "'%s' takes the name of %s",
	           item_name(item), what);
	return NULL;
}

/* material NAME, like NAME: a material's name, or a value that holds one (a parameter, a
 * binding, an array's element through a loop), which eval.c checks when it is known only
 * there. */
static void check_material_ref(struct checker *c, struct ast *id)
{
	const char *name = id->u.ident.name;
	struct binding *b = names_lookup(c, name);
	enum ast_type t = b && names_class(b->kind) == NAMES_VALUES ? b->type : TYPE_NONE;
	if (b && (b->kind == BIND_MATERIAL || t == TYPE_MATERIAL || t == TYPE_ANY)) {
		b->used = true;
		id->u.ident.ref = b;
		c->tainted |= b->failed;
		id->type = b->kind == BIND_MATERIAL ? TYPE_MATERIAL : t;
		return;
	}
	c->tainted = true; /* also when unknown_name says nothing (a name an unread include may define) */
	if (b) {
		diag_error(c->diag, id->span, "'%s' is not a material", name);
		return;
	}
	unknown_name(c, id->span, name, NAMES_MATERIALS);
}

static void check_pattern(struct checker *c, struct ast *id)
{
	for (int p = 0; p < PATTERN_COUNT; p++)
		if (strcmp(id->u.ident.name, scene_desc_pattern_name(p)) == 0) {
			id->u.ident.builtin = p;
			return;
		}
	struct suggestion s;
	char buf[96];
	suggest_init(&s, id->u.ident.name);
	for (int p = 0; p < PATTERN_COUNT; p++)
		suggest_consider(&s, scene_desc_pattern_name(p));
	if (s.best)
		diag_error(c->diag, id->span, "unknown pattern '%s'%s", id->u.ident.name, suggest_text(&s, buf, sizeof buf));
	else
		diag_error(c->diag, id->span, "unknown pattern '%s'; the patterns are center, grid, random, jittered and poisson",
		           id->u.ident.name);
}

static void check_item(struct checker *c, struct ast *item, const struct attr_spec *a)
{
	struct ast_list *args = &item->u.item.args;
	const char *name = item_name(item);
	struct span at = item->u.item.name_span;
	for (size_t i = 0; i < args->n; i++)
		if (args->v[i]->kind == AST_ERROR) { /* reported where it is; its shape would be a guess */
			c->tainted = true;
			return;
		}

	if (item->u.item.block && a->shape != S_LIST && a->shape != S_MATERIAL) {
		diag_error(c->diag, item->u.item.block->open, "'%s' takes a value, not a block", name);
		return;
	}
	switch (a->shape) {
	case S_FLAG:
		if (args->n)
			diag_error(c->diag, args->v[0]->span, "'%s' takes no value", name);
		return;
	case S_NUM: case S_VEC: case S_PIGMENT: case S_STR:
		if (args->n == 0) {
			diag_error(c->diag, at, "'%s' needs a value", name);
			return;
		}
		if (args->n > 1) {
			diag_error(c->diag, args->v[1]->span, "'%s' takes one value%s", name,
			           args->n == 3 && a->shape != S_NUM ? "; write three numbers as a vector, <x, y, z>" : "");
			return;
		}
		if (a->shape == S_STR) {
			check_value(c, args->v[0], S_STR, name);
			return;
		}
		if (args->v[0]->kind == AST_STR) {
			diag_error(c->diag, args->v[0]->span, "'%s' takes a value, not a string", name);
			return;
		}
		check_value(c, args->v[0], a->shape, name);
		return;
	case S_INT2:
		if (args->n != 2) {
			diag_error(c->diag, args->n > 2 ? args->v[2]->span : item->span,
			           "'%s' takes two numbers: width, height", name);
			return;
		}
		for (int i = 0; i < 2; i++)
			if (args->v[i]->kind == AST_STR)
				diag_error(c->diag, args->v[i]->span, "'%s' takes numbers, not a string", name);
			else
				check_value(c, args->v[i], S_NUM, name);
		return;
	case S_MATERIAL:
		if (item->u.item.block && item->u.item.block->broken)
			return;
		if (item->u.item.block) {
			struct ast *seen[KW_COUNT_ALL] = { 0 };
			check_block(c, &material_spec, item->u.item.block, at, seen);
			return;
		}
		if ((item = name_arg(c, item, "a material, or { ... }")))
			check_material_ref(c, item);
		return;
	case S_LIKE:
		if ((item = name_arg(c, item, "a material")))
			check_material_ref(c, item);
		return;
	case S_PATTERN:
		if ((item = name_arg(c, item, "a pattern")))
			check_pattern(c, item);
		return;
	case S_LIST:
		if (item->u.item.block && item->u.item.block->broken)
			return;
		if (!item->u.item.block) {
			diag_error(c->diag, args->n ? args->v[0]->span : at, "'%s' takes a list in braces: %s { ... }",
			           name, name);
			return;
		}
		for (size_t i = 0; i < item->u.item.block->args.n; i++) {
			struct ast *e = item->u.item.block->args.v[i];
			if (e->kind == AST_STR)
				diag_error(c->diag, e->span, "'%s' lists vectors, not strings", name);
			else
				check_value(c, e, S_VEC, name);
		}
		return;
	}
}

/* An attribute of LANGUAGE.md section 9 where it does not apply: says where it does.
 * Returns whether item was one. */
static bool misplaced(struct checker *c, struct ast *item)
{
	struct span at = item->u.item.name_span;
	switch (item->u.item.kw) {
	case KW_OPEN:
		diag_error(c->diag, at, "'open' applies only to a cylinder or a cone: it leaves out their end discs");
		return true;
	case KW_INSIDE_VECTOR:
		diag_error(c->diag, at, "'inside_vector' applies only to a mesh: the other objects know their inside");
		return true;
	case KW_INVERSE:
		diag_error(c->diag, at, "'inverse' applies only to an object: it swaps a solid's inside and outside");
		return true;
	default:
		return false;
	}
}

/* Checks a block's positional arguments and items; records the first item of each
 * attribute in seen[] for the statement's own rules. Returns false when an attribute
 * was unknown: what the block lacks may then be only misspelt. */
bool check_block(struct checker *c, const struct block_spec *spec, struct ast_block *block, struct span where,
                 struct ast *seen[KW_COUNT_ALL])
{
	bool complete = true;
	size_t npos = strlen(spec->positional), least = npos - spec->optional;
	struct ast_list *args = &block->args;
	if (spec->signature && (args->n < least || args->n > npos)) {
		struct span at = args->n > npos ? args->v[npos]->span : args->n ? args->v[args->n - 1]->span : where;
		if (spec->optional)
			diag_error(c->diag, at, "%s takes %zu or %zu values before its attributes: %s", spec->what, least,
			           npos, spec->signature);
		else
			diag_error(c->diag, at, "%s takes %zu value%s before its attributes: %s", spec->what, npos,
			           npos == 1 ? "" : "s", spec->signature);
	}
	for (size_t i = 0; i < args->n; i++) /* a mesh's file name with a bad escape, say */
		c->tainted |= args->v[i]->kind == AST_ERROR;
	for (size_t i = 0; i < args->n && i < npos; i++) {
		if (args->v[i]->kind == AST_STR)
			diag_error(c->diag, args->v[i]->span, "%s takes a value here, not a string", spec->what);
		else
			check_value(c, args->v[i], spec->positional[i] - '0', spec->names[i]);
	}

	for (size_t i = 0; i < block->items.n; i++) {
		struct ast *item = block->items.v[i];
		const struct attr_spec *a = item->u.item.kw >= 0 ? find_attr(spec, item->u.item.kw) : NULL;
		if (!a && misplaced(c, item)) {
			complete = false;
			continue;
		}
		if (!a) {
			struct suggestion s;
			char buf[160];
			suggest_init(&s, item_name(item));
			for (size_t k = 0; k < spec->nattrs; k++)
				suggest_consider(&s, kw_name(spec->attrs[k].kw));
			const char *hint = s.best ? suggest_text(&s, buf, sizeof buf) : suggest_pov_hint(item_name(item), buf, sizeof buf);
			diag_error(c->diag, item->u.item.name_span, "unknown attribute '%s' in %s%s", item_name(item),
			           spec->what, hint ? hint : "");
			complete = false;
			continue;
		}
		struct ast **first = &seen[a->kw];
		if (*first && !a->repeat) {
			diag_error(c->diag, item->u.item.name_span, "'%s' is given twice in %s", item_name(item), spec->what);
			diag_note(c->diag, (*first)->u.item.name_span, "first given here");
			continue;
		}
		if (!*first)
			*first = item;
		if (a->kw == KW_LIKE && i != 0)
			diag_error(c->diag, item->u.item.name_span, "'like' must come first in a material");
		check_item(c, item, a);
	}
	return complete;
}

const struct block_spec *spec_of(enum kw kw)
{
	switch (kw) {
	case KW_CAMERA: return &camera_spec;
	case KW_LIGHT: return &light_spec;
	case KW_MATERIAL: return &material_spec;
	case KW_SPHERE: return &sphere_spec;
	case KW_PLANE: return &plane_spec;
	case KW_TRIANGLE: return &triangle_spec;
	case KW_BOX: return &box_spec;
	case KW_CYLINDER: return &cylinder_spec;
	case KW_CONE: return &cone_spec;
	case KW_DISC: return &disc_spec;
	case KW_TORUS: return &torus_spec;
	case KW_MESH: return &mesh_spec;
	case KW_UNION: return &union_spec;
	case KW_MERGE: return &merge_spec;
	case KW_INTERSECTION: return &intersection_spec;
	case KW_DIFFERENCE: return &difference_spec;
	case KW_SKYBOX: return &skybox_spec;
	case KW_SAMPLES: return &samples_spec;
	default: return NULL;
	}
}
