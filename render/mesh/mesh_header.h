/* mesh_header.h: checks on a mesh file made before assimp reads it, against what assimp
 * 5.2 does with some malformed files (mesh_import.c's only helper). */
#ifndef SCN_MESH_HEADER_H
#define SCN_MESH_HEADER_H

#include <stddef.h>

/* Checks that path can be read, and that the header of a PLY or OFF file is sound
 * enough for assimp (see mesh_header.c). Returns 0, or writes into err a message naming
 * path and the problem and returns 1. */
int mesh_header_check(const char *path, char *err, size_t errlen);

/* Writes the message into err (errlen bytes) and returns 1: the failure of the mesh
 * reader's functions. */
int mesh_header_fail(char *err, size_t errlen, const char *fmt, ...) __attribute__((format(printf, 3, 4)));

#endif
