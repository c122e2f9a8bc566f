/* eval.c: runs a checked scene: expands loops and includes, evaluates each statement
 * (eval_object.c the objects and CSGs, eval_expr.c the expressions; a non-finite result
 * is an error at its place), checks every value's range, and builds the scene_desc.
 * Types were settled by check.c; this file only computes. */
#include "eval_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "file.h"
#include "xalloc.h"

/* ---- statements ---- */

/* Whether nonzero a and b are parallel: the sine of the angle between them, from unit
 * vectors, so scale-free (also for vectors of 1e-310, whose products would underflow). */
static bool parallel(const double a[3], const double b[3])
{
	double ua[3], ub[3], side[3];
	unit(a, ua);
	unit(b, ub);
	cross(ua, ub, side);
	return norm(side) <= 1e-12;
}

/* The camera's focal_point (item at_focus, or look_at when NULL) against its view
 * direction dir; a focal point with nothing to blur is only warned of. */
static void eval_focus(struct evaluator *ev, struct camera_desc *c, struct ast *at_focus, bool aperture_ok,
                       const double dir[3])
{
	if (!at_focus) {
		memcpy(c->focal_point, c->look_at, sizeof c->focal_point);
		return;
	}
	double to[3] = { c->focal_point[0] - c->location[0], c->focal_point[1] - c->location[1],
	                 c->focal_point[2] - c->location[2] };
	if (to[0] * dir[0] + to[1] * dir[1] + to[2] * dir[2] <= 0) {
		char nb[3][32];
		eval_error(ev, arg0(at_focus), "focal_point <%s, %s, %s> is not in front of the camera (behind or beside "
		           "its location)", value_number_text(c->focal_point[0], nb[0]),
		           value_number_text(c->focal_point[1], nb[1]), value_number_text(c->focal_point[2], nb[2]));
	}
	if (aperture_ok && c->aperture == 0)
		diag_warning(ev->diag, at_focus->u.item.name_span, "focal_point does nothing without an aperture > 0");
}

static void eval_camera(struct evaluator *ev, struct ast *s)
{
	struct camera_desc *c = &ev->out->camera;
	struct ast *at_look = NULL, *at_up = NULL, *at_loc = NULL, *at_focus = NULL;
	bool aperture_ok = true, focus_ok = true;
	char nb[32];
	c->given = true;
	c->span = c->resolution_span = s->u.stmt.kw_span;
	struct ast_list *items = &s->u.stmt.block->items;
	for (size_t i = 0; i < items->n; i++) {
		struct ast *it = items->v[i];
		double w, h;
		switch (it->u.item.kw) {
		case KW_LOCATION: at_loc = it; vec_of(ev, arg0(it), c->location); break;
		case KW_LOOK_AT: at_look = it; vec_of(ev, arg0(it), c->look_at); break;
		case KW_UP: at_up = it; vec_of(ev, arg0(it), c->up); break;
		case KW_FOV:
			if (num_of(ev, arg0(it), &c->fov) && !(c->fov > 0 && c->fov < 180))
				eval_error(ev, arg0(it), "fov must be between 0 and 180 degrees (both excluded), not %s",
				           value_number_text(c->fov, nb));
			break;
		case KW_ORTHOGRAPHIC: c->orthographic = true; break;
		case KW_WIDTH:
			positive_of(ev, arg0(it), "width", false, &c->view_width);
			break;
		case KW_APERTURE: aperture_ok = positive_of(ev, arg0(it), "aperture", true, &c->aperture); break;
		case KW_FOCAL_POINT: at_focus = it; focus_ok = vec_of(ev, arg0(it), c->focal_point); break;
		case KW_RESOLUTION:
			c->resolution_span = it->span;
			/* both, so that a bad width does not hide a bad height */
			if (whole_of(ev, it->u.item.args.v[0], 1, 65536, "the width", &w) &
			    whole_of(ev, it->u.item.args.v[1], 1, 65536, "the height", &h)) {
				if (w * h > LANG_MAX_PIXELS)
					eval_error(ev, it, "%.0f x %.0f is more pixels than the limit of 2^28", w, h);
				c->width = (int)w;
				c->height = (int)h;
			}
			break;
		}
	}
	double dir[3] = { c->look_at[0] - c->location[0], c->look_at[1] - c->location[1],
	                  c->look_at[2] - c->location[2] };
	if (is_zero(dir)) {
		eval_error(ev, at_look ? at_look : at_loc ? at_loc : s, "look_at is the same point as location");
		return;
	}
	if (focus_ok)
		eval_focus(ev, c, at_focus, aperture_ok, dir);
	if (is_zero(c->up)) {
		eval_error(ev, at_up ? at_up : s, "up must not be a zero vector");
		return;
	}
	bool flat = parallel(c->up, dir);
	if (flat && at_up)
		eval_error(ev, at_up, "up is parallel to the viewing direction");
	else if (flat) /* the default up: blame the direction */
		eval_error(ev, at_look ? at_look : at_loc ? at_loc : s,
		           "the viewing direction is parallel to the default up <0, 1, 0>; give the camera an 'up'");
}

/* An angle of spotlight { ... } (item it) into *deg: [0, 180), as a cosine repeats past it. */
static bool spot_angle(struct evaluator *ev, struct ast *it, double *deg)
{
	char nb[32];
	if (!num_of(ev, arg0(it), deg))
		return false;
	if (*deg >= 0 && *deg < 180)
		return true;
	eval_error(ev, arg0(it), "a spotlight's %s must be at least 0 and below 180 degrees, not %s",
	           it->u.item.kw == KW_FALLOFF ? "falloff" : "radius", value_number_text(*deg, nb));
	return false;
}

/* spotlight { ... } (item sp) into l, with POV-Ray's defaults: radius 30, falloff 45,
 * tightness 0. Returns point_at's value node when it evaluated, else NULL. */
static struct ast *eval_spotlight(struct evaluator *ev, struct ast *sp, struct light_desc *l)
{
	char nb[32], nb2[32];
	struct ast *aim = NULL, *radius = NULL, *falloff = NULL;
	bool angles = true;
	l->spot = true;
	l->radius = 30;
	l->falloff = 45;
	struct ast_list *items = &sp->u.item.block->items;
	for (size_t i = 0; i < items->n; i++) {
		struct ast *it = items->v[i];
		switch (it->u.item.kw) {
		case KW_POINT_AT:
			if (vec_of(ev, arg0(it), l->point_at))
				aim = arg0(it);
			break;
		case KW_FALLOFF: falloff = it; angles &= spot_angle(ev, it, &l->falloff); break;
		case KW_TIGHTNESS: positive_of(ev, arg0(it), "tightness", true, &l->tightness); break;
		case -1: radius = it; angles &= spot_angle(ev, it, &l->radius); break; /* radius, by name (check_block.c) */
		}
	}
	if (angles && l->falloff < l->radius) {
		if (falloff)
			eval_error(ev, arg0(falloff), "a spotlight's falloff must be at least its radius, %s, not %s",
			           value_number_text(l->radius, nb), value_number_text(l->falloff, nb2));
		else
			eval_error(ev, arg0(radius), "a spotlight's radius must be at most its falloff, 45 by default, not %s",
			           value_number_text(l->radius, nb));
	}
	return aim;
}

/* area { AXIS1, AXIS2, N1, N2  [jitter] [circular] [orient] } (item ar) into l: counts of
 * 1 to 64, and axes that span the lights (orient turns them to face each point, so there
 * only their lengths matter). */
static void eval_area(struct evaluator *ev, struct ast *ar, struct light_desc *l)
{
	struct ast_list *args = &ar->u.item.block->args, *items = &ar->u.item.block->items;
	struct ast *circular = NULL, *orient = NULL;
	bool axes = true, sized = true;
	l->area = true;
	for (int k = 0; k < 2; k++) {
		double n;
		axes &= vec_of(ev, args->v[k], l->area_axis[k]);
		if (whole_of(ev, args->v[2 + k], 1, 64, k ? "an area light's N2" : "an area light's N1", &n))
			l->area_size[k] = (int)n;
		else
			sized = false;
	}
	for (size_t i = 0; i < items->n; i++)
		switch (items->v[i]->u.item.kw) {
		case KW_JITTER: l->area_jitter = true; break;
		case KW_CIRCULAR: l->area_circular = true; circular = items->v[i]; break;
		case KW_ORIENT: l->area_orient = true; orient = items->v[i]; break;
		}
	if (!sized)
		return;
	const int *n = l->area_size;
	for (int k = 0; axes && k < 2; k++)
		if (n[k] > 1 && is_zero(l->area_axis[k])) {
			eval_error(ev, args->v[k], "AXIS%d of an area light is a zero vector, but N%d is %d: its lights would "
			           "sit at one point", k + 1, k + 1, n[k]);
			axes = false;
		}
	if (axes && n[0] > 1 && n[1] > 1 && !l->area_orient && parallel(l->area_axis[0], l->area_axis[1]))
		eval_error(ev, args->v[1], "the axes of an area light are parallel: with N1 and N2 over 1 they must span "
		           "a surface");
	if (circular && (n[0] < 2 || n[1] < 2))
		eval_error(ev, circular, "'circular' needs N1 and N2 of 2 or more (POV-Ray divides by N - 1), not %d",
		           n[0] < 2 ? n[0] : n[1]);
	else if (orient && (n[0] < 2 || n[1] < 2))
		eval_error(ev, orient, "'orient' makes the light circular, which needs N1 and N2 of 2 or more, not %d",
		           n[0] < 2 ? n[0] : n[1]);
	else if (orient && axes) {
		/* POV-Ray's own warnings: an oriented light is a disc, square to each lit point */
		double len[2] = { norm(l->area_axis[0]), norm(l->area_axis[1]) };
		if (fabs(len[0] - len[1]) > 1e-9 * fmax(len[0], len[1]))
			diag_warning(ev->diag, orient->u.item.name_span, "an oriented area light takes AXIS1's length for both "
			             "axes: AXIS2's is ignored");
		if (n[0] != n[1])
			diag_warning(ev->diag, orient->u.item.name_span, "an oriented area light turns with each lit point: "
			             "give it as many points on both axes (N1 %d, N2 %d)", n[0], n[1]);
	}
}

static void eval_light(struct evaluator *ev, struct ast *s)
{
	struct light_desc l = { .color = { 1, 1, 1 }, .intensity = 1, .span = s->u.stmt.kw_span };
	struct ast *aim = NULL; /* a spotlight's point_at, evaluated */
	bool placed = false;    /* the position, evaluated */
	struct ast_list *items = &s->u.stmt.block->items;
	for (size_t i = 0; i < items->n; i++) {
		struct ast *it = items->v[i];
		switch (it->u.item.kw) {
		case KW_POSITION: placed = vec_of(ev, arg0(it), l.vec); break;
		case KW_DIRECTION:
			l.directional = true;
			if (vec_of(ev, arg0(it), l.vec) && is_zero(l.vec))
				eval_error(ev, arg0(it), "a light's direction must not be a zero vector");
			break;
		case KW_COLOR: vec_of(ev, arg0(it), l.color); break;
		case KW_INTENSITY: num_of(ev, arg0(it), &l.intensity); break;
		case KW_SHADOWLESS: l.shadowless = true; break;
		case KW_FADE_DISTANCE:
			positive_of(ev, arg0(it), "fade_distance", false, &l.fade_distance);
			break;
		case KW_FADE_POWER:
			positive_of(ev, arg0(it), "fade_power", true, &l.fade_power);
			break;
		case KW_SPOTLIGHT: aim = eval_spotlight(ev, it, &l); break;
		case KW_AREA: eval_area(ev, it, &l); break;
		}
	}
	if (aim && placed && l.point_at[0] == l.vec[0] && l.point_at[1] == l.vec[1] && l.point_at[2] == l.vec[2])
		eval_error(ev, aim, "point_at is the light's position: the spotlight has no axis");
	struct scene_desc *o = ev->out;
	xgrow((void **)&o->lights, &o->cap_lights, o->nlights + 1, sizeof *o->lights);
	o->lights[o->nlights++] = l;
}

static void eval_skybox(struct evaluator *ev, struct ast *s, const struct source *src)
{
	struct skybox_desc *k = &ev->out->skybox;
	k->span = s->u.stmt.kw_span;
	struct ast_list *items = &s->u.stmt.block->items;
	for (size_t i = 0; i < items->n; i++) {
		struct ast *it = items->v[i];
		switch (it->u.item.kw) {
		case KW_COLOR: k->kind = SKY_COLOR; vec_of(ev, arg0(it), k->color); break;
		case KW_ZENITH: k->kind = SKY_GRADIENT; vec_of(ev, arg0(it), k->color); break;
		case KW_HORIZON: k->kind = SKY_GRADIENT; vec_of(ev, arg0(it), k->horizon); break;
		case KW_IMAGE:
			if (file_of(ev, arg0(it), src, "skybox image", &k->image, &k->image_path))
				k->kind = SKY_IMAGE;
			break;
		case KW_ROTATE: num_of(ev, arg0(it), &k->rotate); break;
		case KW_INTENSITY: num_of(ev, arg0(it), &k->intensity); break;
		}
	}
}

static void eval_fog(struct evaluator *ev, struct ast *s)
{
	struct fog_desc *f = &ev->out->fog;
	f->given = true;
	f->span = s->u.stmt.kw_span;
	struct ast_list *items = &s->u.stmt.block->items;
	for (size_t i = 0; i < items->n; i++) {
		struct ast *it = items->v[i];
		switch (it->u.item.kw) {
		case KW_DISTANCE: positive_of(ev, arg0(it), "a fog's distance", false, &f->distance); break;
		case KW_COLOR: vec_of(ev, arg0(it), f->color); break;
		}
	}
}

static void eval_samples(struct evaluator *ev, struct ast *s)
{
	struct samples_desc *sd = &ev->out->samples;
	struct ast *count_at = s->u.stmt.value, *pattern_at = NULL, *target_at = NULL;
	double x;
	if (count_at && whole_of(ev, count_at, 1, 65536, "the sample count", &x))
		sd->count = (int)x;
	struct ast_list *items = s->u.stmt.block ? &s->u.stmt.block->items : NULL;
	for (size_t i = 0; items && i < items->n; i++) {
		struct ast *it = items->v[i];
		switch (it->u.item.kw) {
		case KW_COUNT:
			count_at = arg0(it);
			if (whole_of(ev, count_at, 1, 65536, "the sample count", &x))
				sd->count = (int)x;
			break;
		case KW_PATTERN:
			pattern_at = it;
			sd->pattern_given = true;
			sd->pattern = (enum sample_pattern)arg0(it)->u.ident.builtin;
			break;
		case KW_SEED:
			if (whole_of(ev, arg0(it), 0, 9007199254740992.0, "the seed", &x))
				sd->seed = (uint64_t)x;
			break;
		case KW_TARGET_ERROR:
			target_at = arg0(it);
			positive_of(ev, arg0(it), "target_error", false, &sd->target_error);
			break;
		}
	}
	if (!sd->pattern_given)
		sd->pattern = sd->count == 1 ? PATTERN_CENTER : PATTERN_JITTERED;
	if (target_at && sd->pattern == PATTERN_GRID)
		/* an adaptive pixel stops after a prefix of its samples, and a grid's prefix is
		 * a band of rows, not the whole pixel */
		eval_error(ev, target_at, "target_error needs a random, jittered or poisson pattern, not grid");
	if (sd->pattern == PATTERN_CENTER && sd->count != 1)
		eval_error(ev, pattern_at, "pattern center takes exactly one sample, but count is %d", sd->count);
	if (sd->pattern == PATTERN_GRID) {
		int n = (int)sqrt((double)sd->count);
		if (n * n != sd->count)
			eval_error(ev, count_at ? count_at : pattern_at,
			           "pattern grid needs a square count (1, 4, 9, 16, ...), not %d", sd->count);
	}
}

/* Too many errors, or a limit on the whole evaluation reached: nothing more runs. */
static bool stopped(const struct evaluator *ev)
{
	return diag_stopped(ev->diag) || ev->exhausted;
}

/* Takes n more loop iterations from the limit on all of them; false (reported at s,
 * sp) past it. */
static bool more_iterations(struct evaluator *ev, struct ast *s, struct span sp, double n)
{
	if (ev->iterations > LANG_MAX_ITERATIONS) { /* the limit was hit: no loop runs any more */
		ev->failures++;
		return false;
	}
	if (n > (double)(LANG_MAX_ITERATIONS - ev->iterations)) {
		eval_error_span(ev, s, sp, "the for loops would run more than %d iterations in all", LANG_MAX_ITERATIONS);
		/* once: the enclosing loops' later runs would only say it again, elsewhere */
		ev->iterations = (uint64_t)LANG_MAX_ITERATIONS + 1;
		return false;
	}
	ev->iterations += (uint64_t)n;
	return true;
}

/* One iteration: the variable bound to var, the body run, and what the body made on the
 * heap released (its bindings end with it). */
static void iterate(struct evaluator *ev, struct ast *s, const struct value *var)
{
	unsigned slot = s->u.loop.b->slot;
	struct heap_mark mark = heap_mark(ev);
	ev->context[ev->ncontext - 1].var = *var;
	ev->slots[slot] = *var;
	eval_stmts(ev, &s->u.loop.body);
	heap_release(ev, mark);
}

static void eval_for(struct evaluator *ev, struct ast *s)
{
	if (!s->u.loop.to) { /* for x in an array */
		struct value a;
		if (!eval_expr(ev, s->u.loop.from, &a))
			return;
		if (a.type != TYPE_ARRAY) {
			eval_error(ev, s->u.loop.from, "a for loop runs over a range A .. B or an array, found %s",
			           value_type_name(a.type));
			return;
		}
		if (!more_iterations(ev, s, s->u.loop.from->span, a.len))
			return;
		context_push(ev, s, NULL);
		for (uint32_t i = 0; i < a.len && !stopped(ev); i++)
			iterate(ev, s, &a.elems[i]);
		context_pop(ev);
		return;
	}
	double from, to;
	if (!whole_of(ev, s->u.loop.from, -9007199254740992.0, 9007199254740992.0, "a for loop's start", &from) ||
	    !whole_of(ev, s->u.loop.to, -9007199254740992.0, 9007199254740992.0, "a for loop's end", &to))
		return;
	if (!more_iterations(ev, s, diag_span_join(s->u.loop.from->span, s->u.loop.to->span), to > from ? to - from : 0))
		return;
	context_push(ev, s, NULL);
	struct value i = { .type = TYPE_NUM };
	for (i.v[0] = from; i.v[0] < to && !stopped(ev); i.v[0]++)
		iterate(ev, s, &i);
	context_pop(ev);
}

static void eval_if(struct evaluator *ev, struct ast *s)
{
	bool c;
	if (truth_of(ev, s->u.cond_stmt.cond, &c))
		eval_stmts(ev, c ? &s->u.cond_stmt.then : &s->u.cond_stmt.other);
}

/* A CSG: its slot and items, then its members, which take what it hands down. */
static void eval_csg(struct evaluator *ev, struct ast *s)
{
	struct csg_frame frame;
	if (!csg_begin(ev, s, &frame))
		return;
	eval_stmts(ev, &s->u.stmt.block->members);
	csg_end(ev, s);
}

static void eval_stmt(struct evaluator *ev, struct ast *s)
{
	if (s->failed)                 /* its error is reported; what it would give is unknown */
		return;
	switch (s->kind) {
	case AST_LET: {
		unsigned slot = s->u.let.b->slot;
		if (!eval_expr(ev, s->u.let.value, &ev->slots[slot]))
			ev->slots[slot].type = TYPE_NONE;
		return;
	}
	case AST_INCLUDE: /* its bindings last beyond it */
		eval_stmts(ev, &s->u.include.body);
		return;
	default:
		break;
	}
	/* the other statements bind nothing beyond themselves: what they put on the heap
	 * is released after them */
	struct heap_mark mark = heap_mark(ev);
	switch (s->kind) {
	case AST_FOR:
		eval_for(ev, s);
		break;
	case AST_IF:
		eval_if(ev, s);
		break;
	case AST_MACRO_CALL: {
		struct call call;
		if (call_enter(ev, s, &call)) {
			eval_stmts(ev, &s->u.call.ref->def->u.def.body);
			call_end(ev, &call);
		}
		break;
	}
	case AST_BLOCK_STMT: {
		const struct source *src = diag_source_at(ev->diag, s->span.start);
		double depth;
		switch (s->u.stmt.kw) {
		case KW_CAMERA: eval_camera(ev, s); break;
		case KW_LIGHT: eval_light(ev, s); break;
		case KW_SKYBOX: eval_skybox(ev, s, src); break;
		case KW_SAMPLES: eval_samples(ev, s); break;
		case KW_FOG: eval_fog(ev, s); break;
		case KW_MAX_DEPTH:
			if (whole_of(ev, s->u.stmt.value, 1, LANG_MAX_DEPTH, "max_depth", &depth))
				ev->out->max_depth = (int)depth;
			break;
		case KW_MATERIAL:
			ev->slots[s->u.stmt.b->slot] = (struct value){
				.type = TYPE_MATERIAL,
				.v = { eval_material(ev, s->u.stmt.block, s->u.stmt.name, s->u.stmt.name_span) } };
			break;
		default:
			if (kw_is_csg(s->u.stmt.kw))
				eval_csg(ev, s);
			else
				eval_shape(ev, s, src);
			break;
		}
		break;
	}
	default:
		break;
	}
	heap_release(ev, mark);
}

void eval_stmts(struct evaluator *ev, struct ast_list *stmts)
{
	for (size_t i = 0; i < stmts->n && !stopped(ev); i++)
		eval_stmt(ev, stmts->v[i]);
}

struct evaluator *eval_new(struct diag *d, struct scene_desc *out)
{
	struct evaluator *ev = xcalloc(1, sizeof *ev);
	ev->diag = d;
	ev->out = out;
	ev->heap = arena_new();
	ev->heap_now = arena_mark(ev->heap);
	ev->stack_base = (uintptr_t)__builtin_frame_address(0);
	return ev;
}

/* Makes room for nslots bindings (each is set before it can be used). */
static void grow_slots(struct evaluator *ev, size_t nslots)
{
	if (nslots <= ev->nslots)
		return;
	xgrow((void **)&ev->slots, &ev->cap_slots, nslots, sizeof *ev->slots);
	ev->nslots = nslots;
}

void eval_statement(struct evaluator *ev, struct ast *stmt, unsigned nslots)
{
	grow_slots(ev, nslots);
	if (!stopped(ev))
		eval_stmt(ev, stmt);
}

void eval_free(struct evaluator *ev, struct eval_counts *counts)
{
	counts->steps += ev->steps;
	counts->calls += ev->ncalls;
	free(ev->slots);
	free(ev->saved);
	free(ev->context);
	arena_free(ev->heap);
	free(ev);
}

void eval_file(struct diag *d, struct ast_list *stmts, unsigned nslots, struct scene_desc *out,
               struct eval_counts *counts)
{
	struct evaluator *ev = eval_new(d, out);
	grow_slots(ev, nslots);
	eval_stmts(ev, stmts);
	eval_free(ev, counts);
}
