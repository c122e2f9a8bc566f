/* pov_hint.c: scn's equivalents of POV-Ray's command-line options, for the users who
 * type +W320 +H240 +A0.3 out of habit. */
#include "pov_hint.h"

#include <stdbool.h>
#include <stdio.h>
#include <string.h>
#include <strings.h>

#include "cli.h"

/* POV-Ray's first and final frame, +KFI and +KFF, are the two ends of one option */
#define FRAMES "--frames A..B (+KFI1 +KFF24 is --frames 1..25: B is one past the last frame)"

/* The options with an equivalent, the longer of two that share a start first. */
static const struct {
	const char *pov;     /* its letters after the '+', in any case (POV-Ray's are) */
	bool numeric;        /* only with a number, or nothing, after them: +WL2 is not +W */
	const char *needs;   /* the option of the command that the hint names (a letter or a long
	                      * name), without which the command has no equivalent; NULL: none */
	const char *scn;     /* what scn writes */
	const char *metavar; /* set: POV-Ray's value follows scn's words, or this without one */
} equivalents[] = {
	{ "WT", true, "j", "-j", "THREADS" },
	{ "W", true, "W", "-W", "WIDTH" },
	{ "H", true, "H", "-H", "HEIGHT" },
	{ "O", false, "o", "-o", "OUT" },
	{ "AM", true, "s", "-s SAMPLES (and -p PATTERN)", NULL },
	{ "A", true, "s", "-s SAMPLES (and -p PATTERN)", NULL },
	{ "R", true, "s", "-s SAMPLES (and -p PATTERN)", NULL },
	{ "J", true, "p", "-p jittered", NULL },
	{ "SR", true, "region", "--region X0,Y0,X1,Y1", NULL },
	{ "SC", true, "region", "--region X0,Y0,X1,Y1", NULL },
	{ "ER", true, "region", "--region X0,Y0,X1,Y1", NULL },
	{ "EC", true, "region", "--region X0,Y0,X1,Y1", NULL },
	{ "F", false, "bit-depth", "-o OUT (.png, .exr or .ppm) and --bit-depth 8|16", NULL },
	{ "KFI", true, "frames", FRAMES, NULL },
	{ "KFF", true, "frames", FRAMES, NULL },
	{ "KC", true, "cyclic", "--cyclic", NULL },
	{ "K", true, "clock", "--clock", "C" },
	{ "I", false, NULL, "the scene's name alone:", "SCENE" },
};

/* Whether one of the n options opts is spec: a letter, or a long name. */
static bool has_option(const struct cli_option *opts, int n, const char *spec)
{
	for (int i = 0; i < n; i++)
		if (spec[1] ? opts[i].name && strcmp(opts[i].name, spec) == 0 : opts[i].letter == spec[0])
			return true;
	return false;
}

const char *pov_hint(const char *arg, const struct cli_option *opts, int n, char *buf, size_t size)
{
	for (size_t k = 0; k < sizeof equivalents / sizeof equivalents[0]; k++) {
		size_t len = strlen(equivalents[k].pov);
		const char *rest = arg + 1 + len;
		if (strncasecmp(arg + 1, equivalents[k].pov, len) != 0 ||
		    (equivalents[k].numeric && rest[strspn(rest, "0123456789.")] != '\0'))
			continue;
		if (equivalents[k].needs && !has_option(opts, n, equivalents[k].needs))
			return NULL;
		if (equivalents[k].metavar)
			snprintf(buf, size, "%s %s", equivalents[k].scn, *rest ? rest : equivalents[k].metavar);
		else
			snprintf(buf, size, "%s", equivalents[k].scn);
		return buf;
	}
	return NULL;
}
