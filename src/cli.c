/* cli.c: helpers for the subcommands' argument parsing, and their memory check. */
#include "cli.h"

#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "diag.h"
#include "memory.h"
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

int cli_scene_arg(const struct command *cmd, const char *arg, const char **scene)
{
	if (arg[0] == '-' && arg[1] != '\0')
		return 0;
	if (*scene) {
		cli_usage_error(cmd, "more than one scene given ('%s')", arg);
		return -1;
	}
	*scene = arg;
	return 1;
}

const char *cli_value(int argc, char **argv, int *i)
{
	if (*i + 1 >= argc)
		return NULL;
	return argv[++*i];
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
