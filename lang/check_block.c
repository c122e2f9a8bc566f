/* check_block.c: which attributes each block statement takes (camera, light, material,
 * the objects and CSGs, skybox, samples, fog) and each block inside a material (pattern, image,
 * normal) or a light (spotlight, area), the shape of each attribute's value, and the check of a
 * block against them. */
#include "check_internal.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "file.h"
#include "scene_desc.h"

struct attr_spec {
	unsigned char kw, shape;
	bool repeat;               /* transforms: any number, applied in order */
};

#define TRANSFORMS { KW_TRANSLATE, S_VEC, true }, { KW_ROTATE, S_VEC, true }, { KW_SCALE, S_VEC, true }

static const struct attr_spec camera_attrs[] = {
	{ KW_LOCATION, S_VEC, false }, { KW_LOOK_AT, S_VEC, false }, { KW_UP, S_VEC, false },
	{ KW_FOV, S_NUM, false }, { KW_RESOLUTION, S_INT2, false }, { KW_ORTHOGRAPHIC, S_FLAG, false },
	{ KW_WIDTH, S_NUM, false }, { KW_APERTURE, S_NUM, false }, { KW_FOCAL_POINT, S_VEC, false },
};
static const struct attr_spec light_attrs[] = {
	{ KW_POSITION, S_VEC, false }, { KW_DIRECTION, S_VEC, false }, { KW_COLOR, S_VEC, false },
	{ KW_INTENSITY, S_NUM, false }, { KW_SHADOWLESS, S_FLAG, false }, { KW_FADE_DISTANCE, S_NUM, false },
	{ KW_FADE_POWER, S_NUM, false }, { KW_SPOTLIGHT, S_BLOCK, false }, { KW_AREA, S_BLOCK, false },
};
/* and radius, which stays a name that scenes may use: spotlight_radius checks it */
static const struct attr_spec spotlight_attrs[] = {
	{ KW_POINT_AT, S_VEC, false }, { KW_FALLOFF, S_NUM, false }, { KW_TIGHTNESS, S_NUM, false },
};
static const struct attr_spec area_attrs[] = {
	{ KW_JITTER, S_FLAG, false }, { KW_CIRCULAR, S_FLAG, false }, { KW_ORIENT, S_FLAG, false },
};
static const struct attr_spec material_attrs[] = {
	{ KW_LIKE, S_LIKE, false }, { KW_DIFFUSE, S_PIGMENT, false }, { KW_SPECULAR, S_VEC, false },
	{ KW_SHININESS, S_NUM, false }, { KW_REFLECT, S_VEC, false }, { KW_TRANSMIT, S_VEC, false },
	{ KW_IOR, S_NUM, false }, { KW_FRESNEL, S_FLAG, false }, { KW_EMIT, S_VEC, false },
	{ KW_NORMAL, S_BLOCK, false },
};
/* LANGUAGE.md section 11: what modifies a pattern's value, in a diffuse pattern and a normal */
#define PATTERN_MODIFIERS { KW_FREQUENCY, S_NUM, false }, { KW_PHASE, S_NUM, false }, \
	{ KW_TURBULENCE, S_VEC, false }, { KW_OCTAVES, S_NUM, false }, { KW_OMEGA, S_NUM, false }, \
	{ KW_LAMBDA, S_NUM, false }
static const struct attr_spec pattern_attrs[] = { { KW_COLORS, S_COLORS, false }, PATTERN_MODIFIERS, TRANSFORMS };
static const struct attr_spec normal_attrs[] = { PATTERN_MODIFIERS, TRANSFORMS };
static const struct attr_spec image_attrs[] = {
	{ KW_MAP, S_WORD, false }, { KW_INTERPOLATE, S_WORD, false }, { KW_ONCE, S_FLAG, false }, TRANSFORMS,
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
	{ KW_INSIDE_VECTOR, S_VEC, false }, { KW_UVS, S_LIST, false }, { KW_INTERPOLATE, S_WORD, false },
};
static const struct attr_spec skybox_attrs[] = {
	{ KW_COLOR, S_VEC, false }, { KW_ZENITH, S_VEC, false }, { KW_HORIZON, S_VEC, false },
	{ KW_IMAGE, S_STR, false }, { KW_ROTATE, S_NUM, false }, { KW_INTENSITY, S_NUM, false },
};
static const struct attr_spec fog_attrs[] = { { KW_DISTANCE, S_NUM, false }, { KW_COLOR, S_VEC, false } };
static const struct attr_spec samples_attrs[] = {
	{ KW_COUNT, S_NUM, false }, { KW_PATTERN, S_WORD, false }, { KW_SEED, S_NUM, false },
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
	unsigned char patterns;    /* a texture block's pattern names (enum texture), which stand
	                            * as items of their own */
};

/* The pattern names a block takes as items. */
enum texture { TEX_NONE, TEX_PIGMENT, TEX_NORMAL };

#define SPEC(what, attrs, pos, sig, ...) { what, attrs, sizeof attrs / sizeof attrs[0], pos, sig, { __VA_ARGS__ }, 0, TEX_NONE }
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
	{ "the disc's center", "the disc's normal", "the disc's radius", "the disc's hole radius" }, 1, TEX_NONE,
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
static const struct block_spec fog_spec = SPEC("fog", fog_attrs, "", NULL, NULL);
static const struct block_spec pattern_spec = {
	"pattern", pattern_attrs, sizeof pattern_attrs / sizeof pattern_attrs[0], "", NULL, { NULL }, 0, TEX_PIGMENT,
};
static const struct block_spec normal_spec = {
	"normal", normal_attrs, sizeof normal_attrs / sizeof normal_attrs[0], "", NULL, { NULL }, 0, TEX_NORMAL,
};
static const struct block_spec image_spec = SPEC("image", image_attrs, "", NULL, NULL);
static const struct block_spec spotlight_spec = SPEC("spotlight", spotlight_attrs, "", NULL, NULL);
static const struct block_spec area_spec = SPEC("area", area_attrs, "2211", "area { AXIS1, AXIS2, N1, N2 ... }",
                                                "an area light's AXIS1", "an area light's AXIS2",
                                                "an area light's N1", "an area light's N2");

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

/* The words of interpolate, in the order of their codes (1: bilinear). */
static const char *const interpolate_words[] = { "nearest", "bilinear" };

/* The word id names, of the list S_WORD attribute kw takes: its index into
 * id->u.ident.builtin, or an error with "did you mean". */
static void check_word(struct checker *c, struct ast *id, int kw)
{
	const char *words[PATTERN_COUNT > 4 ? PATTERN_COUNT : 4];
	size_t n = 0;
	const char *what = kw == KW_MAP ? "map kind" : kw == KW_INTERPOLATE ? "interpolate mode" : "pattern";
	if (kw == KW_MAP)
		for (int k = IMAGE_MAP_PLANAR; k <= IMAGE_MAP_UV; k++)
			words[n++] = scene_desc_map_name(k);
	else if (kw == KW_INTERPOLATE)
		for (size_t k = 0; k < sizeof interpolate_words / sizeof interpolate_words[0]; k++)
			words[n++] = interpolate_words[k];
	else
		for (int p = 0; p < PATTERN_COUNT; p++)
			words[n++] = scene_desc_pattern_name(p);
	for (size_t k = 0; k < n; k++)
		if (strcmp(id->u.ident.name, words[k]) == 0) {
			id->u.ident.builtin = (int)k;
			return;
		}
	struct suggestion s;
	char buf[160];
	suggest_init(&s, id->u.ident.name);
	for (size_t k = 0; k < n; k++)
		suggest_consider(&s, words[k]);
	if (s.best) {
		diag_error(c->diag, id->span, "unknown %s '%s'%s", what, id->u.ident.name, suggest_text(&s, buf, sizeof buf));
		return;
	}
	size_t used = 0;
	for (size_t k = 0; k < n && used < sizeof buf; k++)
		used += (size_t)snprintf(buf + used, sizeof buf - used, "%s%s", k == 0 ? "" : k == n - 1 ? " and " : ", ",
		                         words[k]);
	diag_error(c->diag, id->span, "unknown %s '%s'; the %ss are %s", what, id->u.ident.name, what, buf);
}

static const struct block_spec *texture_spec(int kw);
static void check_texture(struct checker *c, const struct block_spec *spec, struct ast_block *block,
                          struct span kw_span);
static void check_spotlight(struct checker *c, struct ast_block *block, struct span kw_span);
static void check_area(struct checker *c, struct ast_block *block, struct span kw_span);

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

	if (item->u.item.block && a->shape != S_LIST && a->shape != S_MATERIAL && a->shape != S_BLOCK) {
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
		if (args->v[0]->kind == AST_ITEM) { /* diffuse pattern { ... }, image { ... } */
			struct ast *sub = args->v[0];
			check_texture(c, texture_spec(sub->u.item.kw), sub->u.item.block, sub->u.item.name_span);
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
	case S_WORD: {
		int kw = item->u.item.kw;
		if (kw == KW_INTERPOLATE && args->n == 1 && args->v[0]->kind == AST_NUM) {
			diag_error(c->diag, args->v[0]->span, "'interpolate' takes nearest or bilinear (POV-Ray's interpolate 2 "
			           "is bilinear)");
			return;
		}
		if ((item = name_arg(c, item, kw == KW_MAP ? "a map kind" : kw == KW_INTERPOLATE ? "an interpolate mode"
		                                                                   : "a pattern")))
			check_word(c, item, kw);
		return;
	}
	case S_BLOCK:
		if (!item->u.item.block) {
			diag_error(c->diag, args->n ? args->v[0]->span : at, "'%s' takes a block: %s", name,
			           item->u.item.kw == KW_SPOTLIGHT ? "spotlight { point_at <0, 0, 0> }"
			           : item->u.item.kw == KW_AREA ? "area { <1, 0, 0>, <0, 0, 1>, 4, 4 }" : "normal { bumps 0.5 }");
			return;
		}
		if (item->u.item.kw == KW_SPOTLIGHT)
			check_spotlight(c, item->u.item.block, at);
		else if (item->u.item.kw == KW_AREA)
			check_area(c, item->u.item.block, at);
		else
			check_texture(c, &normal_spec, item->u.item.block, at);
		return;
	case S_COLORS: {
		if (args->n != 1) {
			diag_error(c->diag, args->n ? args->v[1]->span : at,
			           "'colors' takes one array of [position, colour] pairs: colors [[0, <0, 0, 0>], [1, <1, 1, 1>]]");
			return;
		}
		enum ast_type t = check_expr(c, args->v[0]);
		if (t != TYPE_NONE && t != TYPE_ANY && t != TYPE_ARRAY)
			diag_error(c->diag, args->v[0]->span, "'colors' takes an array of [position, colour] pairs, found %s",
			           value_type_name(t));
		return;
	}
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
	case KW_COLORS:
		diag_error(c->diag, at, "'colors' applies only to a diffuse pattern { ... }");
		return true;
	case KW_FREQUENCY: case KW_PHASE: case KW_TURBULENCE: case KW_OCTAVES: case KW_OMEGA: case KW_LAMBDA:
		diag_error(c->diag, at, "'%s' applies only to a diffuse pattern { ... } or a normal { ... }", item_name(item));
		return true;
	case KW_MAP: case KW_ONCE:
		diag_error(c->diag, at, "'%s' applies only to a diffuse image { ... }", item_name(item));
		return true;
	case KW_INTERPOLATE:
		diag_error(c->diag, at, "'interpolate' applies only to a diffuse image { ... } or a mesh file");
		return true;
	case KW_UVS:
		diag_error(c->diag, at, "'uvs' applies only to a mesh given by vertices { ... } and faces { ... }");
		return true;
	case KW_NORMAL:
		diag_error(c->diag, at, "'normal' goes in a material: material { normal { ... } }");
		return true;
	case KW_SPOTLIGHT:
		diag_error(c->diag, at, "'spotlight' goes in a light: light { position P  spotlight { point_at V } }");
		return true;
	case KW_POINT_AT: case KW_FALLOFF: case KW_TIGHTNESS:
		diag_error(c->diag, at, "'%s' goes in a light's spotlight { ... }", item_name(item));
		return true;
	case KW_AREA:
		diag_error(c->diag, at, "'area' goes in a light: light { position P  area { AXIS1, AXIS2, N1, N2 } }");
		return true;
	case KW_JITTER: case KW_CIRCULAR: case KW_ORIENT:
		diag_error(c->diag, at, "'%s' goes in a light's area { AXIS1, AXIS2, N1, N2 ... }, after the four values",
		           item_name(item));
		return true;
	case KW_APERTURE: case KW_FOCAL_POINT:
		diag_error(c->diag, at, "'%s' goes in the camera: camera { ... aperture A  focal_point V }", item_name(item));
		return true;
	case KW_PATTERN: case KW_IMAGE: /* specular pattern { ... } */
		if (!item->u.item.block)
			return false;
		diag_error(c->diag, at, "%s { ... } is a value of diffuse only: diffuse %s { ... }", item_name(item),
		           item_name(item));
		return true;
	default:
		return false;
	}
}

/* The pattern names of a texture block of that kind: [*first, *end) of enum pattern_name,
 * and how a message lists them. */
static void pattern_range(unsigned char kind, int *first, int *end, const char **list)
{
	*first = kind == TEX_NORMAL ? PAT_FIRST_NORMAL : 0;
	*end = kind == TEX_NORMAL ? PAT_COUNT : PAT_FIRST_NORMAL;
	*list = kind == TEX_NORMAL ? "bumps, dents, ripples, waves or wrinkles"
	      : "gradient V, radial, onion, wood, marble, leopard, agate, bozo, granite or spotted";
}

/* Whether some item of block names a pattern of the block's kind. */
static bool names_pattern(const struct block_spec *spec, const struct ast_block *block)
{
	int first, end;
	const char *list;
	pattern_range(spec->patterns, &first, &end, &list);
	for (size_t i = 0; i < block->items.n; i++) {
		const struct ast *item = block->items.v[i];
		int p = item->u.item.kw < 0 ? scene_desc_texture_lookup(item->u.item.name) : -1;
		if (p >= first && p < end)
			return true;
	}
	return false;
}

/* An item of a pattern or normal block that is no attribute: the pattern's name (with
 * its value: gradient's vector, a normal's amount), recorded as seen[KW_PATTERN], which
 * those blocks have no other use for. Returns false when it is unknown (it may be the
 * pattern's name or an attribute, misspelt). */
static bool pattern_item(struct checker *c, const struct block_spec *spec, const struct ast_block *block,
                         struct ast *item, struct ast *seen[KW_COUNT_ALL])
{
	const char *name = item->u.item.name;
	struct span at = item->u.item.name_span;
	struct ast_list *args = &item->u.item.args;
	int first, end;
	const char *list;
	pattern_range(spec->patterns, &first, &end, &list);
	int p = scene_desc_texture_lookup(name);
	if (p >= 0 && (p < first || p >= end)) {
		if (spec->patterns == TEX_NORMAL)
			diag_error(c->diag, at, "'%s' is a colour pattern: it goes in diffuse pattern { ... }; a normal takes %s",
			           name, list);
		else
			diag_error(c->diag, at, "'%s' is a normal pattern: it goes in the material's normal { ... }, not in "
			           "diffuse pattern { ... }", name);
		return false; /* it stands for the block's pattern: that none is given is said */
	}
	if (p >= 0) {
		if (seen[KW_PATTERN]) {
			diag_error(c->diag, at, "a %s takes one pattern, and '%s' is given already", spec->what,
			           seen[KW_PATTERN]->u.item.name);
			diag_note(c->diag, seen[KW_PATTERN]->u.item.name_span, "first given here");
			return true;
		}
		seen[KW_PATTERN] = item;
		/* wood marble: the grammar takes the second name for the first's value */
		if (args->n == 1 && args->v[0]->kind == AST_IDENT && scene_desc_texture_lookup(args->v[0]->u.ident.name) >= 0) {
			diag_error(c->diag, args->v[0]->span, "a %s takes one pattern, and '%s' is given already", spec->what,
			           name);
			return true;
		}
		/* wood colours [...]: a misspelt attribute, which the grammar took for wood's value */
		struct ast *head = args->n ? args->v[0] : NULL;
		while (head && (head->kind == AST_INDEX || head->kind == AST_MEMBER || head->kind == AST_BINARY))
			head = head->kind == AST_MEMBER ? head->u.member.e : head->u.bin.l;
		if (p != PAT_GRADIENT && p < PAT_FIRST_NORMAL && head && head->kind == AST_IDENT &&
		    !names_lookup(c, head->u.ident.name)) {
			struct suggestion sg;
			char buf[160];
			suggest_init(&sg, head->u.ident.name);
			for (size_t k = 0; k < spec->nattrs; k++)
				suggest_consider(&sg, kw_name(spec->attrs[k].kw));
			diag_error(c->diag, head->span, "unknown attribute '%s' in %s%s", head->u.ident.name, spec->what,
			           suggest_text(&sg, buf, sizeof buf));
			return false;
		}
		if (item->u.item.block) {
			diag_error(c->diag, item->u.item.block->open, "'%s' takes %s, not a block", name,
			           p == PAT_GRADIENT ? "a vector" : p >= PAT_FIRST_NORMAL ? "an amount" : "no value");
			return true;
		}
		static const struct attr_spec vector = { 0, S_VEC, false }, amount = { 0, S_NUM, false },
		                              flag = { 0, S_FLAG, false };
		if (p == PAT_GRADIENT && args->n == 0)
			diag_error(c->diag, at, "'gradient' needs the direction it runs in: gradient <0, 1, 0>");
		else if (p == PAT_GRADIENT)
			check_item(c, item, &vector);
		else if (p >= PAT_FIRST_NORMAL && args->n > 0) /* the amount may be left out: 0.5 */
			check_item(c, item, &amount);
		else if (p < PAT_FIRST_NORMAL)
			check_item(c, item, &flag);
		return true;
	}
	/* misspelt: the pattern's name, or an attribute; the closer guess says which */
	struct suggestion s;
	char buf[160];
	suggest_init(&s, name);
	for (int k = first; k < end; k++)
		suggest_consider(&s, scene_desc_texture_name(k));
	const char *pattern = s.best;
	for (size_t k = 0; k < spec->nattrs; k++)
		suggest_consider(&s, kw_name(spec->attrs[k].kw));
	if (s.best && s.best == pattern)
		diag_error(c->diag, at, "unknown pattern '%s'%s", name, suggest_text(&s, buf, sizeof buf));
	else if (s.best || names_pattern(spec, block))
		diag_error(c->diag, at, "unknown attribute '%s' in %s%s", name, spec->what, suggest_text(&s, buf, sizeof buf));
	else
		diag_error(c->diag, at, "unknown pattern '%s'; a %s takes %s", name, spec->what, list);
	return false;
}

/* A spotlight's radius, which is no keyword (scenes name their own radii): recorded as
 * seen[KW_SPOTLIGHT], which the spotlight block has no other use for. */
static void spotlight_radius(struct checker *c, struct ast *item, struct ast *seen[KW_COUNT_ALL])
{
	static const struct attr_spec number = { 0, S_NUM, false };
	if (seen[KW_SPOTLIGHT]) {
		diag_error(c->diag, item->u.item.name_span, "'radius' is given twice in spotlight");
		diag_note(c->diag, seen[KW_SPOTLIGHT]->u.item.name_span, "first given here");
		return;
	}
	seen[KW_SPOTLIGHT] = item;
	check_item(c, item, &number);
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
		if (!a && item->u.item.kw < 0 && spec->patterns) {
			complete &= pattern_item(c, spec, block, item, seen);
			continue;
		}
		if (!a && spec == &spotlight_spec && strcmp(item_name(item), "radius") == 0) {
			spotlight_radius(c, item, seen);
			continue;
		}
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
			if (spec == &spotlight_spec)
				suggest_consider(&s, "radius");
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
	case KW_FOG: return &fog_spec;
	default: return NULL;
	}
}

void block_file_name(struct checker *c, struct ast_block *block)
{
	if (block->args.n || !block->items.n)
		return;
	struct ast *first = block->items.v[0];
	struct binding *b = first->u.item.kw < 0 && !first->u.item.args.n && !first->u.item.block
	                    ? names_lookup(c, first->u.item.name) : NULL;
	if (!b || names_class(b->kind) != NAMES_VALUES)
		return;
	ast_list_push(c->nodes, &block->args, ast_ident(c->nodes, first->u.item.name_span, first->u.item.name));
	block->items.v++;
	block->items.n--;
	block->items.cap--;
}

void check_readable(struct checker *c, const struct source *src, struct ast *str, const char *what)
{
	char *path = file_resolve(src->dir, str->u.str.text);
	const char *why = file_unreadable(path);
	if (why)
		diag_error(c->diag, str->span, "cannot read %s '%s': %s", what, str->u.str.text, why);
	free(path);
}

/* The block a diffuse item's pattern or image (kw) holds. */
static const struct block_spec *texture_spec(int kw)
{
	return kw == KW_IMAGE ? &image_spec : &pattern_spec;
}

/* diffuse pattern { ... }, diffuse image { "FILE" ... } or normal { ... }, whose keyword is
 * at kw_span: its attributes, its one pattern name (not an image), its file (an image
 * only). A block broken by a syntax error fails the statement: evaluated, it would lack
 * its pattern. */
static void check_texture(struct checker *c, const struct block_spec *spec, struct ast_block *block,
                          struct span kw_span)
{
	if (block->broken) {
		c->tainted = true;
		return;
	}
	if (spec == &image_spec) {
		block_file_name(c, block);
		struct ast *file = block->args.n ? block->args.v[0] : NULL;
		if (!file) {
			diag_error(c->diag, kw_span, "an image needs a file name: image { \"FILE\" ... }");
		} else if (file->kind == AST_ERROR) {
			c->tainted = true;
		} else {
			check_value(c, file, S_STR, "an image's file name");
			if (file->kind == AST_STR)
				check_readable(c, diag_source_at(c->diag, file->span.start), file, "image file");
		}
	} else if (block->args.n) {
		diag_error(c->diag, block->args.v[0]->span, "a %s takes no file name: it starts with the pattern's name",
		           spec->what);
	}
	struct ast *seen[KW_COUNT_ALL] = { 0 };
	bool complete = check_block(c, spec, block, kw_span, seen) && (spec == &image_spec || !block->args.n);
	if (spec->patterns && !seen[KW_PATTERN] && complete) {
		int first, end;
		const char *list;
		pattern_range(spec->patterns, &first, &end, &list);
		diag_error(c->diag, kw_span, "a %s needs the name of its pattern: %s", spec->what, list);
	}
}

/* spotlight { point_at V  radius DEG  falloff DEG  tightness T }, whose keyword is at
 * kw_span: its attributes, and the axis it cannot do without. */
static void check_spotlight(struct checker *c, struct ast_block *block, struct span kw_span)
{
	if (block->broken) {
		c->tainted = true;
		return;
	}
	struct ast *seen[KW_COUNT_ALL] = { 0 };
	if (check_block(c, &spotlight_spec, block, kw_span, seen) && !seen[KW_POINT_AT])
		diag_error(c->diag, kw_span, "a spotlight needs the point it aims at: spotlight { point_at <0, 0, 0> }");
}

/* area { AXIS1, AXIS2, N1, N2  [jitter] [circular] [orient] }, whose keyword is at
 * kw_span: its four values and its flags; eval.c checks what the values must be. */
static void check_area(struct checker *c, struct ast_block *block, struct span kw_span)
{
	if (block->broken) {
		c->tainted = true;
		return;
	}
	struct ast *seen[KW_COUNT_ALL] = { 0 };
	check_block(c, &area_spec, block, kw_span, seen);
}
