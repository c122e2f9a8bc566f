/* cmd_merge.c: scn merge: joins the parts of `scn render --tile` into the whole image,
 * once they are shown to be parts of one render that cover it exactly once; the pixels
 * are the parts' 32-bit floats, so the file has the bytes of a render of the whole. */
#include "config.h"

#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "image_file.h"
#include "memory.h"
#include "tile.h"
#include "tile_part.h"
#include "xalloc.h"

struct merge_args {
	const char *out;
	long bit_depth;
	bool float32, quiet;
	char **parts;
	int nparts;
};

enum { OPT_OUT, OPT_BIT_DEPTH, OPT_FLOAT, OPT_QUIET, NOPTIONS };
static const struct cli_option options[NOPTIONS] = {
	[OPT_OUT] = { NULL, 'o', true },
	[OPT_BIT_DEPTH] = { "bit-depth", 0, true },
	[OPT_FLOAT] = { "float", 0, false },
	[OPT_QUIET] = { NULL, 'q', false },
};

/* Reads the command line into *a: 0, or -1 once the help is shown, or EXIT_USAGE after a
 * usage message. */
static int parse_args(const struct command *self, int argc, char **argv, struct merge_args *a)
{
	*a = (struct merge_args){ .bit_depth = 8 };
	struct cli_parser p;
	cli_parser_init(&p, self, options, NOPTIONS, argc, argv);
	int o;
	while ((o = cli_next_option(&p)) >= 0) {
		switch (o) {
		case OPT_OUT: a->out = p.value; break;
		case OPT_FLOAT: a->float32 = true; break;
		case OPT_QUIET: a->quiet = true; break;
		default: /* OPT_BIT_DEPTH */
			if (!cli_int(p.value, 8, 16, &a->bit_depth) || (a->bit_depth != 8 && a->bit_depth != 16))
				return cli_usage_error(self, "bad value '%s' for %s (8 or 16)", p.value, p.name);
		}
	}
	if (o == CLI_STOP)
		return p.status;
	if (!(a->parts = cli_operands(&p, &a->nparts)))
		return EXIT_USAGE;
	if (a->nparts == 0)
		return cli_usage_error(self, "no parts given");
	if (!a->out)
		return cli_usage_error(self, "no output given (-o OUT)");
	if (image_format_of(a->out) < 0)
		return cli_usage_error(self, "cannot tell the format of '%s' (use .png, .exr or .ppm)", a->out);
	return 0;
}

/* Whether part b comes from the same render as part a: else says why, naming both
 * files, and returns false. */
static bool same_render(const struct tile_file *a, const char *pa, const struct tile_file *b, const char *pb)
{
	const struct tile_part *x = &a->p, *y = &b->p;
	if (strcmp(x->version, y->version) != 0)
		fprintf(stderr, "scn: error: '%s' and '%s' come from different versions of scn (%s and %s)\n", pa, pb,
		        x->version, y->version);
	else if (x->t.n != y->t.n)
		fprintf(stderr, "scn: error: '%s' and '%s' are parts of different splits (into %ld and %ld parts)\n", pa,
		        pb, x->t.n, y->t.n);
	else if (strcmp(x->settings, y->settings) != 0)
		fprintf(stderr, "scn: error: '%s' and '%s' are parts of renders with different settings ('%s' and '%s')\n",
		        pa, pb, x->settings, y->settings);
	else if (strcmp(x->scene, y->scene) != 0)
		fprintf(stderr, "scn: error: '%s' and '%s' are parts of different scenes (the scenes or the files they read "
		        "differ)\n", pa, pb);
	else if (x->width != y->width || x->height != y->height)
		fprintf(stderr, "scn: error: '%s' and '%s' are parts of images of different sizes (%d x %d and %d x %d)\n",
		        pa, pb, x->width, x->height, y->width, y->height);
	else
		return true;
	return false;
}

/* A part read: its number, its file, and its probes for the estimate. */
struct seen {
	long k;
	const char *path;
	double probe_sum;
	uint64_t probe_pixels;
};

static int by_part(const void *a, const void *b)
{
	const struct seen *x = a, *y = b;
	return (x->k > y->k) - (x->k < y->k);
}

/* Whether the parts in seen[0 .. n), sorted, are each of 0 .. parts - 1 once; else says
 * which is there twice or missing, and returns false. */
static bool cover_once(const struct seen *seen, int n, long parts, int height)
{
	for (int i = 1; i < n; i++)
		if (seen[i].k == seen[i - 1].k) {
			fprintf(stderr, "scn: error: '%s' and '%s' are both part %ld of %ld\n", seen[i - 1].path, seen[i].path,
			        seen[i].k, parts);
			return false;
		}
	for (long k = 0; k < parts; k++)
		if (k >= n || seen[k].k != k) {
			int y0, y1;
			tile_band(k, parts, 0, height, &y0, &y1);
			fprintf(stderr, "scn: error: part %ld of %ld (rows %d to %d) is missing\n", k, parts, y0, y1 - 1);
			return false;
		}
	return true;
}

/* The whole image that part p of the file at path is a part of, in *whole; its size is
 * the file's word, so that memory is checked first. Returns the exit status, after the
 * message. */
static int new_whole(const struct tile_part *p, const char *path, struct image **whole)
{
	char why[160];
	if (!memory_fits(image_bytes(p->width, p->height), why, sizeof why)) {
		fprintf(stderr, "scn: error: '%s': the %d x %d image %s\n", path, p->width, p->height, why);
		return EXIT_RENDER;
	}
	if (!(*whole = image_new(p->width, p->height))) {
		fprintf(stderr, "scn: error: '%s': a %d x %d image has more pixels than the limit of 2^28\n", path,
		        p->width, p->height);
		return EXIT_RENDER;
	}
	return 0;
}

/* Reads the parts into *whole, checking them as it goes, and the error estimate into
 * *rmse (-1: none). Returns the exit status, after the message. */
static int join(const struct merge_args *a, struct image **whole, double *rmse)
{
	struct seen *seen = xcalloc((size_t)a->nparts, sizeof *seen);
	struct tile_file first, f;
	bool probed = true;
	int rc = 0;
	for (int i = 0; i < a->nparts && rc == 0; i++) {
		char err[512];
		struct tile_file *part = i == 0 ? &first : &f;
		int e = tile_part_read(a->parts[i], part, err, sizeof err);
		if (e) {
			fprintf(stderr, "scn: error: %s\n", err);
			rc = cli_file_status(e);
			break;
		}
		if (i == 0)
			rc = new_whole(&first.p, a->parts[0], whole);
		else if (!same_render(&first, a->parts[0], &f, a->parts[i]))
			rc = EXIT_IO;
		if (rc == 0) {
			const struct tile_part *p = &part->p;
			int y0, y1;
			tile_band(p->t.k, p->t.n, 0, p->height, &y0, &y1);
			memcpy((*whole)->rgb + (size_t)y0 * p->width * 3, part->img->rgb,
			       (size_t)(y1 - y0) * p->width * 3 * sizeof *part->img->rgb);
			seen[i] = (struct seen){ p->t.k, a->parts[i], p->probe_sum, p->probe_pixels };
			probed = probed && p->probed;
		}
		if (i > 0)
			tile_file_free(&f);
	}
	if (rc == 0) {
		qsort(seen, (size_t)a->nparts, sizeof *seen, by_part);
		if (!cover_once(seen, a->nparts, first.p.t.n, first.p.height))
			rc = EXIT_IO;
	}
	/* summed in the parts' order, so that the estimate does not depend on the files' */
	double sum = 0;
	uint64_t pixels = 0;
	for (int i = 0; i < a->nparts && rc == 0; i++)
		sum += seen[i].probe_sum, pixels += seen[i].probe_pixels;
	*rmse = probed && pixels ? sqrt(sum / (6.0 * (double)pixels)) : -1;
	tile_file_free(&first);
	free(seen);
	return rc;
}

int cmd_merge(const struct command *self, int argc, char **argv)
{
	struct merge_args a;
	int rc = parse_args(self, argc, argv, &a);
	if (rc)
		return rc < 0 ? 0 : rc;
	/* the output file exists from the start, so that an unwritable place is found before
	 * the parts are read */
	char err[512];
	struct image_write_options wo = { .bit_depth = (int)a.bit_depth, .float32 = a.float32 };
	struct image_file file;
	if (image_file_create(&file, a.out, &wo, err, sizeof err) != 0) {
		fprintf(stderr, "scn: %s\n", err);
		return EXIT_IO;
	}
	struct image *whole = NULL;
	double rmse;
	rc = join(&a, &whole, &rmse);
	int e = image_file_commit(&file, rc == 0 ? whole : NULL, err, sizeof err);
	if (rc == 0 && e != 0) {
		fprintf(stderr, "scn: %s\n", err);
		rc = cli_file_status(e);
	}
	if (rc == 0 && !a.quiet) {
		fprintf(stderr, "scn: wrote %s: %d x %d from %d parts", a.out, whole->width, whole->height, a.nparts);
		if (rmse >= 0)
			fprintf(stderr, "; estimated RMSE %.3g", rmse);
		fputc('\n', stderr);
	}
	image_free(whole);
	return rc;
}
