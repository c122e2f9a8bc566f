/* pov_write.h: POV-Ray SDL spellings of numbers, vectors and strings (pov_write.c), for
 * the exporter's parts. */
#ifndef SCN_POV_WRITE_H
#define SCN_POV_WRITE_H

#include <stdio.h>

#include "affine.h"
#include "vec.h"

/* The shortest decimal that reads back as v exactly. */
void pov_num(FILE *f, double v);
/* <x, y, z>, each as pov_num writes it. */
void pov_vec(FILE *f, struct vec3 v);
/* <x,y,z> in single precision, as mesh2 stores it. */
void pov_fvec(FILE *f, struct vec3 v);
/* A colour with a fourth channel (filter or transmit). */
void pov_vec4(FILE *f, struct vec3 v, double w);
/* A string literal, escaped. */
void pov_str(FILE *f, const char *s);
/* s on one comment line: line breaks become spaces. */
void pov_comment_text(FILE *f, const char *s);
/* "matrix <...>" of an affine map, each number as pov_num writes it. */
void pov_matrix(FILE *f, const struct affine *a);

#endif
