/* xalloc.c: allocation that never returns NULL. Callers never check; running out of
 * memory ends the program with exit status 4, as LANGUAGE.md section 8 specifies, after
 * removing the temporary files of unfinished output (cleanup.h). */
#define _DEFAULT_SOURCE 1 /* madvise's MADV_HUGEPAGE, beside the build's _XOPEN_SOURCE */
#include "xalloc.h"

#include "cleanup.h"

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>

/* SCN_ALLOC_LIMIT=BYTES makes every allocation larger than BYTES fail as if memory had
 * run out: the test suite's way to reach this path in a render, which the up-front
 * memory checks (memory.h) otherwise keep ulimit from reaching. Read at the first
 * allocation, which comes before any thread starts. */
static size_t alloc_limit(void)
{
	static size_t limit;
	static bool known;
	if (!known) {
		const char *s = getenv("SCN_ALLOC_LIMIT");
		limit = s && *s ? (size_t)strtoull(s, NULL, 10) : SIZE_MAX;
		known = true;
	}
	return limit;
}

static void out_of_memory(size_t size)
{
	fprintf(stderr, "scn: out of memory (requesting %zu bytes)\n", size);
	cleanup_exit(4);
}

void *xmalloc(size_t size)
{
	void *p = size <= alloc_limit() ? malloc(size ? size : 1) : NULL;
	if (!p)
		out_of_memory(size);
	return p;
}

void *xcalloc(size_t count, size_t size)
{
	if (size && count > SIZE_MAX / size)
		out_of_memory(SIZE_MAX);
	void *p = count * size <= alloc_limit() ? calloc(count ? count : 1, size ? size : 1) : NULL;
	if (!p)
		out_of_memory(count * size);
	return p;
}

void *xrealloc(void *ptr, size_t size)
{
	void *p = size <= alloc_limit() ? realloc(ptr, size ? size : 1) : NULL;
	if (!p)
		out_of_memory(size);
	return p;
}

void *xaligned_alloc(size_t align, size_t size)
{
	void *p = size <= alloc_limit() ? aligned_alloc(align, size ? size : align) : NULL;
	if (!p)
		out_of_memory(size);
	return p;
}

void *xbig_alloc(size_t size)
{
	if (size < XBIG_PAGE)
		return xaligned_alloc(64, (size + 63) / 64 * 64);
	if (size > SIZE_MAX - XBIG_PAGE)
		out_of_memory(SIZE_MAX);
	size_t whole = (size + XBIG_PAGE - 1) / XBIG_PAGE * XBIG_PAGE;
	void *p = xaligned_alloc(XBIG_PAGE, whole);
#ifdef MADV_HUGEPAGE
	madvise(p, whole, MADV_HUGEPAGE); /* advice: no harm done if the kernel declines it */
#endif
	return p;
}

void xgrow(void **ptr, size_t *cap, size_t need, size_t elem)
{
	if (need <= *cap)
		return;
	size_t n = *cap ? *cap : 8;
	while (n < need) {
		if (n > SIZE_MAX / 2 / elem)
			out_of_memory(SIZE_MAX);
		n *= 2;
	}
	*ptr = xrealloc(*ptr, n * elem);
	*cap = n;
}

char *xstrdup(const char *s)
{
	size_t n = strlen(s) + 1;
	return memcpy(xmalloc(n), s, n);
}
