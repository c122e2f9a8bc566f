/* render.c: the render loop, written once: worker threads take 16x16 tiles as they are
 * fed (all at once for render_image, a few at a time from another process for a render
 * over processes), and every pixel's value depends only on the pixel and its samples, so
 * the image is the same whatever the thread count, process count or tile order. One
 * lock per tile, none per pixel. */
#include "render.h"

#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "camera.h"
#include "cleanup.h"
#include "clock.h"
#include "sampler.h"
#include "stream.h"
#include "xalloc.h"

/* Tiles fed and not yet taken: ranges in the order fed. */
struct feed_range {
	int first, count;
};

struct worker;

struct render_pool {
	const struct scene *sc;
	struct sampler *proto;         /* each worker samples through a clone of it */
	struct render_options opt;
	struct render_sink sink;
	int ntiles;
	double probe_share;            /* of the pixels, chosen by hash, that estimate the error */
	double *tile_probe;            /* per tile: render_pool_tile_probes */
	pthread_mutex_t lock;          /* over the feed, taken once per tile */
	pthread_cond_t fed;
	struct feed_range *ranges;
	size_t head, nranges, cap;     /* ranges[head .. nranges) are left */
	bool closed;
	atomic_int done_tiles;
	struct worker *workers;
	int started;
};

struct worker {
	pthread_t thread;
	struct render_pool *pool;
	struct ray_stats stats;
};

/* Samples before an adaptive pixel may stop: fewer give too rough a variance estimate
 * (two samples that happen to agree on an edge pixel would end it). */
enum { MIN_ADAPTIVE = 8 };

/* The error estimate re-renders a random subset of pixels with an independent
 * randomisation of their pattern (a second replica) and compares the two means: for
 * independent, identically distributed replicas, E[(P1 - P2)^2] = 2 Var(P), with no
 * assumption about the pattern (Owen, "Monte Carlo theory, methods and examples", ch. 17,
 * on replicated randomised quasi-Monte Carlo). The sample variance within one pixel
 * cannot do this: it overstates the error of stratified and Poisson-disc patterns, whose
 * samples are not independent (1.4 to 2.6 times here, measured). The replica is left out
 * of the image, so the image is the same with or without it. PROBE_SHARE of the pixels,
 * but at least PROBE_MIN of them, take part: 6% more camera rays on a large image, and
 * enough probes on a small one for the mean of a heavy-tailed difference to settle. */
#define PROBE_SHARE (1.0 / 16)
enum { PROBE_MIN = 4096 };
#define PROBE_KEY ((uint64_t)1 << 32)  /* hash key of the choice; above sampler_pixel's keys */

/* The lens's dimension of a sample's stream; the area lights' are keyed by their paths
 * (trace.c), which start from 1. */
enum { DIM_LENS = 0 };

/* The ray of sample i of pixel (px, py) at image-plane offset (sx, sy), through the lens
 * where the sample's stream says when the camera has one. */
static struct ray sample_ray(const struct camera *cam, const struct sampler *sm, int px, int py, int i,
                             double sx, double sy, const struct sample_stream *ss)
{
	double u = (px + sx) / cam->width, v = (py + sy) / cam->height;
	int a, b, g;
	if (sampler_grid_cell(sm, i, &a, &b, &g)) {
		/* as the POV-Ray twin (a render at g times the size) computes it, so that no
		 * silhouette sub-sample rounds the other way */
		u = (g * (double)px + a + 0.5) / (g * (double)cam->width);
		v = (g * (double)py + b + 0.5) / (g * (double)cam->height);
	}
	struct ray r = camera_ray(cam, u, v);
	if (cam->lens_radius > 0) {
		struct stream_dim d;
		double lu, lv, x, y;
		stream_dim(ss, DIM_LENS, &d);
		stream_point(&d, 0, &lu, &lv);
		stream_disc(lu, lv, &x, &y);
		r = camera_lens_ray(cam, r, x, y);
	}
	return r;
}

/* One replica of a pixel: the mean of its samples (Welford's running mean and variance),
 * stopping early once the standard error of every channel is below the target at two
 * successive checks. Counts its camera rays in *camera. */
static struct vec3 pixel_mean(const struct scene *sc, struct sampler *sm, double *xy, int px, int py,
                              uint32_t replica, struct ray_stats *st, uint64_t *camera)
{
	const struct sampling *sp = &sc->sampling;
	sampler_pixel(sm, (uint32_t)px, (uint32_t)py, replica, xy);
	struct sample_stream ss = { 0, 0, (uint32_t)sp->count, sp->kind == SAMPLE_RANDOM };
	if (sc->streams)
		ss.key = stream_pixel_key(sp->seed, (uint32_t)px, (uint32_t)py, replica);
	struct vec3 mean = v3s(0), m2 = v3s(0);
	int k = 0;
	bool passed = false;          /* the last adaptive check found the error below the target */
	for (int i = 0; i < sp->count; i++) {
		ss.index = (uint32_t)i;
		struct ray r = sample_ray(&sc->camera, sm, px, py, i, xy[2 * i], xy[2 * i + 1], &ss);
		(*camera)++;
		struct vec3 c = trace_ray(sc, &r, trace_camera_path(), &ss, st);
		if (!isfinite(c.x) || !isfinite(c.y) || !isfinite(c.z)) {
			st->nonfinite++; /* counted, shown by --stats, and kept out of the image */
			continue;
		}
		k++;
		struct vec3 delta = vsub(c, mean);
		mean = vadd(mean, vscale(delta, 1.0 / k));
		m2 = vadd(m2, vmul(delta, vsub(c, mean)));
		if (sp->target_error > 0 && k >= MIN_ADAPTIVE && (k & (k - 1)) == 0 && i + 1 < sp->count) {
			/* checked at 8, 16, 32, ... samples; a pixel stops once two checks in a row
			 * pass, so that one run of agreeing samples on an edge does not end it */
			double se2 = vmaxc(m2) / ((double)(k - 1) * k);
			bool below = se2 < sp->target_error * sp->target_error;
			if (below && passed)
				break;
			passed = below;
		}
	}
	return mean;
}

int render_tile_count(const struct render_options *opt)
{
	return ((opt->x1 - opt->x0 + RENDER_TILE - 1) / RENDER_TILE) * ((opt->y1 - opt->y0 + RENDER_TILE - 1) / RENDER_TILE);
}

void render_tile_rect(const struct render_options *opt, int t, int *x, int *y, int *w, int *h)
{
	int tiles_x = (opt->x1 - opt->x0 + RENDER_TILE - 1) / RENDER_TILE;
	*x = opt->x0 + (t % tiles_x) * RENDER_TILE;
	*y = opt->y0 + (t / tiles_x) * RENDER_TILE;
	*w = opt->x1 - *x < RENDER_TILE ? opt->x1 - *x : RENDER_TILE;
	*h = opt->y1 - *y < RENDER_TILE ? opt->y1 - *y : RENDER_TILE;
}

static void render_tile(struct render_pool *p, struct sampler *sm, double *xy, int t, struct ray_stats *st)
{
	const struct scene *sc = p->sc;
	int tx, ty, tw, th;
	render_tile_rect(&p->opt, t, &tx, &ty, &tw, &th);
	size_t stride;
	float *row = p->sink.pixels(p->sink.ctx, t, &stride);
	double probe_sq = 0;
	for (int py = ty; py < ty + th; py++, row += stride)
		for (int px = tx; px < tx + tw; px++) {
			struct vec3 c = pixel_mean(sc, sm, xy, px, py, 0, st, &st->camera);
			if (p->probe_share > 0 &&
			    sampler_hash01(sc->sampling.seed, (uint64_t)px, (uint64_t)py, PROBE_KEY) < p->probe_share) {
				struct vec3 d = vsub(c, pixel_mean(sc, sm, xy, px, py, 1, st, &st->probe_camera));
				probe_sq += vdot(d, d);
				st->probe_pixels++;
			}
			float *out = row + 3 * (size_t)(px - tx);
			out[0] = (float)c.x;
			out[1] = (float)c.y;
			out[2] = (float)c.z;
		}
	p->tile_probe[t] = probe_sq;
}

/* The next tile fed, waiting for one; -1 once the pool is closed and none is left. */
static int take_tile(struct render_pool *p)
{
	pthread_mutex_lock(&p->lock);
	while (p->head == p->nranges && !p->closed)
		pthread_cond_wait(&p->fed, &p->lock);
	int t = -1;
	if (p->head < p->nranges) {
		struct feed_range *r = &p->ranges[p->head];
		t = r->first++;
		if (--r->count == 0)
			p->head++;
	}
	pthread_mutex_unlock(&p->lock);
	return t;
}

static void *work(void *arg)
{
	struct worker *w = arg;
	struct render_pool *p = w->pool;
	struct sampler *sm = sampler_clone(p->proto);
	double *xy = xmalloc(2 * (size_t)p->sc->sampling.count * sizeof *xy);
	int t;
	while ((t = take_tile(p)) >= 0) {
		render_tile(p, sm, xy, t, &w->stats);
		if (p->sink.done)
			p->sink.done(p->sink.ctx, t);
		atomic_fetch_add(&p->done_tiles, 1);
	}
	free(xy);
	sampler_free(sm);
	return NULL;
}

void render_progress_show(int done, int total, double elapsed)
{
	enum { WIDTH = 30 };
	double f = total ? (double)done / total : 1;
	int bar = (int)(f * WIDTH);
	char line[WIDTH + 1];
	memset(line, '#', (size_t)bar);
	memset(line + bar, '.', (size_t)(WIDTH - bar));
	line[WIDTH] = '\0';
	if (done > 0 && done < total)
		fprintf(stderr, "\r[%s] %3.0f%%  ETA %.0fs ", line, 100 * f, elapsed * (1 - f) / f);
	else
		fprintf(stderr, "\r[%s] %3.0f%%  %.1fs   ", line, 100 * f, elapsed);
}

struct render_pool *render_pool_start(const struct scene *sc, const struct render_options *opt,
                                      const struct render_sink *sink)
{
	struct render_pool *p = xcalloc(1, sizeof *p);
	p->sc = sc;
	p->opt = *opt;
	p->sink = *sink;
	p->proto = sampler_new(&sc->sampling);
	p->ntiles = render_tile_count(opt);
	p->tile_probe = xcalloc((size_t)p->ntiles + 1, sizeof *p->tile_probe);
	int64_t npixels = opt->whole_pixels > 0 ? opt->whole_pixels : (int64_t)(opt->x1 - opt->x0) * (opt->y1 - opt->y0);
	/* the center and grid patterns are the same in both replicas, unless the samples also
	 * draw from their streams */
	if ((sc->streams || (sc->sampling.kind != SAMPLE_CENTER && sc->sampling.kind != SAMPLE_GRID)) && npixels > 0)
		p->probe_share = fmin(1, fmax(PROBE_SHARE, PROBE_MIN / (double)npixels));
	pthread_mutex_init(&p->lock, NULL);
	pthread_cond_init(&p->fed, NULL);
	atomic_init(&p->done_tiles, 0);
	int nthreads = opt->threads > 0 ? opt->threads : (int)sysconf(_SC_NPROCESSORS_ONLN);
	if (nthreads < 1)
		nthreads = 1;
	if (nthreads > p->ntiles && p->ntiles > 0)
		nthreads = p->ntiles;
	p->workers = xcalloc((size_t)nthreads, sizeof *p->workers);
	sigset_t mask;
	cleanup_block_signals(&mask);  /* the workers inherit it: a signal is handled on this thread */
	for (int i = 0; i < nthreads; i++) {
		p->workers[i].pool = p;
		if (pthread_create(&p->workers[i].thread, NULL, work, &p->workers[i]) != 0)
			break;
		p->started++;
	}
	cleanup_restore_signals(&mask);
	if (p->started == 0) {
		struct ray_stats unused;
		render_pool_finish(p, NULL, &unused);
		return NULL;
	}
	return p;
}

void render_pool_feed(struct render_pool *p, int first, int count)
{
	if (count <= 0)
		return;
	pthread_mutex_lock(&p->lock);
	if (p->nranges == p->cap && p->head > 0) {
		/* the ranges taken make room first */
		memmove(p->ranges, p->ranges + p->head, (p->nranges - p->head) * sizeof *p->ranges);
		p->nranges -= p->head;
		p->head = 0;
	}
	if (p->nranges == p->cap) {
		p->cap = p->cap ? 2 * p->cap : 8;
		p->ranges = xrealloc(p->ranges, p->cap * sizeof *p->ranges);
	}
	p->ranges[p->nranges++] = (struct feed_range){ first, count };
	pthread_cond_broadcast(&p->fed);
	pthread_mutex_unlock(&p->lock);
}

void render_pool_close(struct render_pool *p)
{
	pthread_mutex_lock(&p->lock);
	p->closed = true;
	pthread_cond_broadcast(&p->fed);
	pthread_mutex_unlock(&p->lock);
}

int render_pool_done(struct render_pool *p)
{
	return atomic_load(&p->done_tiles);
}

double *render_pool_tile_probes(struct render_pool *p)
{
	return p->tile_probe;
}

void render_pool_finish(struct render_pool *p, const struct ray_stats *more, struct ray_stats *st)
{
	memset(st, 0, sizeof *st);
	for (int i = 0; i < p->started; i++) {
		pthread_join(p->workers[i].thread, NULL);
		trace_stats_add(st, &p->workers[i].stats);
	}
	if (more)
		trace_stats_add(st, more);
	double probe_sq = 0;
	for (int t = 0; t < p->ntiles; t++)
		probe_sq += p->tile_probe[t];
	/* per channel, and the difference of two replicas has twice the variance of one */
	st->probe_sum = probe_sq;
	st->estimated_rmse = st->probe_pixels ? sqrt(probe_sq / (6.0 * (double)st->probe_pixels)) : -1;
	pthread_cond_destroy(&p->fed);
	pthread_mutex_destroy(&p->lock);
	free(p->ranges);
	free(p->workers);
	free(p->tile_probe);
	sampler_free(p->proto);
	free(p);
}

float *render_image_pixels(void *ctx, int t, size_t *stride)
{
	const struct render_target *s = ctx;
	int x, y, w, h;
	render_tile_rect(s->opt, t, &x, &y, &w, &h);
	*stride = 3 * (size_t)s->img->width;
	return &s->img->rgb[3 * ((size_t)(y - s->opt->y0) * (size_t)s->img->width + (size_t)(x - s->opt->x0))];
}

int render_pool_threads(const struct render_pool *p)
{
	return p->started;
}

int render_image(const struct scene *sc, const struct render_options *opt, struct image *img, struct ray_stats *st)
{
	struct render_target target = { opt, img };
	struct render_pool *p = render_pool_start(sc, opt, &(struct render_sink){ render_image_pixels, NULL, &target });
	if (!p)
		return -1;
	int ntiles = render_tile_count(opt);
	render_pool_feed(p, 0, ntiles);
	render_pool_close(p);
	if (opt->progress) {
		double t0 = clock_now();
		while (render_pool_done(p) < ntiles) {
			render_progress_show(render_pool_done(p), ntiles, clock_now() - t0);
			nanosleep(&(struct timespec){ 0, 200 * 1000 * 1000 }, NULL);
		}
		render_progress_show(ntiles, ntiles, clock_now() - t0);
		fputc('\n', stderr);
	}
	render_pool_finish(p, NULL, st);
	return 0;
}
