/* trace.h: the Whitted integrator: the colour a ray sees. */
#ifndef SCN_TRACE_H
#define SCN_TRACE_H

#include <stdint.h>

#include "scene.h"
#include "shape.h"
#include "stream.h"

/* Rays by kind and values that were not finite: counted per thread, summed at the end. */
struct ray_stats {
	uint64_t camera, shadow, reflection, refraction;
	uint64_t area_shadow;          /* shadow rays to area lights' test points, apart */
	uint64_t area_settled;         /* area lights' tests settled without a ray: nothing in
	                                * the way of any of a point's tests */
	uint64_t patterns, images, bumps; /* lookups of colour patterns, image maps, bump patterns */
	uint64_t nonfinite;            /* radiance samples that were NaN or infinite (must stay 0) */
	uint64_t probe_pixels;         /* pixels rendered twice to estimate the error (render.c) */
	uint64_t probe_camera;         /* the camera rays of their second replica, not in camera */
	double probe_sum;              /* over the probe pixels, the squared difference of their two
	                                * replicas, summed in tile order (render.c) */
	double estimated_rmse;         /* of the image (render_image): sqrt(probe_sum / (6
	                                * probe_pixels)); < 0 for grid and center */
};

/* Adds from's counts to to's (probe_sum and estimated_rmse stay to's). */
void trace_stats_add(struct ray_stats *to, const struct ray_stats *from);

/* Where a ray stands in its camera sample's tree of rays: its depth (a camera ray's is
 * 1), the solids it is inside (0 for a camera ray: they start outside every one), and the
 * key of its branch, under which its hits draw their area lights' numbers. */
struct path {
	int depth, inside;
	uint64_t key;
};

/* A camera ray's path. */
static inline struct path trace_camera_path(void)
{
	return (struct path){ 1, 0, 1 };
}

/* The colour seen along r (unit direction) by a ray at path, of the camera sample whose
 * numbers ss gives, per LANGUAGE.md's shading model. */
struct vec3 trace_ray(const struct scene *sc, const struct ray *r, struct path path, const struct sample_stream *ss,
                      struct ray_stats *st);

/* What a ray that hits nothing sees in direction d (unit). */
struct vec3 trace_sky(const struct sky *sky, struct vec3 d);

#endif
