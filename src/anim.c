/* anim.c: animation on the command line: --clock and --frames read, each frame's clock
 * and file name, and the progress bar over frames. */
#include "anim.h"

#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "clock.h"
#include "xalloc.h"

int anim_clock_arg(const struct command *cmd, const char *name, const char *v, double *out)
{
	char *end;
	double c = strtod(v, &end);
	/* strtod skips leading blanks; the value is the whole argument */
	if (end == v || *end || isspace((unsigned char)*v) || !isfinite(c))
		return cli_usage_error(cmd, "bad value '%s' for %s (a finite number)", v, name);
	*out = c;
	return 0;
}

int anim_frames_arg(const struct command *cmd, const char *name, const char *v, struct anim_frames *out)
{
	const char *dots = strstr(v, "..");
	char first[32];
	long a, b;
	bool ok = dots && (size_t)(dots - v) < sizeof first;
	if (ok) {
		snprintf(first, sizeof first, "%.*s", (int)(dots - v), v);
		ok = cli_int(first, -ANIM_MAX_FRAME, ANIM_MAX_FRAME, &a) &&
		     cli_int(dots + 2, -ANIM_MAX_FRAME, ANIM_MAX_FRAME, &b);
	}
	if (!ok)
		return cli_usage_error(cmd, "bad value '%s' for %s (A..B, whole numbers from %ld to %ld)", v, name,
		                       -ANIM_MAX_FRAME, ANIM_MAX_FRAME);
	if (a >= b)
		return cli_usage_error(cmd, "%s %s has no frames: A..B renders frames A to B-1", name, v);
	*out = (struct anim_frames){ .first = a, .end = b };
	return 0;
}

double anim_clock(const struct anim_frames *f, long k)
{
	long last = f->cyclic ? f->end : f->end - 1; /* the frame at clock 1 */
	return last == f->first ? 0 : (double)(k - f->first) / (double)(last - f->first);
}

void anim_clock_text(double c, char *buf, size_t size)
{
	for (int digits = 1; digits <= 17; digits++) {
		snprintf(buf, size, "%.*g", digits, c);
		if (strtod(buf, NULL) == c)
			return;
	}
}

/* The decimal digits of v >= 0. */
static int digits(long v)
{
	int d = 1;
	for (; v >= 10; v /= 10)
		d++;
	return d;
}

/* The width of %0Nd that s (just after its '%') spells, with *len its length up to the
 * 'd'; 0 for %d; -1 for anything else, or N outside 1 .. 64. */
static int conversion(const char *s, size_t *len)
{
	size_t i = 0;
	int width = 0;
	if (s[i] == '0') {
		for (i = 1; isdigit((unsigned char)s[i]) && width <= 64; i++)
			width = 10 * width + (s[i] - '0');
		if (width < 1 || width > 64)
			return -1;
	}
	if (s[i] != 'd')
		return -1;
	*len = i + 1;
	return width;
}

int anim_names_init(struct anim_names *n, const struct command *cmd, const char *out, bool is_template,
                    const struct anim_frames *f)
{
	size_t len = strlen(out), m = 0, at = 0;
	char *text = xmalloc(len + 1); /* out with %% as % and without the conversion */
	bool found = false;
	*n = (struct anim_names){ 0 };
	for (size_t i = 0; i < len; i++) {
		if (!is_template || out[i] != '%') {
			text[m++] = out[i];
			continue;
		}
		if (out[i + 1] == '%') {
			text[m++] = '%';
			i++;
			continue;
		}
		size_t clen;
		int width = conversion(out + i + 1, &clen);
		if (width < 0 || found) {
			free(text);
			if (width < 0)
				return cli_usage_error(cmd, "bad output name '%s' for frames: a '%%' must start %%d or %%0Nd (the "
				                       "frame number, N from 1 to 64) or %%%% (a '%%')", out);
			return cli_usage_error(cmd, "bad output name '%s' for frames: more than one %%d or %%0Nd", out);
		}
		found = true;
		at = m;
		n->width = width;
		i += clen;
	}
	text[m] = '\0';
	if (!found) { /* before the extension of the file's name, not of a folder's */
		const char *base = strrchr(text, '/');
		base = base ? base + 1 : text;
		const char *dot = strrchr(base, '.');
		at = dot ? (size_t)(dot - text) : m;
		long a = labs(f->first), b = labs(f->end - 1);
		n->width = digits(a > b ? a : b);
		n->sign_extra = true;
	}
	n->tail = xstrdup(text + at);
	text[at] = '\0';
	n->head = text;
	return 0;
}

char *anim_name(const struct anim_names *n, long k)
{
	int width = n->width + (n->sign_extra && k < 0);
	size_t size = strlen(n->head) + strlen(n->tail) + (size_t)width + 24;
	char *name = xmalloc(size);
	snprintf(name, size, "%s%0*ld%s", n->head, width, k, n->tail);
	return name;
}

void anim_names_free(struct anim_names *n)
{
	free(n->head);
	free(n->tail);
}

void anim_bar_init(struct anim_bar *b, long total)
{
	*b = (struct anim_bar){ .total = total, .t0 = clock_now() };
}

void anim_bar_show(struct anim_bar *b)
{
	enum { WIDTH = 30 };
	char bar[WIDTH + 1];
	int full = (int)(WIDTH * b->done / b->total);
	memset(bar, '#', (size_t)full);
	memset(bar + full, '.', (size_t)(WIDTH - full));
	bar[WIDTH] = '\0';
	anim_bar_erase(b);
	int n = fprintf(stderr, "\r[%s] %ld/%ld frames", bar, b->done, b->total);
	if (b->done > 0)
		n += fprintf(stderr, "  ETA %.0fs", (clock_now() - b->t0) * (double)(b->total - b->done) / (double)b->done);
	b->shown = n - 1;
}

void anim_bar_erase(struct anim_bar *b)
{
	if (b->shown > 0)
		fprintf(stderr, "\r%*s\r", b->shown, "");
	b->shown = 0;
}
