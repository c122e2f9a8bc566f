/* xalloc.h: allocation that never returns NULL; on failure scn says so and exits 4,
 * through the one path that removes unfinished output (cleanup.h). */
#ifndef SCN_XALLOC_H
#define SCN_XALLOC_H

#include <stddef.h>

void *xmalloc(size_t size);
void *xcalloc(size_t count, size_t size);
void *xrealloc(void *ptr, size_t size);
/* size bytes at a multiple of align (a power of two that divides size); free() frees it. */
void *xaligned_alloc(size_t align, size_t size);
/* size bytes for a big array read at random, cache-line aligned; from XBIG_PAGE bytes on,
 * in whole pages of XBIG_PAGE (so up to XBIG_PAGE - 1 more) that the kernel is asked to
 * back with transparent huge pages where it offers them (Linux: THP on madvise or always),
 * so that a read at random does not also miss the TLB, whose 4 KiB pages reach a few
 * megabytes. free() frees it. */
enum { XBIG_PAGE = 2 << 20 };
void *xbig_alloc(size_t size);
/* Grows *ptr (an array of *cap elements of elem bytes) to hold at least need elements. */
void xgrow(void **ptr, size_t *cap, size_t need, size_t elem);
char *xstrdup(const char *s);

/* Running out of memory: "scn: out of memory (WHAT)" on standard error, WHAT from fmt,
 * then cleanup_exit(4). For what a library allocates, which it reports as a failure of
 * its own. */
_Noreturn void xout_of_memory(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
/* p, a library's allocation (a stream, a scanner); when it is NULL, or when SCN_ALLOC_FAIL
 * makes this allocation fail, xout_of_memory(what). */
void *xcheck(void *p, const char *what);

#endif
