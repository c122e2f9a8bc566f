/* arena.c: chained blocks and a bump pointer. Grammar actions allocate here and never
 * free, so error recovery cannot leak. Under AddressSanitizer every request gets a block
 * of its own, of exactly its size, so that reading past a node (which is only as large
 * as its kind needs) is caught. */
#include "arena.h"

#include <stdalign.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "xalloc.h"

enum { BLOCK_SIZE = 64 * 1024 };

#if defined(__SANITIZE_ADDRESS__)
#define EXACT_BLOCKS 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define EXACT_BLOCKS 1
#endif
#endif
#ifndef EXACT_BLOCKS
#define EXACT_BLOCKS 0
#endif

struct block {
	struct block *next;
	size_t used, size;
	unsigned long long seq;    /* blocks are numbered as made: arena_release frees the newer */
	alignas(max_align_t) unsigned char data[];
};

struct arena {
	struct block *head;
	unsigned long long nblocks;
	bool kept;                 /* arena_keep was called: arena_reset goes back to floor */
	struct arena_mark floor;
};

struct arena *arena_new(void)
{
	return xcalloc(1, sizeof(struct arena));
}

static void free_blocks(struct block *b)
{
	for (struct block *next; b; b = next) {
		next = b->next;
		free(b);
	}
}

void arena_free(struct arena *a)
{
	if (!a)
		return;
	free_blocks(a->head);
	free(a);
}

void arena_keep(struct arena *a)
{
	a->kept = true;
	a->floor = arena_mark(a);
}

struct arena_mark arena_mark(const struct arena *a)
{
	return (struct arena_mark){ a->head, a->head ? a->head->used : 0, a->nblocks };
}

/* The blocks made after the mark are newer than its count. A new block goes first in the
 * list, or (a big one) right after the first: the newer blocks are the ones ahead of the
 * head at the mark and a run right after it, and that head is the only older block
 * allocated from since. Releasing costs what it frees. */
void arena_release(struct arena *a, struct arena_mark m)
{
	while (a->head && a->head->seq >= m.seq) {
		struct block *b = a->head;
		a->head = b->next;
		free(b);
	}
	if (!a->head)
		return;
	while (a->head->next && a->head->next->seq >= m.seq) {
		struct block *b = a->head->next;
		a->head->next = b->next;
		free(b);
	}
	if (a->head == m.head)
		a->head->used = m.used;
}

void arena_reset(struct arena *a)
{
	if (a->kept) {
		arena_release(a, a->floor);
		return;
	}
	/* one standard block is kept: a load that resets after every statement reuses the
	 * same (cached) memory rather than going back to malloc; under AddressSanitizer all
	 * goes, so that a use after the reset is caught */
	struct block *keep = NULL;
	for (struct block *b = a->head, *next; b; b = next) {
		next = b->next;
		if (!keep && b->size == BLOCK_SIZE && !EXACT_BLOCKS)
			keep = b;
		else
			free(b);
	}
	if (keep) {
		keep->next = NULL;
		keep->used = 0;
	}
	a->head = keep;
}

void *arena_alloc(struct arena *a, size_t size)
{
	const size_t align = alignof(double) > alignof(void *) ? alignof(double) : alignof(void *);
	if (!EXACT_BLOCKS)
		size = (size + align - 1) & ~(align - 1);
	struct block *b = a->head;
	if (!b || b->size - b->used < size || EXACT_BLOCKS) {
		/* Big requests get a block of their own, so a block wastes at most its tail. */
		size_t cap = size > BLOCK_SIZE / 4 || EXACT_BLOCKS ? size : BLOCK_SIZE;
		if (cap > SIZE_MAX - sizeof *b)
			cap = SIZE_MAX - sizeof *b; /* xmalloc then fails cleanly */
		b = xmalloc(sizeof *b + cap);
		b->used = 0;
		b->size = cap;
		b->seq = a->nblocks++;
		if (a->head && cap != BLOCK_SIZE) {
			/* keep the current block's free space for the next small request */
			b->next = a->head->next;
			a->head->next = b;
		} else {
			b->next = a->head;
			a->head = b;
		}
	}
	void *p = b->data + b->used;
	b->used += size;
	return memset(p, 0, size);
}

char *arena_strndup(struct arena *a, const char *s, size_t n)
{
	char *p = arena_alloc(a, n + 1);
	memcpy(p, s, n);
	p[n] = '\0';
	return p;
}
