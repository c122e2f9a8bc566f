/* render.h: the tile and thread loop that turns a lowered scene into an image. */
#ifndef SCN_RENDER_H
#define SCN_RENDER_H

#include <stdbool.h>

#include "image.h"
#include "scene.h"
#include "trace.h"

struct render_options {
	int threads;                   /* workers; 0: one per core */
	int x0, y0, x1, y1;            /* the pixel rectangle [x0, x1) x [y0, y1) to render */
	bool progress;                 /* a progress bar with an ETA on standard error */
};

/* Renders the rectangle of sc's camera image into img, whose size is the rectangle's;
 * the result depends on the scene and seed only, not on the thread count. Ray counts go
 * to st. Returns 0, or -1 when no thread could be started. */
int render_image(const struct scene *sc, const struct render_options *opt, struct image *img, struct ray_stats *st);

#endif
