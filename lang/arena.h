/* arena.h: bump allocator for everything the front end makes; one arena_free releases it all. */
#ifndef SCN_ARENA_H
#define SCN_ARENA_H

#include <stddef.h>

struct arena;

struct arena *arena_new(void);
void arena_free(struct arena *a);
/* Releases everything allocated so far; the arena stays usable. */
void arena_reset(struct arena *a);
/* Zeroed, aligned for pointers and doubles (not for long double or vector types); never
 * NULL (exits 4 when memory runs out). */
void *arena_alloc(struct arena *a, size_t size);
char *arena_strndup(struct arena *a, const char *s, size_t n);

#endif
