/* dist.h: scn render over the processes of an MPI launcher (LANGUAGE.md section 13): the
 * tiles of one image from a queue that process 0 keeps, or whole frames of an animation;
 * process 0 gathers the linear pixels and writes every file. scn itself has no MPI
 * (dist_none.c): under a launcher it becomes scn-mpi (dist_mpi.c), which has, so that a
 * plain scn render does not load MPI's libraries. */
#ifndef SCN_DIST_H
#define SCN_DIST_H

#include <stdbool.h>

#include "image.h"
#include "render.h"

/* This process's place among the processes of the run: rank 0 of 1 outside a launcher. */
struct dist_world {
	int rank, size;
	char host[64];                 /* this machine's name, for messages (under a launcher) */
};

/* Starts the run of `scn render`. Outside a launcher: a world of one, and MPI is not
 * touched. Under one (Open MPI's mpirun, Slurm's srun): scn execs scn-mpi (next to scn,
 * or in PKGLIBEXECDIR) with argv, the NULL-terminated argument vector for it ("scn-mpi",
 * "render", the options), and scn-mpi starts MPI. Returns 0, or an exit status after a message (an MPI
 * launcher but no scn-mpi). */
int dist_start(char **argv, struct dist_world *w);

/* Ends the run with exit status status (MPI_Finalize), after every process's last
 * message; a no-op for a world of one. */
void dist_end(const struct dist_world *w);

/* After each process has loaded and lowered the scene on its own: every process passes
 * its exit status and, when that is not 0, its messages. Returns the status of the first
 * process that failed, or 0. Process 0 prints the messages of the others that failed
 * when it did not fail itself (the scene is the same, so its own say it otherwise). */
int dist_agree(const struct dist_world *w, int status, const char *messages);

/* What process 0 received of one image from the others (--stats). */
struct dist_traffic {
	long tiles, messages;          /* tiles rendered by the others, and the messages they came in */
	double bytes;                  /* of those messages */
	double gather_s;               /* process 0's time receiving them and copying them into place */
};

/* Renders opt's rectangle over every process, each with opt->threads threads, tiles
 * handed out by process 0 a few at a time as each process asks. On process 0, img (the
 * rectangle's size) gets every pixel, *st the ray counts of all and the error estimate,
 * and *traffic what came from the others; opt->progress shows one bar. On the others
 * img is NULL and *st their own counts. Returns 0, or -1 when this process could not
 * start its threads (process 0 then says so, or the run is aborted). */
int dist_render_image(const struct dist_world *w, const struct scene *sc, const struct render_options *opt,
                      struct image *img, struct ray_stats *st, struct dist_traffic *traffic);

/* A frame's outcome, from whichever process rendered it, for process 0 to report. */
struct dist_frame {
	long k;                        /* the frame's number */
	int status;                    /* its exit status: 0, or EXIT_* */
	char *messages;                /* its diagnostics, printed before its outcome; or NULL */
	char *stats;                   /* --stats, with DIST_WRITE_MARK where process 0's time
	                                * to write the file goes; or NULL */
	struct image *img;             /* the linear image; NULL unless status is 0 */
	double render_s, rmse;         /* render time; estimated RMSE (< 0: none) */
	int samples;                   /* per pixel */
};
#define DIST_WRITE_MARK "\x01"

/* Frees f's messages, stats and image. */
void dist_frame_free(struct dist_frame *f);

/* Frames [first, end), whole frames per process, handed out by process 0 one at a time
 * as each process asks. render(ctx, k, out) renders frame k into *out (on its own
 * thread on process 0, which serves the queue meanwhile); on process 0, deliver(ctx, f)
 * reports and writes each frame as it arrives, in whatever order, and returns its
 * status; f is freed after (dist_frame_free). Once a frame fails no other is handed out.
 * Returns the first failure's status, or 0; *failed gets the failed frame (or -1) and
 * *written the frames written. */
struct dist_frames {
	long first, end;
	int (*render)(void *ctx, long k, struct dist_frame *out);
	int (*deliver)(void *ctx, struct dist_frame *f);
	void *ctx;
};
int dist_render_frames(const struct dist_world *w, const struct dist_frames *job, long *failed, long *written);

#endif
