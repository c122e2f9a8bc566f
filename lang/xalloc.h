/* xalloc.h: allocation that never returns NULL; on failure scn says so and exits 4. */
#ifndef SCN_XALLOC_H
#define SCN_XALLOC_H

#include <stddef.h>

void *xmalloc(size_t size);
void *xcalloc(size_t count, size_t size);
void *xrealloc(void *ptr, size_t size);
/* size bytes at a multiple of align (a power of two that divides size); free() frees it. */
void *xaligned_alloc(size_t align, size_t size);
/* Grows *ptr (an array of *cap elements of elem bytes) to hold at least need elements. */
void xgrow(void **ptr, size_t *cap, size_t need, size_t elem);
char *xstrdup(const char *s);

#endif
