/* cmd_diff.c: scn diff: reads two images, compares them in linear light, prints the
 * metrics one per line, writes a heatmap, and fails when a metric is over a limit. */
#include "config.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "image_file.h"
#include "imgdiff.h"

/* The comparison failed: a limit is exceeded or the sizes differ (as `cmp` and `diff`
 * exit 1 when their inputs differ). The same number as EXIT_SCENE, another meaning. */
enum { EXIT_DIFFER = 1 };

/* A limit is off (not checked) while negative. */
struct diff_args {
	const char *path[2];               /* A, B */
	const char *heatmap;
	long downsample;                   /* of B; 1: none */
	bool ppm_linear[2];                /* how A's and B's PPM samples are encoded */
	double max_rmse, min_psnr, max_error, max_mean, max_off;   /* max_off in percent */
	bool quiet;
};

/* A non-negative finite number spelt exactly by s, as a decimal or a fraction P/Q
 * ("2/65535"); with percent, a trailing '%' is allowed. */
static bool parse_number(const char *s, bool percent, double *out)
{
	char *end;
	double v = strtod(s, &end);
	if (end == s)
		return false;
	if (*end == '/') {
		const char *q = end + 1;
		double d = strtod(q, &end);
		if (end == q || !(d > 0))
			return false;
		v /= d;
	}
	if (percent && *end == '%')
		end++;
	if (*end || !isfinite(v) || !(v >= 0))
		return false;
	*out = v;
	return true;
}

/* --ppm ENC or ENC,ENC with ENC srgb or linear: both inputs, or A's then B's. */
static bool parse_ppm(const char *s, bool linear[2])
{
	static const char *const names[] = { "srgb", "linear" };
	const char *comma = strchr(s, ',');
	for (int k = 0; k < 2; k++) {
		const char *start = k == 0 || !comma ? s : comma + 1;
		size_t len = k == 0 && comma ? (size_t)(comma - s) : strlen(start);
		int found = -1;
		for (int e = 0; e < 2; e++)
			if (strlen(names[e]) == len && strncmp(start, names[e], len) == 0)
				found = e;
		if (found < 0)
			return false;
		linear[k] = found == 1;
	}
	return true;
}

enum {
	OPT_HEATMAP, OPT_DOWNSAMPLE, OPT_PPM, OPT_MAX_RMSE, OPT_MIN_PSNR, OPT_MAX_ERROR, OPT_MAX_MEAN, OPT_MAX_OFF,
	OPT_QUIET, NOPTIONS
};
static const struct cli_option options[NOPTIONS] = {
	[OPT_HEATMAP] = { "heatmap", 0, true },
	[OPT_DOWNSAMPLE] = { "downsample", 0, true },
	[OPT_PPM] = { "ppm", 0, true },
	[OPT_MAX_RMSE] = { "max-rmse", 0, true },
	[OPT_MIN_PSNR] = { "min-psnr", 0, true },
	[OPT_MAX_ERROR] = { "max-error", 0, true },
	[OPT_MAX_MEAN] = { "max-mean", 0, true },
	[OPT_MAX_OFF] = { "max-off", 0, true },
	[OPT_QUIET] = { "quiet", 'q', false },
};

/* Reads the command line into *a: 0, or -1 once the help is shown, or EXIT_USAGE after a
 * usage message. */
static int parse_args(const struct command *self, int argc, char **argv, struct diff_args *a)
{
	*a = (struct diff_args){ .downsample = 1, .max_rmse = -1, .min_psnr = -1, .max_error = -1,
	                         .max_mean = -1, .max_off = -1 };
	struct cli_parser p;
	cli_parser_init(&p, self, options, NOPTIONS, argc, argv);
	int o;
	while ((o = cli_next_option(&p)) >= 0) {
		const char *v = p.value;
		double *limit = NULL;
		switch (o) {
		case OPT_QUIET: a->quiet = true; continue;
		case OPT_MAX_RMSE: limit = &a->max_rmse; break;
		case OPT_MIN_PSNR: limit = &a->min_psnr; break;
		case OPT_MAX_ERROR: limit = &a->max_error; break;
		case OPT_MAX_MEAN: limit = &a->max_mean; break;
		case OPT_MAX_OFF: limit = &a->max_off; break;
		case OPT_HEATMAP:
			if (image_format_of(v) < 0)
				return cli_usage_error(self, "unknown image format for --heatmap '%s' (use .png, .exr or .ppm)", v);
			a->heatmap = v;
			continue;
		case OPT_DOWNSAMPLE:
			if (!cli_int(v, 1, 65536, &a->downsample))
				return cli_usage_error(self, "bad value '%s' for --downsample (a whole number from 1 to 65536)", v);
			continue;
		default: /* OPT_PPM */
			if (!parse_ppm(v, a->ppm_linear))
				return cli_usage_error(self, "bad value '%s' for --ppm (srgb, linear, or two of them: A's,B's)", v);
			continue;
		}
		bool percent = limit == &a->max_off;
		if (!parse_number(v, percent, limit) || (percent && *limit > 100))
			return cli_usage_error(self, "bad value '%s' for %s (%s)", v, p.name,
			                       percent ? "a percentage from 0 to 100" : "a number >= 0, such as 0.001 or 2/65535");
	}
	if (o == CLI_STOP)
		return p.status;
	int n;
	char **paths = cli_operands(&p, &n);
	if (!paths)
		return EXIT_USAGE;
	if (n > 2)
		return cli_usage_error(self, "more than two images given ('%s')", paths[2]);
	if (n < 2)
		return cli_usage_error(self, n ? "only one image given; diff compares two" : "no images given");
	a->path[0] = paths[0];
	a->path[1] = paths[1];
	return 0;
}

/* Prints "off>K/255 P% (N pixels)". */
static void print_off(int k, int64_t n, int64_t pixels)
{
	printf("off>%d/255 %.4g%% (%lld pixel%s)\n", k, 100.0 * (double)n / (double)pixels, (long long)n,
	       n == 1 ? "" : "s");
}

static void print_stats(const struct imgdiff_stats *s, const struct image *b_full, long downsample)
{
	printf("size %dx%d", s->width, s->height);
	if (downsample > 1)
		printf(" (B %dx%d averaged over %ldx%ld blocks)", b_full->width, b_full->height, downsample,
		       downsample);
	printf("\nrmse %.6g (psnr %.2f dB)\n", s->rmse, s->psnr);
	printf("mean %.6g\n", s->mean);
	printf("bias %.6g\n", s->bias);
	printf("max %.6g", s->max);
	if (s->max > 0)
		printf(" at (%d, %d)", s->max_x, s->max_y);
	printf("\n");
	print_off(1, s->off1, s->pixels);
	print_off(2, s->off2, s->pixels);
}

/* Reports each limit that s exceeds on standard error; returns how many. A limit is
 * exceeded when the metric is above it (below it, for PSNR): equal passes. */
static int check_limits(const struct diff_args *a, const struct imgdiff_stats *s)
{
	int over = 0;
	double off = 100.0 * (double)s->off2 / (double)s->pixels;
	if (a->max_rmse >= 0 && !(s->rmse <= a->max_rmse))
		over++, fprintf(stderr, "scn: rmse %.6g is above --max-rmse %.6g\n", s->rmse, a->max_rmse);
	if (a->min_psnr >= 0 && !(s->psnr >= a->min_psnr))
		over++, fprintf(stderr, "scn: psnr %.2f dB is below --min-psnr %.6g\n", s->psnr, a->min_psnr);
	if (a->max_error >= 0 && !(s->max <= a->max_error))
		over++, fprintf(stderr, "scn: max %.6g at (%d, %d) is above --max-error %.6g\n", s->max, s->max_x,
		                s->max_y, a->max_error);
	if (a->max_mean >= 0 && !(s->mean <= a->max_mean))
		over++, fprintf(stderr, "scn: mean %.6g is above --max-mean %.6g\n", s->mean, a->max_mean);
	if (a->max_off >= 0 && !(off <= a->max_off))
		over++, fprintf(stderr, "scn: %.4g%% of pixels off by more than 2/255 is above --max-off %.6g%%\n",
		                off, a->max_off);
	return over;
}

int cmd_diff(const struct command *self, int argc, char **argv)
{
	struct diff_args a;
	int rc = parse_args(self, argc, argv, &a);
	if (rc != 0)
		return rc < 0 ? 0 : rc;

	struct image *img[2] = { NULL, NULL }, *small = NULL, *heat = NULL;
	char err[512];
	/* before the images are read, so that an unwritable heatmap is found first */
	struct image_file heat_file;
	if (a.heatmap && image_file_create(&heat_file, a.heatmap, NULL, err, sizeof err) != 0) {
		fprintf(stderr, "scn: %s\n", err);
		return EXIT_IO;
	}
	bool heat_open = a.heatmap != NULL;
	for (int k = 0; k < 2; k++) {
		struct image_read_options ro = { .ppm_linear = a.ppm_linear[k] };
		int e = image_read_with(a.path[k], &ro, &img[k], err, sizeof err);
		if (e != 0) {
			fprintf(stderr, "scn: %s\n", err);
			rc = cli_file_status(e);
			goto done;
		}
	}
	const struct image *b = img[1];
	if (a.downsample > 1) {
		if (!(small = imgdiff_downsample(img[1], (int)a.downsample))) {
			fprintf(stderr, "scn: cannot compare: B '%s' is %dx%d, not a multiple of --downsample %ld\n",
			        a.path[1], img[1]->width, img[1]->height, a.downsample);
			rc = EXIT_DIFFER;
			goto done;
		}
		b = small;
	}
	struct imgdiff_stats s;
	if (!imgdiff_compare(img[0], b, &s)) {
		fprintf(stderr, "scn: cannot compare: A '%s' is %dx%d but B '%s' is %dx%d", a.path[0],
		        img[0]->width, img[0]->height, a.path[1], b->width, b->height);
		if (a.downsample > 1)
			fprintf(stderr, " after --downsample %ld", a.downsample);
		fprintf(stderr, "\n");
		rc = EXIT_DIFFER;
		goto done;
	}
	if (!a.quiet)
		print_stats(&s, img[1], a.downsample);
	if (fflush(stdout) != 0) {
		perror("scn: standard output");
		rc = EXIT_IO;
		goto done;
	}
	if (a.heatmap) {
		heat = imgdiff_heatmap(img[0], b);
		heat_open = false;
		int e = image_file_commit(&heat_file, heat, err, sizeof err);
		if (e != 0) {
			fprintf(stderr, "scn: %s\n", err);
			rc = cli_file_status(e);
			goto done;
		}
	}
	rc = check_limits(&a, &s) > 0 ? EXIT_DIFFER : 0;
done:
	if (heat_open)
		image_file_commit(&heat_file, NULL, err, sizeof err);
	image_free(heat);
	image_free(small);
	image_free(img[0]);
	image_free(img[1]);
	return rc;
}
