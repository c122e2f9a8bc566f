/* parallel.c: parallel_for() on pthreads, and the chunks a pass is cut into. */
#include "parallel.h"

#include <pthread.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <unistd.h>

#include "xalloc.h"

/* Items in a pass from which it is cut into MAX_CHUNKS pieces, so that threads share
 * the work evenly; below it, a thread's start costs more than the pass. */
enum { MIN_CHUNKED = 4096 };

struct parallel {
	void (*fn)(void *ctx, size_t i);
	void *ctx;
	size_t n;
	atomic_size_t next;
};

static void *parallel_worker(void *arg)
{
	struct parallel *p = arg;
	for (size_t i; (i = atomic_fetch_add(&p->next, 1)) < p->n;)
		p->fn(p->ctx, i);
	return NULL;
}

void parallel_for(size_t n, void (*fn)(void *ctx, size_t i), void *ctx)
{
	struct parallel p = { .fn = fn, .ctx = ctx, .n = n };
	atomic_init(&p.next, 0);
	long cores = sysconf(_SC_NPROCESSORS_ONLN);
	size_t threads = cores > 1 ? (size_t)cores : 1;
	if (threads > n)
		threads = n;
	pthread_t *tid = xcalloc(threads > 1 ? threads - 1 : 1, sizeof *tid);
	size_t started = 0;
	while (started + 1 < threads && pthread_create(&tid[started], NULL, parallel_worker, &p) == 0)
		started++;
	parallel_worker(&p); /* if no thread could start, this one does it all */
	for (size_t i = 0; i < started; i++)
		pthread_join(tid[i], NULL);
	free(tid);
}

size_t parallel_chunks(size_t n)
{
	return n > MIN_CHUNKED ? MAX_CHUNKS : 1;
}

void parallel_chunk_items(size_t n, size_t nchunks, size_t c, size_t *lo, size_t *hi)
{
	*lo = n * c / nchunks;
	*hi = n * (c + 1) / nchunks;
}
