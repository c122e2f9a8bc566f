/* part_make.h: leaf parts (part.h) from the shapes as LANGUAGE.md section 9 writes them,
 * in the object's own space, placed in the world by x. Each sets the kind, the canonical
 * numbers, the maps and the bounds, and leaves inverse and surface to the caller; false
 * when the shape's map cannot be inverted in double (too small or too large a scale to
 * compute with). The arguments are valid (evaluation checked them). */
#ifndef SCN_PART_MAKE_H
#define SCN_PART_MAKE_H

#include "part.h"

bool part_make_sphere(struct part *p, struct vec3 center, double radius, const struct affine *x);
bool part_make_box(struct part *p, struct vec3 c0, struct vec3 c1, const struct affine *x);
bool part_make_cone(struct part *p, struct vec3 base, double r0, struct vec3 cap, double r1, bool open,
                    const struct affine *x);
bool part_make_disc(struct part *p, struct vec3 center, struct vec3 normal, double radius, double hole,
                    const struct affine *x);
bool part_make_torus(struct part *p, double major, double minor, const struct affine *x);
bool part_make_plane(struct part *p, struct vec3 normal, double offset, const struct affine *x);

#endif
