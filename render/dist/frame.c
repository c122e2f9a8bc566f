/* frame.c: what dist_none.c and dist_mpi.c share about a frame's outcome. */
#include <stdlib.h>

#include "dist.h"

void dist_frame_free(struct dist_frame *f)
{
	free(f->messages);
	free(f->stats);
	image_free(f->img);
	f->messages = f->stats = NULL;
	f->img = NULL;
}
