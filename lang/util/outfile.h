/* outfile.h: output files written whole or not at all: a temporary file beside the
 * target, flushed to disk and renamed over it (LANGUAGE.md section 8). */
#ifndef SCN_OUTFILE_H
#define SCN_OUTFILE_H

#include <stddef.h>

/* Opens a new, empty temporary file in the directory of path; its name goes to *tmp, and
 * err is emptied for the writer's messages. Returns the descriptor, or minus an errno
 * value with "cannot write 'path': reason" in err (*tmp is then freed and NULL). */
int outfile_open(const char *path, char **tmp, char *err, size_t errlen);

/* Ends what outfile_open began. When rc is 0, flushes fd to disk, closes it and renames
 * tmp over path; otherwise, or when a step fails, closes fd and removes tmp, leaving
 * path untouched. Returns the first error (rc itself when it was not 0), 0 on success;
 * err gets "cannot write 'path': reason" unless it already holds a message. Frees tmp. */
int outfile_finish(int fd, char *tmp, const char *path, int rc, char *err, size_t errlen);

/* Writes all n bytes to fd, retrying short writes; returns 0 or errno. */
int outfile_write(int fd, const void *buf, size_t n);

#endif
