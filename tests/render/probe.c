/* probe.c: checks a rendered image (and the render's --stats) against NAME.expect:
 *   pixel X Y R G B TOL     linear RGB of pixel (X, Y) within TOL per channel
 *   mean R G B TOL          the image's mean colour within TOL
 *   rays KIND N             --stats counted exactly N of KIND: camera, shadow,
 *                           area_shadow, reflection, refraction rays, or nonfinite
 *                           radiance values
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
 *   uniform X0 Y0 X1 Y1 TOL every pixel of the rectangle is within TOL of the rectangle's
 *                           median colour (one answer over a face, whichever it is)
 *   camera LX LY LZ AX AY AZ UX UY UZ FOV W H G
 *                           the scene's camera (location, look_at, up, fov), its W x H
 *                           pixels and its grid pattern's G (G x G samples a pixel; 1: the
 *                           pixel centre), for the checks below; an image of G W x G H
 *                           (POV-Ray's twin of a grid render) is first made the mean of
 *                           each G x G block
 *   hit SHAPE NUMBERS R G B R' G' B' TOL
 *                           every pixel is within TOL of the mean over its samples of R G B
 *                           where the sample's ray meets SHAPE and R' G' B' where it does
 *                           not, decided exactly (probe_hit.c); a ray within a relative
 *                           1e-9 of tangency (PROBE_MARGIN) may count either way. SHAPE:
 *                             ellipsoid CX CY CZ AX AY AZ   centre, semi-axes
 *                             torus CX CY CZ MAJOR MINOR    about the y axis through C
 *                             disc CX CY CZ NX NY NZ RADIUS
 *                             box LX LY LZ HX HY HZ         (lo = hi on an axis: a rectangle)
 *   lambert ellipsoid CX CY CZ AX AY AZ KR KG KB LX LY LZ R' G' B' TOL
 *                           the same with K max(n.l, 0) where a sample meets the ellipsoid:
 *                           n its exact normal there, l the unit vector along L (towards a
 *                           distant light)
 * Text after a check's numbers is a label for people (tests/extreme/compare-pov shows it).
 * Usage: probe IMAGE STATS EXPECT [TWIN]. Prints every mismatch; exits 1 on any. */
#include <inttypes.h>
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "image_file.h"
#include "probe_hit.h"

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
		{ "camera", "  camera " }, { "shadow", "  shadow " }, { "area_shadow", "  area shadow " },
		{ "reflection", "  reflection " },
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

/* The numbers at the start of text, up to max of them: how many. */
static int numbers(const char *text, double *v, int max)
{
	int n = 0;
	while (n < max) {
		char *end;
		double x = strtod(text, &end);
		if (end == text)
			break;
		v[n++] = x;
		text = end;
	}
	return n;
}

/* uniform: the pixels of the rectangle r off its median colour by more than tol, printing
 * the first few. */
static long long count_not_uniform(const struct image *img, const double r[4], double tol)
{
	int x0 = r[0] < 0 ? 0 : (int)r[0], y0 = r[1] < 0 ? 0 : (int)r[1];
	int x1 = r[2] > img->width ? img->width : (int)r[2], y1 = r[3] > img->height ? img->height : (int)r[3];
	if (x1 <= x0 || y1 <= y0)
		return 0;
	size_t n = (size_t)(x1 - x0) * (size_t)(y1 - y0);
	float *c = malloc(n * sizeof *c);
	double median[3];
	for (int k = 0; k < 3; k++) {
		size_t i = 0;
		for (int y = y0; y < y1; y++)
			for (int x = x0; x < x1; x++)
				c[i++] = img->rgb[3 * ((size_t)y * (size_t)img->width + (size_t)x) + k];
		/* the median by selection: sort is enough at the sizes of these tests */
		for (size_t a = 1; a < n; a++)
			for (size_t b = a; b > 0 && c[b - 1] > c[b]; b--) {
				float t = c[b];
				c[b] = c[b - 1];
				c[b - 1] = t;
			}
		median[k] = c[n / 2];
	}
	free(c);
	long long off = 0;
	for (int y = y0; y < y1; y++)
		for (int x = x0; x < x1; x++) {
			const float *p = &img->rgb[3 * ((size_t)y * (size_t)img->width + (size_t)x)];
			if (near(p, median, tol))
				continue;
			if (off++ < 5)
				printf("  pixel %d %d = %.6f %.6f %.6f, median %.6f %.6f %.6f\n", x, y, p[0], p[1], p[2], median[0],
				       median[1], median[2]);
		}
	return off;
}

/* camera: an image of grid times the camera's size becomes the mean of each grid x grid
 * block (POV-Ray's twin of a grid render is rendered so: scn pov). */
static bool fit_camera(struct image **img, const struct probe_camera *c)
{
	int g = c->grid;
	if ((*img)->width == c->width && (*img)->height == c->height)
		return true;
	if (g < 2 || (*img)->width != g * c->width || (*img)->height != g * c->height)
		return false;
	struct image *small = image_new(c->width, c->height);
	for (int y = 0; y < c->height; y++)
		for (int x = 0; x < c->width; x++)
			for (int k = 0; k < 3; k++) {
				double sum = 0;
				for (int b = 0; b < g; b++)
					for (int a = 0; a < g; a++)
						sum += (*img)->rgb[3 * ((size_t)(g * y + b) * (size_t)(*img)->width + (size_t)(g * x + a)) + k];
				small->rgb[3 * ((size_t)y * (size_t)c->width + (size_t)x) + k] = (float)(sum / (g * g));
			}
	image_free(*img);
	*img = small;
	return true;
}

/* hit and lambert: the pixels off the analytic value by more than tol (the range a
 * pixel's undecided samples allow widened by tol), printing the first few; and a summary
 * of the mask. kd non-NULL: lambert, the shape an ellipsoid. */
static long long count_off_shape(const struct image *img, const struct probe_camera *c, const struct probe_shape *s,
                                 const double in[3], const double *kd, const double light[3], const double out[3],
                                 double tol, int lineno)
{
	real l[3] = { 0, 0, 0 };
	if (kd) {
		real n = sqrt((real)light[0] * light[0] + (real)light[1] * light[1] + (real)light[2] * light[2]);
		for (int k = 0; k < 3; k++)
			l[k] = light[k] / n;
	}
	int g = c->grid;
	long long off = 0, full = 0, part = 0, edges = 0;
	for (int py = 0; py < img->height; py++)
		for (int px = 0; px < img->width; px++) {
			double lo[3] = { 0, 0, 0 }, hi[3] = { 0, 0, 0 };
			int hits = 0, edge = 0;
			for (int b = 0; b < g; b++)
				for (int a = 0; a < g; a++) {
					real d[3];
					probe_camera_ray(c, px, py, a, b, d);
					enum probe_side side = probe_shape_side(s, c->eye, d);
					double v[3] = { 0, 0, 0 };
					if (in)
						v[0] = in[0], v[1] = in[1], v[2] = in[2];
					if (side != PROBE_OUT && kd) {
						real n[3];
						/* an undecided ray meets the grown shape */
						if (!probe_ellipsoid_normal(s, c->eye, d, side == PROBE_IN ? 1 : 1 + PROBE_MARGIN, n))
							n[0] = n[1] = n[2] = 0;
						real nl = n[0] * l[0] + n[1] * l[1] + n[2] * l[2];
						for (int k = 0; k < 3; k++)
							v[k] = kd[k] * (double)(nl > 0 ? nl : 0);
					}
					for (int k = 0; k < 3; k++) {
						double x = side == PROBE_OUT ? out[k] : v[k];
						double y = side == PROBE_EDGE ? out[k] : x;
						lo[k] += x < y ? x : y;
						hi[k] += x < y ? y : x;
					}
					hits += side == PROBE_IN;
					edge += side == PROBE_EDGE;
				}
			edges += edge;
			full += hits == g * g;
			part += hits + edge > 0 && hits < g * g;
			const float *p = &img->rgb[3 * ((size_t)py * (size_t)img->width + (size_t)px)];
			bool ok = true;
			for (int k = 0; k < 3; k++)
				ok &= p[k] >= lo[k] / (g * g) - tol && p[k] <= hi[k] / (g * g) + tol;
			if (ok)
				continue;
			if (off++ < 5)
				printf("  pixel %d %d = %.6f %.6f %.6f, expected %.6f %.6f %.6f (%d of %d samples meet it, %d on "
				       "the edge)\n", px, py, p[0], p[1], p[2], lo[0] / (g * g), lo[1] / (g * g), lo[2] / (g * g),
				       hits, g * g, edge);
		}
	printf("line %d: the analytic mask: %lld pixels wholly on the shape, %lld partly, %lld samples undecided\n",
	       lineno, full, part, edges);
	return off;
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
	struct probe_camera cam;
	bool have_cam = false;
	while (fgets(line, sizeof line, ef)) {
		lineno++;
		char kind[32], op[2], op2[32], file[256];
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
		} else if (sscanf(line, "uniform %lf %lf %lf %lf %lf", &v[0], &v[1], &v[2], &v[3], &v[4]) == 5) {
			long long got = count_not_uniform(img, v, v[4]);
			if (got != 0) {
				printf("FAIL: line %d: %lld pixels differ from the median of %g %g %g %g by more than %g\n", lineno,
				       got, v[0], v[1], v[2], v[3], v[4]);
				failures++;
			}
		} else if (sscanf(line, "camera %lf", &v[0]) == 1) {
			double c[13];
			if (numbers(line + strlen("camera"), c, 13) != 13 || c[10] < 1 || c[11] < 1 || c[12] < 1) {
				printf("FAIL: line %d of %s: cannot read '%s'\n", lineno, argv[3], line);
				failures++;
				continue;
			}
			probe_camera_setup(&cam, &c[0], &c[3], &c[6], c[9], (int)c[10], (int)c[11], (int)c[12]);
			have_cam = true;
			if (!fit_camera(&img, &cam)) {
				printf("FAIL: line %d: the image is %dx%d, not %dx%d (or %d times that)\n", lineno, img->width,
				       img->height, cam.width, cam.height, cam.grid);
				failures++;
				have_cam = false;
			}
		} else if (sscanf(line, "%31s %31s", kind, op2) == 2 && (strcmp(kind, "hit") == 0 || strcmp(kind, "lambert") == 0)) {
			static const struct { const char *name; enum probe_shape_kind kind; int n; } shapes[] = {
				{ "ellipsoid", PROBE_ELLIPSOID, 6 }, { "torus", PROBE_TORUS, 5 },
				{ "disc", PROBE_DISC, 7 }, { "box", PROBE_BOX, 6 },
			};
			bool lambert = kind[0] == 'l';
			int which = -1;
			for (int i = 0; i < 4; i++)
				if (strcmp(op2, shapes[i].name) == 0)
					which = i;
			double a[32];
			int want = which < 0 ? -1 : shapes[which].n + (lambert ? 10 : 7);
			const char *rest = strstr(line, op2) + strlen(op2);
			if (which < 0 || (lambert && which != 0) || numbers(rest, a, want) != want || !have_cam) {
				printf("FAIL: line %d of %s: cannot read '%s'%s\n", lineno, argv[3], line,
				       have_cam ? "" : " (no camera line before it)");
				failures++;
				continue;
			}
			struct probe_shape sh = { .kind = shapes[which].kind };
			for (int k = 0; k < 3; k++) {
				sh.c[k] = a[k];
				sh.a[k] = sh.n[k] = a[3 + k];
				sh.lo[k] = a[k];
				sh.hi[k] = a[3 + k];
			}
			sh.major = a[3];
			sh.minor = a[4];
			sh.radius = a[6];
			const double *colours = &a[shapes[which].n];
			long long got = lambert ? count_off_shape(img, &cam, &sh, NULL, colours, colours + 3, colours + 6,
			                                          colours[9], lineno)
			                        : count_off_shape(img, &cam, &sh, colours, NULL, NULL, colours + 3, colours[6],
			                                          lineno);
			if (got != 0) {
				printf("FAIL: line %d: %lld pixels differ from the analytic %s by more than %g\n", lineno, got, op2,
				       lambert ? colours[9] : colours[6]);
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
