/* load.c: the front end end to end: read a scene file, parse, check, evaluate. */
#include "load.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "arena.h"
#include "check.h"
#include "eval.h"
#include "lang.h"
#include "xalloc.h"

/* Reads standard input whole, like lang_read_file. */
static int read_stdin(char **text, uint32_t *len)
{
	size_t cap = 1 << 16, n = 0;
	char *buf = xmalloc(cap);
	size_t got;
	while ((got = fread(buf + n, 1, cap - n - 1, stdin)) > 0) {
		n += got;
		if (n + 1 == cap) {
			if (cap >= DIAG_MAX_SOURCE_BYTES) {
				free(buf);
				return EFBIG;
			}
			cap *= 2;
			buf = xrealloc(buf, cap);
		}
	}
	if (ferror(stdin)) {
		free(buf);
		return errno ? errno : EIO;
	}
	buf[n] = '\0';
	*text = buf;
	*len = (uint32_t)n;
	return 0;
}

static double now(void)
{
	struct timespec ts;
	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (double)ts.tv_sec + ts.tv_nsec * 1e-9;
}

enum load_status lang_load_scene(struct diag *d, const char *path, struct scene_desc *out,
                                 struct load_times *times)
{
	struct load_times t = { 0 };
	double t0 = now();
	bool from_stdin = strcmp(path, "-") == 0;
	scene_desc_init(out);
	char *text;
	uint32_t len;
	int err = from_stdin ? read_stdin(&text, &len) : lang_read_file(path, &text, &len);
	if (err) {
		diag_plain(d, DIAG_ERROR, "cannot read '%s': %s", from_stdin ? "<stdin>" : path,
		           err == EFBIG ? "larger than 256 MiB" : strerror(err));
		return LOAD_IO_ERROR;
	}
	const struct source *src = diag_add_source(d, from_stdin ? "<stdin>" : path, text, len, NULL,
	                                           (struct span){ 0, 0 });
	struct arena *a = arena_new();
	struct ast_list stmts = lang_parse(a, d, src);
	double t1 = now();
	t.parse = t1 - t0;
	unsigned nslots = lang_check(a, d, src, &stmts); /* parses included files too */
	double t2 = now();
	t.check = t2 - t1;
	if (d->errors == 0)
		lang_eval(d, &stmts, nslots, out);
	t.eval = now() - t2;
	arena_free(a);
	if (times)
		*times = t;
	return d->errors ? LOAD_SCENE_ERROR : LOAD_OK;
}
