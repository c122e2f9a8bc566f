/* render.c: the render loop, written once: worker threads take 16x16 tiles from a shared
 * counter, and every pixel's value depends only on the pixel and its samples, so the
 * image is the same whatever the thread count or tile order. No locks per pixel. */
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

enum { TILE = 16 };

struct job {
	const struct scene *sc;
	const struct sampler *proto;   /* each worker samples through a clone of it */
	const struct render_options *opt;
	struct image *img;
	int tiles_x, ntiles;
	double probe_share;            /* of the pixels, chosen by hash, that estimate the error */
	atomic_int next_tile;
	atomic_int done_tiles;
};

struct worker {
	pthread_t thread;
	struct job *job;
	struct ray_stats stats;
	double probe_sq;               /* sum over its probe pixels of the squared replica difference */
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

static void render_tile(struct job *job, struct sampler *sm, double *xy, int tile, struct ray_stats *st,
                        double *probe_sq)
{
	const struct render_options *opt = job->opt;
	const struct scene *sc = job->sc;
	int tx = opt->x0 + (tile % job->tiles_x) * TILE, ty = opt->y0 + (tile / job->tiles_x) * TILE;
	for (int py = ty; py < ty + TILE && py < opt->y1; py++)
		for (int px = tx; px < tx + TILE && px < opt->x1; px++) {
			struct vec3 c = pixel_mean(sc, sm, xy, px, py, 0, st, &st->camera);
			if (job->probe_share > 0 &&
			    sampler_hash01(sc->sampling.seed, (uint64_t)px, (uint64_t)py, PROBE_KEY) < job->probe_share) {
				struct vec3 d = vsub(c, pixel_mean(sc, sm, xy, px, py, 1, st, &st->probe_camera));
				*probe_sq += vdot(d, d);
				st->probe_pixels++;
			}
			float *out = &job->img->rgb[3 * ((size_t)(py - opt->y0) * (size_t)job->img->width + (size_t)(px - opt->x0))];
			out[0] = (float)c.x;
			out[1] = (float)c.y;
			out[2] = (float)c.z;
		}
}

static void *work(void *arg)
{
	struct worker *w = arg;
	struct job *job = w->job;
	struct sampler *sm = sampler_clone(job->proto);
	double *xy = xmalloc(2 * (size_t)job->sc->sampling.count * sizeof *xy);
	for (;;) {
		int tile = atomic_fetch_add(&job->next_tile, 1);
		if (tile >= job->ntiles)
			break;
		render_tile(job, sm, xy, tile, &w->stats, &w->probe_sq);
		atomic_fetch_add(&job->done_tiles, 1);
	}
	free(xy);
	sampler_free(sm);
	return NULL;
}

static void show_progress(int done, int total, double elapsed)
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

int render_image(const struct scene *sc, const struct render_options *opt, struct image *img, struct ray_stats *st)
{
	struct job job = { .sc = sc, .opt = opt, .img = img };
	struct sampler *proto = sampler_new(&sc->sampling);
	job.proto = proto;
	job.tiles_x = (opt->x1 - opt->x0 + TILE - 1) / TILE;
	job.ntiles = job.tiles_x * ((opt->y1 - opt->y0 + TILE - 1) / TILE);
	size_t npixels = (size_t)(opt->x1 - opt->x0) * (size_t)(opt->y1 - opt->y0);
	/* the center and grid patterns are the same in both replicas, unless the samples also
	 * draw from their streams */
	if ((sc->streams || (sc->sampling.kind != SAMPLE_CENTER && sc->sampling.kind != SAMPLE_GRID)) && npixels > 0)
		job.probe_share = fmin(1, fmax(PROBE_SHARE, PROBE_MIN / (double)npixels));
	atomic_init(&job.next_tile, 0);
	atomic_init(&job.done_tiles, 0);
	int nthreads = opt->threads > 0 ? opt->threads : (int)sysconf(_SC_NPROCESSORS_ONLN);
	if (nthreads < 1)
		nthreads = 1;
	if (nthreads > job.ntiles && job.ntiles > 0)
		nthreads = job.ntiles;
	struct worker *workers = xcalloc((size_t)nthreads, sizeof *workers);
	int started = 0;
	sigset_t mask;
	cleanup_block_signals(&mask);  /* the workers inherit it: a signal is handled on this thread */
	for (int i = 0; i < nthreads; i++) {
		workers[i].job = &job;
		if (pthread_create(&workers[i].thread, NULL, work, &workers[i]) != 0)
			break;
		started++;
	}
	cleanup_restore_signals(&mask);
	if (started == 0) {
		free(workers);
		sampler_free(proto);
		return -1;
	}
	if (opt->progress) {
		double t0 = clock_now();
		while (atomic_load(&job.done_tiles) < job.ntiles) {
			show_progress(atomic_load(&job.done_tiles), job.ntiles, clock_now() - t0);
			nanosleep(&(struct timespec){ 0, 200 * 1000 * 1000 }, NULL);
		}
		show_progress(job.ntiles, job.ntiles, clock_now() - t0);
		fputc('\n', stderr);
	}
	memset(st, 0, sizeof *st);
	double probe_sq = 0;
	for (int i = 0; i < started; i++) {
		pthread_join(workers[i].thread, NULL);
		probe_sq += workers[i].probe_sq;
		st->camera += workers[i].stats.camera;
		st->probe_camera += workers[i].stats.probe_camera;
		st->probe_pixels += workers[i].stats.probe_pixels;
		st->shadow += workers[i].stats.shadow;
		st->area_shadow += workers[i].stats.area_shadow;
		st->area_settled += workers[i].stats.area_settled;
		st->reflection += workers[i].stats.reflection;
		st->refraction += workers[i].stats.refraction;
		st->nonfinite += workers[i].stats.nonfinite;
		st->patterns += workers[i].stats.patterns;
		st->images += workers[i].stats.images;
		st->bumps += workers[i].stats.bumps;
	}
	/* which worker rendered which tile varies from run to run, so this sum may differ
	 * in its last bits: it is reported, never written into the image */
	/* per channel, and the difference of two replicas has twice the variance of one */
	st->estimated_rmse = st->probe_pixels ? sqrt(probe_sq / (6.0 * (double)st->probe_pixels)) : -1;
	free(workers);
	sampler_free(proto);
	return 0;
}
