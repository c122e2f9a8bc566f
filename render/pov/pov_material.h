/* pov_material.h: the POV-Ray declaration of one scn material (pov_material.c). */
#ifndef SCN_POV_MATERIAL_H
#define SCN_POV_MATERIAL_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "scene.h"

/* A comment with sc's material index as scn has it, then "#declare scn_material_<index> =
 * material { ... }"; with shared, when it has an interior, also "scn_material_<index>_shared",
 * the same without its interior, for the members of a solid whose CSG holds the interior
 * (pov_solid.c); with listed, also "scn_texture_<index>", its layered texture alone, for a
 * mesh2's texture_list (which takes textures, not materials: the mesh2 holds the interior).
 * Image files are named relative to pov_dir (pov_image_reference). */
void pov_write_material(FILE *f, const struct scene *sc, size_t index, bool shared, bool listed, const char *pov_dir);
/* Whether POV-Ray's twin of m has an interior (m transmits, or reflects by Fresnel, whose
 * weight POV-Ray takes from the interior's ior), and *ior the ior written in it. */
bool pov_material_interior(const struct material *m, double *ior);
/* "material { scn_material_<index> ... }" for a surface of sc, in world space: a textured
 * material is moved into the surface's pattern space (surface.to_object). Written after an
 * object's own transforms, it is not moved by them. With shared, a material with an
 * interior is named by its _shared declaration. */
void pov_material_ref(FILE *f, const struct scene *sc, uint32_t surface, bool shared);
/* "texture { scn_texture_<index> ... }" for a surface of sc in a mesh2's texture_list: with
 * world, a textured material moved into the surface's pattern space as pov_material_ref
 * does; without, as it is (a mesh2 in a file's own space, which its placement moves). */
void pov_texture_ref(FILE *f, const struct scene *sc, uint32_t surface, bool world);

#endif
