/* eval_texture.c: a material's surfaces (LANGUAGE.md section 11): diffuse pattern { ... },
 * normal { ... } and diffuse image { ... } into the scene's patterns, colour maps and
 * images, each value checked where it is written. */
#include "eval_internal.h"

#include <stdlib.h>

#include "xalloc.h"

/* The entry of colour map e at index i, for messages: the literal element when e is
 * written as an array, else e; *position and *colour its parts when it is written as a
 * pair, else that entry. */
static struct ast *entry_at(struct ast *e, uint32_t i, struct ast **position, struct ast **colour)
{
	struct ast *at = e->kind == AST_ARRAY && i < e->u.elems.n ? e->u.elems.v[i] : e;
	bool pair = at != e && at->kind == AST_ARRAY && at->u.elems.n == 2;
	*position = pair ? at->u.elems.v[0] : at;
	*colour = pair ? at->u.elems.v[1] : at;
	return at;
}

/* colors ARRAY: its [position, colour] pairs, appended to the scene's color_maps, with
 * positions in [0, 1] that never fall (two equal ones make a sharp edge, as in POV-Ray).
 * False after an error, reported at the entry, and nothing appended. */
static bool colour_map(struct evaluator *ev, struct ast *e, struct pattern_desc *p)
{
	struct value v;
	char nb[32], nb2[32];
	if (!eval_expr(ev, e, &v))
		return false;
	if (v.type != TYPE_ARRAY || v.len == 0) {
		eval_error(ev, e, "'colors' takes an array of [position, colour] pairs, found %s",
		           v.type == TYPE_ARRAY ? "an empty array" : value_type_name(v.type));
		return false;
	}
	struct scene_desc *o = ev->out;
	size_t base = o->ncolor_maps;
	for (uint32_t i = 0; i < v.len; i++) {
		const struct value *pair = &v.elems[i];
		struct ast *position, *colour, *at = entry_at(e, i, &position, &colour);
		bool ok = false;
		if (pair->type == TYPE_ARRAY && pair->len != 2)
			eval_error(ev, at, "an entry of 'colors' is a [position, colour] pair, as [0.5, <1, 0, 0>], not an "
			           "array of %u", pair->len);
		else if (pair->type != TYPE_ARRAY)
			eval_error(ev, at, "an entry of 'colors' is a [position, colour] pair, as [0.5, <1, 0, 0>], not %s",
			           value_type_name(pair->type));
		else if (pair->elems[0].type != TYPE_NUM)
			eval_error(ev, position, "a colour map's position must be a number, found %s",
			           value_type_name(pair->elems[0].type));
		else if (pair->elems[1].type != TYPE_NUM && pair->elems[1].type != TYPE_VEC)
			eval_error(ev, colour, "a colour map's colour must be a number or a vector, found %s",
			           value_type_name(pair->elems[1].type));
		else if (!(pair->elems[0].v[0] >= 0 && pair->elems[0].v[0] <= 1))
			eval_error(ev, position, "a colour map's position must be between 0 and 1, not %s",
			           value_number_text(pair->elems[0].v[0], nb));
		else if (i > 0 && pair->elems[0].v[0] < o->color_maps[o->ncolor_maps - 1].position)
			eval_error(ev, position, "a colour map's positions must not fall: %s comes after %s",
			           value_number_text(pair->elems[0].v[0], nb),
			           value_number_text(o->color_maps[o->ncolor_maps - 1].position, nb2));
		else
			ok = true;
		if (!ok) {
			o->ncolor_maps = base;
			return false;
		}
		struct color_map_entry entry = { .position = pair->elems[0].v[0] };
		for (int k = 0; k < 3; k++)
			entry.color[k] = pair->elems[1].type == TYPE_NUM ? pair->elems[1].v[0] : pair->elems[1].v[k];
		xgrow((void **)&o->color_maps, &o->cap_color_maps, o->ncolor_maps + 1, sizeof *o->color_maps);
		o->color_maps[o->ncolor_maps++] = entry;
	}
	p->map = (uint32_t)base;
	p->nmap = v.len;
	return true;
}

/* A transform item of a texture block, composed into *x; *moved records that there was one. */
static bool texture_transform(struct evaluator *ev, struct ast *it, struct xform *x, bool *moved)
{
	*moved = true;
	if (!xform_apply(ev, it, x))
		return false;
	if (xform_finite(x))
		return true;
	eval_error(ev, it, "the transforms make the pattern too large to be numbers");
	return false;
}

int eval_pattern(struct evaluator *ev, struct ast *sub, struct ast_block *block, bool normal)
{
	struct pattern_desc p = {
		.amount = 0.5, .frequency = 1, .octaves = 6, .omega = 0.5, .lambda = 2, .xform = -1,
		.span = sub->u.item.name_span,
	};
	struct xform x = { { { 1, 0, 0, 0 }, { 0, 1, 0, 0 }, { 0, 0, 1, 0 } } };
	struct scene_desc *o = ev->out;
	size_t maps = o->ncolor_maps;
	bool ok = true, moved = false;
	double octaves;
	for (size_t i = 0; i < block->items.n; i++) {
		struct ast *it = block->items.v[i];
		switch (it->u.item.kw) {
		case -1: /* the pattern's name (check.c) */
			p.name = (uint8_t)scene_desc_texture_lookup(it->u.item.name);
			if (p.name == PAT_GRADIENT && !vec_of(ev, arg0(it), p.vector)) {
				ok = false;
			} else if (p.name == PAT_GRADIENT && is_zero(p.vector)) {
				eval_error(ev, arg0(it), "gradient's direction must not be a zero vector");
				ok = false;
			}
			if (normal && it->u.item.args.n)
				ok &= num_of(ev, arg0(it), &p.amount);
			break;
		case KW_COLORS: ok &= colour_map(ev, arg0(it), &p); break;
		case KW_FREQUENCY: ok &= num_of(ev, arg0(it), &p.frequency); break;
		case KW_PHASE: ok &= num_of(ev, arg0(it), &p.phase); break;
		case KW_TURBULENCE: ok &= vec_of(ev, arg0(it), p.turbulence); break;
		case KW_OCTAVES:
			ok &= whole_of(ev, arg0(it), 1, 10, "octaves", &octaves);
			p.octaves = (int)octaves;
			break;
		case KW_OMEGA: ok &= num_of(ev, arg0(it), &p.omega); break;
		case KW_LAMBDA: ok &= num_of(ev, arg0(it), &p.lambda); break;
		case KW_TRANSLATE: case KW_ROTATE: case KW_SCALE:
			ok &= texture_transform(ev, it, &x, &moved);
			break;
		}
	}
	if (!ok) {
		o->ncolor_maps = maps;
		return -1;
	}
	if (moved)
		p.xform = xform_push(ev, &x);
	xgrow((void **)&o->patterns, &o->cap_patterns, o->npatterns + 1, sizeof *o->patterns);
	o->patterns[o->npatterns] = p;
	return (int)o->npatterns++;
}

int eval_image(struct evaluator *ev, struct ast *sub)
{
	struct ast_block *block = sub->u.item.block;
	struct ast *file = block->args.v[0];
	struct image_desc im = { .map = IMAGE_MAP_PLANAR, .xform = -1, .span = file->span };
	struct xform x = { { { 1, 0, 0, 0 }, { 0, 1, 0, 0 }, { 0, 0, 1, 0 } } };
	bool moved = false;
	bool ok = file_of(ev, file, diag_source_at(ev->diag, file->span.start), "image file", &im.file, &im.path);
	for (size_t i = 0; i < block->items.n; i++) {
		struct ast *it = block->items.v[i];
		switch (it->u.item.kw) {
		/* the words' codes, from check.c: the order of enum image_map_kind; nearest, bilinear */
		case KW_MAP: im.map = (uint8_t)arg0(it)->u.ident.builtin; break;
		case KW_INTERPOLATE: im.bilinear = arg0(it)->u.ident.builtin == 1; break;
		case KW_ONCE: im.once = true; break;
		case KW_TRANSLATE: case KW_ROTATE: case KW_SCALE:
			ok &= texture_transform(ev, it, &x, &moved);
			break;
		}
	}
	if (!ok) {
		free(im.file);
		free(im.path);
		return -1;
	}
	if (moved)
		im.xform = xform_push(ev, &x);
	struct scene_desc *o = ev->out;
	xgrow((void **)&o->images, &o->cap_images, o->nimages + 1, sizeof *o->images);
	o->images[o->nimages] = im;
	return (int)o->nimages++;
}
