/* cmd_render.c: scn render: create the output file, load, apply the command line's
 * overrides, lower, render and write the image, reporting each phase's time and the rays
 * by kind with --stats; once, or for each frame of an animation (--frames). */
#include "config.h"

#include <fcntl.h>
#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "accel.h"
#include "anim.h"
#include "cli.h"
#include "clock.h"
#include "diag.h"
#include "dist.h"
#include "image_file.h"
#include "load.h"
#include "lower.h"
#include "render.h"
#include "scene_desc.h"
#include "tile.h"
#include "tile_part.h"
#include "xalloc.h"

struct render_args {
	const char *scene, *out;
	long width, height, samples, depth, threads, seed, bit_depth;
	int pattern;                       /* -1: the scene's */
	bool float32, stats, quiet;
	int progress;                      /* -1: when standard error is a terminal */
	enum accel_kind accel;
	const char *accel_name;
	bool region;
	long x0, y0, x1, y1;
	bool clock_given;                  /* --clock */
	double clock;
	bool animate, cyclic;              /* --frames, --cyclic */
	struct anim_frames frames;
	struct tile tile;                  /* --tile; n 0: none */
};

enum {
	OPT_OUT, OPT_WIDTH, OPT_HEIGHT, OPT_SAMPLES, OPT_PATTERN, OPT_DEPTH, OPT_THREADS, OPT_ACCEL, OPT_REGION,
	OPT_SEED, OPT_BIT_DEPTH, OPT_FLOAT, OPT_STATS, OPT_PROGRESS, OPT_NO_PROGRESS, OPT_QUIET, OPT_CLOCK, OPT_FRAMES,
	OPT_CYCLIC, OPT_TILE, NOPTIONS
};
static const struct cli_option options[NOPTIONS] = {
	[OPT_OUT] = { NULL, 'o', true },
	[OPT_WIDTH] = { NULL, 'W', true },
	[OPT_HEIGHT] = { NULL, 'H', true },
	[OPT_SAMPLES] = { NULL, 's', true },
	[OPT_PATTERN] = { NULL, 'p', true },
	[OPT_DEPTH] = { NULL, 'd', true },
	[OPT_THREADS] = { NULL, 'j', true },
	[OPT_ACCEL] = { "accel", 0, true },
	[OPT_REGION] = { "region", 0, true },
	[OPT_SEED] = { "seed", 0, true },
	[OPT_BIT_DEPTH] = { "bit-depth", 0, true },
	[OPT_FLOAT] = { "float", 0, false },
	[OPT_STATS] = { "stats", 0, false },
	[OPT_PROGRESS] = { "progress", 0, false },
	[OPT_NO_PROGRESS] = { "no-progress", 0, false },
	[OPT_QUIET] = { NULL, 'q', false },
	[OPT_CLOCK] = { "clock", 0, true },
	[OPT_FRAMES] = { "frames", 0, true },
	[OPT_CYCLIC] = { "cyclic", 0, false },
	[OPT_TILE] = { "tile", 0, true },
};

/* Reads the command line into *a: 0, or -1 once the help is shown, or EXIT_USAGE after a
 * usage message. */
static int parse_args(const struct command *self, int argc, char **argv, struct render_args *a)
{
	*a = (struct render_args){ .width = -1, .height = -1, .samples = -1, .depth = -1, .threads = 0,
	                           .seed = -1, .bit_depth = 8, .pattern = -1, .progress = -1,
	                           .accel_name = "bvh" };
	struct cli_parser p;
	cli_parser_init(&p, self, options, NOPTIONS, argc, argv);
	int o;
	while ((o = cli_next_option(&p)) >= 0) {
		const char *v = p.value;
		long *target = NULL, lo = 0, hi = 0;
		switch (o) {
		case OPT_FLOAT: a->float32 = true; continue;
		case OPT_STATS: a->stats = true; continue;
		case OPT_PROGRESS: a->progress = 1; continue;
		case OPT_NO_PROGRESS: a->progress = 0; continue;
		case OPT_QUIET: a->quiet = true; continue;
		case OPT_OUT: a->out = v; continue;
		case OPT_CYCLIC: a->cyclic = true; continue;
		case OPT_CLOCK:
			if (anim_clock_arg(self, p.name, v, &a->clock))
				return EXIT_USAGE;
			a->clock_given = true;
			continue;
		case OPT_FRAMES:
			if (anim_frames_arg(self, p.name, v, &a->frames))
				return EXIT_USAGE;
			a->animate = true;
			continue;
		case OPT_TILE: {
			const char *why = tile_parse(v, &a->tile);
			if (why)
				return cli_usage_error(self, "bad --tile '%s': %s", v, why);
			continue;
		}
		case OPT_WIDTH: target = &a->width; lo = 1; hi = 65536; break;
		case OPT_HEIGHT: target = &a->height; lo = 1; hi = 65536; break;
		case OPT_SAMPLES: target = &a->samples; lo = 1; hi = 65536; break;
		case OPT_DEPTH: target = &a->depth; lo = 1; hi = 256; break;
		case OPT_THREADS: target = &a->threads; lo = 0; hi = 4096; break;
		case OPT_SEED: target = &a->seed; lo = 0; hi = 0x7fffffffffffffffL; break;
		case OPT_BIT_DEPTH: target = &a->bit_depth; lo = 8; hi = 16; break;
		case OPT_PATTERN:
			a->pattern = -1;
			for (int k = 0; k < PATTERN_COUNT; k++)
				if (strcmp(v, scene_desc_pattern_name(k)) == 0)
					a->pattern = k;
			if (a->pattern < 0)
				return cli_usage_error(self, "unknown pattern '%s' (center, grid, random, jittered, poisson)", v);
			continue;
		case OPT_ACCEL:
			if (strcmp(v, "bvh") == 0)
				a->accel = ACCEL_BVH;
			else if (strcmp(v, "grid") == 0)
				a->accel = ACCEL_GRID;
			else if (strcmp(v, "none") == 0)
				a->accel = ACCEL_NONE;
			else
				return cli_usage_error(self, "unknown accelerator '%s' (bvh, grid or none)", v);
			a->accel_name = v;
			continue;
		default: { /* OPT_REGION */
			char tail;
			if (sscanf(v, "%ld,%ld,%ld,%ld%c", &a->x0, &a->y0, &a->x1, &a->y1, &tail) != 4)
				return cli_usage_error(self, "bad region '%s' (X0,Y0,X1,Y1)", v);
			a->region = true;
			continue;
		}
		}
		if (!cli_int(v, lo, hi, target) || (target == &a->bit_depth && *target != 8 && *target != 16))
			return cli_usage_error(self, "bad value '%s' for %s (%s)", v, p.name,
			                       target == &a->bit_depth ? "8 or 16" : "a whole number in range");
	}
	if (o == CLI_STOP)
		return p.status;
	if (a->clock_given && a->animate)
		return cli_usage_error(self, "--clock and --frames do not go together: --frames sets each frame's clock");
	if (a->cyclic && !a->animate)
		return cli_usage_error(self, "--cyclic needs --frames");
	if (a->tile.n && a->animate)
		return cli_usage_error(self, "--tile and --frames do not go together: render one frame per task with "
		                       "--frames F..F+1");
	if (a->tile.n && a->out && image_format_of(a->out) != IMAGE_EXR)
		return cli_usage_error(self, "--tile writes a 32-bit float OpenEXR part: '%s' must end in .exr", a->out);
	a->frames.cyclic = a->cyclic;
	if (!(a->scene = cli_scene(&p)))
		return EXIT_USAGE;
	/* load_scene reads the scene anew for each frame, and standard input reads once */
	if (a->animate && strcmp(a->scene, "-") == 0)
		return cli_usage_error(self, "--frames reads the scene once for each frame: it cannot come from standard input");
	return 0;
}

/* Applies the command line's overrides to the scene; a combination the language would
 * reject is a usage error. */
static int override(const struct command *self, const struct render_args *a, struct scene_desc *s)
{
	if (a->width > 0)
		s->camera.width = (int)a->width;
	if (a->height > 0)
		s->camera.height = (int)a->height;
	if ((double)s->camera.width * s->camera.height > (double)IMAGE_MAX_PIXELS)
		return cli_usage_error(self, "%d x %d is more pixels than the limit of 2^28", s->camera.width,
		                       s->camera.height);
	if (a->samples > 0)
		s->samples.count = (int)a->samples;
	if (a->pattern >= 0)
		s->samples.pattern = (enum sample_pattern)a->pattern;
	else if (!s->samples.pattern_given) /* the default follows the count, as in a scene */
		s->samples.pattern = s->samples.count == 1 ? PATTERN_CENTER : PATTERN_JITTERED;
	if (a->depth > 0)
		s->max_depth = (int)a->depth;
	if (a->seed >= 0)
		s->samples.seed = (uint64_t)a->seed;
	if (a->region && (a->x0 < 0 || a->y0 < 0 || a->x0 >= a->x1 || a->y0 >= a->y1 || a->x1 > s->camera.width ||
	                  a->y1 > s->camera.height))
		return cli_usage_error(self, "region %ld,%ld,%ld,%ld is not inside the %d x %d image", a->x0, a->y0, a->x1,
		                       a->y1, s->camera.width, s->camera.height);
	int n = s->samples.count, root = (int)sqrt((double)n);
	if (s->samples.pattern == PATTERN_CENTER && n != 1)
		return cli_usage_error(self, "pattern center takes exactly one sample, not %d", n);
	if (s->samples.pattern == PATTERN_GRID && root * root != n)
		return cli_usage_error(self, "pattern grid needs a square sample count (1, 4, 9, 16, ...), not %d", n);
	if (s->samples.pattern == PATTERN_GRID && s->samples.target_error > 0)
		return cli_usage_error(self, "the scene's target_error needs a random, jittered or poisson pattern, not grid");
	return 0;
}

/* Whether the w x h image fits the machine's memory; if not, an error at the scene's
 * resolution or naming the options that set the size, and EXIT_RENDER. */
static int image_fits(const struct render_args *a, const struct scene_desc *s, struct diag *d, int w, int h)
{
	char what[64], options[160] = "";
	snprintf(what, sizeof what, "a %d x %d image", w, h);
	if (a->width > 0)
		snprintf(options, sizeof options, "-W %ld", a->width);
	if (a->height > 0)
		snprintf(options + strlen(options), sizeof options - strlen(options), "%s-H %ld", *options ? " " : "",
		         a->height);
	if (a->region)
		snprintf(options + strlen(options), sizeof options - strlen(options), "%s--region %ld,%ld,%ld,%ld",
		         *options ? " " : "", a->x0, a->y0, a->x1, a->y1);
	return cli_memory_fits(d, *options ? NULL : &s->camera.resolution_span, options, what, image_bytes(w, h));
}

/* --tile: the part being rendered and the strings its header points to. */
struct tile_job {
	struct tile_part p;
	char *settings;
	char scene[33];
};

/* --tile: narrows ro, the output rectangle, to the part's rows, with the whole's pixel
 * count for the probes, and names the part's origin in *part from s (the scene after the
 * overrides). Returns the exit status after the message: a usage error when there are
 * more parts than rows (said only where speaks: process 0), EXIT_IO in d when a file
 * the scene reads cannot be read. */
static int start_part(const struct command *self, const struct render_args *a, const struct scene_desc *s,
                      struct render_options *ro, struct tile_job *part, struct diag *d, bool speaks)
{
	int w = ro->x1 - ro->x0, h = ro->y1 - ro->y0;
	if (a->tile.n > h) /* the same on every process: process 0 alone says it */
		return speaks ? cli_usage_error(self, "--tile %ld/%ld: %ld parts are more than the %d rows of the image",
		                                a->tile.k, a->tile.n, a->tile.n, h)
		              : EXIT_USAGE;
	ro->whole_pixels = (int64_t)w * h;
	tile_band(a->tile.k, a->tile.n, ro->y0, h, &ro->y0, &ro->y1);
	part->settings = tile_settings(s, a->region ? (const long[4]){ a->x0, a->y0, a->x1, a->y1 } : NULL,
	                               a->accel_name);
	part->p = (struct tile_part){ a->tile, w, h, PACKAGE_VERSION, part->settings, part->scene, false, 0, 0 };
	char err[512];
	int e = tile_scene_hash(s, part->settings, part->scene, err, sizeof err);
	if (e) {
		diag_plain(d, DIAG_ERROR, "%s", err);
		return cli_file_status(e);
	}
	return 0;
}

/* What is known of a render once the scene is loaded, lowered and built: the same on
 * every process of a render over several. */
struct prepared {
	struct load_times lt;
	struct lower_times wt;
	struct scene sc;
	struct render_options ro;
	struct tile_job part;              /* with --tile */
	double bvh_s;
};

/* --stats to out; write_s < 0: the write time is process 0's to fill in, at
 * DIST_WRITE_MARK (a frame rendered by another process). traffic: what other processes
 * sent of this image, or NULL. */
static void print_stats(FILE *out, const struct prepared *p, double render_s, double write_s,
                        const struct ray_stats *st, const struct dist_world *w, const struct dist_traffic *traffic)
{
	const struct load_times *lt = &p->lt;
	const struct lower_times *wt = &p->wt;
	const struct scene *sc = &p->sc;
	fprintf(out, "time: parse %.3fs  check %.3fs  evaluate %.3fs  load meshes %.3fs  load images %.3fs  build %s %.3fs"
	        "  render %.3fs  write ", lt->parse, lt->check, lt->eval, wt->load_meshes, wt->load_images,
	        sc->accel.grid ? "grid" : "bvh", p->bvh_s, render_s);
	if (write_s < 0)
		fputs(DIST_WRITE_MARK "s\n", out);
	else
		fprintf(out, "%.3fs\n", write_s);
	fprintf(out, "evaluation: %" PRIu64 " steps, %" PRIu64 " calls of functions and macros\n", lt->evaluated.steps,
	        lt->evaluated.calls);
	fprintf(out, "scene: %zu spheres, %zu planes, %zu triangles, %zu solids of %zu parts, %zu lights, %zu materials; ",
	        sc->geo.nspheres, sc->geo.nplanes, sc->geo.ntriangles, sc->geo.nsolids + sc->geo.nunbounded,
	        sc->geo.nparts, sc->nlights, sc->nmaterials);
	if (sc->accel.grid) {
		int cells[3];
		size_t refs;
		grid_shape(sc->accel.grid, cells, &refs);
		fprintf(out, "grid %d x %d x %d cells, %zu references\n", cells[0], cells[1], cells[2], refs);
	} else {
		struct bvh_shape shape = bvh_shape(sc->accel.bvh);
		fprintf(out, "bvh %zu nodes, depth %d, %zu triangle packets\n", shape.nodes, shape.depth, shape.packets);
	}
	if (sc->npatterns || sc->nimage_maps) {
		/* the image files' texels, each file once */
		uint64_t bytes = 0;
		for (size_t i = 0; i < sc->nimages; i++)
			bytes += image_bytes(sc->images[i]->width, sc->images[i]->height);
		fprintf(out, "textures: %zu patterns, %zu image maps of %zu image files (%.1f MB); lookups: pattern %llu"
		        "  image %llu  bump %llu\n", sc->npatterns, sc->nimage_maps, sc->nimages, bytes / 1e6,
		        (unsigned long long)st->patterns, (unsigned long long)st->images, (unsigned long long)st->bumps);
	}
	fprintf(out, "rays:  camera %llu  shadow %llu", (unsigned long long)st->camera, (unsigned long long)st->shadow);
	if (sc->narea_lights) /* a scene's area-light tests, its dearest rays, apart from the point lights' */
		fprintf(out, "  area shadow %llu (and %llu tests settled without one)", (unsigned long long)st->area_shadow,
		        (unsigned long long)st->area_settled);
	fprintf(out, "  reflection %llu  refraction %llu  total %llu\n", (unsigned long long)st->reflection,
	        (unsigned long long)st->refraction,
	        (unsigned long long)(st->camera + st->probe_camera + st->shadow + st->area_shadow + st->reflection +
	                             st->refraction));
	if (st->probe_pixels)
		fprintf(out, "error estimate: %llu pixels rendered twice, %llu camera rays\n",
		        (unsigned long long)st->probe_pixels, (unsigned long long)st->probe_camera);
	fprintf(out, "non-finite radiance values: %llu\n", (unsigned long long)st->nonfinite);
	if (traffic && w->size > 1)
		fprintf(out, "processes: %d; %ld of %d tiles from the others in %ld messages, %.0f bytes (%.0f a tile);"
		        " gathering them took %.3fs\n", w->size, traffic->tiles, render_tile_count(&p->ro), traffic->messages,
		        traffic->bytes, traffic->tiles ? traffic->bytes / (double)traffic->tiles : 0.0, traffic->gather_s);
}

/* Loads the scene at moment at, applies the overrides, lowers and builds. The
 * diagnostics go to to, all printed before the build (drop_warnings: the errors alone);
 * the image's memory is counted against the machine's only where it is made
 * (makes_image: process 0, which alone prints a usage error). Returns the exit status. */
static int prepare(const struct command *self, const struct render_args *a, const struct load_frame *at,
                   bool makes_image, FILE *to, bool drop_warnings, struct prepared *p)
{
	struct diag d;
	diag_init(&d, to);
	struct diag_mark start = diag_mark(&d);
	struct scene_desc desc;
	*p = (struct prepared){ .ro = { .threads = (int)a->threads } };
	int rc = (int)load_scene(&d, a->scene, at, &desc, &p->lt);
	struct render_options *ro = &p->ro;
	if (rc == 0)
		rc = override(self, a, &desc);
	if (rc == 0) {
		ro->x1 = desc.camera.width, ro->y1 = desc.camera.height;
		if (a->region)
			ro->x0 = (int)a->x0, ro->y0 = (int)a->y0, ro->x1 = (int)a->x1, ro->y1 = (int)a->y1;
		if (a->tile.n)
			rc = start_part(self, a, &desc, ro, &p->part, &d, makes_image);
	}
	if (rc == 0 && makes_image)
		rc = image_fits(a, &desc, &d, ro->x1 - ro->x0, ro->y1 - ro->y0);
	int64_t image = makes_image ? (int64_t)image_bytes(ro->x1 - ro->x0, ro->y1 - ro->y0) : 0;
	if (rc == 0)
		rc = (int)lower_scene(&d, &desc, &p->sc, &p->wt, image);
	scene_desc_free(&desc); /* lowered: its memory goes to the BVH */
	/* nothing is printed before this, so the warnings can still go */
	if (drop_warnings && d.errors == 0)
		diag_rewind(&d, start);
	diag_fini(&d);
	if (rc == 0) {
		double t0 = clock_now();
		accel_build(&p->sc.accel, &p->sc.geo, a->accel);
		p->bvh_s = clock_now() - t0;
	}
	return rc;
}

/* A new image of p's rectangle, or NULL after a message. */
static struct image *new_image(const struct prepared *p)
{
	const struct render_options *ro = &p->ro;
	struct image *img = image_new(ro->x1 - ro->x0, ro->y1 - ro->y0);
	if (!img)
		fprintf(stderr, "scn: cannot allocate a %d x %d image\n", ro->x1 - ro->x0, ro->y1 - ro->y0);
	return img;
}

/* " (frame 3, clock 0.25)", or "" for a still without --clock. */
static const char *moment_note(const char *moment, char *buf, size_t size)
{
	if (!moment)
		return "";
	snprintf(buf, size, " (%s)", moment);
	return buf;
}

static void warn_nonfinite(FILE *out, const struct ray_stats *st, const char *moment)
{
	char note[128];
	if (st->nonfinite)
		fprintf(out, "scn: warning: %llu radiance values were not finite and were left out of the image%s\n",
		        (unsigned long long)st->nonfinite, moment_note(moment, note, sizeof note));
}

static void report_written(const char *out, const char *moment, const struct image *img, int samples,
                           double render_s, double rmse)
{
	char note[128];
	fprintf(stderr, "scn: wrote %s%s: %d x %d, %d sample%s per pixel, rendered in %.2f s", out,
	        moment_note(moment, note, sizeof note), img->width, img->height, samples, samples == 1 ? "" : "s",
	        render_s);
	if (rmse >= 0)
		fprintf(stderr, "; estimated RMSE %.3g", rmse);
	fputc('\n', stderr);
}

/* One render and its image file: the whole of a still, or one frame of --frames. */
struct shot {
	const char *out;                   /* the image file */
	struct load_frame at;              /* the moment the scene is evaluated at */
	const char *moment;                /* "frame 3, clock 0.25" for the messages, or NULL */
	bool drop_warnings;                /* a frame after the first: its warnings only if it fails */
	bool tile_progress;                /* render_image's progress bar */
	struct anim_bar *bar;              /* the bar over frames, shown while this one renders, or NULL */
};

/* Renders s on every process of w: process 0 creates the file, loads the scene at its
 * moment, applies the overrides, lowers, renders its share and writes; the others load,
 * lower and render their shares, saying nothing unless they alone fail. Returns the exit
 * status, after the messages. */
static int render_shot(const struct command *self, const struct render_args *a, const struct shot *s,
                       const struct dist_world *w)
{
	bool writer = w->rank == 0;
	/* the output file exists from the start, so that an unwritable place is found
	 * before the render and not after it */
	char err[512];
	struct image_write_options wo = { .bit_depth = (int)a->bit_depth, .float32 = a->float32 || a->tile.n };
	struct image_file file;
	int rc = writer ? image_file_create(&file, s->out, &wo, err, sizeof err) : 0;
	if (rc != 0)
		fprintf(stderr, "scn: %s\n", err);
	if (rc != 0 && w->size == 1)
		return EXIT_IO;
	rc = rc ? EXIT_IO : 0;
	bool file_open = writer && rc == 0;

	/* the other processes' messages are kept, for process 0 to print if they alone fail */
	char *kept = NULL;
	size_t kept_size = 0;
	FILE *to = writer ? stderr : open_memstream(&kept, &kept_size);
	struct prepared p = { 0 };
	struct image *img = NULL;
	if (rc == 0)
		rc = prepare(self, a, &s->at, writer, to ? to : stderr, s->drop_warnings || !writer, &p);
	if (!writer && to)
		fclose(to);
	if (rc == 0 && writer && !(img = new_image(&p)))
		rc = EXIT_RENDER;
	rc = dist_agree(w, rc, kept);
	free(kept);
	if (rc)
		goto done;

	struct ray_stats st;
	struct dist_traffic traffic;
	p.ro.progress = s->tile_progress && writer;
	if (s->bar && writer)
		anim_bar_show(s->bar);
	double t0 = clock_now();
	int started = dist_render_image(w, &p.sc, &p.ro, img, &st, &traffic);
	double render_s = clock_now() - t0;
	if (s->bar && writer)
		anim_bar_erase(s->bar);
	if (started != 0) {
		fprintf(stderr, "scn: cannot start the render threads\n");
		rc = EXIT_RENDER;
		goto done;
	}
	if (!writer)
		goto done;
	warn_nonfinite(stderr, &st, s->moment);
	struct tile_header header;
	if (a->tile.n) {
		/* the estimate's sums, for scn merge's estimate of the whole */
		struct tile_part *part = &p.part.p;
		part->probed = true;
		part->probe_pixels = st.probe_pixels;
		part->probe_sum = st.probe_sum;
		tile_header_init(&header, part);
		file.opt.exr = &header.exr;
	}
	t0 = clock_now();
	file_open = false;
	int e = image_file_commit(&file, img, err, sizeof err);
	if (e != 0) {
		fprintf(stderr, "scn: %s\n", err);
		rc = cli_file_status(e);
		goto done;
	}
	if (a->stats)
		print_stats(stderr, &p, render_s, clock_now() - t0, &st, w, &traffic);
	if (!a->quiet)
		report_written(s->out, s->moment, img, p.sc.sampling.count, render_s, st.estimated_rmse);
done:
	if (file_open)
		image_file_commit(&file, NULL, err, sizeof err);
	image_free(img);
	scene_free(&p.sc);
	free(p.part.settings);
	return rc;
}

static int known_format(const struct command *self, const char *out)
{
	if (image_format_of(out) < 0)
		return cli_usage_error(self, "cannot tell the format of '%s' (use .png, .exr or .ppm)", out);
	return 0;
}

/* After the messages of frame k, which failed: which frame it was, and what is written:
 * the frames before it, or, from several processes, others too. */
static void frame_failed(const struct anim_frames *f, long k, long written)
{
	char clock[32], what[96];
	anim_clock_text(anim_clock(f, k), clock, sizeof clock);
	if (written == 0)
		snprintf(what, sizeof what, "no frame was written");
	else if (written != k - f->first)
		snprintf(what, sizeof what, "%ld other frame%s written", written, written == 1 ? " was" : "s were");
	else if (written == 1)
		snprintf(what, sizeof what, "frame %ld was written", f->first);
	else
		snprintf(what, sizeof what, "frames %ld %s %ld were written", f->first, written == 2 ? "and" : "to", k - 1);
	fprintf(stderr, "scn: error: frame %ld (clock %s) failed; %s\n", k, clock, what);
}

/* "frame 3, clock 0.25": how the messages name frame k. */
static void frame_moment(const struct anim_frames *f, long k, char *buf, size_t size)
{
	char clock[32];
	anim_clock_text(anim_clock(f, k), clock, sizeof clock);
	snprintf(buf, size, "frame %ld, clock %s", k, clock);
}

/* The frames' output names, checked: 0, or the exit status after a message. */
static int frame_names(const struct command *self, const struct render_args *a, struct anim_names *names)
{
	char *fallback = a->out ? NULL : cli_default_output(a->scene, ".png");
	int rc = anim_names_init(names, self, a->out ? a->out : fallback, a->out != NULL, &a->frames);
	free(fallback);
	if (rc)
		return rc;
	char *name = anim_name(names, a->frames.first); /* every frame's extension is the first's */
	rc = known_format(self, name);
	free(name);
	if (rc)
		anim_names_free(names);
	return rc;
}

/* --frames on one process, or on fewer than the frames: each frame a whole render, in
 * order, until one fails. */
static int render_frames(const struct command *self, const struct render_args *a, bool progress,
                         const struct dist_world *w)
{
	const struct anim_frames *f = &a->frames;
	struct anim_names names;
	int rc = frame_names(self, a, &names);
	if (rc)
		return rc;
	struct anim_bar bar;
	anim_bar_init(&bar, f->end - f->first);
	for (long k = f->first; rc == 0 && k < f->end; k++) {
		char moment[96];
		frame_moment(f, k, moment, sizeof moment);
		char *name = anim_name(&names, k);
		struct shot s = { .out = name, .at = { anim_clock(f, k), k }, .moment = moment,
		                  .drop_warnings = k > f->first, .bar = progress ? &bar : NULL };
		rc = render_shot(self, a, &s, w);
		free(name);
		if (rc && w->rank == 0)
			frame_failed(f, k, k - f->first);
		bar.done++;
	}
	anim_names_free(&names);
	return rc;
}

/* --frames over at least as many frames as processes: whole frames per process. */
struct spread {
	const struct command *self;
	const struct render_args *a;
	struct anim_names names;
	struct anim_bar *bar;              /* on process 0 with --progress, or NULL */
};

/* Renders frame k into *out, its messages kept for process 0 to print. */
static int spread_render(void *ctx, long k, struct dist_frame *out)
{
	struct spread *sp = ctx;
	const struct render_args *a = sp->a;
	*out = (struct dist_frame){ .k = k, .rmse = -1 };
	size_t size;
	FILE *to = open_memstream(&out->messages, &size);
	struct prepared p;
	struct load_frame at = { anim_clock(&a->frames, k), k };
	int rc = prepare(sp->self, a, &at, true, to ? to : stderr, k > a->frames.first, &p);
	if (rc == 0 && !(out->img = new_image(&p)))
		rc = EXIT_RENDER;
	if (rc == 0) {
		struct ray_stats st;
		double t0 = clock_now();
		if (render_image(&p.sc, &p.ro, out->img, &st) != 0) {
			fprintf(to ? to : stderr, "scn: cannot start the render threads\n");
			rc = EXIT_RENDER;
		}
		out->render_s = clock_now() - t0;
		out->rmse = st.estimated_rmse;
		out->samples = p.sc.sampling.count;
		char moment[96];
		frame_moment(&a->frames, k, moment, sizeof moment);
		warn_nonfinite(to ? to : stderr, &st, moment);
		size_t stats_size;
		FILE *stats = a->stats ? open_memstream(&out->stats, &stats_size) : NULL;
		if (stats) {
			print_stats(stats, &p, out->render_s, -1, &st, NULL, NULL);
			fclose(stats);
		}
	}
	if (to)
		fclose(to);
	if (rc) {
		image_free(out->img);
		out->img = NULL;
	}
	out->status = rc;
	scene_free(&p.sc);
	return rc;
}

/* On process 0: prints frame f's messages, writes it, and reports. */
static int spread_deliver(void *ctx, struct dist_frame *f)
{
	struct spread *sp = ctx;
	const struct render_args *a = sp->a;
	if (sp->bar)
		anim_bar_erase(sp->bar);
	if (f->messages)
		fputs(f->messages, stderr);
	int rc = f->status;
	if (rc == 0) {
		char err[512], moment[96];
		char *name = anim_name(&sp->names, f->k);
		struct image_write_options wo = { .bit_depth = (int)a->bit_depth, .float32 = a->float32 };
		struct image_file file;
		double t0 = clock_now();
		int e = image_file_create(&file, name, &wo, err, sizeof err);
		if (e == 0)
			e = image_file_commit(&file, f->img, err, sizeof err);
		if (e) {
			fprintf(stderr, "scn: %s\n", err);
			rc = cli_file_status(e);
		}
		if (rc == 0 && f->stats) {
			char *mark = strstr(f->stats, DIST_WRITE_MARK);
			if (mark)
				fprintf(stderr, "%.*s%.3f%s", (int)(mark - f->stats), f->stats, clock_now() - t0, mark + 1);
		}
		frame_moment(&a->frames, f->k, moment, sizeof moment);
		if (rc == 0 && !a->quiet)
			report_written(name, moment, f->img, f->samples, f->render_s, f->rmse);
		free(name);
	}
	if (sp->bar) {
		sp->bar->done++;
		anim_bar_show(sp->bar);
	}
	return rc;
}

static int render_frames_spread(const struct command *self, const struct render_args *a, bool progress,
                                const struct dist_world *w)
{
	struct spread sp = { .self = self, .a = a };
	int rc = frame_names(self, a, &sp.names);
	if (rc)
		return rc;
	struct anim_bar bar;
	anim_bar_init(&bar, a->frames.end - a->frames.first);
	sp.bar = progress && w->rank == 0 ? &bar : NULL;
	if (sp.bar)
		anim_bar_show(sp.bar);
	long failed, written;
	rc = dist_render_frames(w, &(struct dist_frames){ a->frames.first, a->frames.end, spread_render,
	                                                  spread_deliver, &sp }, &failed, &written);
	if (sp.bar)
		anim_bar_erase(sp.bar);
	if (failed >= 0)
		frame_failed(&a->frames, failed, written);
	anim_names_free(&sp.names);
	return rc;
}

/* Runs the render that the arguments ask for on every process of w. */
static int render_run(const struct command *self, const struct render_args *a, const struct dist_world *w)
{
	bool progress = !a->quiet && (a->progress >= 0 ? a->progress : isatty(2));
	if (a->animate && w->size > 1 && a->frames.end - a->frames.first >= w->size)
		return render_frames_spread(self, a, progress, w);
	if (a->animate)
		return render_frames(self, a, progress, w);
	char *out = a->out ? xstrdup(a->out) : a->tile.n ? tile_default_output(a->scene, &a->tile)
	                                     : cli_default_output(a->scene, ".png");
	int rc = known_format(self, out);
	if (rc == 0) {
		char clock[32], moment[48];
		anim_clock_text(a->clock, clock, sizeof clock);
		snprintf(moment, sizeof moment, "clock %s", clock);
		struct shot s = { .out = out, .at = { a->clock, 0 }, .moment = a->clock_given ? moment : NULL,
		                  .tile_progress = progress };
		rc = render_shot(self, a, &s, w);
	}
	free(out);
	return rc;
}

/* parse_args, with standard output and error thrown away when quiet: the command line
 * is read on every process, and process 0 alone says what is wrong with it. */
static int parse_quietly(bool quiet, const struct command *self, int argc, char **argv, struct render_args *a)
{
	int saved[2] = { -1, -1 };
	int null = quiet ? open("/dev/null", O_WRONLY) : -1;
	if (null >= 0) {
		fflush(stdout);
		fflush(stderr);
		for (int fd = 1; fd <= 2; fd++) {
			saved[fd - 1] = dup(fd);
			dup2(null, fd);
		}
		close(null);
	}
	int rc = parse_args(self, argc, argv, a);
	if (null >= 0) {
		fflush(stdout);
		fflush(stderr);
		for (int fd = 1; fd <= 2; fd++)
			if (saved[fd - 1] >= 0) {
				dup2(saved[fd - 1], fd);
				close(saved[fd - 1]);
			}
	}
	return rc;
}

int cmd_render(const struct command *self, int argc, char **argv)
{
	/* under an MPI launcher, scn becomes scn-mpi here, with scn render's arguments */
	char **all = xmalloc(((size_t)argc + 2) * sizeof *all);
	all[0] = "scn-mpi";
	memcpy(all + 1, argv, (size_t)argc * sizeof *argv);
	all[argc + 1] = NULL;
	struct dist_world w;
	int rc = dist_start(all, &w);
	free(all);
	if (rc)
		return rc;
	struct render_args a;
	rc = parse_quietly(w.rank != 0, self, argc, argv, &a);
	if (rc == 0)
		rc = render_run(self, &a, &w);
	dist_end(&w);
	/* process 0 has said what failed, and its status is the run's: another process that
	 * ended with one first would have the launcher stop process 0 before it could */
	return rc < 0 || w.rank != 0 ? 0 : rc;
}
