/* pov_hint.h: what scn writes for a POV-Ray command-line option such as +W320. */
#ifndef SCN_POV_HINT_H
#define SCN_POV_HINT_H

#include <stddef.h>

struct cli_option;

/* scn's equivalent of POV-Ray's option arg ("+W320": "-W 320") in buf, when the command
 * with the n options opts has one; NULL otherwise. */
const char *pov_hint(const char *arg, const struct cli_option *opts, int n, char *buf, size_t size);

#endif
