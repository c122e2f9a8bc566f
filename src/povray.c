/* povray.c: running POV-Ray 3.7 as a child process (fork and exec, no shell), its
 * output to a log file in the private folder, which is where its image goes too. The
 * folder, each file povray_file names in it and the child are registered with cleanup.h
 * while they exist, so that an interrupted scn converge leaves none of them behind. */
#include "povray.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "cleanup.h"
#include "clock.h"
#include "image_file.h"
#include "xalloc.h"

/* The path of an executable named name on PATH, or NULL; malloc'd. */
static char *find_program(const char *name)
{
	const char *path = getenv("PATH");
	if (!path)
		path = "/usr/bin:/bin";
	for (;;) {
		size_t n = strcspn(path, ":");
		char *full = xmalloc(n + strlen(name) + 3);
		sprintf(full, "%.*s/%s", (int)n, n ? path : ".", name);
		if (access(full, X_OK) == 0)
			return full;
		free(full);
		if (!path[n])
			return NULL;
		path += n + 1;
	}
}

bool povray_open(struct povray *pv, char *err, size_t errlen)
{
	*pv = (struct povray){ 0 };
	if (!(pv->path = find_program("povray"))) {
		snprintf(err, errlen, "povray is not on PATH");
		return false;
	}
	const char *tmp = getenv("TMPDIR");
	if (!tmp || !*tmp)
		tmp = "/tmp";
	pv->dir = xmalloc(strlen(tmp) + 32);
	sprintf(pv->dir, "%s/scn-converge.XXXXXX", tmp);
	if (!mkdtemp(pv->dir)) {
		snprintf(err, errlen, "cannot make a folder '%s': %s", pv->dir, strerror(errno));
		free(pv->path);
		free(pv->dir);
		*pv = (struct povray){ 0 };
		return false;
	}
	cleanup_register(pv->dir, true);
	return true;
}

char *povray_file(const struct povray *pv, const char *name)
{
	char *p = xmalloc(strlen(pv->dir) + strlen(name) + 2);
	sprintf(p, "%s/%s", pv->dir, name);
	cleanup_register(p, false);
	return p;
}

/* Removes the file at p (named by povray_file) and frees p. */
static void remove_file(char *p)
{
	unlink(p);
	cleanup_unregister(p);
	free(p);
}

/* Runs argv (argv[0] a path) in folder dir with standard input from /dev/null and
 * standard output and error to the file log there. Returns the exit status (128 + the
 * signal when one ended it), or -1 when it could not be started. */
static int run_child(const char *dir, char *const argv[], const char *log)
{
	pid_t pid = cleanup_fork();
	if (pid < 0)
		return -1;
	if (pid == 0) {
		int in = open("/dev/null", O_RDONLY);
		if (in < 0 || chdir(dir) != 0)
			_exit(126);
		int fd = open(log, O_WRONLY | O_CREAT | O_TRUNC, 0666);
		if (fd < 0)
			_exit(126);
		dup2(in, 0);
		dup2(fd, 1);
		dup2(fd, 2);
		execv(argv[0], argv);
		_exit(127);
	}
	int status;
	while (waitpid(pid, &status, 0) < 0)
		if (errno != EINTR)
			return -1;
	cleanup_reaped(pid);
	return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
}

/* POV-Ray's "Trace Time: ... (X seconds)" from its log, or -1. */
static double trace_time(const char *log)
{
	FILE *f = fopen(log, "r");
	if (!f)
		return -1;
	char line[512];
	double t = -1;
	while (fgets(line, sizeof line, f)) {
		const char *p = strstr(line, "Trace Time:");
		const char *paren = p ? strchr(p, '(') : NULL;
		if (paren && sscanf(paren + 1, "%lf", &t) != 1)
			t = -1;
	}
	fclose(f);
	return t;
}

/* The last lines of the log, to standard error. */
static void show_tail(const char *log)
{
	enum { N = 8 };
	FILE *f = fopen(log, "r");
	if (!f)
		return;
	char lines[N][256];
	int n = 0;
	while (fgets(lines[n % N], sizeof lines[0], f))
		n++;
	fclose(f);
	for (int i = n > N ? n - N : 0; i < n; i++)
		fprintf(stderr, "  | %s%s", lines[i % N], strchr(lines[i % N], '\n') ? "" : "\n");
}

int povray_render(const struct povray *pv, const char *pov_name, const char *aa, int width, int height,
                  int threads, struct povray_render *out, char *err, size_t errlen)
{
	static unsigned serial;        /* a new image and log name for each run */
	unsigned k = serial++;
	char w[32], h[32], wt[32], in[64], png[32], log[32];
	snprintf(w, sizeof w, "+W%d", width);
	snprintf(h, sizeof h, "+H%d", height);
	snprintf(wt, sizeof wt, "+WT%d", threads);
	snprintf(in, sizeof in, "+I%s", pov_name);
	snprintf(png, sizeof png, "run-%u.png", k);
	snprintf(log, sizeof log, "run-%u.log", k);
	char o[40];
	snprintf(o, sizeof o, "+O%s", png);
	char *words = xstrdup(aa);
	char *argv[32];
	int n = 0;
	argv[n++] = pv->path;
	argv[n++] = "-D";                     /* no display window, nor ASCII art */
	for (char *t = strtok(words, " "); t && n < 24; t = strtok(NULL, " "))
		argv[n++] = t;
	argv[n++] = w;
	argv[n++] = h;
	argv[n++] = "+FN16";                  /* a 16-bit PNG ... */
	argv[n++] = "File_Gamma=1.0";         /* ... of linear values */
	argv[n++] = in;
	argv[n++] = o;
	argv[n++] = wt;
	argv[n] = NULL;
	*out = (struct povray_render){ .trace = -1 };
	char *log_path = povray_file(pv, log), *png_path = povray_file(pv, png);
	double t0 = clock_now();
	int status = run_child(pv->dir, argv, log);
	out->seconds = clock_now() - t0;
	free(words);
	int rc = 0;
	if (status != 0) {
		if (status < 0)
			snprintf(err, errlen, "cannot run %s: %s", pv->path, strerror(errno));
		else
			snprintf(err, errlen, "povray %s %s %s exited with status %d", aa, w, h, status);
		show_tail(log_path);
		rc = -1;
	} else if (image_read(png_path, &out->img, err, errlen) != 0) {
		rc = -1;
	} else {
		out->trace = trace_time(log_path);
	}
	remove_file(png_path);
	remove_file(log_path);
	return rc;
}

void povray_close(struct povray *pv)
{
	if (pv->dir) {
		DIR *d = opendir(pv->dir);
		if (d) {
			struct dirent *e;
			while ((e = readdir(d))) {
				if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0)
					continue;
				remove_file(povray_file(pv, e->d_name));
			}
			closedir(d);
		}
		rmdir(pv->dir);
		cleanup_unregister(pv->dir);
	}
	free(pv->dir);
	free(pv->path);
	*pv = (struct povray){ 0 };
}
