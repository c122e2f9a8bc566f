/* pov_material.h: the POV-Ray declaration of one scn material (pov_material.c). */
#ifndef SCN_POV_MATERIAL_H
#define SCN_POV_MATERIAL_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "scene.h"

/* A comment with the material as scn has it, then "#declare scn_material_<index> =
 * material { ... }". */
void pov_write_material(FILE *f, size_t index, const struct material *m);
/* "material { scn_material_<index> ... }" for a surface of sc, in world space: a checker
 * is moved into the surface's pattern space (surface.to_object). Written after an
 * object's own transforms, it is not moved by them. */
void pov_material_ref(FILE *f, const struct scene *sc, uint32_t surface);

#endif
