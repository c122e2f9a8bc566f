/* light.h: what a light gives beyond a point light's colour (LANGUAGE.md section 12,
 * povray-equivalence.md section 15): POV-Ray's spotlight factor and fade, and the test
 * points of an area light and their weights. */
#ifndef SCN_LIGHT_H
#define SCN_LIGHT_H

#include "bvh.h"
#include "scene.h"

/* The spotlight factor of li for unit l from the lit point towards the light. */
double light_spot(const struct light *li, struct vec3 l);

/* POV-Ray's fade 2 / (1 + (dist / D)^P) of li (fade_power > 0). */
double light_fade(const struct light *li, double dist);

/* POV-Ray's weights for n test points along an area light's axis (w[0 .. n-1], summing
 * to 1): the average of a span's two ends, recursively split at its middle while it holds
 * more than two points. */
void light_area_weights(int n, double *w);

/* The axes a's grid spans as seen from a lit point in unit direction l from it towards
 * the light: its own, or with orient turned square to l, both as long as the first. */
void light_area_axes(const struct area_light *a, struct vec3 l, struct vec3 axes[2]);

/* The offset from the light's position of the test point at grid coordinates (u, v):
 * whole numbers for the grid, plus an offset in (-0.5, 0.5) when jittered. */
struct vec3 light_area_offset(const struct area_light *a, const struct vec3 axes[2], double u, double v);

/* The convex region (a pyramid from apex to the light's extent, jitter included, and the
 * light's plane) that holds every shadow test of a from apex, with axes as
 * light_area_axes gives them: widened by margin, which must cover the distance the tests'
 * origins move off apex; its planes are the four sides, then (plane 4) the light's. And
 * the extent's corners. False when the light is a line or a point, whose region would not
 * be bounded. */
bool light_area_region(const struct area_light *a, const struct vec3 axes[2], struct vec3 centre, struct vec3 apex,
                       double margin, struct bvh_region *region, struct vec3 corner[4]);

#endif
