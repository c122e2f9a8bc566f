/* torus.h: ray and torus in the torus's own space, robust for thin, far and grazing cases
 * (NUMERICS.md, LANGUAGE.md section 9). The torus lies around the y axis through the
 * origin, major radius R, minor radius r, 0 < r < R. */
#ifndef SCN_TORUS_H
#define SCN_TORUS_H

#include <stdbool.h>

#include "vec.h"

/* The t in (0, tmax) where o + t d meets the torus, ascending, at most 4; returns how many.
 * d need not be a unit vector (the caller passes a ray mapped into object space by an
 * affine map, so t is the world ray's parameter). A root is reported only when it is
 * positive beyond its own error bound, so that a ray leaving the surface from an origin
 * already offset by the hit point's error bound does not hit it again at t ~ 0. A ray
 * tangent to the tube within rounding gives a close pair of roots or none. */
int torus_roots(double major, double minor, struct vec3 o, struct vec3 d, double tmax, double t[4]);
/* The smallest t in (t_after, tmax) of torus_roots()'s (the same roots, by the same
 * rule), in *t; false when there is none. Cheaper: the ray's pieces are solved in order
 * and the search stops at the first that has one, skipping those wholly before t_after. */
bool torus_first(double major, double minor, struct vec3 o, struct vec3 d, double t_after, double tmax, double *t);
/* The point of the torus nearest p (p is a hit point computed as o + t d), its outward
 * unit normal, and a bound on the absolute error of each coordinate of the returned point
 * (pbrt's pError, as sphere_surface's). */
void torus_surface(double major, double minor, struct vec3 p, struct vec3 *on, struct vec3 *p_err,
		   struct vec3 *normal);
/* Whether p lies strictly inside the solid torus: the exact sign of (|p|^2 + R^2 - r^2)^2
 * - 4 R^2 (x^2 + z^2), from a stable form when its error bound decides it and in exact
 * arithmetic otherwise. */
bool torus_inside(double major, double minor, struct vec3 p);

#endif
