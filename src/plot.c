/* plot.c: a log-log line plot as plain SVG: fixed page layout, the axes fitted to the
 * points with a margin, grid lines at 1..9 x 10^k and labels at 1, 2 and 5 x 10^k (or
 * every decade when the axis spans many, or every line when it spans less than one). */
#include "plot.h"

#include <errno.h>
#include <math.h>

enum {
	PAGE_W = 860, PAGE_H = 560,
	LEFT = 90, RIGHT = 610, TOP = 70, BOTTOM = 490,   /* the plot area */
	LEGEND_X = 630, LEGEND_W = 215, LEGEND_ROW = 22,
};

/* The narrowest axis, in decades: enough for two labelled grid lines anywhere. */
#define MIN_SPAN 0.5

static bool usable(double v)
{
	return isfinite(v) && v > 0;
}

static void escaped(FILE *out, const char *s)
{
	for (; *s; s++) {
		switch (*s) {
		case '&': fputs("&amp;", out); break;
		case '<': fputs("&lt;", out); break;
		case '>': fputs("&gt;", out); break;
		case '"': fputs("&quot;", out); break;
		default:
			/* control characters are not allowed in XML 1.0 */
			fputc((unsigned char)*s < 0x20 ? ' ' : *s, out);
		}
	}
}

struct axis {
	double lo, hi;                 /* log10 of the ends */
};

/* The range of the usable x (or y) values of every series, widened by a margin. */
static struct axis fit_axis(const struct plot *p, bool x)
{
	double lo = INFINITY, hi = -INFINITY;
	for (size_t s = 0; s < p->nseries; s++) {
		const struct plot_series *sr = &p->series[s];
		for (size_t i = 0; i < sr->n; i++) {
			if (!usable(sr->x[i]) || !usable(sr->y[i]))
				continue;
			double v = log10(x ? sr->x[i] : sr->y[i]);
			lo = fmin(lo, v);
			hi = fmax(hi, v);
		}
	}
	if (lo > hi)
		lo = -1, hi = 0;
	double pad = fmax(0.06 * (hi - lo), 0.05);
	lo -= pad, hi += pad;
	if (hi - lo < MIN_SPAN) {
		double mid = (lo + hi) / 2;
		lo = mid - MIN_SPAN / 2, hi = mid + MIN_SPAN / 2;
	}
	return (struct axis){ lo, hi };
}

/* Position of log10 value v along an axis drawn from a to b. */
static double place(const struct axis *ax, double v, double a, double b)
{
	return a + (v - ax->lo) / (ax->hi - ax->lo) * (b - a);
}

/* Grid lines and tick labels of one axis. */
static void draw_ticks(FILE *out, const struct axis *ax, bool x)
{
	double span = ax->hi - ax->lo;
	for (int k = (int)floor(ax->lo); k <= (int)ceil(ax->hi); k++) {
		for (int m = 1; m <= 9; m++) {
			double lv = log10((double)m) + k;
			if (lv < ax->lo || lv > ax->hi)
				continue;
			bool label = m == 1 || (span < 2.5 && (m == 2 || m == 5)) || span < 1;
			if (!label && span > 6)
				continue;
			const char *stroke = m == 1 ? "#bbbbbb" : label ? "#dddddd" : "#eeeeee";
			if (x) {
				double px = place(ax, lv, LEFT, RIGHT);
				fprintf(out, "<line x1=\"%.1f\" y1=\"%d\" x2=\"%.1f\" y2=\"%d\" stroke=\"%s\"/>\n", px, TOP, px,
				        BOTTOM, stroke);
				if (label)
					fprintf(out, "<text x=\"%.1f\" y=\"%d\" text-anchor=\"middle\">%g</text>\n", px, BOTTOM + 18,
					        m * pow(10, k));
			} else {
				double py = place(ax, lv, BOTTOM, TOP);
				fprintf(out, "<line x1=\"%d\" y1=\"%.1f\" x2=\"%d\" y2=\"%.1f\" stroke=\"%s\"/>\n", LEFT, py, RIGHT,
				        py, stroke);
				if (label)
					fprintf(out, "<text x=\"%d\" y=\"%.1f\" text-anchor=\"end\">%g</text>\n", LEFT - 6, py + 4,
					        m * pow(10, k));
			}
		}
	}
}

static void marker(FILE *out, const struct plot_series *sr, double px, double py)
{
	if (sr->squares)
		fprintf(out, "<rect x=\"%.1f\" y=\"%.1f\" width=\"7\" height=\"7\" fill=\"%s\"/>\n", px - 3.5, py - 3.5,
		        sr->color);
	else
		fprintf(out, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"3.5\" fill=\"%s\"/>\n", px, py, sr->color);
}

static void line_style(FILE *out, const struct plot_series *sr)
{
	fprintf(out, " fill=\"none\" stroke=\"%s\" stroke-width=\"2\"%s", sr->color,
	        sr->dashed ? " stroke-dasharray=\"7 4\"" : "");
}

int plot_svg(const struct plot *p, FILE *out)
{
	struct axis ax = fit_axis(p, true), ay = fit_axis(p, false);
	fprintf(out,
	        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
	        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" viewBox=\"0 0 %d %d\""
	        " font-family=\"sans-serif\" font-size=\"13\">\n"
	        "<rect width=\"%d\" height=\"%d\" fill=\"white\"/>\n",
	        PAGE_W, PAGE_H, PAGE_W, PAGE_H, PAGE_W, PAGE_H);
	if (p->title) {
		fprintf(out, "<text x=\"%d\" y=\"26\" text-anchor=\"middle\" font-size=\"16\">", PAGE_W / 2);
		escaped(out, p->title);
		fputs("</text>\n", out);
	}
	if (p->subtitle) {
		fprintf(out, "<text x=\"%d\" y=\"46\" text-anchor=\"middle\" font-size=\"12\" fill=\"#444444\">", PAGE_W / 2);
		escaped(out, p->subtitle);
		fputs("</text>\n", out);
	}
	draw_ticks(out, &ax, true);
	draw_ticks(out, &ay, false);
	fprintf(out, "<rect x=\"%d\" y=\"%d\" width=\"%d\" height=\"%d\" fill=\"none\" stroke=\"black\"/>\n", LEFT, TOP,
	        RIGHT - LEFT, BOTTOM - TOP);
	fprintf(out, "<text x=\"%d\" y=\"%d\" text-anchor=\"middle\">", (LEFT + RIGHT) / 2, BOTTOM + 42);
	escaped(out, p->xlabel);
	fprintf(out, "</text>\n<text transform=\"translate(24,%d) rotate(-90)\" text-anchor=\"middle\">",
	        (TOP + BOTTOM) / 2);
	escaped(out, p->ylabel);
	fputs("</text>\n", out);

	for (size_t s = 0; s < p->nseries; s++) {
		const struct plot_series *sr = &p->series[s];
		fputs("<polyline points=\"", out);
		bool first = true;
		for (size_t i = 0; i < sr->n; i++) {
			if (!usable(sr->x[i]) || !usable(sr->y[i]))
				continue;
			fprintf(out, "%s%.1f,%.1f", first ? "" : " ", place(&ax, log10(sr->x[i]), LEFT, RIGHT),
			        place(&ay, log10(sr->y[i]), BOTTOM, TOP));
			first = false;
		}
		fputc('"', out);
		line_style(out, sr);
		fputs("/>\n", out);
		for (size_t i = 0; i < sr->n; i++)
			if (usable(sr->x[i]) && usable(sr->y[i]))
				marker(out, sr, place(&ax, log10(sr->x[i]), LEFT, RIGHT), place(&ay, log10(sr->y[i]), BOTTOM, TOP));
	}

	if (p->nseries > 0) {
		fprintf(out, "<rect x=\"%d\" y=\"%d\" width=\"%d\" height=\"%d\" fill=\"white\" stroke=\"#888888\"/>\n",
		        LEGEND_X, TOP, LEGEND_W, 12 + LEGEND_ROW * (int)p->nseries);
		for (size_t s = 0; s < p->nseries; s++) {
			const struct plot_series *sr = &p->series[s];
			int y = TOP + 6 + LEGEND_ROW / 2 + LEGEND_ROW * (int)s;
			fprintf(out, "<line x1=\"%d\" y1=\"%d\" x2=\"%d\" y2=\"%d\"", LEGEND_X + 10, y, LEGEND_X + 40, y);
			line_style(out, sr);
			fputs("/>\n", out);
			marker(out, sr, LEGEND_X + 25, y);
			fprintf(out, "<text x=\"%d\" y=\"%d\">", LEGEND_X + 48, y + 4);
			escaped(out, sr->name);
			fputs("</text>\n", out);
		}
	}
	fputs("</svg>\n", out);
	return ferror(out) ? EIO : 0;
}
