/* outfile.c: the temporary-file-and-rename protocol shared by the image and POV-Ray
 * writers: an interrupted or failed write never leaves a truncated file or destroys the
 * one that was there. Where the file system can, the temporary file has no name until
 * it is complete (Linux's O_TMPFILE), so that not even SIGKILL leaves it behind;
 * elsewhere it is named, and a signal or running out of memory removes it (cleanup.h). */
#define _GNU_SOURCE /* O_TMPFILE */
#include "outfile.h"

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cleanup.h"
#include "xalloc.h"

/* The name is short and fixed apart from the counter, so that a long final name cannot
 * make it too long, and O_EXCL keeps two writers (or a stale file) apart. The mode 0666
 * lets the umask decide the permissions, as for any file the user creates. */
int outfile_open(const char *path, char **tmp, char *err, size_t errlen)
{
	if (errlen)
		err[0] = '\0';
	struct stat st;
	if (stat(path, &st) == 0 && S_ISDIR(st.st_mode)) {  /* known now, not at the rename */
		*tmp = NULL;
		snprintf(err, errlen, "cannot write '%s': %s", path, strerror(EISDIR));
		return -EISDIR;
	}
	static unsigned counter;       /* files are written from one thread */
	const char *slash = strrchr(path, '/');
	int dirlen = slash ? (int)(slash - path + 1) : 0;
	size_t size = (size_t)dirlen + 64;
	*tmp = xmalloc(size);
	int e = EEXIST;
#ifdef O_TMPFILE
	/* unnamed until outfile_finish links it (through /proc, which must be there) */
	snprintf(*tmp, size, "%.*s", dirlen ? dirlen : 1, dirlen ? path : ".");
	int unnamed = access("/proc/self/fd", X_OK) == 0 ? open(*tmp, O_TMPFILE | O_WRONLY | O_CLOEXEC, 0666) : -1;
	snprintf(*tmp, size, "%.*s.scn-%ld-%u.tmp", dirlen, path, (long)getpid(), counter++);
	if (unnamed >= 0)
		return unnamed;
#endif
	for (int attempt = 0; attempt < 100; attempt++) {
		snprintf(*tmp, size, "%.*s.scn-%ld-%u.tmp", dirlen, path, (long)getpid(), counter++);
		/* registered before it exists, so that no signal finds it made and not known */
		cleanup_register(*tmp, false);
		int fd = open(*tmp, O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
		if (fd >= 0)
			return fd;
		e = errno;
		cleanup_unregister(*tmp);
		if (e != EEXIST)
			break;
	}
	free(*tmp);
	*tmp = NULL;
	snprintf(err, errlen, "cannot write '%s': %s", path, strerror(e));
	return -e;
}

int outfile_finish(int fd, char *tmp, const char *path, int rc, char *err, size_t errlen)
{
	/* fsync before rename: otherwise a crash soon after could leave the new name
	 * pointing at an empty file, the very thing the rename is there to prevent. close
	 * is checked too, since some file systems report write errors only there. */
	if (rc == 0 && fsync(fd) != 0 && errno != EINVAL)
		rc = errno;
	/* an unnamed file gets tmp's name only now, for as long as the rename takes */
	struct stat st;
	if (rc == 0 && fstat(fd, &st) == 0 && st.st_nlink == 0) {
		char self[64];
		snprintf(self, sizeof self, "/proc/self/fd/%d", fd);
		cleanup_register(tmp, false);
		int linked = linkat(AT_FDCWD, self, AT_FDCWD, tmp, AT_SYMLINK_FOLLOW);
		/* a file of that name, which holds this process's id, was left by a dead process
		 * that had the same id: it is no one's */
		if (linked != 0 && errno == EEXIST && unlink(tmp) == 0)
			linked = linkat(AT_FDCWD, self, AT_FDCWD, tmp, AT_SYMLINK_FOLLOW);
		if (linked != 0)
			rc = errno;
	}
	if (close(fd) != 0 && rc == 0)
		rc = errno;
	if (rc == 0 && rename(tmp, path) != 0)
		rc = errno;
	if (rc != 0) {
		if (errlen && !err[0])
			snprintf(err, errlen, "cannot write '%s': %s", path, strerror(rc));
		unlink(tmp);
	}
	cleanup_unregister(tmp);
	free(tmp);
	return rc;
}

int outfile_write(int fd, const void *buf, size_t n)
{
	const char *p = buf;
	while (n > 0) {
		ssize_t k = write(fd, p, n);
		if (k < 0) {
			if (errno == EINTR)
				continue;
			return errno;
		}
		p += k;
		n -= (size_t)k;
	}
	return 0;
}
