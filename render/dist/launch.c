/* launch.c: whether this process was started by an MPI launcher, read from what the
 * launchers put in its environment; shared by scn (which then becomes scn-mpi) and
 * scn-mpi (which then starts MPI). */
#include "launch.h"

#include <stdlib.h>

/* Open MPI's mpirun sets the first; PMIx (Open MPI 4's own runtime, and Slurm's srun
 * --mpi=pmix) the second; PMI-1 and PMI-2 (srun --mpi=pmi2, MPICH's Hydra) the third. */
static const char *const vars[] = { "OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK" };

const char *dist_launcher(void)
{
	for (size_t i = 0; i < sizeof vars / sizeof *vars; i++)
		if (getenv(vars[i]))
			return vars[i];
	return NULL;
}
