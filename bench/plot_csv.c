/* plot_csv.c: src/plot.c's log-log SVG plot from a text description on standard input,
 * for bench/run's scaling study. Lines: "title T", "subtitle T", "xlabel T", "ylabel T",
 * "series COLOR solid|dashed NAME", then that series' points as "X Y". */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "plot.h"
#include "xalloc.h"

enum { MAX_SERIES = 16, MAX_POINTS = 64 };

struct points {
	char name[128], color[32];
	double x[MAX_POINTS], y[MAX_POINTS];
};

/* The rest of line after its first word, without the newline. */
static char *rest(char *line)
{
	char *s = strchr(line, ' ');
	s = s ? s + 1 : line + strlen(line);
	s[strcspn(s, "\n")] = '\0';
	return xstrdup(s);
}

int main(void)
{
	static struct points pts[MAX_SERIES];
	struct plot_series series[MAX_SERIES];
	struct plot p = { 0 };
	char *text[4] = { NULL };
	static const char *const keys[4] = { "title ", "subtitle ", "xlabel ", "ylabel " };
	char line[512];
	size_t ns = 0;
	while (fgets(line, sizeof line, stdin)) {
		char style[16];
		double x, y;
		bool keyword = false;
		for (int k = 0; k < 4; k++)
			if (strncmp(line, keys[k], strlen(keys[k])) == 0) {
				free(text[k]);
				text[k] = rest(line);
				keyword = true;
			}
		if (keyword)
			continue;
		if (strncmp(line, "series ", 7) == 0 && ns < MAX_SERIES) {
			struct points *s = &pts[ns];
			int name_at = 0;
			if (sscanf(line + 7, "%31s %15s %n", s->color, style, &name_at) != 2 || !name_at)
				goto bad;
			snprintf(s->name, sizeof s->name, "%.*s", (int)strcspn(line + 7 + name_at, "\n"), line + 7 + name_at);
			series[ns] = (struct plot_series){ s->name, s->color, strcmp(style, "dashed") == 0, ns % 2 == 1, 0,
			                                   s->x, s->y };
			ns++;
		} else if (sscanf(line, "%lf %lf", &x, &y) == 2 && ns > 0 && series[ns - 1].n < MAX_POINTS) {
			struct plot_series *s = &series[ns - 1];
			pts[ns - 1].x[s->n] = x;
			pts[ns - 1].y[s->n] = y;
			s->n++;
		} else {
			goto bad;
		}
	}
	p = (struct plot){ text[0], text[1], text[2] ? text[2] : "", text[3] ? text[3] : "", ns, series };
	int rc = plot_svg(&p, stdout) == 0 ? 0 : 1;
	for (int k = 0; k < 4; k++)
		free(text[k]);
	return rc;
bad:
	fprintf(stderr, "plot_csv: cannot read: %s", line);
	return 2;
}
