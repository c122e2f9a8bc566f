/* cleanup.c: the registry of what an early end must remove, and the signal handler that
 * removes it. The handler may interrupt the main thread anywhere, so the registry is a
 * fixed table of copied paths whose slot is marked in use only after its path is
 * complete, and the handler calls only async-signal-safe functions (kill, waitpid,
 * unlink, rmdir, write, signal, raise). */
#include "cleanup.h"

#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

enum { SLOTS = 16, SLOT_BYTES = 4096 + 64 };
enum { FREE, FILE_SLOT, DIR_SLOT };

static char slot_path[SLOTS][SLOT_BYTES];
static volatile sig_atomic_t slot_kind[SLOTS];
static volatile sig_atomic_t child;     /* the registered child's pid, or 0 */

static const int handled[] = { SIGINT, SIGTERM, SIGHUP };
enum { NHANDLED = sizeof handled / sizeof handled[0] };

/* Async-signal-safe: the handler's whole work but the exit. */
static void remove_all(void)
{
	pid_t pid = (pid_t)child;
	if (pid > 0) {
		kill(pid, SIGKILL);
		waitpid(pid, NULL, 0);
		child = 0;
	}
	for (int kind = FILE_SLOT; kind <= DIR_SLOT; kind++)  /* a folder empties first */
		for (int i = 0; i < SLOTS; i++)
			if (slot_kind[i] == kind) {
				if (kind == FILE_SLOT)
					unlink(slot_path[i]);
				else
					rmdir(slot_path[i]);
				slot_kind[i] = FREE;
			}
}

/* A crash (a bug in scn, or a failing machine) ends the run as the signal would, after
 * the same removals, with a message that says so. Not in a sanitizer build, whose own
 * handlers report where a crash happened. */
#if defined(__SANITIZE_ADDRESS__)
#define SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SANITIZED 1
#endif
#endif
#ifndef SANITIZED
static const struct {
	int sig;
	const char *line;
} crashes[] = {
	{ SIGSEGV, "scn: crashed with SIGSEGV (a bug in scn); its temporary files are removed\n" },
	{ SIGBUS, "scn: crashed with SIGBUS (a bug in scn, or a file changed under it); its temporary files are removed\n" },
	{ SIGFPE, "scn: crashed with SIGFPE (a bug in scn); its temporary files are removed\n" },
	{ SIGILL, "scn: crashed with SIGILL (a bug in scn, or a build for another CPU); its temporary files are removed\n" },
	{ SIGABRT, "scn: crashed with SIGABRT (a bug in scn); its temporary files are removed\n" },
};
enum { NCRASHES = sizeof crashes / sizeof crashes[0] };

/* The crash handler's own stack, for the main thread, where the parser, checker and
 * evaluator recurse: a stack overflow's SIGSEGV comes with the stack full, and a handler
 * run on it would fault again before it removed anything. (Render threads recurse no
 * deeper than a scene's max_depth.) */
static char crash_stack[64 * 1024];

static void on_crash(int sig)
{
	remove_all();
	for (int i = 0; i < NCRASHES; i++)
		if (crashes[i].sig == sig) {
			ssize_t ignored = write(2, crashes[i].line, strlen(crashes[i].line));
			(void)ignored;
		}
	/* SA_RESETHAND has put the default action back: the signal, raised again or
	 * re-raised by the faulting instruction, ends the process */
	raise(sig);
}
#endif

bool cleanup_handles_crashes(void)
{
#ifdef SANITIZED
	return false;
#else
	return true;
#endif
}

/* cleanup_name_process's words, "process 2 of 4 (on node7): " */
static char process_name[128];

void cleanup_name_process(const char *name)
{
	snprintf(process_name, sizeof process_name, "%s", name);
}

static void on_signal(int sig)
{
	remove_all();
	static const char prefix[] = "scn: ", stopped[] = "stopped by ";
	const char *name = sig == SIGINT ? "SIGINT\n" : sig == SIGTERM ? "SIGTERM\n" : "SIGHUP\n";
	ssize_t ignored = write(2, prefix, sizeof prefix - 1);
	ignored = write(2, process_name, strlen(process_name));
	ignored = write(2, stopped, sizeof stopped - 1);
	ignored = write(2, name, strlen(name));
	(void)ignored;
	/* the default action, once the handler returns and the signal is unblocked: the
	 * process ends as killed by sig, which its parent sees (status 128 + sig) */
	signal(sig, SIG_DFL);
	raise(sig);
}

void cleanup_install_signals(void)
{
	struct sigaction sa = { .sa_handler = on_signal };
	sigemptyset(&sa.sa_mask);
	for (int i = 0; i < NHANDLED; i++)
		sigaddset(&sa.sa_mask, handled[i]);
	for (int i = 0; i < NHANDLED; i++) {
		struct sigaction old;
		/* a signal ignored by whoever started scn (nohup, a shell's background job) stays ignored */
		if (sigaction(handled[i], NULL, &old) == 0 && old.sa_handler == SIG_IGN)
			continue;
		sigaction(handled[i], &sa, NULL);
	}
#ifndef SANITIZED
	stack_t alt = { .ss_sp = crash_stack, .ss_size = sizeof crash_stack };
	bool on_alt = sigaltstack(&alt, NULL) == 0;
	struct sigaction crash = { .sa_handler = on_crash, .sa_flags = SA_RESETHAND | (on_alt ? SA_ONSTACK : 0) };
	sigemptyset(&crash.sa_mask);
	for (int i = 0; i < NCRASHES; i++)
		sigaction(crashes[i].sig, &crash, NULL);
#endif
}

bool cleanup_register(const char *path, bool dir)
{
	size_t n = strlen(path);
	if (n >= SLOT_BYTES)
		return false;
	for (int i = 0; i < SLOTS; i++)
		if (slot_kind[i] == FREE) {
			memcpy(slot_path[i], path, n + 1);
			atomic_signal_fence(memory_order_seq_cst);  /* the path is whole before it counts */
			slot_kind[i] = dir ? DIR_SLOT : FILE_SLOT;
			return true;
		}
	return false;
}

void cleanup_unregister(const char *path)
{
	for (int i = 0; i < SLOTS; i++)
		if (slot_kind[i] != FREE && strcmp(slot_path[i], path) == 0) {
			slot_kind[i] = FREE;
			return;
		}
}

static void handled_set(sigset_t *set)
{
	sigemptyset(set);
	for (int i = 0; i < NHANDLED; i++)
		sigaddset(set, handled[i]);
}

void cleanup_block_signals(sigset_t *old)
{
	sigset_t set;
	handled_set(&set);
	pthread_sigmask(SIG_BLOCK, &set, old);
}

void cleanup_restore_signals(const sigset_t *old)
{
	pthread_sigmask(SIG_SETMASK, old, NULL);
}

pid_t cleanup_fork(void)
{
	sigset_t old;
	cleanup_block_signals(&old);
	pid_t pid = fork();
	if (pid == 0) {
		for (int i = 0; i < NHANDLED; i++) {
			struct sigaction sa;
			if (sigaction(handled[i], NULL, &sa) == 0 && sa.sa_handler == on_signal)
				signal(handled[i], SIG_DFL);
		}
#ifndef SANITIZED
		/* a crash there must not remove the parent's files */
		for (int i = 0; i < NCRASHES; i++)
			signal(crashes[i].sig, SIG_DFL);
#endif
	} else if (pid > 0) {
		child = pid;
	}
	cleanup_restore_signals(&old);
	return pid;
}

void cleanup_reaped(pid_t pid)
{
	if (child == pid)
		child = 0;
}

_Noreturn void cleanup_exit(int status)
{
	remove_all();
	exit(status);
}
