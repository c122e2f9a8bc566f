/* cli.c: the subcommands' argument parsing (getopt_long over each one's option table, with
 * scn's messages), their usage errors and option values, and their memory check. */
#include "cli.h"

#include <assert.h>
#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "diag.h"
#include "memory.h"
#include "pov_hint.h"
#include "suggest.h"
#include "xalloc.h"

int cli_usage_error(const struct command *cmd, const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	fputs("scn: ", stderr);
	vfprintf(stderr, fmt, ap);
	va_end(ap);
	fprintf(stderr, "\nusage: %s\n", cmd ? cmd->usage : "scn COMMAND [ARGS]; see 'scn --help'");
	return EXIT_USAGE;
}

int cli_help(const struct command *cmd)
{
	printf("usage: %s\n\n%s", cmd->usage, cmd->help);
	return 0;
}

/* getopt_long's value for opts[i] given by its long name (or --help, i = nopts): above
 * every letter, so that a failure's optopt tells a long option from a short one. */
enum { LONG_BASE = 256 };

void cli_parser_init(struct cli_parser *p, const struct command *cmd, const struct cli_option *opts, int nopts,
                     int argc, char **argv)
{
	assert(nopts <= CLI_MAX_OPTIONS);
	*p = (struct cli_parser){ .cmd = cmd, .opts = opts, .nopts = nopts, .argc = argc, .argv = argv };
	char *s = p->shorts;
	struct option *l = p->longs;
	*s++ = ':';   /* a missing value returns ':', not '?' */
	*s++ = 'h';
	*l++ = (struct option){ "help", no_argument, NULL, LONG_BASE + nopts };
	for (int i = 0; i < nopts; i++) {
		if (opts[i].letter) {
			*s++ = opts[i].letter;
			if (opts[i].value)
				*s++ = ':';
		}
		if (opts[i].name)
			*l++ = (struct option){ opts[i].name, opts[i].value ? required_argument : no_argument, NULL,
			                        LONG_BASE + i };
	}
	*s = '\0';
	*l = (struct option){ 0 };
	optind = 0;   /* glibc: start afresh, forgetting any earlier scan */
	opterr = 0;   /* the messages are ours */
}

/* The long name of option i (nopts: help), or NULL. */
static const char *long_name(const struct cli_parser *p, int i)
{
	return i == p->nopts ? "help" : p->opts[i].name;
}

/* Reports the unknown or ambiguous long option arg (its "=value" left out), with the
 * options it abbreviates, or the closest one to a misspelling. */
static int bad_long_option(const struct cli_parser *p, const char *arg)
{
	int len = (int)strcspn(arg + 2, "=");
	char matches[256] = "", word[64];
	int nmatch = 0;
	for (int i = 0; i <= p->nopts; i++) {
		const char *name = long_name(p, i);
		if (name && strncmp(name, arg + 2, (size_t)len) == 0) {
			size_t used = strlen(matches);
			snprintf(matches + used, sizeof matches - used, "%s--%s", nmatch++ ? ", " : "", name);
		}
	}
	if (nmatch > 1)
		return cli_usage_error(p->cmd, "ambiguous option '%.*s' for %s (%s)", len + 2, arg, p->cmd->name, matches);
	snprintf(word, sizeof word, "%.*s", len, arg + 2);
	struct suggestion sg;
	suggest_init(&sg, word);
	for (int i = 0; i <= p->nopts; i++)
		if (long_name(p, i))
			suggest_consider(&sg, long_name(p, i));
	return cli_usage_error(p->cmd, "unknown option '%.*s' for %s%s%s%s", len + 2, arg, p->cmd->name,
	                       sg.best ? "; did you mean '--" : "", sg.best ? sg.best : "", sg.best ? "'?" : "");
}

/* The usage error for getopt_long's failure c: '?' or ':' (a missing value). */
static int option_error(const struct cli_parser *p, int c)
{
	if (optopt >= LONG_BASE) /* a long name, known */
		return cli_usage_error(p->cmd, c == ':' ? "option '--%s' needs a value" : "option '--%s' takes no value",
		                       long_name(p, optopt - LONG_BASE));
	if (optopt) /* a letter */
		return cli_usage_error(p->cmd, c == ':' ? "option '-%c' needs a value" : "unknown option '-%c' for %s",
		                       optopt, p->cmd->name);
	/* a long name, unknown or ambiguous: getopt_long has just stepped past it */
	return bad_long_option(p, p->argv[optind - 1]);
}

int cli_next_option(struct cli_parser *p)
{
	int c = getopt_long(p->argc, p->argv, p->shorts, p->longs, NULL);
	if (c == -1)
		return CLI_END;
	if (c == '?' || c == ':') {
		p->status = option_error(p, c);
		return CLI_STOP;
	}
	int i = c - LONG_BASE;
	if (c < LONG_BASE)
		for (i = c == 'h' ? p->nopts : 0; i < p->nopts && p->opts[i].letter != c; i++)
			;
	if (i == p->nopts) {
		cli_help(p->cmd);
		p->status = -1;
		return CLI_STOP;
	}
	if (c < LONG_BASE)
		snprintf(p->name, sizeof p->name, "-%c", c);
	else
		snprintf(p->name, sizeof p->name, "--%s", p->opts[i].name);
	p->value = optarg;
	return i;
}

/* The usage error for an operand that starts with '+' and names no file: POV-Ray's
 * options start so, and without this one is taken for a second scene. */
static int pov_option(const struct cli_parser *p, const char *arg)
{
	char buf[160];
	const char *hint = pov_hint(arg, p->opts, p->nopts, buf, sizeof buf);
	if (hint)
		return cli_usage_error(p->cmd, "'%s' looks like a POV-Ray option; scn %s's equivalent is %s", arg,
		                       p->cmd->name, hint);
	return cli_usage_error(p->cmd, "'%s' looks like a POV-Ray option, and POV-Ray's options are not scn's; see "
	                       "'scn help %s'", arg, p->cmd->name);
}

char **cli_operands(struct cli_parser *p, int *n)
{
	*n = p->argc - optind;
	char **ops = p->argv + optind;
	for (int k = 0; k < *n; k++)
		if (ops[k][0] == '+' && access(ops[k], F_OK) != 0) {
			pov_option(p, ops[k]);
			return NULL;
		}
	return ops;
}

const char *cli_scene(struct cli_parser *p)
{
	int n;
	char **ops = cli_operands(p, &n);
	if (!ops)
		return NULL;
	if (n == 0)
		cli_usage_error(p->cmd, "no scene given");
	else if (n > 1)
		cli_usage_error(p->cmd, "more than one scene given ('%s')", ops[1]);
	return n == 1 ? ops[0] : NULL;
}

bool cli_int(const char *s, long lo, long hi, long *out)
{
	char *end;
	errno = 0;
	long v = strtol(s, &end, 10);
	if (errno || end == s || *end || v < lo || v > hi)
		return false;
	*out = v;
	return true;
}

int cli_file_status(int e)
{
	return e == ENOMEM ? EXIT_RENDER : EXIT_IO;
}

int cli_memory_fits(struct diag *d, const struct span *at, const char *options, const char *what, uint64_t bytes)
{
	char msg[160];
	if (memory_fits(bytes, msg, sizeof msg))
		return 0;
	if (at)
		diag_error(d, *at, "%s %s", what, msg);
	else
		diag_plain(d, DIAG_ERROR, "%s: %s %s", options, what, msg);
	return EXIT_RENDER;
}

char *cli_default_output(const char *scene, const char *ext)
{
	const char *base = strrchr(scene, '/');
	base = strcmp(scene, "-") == 0 ? "stdin" : base ? base + 1 : scene;
	const char *dot = strrchr(base, '.');
	size_t n = dot && dot != base ? (size_t)(dot - base) : strlen(base);
	size_t e = strlen(ext);
	char *out = xmalloc(n + e + 1);
	memcpy(out, base, n);
	memcpy(out + n, ext, e + 1);
	return out;
}
