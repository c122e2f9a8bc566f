/* test_image.c: the image layer: film limits, the sRGB curve, PNG/EXR/PPM round trips
 * within their quantisation, foreign PNG and EXR layouts, corrupt files, atomic writes. */
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <ftw.h>
#include <limits.h>
#include <math.h>
#include <openexr.h>
#include <png.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include "check.h"
#include "image_file.h"

static char tmpdir[PATH_MAX];

/* tmpdir/name in one of a few rotating buffers, so that two can be used at once */
static const char *tpath(const char *name)
{
	static char buf[4][PATH_MAX + 64];
	static int next;
	char *p = buf[next++ % 4];
	snprintf(p, sizeof buf[0], "%s/%s", tmpdir, name);
	return p;
}

/* The whole file in a malloc'd buffer, its size in *n; NULL if it cannot be read. */
static unsigned char *slurp(const char *path, size_t *n)
{
	FILE *f = fopen(path, "rb");
	if (!f)
		return NULL;
	unsigned char *data = NULL;
	size_t cap = 0, len = 0;
	for (;;) {
		if (len == cap) {
			cap = cap ? 2 * cap : 4096;
			data = realloc(data, cap);
		}
		size_t k = fread(data + len, 1, cap - len, f);
		if (k == 0)
			break;
		len += k;
	}
	fclose(f);
	*n = len;
	return data;
}

static void spit(const char *path, const void *data, size_t n)
{
	FILE *f = fopen(path, "wb");
	CHECK(f != NULL);
	if (!f)
		return;
	CHECK(fwrite(data, 1, n, f) == n);
	fclose(f);
}

static bool same_file(const char *a, const char *b)
{
	size_t na, nb;
	unsigned char *da = slurp(a, &na), *db = slurp(b, &nb);
	bool same = da && db && na == nb && memcmp(da, db, na) == 0;
	free(da);
	free(db);
	return same;
}

/* Entries in tmpdir (to see that no temporary file is left behind). */
static int count_entries(void)
{
	int n = 0;
	DIR *d = opendir(tmpdir);
	CHECK(d != NULL);
	for (struct dirent *e; d && (e = readdir(d)) != NULL;)
		n += strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0;
	if (d)
		closedir(d);
	return n;
}

static int remove_one(const char *path, const struct stat *st, int flag, struct FTW *ftw)
{
	(void)st;
	(void)flag;
	(void)ftw;
	return remove(path);
}

/* Deterministic values in [0, 1) (an LCG), so that failures repeat. */
static float noise(unsigned *state)
{
	*state = *state * 1664525u + 1013904223u;
	return (float)((*state >> 8) / 16777216.0);
}

static struct image *test_image(int w, int h, unsigned seed)
{
	struct image *img = image_new(w, h);
	for (size_t i = 0; i < (size_t)w * h * 3; i++)
		img->rgb[i] = noise(&seed);
	/* the ends and the knee of the sRGB curve */
	img->rgb[0] = 0;
	img->rgb[1] = 1;
	img->rgb[2] = 0.0031308f;
	return img;
}

static void test_new(void)
{
	struct image *img = image_new(5, 3);
	CHECK(img && img->width == 5 && img->height == 3);
	bool zero = true;
	for (int i = 0; img && i < 5 * 3 * 3; i++)
		zero = zero && img->rgb[i] == 0;
	CHECK(zero);
	image_free(img);
	image_free(NULL);
	CHECK(image_new(0, 1) == NULL);
	CHECK(image_new(1, 0) == NULL);
	CHECK(image_new(-1, 5) == NULL);
	CHECK(image_new(1 << 15, 1 << 14) == NULL);          /* 2^29 pixels */
	CHECK(image_new((1 << 28) + 1, 1) == NULL);
	CHECK(image_new(INT_MAX, INT_MAX) == NULL);
	CHECK(image_new(INT_MAX, 1) == NULL);
}

static void test_format_of(void)
{
	CHECK(image_format_of("a.png") == IMAGE_PNG);
	CHECK(image_format_of("out/A.PNG") == IMAGE_PNG);
	CHECK(image_format_of("x.Exr") == IMAGE_EXR);
	CHECK(image_format_of("../x.y.ppm") == IMAGE_PPM);
	CHECK(image_format_of("x.tga") == -1);
	CHECK(image_format_of("x.pngx") == -1);
	CHECK(image_format_of("x.pn") == -1);
	CHECK(image_format_of("noext") == -1);
	CHECK(image_format_of(".png") == -1);
	CHECK(image_format_of("dir.png/x") == -1);
	CHECK(image_format_of("x.") == -1);
}

static void test_srgb(void)
{
	CHECK(image_srgb_encode(0) == 0);
	CHECK_NEAR(image_srgb_encode(1), 1, 1e-15);
	CHECK_NEAR(image_srgb_decode(1), 1, 1e-15);
	CHECK_NEAR(image_srgb_encode(0.5), 0.7353569830524495, 1e-15);
	CHECK_NEAR(image_srgb_decode(0.5), 0.21404114048223255, 1e-15);
	CHECK_NEAR(image_srgb_encode(0.2), 0.48452920448170694, 1e-15);   /* POV-Ray: 0.4845 */
	CHECK_NEAR(image_srgb_encode(0.001), 0.01292, 1e-15);            /* the linear toe */
	CHECK_NEAR(image_srgb_decode(0.04045), 0.04045 / 12.92, 1e-15);
	CHECK_NEAR(image_srgb_decode(128 / 255.0), 0.21586050011389926, 1e-15);
	for (double x = 0; x <= 1; x += 1 / 64.0)
		CHECK_NEAR(image_srgb_decode(image_srgb_encode(x)), x, 1e-14);

	/* samples: the curve and floor(clamp(c) * M + 0.5) */
	CHECK(image_srgb_sample(0.2f, 255) == 124);                   /* 0.4845 * 255 = 123.6 */
	CHECK(image_srgb_sample(0.5f, 255) == 188);                   /* 187.52 */
	CHECK(image_srgb_sample(0.5f, 65535) == 48192);               /* 48191.6 */
	CHECK(image_srgb_sample(0, 255) == 0);
	CHECK(image_srgb_sample(1, 255) == 255);
	CHECK(image_srgb_sample(1, 65535) == 65535);
	CHECK(image_srgb_sample(2, 65535) == 65535);
	CHECK(image_srgb_sample(-0.1f, 255) == 0);
	CHECK(image_srgb_sample(NAN, 255) == 0);
	CHECK(image_srgb_sample(INFINITY, 255) == 255);
	CHECK(image_srgb_sample(-INFINITY, 65535) == 0);
	CHECK(image_srgb_sample(0.4f / 255 / 12.92f, 255) == 0);    /* the toe: 0.4 of a step */
	CHECK(image_srgb_sample(0.6f / 255 / 12.92f, 255) == 1);
	/* single precision, as POV-Ray: never more than one step from the exact value */
	int off = 0;
	for (int i = 0; i <= 1 << 16; i++) {
		float c = (float)i / (1 << 16);
		double exact = image_srgb_encode(c) * 65535 + 0.5;
		unsigned q = image_srgb_sample(c, 65535);
		CHECK(q == (unsigned)exact || q + 1 == (unsigned)exact || q == (unsigned)exact + 1);
		off += q != (unsigned)exact;
	}
	CHECK(off < 1000);
}

/* Writes img to name, reads it back; NULL (with a failed check) on any error. */
static struct image *round_trip(const struct image *img, const char *name, int depth, bool f32)
{
	char err[512] = "";
	struct image_write_options opt = { .bit_depth = depth, .float32 = f32 };
	int rc = image_write(img, tpath(name), &opt, err, sizeof err);
	CHECK(rc == 0);
	if (rc) {
		fprintf(stderr, "  %s\n", err);
		return NULL;
	}
	struct image *back = NULL;
	rc = image_read(tpath(name), &back, err, sizeof err);
	CHECK(rc == 0 && back);
	if (rc)
		fprintf(stderr, "  %s\n", err);
	else
		CHECK(back->width == img->width && back->height == img->height);
	return back;
}

/* PNG and PPM store q = floor(clamp(encode(c), 0, 1) * M + 0.5). Reading decodes
 * exactly that sample, so the result must equal the model. And |q/M - encode(c)| is at
 * most 0.5/M plus the single-precision error of the encoding (a few float steps,
 * 4 * 2^-24 allowed), and the decoding curve is steepest at 1 (slope 2.4/1.055): the
 * linear error is at most 2.4/1.055 * (0.5/M + 2^-22) (0.0045 at 8 bits, 1.8e-5 at 16),
 * plus the rounding of the result to float. */
static void check_quantised(const struct image *img, const struct image *back, unsigned maxval,
                            const char *what)
{
	if (!back)
		return;
	double bound = 2.4 / 1.055 * (0.5 / maxval + 0x1p-22) + 0x1p-24;
	double worst = 0;
	int model_misses = 0;
	for (size_t i = 0; i < (size_t)img->width * img->height * 3; i++) {
		double c = img->rgb[i];
		double clamped = isnan(c) ? 0 : c < 0 ? 0 : c > 1 ? 1 : c;
		unsigned q = image_srgb_sample(img->rgb[i], maxval);
		float model = (float)image_srgb_decode((double)q / maxval);
		if (back->rgb[i] != model)
			model_misses++;
		double e = fabs(back->rgb[i] - clamped);
		if (e > worst)
			worst = e;
	}
	if (model_misses || worst > bound)
		fprintf(stderr, "  %s: %d samples off the model, worst error %g (bound %g)\n", what,
		        model_misses, worst, bound);
	CHECK(model_misses == 0);
	CHECK(worst <= bound);
}

static void test_round_trips(void)
{
	struct image *img = test_image(37, 23, 1);
	/* out-of-range values clamp on PNG and PPM */
	float special[] = { NAN, -0.5f, 3.0f, INFINITY, -INFINITY, 1e-9f };
	for (int i = 0; i < 6; i++)
		img->rgb[30 + i] = special[i];

	struct image *b;
	b = round_trip(img, "rt8.png", 8, false);
	check_quantised(img, b, 255, "png 8");
	if (b) {
		CHECK(b->rgb[30] == 0 && b->rgb[31] == 0 && b->rgb[32] == 1 && b->rgb[33] == 1 &&
		      b->rgb[34] == 0);
	}
	image_free(b);
	b = round_trip(img, "rt16.png", 16, false);
	check_quantised(img, b, 65535, "png 16");
	image_free(b);
	b = round_trip(img, "rt8.ppm", 8, false);
	check_quantised(img, b, 255, "ppm 8");
	image_free(b);
	b = round_trip(img, "rt16.ppm", 16, false);
	check_quantised(img, b, 65535, "ppm 16");
	image_free(b);

	/* EXR keeps values outside [0, 1]; only NaN becomes 0 */
	img->rgb[31] = -0.25f;
	img->rgb[32] = 5.0f;
	img->rgb[35] = 1000.0f;
	img->rgb[36] = 1e5f;           /* beyond half's range */
	img->rgb[37] = 1e-6f;          /* a half subnormal */
	b = round_trip(img, "rtf.exr", 8, true);
	if (b) {
		int misses = 0;
		for (size_t i = 0; i < (size_t)img->width * img->height * 3; i++) {
			float want = isnan(img->rgb[i]) ? 0.0f : img->rgb[i];
			misses += b->rgb[i] != want;
		}
		CHECK(misses == 0);
	}
	image_free(b);
	/* half rounds to nearest: relative error <= 2^-11 for normal numbers, absolute
	 * <= 2^-25 for subnormals (below 2^-14) */
	b = round_trip(img, "rth.exr", 8, false);
	if (b) {
		int misses = 0;
		for (size_t i = 0; i < (size_t)img->width * img->height * 3; i++) {
			float c = img->rgb[i];
			if (isnan(c) || i == 36)
				continue;
			if (isinf(c) ? b->rgb[i] != c : fabs(b->rgb[i] - c) > fabs(c) * 0x1p-11 + 0x1p-25)
				misses++;
		}
		CHECK(misses == 0);
		CHECK(b->rgb[30] == 0);
		CHECK(b->rgb[31] == -0.25f && b->rgb[32] == 5.0f && b->rgb[35] == 1000.0f);
		CHECK(isinf(b->rgb[36]) && b->rgb[36] > 0);
		CHECK(isinf(b->rgb[33]) && isinf(b->rgb[34]) && b->rgb[34] < 0);
	}
	image_free(b);
	/* a one-pixel image: the smallest chunk */
	struct image *one = image_new(1, 1);
	one->rgb[0] = 0.25f;
	b = round_trip(one, "one.exr", 8, false);
	CHECK(b && b->rgb[0] == 0.25f && b->rgb[1] == 0);
	image_free(b);
	b = round_trip(one, "one.png", 16, false);
	CHECK(b && fabs(b->rgb[0] - 0.25f) < 2e-5);
	image_free(b);
	image_free(one);
	image_free(img);
}

/* The same image gives the same bytes, every time and for every format. */
static void test_reproducible(void)
{
	struct image *img = test_image(40, 33, 7);
	static const struct { const char *a, *b; int depth; bool f32; } cases[] = {
		{ "same1.png", "same2.png", 8, false }, { "same1_16.png", "same2_16.png", 16, false },
		{ "same1.exr", "same2.exr", 8, false }, { "same1f.exr", "same2f.exr", 8, true },
		{ "same1.ppm", "same2.ppm", 8, false }, { "same1_16.ppm", "same2_16.ppm", 16, false },
	};
	for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
		char err[512];
		struct image_write_options opt = { .bit_depth = cases[i].depth, .float32 = cases[i].f32 };
		CHECK(image_write(img, tpath(cases[i].a), &opt, err, sizeof err) == 0);
		sleep(i == 0 ? 1 : 0);         /* a clock in the metadata would show */
		CHECK(image_write(img, tpath(cases[i].b), &opt, err, sizeof err) == 0);
		if (!same_file(tpath(cases[i].a), tpath(cases[i].b)))
			fprintf(stderr, "  %s and %s differ\n", cases[i].a, cases[i].b);
		CHECK(same_file(tpath(cases[i].a), tpath(cases[i].b)));
	}
	image_free(img);
}

/* The PPM header has no comments, and the raster follows it exactly. */
static void test_ppm_layout(void)
{
	struct image *img = test_image(6, 4, 3);
	char err[512];
	struct image_write_options o16 = { .bit_depth = 16, .float32 = false };
	CHECK(image_write(img, tpath("lay8.ppm"), NULL, err, sizeof err) == 0);
	CHECK(image_write(img, tpath("lay16.ppm"), &o16, err, sizeof err) == 0);
	size_t n;
	unsigned char *d = slurp(tpath("lay8.ppm"), &n);
	CHECK(d && n == 11 + 6 * 4 * 3 && memcmp(d, "P6\n6 4\n255\n", 11) == 0);
	/* pixel 1's red, 8-bit */
	CHECK(d && d[11 + 3] == image_srgb_sample(img->rgb[3], 255));
	free(d);
	d = slurp(tpath("lay16.ppm"), &n);
	CHECK(d && n == 13 + 6 * 4 * 6 && memcmp(d, "P6\n6 4\n65535\n", 13) == 0);
	unsigned q = image_srgb_sample(img->rgb[3], 65535);
	CHECK(d && d[13 + 6] == q >> 8 && d[13 + 7] == (q & 0xff));      /* big-endian */
	free(d);
	image_free(img);

	/* comments and odd white space in a header, as POV-Ray writes them */
	static const unsigned char pov[] = "P6\n# Created by POV-Ray\n#second\n2  1\n# x\n65535\n"
	                                   "\x00\x00\xff\xff\x80\x00" "\x12\x34\x00\x01\xff\xfe";
	spit(tpath("pov.ppm"), pov, sizeof pov - 1);
	struct image *b = NULL;
	CHECK(image_read(tpath("pov.ppm"), &b, err, sizeof err) == 0);
	if (b) {
		CHECK(b->width == 2 && b->height == 1);
		CHECK(b->rgb[0] == 0 && b->rgb[1] == 1);
		CHECK(b->rgb[2] == (float)image_srgb_decode(0x8000 / 65535.0));
		CHECK(b->rgb[3] == (float)image_srgb_decode(0x1234 / 65535.0));
	}
	image_free(b);
	/* maxval 100: the samples scale by it */
	static const unsigned char m100[] = "P6 1 1 100\n\x00\x32\x64";
	spit(tpath("m100.ppm"), m100, sizeof m100 - 1);
	b = NULL;
	CHECK(image_read(tpath("m100.ppm"), &b, err, sizeof err) == 0);
	CHECK(b && b->rgb[0] == 0 && b->rgb[1] == (float)image_srgb_decode(0.5) && b->rgb[2] == 1);
	image_free(b);
}

/* The chunk types of a PNG file, as a string of 4-letter names. */
static void png_chunks(const unsigned char *d, size_t n, char *names, size_t cap,
                       unsigned char *srgb_intent, unsigned *gama)
{
	names[0] = '\0';
	for (size_t p = 8; p + 12 <= n;) {
		size_t len = (size_t)d[p] << 24 | (size_t)d[p + 1] << 16 | d[p + 2] << 8 | d[p + 3];
		const unsigned char *type = d + p + 4, *data = d + p + 8;
		if (strlen(names) + 6 < cap)
			strncat(names, (const char *)type, 4), strcat(names, " ");
		if (memcmp(type, "sRGB", 4) == 0 && len == 1)
			*srgb_intent = data[0];
		if (memcmp(type, "gAMA", 4) == 0 && len == 4)
			*gama = (unsigned)data[0] << 24 | data[1] << 16 | data[2] << 8 | data[3];
		p += 12 + len;
	}
}

static void test_png_chunks(void)
{
	struct image *img = test_image(9, 5, 11);
	for (int depth = 8; depth <= 16; depth += 8) {
		char err[512];
		struct image_write_options opt = { .bit_depth = depth, .float32 = false };
		const char *path = tpath(depth == 8 ? "chunks8.png" : "chunks16.png");
		CHECK(image_write(img, path, &opt, err, sizeof err) == 0);
		size_t n;
		unsigned char *d = slurp(path, &n);
		char names[256];
		unsigned char intent = 99;
		unsigned gama = 0;
		if (!d)
			continue;
		CHECK(d[24] == depth);     /* IHDR's bit depth */
		CHECK(d[25] == 2);         /* colour type RGB */
		png_chunks(d, n, names, sizeof names, &intent, &gama);
		CHECK(strncmp(names, "IHDR ", 5) == 0);
		CHECK(strstr(names, "sRGB") && strstr(names, "gAMA") && strstr(names, "cHRM"));
		CHECK(!strstr(names, "tIME") && !strstr(names, "tEXt") && !strstr(names, "zTXt") &&
		      !strstr(names, "iTXt"));
		CHECK(strstr(names, "IEND") && strcmp(names + strlen(names) - 5, "IEND ") == 0);
		CHECK(intent == 0);        /* perceptual */
		CHECK(gama == 45455);
		free(d);
	}
	image_free(img);
}

/* A PNG written with libpng directly: w x h, the given colour type and depth, rows
 * from data (packed as libpng expects); gamma < 0: untagged, 0: sRGB chunk, else a
 * gAMA chunk of that value. pal/trns for palette images. */
static void write_png(const char *path, int w, int h, int color, int depth, const unsigned char *data,
                      double gamma, const png_color *pal, int npal, const png_byte *trns, int ntrns,
                      bool interlace)
{
	FILE *f = fopen(path, "wb");
	CHECK(f != NULL);
	if (!f)
		return;
	png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
	png_infop info = png_create_info_struct(png);
	if (setjmp(png_jmpbuf(png))) {
		CHECK(!"libpng failed in the test's own writer");
		png_destroy_write_struct(&png, &info);
		fclose(f);
		return;
	}
	png_init_io(png, f);
	png_set_IHDR(png, info, w, h, depth, color, interlace ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE,
	             PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
	if (gamma == 0)
		png_set_sRGB(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
	else if (gamma > 0)
		png_set_gAMA(png, info, gamma);
	if (pal)
		png_set_PLTE(png, info, pal, npal);
	if (trns)
		png_set_tRNS(png, info, trns, ntrns, NULL);
	png_write_info(png, info);
	size_t rowbytes = png_get_rowbytes(png, info);
	int passes = png_set_interlace_handling(png);
	for (int p = 0; p < passes; p++)
		for (int y = 0; y < h; y++)
			png_write_row(png, data + y * rowbytes);
	png_write_end(png, info);
	png_destroy_write_struct(&png, &info);
	fclose(f);
}

static struct image *read_ok(const char *name)
{
	char err[512] = "";
	struct image *img = NULL;
	int rc = image_read(tpath(name), &img, err, sizeof err);
	if (rc)
		fprintf(stderr, "  reading %s: %s\n", name, err);
	CHECK(rc == 0 && img);
	return img;
}

static void test_foreign_png(void)
{
	/* 8-bit RGB, one pixel, untagged: the sRGB curve */
	const unsigned char rgb8[] = { 128, 0, 255 };
	write_png(tpath("untagged.png"), 1, 1, PNG_COLOR_TYPE_RGB, 8, rgb8, -1, NULL, 0, NULL, 0, false);
	struct image *b = read_ok("untagged.png");
	CHECK(b && b->rgb[0] == (float)image_srgb_decode(128 / 255.0) && b->rgb[1] == 0 && b->rgb[2] == 1);
	image_free(b);
	/* gAMA 1.0: linear, as POV-Ray's File_Gamma=1.0 output */
	write_png(tpath("gamma1.png"), 1, 1, PNG_COLOR_TYPE_RGB, 8, rgb8, 1.0, NULL, 0, NULL, 0, false);
	b = read_ok("gamma1.png");
	CHECK(b && b->rgb[0] == (float)(128 / 255.0) && b->rgb[2] == 1);
	image_free(b);
	/* gAMA 0.5: a power law of 2, not sRGB */
	write_png(tpath("gamma05.png"), 1, 1, PNG_COLOR_TYPE_RGB, 8, rgb8, 0.5, NULL, 0, NULL, 0, false);
	b = read_ok("gamma05.png");
	CHECK(b && fabs(b->rgb[0] - pow(128 / 255.0, 2)) < 1e-7);
	image_free(b);
	/* an sRGB chunk */
	write_png(tpath("srgb.png"), 1, 1, PNG_COLOR_TYPE_RGB, 8, rgb8, 0, NULL, 0, NULL, 0, false);
	b = read_ok("srgb.png");
	CHECK(b && b->rgb[0] == (float)image_srgb_decode(128 / 255.0));
	image_free(b);
	/* 16-bit, gAMA 1.0 (POV-Ray's +FN16 File_Gamma=1.0) */
	const unsigned char rgb16[] = { 0x9c, 0x40, 0, 1, 0xff, 0xff };
	write_png(tpath("lin16.png"), 1, 1, PNG_COLOR_TYPE_RGB, 16, rgb16, 1.0, NULL, 0, NULL, 0, false);
	b = read_ok("lin16.png");
	CHECK(b && b->rgb[0] == (float)(40000 / 65535.0) && b->rgb[1] == (float)(1 / 65535.0) &&
	      b->rgb[2] == 1);
	image_free(b);
	/* grey 8-bit */
	const unsigned char grey[] = { 200, 10 };
	write_png(tpath("grey.png"), 2, 1, PNG_COLOR_TYPE_GRAY, 8, grey, -1, NULL, 0, NULL, 0, false);
	b = read_ok("grey.png");
	float g200 = (float)image_srgb_decode(200 / 255.0), g10 = (float)image_srgb_decode(10 / 255.0);
	CHECK(b && b->rgb[0] == g200 && b->rgb[1] == g200 && b->rgb[2] == g200 && b->rgb[3] == g10);
	image_free(b);
	/* grey 1-bit: 1 is white */
	const unsigned char bits[] = { 0xa0 };  /* 1 0 1 */
	write_png(tpath("bits.png"), 3, 1, PNG_COLOR_TYPE_GRAY, 1, bits, -1, NULL, 0, NULL, 0, false);
	b = read_ok("bits.png");
	CHECK(b && b->rgb[0] == 1 && b->rgb[3] == 0 && b->rgb[5] == 0 && b->rgb[6] == 1);
	image_free(b);
	/* grey + alpha 16-bit: alpha dropped */
	const unsigned char ga16[] = { 0xff, 0xff, 0, 0 };
	write_png(tpath("ga16.png"), 1, 1, PNG_COLOR_TYPE_GRAY_ALPHA, 16, ga16, 1.0, NULL, 0, NULL, 0, false);
	b = read_ok("ga16.png");
	CHECK(b && b->rgb[0] == 1 && b->rgb[1] == 1 && b->rgb[2] == 1);
	image_free(b);
	/* RGBA 8-bit: alpha dropped, colour not premultiplied */
	const unsigned char rgba[] = { 255, 128, 0, 0 };
	write_png(tpath("rgba.png"), 1, 1, PNG_COLOR_TYPE_RGB_ALPHA, 8, rgba, 1.0, NULL, 0, NULL, 0, false);
	b = read_ok("rgba.png");
	CHECK(b && b->rgb[0] == 1 && b->rgb[1] == (float)(128 / 255.0) && b->rgb[2] == 0);
	image_free(b);
	/* 2-bit palette with transparency: colours from the palette, tRNS ignored */
	const png_color pal[3] = { { 255, 0, 0 }, { 0, 255, 0 }, { 0, 0, 255 } };
	const png_byte trns[3] = { 0, 128, 255 };
	const unsigned char idx[] = { 0x24 };   /* 0 2 1 0 */
	write_png(tpath("pal.png"), 4, 1, PNG_COLOR_TYPE_PALETTE, 2, idx, -1, pal, 3, trns, 3, false);
	b = read_ok("pal.png");
	CHECK(b && b->rgb[0] == 1 && b->rgb[1] == 0 && b->rgb[2] == 0);
	CHECK(b && b->rgb[3] == 0 && b->rgb[4] == 0 && b->rgb[5] == 1);
	CHECK(b && b->rgb[6] == 0 && b->rgb[7] == 1 && b->rgb[8] == 0);
	image_free(b);
	/* Adam7 interlaced, 13 x 11, every pixel distinct */
	enum { IW = 13, IH = 11 };
	unsigned char inter[IW * IH * 3];
	for (int i = 0; i < IW * IH * 3; i++)
		inter[i] = (unsigned char)(i * 7 + i / 3);
	write_png(tpath("adam7.png"), IW, IH, PNG_COLOR_TYPE_RGB, 8, inter, 1.0, NULL, 0, NULL, 0, true);
	b = read_ok("adam7.png");
	int misses = 0;
	for (int i = 0; b && i < IW * IH * 3; i++)
		misses += b->rgb[i] != (float)(inter[i] / 255.0);
	CHECK(b && misses == 0);
	image_free(b);
}

/* An EXR written with OpenEXR's C API directly: a w x h data window at (x0, y0), one
 * channel per letter of channels, all of one pixel type, scanline or 8 x 8 tiles.
 * Channel R or Y of pixel i is exr_value(i, 0), G exr_value(i, 1), B exr_value(i, 2),
 * any other 0.5. */
static float exr_value(int i, int k)
{
	return (float)((i * 3 + k) % 50);
}

static void write_exr(const char *path, int w, int h, int x0, int y0, exr_pixel_type_t type,
                      bool tiled, const char *channels, exr_compression_t comp)
{
	exr_context_t ctx;
	exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
	int part;
	exr_result_t rv = exr_start_write(&ctx, path, EXR_WRITE_FILE_DIRECTLY, &init);
	CHECK(rv == EXR_ERR_SUCCESS);
	if (rv)
		return;
	rv = exr_add_part(ctx, NULL, tiled ? EXR_STORAGE_TILED : EXR_STORAGE_SCANLINE, &part);
	exr_attr_box2i_t dw = { .min = { .x = x0, .y = y0 }, .max = { .x = x0 + w - 1, .y = y0 + h - 1 } };
	exr_attr_v2f_t center = { .x = 0, .y = 0 };
	rv |= exr_initialize_required_attr(ctx, part, &dw, &dw, 1.0f, &center, 1.0f,
	                                   EXR_LINEORDER_INCREASING_Y, comp);
	if (tiled)
		rv |= exr_set_tile_descriptor(ctx, part, 8, 8, EXR_TILE_ONE_LEVEL, EXR_TILE_ROUND_DOWN);
	for (const char *c = channels; *c; c++) {
		char name[2] = { *c, 0 };
		rv |= exr_add_channel(ctx, part, name, type, EXR_PERCEPTUALLY_LOGARITHMIC, 1, 1);
	}
	rv |= exr_write_header(ctx);
	CHECK(rv == EXR_ERR_SUCCESS);
	/* planar source data, one plane per channel of the file's order (A B G R / A Y) */
	size_t nch = strlen(channels);
	unsigned char *planes = calloc((size_t)w * h * nch, 4);
	float *fplanes = calloc((size_t)w * h * nch, sizeof(float));
	int ntiles_x = tiled ? (w + 7) / 8 : 1, ntiles_y = tiled ? (h + 7) / 8 : 0;
	int32_t lines = 1;
	if (!tiled) {
		exr_get_scanlines_per_chunk(ctx, part, &lines);
		ntiles_y = (h + lines - 1) / lines;
	}
	exr_encode_pipeline_t enc = EXR_ENCODE_PIPELINE_INITIALIZER;
	bool started = false;
	for (int ty = 0; ty < ntiles_y && rv == EXR_ERR_SUCCESS; ty++) {
		for (int tx = 0; tx < ntiles_x && rv == EXR_ERR_SUCCESS; tx++) {
			exr_chunk_info_t ci;
			if (tiled)
				rv = exr_write_tile_chunk_info(ctx, part, tx, ty, 0, 0, &ci);
			else
				rv = exr_write_scanline_chunk_info(ctx, part, y0 + ty * lines, &ci);
			rv |= started ? exr_encoding_update(ctx, part, &ci, &enc)
			              : exr_encoding_initialize(ctx, part, &ci, &enc);
			started = true;
			if (rv)
				break;
			int px = tiled ? tx * 8 : 0, py = tiled ? ty * 8 : ty * lines;
			for (int c = 0; c < enc.channel_count; c++) {
				exr_coding_channel_info_t *ch = &enc.channels[c];
				const char *n = ch->channel_name;
				int k = n[0] == 'R' || n[0] == 'Y' ? 0 : n[0] == 'G' ? 1 : n[0] == 'B' ? 2 : 3;
				float *fp = fplanes + (size_t)c * w * h;
				unsigned char *p = planes + (size_t)c * w * h * 4;
				for (int y = 0; y < ci.height; y++)
					for (int x = 0; x < ci.width; x++) {
						int i = (py + y) * w + px + x;
						float v = k == 3 ? 0.5f : exr_value(i, k);
						if (type == EXR_PIXEL_UINT) {
							uint32_t u = (uint32_t)v;
							memcpy(p + (size_t)i * 4, &u, 4);
						} else {
							fp[i] = v;
						}
					}
				ch->user_pixel_stride = (int32_t)(type == EXR_PIXEL_UINT ? 4 : sizeof(float));
				ch->user_line_stride = ch->user_pixel_stride * w;
				ch->user_data_type = type == EXR_PIXEL_UINT ? EXR_PIXEL_UINT : EXR_PIXEL_FLOAT;
				ch->user_bytes_per_element = 4;
				size_t off = ((size_t)py * w + px) * 4;
				ch->encode_from_ptr = type == EXR_PIXEL_UINT ? p + off : (uint8_t *)fp + off;
			}
			rv = exr_encoding_choose_default_routines(ctx, part, &enc);
			if (rv == EXR_ERR_SUCCESS)
				rv = exr_encoding_run(ctx, part, &enc);
		}
	}
	CHECK(rv == EXR_ERR_SUCCESS);
	if (started)
		exr_encoding_destroy(ctx, &enc);
	CHECK(exr_finish(&ctx) == EXR_ERR_SUCCESS);
	free(planes);
	free(fplanes);
}

static void test_foreign_exr(void)
{
	static const struct {
		const char *name;
		exr_pixel_type_t type;
		bool tiled;
		const char *channels;
		exr_compression_t comp;
		int x0, y0;
	} cases[] = {
		{ "scan_half.exr", EXR_PIXEL_HALF, false, "RGB", EXR_COMPRESSION_NONE, 0, 0 },
		{ "scan_float_alpha.exr", EXR_PIXEL_FLOAT, false, "RGBA", EXR_COMPRESSION_PIZ, 0, 0 },
		{ "scan_uint.exr", EXR_PIXEL_UINT, false, "RGB", EXR_COMPRESSION_ZIP, 0, 0 },
		{ "scan_offset.exr", EXR_PIXEL_HALF, false, "RGB", EXR_COMPRESSION_ZIPS, -5, 7 },
		{ "scan_extra.exr", EXR_PIXEL_HALF, false, "ZRYGB", EXR_COMPRESSION_RLE, 0, 0 },
		{ "tile_half.exr", EXR_PIXEL_HALF, true, "RGBA", EXR_COMPRESSION_ZIP, 0, 0 },
		{ "tile_uint.exr", EXR_PIXEL_UINT, true, "RGB", EXR_COMPRESSION_NONE, 3, -2 },
		{ "tile_grey.exr", EXR_PIXEL_FLOAT, true, "YA", EXR_COMPRESSION_RLE, 0, 0 },
		{ "scan_grey.exr", EXR_PIXEL_HALF, false, "Y", EXR_COMPRESSION_PIZ, 0, 0 },
		/* all half, with channels we skip: OpenEXR's fast unpackers write them too */
		{ "scan_grey_gb.exr", EXR_PIXEL_HALF, false, "YGB", EXR_COMPRESSION_ZIP, 0, 0 },
		{ "tile_grey_gb.exr", EXR_PIXEL_HALF, true, "YGB", EXR_COMPRESSION_NONE, 0, 0 },
	};
	enum { W = 21, H = 19 };       /* partial tiles and chunks at the edges */
	for (size_t t = 0; t < sizeof cases / sizeof cases[0]; t++) {
		write_exr(tpath(cases[t].name), W, H, cases[t].x0, cases[t].y0, cases[t].type,
		          cases[t].tiled, cases[t].channels, cases[t].comp);
		struct image *b = read_ok(cases[t].name);
		if (!b)
			continue;
		CHECK(b->width == W && b->height == H);
		int misses = 0;
		for (int i = 0; i < W * H && b->width == W && b->height == H; i++)
			for (int k = 0; k < 3; k++)
				misses += b->rgb[i * 3 + k] != exr_value(i, cases[t].channels[0] == 'Y' ? 0 : k);
		if (misses)
			fprintf(stderr, "  %s: %d samples wrong\n", cases[t].name, misses);
		CHECK(misses == 0);
		image_free(b);
	}

	/* no colour channels at all */
	write_exr(tpath("nocolour.exr"), 2, 2, 0, 0, EXR_PIXEL_FLOAT, false, "ZA", EXR_COMPRESSION_NONE);
	char err[512];
	struct image *b = NULL;
	CHECK(image_read(tpath("nocolour.exr"), &b, err, sizeof err) == EINVAL && !b);
	CHECK(strstr(err, "no R, G and B") != NULL);
}

/* Reading must fail with a message naming the file, and never crash. */
static void expect_read_error(const char *path, int want_rc, const char *want_msg)
{
	char err[512] = "";
	struct image *img = (struct image *)1;
	int rc = image_read(path, &img, err, sizeof err);
	if (rc == 0 || (want_rc && rc != want_rc) || (want_msg && !strstr(err, want_msg)) ||
	    !strstr(err, path) || strncmp(err, "cannot read '", 13) != 0)
		fprintf(stderr, "  %s: rc %d, message \"%s\"\n", path, rc, err);
	CHECK(rc != 0);
	CHECK(want_rc == 0 || rc == want_rc);
	CHECK(img == NULL);
	CHECK(strstr(err, path) != NULL);
	CHECK(strncmp(err, "cannot read '", 13) == 0);
	CHECK(!want_msg || strstr(err, want_msg));
}

/* Copies the first n bytes of src to dst (a cut-off file). */
static void truncate_copy(const char *src, const char *dst, size_t n)
{
	size_t len;
	unsigned char *d = slurp(src, &len);
	CHECK(d != NULL);
	if (d)
		spit(dst, d, n < len ? n : len);
	free(d);
}

/* Cuts the file at many places and flips bytes all over it: every read must fail
 * cleanly when cut, and return either an image or an error when flipped. */
static void torture(const char *name)
{
	size_t len;
	unsigned char *d = slurp(tpath(name), &len);
	CHECK(d != NULL);
	if (!d)
		return;
	char cut[64];
	snprintf(cut, sizeof cut, "cut_%s", name);
	size_t step = len / 40 ? len / 40 : 1;
	for (size_t n = 0; n < len; n += (n < 64 ? 1 : step)) {
		spit(tpath(cut), d, n);
		expect_read_error(tpath(cut), 0, NULL);
	}
	spit(tpath(cut), d, len - 1);
	expect_read_error(tpath(cut), 0, NULL);

	unsigned state = 99;
	for (int t = 0; t < 200; t++) {
		unsigned char *c = malloc(len);
		memcpy(c, d, len);
		for (int k = 0; k < 1 + t % 4; k++) {
			size_t at = 8 + (size_t)(noise(&state) * (len - 8));
			c[at] ^= (unsigned char)(1 + noise(&state) * 255);
		}
		spit(tpath(cut), c, len);
		char err[512];
		struct image *img = NULL;
		int rc = image_read(tpath(cut), &img, err, sizeof err);
		CHECK(rc == 0 ? img != NULL : img == NULL && strstr(err, tpath(cut)) != NULL);
		image_free(img);
		free(c);
	}
	free(d);
}

/* A PNG file of only a header for w x h RGB pixels and an empty IDAT: png_read_info
 * stops at the first IDAT, so the header is all the reader sees before it allocates. */
static void write_png_header(const char *path, png_uint_32 w, png_uint_32 h)
{
	FILE *f = fopen(path, "wb");
	CHECK(f != NULL);
	png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
	png_infop info = png_create_info_struct(png);
	if (setjmp(png_jmpbuf(png)) == 0) {
		png_init_io(png, f);
		png_set_user_limits(png, 0x7fffffff, 0x7fffffff);
		png_set_IHDR(png, info, w, h, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
		             PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
		png_write_info(png, info);
		png_write_chunk(png, (png_const_bytep)"IDAT", NULL, 0);
	}
	png_destroy_write_struct(&png, &info);
	fclose(f);
}

static void test_corrupt(void)
{
	char err[512];
	expect_read_error(tpath("does-not-exist.png"), ENOENT, "No such file or directory");
	CHECK(mkdir(tpath("adir.png"), 0777) == 0);
	expect_read_error(tpath("adir.png"), EISDIR, "Is a directory");
	spit(tpath("empty.png"), "", 0);
	expect_read_error(tpath("empty.png"), EINVAL, "empty file");
	spit(tpath("text.png"), "hello, world\n", 13);
	expect_read_error(tpath("text.png"), EINVAL, "not a PNG, OpenEXR or binary PPM");

	/* files of each format, cut and damaged */
	struct image *img = test_image(24, 20, 5);
	struct image_write_options o16 = { .bit_depth = 16, .float32 = false }, of = { .bit_depth = 8, .float32 = true };
	CHECK(image_write(img, tpath("good.png"), NULL, err, sizeof err) == 0);
	CHECK(image_write(img, tpath("good16.png"), &o16, err, sizeof err) == 0);
	CHECK(image_write(img, tpath("good.exr"), NULL, err, sizeof err) == 0);
	CHECK(image_write(img, tpath("goodf.exr"), &of, err, sizeof err) == 0);
	CHECK(image_write(img, tpath("good.ppm"), &o16, err, sizeof err) == 0);
	image_free(img);
	truncate_copy(tpath("good.png"), tpath("trunc.png"), 100);
	expect_read_error(tpath("trunc.png"), EINVAL, "truncated");
	truncate_copy(tpath("good.ppm"), tpath("trunc.ppm"), 500);
	expect_read_error(tpath("trunc.ppm"), EINVAL, "truncated");
	torture("good.png");
	torture("good16.png");
	torture("good.exr");
	torture("goodf.exr");
	torture("good.ppm");
	write_exr(tpath("scan_none.exr"), 21, 19, 0, 0, EXR_PIXEL_HALF, false, "RGB",
	          EXR_COMPRESSION_NONE);
	torture("scan_none.exr");
	write_exr(tpath("tiled.exr"), 21, 19, 0, 0, EXR_PIXEL_FLOAT, true, "RGBA",
	          EXR_COMPRESSION_ZIP);
	torture("tiled.exr");

	/* garbage behind each format's magic */
	unsigned char junk[4096];
	unsigned state = 3;
	for (size_t i = 0; i < sizeof junk; i++)
		junk[i] = (unsigned char)(noise(&state) * 256);
	memcpy(junk, "\x89PNG\r\n\x1a\n", 8);
	spit(tpath("junk.png"), junk, sizeof junk);
	expect_read_error(tpath("junk.png"), EINVAL, NULL);
	memcpy(junk, "\x76\x2f\x31\x01\x02\0\0\0", 8);
	spit(tpath("junk.exr"), junk, sizeof junk);
	expect_read_error(tpath("junk.exr"), EINVAL, "OpenEXR");
	memcpy(junk, "P6\n", 3);
	spit(tpath("junk.ppm"), junk, sizeof junk);
	expect_read_error(tpath("junk.ppm"), EINVAL, "malformed PPM header");

	/* PPM headers */
	static const struct { const char *name, *text, *msg; int rc; } ppm[] = {
		{ "p_letters.ppm", "P6\nab 2\n255\n", "malformed", EINVAL },
		{ "p_zero.ppm", "P6\n0 2\n255\n", "no pixels", EINVAL },
		{ "p_maxval0.ppm", "P6\n1 1\n0\n", "maxval", EINVAL },
		{ "p_maxval_big.ppm", "P6\n1 1\n65536\n", "maxval", EINVAL },
		{ "p_overflow.ppm", "P6\n99999999999 1\n255\n", "malformed", EINVAL },
		{ "p_huge.ppm", "P6\n100000 100000\n255\n", "too large", EFBIG },
		{ "p_nospace.ppm", "P6\n1 1\n255", "malformed", EINVAL },
		{ "p_above.ppm", "P6 1 1 100\n\x00\x65\x00", "maxval", EINVAL },
		{ "p_short.ppm", "P6 2 1 255\n\x01\x02\x03\x04", "unexpected end of file", EINVAL },
		{ "p_p3.ppm", "P3\n1 1\n255\n0 0 0\n", "not a PNG", EINVAL },
	};
	for (size_t i = 0; i < sizeof ppm / sizeof ppm[0]; i++) {
		spit(tpath(ppm[i].name), ppm[i].text, strlen(ppm[i].text) + (i == 7 ? 3 : 0));
		expect_read_error(tpath(ppm[i].name), ppm[i].rc, ppm[i].msg);
	}

	/* PNG headers claiming 100000 x 100000 pixels, and 2^28 (the limit) in a file of a
	 * few bytes: both refused before any allocation */
	write_png_header(tpath("huge.png"), 100000, 100000);
	expect_read_error(tpath("huge.png"), EFBIG, "too large");
	write_png_header(tpath("big.png"), 16384, 16384);
	expect_read_error(tpath("big.png"), EINVAL, "16384 x 16384 pixels cannot fit in its 45 bytes");
}

static void test_atomic(void)
{
	char err[512];
	struct image *img = test_image(128, 128, 21);
	char keep[PATH_MAX + 64];
	snprintf(keep, sizeof keep, "%s", tpath("keep.png"));
	static const char old[] = "the old contents";
	spit(keep, old, sizeof old);

	/* a directory that does not exist */
	char path[2 * PATH_MAX];
	snprintf(path, sizeof path, "%s/no/such/dir/x.png", tmpdir);
	int before = count_entries();
	CHECK(image_write(img, path, NULL, err, sizeof err) == ENOENT);
	char want[2 * PATH_MAX + 64];
	snprintf(want, sizeof want, "cannot write '%s': No such file or directory", path);
	CHECK(strcmp(err, want) == 0);
	/* a parent that is a file */
	snprintf(path, sizeof path, "%s/x.png", keep);
	CHECK(image_write(img, path, NULL, err, sizeof err) == ENOTDIR);
	CHECK(strstr(err, path) && strstr(err, "Not a directory"));
	/* the target is a directory: everything is written, then rename fails */
	CHECK(mkdir(tpath("target.exr"), 0777) == 0);
	before = count_entries();
	CHECK(image_write(img, tpath("target.exr"), NULL, err, sizeof err) == EISDIR);
	CHECK(strstr(err, tpath("target.exr")) && strstr(err, "Is a directory"));
	CHECK(count_entries() == before);
	/* options and extensions */
	CHECK(image_write(img, tpath("x.tga"), NULL, err, sizeof err) == EINVAL);
	CHECK(strstr(err, "unknown image format") != NULL);
	struct image_write_options bad = { .bit_depth = 12, .float32 = false };
	CHECK(image_write(img, tpath("x.png"), &bad, err, sizeof err) == EINVAL);
	CHECK(strstr(err, "bit depth 12") != NULL);
	CHECK(count_entries() == before);

	/* Running out of room in the middle of the data: a file size limit makes the
	 * writes fail with EFBIG after the first few kilobytes. */
	struct rlimit saved, small;
	CHECK(getrlimit(RLIMIT_FSIZE, &saved) == 0);
	small = saved;
	small.rlim_cur = 4096;
	void (*old_handler)(int) = signal(SIGXFSZ, SIG_IGN);
	static const char *const names[] = { "keep.png", "keep.exr", "keep.ppm" };
	for (int f = 0; f < 3; f++) {
		const char *p = tpath(names[f]);
		spit(p, old, sizeof old);
		before = count_entries();
		CHECK(setrlimit(RLIMIT_FSIZE, &small) == 0);
		struct image_write_options opt = { .bit_depth = 16, .float32 = true };
		int rc = image_write(img, p, &opt, err, sizeof err);
		CHECK(setrlimit(RLIMIT_FSIZE, &saved) == 0);
		if (rc != EFBIG)
			fprintf(stderr, "  %s: rc %d: %s\n", names[f], rc, err);
		CHECK(rc == EFBIG);
		CHECK(strstr(err, p) && strstr(err, "File too large"));
		size_t n;
		unsigned char *d = slurp(p, &n);
		CHECK(d && n == sizeof old && memcmp(d, old, n) == 0);
		free(d);
		CHECK(count_entries() == before);
	}
	signal(SIGXFSZ, old_handler);

	/* success replaces the file, with the umask's permissions */
	mode_t mask = umask(022);
	CHECK(image_write(img, keep, NULL, err, sizeof err) == 0);
	umask(mask);
	struct stat st;
	CHECK(stat(keep, &st) == 0 && (st.st_mode & 0777) == 0644);
	struct image *b = read_ok("keep.png");
	CHECK(b && b->width == 128);
	image_free(b);
	/* a name without a directory: the temporary goes to the current one */
	char cwd[PATH_MAX];
	CHECK(getcwd(cwd, sizeof cwd) != NULL);
	CHECK(chdir(tmpdir) == 0);
	CHECK(image_write(img, "relative.PPM", NULL, err, sizeof err) == 0);
	CHECK(chdir(cwd) == 0);
	b = read_ok("relative.PPM");
	image_free(b);
	/* an unwritable directory (root may write anywhere, so only checked for others) */
	if (geteuid() != 0) {
		CHECK(mkdir(tpath("ro"), 0555) == 0);
		CHECK(image_write(img, tpath("ro/x.png"), NULL, err, sizeof err) == EACCES);
		CHECK(strstr(err, "Permission denied") != NULL);
		chmod(tpath("ro"), 0777);
	}
	image_free(img);
}

int main(void)
{
	const char *base = getenv("TMPDIR");
	snprintf(tmpdir, sizeof tmpdir, "%s/scn-test-image-XXXXXX", base && *base ? base : "/tmp");
	if (!mkdtemp(tmpdir)) {
		perror("mkdtemp");
		return 99;
	}
	test_new();
	test_format_of();
	test_srgb();
	test_round_trips();
	test_reproducible();
	test_ppm_layout();
	test_png_chunks();
	test_foreign_png();
	test_foreign_exr();
	test_corrupt();
	test_atomic();
	if (check_failures == 0)
		nftw(tmpdir, remove_one, 16, FTW_DEPTH | FTW_PHYS);
	else
		fprintf(stderr, "files kept in %s\n", tmpdir);
	return check_result();
}
