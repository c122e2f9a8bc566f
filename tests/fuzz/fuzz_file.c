/* fuzz_file.c: the harnesses' temporary file (see fuzz.h). A directory of our own keeps
 * relative includes and mesh side files (an OBJ's mtllib) from finding anything else. */
#include "fuzz.h"

#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static char dir[64];
static char file[128];

static void remove_file(void)
{
	if (file[0])
		unlink(file);
	file[0] = '\0';
}

static void remove_dir(void)
{
	remove_file();
	rmdir(dir);
}

static void die(const char *what)
{
	perror(what);
	abort();
}

const char *fuzz_file(const char *name, const uint8_t *data, size_t size)
{
	if (!dir[0]) {
		const char *tmp = getenv("TMPDIR");
		snprintf(dir, sizeof dir, "%s/scn-fuzz-XXXXXX", tmp && strlen(tmp) < 40 ? tmp : "/tmp");
		if (!mkdtemp(dir))
			die(dir);
		atexit(remove_dir);
	}
	remove_file();
	snprintf(file, sizeof file, "%s/%s", dir, name);
	int fd = open(file, O_WRONLY | O_CREAT | O_TRUNC, 0600);
	if (fd < 0)
		die(file);
	for (size_t done = 0; done < size;) {
		ssize_t k = write(fd, data + done, size - done);
		if (k < 0)
			die(file);
		done += (size_t)k;
	}
	if (close(fd) != 0)
		die(file);
	return file;
}
