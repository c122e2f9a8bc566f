/* test_crash.c: a stack overflow on the main thread, the crash a runaway recursion in the
 * parser, checker or evaluator would be, still runs scn's crash handler (lang/cleanup.c):
 * the registered temporary file is removed, the message says scn crashed, and the
 * process ends by SIGSEGV. Skipped (77) in a sanitizer build, which reports crashes
 * itself and installs no handler. */
#include "config.h"

#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "check.h"
#include "cleanup.h"

/* Recursion deep enough to pass the stack limit, each frame handed to the next so that
 * the compiler can neither drop nor reuse it. */
static long descend(long n, volatile char *up)
{
	volatile char frame[4096];
	frame[0] = up[0];
	frame[1] = 1;
	return n == 0 ? frame[0] : descend(n - 1, frame) + frame[1];
}

int main(void)
{
	if (!cleanup_handles_crashes())
		return 77;
	char tmp[] = "/tmp/scn-test-crash-XXXXXX";
	int fd = mkstemp(tmp);
	CHECK(fd >= 0);
	close(fd);
	char errpath[] = "/tmp/scn-test-crash-err-XXXXXX";
	int err = mkstemp(errpath);
	CHECK(err >= 0);
	pid_t pid = fork();
	if (pid == 0) {
		/* a stack of 8 MiB at most, whatever the shell's limit, and no core file */
		struct rlimit stack = { 8 << 20, 8 << 20 }, core = { 0, 0 };
		setrlimit(RLIMIT_STACK, &stack);
		setrlimit(RLIMIT_CORE, &core);
		dup2(err, 2);
		cleanup_install_signals();
		cleanup_register(tmp, false);
		volatile char top[2] = { 0 };
		return (int)descend(1L << 40, top);
	}
	int status = 0;
	CHECK(waitpid(pid, &status, 0) == pid);
	CHECK(WIFSIGNALED(status) && WTERMSIG(status) == SIGSEGV);
	CHECK(access(tmp, F_OK) != 0); /* removed by the handler */
	char text[512] = { 0 };
	ssize_t n = pread(err, text, sizeof text - 1, 0);
	CHECK(n > 0 && strstr(text, "scn: crashed with SIGSEGV") != NULL);
	close(err);
	unlink(errpath);
	unlink(tmp);
	return check_result();
}
