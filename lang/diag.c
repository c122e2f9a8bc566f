/* diag.c: source registry and diagnostics in GCC's form:
 *   file:line:col: error: message
 *      12 | the source line
 *         |      ^~~~
 * Columns count bytes; the caret line pads by characters so that it stays under the
 * span on a terminal, copying tabs from the source. */
#include "diag.h"

#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "xalloc.h"

/* Warnings shown at the most; the rest are counted. */
enum { MAX_WARNINGS = 100 };

/* Lines longer than this are shown as a window around the span. */
enum { LINE_WINDOW = 160, WINDOW_LEAD = 60 };

static const char *const level_names[] = { "error", "warning", "note" };

void diag_init(struct diag *d, FILE *out)
{
	memset(d, 0, sizeof *d);
	d->out = out;
	d->max_errors = 20;
}

static void free_source(struct source *s)
{
	free(s->path);
	free(s->dir);
	free(s->text);
	free(s->lines);
	free(s);
}

void diag_fini(struct diag *d)
{
	diag_flush(d);
	free(d->records);
	for (size_t i = 0; i < d->nfiles; i++)
		free_source(d->files[i]);
	free(d->files);
	memset(d, 0, sizeof *d);
}

struct diag_mark diag_mark(const struct diag *d)
{
	return (struct diag_mark){ d->nrecords, d->nfiles, d->next_base, d->errors, d->warnings, d->stopped, d->dropped };
}

bool diag_any_order(const struct diag *d, struct diag_mark m)
{
	return d->errors == m.errors && d->stopped == m.stopped && d->warnings <= MAX_WARNINGS;
}

void diag_rewind(struct diag *d, struct diag_mark m)
{
	for (size_t i = m.nrecords; i < d->nrecords; i++) {
		free(d->records[i].text);
		free(d->records[i].key);
	}
	for (size_t i = m.nfiles; i < d->nfiles; i++)
		free_source(d->files[i]);
	d->nrecords = m.nrecords;
	d->nfiles = m.nfiles;
	d->next_base = m.next_base;
	d->errors = m.errors;
	d->warnings = m.warnings;
	d->stopped = m.stopped;
	d->dropped = m.dropped;
}

static char *dir_of(const char *path)
{
	const char *slash = strrchr(path, '/');
	if (!slash)
		return xstrdup(".");
	size_t n = slash == path ? 1 : (size_t)(slash - path); /* "/x" lives in "/" */
	char *dir = xmalloc(n + 1);
	memcpy(dir, path, n);
	dir[n] = '\0';
	return dir;
}

struct source *diag_add_source(struct diag *d, const char *path, char *text, uint32_t len,
                               const struct source *includer, struct span include_site)
{
	/* +1 keeps an offset for end of file even in an empty file */
	if (len >= DIAG_MAX_SOURCE_BYTES - d->next_base) {
		free(text);
		return NULL;
	}
	struct source *s = xcalloc(1, sizeof *s);
	s->path = xstrdup(path);
	s->dir = dir_of(path);
	s->text = text;
	s->len = len;
	s->base = d->next_base;
	s->included = includer != NULL;
	s->include_site = include_site;
	d->next_base += len + 1;
	xgrow((void **)&d->files, &d->cap, d->nfiles + 1, sizeof *d->files);
	d->files[d->nfiles++] = s;
	return s;
}

const struct source *diag_source_at(const struct diag *d, uint32_t off)
{
	/* files are registered in increasing base order */
	size_t lo = 0, hi = d->nfiles;
	while (hi - lo > 1) {
		size_t mid = (lo + hi) / 2;
		if (d->files[mid]->base <= off)
			lo = mid;
		else
			hi = mid;
	}
	return d->nfiles ? d->files[lo] : NULL;
}

static void index_lines(struct source *s)
{
	size_t cap = 0, n = 0;
	uint32_t *lines = NULL;
	xgrow((void **)&lines, &cap, 1, sizeof *lines);
	lines[n++] = 0;
	for (uint32_t i = 0; i < s->len; i++)
		if (s->text[i] == '\n') {
			xgrow((void **)&lines, &cap, n + 1, sizeof *lines);
			lines[n++] = i + 1;
		}
	s->lines = lines;
	s->nlines = (uint32_t)n;
}

/* Index (0-based) of the line holding local offset off. */
static uint32_t line_index(struct source *s, uint32_t off)
{
	if (!s->lines)
		index_lines(s);
	uint32_t lo = 0, hi = s->nlines;
	while (hi - lo > 1) {
		uint32_t mid = lo + (hi - lo) / 2;
		if (s->lines[mid] <= off)
			lo = mid;
		else
			hi = mid;
	}
	return lo;
}

void diag_line_col(const struct diag *d, uint32_t off, unsigned *line, unsigned *col)
{
	struct source *s = (struct source *)diag_source_at(d, off);
	uint32_t local = off - s->base;
	if (local > s->len)
		local = s->len;
	uint32_t li = line_index(s, local);
	*line = li + 1;
	*col = local - s->lines[li] + 1;
}

/* Writes text[from, to) for the quoted line: control bytes become '?' so that hostile
 * input cannot drive the terminal. */
static void put_source_text(FILE *out, const char *text, uint32_t from, uint32_t to)
{
	for (uint32_t i = from; i < to; i++) {
		unsigned char c = (unsigned char)text[i];
		fputc((c < 0x20 && c != '\t') || c == 0x7f ? '?' : c, out);
	}
}

/* Pads the caret line under text[from, to): one space per character, tabs kept. */
static void put_padding(FILE *out, const char *text, uint32_t from, uint32_t to)
{
	for (uint32_t i = from; i < to; i++) {
		unsigned char c = (unsigned char)text[i];
		if (c == '\t')
			fputc('\t', out);
		else if ((c & 0xc0) != 0x80) /* not a UTF-8 continuation byte */
			fputc(' ', out);
	}
}

static void quote_line(struct diag *d, struct source *s, uint32_t start, uint32_t end, unsigned line)
{
	uint32_t li = line - 1;
	uint32_t ls = s->lines[li];
	uint32_t le = li + 1 < s->nlines ? s->lines[li + 1] - 1 : s->len;
	if (le > ls && s->text[le - 1] == '\r')
		le--;
	if (end > le)
		end = le;
	if (end <= start)
		end = start + 1; /* a caret even at end of line or file */

	uint32_t ws = ls, we = le;
	if (le - ls > LINE_WINDOW) {
		ws = start > ls + WINDOW_LEAD ? start - WINDOW_LEAD : ls;
		we = ws + LINE_WINDOW < le ? ws + LINE_WINDOW : le;
		if (end > we)
			end = we > start ? we : start + 1;
	}
	int width = line > 99999 ? snprintf(NULL, 0, "%u", line) : 5; /* the gutter grows past 5 digits */
	fprintf(d->out, "%*u | %s", width, line, ws > ls ? "..." : "");
	put_source_text(d->out, s->text, ws, we);
	fprintf(d->out, "%s\n%*s | %s", we < le ? "..." : "", width, "", ws > ls ? "   " : "");
	put_padding(d->out, s->text, ws, start);
	fputc('^', d->out);
	for (uint32_t i = start + 1; i < end; i++)
		if (((unsigned char)s->text[i] & 0xc0) != 0x80)
			fputc('~', d->out);
	fputc('\n', d->out);
}

/* Whether to print a diagnostic: notes follow the fate of the message they annotate;
 * the error after the last one allowed stops the run, once. */
static bool admit(struct diag *d, enum diag_level level)
{
	if (level == DIAG_NOTE)
		return !d->dropped;
	d->dropped = d->stopped;
	if (d->stopped)
		return false;
	if (level == DIAG_ERROR && d->errors == d->max_errors) {
		d->stopped = d->dropped = true;
		return false;
	}
	if (level == DIAG_ERROR) {
		d->errors++;
	} else if (++d->warnings > MAX_WARNINGS) { /* 100k unused names need not say so 100k times */
		d->dropped = true;
		return false;
	}
	return true;
}

/* Starts the record of a new diagnostic at span sp (NULL: no place, sorted first), or
 * reopens the last one for a note; d->out writes into it until end_record. */
static FILE *begin_record(struct diag *d, enum diag_level level, const struct span *sp, char **buf, size_t *len)
{
	if (level != DIAG_NOTE || d->nrecords == 0) {
		xgrow((void **)&d->records, &d->cap_records, d->nrecords + 1, sizeof *d->records);
		struct diag_record *r = &d->records[d->nrecords++];
		memset(r, 0, sizeof *r);
		r->seq = d->nrecords;
		r->text = xstrdup("");
		if (sp) {
			unsigned depth = 1;
			for (const struct source *s = diag_source_at(d, sp->start); s->included;
			     s = diag_source_at(d, s->include_site.start))
				depth++;
			r->key = xcalloc(depth, sizeof *r->key);
			r->nkey = depth;
			uint32_t off = sp->start;
			for (unsigned i = depth; i-- > 0;) {
				const struct source *s = diag_source_at(d, off);
				r->key[i] = off - s->base;
				off = s->include_site.start;
			}
		}
	}
	return xcheck(open_memstream(buf, len), "diagnostics");
}

/* Closes the stream of begin_record (which sets *buf) and appends its text. */
static void end_record(struct diag *d, FILE *f, char **buf, size_t *len)
{
	if (fclose(f) != 0)
		xout_of_memory("diagnostics");
	struct diag_record *r = &d->records[d->nrecords - 1];
	/* A message quotes strings and file names of the scene: their control bytes (an
	 * escape sequence in an include's name) must not reach the terminal either. */
	for (size_t i = 0; i < *len; i++) {
		unsigned char c = (unsigned char)(*buf)[i];
		if ((c < 0x20 && c != '\t' && c != '\n') || c == 0x7f)
			(*buf)[i] = '?';
	}
	size_t old = strlen(r->text);
	r->text = xrealloc(r->text, old + *len + 1);
	memcpy(r->text + old, *buf, *len + 1);
	free(*buf);
}

static int by_position(const void *pa, const void *pb)
{
	const struct diag_record *a = pa, *b = pb;
	for (unsigned i = 0; i < a->nkey && i < b->nkey; i++)
		if (a->key[i] != b->key[i])
			return a->key[i] < b->key[i] ? -1 : 1;
	if (a->nkey != b->nkey)
		return a->nkey < b->nkey ? -1 : 1;
	return a->seq < b->seq ? -1 : a->seq > b->seq;
}

void diag_flush(struct diag *d)
{
	if (d->nrecords > 1) /* qsort's array must not be NULL, even when empty */
		qsort(d->records, d->nrecords, sizeof *d->records, by_position);
	for (size_t i = 0; i < d->nrecords; i++) {
		fputs(d->records[i].text, d->out);
		free(d->records[i].text);
		free(d->records[i].key);
	}
	d->nrecords = 0;
	if (d->warnings > MAX_WARNINGS && !d->warnings_told) {
		fprintf(d->out, "scn: %d more warnings not shown\n", d->warnings - MAX_WARNINGS);
		d->warnings_told = true;
	}
	if (d->stopped && !d->stop_told) {
		fprintf(d->out, "scn: too many errors (more than %d), stopping\n", d->max_errors);
		d->stop_told = true;
	}
	fflush(d->out);
}

void diag_report(struct diag *d, enum diag_level level, struct span sp, const char *fmt, ...)
{
	if (!admit(d, level))
		return;
	char *buf;
	size_t len;
	FILE *real = d->out;
	d->out = begin_record(d, level, &sp, &buf, &len);
	struct source *s = (struct source *)diag_source_at(d, sp.start);
	if (level != DIAG_NOTE)
		for (const struct source *inc = s; inc && inc->included;) {
			unsigned l, c;
			diag_line_col(d, inc->include_site.start, &l, &c);
			inc = diag_source_at(d, inc->include_site.start);
			fprintf(d->out, "In file included from %s:%u:%u:\n", inc->path, l, c);
		}
	unsigned line, col;
	diag_line_col(d, sp.start, &line, &col);
	fprintf(d->out, "%s:%u:%u: %s: ", s->path, line, col, level_names[level]);
	va_list ap;
	va_start(ap, fmt);
	vfprintf(d->out, fmt, ap);
	va_end(ap);
	fputc('\n', d->out);
	quote_line(d, s, sp.start - s->base, sp.end - s->base, line);
	end_record(d, d->out, &buf, &len);
	d->out = real;
}

void diag_plain(struct diag *d, enum diag_level level, const char *fmt, ...)
{
	if (!admit(d, level))
		return;
	char *buf;
	size_t len;
	FILE *f = begin_record(d, level, NULL, &buf, &len);
	fprintf(f, "scn: %s: ", level_names[level]);
	va_list ap;
	va_start(ap, fmt);
	vfprintf(f, fmt, ap);
	va_end(ap);
	fputc('\n', f);
	end_record(d, f, &buf, &len);
}
