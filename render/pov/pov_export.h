/* pov_export.h: the POV-Ray 3.7 back end: writes a lowered scene as POV-Ray SDL that
 * computes scn's model (LANGUAGE.md "Shading") with the recipes of
 * doc/povray.md, headed by the povray command line that renders it. */
#ifndef SCN_POV_EXPORT_H
#define SCN_POV_EXPORT_H

#include <stddef.h>
#include <stdio.h>

#include "scene.h"

struct pov_export_options {
	const char *pov_name;          /* the .pov file's name for the command line's +I (its base
	                                  name: the command runs in the file's folder) */
	const char *source;            /* the scene's file name, for a comment, or NULL */
	const char *generator;         /* "scn VERSION", for a comment, or NULL */
	/* SKY_LATLONG: the image the scene was lowered from, as a path valid from the
	 * current directory (it is read again to tell its format and transfer curve),
	 * and the folder the .pov goes to ("": the current directory): the .pov names the
	 * image relative to that folder, or by its absolute path when pov_dir is NULL. */
	const char *sky_image;
	const char *pov_dir;
	/* The camera as the scene gave it, when known (else NULL and 0): POV-Ray then frames
	 * it from the same numbers as scn (look_at and up; fov, the horizontal angle in
	 * degrees), instead of from the lowered frame. */
	const double *look_at, *up;
	double fov;
	const double *sky_rotate;      /* SKY_LATLONG: the rotation in degrees, when known */
	/* Every area_light's adaptive level plus one: 0 (the default, so that an initialiser
	 * that leaves it out means it) writes no adaptive keyword, POV-Ray's full subdivision
	 * that scn computes; K + 1 writes "adaptive K" (scn converge, to time POV-Ray at each
	 * level). */
	int area_adaptive;
};

/* Writes sc to out. Returns 0, or an errno code with a message in err (a write error,
 * or the sky image cannot be read again). */
int pov_export(const struct scene *sc, const struct pov_export_options *opt, FILE *out, char *err,
               size_t errlen);

/* Writes sc to path as pov_export does, through a temporary file in path's folder that
 * is renamed over path, so that a failure leaves neither a partial file nor a damaged
 * older one. Returns 0 or an errno code with a message naming path in err. */
int pov_export_file(const struct scene *sc, const struct pov_export_options *opt, const char *path, char *err,
                    size_t errlen);

#endif
