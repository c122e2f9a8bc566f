/* dist_none.c: dist.h in scn, which has no MPI: outside a launcher a world of one; under
 * a launcher scn becomes scn-mpi, or refuses when this build has none. */
#include "config.h"

#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "dist.h"
#include "launch.h"

/* scn-mpi beside this program (the build tree, or an install moved as a whole), else
 * where `make install` put it. */
static void exec_scn_mpi(char **argv)
{
	char self[PATH_MAX];
	ssize_t n = readlink("/proc/self/exe", self, sizeof self - sizeof "/scn-mpi");
	if (n > 0) {
		self[n] = '\0';
		char *slash = strrchr(self, '/');
		if (slash) {
			strcpy(slash, "/scn-mpi");
			execv(self, argv);
		}
	}
	execv(PKGLIBEXECDIR "/scn-mpi", argv);
}

int dist_start(char **argv, struct dist_world *w)
{
	*w = (struct dist_world){ 0, 1, "" };
	const char *by = dist_launcher();
	if (!by)
		return 0;
	exec_scn_mpi(argv);
	/* still here: no scn-mpi. One process needs none. */
	const char *size = getenv("OMPI_COMM_WORLD_SIZE");
	if (!size)
		size = getenv("PMI_SIZE");
	if (size && strcmp(size, "1") == 0)
		return 0;
#ifdef HAVE_MPI
	fprintf(stderr, "scn: error: started by an MPI launcher (%s is set), but scn-mpi, which runs scn over MPI, is "
	        "missing beside scn and in " PKGLIBEXECDIR "\n", by);
#else
	fprintf(stderr, "scn: error: started by an MPI launcher (%s is set), but this scn was built without MPI; run it "
	        "without the launcher, or build it with MPI (apt-get install libopenmpi-dev, then configure)\n", by);
#endif
	return 2;
}

void dist_end(const struct dist_world *w)
{
	(void)w;
}

int dist_agree(const struct dist_world *w, int status, const char *messages)
{
	(void)w;
	(void)messages;
	return status;
}

int dist_render_image(const struct dist_world *w, const struct scene *sc, const struct render_options *opt,
                      struct image *img, struct ray_stats *st, struct dist_traffic *traffic)
{
	(void)w;
	*traffic = (struct dist_traffic){ 0 };
	return render_image(sc, opt, img, st);
}

/* A world of one, in order. */
int dist_render_frames(const struct dist_world *w, const struct dist_frames *job, long *failed, long *written)
{
	(void)w;
	*failed = -1;
	*written = 0;
	for (long k = job->first; k < job->end; k++) {
		struct dist_frame f;
		job->render(job->ctx, k, &f);
		int rc = job->deliver(job->ctx, &f);
		dist_frame_free(&f);
		if (rc) {
			*failed = k;
			return rc;
		}
		++*written;
	}
	return 0;
}
