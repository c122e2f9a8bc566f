/* arena.h: bump allocator for everything the front end makes; one arena_free releases it all. */
#ifndef SCN_ARENA_H
#define SCN_ARENA_H

#include <stddef.h>

struct arena;

struct arena *arena_new(void);
void arena_free(struct arena *a);
/* Releases everything allocated so far, but what arena_keep kept; the arena stays usable. */
void arena_reset(struct arena *a);
/* Makes everything allocated so far outlive arena_reset (until arena_free): a
 * definition's tree, which runs at each call, among trees released one at a time. */
void arena_keep(struct arena *a);

/* A moment of an arena, to release what was allocated after it (last in, first out). */
struct arena_mark {
	struct block *head;
	size_t used;
	unsigned long long seq;
};
struct arena_mark arena_mark(const struct arena *a);
void arena_release(struct arena *a, struct arena_mark m);
/* Zeroed, aligned for pointers and doubles (not for long double or vector types); never
 * NULL (exits 4 when memory runs out). */
void *arena_alloc(struct arena *a, size_t size);
char *arena_strndup(struct arena *a, const char *s, size_t n);

#endif
