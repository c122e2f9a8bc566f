/* load.c: the front end end to end: read a scene file, parse, check, evaluate. */
#include "load.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "arena.h"
#include "check.h"
#include "clock.h"
#include "eval.h"
#include "file.h"
#include "lang.h"
#include "scene_desc.h"
#include "xalloc.h"

/* The whole file parsed, then checked, then evaluated: every diagnostic of each phase
 * before the next phase runs, which decides which of them count against the limit on
 * errors (diag.h), and gives "defined after its use" notes the whole file. */
static void load_in_phases(struct diag *d, const struct source *src, struct scene_desc *out, struct load_times *t)
{
	double t0 = clock_now();
	struct arena *a = arena_new();
	struct ast_list stmts = lang_parse(a, a, d, src);
	double t1 = clock_now();
	t->parse += t1 - t0;
	unsigned nslots = check_file(a, d, src, &stmts); /* parses included files too */
	double t2 = clock_now();
	t->check += t2 - t1;
	/* the statements that checked clean are evaluated even after an error elsewhere, for
	 * their value errors (check.c marks the others failed); once the errors have reached
	 * the limit nothing more would print */
	if (!diag_stopped(d))
		eval_file(d, &stmts, nslots, out, &t->evaluated);
	t->eval += clock_now() - t2;
	arena_free(a);
}

/* A load one statement at a time: parsed, checked, evaluated and released, so that a
 * file of a million statements never holds a million syntax trees. Its diagnostics come
 * in another order than the phases', so it goes on only while that makes no difference
 * (diag_any_order: warnings only, which check.c and eval.c give once per place); the
 * first error makes it give up (see load_scene). */
struct stream {
	struct diag *d;
	struct diag_mark start;        /* what the diagnostics were when it started */
	struct checker *checker;
	struct evaluator *ev;
	double last;                   /* the coarse clock's last reading */
	double parse_s, check_s, eval_s; /* by the coarse clock: how the time divides */
};

/* Adds the coarse time since the last reading to *phase. The coarse clock, for the three
 * readings around each of a million statements: the exact one would take several percent
 * of the load. It moves in ticks, but a statement starts at no particular point of a
 * tick, so the sum of many short readings is as likely to be over as under: right on
 * average, and right to a tick for a long statement. */
static void lap(struct stream *st, double *phase)
{
	double t = clock_now_coarse();
	*phase += t - st->last;
	st->last = t;
}

static bool stream_statement(void *arg, struct ast *stmt)
{
	struct stream *st = arg;
	if (!diag_any_order(st->d, st->start))
		return false;
	lap(st, &st->parse_s);
	check_statement(st->checker, stmt);
	lap(st, &st->check_s);
	if (!diag_any_order(st->d, st->start))
		return false;
	eval_statement(st->ev, stmt, check_slots(st->checker));
	lap(st, &st->eval_s);
	return diag_any_order(st->d, st->start);
}

/* Returns whether the load went through as the phases would have; if not, out holds part
 * of the scene and d what the first statements said. */
static bool load_streaming(struct diag *d, const struct source *src, struct scene_desc *out, struct load_times *t)
{
	double t0 = clock_now();
	struct arena *nodes = arena_new(), *keep = arena_new();
	struct stream st = { .d = d, .start = diag_mark(d), .last = clock_now_coarse() };
	st.checker = check_new(nodes, keep, d, src, NULL);
	st.ev = eval_new(d, out);
	lang_parse_each(nodes, keep, d, src, stream_statement, &st);
	/* the file's unused names are warned about at its end, as in phases */
	check_free(st.checker, diag_any_order(d, st.start));
	bool same = diag_any_order(d, st.start);
	eval_free(st.ev, &t->evaluated);
	arena_free(nodes);
	arena_free(keep);
	/* the exact clock says how much time there was, the coarse one how it divides (all
	 * parse when no tick passed) */
	lap(&st, &st.parse_s);
	double total = clock_now() - t0, ticked = st.parse_s + st.check_s + st.eval_s;
	t->parse += ticked > 0 ? total * st.parse_s / ticked : total;
	t->check += ticked > 0 ? total * st.check_s / ticked : 0;
	t->eval += ticked > 0 ? total * st.eval_s / ticked : 0;
	return same;
}

enum load_status load_scene(struct diag *d, const char *path, const struct load_frame *at,
                            struct scene_desc *out, struct load_times *times)
{
	struct load_times t = { 0 };
	double t0 = clock_now();
	bool from_stdin = strcmp(path, "-") == 0;
	struct load_frame moment = at ? *at : (struct load_frame){ 0, 0 };
	scene_desc_init(out);
	out->clock = moment.clock;
	out->frame = moment.frame;
	char *text;
	uint32_t len;
	int err = from_stdin ? file_read_stdin(&text, &len) : file_read(path, &text, &len);
	if (err) {
		diag_plain(d, DIAG_ERROR, "cannot read '%s': %s", from_stdin ? "<stdin>" : path,
		           err == EFBIG ? "larger than 256 MiB" : strerror(err));
		return LOAD_IO_ERROR;
	}
	const struct source *src = diag_add_source(d, from_stdin ? "<stdin>" : path, text, len, NULL,
	                                           (struct span){ 0, 0 });
	t.parse = clock_now() - t0;
	/* Most scenes have no error and load one statement at a time. One that has is loaded
	 * again in phases, from the start, so that what it says is exactly what the phases
	 * say; the statements before the first error are read twice. */
	struct diag_mark start = diag_mark(d);
	if (!load_streaming(d, src, out, &t)) {
		diag_rewind(d, start);
		t.evaluated = (struct eval_counts){ 0 };
		scene_desc_free(out);
		scene_desc_init(out);
		out->clock = moment.clock;
		out->frame = moment.frame;
		load_in_phases(d, src, out, &t);
	}
	if (times)
		*times = t;
	return d->errors ? LOAD_SCENE_ERROR : LOAD_OK;
}
