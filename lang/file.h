/* file.h: reading the scene's files and resolving their paths (file.c). */
#ifndef SCN_FILE_H
#define SCN_FILE_H

#include <stdint.h>

/* Reads a whole file into a NUL-terminated malloc'd buffer. Returns 0 or an errno value
 * (EFBIG when it is larger than DIAG_MAX_SOURCE_BYTES). */
int file_read(const char *path, char **text, uint32_t *len);
/* The same for standard input (a scene given as -). */
int file_read_stdin(char **text, uint32_t *len);

/* Joins path to dir unless path is absolute; malloc'd. */
char *file_resolve(const char *dir, const char *path);

#endif
