/* probe.c: checks a rendered image (and the render's --stats) against NAME.expect:
 *   pixel X Y R G B TOL     linear RGB of pixel (X, Y) within TOL per channel
 *   mean R G B TOL          the image's mean colour within TOL
 *   rays KIND N             --stats counted exactly N of KIND: camera, shadow,
 *                           reflection, refraction rays, or nonfinite radiance values
 *   rays KIND < N           --stats counted fewer than N of KIND (or > N: more than N)
 * Usage: probe IMAGE STATS EXPECT. Prints every mismatch; exits 1 on any. */
#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "image.h"

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

int main(int argc, char **argv)
{
	if (argc != 4) {
		fprintf(stderr, "usage: probe IMAGE STATS EXPECT\n");
		return 99;
	}
	struct image *img;
	char err[512];
	if (image_read(argv[1], &img, err, sizeof err) != 0) {
		fprintf(stderr, "probe: %s\n", err);
		return 99;
	}
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
		char kind[32], op[2];
		double v[6];
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
			snprintf(what, sizeof what, "pixel %d %d", x, y);
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
		} else {
			printf("FAIL: line %d of %s: cannot read '%s'\n", lineno, argv[3], line);
			failures++;
		}
	}
	fclose(sf);
	fclose(ef);
	image_free(img);
	return failures ? 1 : 0;
}
