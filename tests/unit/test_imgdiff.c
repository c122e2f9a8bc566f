/* test_imgdiff.c: render/imgdiff.c: metrics by hand, the 1/255 boundary, NaN and
 * infinities, where the maximum is reported, box downsampling, and the heatmap scale. */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "imgdiff.h"

static struct image *filled(int w, int h, float v)
{
	struct image *img = image_new(w, h);
	for (size_t i = 0; i < (size_t)w * h * 3; i++)
		img->rgb[i] = v;
	return img;
}

/* One channel off by d in a 4x2 image: rmse, mean, max and counts follow by hand. */
static void test_metrics(void)
{
	struct image *a = filled(4, 2, 0.25f), *b = filled(4, 2, 0.25f);
	struct imgdiff_stats s;
	CHECK(imgdiff_compare(a, b, &s));
	CHECK(s.rmse == 0 && s.mean == 0 && s.max == 0 && isinf(s.psnr) && s.psnr > 0);
	CHECK(s.off1 == 0 && s.off2 == 0 && s.pixels == 8 && s.max_x == 0 && s.max_y == 0);

	b->rgb[3 * (1 * 4 + 2) + 1] = 0.25f + 0.125f;     /* (2, 1) green, exact in float */
	b->rgb[3 * (0 * 4 + 3) + 0] = 0.25f - 0.0625f;    /* (3, 0) red */
	CHECK(imgdiff_compare(a, b, &s));
	CHECK(s.max == 0.125 && s.max_x == 2 && s.max_y == 1);
	CHECK_NEAR(s.mean, (0.125 + 0.0625) / 24, 1e-15);
	CHECK_NEAR(s.rmse, sqrt((0.125 * 0.125 + 0.0625 * 0.0625) / 24), 1e-15);
	CHECK_NEAR(s.psnr, 20 * log10(1 / s.rmse), 1e-12);
	CHECK(s.off1 == 2 && s.off2 == 2);

	/* the first pixel in reading order wins a tie */
	b->rgb[3 * (0 * 4 + 1) + 2] = 0.25f + 0.125f;     /* (1, 0) blue */
	CHECK(imgdiff_compare(a, b, &s) && s.max_x == 1 && s.max_y == 0);

	/* another size: no metrics */
	struct image *c = filled(2, 4, 0.25f);
	CHECK(!imgdiff_compare(a, c, &s));
	image_free(a);
	image_free(b);
	image_free(c);
}

/* 8-bit samples k steps apart count as off by more than 1/255 only from k = 2. */
static void test_boundary(void)
{
	struct image *a = image_new(255, 3), *b = image_new(255, 3);
	for (int v = 0; v < 255; v++)
		for (int k = 1; k <= 3; k++) {
			if (v + k > 255)
				continue;
			size_t i = 3 * ((size_t)(k - 1) * 255 + (size_t)v);
			a->rgb[i] = (float)(v / 255.0);
			b->rgb[i] = (float)((v + k) / 255.0);
		}
	struct imgdiff_stats s;
	CHECK(imgdiff_compare(a, b, &s));
	/* row 0 (1 step) counts nowhere; row 1 (2 steps, 254 pixels) only in off1;
	 * row 2 (3 steps, 253 pixels) in both */
	CHECK(s.off1 == 254 + 253);
	CHECK(s.off2 == 253);
	image_free(a);
	image_free(b);
}

static void test_nonfinite(void)
{
	struct image *a = filled(3, 1, 0.5f), *b = filled(3, 1, 0.5f);
	a->rgb[0] = b->rgb[0] = NAN;                       /* both NaN: equal */
	a->rgb[3] = b->rgb[3] = INFINITY;                  /* the same infinity: equal */
	struct imgdiff_stats s;
	CHECK(imgdiff_compare(a, b, &s) && s.max == 0 && s.rmse == 0);
	b->rgb[6] = NAN;                                   /* one NaN: infinitely off */
	CHECK(imgdiff_compare(a, b, &s) && isinf(s.max) && isinf(s.rmse) && isinf(s.mean));
	CHECK(s.max_x == 2 && s.off1 == 1 && s.psnr < 0 && isinf(s.psnr));
	b->rgb[6] = 0.5f;
	b->rgb[3] = -INFINITY;                             /* opposite infinities */
	CHECK(imgdiff_compare(a, b, &s) && isinf(s.max) && s.max_x == 1);
	image_free(a);
	image_free(b);
}

static void test_downsample(void)
{
	struct image *img = image_new(6, 4);
	for (int y = 0; y < 4; y++)
		for (int x = 0; x < 6; x++)
			for (int c = 0; c < 3; c++)
				img->rgb[3 * (y * 6 + x) + c] = (float)(x + 10 * y + 100 * c);
	struct image *half = imgdiff_downsample(img, 2);
	CHECK(half && half->width == 3 && half->height == 2);
	/* block (1, 1): x 2..3, y 2..3: mean x 2.5, mean y 2.5 */
	CHECK(half && half->rgb[3 * (1 * 3 + 1) + 2] == 2.5f + 25 + 200);
	image_free(half);
	struct image *same = imgdiff_downsample(img, 1);
	struct imgdiff_stats s;
	CHECK(same && imgdiff_compare(img, same, &s) && s.max == 0);
	image_free(same);
	CHECK(imgdiff_downsample(img, 4) == NULL);          /* 6 is not a multiple of 4 */
	CHECK(imgdiff_downsample(img, 3) == NULL);          /* nor is 4 of 3 */
	CHECK(imgdiff_downsample(img, 0) == NULL);
	struct image *flat = filled(2, 2, 0.5f), *one = imgdiff_downsample(flat, 2);
	CHECK(one && one->width == 1 && one->rgb[0] == 0.5f);
	image_free(one);
	image_free(flat);
	image_free(img);
}

/* Black below 2^-17, dark blue from 2^-16, yellow at 2^-8, white from 2^-4. */
static void test_heatmap(void)
{
	static const double errors[] = { 0, 0x1p-18, 0x1p-16, 0x1p-8, 0x1p-4, 0.5 };
	enum { N = sizeof errors / sizeof errors[0] };
	struct image *a = image_new(N, 1), *b = image_new(N, 1);
	for (int i = 0; i < N; i++)
		b->rgb[3 * i + 1] = (float)errors[i];
	struct image *h = imgdiff_heatmap(a, b);
	CHECK(h && h->width == N && h->height == 1);
	const float *p = h->rgb;
	CHECK(p[0] == 0 && p[1] == 0 && p[2] == 0);
	CHECK(p[3] == 0 && p[4] == 0 && p[5] == 0);
	CHECK(p[6] == 0 && p[7] == 0 && p[8] > 0.05f);                    /* dark blue */
	CHECK(p[9] == 1 && p[10] > 0.6f && p[10] < 0.75f && p[11] < 1e-6f);  /* yellow */
	CHECK(p[12] == 1 && p[13] == 1 && p[14] == 1);
	CHECK(p[15] == 1 && p[16] == 1 && p[17] == 1);
	image_free(h);
	struct image *c = image_new(1, N);
	CHECK(imgdiff_heatmap(a, c) == NULL);
	image_free(a);
	image_free(b);
	image_free(c);
}

int main(void)
{
	test_metrics();
	test_boundary();
	test_nonfinite();
	test_downsample();
	test_heatmap();
	return check_result();
}
