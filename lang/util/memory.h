/* memory.h: how much memory a run may have, so that a request too big for the machine
 * (an image, a mesh and its BVH) is refused before any of it is allocated, saying what
 * was asked and what there is. */
#ifndef SCN_MEMORY_H
#define SCN_MEMORY_H

#include <stddef.h>
#include <stdbool.h>
#include <stdint.h>

/* The bytes this process may still allocate: the least of the machine's physical memory,
 * the address-space limit (ulimit -v) less what is mapped already, and the data-size
 * limit (ulimit -d) less the data already in use. *what says which, as in "this machine
 * has" / "ulimit -v leaves" / "ulimit -d leaves". */
uint64_t memory_available(const char **what);

/* bytes in the largest binary unit that keeps it at 1 or more: "3.0 GiB", "512 MiB". */
void memory_text(uint64_t bytes, char *buf, size_t n);

/* Whether need bytes fit; if not, writes "needs X; this machine has Y" (or the limit
 * that is smaller) into msg. */
bool memory_fits(uint64_t need, char *msg, size_t n);

#endif
