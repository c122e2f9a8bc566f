/* xalloc.h: allocation that never returns NULL; on failure scn says so and exits 4. */
#ifndef SCN_XALLOC_H
#define SCN_XALLOC_H

#include <stddef.h>

void *xmalloc(size_t size);
void *xcalloc(size_t count, size_t size);
void *xrealloc(void *ptr, size_t size);
/* size bytes at a multiple of align (a power of two that divides size); free() frees it. */
void *xaligned_alloc(size_t align, size_t size);
/* size bytes for a big array read at random (the BVH's nodes, packets and primitives),
 * cache-line aligned; from 2 MiB on, in whole 2 MiB pages the kernel is asked to back
 * with transparent huge pages where it offers them (Linux: madvise, or always), so that
 * a random read does not also miss the TLB: in 4 KiB pages a 100 MB array is 25,000
 * pages, against a TLB of 1,500 or so. free() frees it. */
void *xbig_alloc(size_t size);
/* Grows *ptr (an array of *cap elements of elem bytes) to hold at least need elements. */
void xgrow(void **ptr, size_t *cap, size_t need, size_t elem);
char *xstrdup(const char *s);

#endif
