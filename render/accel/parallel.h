/* parallel.h: a loop's iterations on every core, for passes over big arrays (the BVH's
 * build, collapse and reordering): deterministic, as what an iteration does depends on
 * its index alone. */
#ifndef SCN_PARALLEL_H
#define SCN_PARALLEL_H

#include <stddef.h>

enum { MAX_CHUNKS = 64 }; /* the most pieces parallel_chunks() cuts a pass into */

/* Runs fn(ctx, i) for each i in [0, n) on up to as many threads as there are processors
 * (the calling one among them), each thread taking the next i. */
void parallel_for(size_t n, void (*fn)(void *ctx, size_t i), void *ctx);

/* The pieces a pass over n items is cut into for parallel_for (one when n is small, at
 * most MAX_CHUNKS), and the items [lo, hi) of piece c. */
size_t parallel_chunks(size_t n);
void parallel_chunk_items(size_t n, size_t nchunks, size_t c, size_t *lo, size_t *hi);

#endif
