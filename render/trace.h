/* trace.h: the Whitted integrator: the colour a ray sees. */
#ifndef SCN_TRACE_H
#define SCN_TRACE_H

#include <stdint.h>

#include "scene.h"
#include "shape.h"

/* Rays by kind and values that were not finite: counted per thread, summed at the end. */
struct ray_stats {
	uint64_t camera, shadow, reflection, refraction;
	uint64_t patterns, images, bumps; /* lookups of colour patterns, image maps, bump patterns */
	uint64_t nonfinite;            /* radiance samples that were NaN or infinite (must stay 0) */
	uint64_t probe_pixels;         /* pixels rendered twice to estimate the error (render.c) */
	uint64_t probe_camera;         /* the camera rays of their second replica, not in camera */
	double estimated_rmse;         /* of the image (render_image); < 0 for grid and center */
};

/* The colour seen along r (unit direction) by a ray of the given depth (a camera ray
 * has depth 1) inside `inside` solids (0 for a camera ray: they start outside every one),
 * per LANGUAGE.md's shading model. */
struct vec3 trace_ray(const struct scene *sc, const struct ray *r, int depth, int inside, struct ray_stats *st);

/* What a ray that hits nothing sees in direction d (unit). */
struct vec3 trace_sky(const struct sky *sky, struct vec3 d);

#endif
