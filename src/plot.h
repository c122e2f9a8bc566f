/* plot.h: a log-log line plot written as a standalone SVG file, for scn converge: one
 * polyline with markers per series, decade grid lines, axis labels and a legend. */
#ifndef SCN_PLOT_H
#define SCN_PLOT_H

#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>

struct plot_series {
	const char *name;              /* the legend's text */
	const char *color;             /* an SVG colour such as "#1f77b4" */
	bool dashed;                   /* a dashed line */
	bool squares;                  /* square markers instead of round ones */
	size_t n;
	const double *x, *y;           /* the points, joined in this order; a point whose x or
	                                  y is not a positive finite number is left out */
};

struct plot {
	const char *title;             /* above the plot, or NULL */
	const char *subtitle;          /* a smaller second line, or NULL */
	const char *xlabel, *ylabel;
	size_t nseries;
	const struct plot_series *series;
};

/* Writes p to out as an SVG document. Text is escaped for XML. Returns 0, or EIO when
 * out reports an error. */
int plot_svg(const struct plot *p, FILE *out);

#endif
