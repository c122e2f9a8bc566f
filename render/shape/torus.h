/* torus.h: ray and torus (placeholder until the quartic solver lands). */
#ifndef SCN_TORUS_H
#define SCN_TORUS_H

#include <stdbool.h>

#include "vec.h"

int torus_roots(double major, double minor, struct vec3 o, struct vec3 d, double tmax, double t[4]);
void torus_surface(double major, double minor, struct vec3 p, struct vec3 *on, struct vec3 *p_err, struct vec3 *normal);
bool torus_inside(double major, double minor, struct vec3 p);

#endif
