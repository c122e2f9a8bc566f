/* probe.c: checks a rendered image (and the render's --stats) against NAME.expect:
 *   pixel X Y R G B TOL     linear RGB of pixel (X, Y) within TOL per channel
 *   mean R G B TOL          the image's mean colour within TOL
 *   rays KIND N             --stats counted exactly N of KIND: camera, shadow,
 *                           reflection, refraction rays, or nonfinite radiance values
 *   rays KIND < N           --stats counted fewer than N of KIND (or > N: more than N)
 *   count X0 Y0 X1 Y1 R G B TOL N
 *                           exactly N pixels of the rectangle [X0, X1) x [Y0, Y1) are
 *                           within TOL of R G B in every channel (an analytic mask);
 *                           `< N` or `> N` for fewer or more than N
 *   twin FILE.scn TOL N     the image has the size of TWIN (the render of FILE.scn,
 *                           made by the caller) and at most N of its pixels differ from
 *                           TWIN's by more than TOL in some channel
 *   darker FILE.scn X0 Y0 X1 Y1 LEVEL RATIO N
 *                           of the pixels of the rectangle where TWIN exceeds LEVEL in
 *                           every channel, at most N are below RATIO times TWIN's value
 *                           in some channel
 * Text after a check's numbers is a label for people (tests/extreme/compare-pov shows it).
 * Usage: probe IMAGE STATS EXPECT [TWIN]. Prints every mismatch; exits 1 on any. */
#include <inttypes.h>
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "image_file.h"

static int failures;

static void pixel_check(const struct image *img, const char *what, const double got[3], const double want[3],
                        double tol)
{
	for (int k = 0; k < 3; k++)
		if (!(fabs(got[k] - want[k]) <= tol)) {
			printf("FAIL: %s = %.6f %.6f %.6f, expected %.6f %.6f %.6f within %g\n", what, got[0], got[1],
			       got[2], want[0], want[1], want[2], tol);
			failures++;
			return;
		}
	(void)img;
}

/* The count of KIND in the --stats output, or -1: each kind is found by the label
 * scn render --stats prints before it. */
static long long stat_of(const char *stats, const char *kind)
{
	static const char *const labels[][2] = {
		{ "camera", "  camera " }, { "shadow", "  shadow " }, { "reflection", "  reflection " },
		{ "refraction", "  refraction " }, { "nonfinite", "non-finite radiance values: " },
	};
	for (size_t i = 0; i < sizeof labels / sizeof labels[0]; i++)
		if (strcmp(kind, labels[i][0]) == 0) {
			const char *p = strstr(stats, labels[i][1]);
			return p ? strtoll(p + strlen(labels[i][1]), NULL, 10) : -1;
		}
	return -1;
}

static bool near(const float *p, const double want[3], double tol)
{
	for (int k = 0; k < 3; k++)
		if (!(fabs(p[k] - want[k]) <= tol))
			return false;
	return true;
}

/* The pixels of the rectangle [x0, x1) x [y0, y1), clipped to the image, within tol of rgb. */
static long long count_near(const struct image *img, const double r[4], const double rgb[3], double tol)
{
	long long n = 0;
	for (int y = r[1] < 0 ? 0 : (int)r[1]; y < img->height && y < r[3]; y++)
		for (int x = r[0] < 0 ? 0 : (int)r[0]; x < img->width && x < r[2]; x++)
			n += near(&img->rgb[3 * ((size_t)y * (size_t)img->width + (size_t)x)], rgb, tol);
	return n;
}

/* The pixels of a that differ from b's by more than tol in some channel, printing the
 * first few; -1 when the sizes differ. */
static long long count_off(const struct image *a, const struct image *b, double tol)
{
	if (a->width != b->width || a->height != b->height)
		return -1;
	long long n = 0;
	for (size_t i = 0; i < (size_t)a->width * (size_t)a->height; i++) {
		double want[3] = { b->rgb[3 * i], b->rgb[3 * i + 1], b->rgb[3 * i + 2] };
		if (near(&a->rgb[3 * i], want, tol))
			continue;
		if (n++ < 5)
			printf("  pixel %zu %zu = %.6f %.6f %.6f, twin %.6f %.6f %.6f\n", i % (size_t)a->width,
			       i / (size_t)a->width, a->rgb[3 * i], a->rgb[3 * i + 1], a->rgb[3 * i + 2], want[0], want[1],
			       want[2]);
	}
	return n;
}

/* The pixels of a in the rectangle [x0, x1) x [y0, y1) of r below ratio times b's in some
 * channel, of those where b exceeds level in every channel, printing the first few; -1
 * when the sizes differ. */
static long long count_darker(const struct image *a, const struct image *b, const double r[4], double level,
                              double ratio)
{
	if (a->width != b->width || a->height != b->height)
		return -1;
	long long n = 0;
	for (int y = r[1] < 0 ? 0 : (int)r[1]; y < a->height && y < r[3]; y++)
		for (int x = r[0] < 0 ? 0 : (int)r[0]; x < a->width && x < r[2]; x++) {
			size_t i = (size_t)y * (size_t)a->width + (size_t)x;
			const float *p = &a->rgb[3 * i], *q = &b->rgb[3 * i];
			if (!(q[0] > level && q[1] > level && q[2] > level))
				continue;
			if (p[0] >= ratio * q[0] && p[1] >= ratio * q[1] && p[2] >= ratio * q[2])
				continue;
			if (n++ < 5)
				printf("  pixel %d %d = %.6f %.6f %.6f, twin %.6f %.6f %.6f\n", x, y, p[0], p[1], p[2], q[0],
				       q[1], q[2]);
		}
	return n;
}

static struct image *read_or_die(const char *path)
{
	struct image *img;
	char err[512];
	if (image_read(path, &img, err, sizeof err) != 0) {
		fprintf(stderr, "probe: %s\n", err);
		exit(99);
	}
	return img;
}

int main(int argc, char **argv)
{
	if (argc != 4 && argc != 5) {
		fprintf(stderr, "usage: probe IMAGE STATS EXPECT [TWIN]\n");
		return 99;
	}
	struct image *img = read_or_die(argv[1]);
	struct image *twin = argc == 5 ? read_or_die(argv[4]) : NULL;
	FILE *sf = fopen(argv[2], "r"), *ef = fopen(argv[3], "r");
	if (!sf || !ef) {
		fprintf(stderr, "probe: cannot open %s\n", sf ? argv[3] : argv[2]);
		return 99;
	}
	static char stats[1 << 16];
	stats[fread(stats, 1, sizeof stats - 1, sf)] = '\0';
	char line[512];
	int lineno = 0;
	while (fgets(line, sizeof line, ef)) {
		lineno++;
		char kind[32], op[2], file[256];
		double v[10];
		long long n;
		if (line[0] == '#' || line[0] == '\n')
			continue;
		if (sscanf(line, "pixel %lf %lf %lf %lf %lf %lf", &v[0], &v[1], &v[2], &v[3], &v[4], &v[5]) == 6) {
			int x = (int)v[0], y = (int)v[1];
			if (x < 0 || y < 0 || x >= img->width || y >= img->height) {
				printf("FAIL: line %d: pixel %d %d is outside the %dx%d image\n", lineno, x, y, img->width,
				       img->height);
				failures++;
				continue;
			}
			const float *p = &img->rgb[3 * ((size_t)y * (size_t)img->width + (size_t)x)];
			double got[3] = { p[0], p[1], p[2] };
			char what[64];
			snprintf(what, sizeof what, "line %d: pixel %d %d", lineno, x, y);
			pixel_check(img, what, got, &v[2], v[5]);
		} else if (sscanf(line, "mean %lf %lf %lf %lf", &v[0], &v[1], &v[2], &v[3]) == 4) {
			double sum[3] = { 0, 0, 0 };
			size_t np = (size_t)img->width * (size_t)img->height;
			for (size_t i = 0; i < np; i++)
				for (int k = 0; k < 3; k++)
					sum[k] += img->rgb[3 * i + k];
			for (int k = 0; k < 3; k++)
				sum[k] /= (double)np;
			pixel_check(img, "mean", sum, v, v[3]);
		} else if (sscanf(line, "rays %31s %lld", kind, &n) == 2) {
			long long got = stat_of(stats, kind);
			if (got != n) {
				printf("FAIL: %s rays: %lld, expected %lld\n", kind, got, n);
				failures++;
			}
		} else if (sscanf(line, "rays %31s %1[<>] %lld", kind, op, &n) == 3) {
			long long got = stat_of(stats, kind);
			if (got < 0 || (op[0] == '<' ? !(got < n) : !(got > n))) {
				printf("FAIL: %s rays: %lld, expected %s %lld\n", kind, got, op, n);
				failures++;
			}
		} else if (sscanf(line, "count %lf %lf %lf %lf %lf %lf %lf %lf %1[<>] %lld", &v[0], &v[1], &v[2], &v[3],
		                  &v[4], &v[5], &v[6], &v[7], op, &n) == 10 ||
		           (op[0] = '=', sscanf(line, "count %lf %lf %lf %lf %lf %lf %lf %lf %lld", &v[0], &v[1], &v[2],
		                                &v[3], &v[4], &v[5], &v[6], &v[7], &n) == 9)) {
			long long got = count_near(img, v, &v[4], v[7]);
			if (op[0] == '<' ? !(got < n) : op[0] == '>' ? !(got > n) : got != n) {
				printf("FAIL: line %d: %lld pixels of %g %g %g %g are %g %g %g within %g, expected %s%lld\n",
				       lineno, got, v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], op[0] == '=' ? "" : op, n);
				failures++;
			}
		} else if (sscanf(line, "twin %255s %lf %lld", file, &v[0], &n) == 3) {
			long long got = twin ? count_off(img, twin, v[0]) : -1;
			if (got < 0 || got > n) {
				printf("FAIL: line %d: %lld pixels differ from %s's by more than %g, expected at most %lld\n",
				       lineno, got, file, v[0], n);
				failures++;
			}
		} else if (sscanf(line, "darker %255s %lf %lf %lf %lf %lf %lf %lld", file, &v[0], &v[1], &v[2], &v[3], &v[4],
		                  &v[5], &n) == 8) {
			long long got = twin ? count_darker(img, twin, v, v[4], v[5]) : -1;
			if (got < 0 || got > n) {
				printf("FAIL: line %d: %lld pixels of %g %g %g %g where %s's exceed %g are below %g of it, "
				       "expected at most %lld\n", lineno, got, v[0], v[1], v[2], v[3], file, v[4], v[5], n);
				failures++;
			}
		} else {
			printf("FAIL: line %d of %s: cannot read '%s'\n", lineno, argv[3], line);
			failures++;
		}
	}
	fclose(sf);
	fclose(ef);
	image_free(img);
	if (twin)
		image_free(twin);
	return failures ? 1 : 0;
}
