/* povray.h: POV-Ray as a child process, for scn converge: found on PATH, run in a private
 * temporary folder with the command line of povray-equivalence.md section 1, timed whole
 * (its start-up included), its 16-bit linear PNG read back. */
#ifndef SCN_POVRAY_H
#define SCN_POVRAY_H

#include <stdbool.h>
#include <stddef.h>

#include "image.h"

struct povray {
	char *path;                    /* the povray executable */
	char *dir;                     /* a new temporary folder for the scene, images and logs */
};

/* Finds povray on PATH and makes the folder (under $TMPDIR, else /tmp). Returns false
 * with the reason in err, pv then needing no povray_close. */
bool povray_open(struct povray *pv, char *err, size_t errlen);

/* The path of the file named name in pv's folder; malloc'd. The file is removed by
 * povray_close, or by a signal before that (cleanup.h). */
char *povray_file(const struct povray *pv, const char *name);

struct povray_render {
	double seconds;                /* wall time of the whole process, from fork to exit */
	double trace;                  /* POV-Ray's own Trace Time, or -1 when it did not say */
	struct image *img;             /* the render, linear; the caller frees it with image_free */
};

/* Renders the scene pov_name of pv's folder at width x height with the anti-aliasing
 * options aa (words separated by spaces: "-A", "+A0.0 +AM2 +R3 -J") on threads threads.
 * Returns 0, or -1 with the reason in err (the last lines of POV-Ray's output go to
 * standard error). */
int povray_render(const struct povray *pv, const char *pov_name, const char *aa, int width, int height,
                  int threads, struct povray_render *out, char *err, size_t errlen);

/* Removes pv's folder with everything in it, and frees pv's strings. */
void povray_close(struct povray *pv);

#endif
