/* file.h: reading the scene's files and resolving their paths (file.c). */
#ifndef SCN_FILE_H
#define SCN_FILE_H

#include <stdint.h>

/* Reads a whole file into a NUL-terminated malloc'd buffer. Returns 0 or an errno value
 * (EFBIG when it is larger than DIAG_MAX_SOURCE_BYTES). */
int file_read(const char *path, char **text, uint32_t *len);
/* The same for standard input (a scene given as -). */
int file_read_stdin(char **text, uint32_t *len);

/* A pipe (or a socket) named in a scene, say /dev/stdin, could keep a read waiting
 * forever for a writer: "a pipe or a socket, not a file" for one, else NULL. */
const char *file_not_regular(const char *path);
/* Why the file at path cannot be read (file_not_regular's reason, or the system's), or
 * NULL when it can. */
const char *file_unreadable(const char *path);

/* Joins path to dir unless path is absolute; malloc'd. */
char *file_resolve(const char *dir, const char *path);

#endif
