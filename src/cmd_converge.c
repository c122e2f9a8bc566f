/* cmd_converge.c: scn converge: image error against run time. The scene is loaded,
 * lowered and given its BVH once; then it is rendered in this process at rising sample
 * counts for each pattern and at falling adaptive targets, and POV-Ray renders its twin
 * at rising anti-aliasing depths as a child process. Every image is measured against one
 * reference; the points run cheapest first until the time budget is spent. */
#include "config.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <unistd.h>

#include "accel.h"
#include "cli.h"
#include "clock.h"
#include "diag.h"
#include "image_file.h"
#include "imgdiff.h"
#include "load.h"
#include "lower.h"
#include "outfile.h"
#include "plot.h"
#include "pov_export.h"
#include "povray.h"
#include "render.h"
#include "scene_desc.h"
#include "xalloc.h"

struct converge_args {
	const char *scene, *reference, *csv, *plot;
	double budget;                 /* seconds */
	long threads, width, height;   /* width, height -1: not given */
	long ref_samples;              /* 0: chosen from the budget */
	bool no_pov, quiet;
};

enum series_kind { SERIES_FIXED, SERIES_ADAPTIVE, SERIES_POV };

/* The series in the order of the table: random, jittered, poisson, grid, adaptive,
 * then POV-Ray's (always last): "POV-Ray", and when the scene has area lights one more
 * per area_light adaptive level that subdivides less than POV-Ray's default. */
enum { GRID_SERIES = 3 };

/* The points rendered before the default reference, to time a sample: the grid's
 * counts 1 and 4 (a single sample's time is mostly the render's fixed overhead). */
enum { CALIBRATION = 2 };

/* A row of points of one kind: counts 1, 4, 16, ... (fixed), targets 0.02, 0.01, ...
 * (adaptive), or -A then +AM2 +R1, +R2, ... (POV-Ray). */
struct series {
	char name[32];
	enum series_kind kind;
	enum sample_kind pattern;
	const char *color;
	bool dashed, squares;
	int nsteps, next;              /* steps planned; the next to run */
	bool stopped;                  /* the budget, or a failure, ended it */
	double last_seconds;           /* the previous point's time, 0 before it */
	double last_cost;              /* its nominal rays per pixel */
	double pov_fixed;              /* POV-Ray: its last run's time outside Trace Time */
	int pov_adaptive;              /* POV-Ray: its area_adaptive (pov_export.h; 0: none) */
};

struct point {
	int series;
	char setting[48];
	double spp;                    /* samples per pixel: mean rays for adaptive, lattice points for AM2 */
	double seconds, rmse;
	double est;                    /* the render's estimated RMSE; < 0: none */
};

/* Everything a run shares. */
struct run {
	const struct converge_args *a;
	struct scene sc;
	struct image *ref, *img;
	int threads;                   /* resolved: never 0 */
	int max_count;                 /* the largest sample count of a fixed series */
	double t_start;
	double per_sample;             /* seconds per sample per pixel of scn, last measured; 0: unknown */
	struct series *series;
	int nseries;
	size_t cap_series;
	int pov_levels;                /* POV-Ray's adaptive levels below full subdivision: 0 to
	                                  pov_levels - 1 each get a series (0: no area light) */
	struct point *points;
	size_t npoints, cap_points;
	struct povray pov;             /* POV-Ray and its folder, when has_pov */
	bool has_pov;
	char no_pov[256];              /* otherwise, why not */
	char skipped[1024];            /* the points the budget left out */
};

/* The adaptive series' first target; each next one is half the one before. */
#define ADAPTIVE_FIRST 0.02
enum { ADAPTIVE_STEPS = 5 };

static bool positive_number(const char *s, double *out)
{
	char *end;
	errno = 0;
	double v = strtod(s, &end);
	if (errno || end == s || *end || !isfinite(v) || v <= 0 || v > 1e7)
		return false;
	*out = v;
	return true;
}

enum {
	OPT_REFERENCE, OPT_BUDGET, OPT_CSV, OPT_PLOT, OPT_THREADS, OPT_WIDTH, OPT_HEIGHT, OPT_REFERENCE_SAMPLES,
	OPT_NO_POV, OPT_QUIET, NOPTIONS
};
static const struct cli_option options[NOPTIONS] = {
	[OPT_REFERENCE] = { "reference", 0, true },
	[OPT_BUDGET] = { "budget", 0, true },
	[OPT_CSV] = { "csv", 0, true },
	[OPT_PLOT] = { "plot", 0, true },
	[OPT_THREADS] = { NULL, 'j', true },
	[OPT_WIDTH] = { NULL, 'W', true },
	[OPT_HEIGHT] = { NULL, 'H', true },
	[OPT_REFERENCE_SAMPLES] = { "reference-samples", 0, true },
	[OPT_NO_POV] = { "no-pov", 0, false },
	[OPT_QUIET] = { NULL, 'q', false },
};

/* Reads the command line into *a: 0, or -1 once the help is shown, or EXIT_USAGE after a
 * usage message. */
static int parse_args(const struct command *self, int argc, char **argv, struct converge_args *a)
{
	*a = (struct converge_args){ .budget = 120, .width = -1, .height = -1 };
	struct cli_parser p;
	cli_parser_init(&p, self, options, NOPTIONS, argc, argv);
	int o;
	while ((o = cli_next_option(&p)) >= 0) {
		const char *v = p.value;
		bool ok = true;
		switch (o) {
		case OPT_NO_POV: a->no_pov = true; break;
		case OPT_QUIET: a->quiet = true; break;
		case OPT_REFERENCE: a->reference = v; break;
		case OPT_CSV: a->csv = v; break;
		case OPT_PLOT: a->plot = v; break;
		case OPT_BUDGET: ok = positive_number(v, &a->budget); break;
		case OPT_THREADS: ok = cli_int(v, 0, 4096, &a->threads); break;
		case OPT_WIDTH: ok = cli_int(v, 1, 65536, &a->width); break;
		case OPT_HEIGHT: ok = cli_int(v, 1, 65536, &a->height); break;
		default: { /* OPT_REFERENCE_SAMPLES */
			ok = cli_int(v, 16, 65536, &a->ref_samples);
			long r = lround(sqrt((double)a->ref_samples));
			if (ok && r * r != a->ref_samples)
				return cli_usage_error(self, "--reference-samples needs a square count (16, 64, 256, 1024, ...), not %s", v);
		}
		}
		if (!ok)
			return cli_usage_error(self, "bad value '%s' for %s (%s)", v, p.name,
			                       o == OPT_BUDGET ? "seconds, a positive number" : "a whole number in range");
	}
	if (o == CLI_STOP)
		return p.status;
	if (!(a->scene = cli_scene(&p)))
		return EXIT_USAGE;
	if (a->plot) {
		size_t n = strlen(a->plot);
		if (n < 4 || strcasecmp(a->plot + n - 4, ".svg") != 0)
			return cli_usage_error(self, "--plot writes SVG: name the file .svg, not '%s'", a->plot);
	}
	return 0;
}

/* Whether a file can be created at path: its folder exists and is writable. Checked
 * before the renders, so that minutes of work do not end in an unwritable name. */
static bool writable_place(const char *path)
{
	const char *slash = strrchr(path, '/');
	char *dir = xstrdup(slash ? path : ".");
	if (slash)
		dir[slash == path ? 1 : slash - path] = '\0';
	bool ok = access(dir, W_OK | X_OK) == 0;
	if (!ok)
		fprintf(stderr, "scn: cannot write '%s': %s\n", path, strerror(errno));
	free(dir);
	return ok;
}

static void note(const struct run *r, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

static void note(const struct run *r, const char *fmt, ...)
{
	if (r->a->quiet)
		return;
	va_list ap;
	va_start(ap, fmt);
	fputs("scn converge: ", stderr);
	vfprintf(stderr, fmt, ap);
	fputc('\n', stderr);
	va_end(ap);
}

/* Images as a file shows them: every channel clipped to [0, 1] (NaN to 0). POV-Ray's
 * PNG is clipped, so every image is, or its highlights would count as error. */
static void clip(struct image *img)
{
	size_t n = 3 * (size_t)img->width * (size_t)img->height;
	for (size_t i = 0; i < n; i++)
		img->rgb[i] = fminf(fmaxf(img->rgb[i], 0.0f), 1.0f);
}

/* --- scn's renders --- */

/* Renders sc with the sampling s into r->img, clipped; seconds and stats out. */
static int render_with(struct run *r, struct sampling s, double *seconds, struct ray_stats *st)
{
	r->sc.sampling = s;
	struct render_options ro = { .threads = r->threads, .x1 = r->sc.camera.width, .y1 = r->sc.camera.height };
	double t0 = clock_now();
	if (render_image(&r->sc, &ro, r->img, st) != 0) {
		fprintf(stderr, "scn: cannot start the render threads\n");
		return EXIT_RENDER;
	}
	*seconds = clock_now() - t0;
	clip(r->img);
	return 0;
}

static double rmse_of(const struct image *img, const struct image *ref)
{
	struct imgdiff_stats ds;
	return imgdiff_compare(img, ref, &ds) ? ds.rmse : NAN;
}

static struct point *add_point(struct run *r, int series)
{
	xgrow((void **)&r->points, &r->cap_points, r->npoints + 1, sizeof *r->points);
	struct point *p = &r->points[r->npoints++];
	*p = (struct point){ .series = series, .est = -1 };
	return p;
}

static int fixed_count(int step)
{
	return 1 << (2 * step);
}

static double adaptive_target(int step)
{
	return ADAPTIVE_FIRST / (1 << step);
}

/* The adaptive series' largest count at a step: halving the target takes four times the
 * samples where noise is left, so the cap grows with it from the fixed series' largest,
 * up to the 16 times that the reference takes (a cap held fixed made every target below
 * its reach give the same image). */
static int adaptive_cap(const struct run *r, int step)
{
	long cap = r->max_count;
	for (int i = 0; i < step && cap < 16L * r->max_count; i++)
		cap *= 4;
	return (int)(cap < 65536 ? cap : 65536);
}

/* POV-Ray's anti-aliasing at step 0 (-A) and at +AM2 depth d = step. */
static void pov_setting(int step, char *buf, size_t n)
{
	if (step == 0)
		snprintf(buf, n, "-A");
	else
		snprintf(buf, n, "+A0.0 +AM2 +R%d -J", step);
}

/* What the step's point costs, in rays per pixel (POV-Ray's +AM2 +Rd lattice has
 * (2^(d-1)+1)^2 points per pixel, but neighbours share its edges: 4^(d-1) rays). */
static double nominal_cost(const struct run *r, const struct series *s, int step)
{
	switch (s->kind) {
	case SERIES_FIXED: return fixed_count(step);
	case SERIES_ADAPTIVE: return adaptive_cap(r, step);
	default: return step == 0 ? 1 : (double)(1 << (2 * (step - 1)));
	}
}

/* The predicted seconds of the series' next point: the previous point's time scaled by
 * the sample ratio, or from scn's time per sample before the series has a point. */
static double predict(const struct run *r, const struct series *s)
{
	double cost = nominal_cost(r, s, s->next);
	switch (s->kind) {
	case SERIES_FIXED:
		return s->last_seconds > 0 ? s->last_seconds * cost / s->last_cost : r->per_sample * cost;
	case SERIES_ADAPTIVE:
		/* halving the target takes about four times the samples where noise is left, and
		 * no more where the minimum already met it; never more than the maximum count */
		return s->last_seconds > 0 ? fmin(s->last_seconds * 2.5, r->per_sample * cost)
		                           : r->per_sample * fmin(16, cost);
	default:
		if (s->last_seconds <= 0)
			return 0.7 + r->per_sample;  /* POV-Ray starts in about 0.6 s */
		return s->pov_fixed + (s->last_seconds - s->pov_fixed) * cost / s->last_cost;
	}
}

static int run_scn_step(struct run *r, int si)
{
	struct series *s = &r->series[si];
	int step = s->next;
	struct sampling smp = { .kind = s->pattern, .seed = r->sc.sampling.seed };
	if (s->kind == SERIES_FIXED)
		smp.count = fixed_count(step);
	else
		smp.count = adaptive_cap(r, step), smp.target_error = adaptive_target(step);
	double seconds;
	struct ray_stats st;
	int rc = render_with(r, smp, &seconds, &st);
	if (rc)
		return rc;
	struct point *p = add_point(r, si);
	double npix = (double)r->img->width * r->img->height;
	p->seconds = seconds;
	p->rmse = r->ref ? rmse_of(r->img, r->ref) : NAN;  /* NAN: measured once the reference exists */
	if (s->kind == SERIES_FIXED) {
		snprintf(p->setting, sizeof p->setting, "count %d", smp.count);
		p->spp = smp.count;
	} else {
		snprintf(p->setting, sizeof p->setting, "target %g max %d", smp.target_error, smp.count);
		p->spp = (double)st.camera / npix;
	}
	p->est = st.estimated_rmse;
	r->per_sample = seconds / p->spp;
	s->last_seconds = seconds;
	s->last_cost = nominal_cost(r, s, step);
	if (r->ref)
		note(r, "%s %s: %.3f s, RMSE %.4g", s->name, p->setting, p->seconds, p->rmse);
	else
		note(r, "%s %s: %.3f s", s->name, p->setting, p->seconds);
	return 0;
}

/* --- POV-Ray --- */

/* The twin's file name for an area_adaptive value (pov_export.h): one file per level. */
static void twin_name(int area_adaptive, char *buf, size_t n)
{
	if (area_adaptive > 0)
		snprintf(buf, n, "twin-adaptive%d.pov", area_adaptive - 1);
	else
		snprintf(buf, n, "twin.pov");
}

/* The adaptive levels at which POV-Ray's area_light subdivision can stop short of the
 * full grid: its trace.cpp (TraceAreaLightSubsetShadowRay) tests the four corners of a
 * cell of the N1 x N2 grid and splits it in four (a side of w points apart into two of
 * floor(w/2)) while level < adaptive or two neighbouring corners differ by more than 0.1,
 * down to sides of 1; a grid whose longer side is w apart is split fully at a level
 * equal to the number of halvings that take w to 1, or more, which is then the number
 * of levels that differ from no adaptive keyword (Adaptive_Level 100). */
static int area_levels(const struct scene *sc)
{
	int levels = 0;
	for (size_t i = 0; i < sc->narea_lights; i++)
		for (int k = 0; k < 2; k++) {
			int n = 0;
			for (int w = sc->area_lights[i].size[k] - 1; w > 1; w /= 2)
				n++;
			levels = n > levels ? n : levels;
		}
	return levels;
}

static void run_pov_step(struct run *r, int si)
{
	struct series *s = &r->series[si];
	int step = s->next;
	char aa[48], err[1024], twin[32];
	pov_setting(step, aa, sizeof aa);
	twin_name(s->pov_adaptive, twin, sizeof twin);
	struct povray_render pr;
	if (povray_render(&r->pov, twin, aa, r->sc.camera.width, r->sc.camera.height, r->threads, &pr, err,
	                  sizeof err) != 0) {
		fprintf(stderr, "scn converge: warning: %s; no more POV-Ray points\n", err);
		s->stopped = true;
		return;
	}
	if (pr.img->width != r->ref->width || pr.img->height != r->ref->height) {
		fprintf(stderr, "scn converge: warning: POV-Ray wrote a %d x %d image, not %d x %d; no more POV-Ray points\n",
		        pr.img->width, pr.img->height, r->ref->width, r->ref->height);
		s->stopped = true;
		image_free(pr.img);
		return;
	}
	clip(pr.img);
	struct point *p = add_point(r, si);
	snprintf(p->setting, sizeof p->setting, "%s", aa);
	p->spp = step == 0 ? 1 : pow((1 << (step - 1)) + 1, 2);
	p->seconds = pr.seconds;
	p->rmse = rmse_of(pr.img, r->ref);
	image_free(pr.img);
	s->pov_fixed = pr.trace >= 0 && pr.trace <= pr.seconds ? pr.seconds - pr.trace : 0;
	s->last_seconds = pr.seconds;
	s->last_cost = nominal_cost(r, s, step);
	note(r, "%s %s: %.3f s (its Trace Time %.3f s), RMSE %.4g", s->name, aa, pr.seconds, pr.trace, p->rmse);
}

/* Finds povray and writes the scene's twin to its folder, one for each adaptive level
 * (area_levels); false with a warning when either fails, and there is then no POV-Ray
 * series. */
static bool open_pov(struct run *r, const struct scene_desc *desc, const char **why)
{
	char err[1024];
	if (!povray_open(&r->pov, r->no_pov, sizeof r->no_pov)) {
		fprintf(stderr, "scn converge: no POV-Ray series: %s\n", r->no_pov);
		*why = r->no_pov;
		return false;
	}
	char version[64];
	snprintf(version, sizeof version, "scn %s", PACKAGE_VERSION);
	struct pov_export_options po = {
		.pov_name = "twin.pov",
		.source = strcmp(r->a->scene, "-") == 0 ? "standard input" : r->a->scene,
		.generator = version,
		.sky_image = desc->skybox.kind == SKY_IMAGE ? desc->skybox.image_path : NULL,
		.pov_dir = NULL,           /* the sky image by its absolute path */
		.look_at = desc->camera.look_at,
		.up = desc->camera.up,
		.fov = desc->camera.fov,
		.sky_rotate = &desc->skybox.rotate,
	};
	/* the header's command line then says -A; scn converge gives its own */
	r->sc.sampling = (struct sampling){ .count = 1, .kind = SAMPLE_CENTER, .seed = r->sc.sampling.seed };
	r->pov_levels = area_levels(&r->sc);
	bool ok = true;
	for (int k = 0; ok && k <= r->pov_levels; k++) {
		char twin[32];
		po.area_adaptive = k;  /* 0: the full subdivision, then adaptive 0, 1, ... */
		twin_name(k, twin, sizeof twin);
		po.pov_name = twin;
		char *path = povray_file(&r->pov, twin);
		ok = pov_export_file(&r->sc, &po, path, err, sizeof err) == 0;
		free(path);
	}
	if (!ok) {
		fprintf(stderr, "scn converge: no POV-Ray series: %s\n", err);
		*why = "its scene could not be written";
		povray_close(&r->pov);
	}
	return ok;
}

/* --- the reference --- */

/* The grid's side for the default reference: the largest of 64, 32 and 16 whose
 * render, predicted from the time per sample so far, fits in half the budget (16 in any
 * case), or the side of --reference-samples. Half, because the series up to a 16th of
 * its count take about as long again: the four patterns a third of the reference's time,
 * adaptive up to a third, POV-Ray (about three times slower a ray) a quarter. */
static int reference_side(const struct run *r)
{
	if (r->a->ref_samples > 0)
		return (int)lround(sqrt((double)r->a->ref_samples));
	for (int side = 64; side > 16; side /= 2)
		if (r->per_sample * side * side <= 0.5 * r->a->budget)
			return side;
	return 16;
}

/* The fixed series' largest count: a sixteenth of the reference's, rounded down to a
 * power of 4 (256 with a reference file): its error is then several times the
 * reference's own, which adds to it in quadrature. */
static int max_count_for(long ref_count)
{
	int m = 4;
	while ((long)m * 4 * 16 <= ref_count && m < 16384)
		m *= 4;
	return m;
}

/* --- the report --- */

/* A series' best points: by rising time, each with less error than every faster one. */
struct curve {
	size_t n;
	double *t, *e;
};

static int by_time(const void *a, const void *b)
{
	const double *x = a, *y = b;
	return (x[0] > y[0]) - (x[0] < y[0]);
}

static struct curve frontier(const struct run *r, int si, double extra)
{
	double *pairs = xmalloc(2 * (r->npoints + 1) * sizeof *pairs);
	size_t n = 0;
	for (size_t i = 0; i < r->npoints; i++)
		if (r->points[i].series == si && r->points[i].rmse > 0 && isfinite(r->points[i].rmse)) {
			pairs[2 * n] = r->points[i].seconds + extra;
			pairs[2 * n + 1] = r->points[i].rmse;
			n++;
		}
	qsort(pairs, n, 2 * sizeof *pairs, by_time);
	struct curve c = { 0, xmalloc((n + 1) * sizeof(double)), xmalloc((n + 1) * sizeof(double)) };
	for (size_t i = 0; i < n; i++)
		if (c.n == 0 || pairs[2 * i + 1] < c.e[c.n - 1]) {
			c.t[c.n] = fmax(pairs[2 * i], 1e-9);
			c.e[c.n] = pairs[2 * i + 1];
			c.n++;
		}
	free(pairs);
	return c;
}

/* The time the curve takes to reach error x, interpolated in log-log between the points
 * around it; false when x is outside its errors. */
static bool time_at(const struct curve *c, double x, double *t)
{
	if (c->n == 0 || x > c->e[0] || x < c->e[c->n - 1])
		return false;
	for (size_t i = 0; i + 1 < c->n; i++)
		if (c->e[i] >= x && x >= c->e[i + 1]) {
			double u = log(x / c->e[i]) / log(c->e[i + 1] / c->e[i]);
			*t = exp(log(c->t[i]) + u * log(c->t[i + 1] / c->t[i]));
			return true;
		}
	*t = c->t[c->n - 1];
	return true;
}

/* The first POV-Ray series (they are last). */
static int first_pov(const struct run *r)
{
	int i = r->nseries;
	while (i > 0 && r->series[i - 1].kind == SERIES_POV)
		i--;
	return i;
}

/* The equal-error comparison: the error X is the lowest that every POV-Ray series with a
 * point and at least one scn series reach (the lowest of one POV-Ray series alone would
 * leave the others, a hair above it by noise, out of the comparison); scn's time there is
 * its fastest series' (fixed cost included), POV-Ray's its fastest series' there (its best
 * adaptive level). With one POV-Ray series: the lowest error both reach. */
static void print_comparison(const struct run *r, double fixed, const char *why_no_pov)
{
	int pov = first_pov(r), npov = r->nseries - pov;
	if (why_no_pov) {
		printf("at equal error: no POV-Ray series to compare with (%s)\n", why_no_pov);
		return;
	}
	struct curve *c = xmalloc((size_t)r->nseries * sizeof *c);
	for (int i = 0; i < r->nseries; i++)
		c[i] = frontier(r, i, i >= pov ? 0 : fixed);
	double lo_scn = INFINITY, lo_pov = INFINITY, hi_pov = 0, x_pov = 0;
	for (int i = 0; i < r->nseries; i++)
		if (c[i].n && i < pov)
			lo_scn = fmin(lo_scn, c[i].e[c[i].n - 1]);
		else if (c[i].n)
			lo_pov = fmin(lo_pov, c[i].e[c[i].n - 1]), hi_pov = fmax(hi_pov, c[i].e[0]),
			x_pov = fmax(x_pov, c[i].e[c[i].n - 1]);
	double x = isfinite(lo_pov) ? fmax(lo_scn, x_pov) : NAN, tp = INFINITY;
	int best = -1, best_pov = -1;
	double tbest = INFINITY;
	for (int i = pov; i < r->nseries; i++) {
		double t;
		if (isfinite(x) && time_at(&c[i], x, &t) && t < tp)
			tp = t, best_pov = i;
	}
	if (best_pov >= 0) {
		printf("time to RMSE %.4g (scn: render plus its fixed cost; POV-Ray: the whole process):", x);
		for (int i = 0; i < pov; i++) {
			/* a series whose fastest point is already below x reached x by then (small
			 * images, where timing noise can make one spp slower than four): that
			 * time bounds scn's from above, never in scn's favour */
			double t = c[i].n ? c[i].t[0] : 0;
			if ((c[i].n && x > c[i].e[0]) || time_at(&c[i], x, &t)) {
				printf(" %s %.3g s,", r->series[i].name + 4, t);
				if (t < tbest)
					tbest = t, best = i;
			} else {
				printf(" %s -,", r->series[i].name + 4);
			}
		}
		for (int i = pov; i < r->nseries; i++) {
			double t;
			if (time_at(&c[i], x, &t))
				printf(" %s %.3g s%s", r->series[i].name, t, i + 1 < r->nseries ? "," : "\n");
			else
				printf(" %s -%s", r->series[i].name, i + 1 < r->nseries ? "," : "\n");
		}
	}
	if (!isfinite(lo_pov)) {
		printf("at equal error: no POV-Ray point to compare with (see the warnings)\n");
	} else if (best < 0) {
		printf("at equal error: no RMSE that both scn and POV-Ray reach");
		if (isfinite(lo_scn))
			printf(" (scn down to %.4g, POV-Ray %.4g to %.4g)", lo_scn, lo_pov, hi_pov);
		printf("\n");
	} else if (npov == 1) {
		printf("at equal error (RMSE %.4g), scn takes %.3g s and POV-Ray %.3g s: scn/POV-Ray = %.3g (scn %s)\n", x,
		       tbest, tp, tbest / tp, r->series[best].name + 4);
	} else {
		printf("at equal error (RMSE %.4g), scn takes %.3g s and POV-Ray %.3g s: scn/POV-Ray = %.3g (scn %s;"
		       " POV-Ray's fastest there: %s)\n",
		       x, tbest, tp, tbest / tp, r->series[best].name + 4, r->series[best_pov].name);
	}
	for (int i = 0; i < r->nseries; i++)
		free(c[i].t), free(c[i].e);
	free(c);
}

static const char *spp_text(double spp, char *buf, size_t n)
{
	if (spp == floor(spp))
		snprintf(buf, n, "%.0f", spp);
	else
		snprintf(buf, n, "%.1f", spp);
	return buf;
}

static void print_table(const struct run *r)
{
	int w = 14;                    /* the series' column: wider for "POV-Ray adaptive K" */
	for (int s = 0; s < r->nseries; s++)
		w = (int)strlen(r->series[s].name) > w ? (int)strlen(r->series[s].name) : w;
	printf("%-*s %-22s %6s %9s %10s %10s\n", w, "series", "setting", "spp", "seconds", "RMSE", "est. RMSE");
	for (int s = 0; s < r->nseries; s++)
		for (size_t i = 0; i < r->npoints; i++) {
			const struct point *p = &r->points[i];
			if (p->series != s)
				continue;
			char spp[32], est[32] = "-";
			if (p->est >= 0)
				snprintf(est, sizeof est, "%.4g", p->est);
			printf("%-*s %-22s %6s %9.3f %10.4g %10s\n", w, r->series[s].name, p->setting,
			       spp_text(p->spp, spp, sizeof spp), p->seconds, p->rmse, est);
		}
}

/* Writes text through a temporary file renamed into place; false with a message. */
static bool write_file(const char *path, const char *text, size_t len)
{
	char *tmp, err[1024];
	int fd = outfile_open(path, &tmp, err, sizeof err);
	int rc = fd < 0 ? -fd : outfile_finish(fd, tmp, path, outfile_write(fd, text, len), err, sizeof err);
	if (rc != 0) {
		fprintf(stderr, "scn: %s\n", err);
		return false;
	}
	return true;
}

static bool write_csv(const struct run *r, const char *path)
{
	char *text = NULL;
	size_t len = 0;
	FILE *f = open_memstream(&text, &len);
	if (!f)
		return false;
	fprintf(f, "series,setting,samples_per_pixel,seconds,rmse,estimated_rmse\n");
	for (int s = 0; s < r->nseries; s++)
		for (size_t i = 0; i < r->npoints; i++) {
			const struct point *p = &r->points[i];
			if (p->series != s)
				continue;
			fprintf(f, "%s,%s,%.6g,%.6f,%.6g,", r->series[s].name, p->setting, p->spp, p->seconds, p->rmse);
			if (p->est >= 0)
				fprintf(f, "%.6g", p->est);
			fputc('\n', f);
		}
	fclose(f);
	bool ok = write_file(path, text, len);
	free(text);
	return ok;
}

static bool write_plot(const struct run *r, const char *path, const char *title, const char *subtitle)
{
	struct plot_series *ps = xmalloc((size_t)r->nseries * sizeof *ps);
	double *xs = xmalloc((r->npoints + 1) * sizeof *xs), *ys = xmalloc((r->npoints + 1) * sizeof *ys);
	size_t used = 0;
	int n = 0;
	for (int s = 0; s < r->nseries; s++) {
		size_t first = used;
		for (size_t i = 0; i < r->npoints; i++)
			if (r->points[i].series == s) {
				xs[used] = r->points[i].seconds;
				ys[used] = r->points[i].rmse;
				used++;
			}
		if (used == first)
			continue;
		const struct series *sr = &r->series[s];
		ps[n++] = (struct plot_series){ sr->name, sr->color, sr->dashed, sr->squares, used - first, xs + first,
		                                ys + first };
	}
	struct plot p = { title, subtitle, "seconds (scn: the render alone; POV-Ray: the whole process)",
	                  "RMSE against the reference (linear, clipped to [0, 1])", (size_t)n, ps };
	char *text = NULL;
	size_t len = 0;
	FILE *f = open_memstream(&text, &len);
	bool ok = f && plot_svg(&p, f) == 0;
	if (f)
		fclose(f);
	ok = ok && write_file(path, text, len);
	free(text);
	free(ps);
	free(xs);
	free(ys);
	return ok;
}

/* --- the command --- */

static void plan_series(struct run *r, bool pov)
{
	static const struct { const char *name; enum sample_kind k; const char *color; } fixed[] = {
		{ "scn random", SAMPLE_RANDOM, "#8c8c8c" },
		{ "scn jittered", SAMPLE_JITTERED, "#1f77b4" },
		{ "scn poisson", SAMPLE_POISSON, "#2ca02c" },
		{ "scn grid", SAMPLE_GRID, "#9467bd" },
	};
	/* POV-Ray's adaptive levels, each its own colour */
	static const char *const pov_colors[] = { "#8c564b", "#e377c2", "#17becf", "#bcbd22", "#7f7f7f" };
	int steps = 0;
	while (fixed_count(steps) <= r->max_count)
		steps++;
	r->nseries = 0;
	int levels = pov ? r->pov_levels : 0;
	xgrow((void **)&r->series, &r->cap_series, (size_t)(6 + levels), sizeof *r->series);
	for (size_t i = 0; i < sizeof fixed / sizeof *fixed; i++)
		r->series[r->nseries++] = (struct series){ .kind = SERIES_FIXED, .pattern = fixed[i].k,
		                                           .color = fixed[i].color, .nsteps = steps };
	r->series[r->nseries++] = (struct series){ .kind = SERIES_ADAPTIVE, .pattern = SAMPLE_JITTERED,
	                                           .color = "#ff7f0e", .nsteps = ADAPTIVE_STEPS };
	for (size_t i = 0; i < sizeof fixed / sizeof *fixed; i++)
		snprintf(r->series[i].name, sizeof r->series[i].name, "%s", fixed[i].name);
	snprintf(r->series[r->nseries - 1].name, sizeof r->series[0].name, "scn adaptive");
	/* -A, then +R1 up to the depth whose 4^(d-1) rays per pixel match the largest count:
	 * with no adaptive keyword, then at each adaptive level */
	for (int k = 0; k <= levels; k++) {
		struct series *s = &r->series[r->nseries++];
		*s = (struct series){ .kind = SERIES_POV, .color = k ? pov_colors[(k - 1) % 5] : "#d62728",
		                      .dashed = true, .squares = true, .nsteps = pov ? steps + 1 : 0, .pov_adaptive = k };
		if (k)
			snprintf(s->name, sizeof s->name, "POV-Ray adaptive %d", k - 1);
		else
			snprintf(s->name, sizeof s->name, "POV-Ray");
	}
}

static void skip_note(struct run *r, const struct series *s, double predicted)
{
	char setting[48];
	if (s->kind == SERIES_FIXED)
		snprintf(setting, sizeof setting, "count %d", fixed_count(s->next));
	else if (s->kind == SERIES_ADAPTIVE)
		snprintf(setting, sizeof setting, "target %g", adaptive_target(s->next));
	else
		pov_setting(s->next, setting, sizeof setting);
	size_t used = strlen(r->skipped);
	snprintf(r->skipped + used, sizeof r->skipped - used, "%s%s %s (about %.3g s)", used ? ", " : "", s->name,
	         setting, predicted);
}

/* Runs the series' points, cheapest predicted first, while they fit in the budget. */
static int run_points(struct run *r)
{
	for (;;) {
		int best = -1;
		double best_t = INFINITY;
		for (int i = 0; i < r->nseries; i++) {
			struct series *s = &r->series[i];
			if (s->stopped || s->next >= s->nsteps)
				continue;
			double t = predict(r, s);
			if (t < best_t)
				best_t = t, best = i;
		}
		if (best < 0)
			return 0;
		struct series *s = &r->series[best];
		if (clock_now() - r->t_start + best_t > r->a->budget) {
			skip_note(r, s, best_t);
			s->stopped = true;
			continue;
		}
		if (s->kind == SERIES_POV) {
			run_pov_step(r, best);
		} else {
			int rc = run_scn_step(r, best);
			if (rc)
				return rc;
		}
		s->next++;
	}
}

/* The render size: -W and -H, or one of them with the scene's aspect ratio, or the
 * reference image's size, or the scene's. */
static int choose_size(const struct command *self, const struct converge_args *a, const struct image *ref,
                       struct scene_desc *desc)
{
	int w = desc->camera.width, h = desc->camera.height;
	if (a->width > 0 && a->height > 0)
		w = (int)a->width, h = (int)a->height;
	else if (a->width > 0)
		h = (int)fmax(1, lround((double)a->width * h / w)), w = (int)a->width;
	else if (a->height > 0)
		w = (int)fmax(1, lround((double)a->height * w / h)), h = (int)a->height;
	else if (ref)
		w = ref->width, h = ref->height;
	if ((double)w * h > (double)IMAGE_MAX_PIXELS)
		return cli_usage_error(self, "%d x %d is more pixels than the limit of 2^28", w, h);
	if (ref && (ref->width != w || ref->height != h))
		return cli_usage_error(self, "the reference %s is %d x %d, but the renders would be %d x %d", a->reference,
		                       ref->width, ref->height, w, h);
	desc->camera.width = w;
	desc->camera.height = h;
	return 0;
}

int cmd_converge(const struct command *self, int argc, char **argv)
{
	struct converge_args a;
	int rc = parse_args(self, argc, argv, &a);
	if (rc)
		return rc < 0 ? 0 : rc;
	if ((a.csv && !writable_place(a.csv)) || (a.plot && !writable_place(a.plot)))
		return EXIT_IO;

	struct run r = { .a = &a, .t_start = clock_now() };
	struct diag d;
	diag_init(&d, stderr);
	struct scene_desc desc;
	struct load_times lt;
	struct lower_times wt = { 0 };
	const char *why_no_pov = NULL;
	struct image *first[CALIBRATION] = { 0 };  /* the first renders, while the reference is made */
	rc = (int)load_scene(&d, a.scene, NULL, &desc, &lt);
	diag_flush(&d);
	if (rc)
		goto done;
	char err[1024];
	int e = a.reference ? image_read(a.reference, &r.ref, err, sizeof err) : 0;
	if (e != 0) {
		fprintf(stderr, "scn: %s\n", err);
		rc = cli_file_status(e);
		goto done;
	}
	if ((rc = choose_size(self, &a, r.ref, &desc)))
		goto done;
	/* held at once: the first renders, the reference, the render and POV-Ray's */
	uint64_t images = (CALIBRATION + 3) * image_bytes(desc.camera.width, desc.camera.height);
	char what[96];
	snprintf(what, sizeof what, "converging at %d x %d, with %d images at once,", desc.camera.width,
	         desc.camera.height, CALIBRATION + 3);
	const char *option = a.width > 0 || a.height > 0 ? "-W/-H" : a.reference ? "--reference" : NULL;
	if ((rc = cli_memory_fits(&d, option ? NULL : &desc.camera.resolution_span, option, what, images))) {
		diag_flush(&d);
		goto done;
	}
	double t0 = clock_now();
	rc = (int)lower_scene(&d, &desc, &r.sc, &wt, (int64_t)images);
	double lower_s = clock_now() - t0;
	diag_flush(&d);
	if (rc)
		goto done;
	t0 = clock_now();
	accel_build(&r.sc.accel, &r.sc.geo, ACCEL_BVH);
	double bvh_s = clock_now() - t0;
	double fixed = lt.parse + lt.check + lt.eval + lower_s + bvh_s;
	long cores = sysconf(_SC_NPROCESSORS_ONLN);
	r.threads = a.threads > 0 ? (int)a.threads : cores > 0 ? (int)cores : 1;
	int w = r.sc.camera.width, h = r.sc.camera.height;
	r.img = image_new(w, h);

	if (a.no_pov)
		why_no_pov = "--no-pov";
	else
		r.has_pov = open_pov(&r, &desc, &why_no_pov);

	/* the reference: a file, or a grid render sized by the first renders' time */
	char ref_text[160];
	r.max_count = 256;
	if (!r.ref) {
		r.max_count = 4;
		plan_series(&r, false);
		/* the grid series' first two points (counts 1 and 4), rendered first to time a
		 * sample; their error is measured once the reference exists */
		for (int i = 0; i < CALIBRATION; i++) {
			if ((rc = run_scn_step(&r, GRID_SERIES)))
				goto done;
			r.series[GRID_SERIES].next++;
			first[i] = r.img;
			r.img = image_new(w, h);
		}
		int side = reference_side(&r);
		note(&r, "reference: grid %d x %d samples per pixel (about %.0f s)", side, side,
		     r.per_sample * side * side);
		double seconds;
		struct ray_stats st;
		struct sampling smp = { .count = side * side, .kind = SAMPLE_GRID, .seed = r.sc.sampling.seed };
		if ((rc = render_with(&r, smp, &seconds, &st)))
			goto done;
		r.ref = r.img;
		r.img = image_new(w, h);
		for (int i = 0; i < CALIBRATION; i++)
			r.points[i].rmse = rmse_of(first[i], r.ref);
		r.max_count = max_count_for((long)side * side);
		snprintf(ref_text, sizeof ref_text, "scn grid %d x %d = %d samples per pixel, rendered in %.3f s", side, side,
		         side * side, seconds);
	} else {
		clip(r.ref);
		snprintf(ref_text, sizeof ref_text, "%s", a.reference);
	}
	{
		/* the plan again, with the real largest count, keeping the grid's first point
		 * (none with a reference file, where this is the first plan) */
		struct series grid = r.nseries > GRID_SERIES ? r.series[GRID_SERIES] : (struct series){ 0 };
		plan_series(&r, r.has_pov);
		r.series[GRID_SERIES].next = grid.next;
		r.series[GRID_SERIES].last_seconds = grid.last_seconds;
		r.series[GRID_SERIES].last_cost = grid.last_cost;
	}
	if ((rc = run_points(&r)))
		goto done;

	printf("scene: %s, %d x %d, max_depth %d, %d thread%s\n", a.scene, w, h, r.sc.max_depth, r.threads,
	       r.threads == 1 ? "" : "s");
	printf("reference: %s\n", ref_text);
	printf("scn's fixed cost, once, not in its times below: load %.3f s, lower %.3f s, bvh %.3f s\n",
	       lt.parse + lt.check + lt.eval, lower_s, bvh_s);
	printf("RMSE: every channel of every pixel against the reference, linear light, clipped to [0, 1]\n");
	printf("seconds: scn's render alone; POV-Ray's whole process (start-up, parse, render, write)\n");
	printf("spp: samples per pixel; adaptive: the mean taken; POV-Ray +AM2 +Rd: the (2^(d-1)+1)^2 lattice\n"
	       "     points per pixel, whose edges neighbours share (about 4^(d-1) rays per pixel)\n\n");
	print_table(&r);
	printf("\n");
	if (r.skipped[0])
		printf("not run, over the budget of %g s: %s\n", a.budget, r.skipped);
	const struct series *pov = &r.series[first_pov(&r)];
	if (pov->last_seconds > 0)
		printf("POV-Ray's start-up and parse took %.3f s of its last run (its wall time less its Trace Time)\n",
		       pov->pov_fixed);
	printf("total: %.1f s\n", clock_now() - r.t_start);
	fflush(stdout);

	char title[256], subtitle[512];
	const char *base = strrchr(a.scene, '/');
	snprintf(title, sizeof title, "scn converge: %s, %d x %d", base ? base + 1 : a.scene, w, h);
	snprintf(subtitle, sizeof subtitle, "reference: %s; %d thread%s", ref_text, r.threads, r.threads == 1 ? "" : "s");
	if (a.csv && !write_csv(&r, a.csv))
		rc = EXIT_IO;
	if (a.plot && !write_plot(&r, a.plot, title, subtitle))
		rc = EXIT_IO;
	print_comparison(&r, fixed, why_no_pov);
done:
	for (int i = 0; i < CALIBRATION; i++)
		image_free(first[i]);
	image_free(r.img);
	image_free(r.ref);
	if (r.has_pov)
		povray_close(&r.pov);
	free(r.points);
	free(r.series);
	scene_free(&r.sc);
	scene_desc_free(&desc);
	diag_fini(&d);
	return rc;
}
