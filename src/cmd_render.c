/* cmd_render.c: scn render: create the output file, load, apply the command line's
 * overrides, lower, render and write the image, reporting each phase's time and the rays
 * by kind with --stats; once, or for each frame of an animation (--frames). */
#include "config.h"

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

static void print_stats(const struct load_times *lt, const struct lower_times *wt, double bvh_s, double render_s,
                        double write_s, const struct scene *sc, const struct ray_stats *st)
{
	fprintf(stderr,
	        "time: parse %.3fs  check %.3fs  evaluate %.3fs  load meshes %.3fs  load images %.3fs  build %s %.3fs"
	        "  render %.3fs  write %.3fs\n",
	        lt->parse, lt->check, lt->eval, wt->load_meshes, wt->load_images, sc->accel.grid ? "grid" : "bvh", bvh_s,
	        render_s, write_s);
	fprintf(stderr, "evaluation: %" PRIu64 " steps, %" PRIu64 " calls of functions and macros\n", lt->evaluated.steps,
	        lt->evaluated.calls);
	fprintf(stderr, "scene: %zu spheres, %zu planes, %zu triangles, %zu solids of %zu parts, %zu lights, %zu materials; ",
	        sc->geo.nspheres, sc->geo.nplanes, sc->geo.ntriangles, sc->geo.nsolids + sc->geo.nunbounded,
	        sc->geo.nparts, sc->nlights, sc->nmaterials);
	if (sc->accel.grid) {
		int cells[3];
		size_t refs;
		grid_shape(sc->accel.grid, cells, &refs);
		fprintf(stderr, "grid %d x %d x %d cells, %zu references\n", cells[0], cells[1], cells[2], refs);
	} else {
		struct bvh_shape shape = bvh_shape(sc->accel.bvh);
		fprintf(stderr, "bvh %zu nodes, depth %d, %zu triangle packets\n", shape.nodes, shape.depth, shape.packets);
	}
	if (sc->npatterns || sc->nimage_maps) {
		/* the image files' texels, each file once */
		uint64_t bytes = 0;
		for (size_t i = 0; i < sc->nimages; i++)
			bytes += image_bytes(sc->images[i]->width, sc->images[i]->height);
		fprintf(stderr, "textures: %zu patterns, %zu image maps of %zu image files (%.1f MB); lookups: pattern %llu"
		        "  image %llu  bump %llu\n", sc->npatterns, sc->nimage_maps, sc->nimages, bytes / 1e6,
		        (unsigned long long)st->patterns, (unsigned long long)st->images, (unsigned long long)st->bumps);
	}
	fprintf(stderr, "rays:  camera %llu  shadow %llu", (unsigned long long)st->camera, (unsigned long long)st->shadow);
	if (sc->narea_lights) /* a scene's area-light tests, its dearest rays, apart from the point lights' */
		fprintf(stderr, "  area shadow %llu (and %llu tests settled without one)", (unsigned long long)st->area_shadow,
		        (unsigned long long)st->area_settled);
	fprintf(stderr, "  reflection %llu  refraction %llu  total %llu\n", (unsigned long long)st->reflection,
	        (unsigned long long)st->refraction,
	        (unsigned long long)(st->camera + st->probe_camera + st->shadow + st->area_shadow + st->reflection +
	                             st->refraction));
	if (st->probe_pixels)
		fprintf(stderr, "error estimate: %llu pixels rendered twice, %llu camera rays\n",
		        (unsigned long long)st->probe_pixels, (unsigned long long)st->probe_camera);
	fprintf(stderr, "non-finite radiance values: %llu\n", (unsigned long long)st->nonfinite);
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

/* --tile: the part being rendered and the strings its header points to. */
struct tile_job {
	struct tile_part p;
	char *settings;
	char scene[33];
};

/* --tile: narrows ro, the output rectangle, to the part's rows, with the whole's pixel
 * count for the probes, and names the part's origin in *part from s (the scene after the
 * overrides). Returns the exit status after the message: a usage error when there are
 * more parts than rows, EXIT_IO when a file the scene reads cannot be read. */
static int start_part(const struct command *self, const struct render_args *a, const struct scene_desc *s,
                      struct render_options *ro, struct tile_job *part)
{
	int w = ro->x1 - ro->x0, h = ro->y1 - ro->y0;
	if (a->tile.n > h)
		return cli_usage_error(self, "--tile %ld/%ld: %ld parts are more than the %d rows of the image", a->tile.k,
		                       a->tile.n, a->tile.n, h);
	ro->whole_pixels = (int64_t)w * h;
	tile_band(a->tile.k, a->tile.n, ro->y0, h, &ro->y0, &ro->y1);
	part->settings = tile_settings(s, a->region ? (const long[4]){ a->x0, a->y0, a->x1, a->y1 } : NULL,
	                               a->accel_name);
	part->p = (struct tile_part){ a->tile, w, h, PACKAGE_VERSION, part->settings, part->scene, false, 0, 0 };
	char err[512];
	int e = tile_scene_hash(s, part->settings, part->scene, err, sizeof err);
	if (e) {
		fprintf(stderr, "scn: %s\n", err);
		return cli_file_status(e);
	}
	return 0;
}

/* Renders s: creates its file, loads the scene at its moment, applies the overrides,
 * lowers, renders and writes. Returns the exit status, after the messages. */
static int render_shot(const struct command *self, const struct render_args *a, const struct shot *s)
{
	/* the output file exists from the start, so that an unwritable place is found
	 * before the render and not after it */
	char err[512];
	struct image_write_options wo = { .bit_depth = (int)a->bit_depth, .float32 = a->float32 || a->tile.n };
	struct image_file file;
	if (image_file_create(&file, s->out, &wo, err, sizeof err) != 0) {
		fprintf(stderr, "scn: %s\n", err);
		return EXIT_IO;
	}
	bool file_open = true;

	struct diag d;
	diag_init(&d, stderr);
	struct diag_mark start = diag_mark(&d);
	struct scene_desc desc;
	struct load_times lt;
	struct lower_times wt = { 0 };
	struct scene sc = { 0 };
	struct image *img = NULL;
	struct render_options ro = { .threads = (int)a->threads, .progress = s->tile_progress };
	struct tile_job part = { .settings = NULL };
	struct tile_header header;
	int rc = (int)load_scene(&d, a->scene, &s->at, &desc, &lt);
	if (rc == 0)
		rc = override(self, a, &desc);
	if (rc == 0) {
		ro.x1 = desc.camera.width, ro.y1 = desc.camera.height;
		if (a->region)
			ro.x0 = (int)a->x0, ro.y0 = (int)a->y0, ro.x1 = (int)a->x1, ro.y1 = (int)a->y1;
		if (a->tile.n)
			rc = start_part(self, a, &desc, &ro, &part);
	}
	if (rc == 0)
		rc = image_fits(a, &desc, &d, ro.x1 - ro.x0, ro.y1 - ro.y0);
	if (rc == 0)
		rc = (int)lower_scene(&d, &desc, &sc, &wt, (int64_t)image_bytes(ro.x1 - ro.x0, ro.y1 - ro.y0));
	scene_desc_free(&desc); /* lowered: its memory goes to the BVH */
	/* nothing is printed before the flush, so the warnings can still go */
	if (s->drop_warnings && d.errors == 0)
		diag_rewind(&d, start);
	diag_flush(&d);
	if (rc)
		goto done;
	double t0 = clock_now();
	accel_build(&sc.accel, &sc.geo, a->accel);
	double bvh_s = clock_now() - t0;

	img = image_new(ro.x1 - ro.x0, ro.y1 - ro.y0);
	if (!img) {
		fprintf(stderr, "scn: cannot allocate a %d x %d image\n", ro.x1 - ro.x0, ro.y1 - ro.y0);
		rc = EXIT_RENDER;
		goto done;
	}
	struct ray_stats st;
	if (s->bar)
		anim_bar_show(s->bar);
	t0 = clock_now();
	int started = render_image(&sc, &ro, img, &st);
	double render_s = clock_now() - t0;
	if (s->bar)
		anim_bar_erase(s->bar);
	if (started != 0) {
		fprintf(stderr, "scn: cannot start the render threads\n");
		rc = EXIT_RENDER;
		goto done;
	}
	if (st.nonfinite)
		fprintf(stderr, "scn: warning: %llu radiance values were not finite and were left out of the image%s%s%s\n",
		        (unsigned long long)st.nonfinite, s->moment ? " (" : "", s->moment ? s->moment : "",
		        s->moment ? ")" : "");
	if (a->tile.n) {
		/* the estimate's sum, recovered from the RMSE, for scn merge's estimate */
		part.p.probed = true;
		part.p.probe_pixels = st.probe_pixels;
		part.p.probe_sum = st.probe_pixels ? 6.0 * (double)st.probe_pixels * st.estimated_rmse * st.estimated_rmse : 0;
		tile_header_init(&header, &part.p);
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
		print_stats(&lt, &wt, bvh_s, render_s, clock_now() - t0, &sc, &st);
	if (!a->quiet) {
		fprintf(stderr, "scn: wrote %s%s%s%s: %d x %d, %d sample%s per pixel, rendered in %.2f s", s->out,
		        s->moment ? " (" : "", s->moment ? s->moment : "", s->moment ? ")" : "", img->width, img->height,
		        sc.sampling.count, sc.sampling.count == 1 ? "" : "s", render_s);
		if (st.estimated_rmse >= 0)
			fprintf(stderr, "; estimated RMSE %.3g", st.estimated_rmse);
		fputc('\n', stderr);
	}
done:
	if (file_open)
		image_file_commit(&file, NULL, err, sizeof err);
	image_free(img);
	scene_free(&sc);
	free(part.settings);
	diag_fini(&d);
	return rc;
}

static int known_format(const struct command *self, const char *out)
{
	if (image_format_of(out) < 0)
		return cli_usage_error(self, "cannot tell the format of '%s' (use .png, .exr or .ppm)", out);
	return 0;
}

/* After the messages of frame k, which failed: which frame it was, and what is written. */
static void frame_failed(const struct anim_frames *f, long k, const char *clock)
{
	char written[96];
	long done = k - f->first;
	if (done == 0)
		snprintf(written, sizeof written, "no frame was written");
	else if (done == 1)
		snprintf(written, sizeof written, "frame %ld was written", f->first);
	else
		snprintf(written, sizeof written, "frames %ld %s %ld were written", f->first, done == 2 ? "and" : "to", k - 1);
	fprintf(stderr, "scn: error: frame %ld (clock %s) failed; %s\n", k, clock, written);
}

/* --frames: each frame a whole render, in order, until one fails. */
static int render_frames(const struct command *self, const struct render_args *a, bool progress)
{
	const struct anim_frames *f = &a->frames;
	char *fallback = a->out ? NULL : cli_default_output(a->scene, ".png");
	struct anim_names names;
	int rc = anim_names_init(&names, self, a->out ? a->out : fallback, a->out != NULL, f);
	free(fallback);
	if (rc)
		return rc;
	char *name = anim_name(&names, f->first); /* every frame's extension is the first's */
	rc = known_format(self, name);
	free(name);
	struct anim_bar bar;
	anim_bar_init(&bar, f->end - f->first);
	for (long k = f->first; rc == 0 && k < f->end; k++) {
		char clock[32], moment[96];
		struct load_frame at = { anim_clock(f, k), k };
		anim_clock_text(at.clock, clock, sizeof clock);
		snprintf(moment, sizeof moment, "frame %ld, clock %s", k, clock);
		name = anim_name(&names, k);
		struct shot s = { .out = name, .at = at, .moment = moment, .drop_warnings = k > f->first,
		                  .bar = progress ? &bar : NULL };
		rc = render_shot(self, a, &s);
		free(name);
		if (rc)
			frame_failed(f, k, clock);
		bar.done++;
	}
	anim_names_free(&names);
	return rc;
}

int cmd_render(const struct command *self, int argc, char **argv)
{
	struct render_args a;
	int rc = parse_args(self, argc, argv, &a);
	if (rc)
		return rc < 0 ? 0 : rc;
	bool progress = !a.quiet && (a.progress >= 0 ? a.progress : isatty(2));
	if (a.animate)
		return render_frames(self, &a, progress);
	char *out = a.out ? xstrdup(a.out) : a.tile.n ? tile_default_output(a.scene, &a.tile)
	                                   : cli_default_output(a.scene, ".png");
	rc = known_format(self, out);
	if (rc == 0) {
		char clock[32], moment[48];
		anim_clock_text(a.clock, clock, sizeof clock);
		snprintf(moment, sizeof moment, "clock %s", clock);
		struct shot s = { .out = out, .at = { a.clock, 0 }, .moment = a.clock_given ? moment : NULL,
		                  .tile_progress = progress };
		rc = render_shot(self, &a, &s);
	}
	free(out);
	return rc;
}
