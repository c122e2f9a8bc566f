/* xalloc.c: allocation that never returns NULL. Callers never check; running out of
 * memory ends the program with exit status 4, as LANGUAGE.md section 8 specifies, after
 * removing the temporary files of unfinished output (cleanup.h). Every report of running
 * out of memory, here or in a library's allocation, goes through xout_of_memory. */
#define _DEFAULT_SOURCE 1 /* madvise's MADV_HUGEPAGE, beside the build's _XOPEN_SOURCE */
#include "xalloc.h"

#include "cleanup.h"

#include <stdarg.h>
#include <stdatomic.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>

/* Two ways for the test suite to reach the out-of-memory path, which the up-front memory
 * checks (memory.h) otherwise keep ulimit from reaching:
 *   SCN_ALLOC_LIMIT=BYTES  every allocation larger than BYTES fails;
 *   SCN_ALLOC_FAIL=N       the N-th allocation fails (counting from 1, xcheck's too), so
 *                          that a test can fail each allocation of a run in turn.
 * Read at the first allocation, which comes before any thread starts; the count is
 * atomic, as threads allocate too, and kept only when SCN_ALLOC_FAIL is set. */
static struct {
	bool known;
	size_t limit;
	unsigned long fail_at;         /* 0: none */
	atomic_ulong count;
} faults;

/* Whether this allocation of size bytes is to fail. */
static bool injected(size_t size)
{
	if (!faults.known) {
		const char *s = getenv("SCN_ALLOC_LIMIT");
		faults.limit = s && *s ? (size_t)strtoull(s, NULL, 10) : SIZE_MAX;
		s = getenv("SCN_ALLOC_FAIL");
		faults.fail_at = s && *s ? strtoul(s, NULL, 10) : 0;
		faults.known = true;
	}
	if (size > faults.limit)
		return true;
	return faults.fail_at && atomic_fetch_add(&faults.count, 1) + 1 == faults.fail_at;
}

_Noreturn void xout_of_memory(const char *fmt, ...)
{
	char what[512];
	va_list ap;
	va_start(ap, fmt);
	vsnprintf(what, sizeof what, fmt, ap);
	va_end(ap);
	fprintf(stderr, "scn: out of memory (%s)\n", what);
	cleanup_exit(4);
}

static _Noreturn void out_of_memory(size_t size)
{
	xout_of_memory("requesting %zu bytes", size);
}

void *xcheck(void *p, const char *what)
{
	if (!p || injected(0))
		xout_of_memory("%s", what);
	return p;
}

void *xmalloc(size_t size)
{
	void *p = !injected(size) ? malloc(size ? size : 1) : NULL;
	if (!p)
		out_of_memory(size);
	return p;
}

void *xcalloc(size_t count, size_t size)
{
	if (size && count > SIZE_MAX / size)
		out_of_memory(SIZE_MAX);
	void *p = !injected(count * size) ? calloc(count ? count : 1, size ? size : 1) : NULL;
	if (!p)
		out_of_memory(count * size);
	return p;
}

void *xrealloc(void *ptr, size_t size)
{
	void *p = !injected(size) ? realloc(ptr, size ? size : 1) : NULL;
	if (!p)
		out_of_memory(size);
	return p;
}

void *xaligned_alloc(size_t align, size_t size)
{
	void *p = !injected(size) ? aligned_alloc(align, size ? size : align) : NULL;
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
