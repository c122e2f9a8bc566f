/* file.c: a scene or included file read whole into memory, which diag.c quotes lines
 * from, and paths taken relative to the including file's folder. */
#include "file.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "diag.h"
#include "xalloc.h"

/* Reads f to its end into a buffer that starts at cap bytes and doubles; as file_read. */
static int read_stream(FILE *f, size_t cap, char **text, uint32_t *len)
{
	size_t n = 0;
	char *buf = xmalloc(cap);
	for (;;) {
		if (n + 1 >= cap) {
			if (cap >= DIAG_MAX_SOURCE_BYTES) {
				free(buf);
				return EFBIG;
			}
			cap *= 2;
			buf = xrealloc(buf, cap);
		}
		size_t got = fread(buf + n, 1, cap - n - 1, f);
		n += got;
		if (got == 0)
			break;
	}
	if (ferror(f)) {
		free(buf);
		return errno ? errno : EIO;
	}
	buf = xrealloc(buf, n + 1); /* many small includes must not hold 64 KiB each */
	buf[n] = '\0';
	*text = buf;
	*len = (uint32_t)n;
	return 0;
}

int file_read(const char *path, char **text, uint32_t *len)
{
	FILE *f = fopen(path, "rb");
	if (!f)
		return errno;
	/* a file is read into a buffer of its size at once (one byte more, to see its end):
	 * doubling from 64 KiB would copy a 60 MB scene twice over and touch twice its pages */
	struct stat st;
	size_t cap = fstat(fileno(f), &st) == 0 && S_ISREG(st.st_mode) && st.st_size < DIAG_MAX_SOURCE_BYTES
	           ? (size_t)st.st_size + 2 : 1 << 16;
	int err = read_stream(f, cap, text, len);
	fclose(f);
	return err;
}

int file_read_stdin(char **text, uint32_t *len)
{
	return read_stream(stdin, 1 << 16, text, len);
}

char *file_resolve(const char *dir, const char *path)
{
	if (path[0] == '/' || strcmp(dir, ".") == 0)
		return xstrdup(path);
	size_t ld = strlen(dir), lp = strlen(path);
	char *out = xmalloc(ld + lp + 2);
	memcpy(out, dir, ld);
	out[ld] = '/';
	memcpy(out + ld + 1, path, lp + 1);
	return out;
}

const char *file_not_regular(const char *path)
{
	struct stat st;
	if (stat(path, &st) == 0 && (S_ISFIFO(st.st_mode) || S_ISSOCK(st.st_mode)))
		return "a pipe or a socket, not a file";
	return NULL;
}

const char *file_unreadable(const char *path)
{
	const char *why = file_not_regular(path);
	if (why)
		return why;
	FILE *f = fopen(path, "rb");
	if (!f)
		return strerror(errno);
	/* opening a directory succeeds; reading it does not */
	char byte;
	int err = fread(&byte, 1, 1, f) == 0 && ferror(f) ? (errno ? errno : EIO) : 0;
	fclose(f);
	return err ? strerror(err) : NULL;
}
