/* cleanup.h: what a run must not leave behind when it ends early, by a signal (SIGINT,
 * SIGTERM, SIGHUP; or SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, a crash) or by running
 * out of memory: its temporary files and folders and its
 * child process. Writers register them while they exist; the signal handler and
 * cleanup_exit remove them, then the process ends with the signal (status 128 + N) or the
 * given status. */
#ifndef SCN_CLEANUP_H
#define SCN_CLEANUP_H

#include <signal.h>
#include <stdbool.h>
#include <sys/types.h>

/* Installs the handlers for SIGINT, SIGTERM and SIGHUP. A handler kills and reaps the
 * child, removes the registered files and then the folders, writes "scn: stopped by
 * SIGxxx" and ends the process by the same signal with its default action. It runs on
 * the main thread: render threads are started with the signals blocked
 * (cleanup_block_signals). Crash signals (SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT) get a
 * handler that does the same in whichever thread crashed, saying that scn crashed (on
 * a stack of its own in the calling thread, so that a stack overflow there is reported
 * too); not in a build with AddressSanitizer, which reports crashes itself. */
void cleanup_install_signals(void);
/* Words that name this process in the "stopped by" line, such as "process 2 of 4 (on
 * node7): ", for a run of several processes; copied. */
void cleanup_name_process(const char *name);
/* Whether cleanup_install_signals handles crashes: not with AddressSanitizer. */
bool cleanup_handles_crashes(void);

/* Registers a temporary file (or, with dir, a folder removed after the files) to remove
 * should the run end early; unregisters it. path is copied. Returns false when the table
 * is full or path too long, and the file is then not removed on a signal. */
bool cleanup_register(const char *path, bool dir);
void cleanup_unregister(const char *path);

/* Blocks the three signals in the calling thread, the old mask going to *old, so that the
 * threads it starts inherit the block; cleanup_restore_signals puts *old back. */
void cleanup_block_signals(sigset_t *old);
void cleanup_restore_signals(const sigset_t *old);

/* fork(), with the child registered (killed and reaped on a signal) until cleanup_reaped,
 * and in the child the three signals back to their default actions, so that a signal
 * between fork and exec does not run scn's handler there. */
pid_t cleanup_fork(void);
void cleanup_reaped(pid_t pid);

/* Removes what is registered and exits with status (exit(3): standard output is flushed). */
_Noreturn void cleanup_exit(int status);

#endif
