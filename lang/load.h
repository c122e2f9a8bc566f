/* load.h: the front end end to end, for the scn command. */
#ifndef SCN_LOAD_H
#define SCN_LOAD_H

#include "diag.h"
#include "eval.h"
#include "scene_desc.h"

/* LOAD_TOO_BIG: the scene needs more memory than the machine has (lower_scene). */
enum load_status { LOAD_OK = 0, LOAD_SCENE_ERROR = 1, LOAD_IO_ERROR = 3, LOAD_TOO_BIG = 4 };

struct load_times {
	double parse, check, eval;     /* seconds; parse includes reading the file */
	struct eval_counts evaluated;  /* of the evaluation that gave the scene */
};

/* The moment of an animation a scene is evaluated at: the values of clock and frame. */
struct load_frame {
	double clock;
	long frame;
};

/* Reads the scene at path ("-": standard input), with its includes, and evaluates it into
 * out (always initialised; scene_desc_free it) at the moment at (NULL: clock 0, frame 0).
 * Diagnostics go to d. The status doubles as the command's exit status. times may be NULL. */
enum load_status load_scene(struct diag *d, const char *path, const struct load_frame *at,
                            struct scene_desc *out, struct load_times *times);

#endif
