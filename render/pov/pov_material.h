/* pov_material.h: the POV-Ray declaration of one scn material (pov_material.c). */
#ifndef SCN_POV_MATERIAL_H
#define SCN_POV_MATERIAL_H

#include <stddef.h>
#include <stdio.h>

#include "scene.h"

/* A comment with the material as scn has it, then "#declare scn_material_<index> =
 * material { ... }". */
void pov_write_material(FILE *f, size_t index, const struct material *m);

#endif
