/* shade.h: what a material gives at a hit besides its constants: k_d from its pigment
 * (a colour, a checker, a pattern through its colour map, an image map) and the shading
 * normal perturbed by its bump pattern, each in the object's own space (LANGUAGE.md
 * section 11). Nothing here runs for a material without texture. */
#ifndef SCN_SHADE_H
#define SCN_SHADE_H

#include "scene.h"
#include "shape.h"

/* k_d at the hit h (surface sp) of a primitive made of srf, whose material is m. */
struct vec3 shade_diffuse(const struct scene *sc, const struct surface *srf, const struct material *m,
                          const struct hit *h, const struct surface_point *sp);
/* The unit shading normal ns at p perturbed by m's bump pattern (m->bump >= 0). */
struct vec3 shade_bump(const struct scene *sc, const struct surface *srf, const struct material *m, struct vec3 p,
                       struct vec3 ns);

#endif
