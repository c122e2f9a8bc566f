/* suggest.h: "did you mean" for misspelt names, and hints for POV-Ray's words. */
#ifndef SCN_SUGGEST_H
#define SCN_SUGGEST_H

#include <stddef.h>

/* Keeps the closest candidate to name seen so far. */
struct suggestion {
	const char *name;
	const char *best;
	unsigned dist;
};

void suggest_init(struct suggestion *s, const char *name);
void suggest_consider(struct suggestion *s, const char *candidate);
/* "; did you mean 'x'?" in buf, or "" when no candidate was close enough. */
const char *suggest_text(const struct suggestion *s, char *buf, size_t size);
/* " (what scn writes instead)" in buf for a word POV-Ray users write, or NULL. */
const char *suggest_pov_hint(const char *name, char *buf, size_t size);

#endif
