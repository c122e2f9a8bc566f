/* render.h: the tile and thread loop that turns a lowered scene into an image: whole
 * (render_image), or tile by tile as a caller feeds them (the pool, which the render over
 * processes, render/dist, drives). */
#ifndef SCN_RENDER_H
#define SCN_RENDER_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "image.h"
#include "scene.h"
#include "trace.h"

struct render_options {
	int threads;                   /* workers; 0: one per core */
	int x0, y0, x1, y1;            /* the pixel rectangle [x0, x1) x [y0, y1) to render */
	int64_t whole_pixels;          /* the pixels of the image the rectangle is part of (a
	                                * --tile part's whole), whose count sets the share of
	                                * probe pixels (render.c); 0: the rectangle is the whole */
	bool progress;                 /* a progress bar with an ETA on standard error */
};

/* Renders the rectangle of sc's camera image into img, whose size is the rectangle's;
 * the result depends on the scene and seed only, not on the thread count. Ray counts go
 * to st. Returns 0, or -1 when no thread could be started. */
int render_image(const struct scene *sc, const struct render_options *opt, struct image *img, struct ray_stats *st);

/* The rectangle's tiles: RENDER_TILE pixels square (smaller at its right and bottom
 * edges), numbered row by row from 0. */
enum { RENDER_TILE = 16 };
int render_tile_count(const struct render_options *opt);
/* Tile t's pixels, [x, x + w) x [y, y + h) in the camera's image. */
void render_tile_rect(const struct render_options *opt, int t, int *x, int *y, int *w, int *h);

/* Where the pool puts a tile's pixels: pixels(ctx, t, &stride) gives the place of tile
 * t's top-left pixel and the floats from one row to the next; done(ctx, t) follows the
 * tile's last pixel. Both are called on the workers' threads, each tile once. */
struct render_sink {
	float *(*pixels)(void *ctx, int t, size_t *stride);
	void (*done)(void *ctx, int t);
	void *ctx;
};

/* The sink that puts each tile in its place in img, an image of opt's rectangle: ctx is
 * a struct render_target. */
struct render_target {
	const struct render_options *opt;
	struct image *img;
};
float *render_image_pixels(void *ctx, int t, size_t *stride);

/* Worker threads that render the tiles they are fed, in the order fed; an idle worker
 * waits for more until the pool is closed. No lock is held while a tile renders. */
struct render_pool;
/* Starts opt->threads workers (0: one per core, never more than the tiles). NULL when
 * no thread could be started. */
struct render_pool *render_pool_start(const struct scene *sc, const struct render_options *opt,
                                      const struct render_sink *sink);
/* Tiles first, first + 1, ..., first + count - 1 are to be rendered. */
void render_pool_feed(struct render_pool *p, int first, int count);
/* No more tiles will be fed: the workers end once those fed are done. */
void render_pool_close(struct render_pool *p);
/* How many worker threads it has. */
int render_pool_threads(const struct render_pool *p);
/* How many tiles are done. */
int render_pool_done(struct render_pool *p);
/* Per tile, the sum over its probe pixels of the squared difference of two replicas
 * (render.c), 0 for a tile not rendered here: a render over processes sets the others'
 * tiles (render/dist) before render_pool_finish sums them, in tile order, so that the
 * estimate has the same bits whoever rendered which tile. */
double *render_pool_tile_probes(struct render_pool *p);
/* After render_pool_close: waits for the workers and frees the pool. *st gets their ray
 * counts plus *more (other processes' counts; may be NULL) and the error estimate from
 * every tile's probes. */
void render_pool_finish(struct render_pool *p, const struct ray_stats *more, struct ray_stats *st);

/* The progress bar, "[####....]  40%  ETA 3s", redrawn in place on standard error. */
void render_progress_show(int done, int total, double elapsed);

#endif
