/* imgdiff.c: the error between two images in linear light, box downsampling, and the
 * heatmap of where they differ. */
#include "imgdiff.h"

#include <math.h>
#include <stddef.h>

/* The error of one channel: see struct imgdiff_stats. */
static double channel_error(float a, float b)
{
	if (a == b || (isnan(a) && isnan(b)))
		return 0;
	double d = fabs((double)a - (double)b);   /* exact for floats of like magnitude */
	return isnan(d) ? INFINITY : d;
}

bool imgdiff_compare(const struct image *a, const struct image *b, struct imgdiff_stats *out)
{
	if (a->width != b->width || a->height != b->height)
		return false;
	*out = (struct imgdiff_stats){ .width = a->width, .height = a->height };
	const double off1 = 1.0 / 255 + IMGDIFF_OFF_SLACK, off2 = 2.0 / 255 + IMGDIFF_OFF_SLACK;
	double sum = 0, sum2 = 0, signed_sum = 0;
	for (int y = 0; y < a->height; y++) {
		/* sums per row, then over rows: less rounding than one running sum of 10^8 terms */
		double row = 0, row2 = 0, row_signed = 0;
		size_t base = (size_t)y * (size_t)a->width * 3;
		for (int x = 0; x < a->width; x++) {
			double worst = 0;
			for (int c = 0; c < 3; c++) {
				size_t i = base + 3 * (size_t)x + (size_t)c;
				double d = channel_error(a->rgb[i], b->rgb[i]);
				row += d;
				row2 += d * d;
				double sd = (double)a->rgb[i] - (double)b->rgb[i];
				if (isfinite(sd))
					row_signed += sd;
				if (d > worst)
					worst = d;
			}
			if (worst > out->max) {
				out->max = worst;
				out->max_x = x;
				out->max_y = y;
			}
			out->off1 += worst > off1;
			out->off2 += worst > off2;
		}
		sum += row;
		sum2 += row2;
		signed_sum += row_signed;
	}
	out->pixels = (int64_t)a->width * a->height;
	double n = 3.0 * (double)out->pixels;
	out->mean = sum / n;
	out->bias = signed_sum / n;
	out->rmse = sqrt(sum2 / n);
	out->psnr = out->rmse > 0 ? 20 * log10(1 / out->rmse) : INFINITY;
	return true;
}

struct image *imgdiff_downsample(const struct image *img, int n)
{
	if (n < 1 || img->width % n != 0 || img->height % n != 0)
		return NULL;
	struct image *out = image_new(img->width / n, img->height / n);
	double scale = 1.0 / ((double)n * n);
	for (int y = 0; y < out->height; y++)
		for (int x = 0; x < out->width; x++)
			for (int c = 0; c < 3; c++) {
				double s = 0;
				for (int j = 0; j < n; j++) {
					const float *src = img->rgb + ((size_t)(n * y + j) * (size_t)img->width +
					                               (size_t)n * (size_t)x) * 3 + c;
					for (int i = 0; i < n; i++)
						s += src[3 * i];
				}
				out->rgb[((size_t)y * (size_t)out->width + (size_t)x) * 3 + c] = (float)(s * scale);
			}
	return out;
}

/* The ramp's stops, evenly spaced on the log scale, as display (sRGB-encoded) colours:
 * dark blue, blue, yellow, white. Brightness rises all the way, so the picture also
 * reads in grey. */
static const float ramp[][3] = {
	{ 0.00f, 0.00f, 0.30f },
	{ 0.10f, 0.35f, 1.00f },
	{ 1.00f, 0.85f, 0.00f },
	{ 1.00f, 1.00f, 1.00f },
};
enum { RAMP_STOPS = sizeof ramp / sizeof ramp[0] };

/* The linear colour for a pixel's largest channel error e. */
static void heat_colour(double e, float *rgb)
{
	if (!(e >= ldexp(1, IMGDIFF_HEAT_BLACK))) {   /* also NaN, which channel_error never gives */
		rgb[0] = rgb[1] = rgb[2] = 0;
		return;
	}
	double t = (log2(e) - IMGDIFF_HEAT_LO) / (IMGDIFF_HEAT_HI - IMGDIFF_HEAT_LO);
	t = t < 0 ? 0 : t > 1 ? 1 : t;
	double pos = t * (RAMP_STOPS - 1);
	int k = pos >= RAMP_STOPS - 1 ? RAMP_STOPS - 2 : (int)pos;
	double f = pos - k;
	for (int c = 0; c < 3; c++)
		rgb[c] = (float)image_srgb_decode((1 - f) * ramp[k][c] + f * ramp[k + 1][c]);
}

struct image *imgdiff_heatmap(const struct image *a, const struct image *b)
{
	if (a->width != b->width || a->height != b->height)
		return NULL;
	struct image *out = image_new(a->width, a->height);
	size_t n = (size_t)a->width * (size_t)a->height;
	for (size_t p = 0; p < n; p++) {
		double worst = 0;
		for (int c = 0; c < 3; c++) {
			double d = channel_error(a->rgb[3 * p + c], b->rgb[3 * p + c]);
			if (d > worst)
				worst = d;
		}
		heat_colour(worst, out->rgb + 3 * p);
	}
	return out;
}
