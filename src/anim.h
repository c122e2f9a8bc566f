/* anim.h: animation on the command line (LANGUAGE.md section 13): the values of --clock
 * and --frames, each frame's clock and file name, and the progress bar over frames. */
#ifndef SCN_ANIM_H
#define SCN_ANIM_H

#include <stdbool.h>
#include <stddef.h>

struct command;

/* The frames of --frames A..B: A, A+1, ..., B-1. */
struct anim_frames {
	long first, end;               /* A and B */
	bool cyclic;                   /* --cyclic: clock 1 would be frame B, which is frame A again */
};

/* The bounds of A and B, so that every frame number and difference is exact in a double. */
#define ANIM_MAX_FRAME 1000000000L

/* Reads the value v of the option name (--clock): a finite number in strtod's syntax,
 * nothing around it. Returns 0, or EXIT_USAGE after a usage message for cmd. */
int anim_clock_arg(const struct command *cmd, const char *name, const char *v, double *out);
/* Reads the value v of the option name (--frames): A..B, whole numbers with A < B.
 * Returns 0, or EXIT_USAGE after a usage message for cmd; cyclic is left false. */
int anim_frames_arg(const struct command *cmd, const char *name, const char *v, struct anim_frames *out);

/* The clock of frame k: 0 at the first frame, 1 at the last, evenly between, computed in
 * one division so that --clock with the same number (anim_clock_text) gives the same
 * scene; with cyclic, 1 would be at frame B. A single frame has clock 0. */
double anim_clock(const struct anim_frames *f, long k);
/* The shortest decimal that reads back as c (at most 17 digits), into buf. */
void anim_clock_text(double c, char *buf, size_t size);

/* The file names of the frames: head, the frame number (printf's %0*ld with width, one
 * more for a negative number when sign_extra), tail. */
struct anim_names {
	char *head, *tail;             /* malloc'd */
	int width;
	bool sign_extra;               /* the '-' comes before width digits, not among them */
};

/* The names for the frames f from out. A template (what -o gives) holds at most one %d
 * or %0Nd for the frame number and writes a '%' as %%. Without a conversion, and always
 * when out is not a template (the default name), the number goes before the extension,
 * zero-padded to the digits of the frame farthest from 0 (POV-Ray's naming: the width of
 * B-1), with a '-' before the digits of a negative one. Returns 0, or EXIT_USAGE after a
 * usage message for cmd about a bad template. */
int anim_names_init(struct anim_names *n, const struct command *cmd, const char *out, bool is_template,
                    const struct anim_frames *f);
/* Frame k's file name; malloc'd. */
char *anim_name(const struct anim_names *n, long k);
void anim_names_free(struct anim_names *n);

/* The progress bar over the frames on standard error: "[####......] 4/10 frames  ETA 12s",
 * shown while a frame renders and erased before anything else is printed. */
struct anim_bar {
	long done, total;              /* frames */
	double t0;                     /* when the first frame started */
	int shown;                     /* the characters on the line now; 0: none */
};

void anim_bar_init(struct anim_bar *b, long total);
void anim_bar_show(struct anim_bar *b);
void anim_bar_erase(struct anim_bar *b);

#endif
