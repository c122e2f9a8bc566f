/* pov_texture.h: a material's pattern, image map and bump pattern in POV-Ray's words
 * (pov_texture.c), for the materials' recipes (pov_material.c). */
#ifndef SCN_POV_TEXTURE_H
#define SCN_POV_TEXTURE_H

#include <stdio.h>

#include "scene.h"

/* "pigment { ... }" of pattern pt with its colour map's colours divided by div, each with
 * transmit t. */
void pov_pattern_pigment(FILE *f, const struct pattern *pt, double div, double t);
/* "pigment { ... image_map { ... } }" of im, every texel with transmit t (its colours
 * are not divided: the finish's diffuse does that). The image file named relative to
 * pov_dir as pov_image_reference does. */
void pov_image_pigment(FILE *f, const struct scene *sc, const struct image_map *im, double t, const char *pov_dir);
/* The file image img of sc was read from (as lowering named it). */
const char *pov_image_path(const struct scene *sc, const struct image *img);
/* " normal { ... }" of bump pattern pt. */
void pov_bump_normal(FILE *f, const struct pattern *pt);
/* The path of an image file as the .pov must name it: relative to pov_dir when both
 * resolve, else (or with pov_dir NULL) absolute. The caller frees it. */
char *pov_image_reference(const char *image, const char *pov_dir);
/* An image_map's file: its format's keyword, its name (pov_image_reference) and the
 * decoding (" gamma ...") that makes POV-Ray read it as image_read did (src). */
void pov_image_file(FILE *f, const struct image_source *src, const char *path, const char *pov_dir);

#endif
