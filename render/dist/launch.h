/* launch.h: the MPI launcher that started this process, if any. */
#ifndef SCN_LAUNCH_H
#define SCN_LAUNCH_H

/* The name of the environment variable by which a launcher shows itself, or NULL when
 * no launcher started this process. */
const char *dist_launcher(void);

#endif
