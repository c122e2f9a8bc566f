/* mesh_dump.h: scn check --dump's lines for the materials that objects take from their
 * mesh files (LANGUAGE.md section 11). */
#ifndef SCN_MESH_DUMP_H
#define SCN_MESH_DUMP_H

#include <stdio.h>

#include "load.h"
#include "scene_desc.h"

/* Writes to out, for each mesh file that an object without a material of its own uses
 * (its material none, or a CSG's), once, in the order of the objects: one line for each
 * material the file gives its triangles, in the style of scene_desc_dump. The files are
 * read again (the lowering keeps nothing of them). Returns LOAD_OK, or, after writing
 * to stderr why a file could not be read again, LOAD_TOO_BIG for memory and
 * LOAD_IO_ERROR otherwise (the file changed since the lowering read it). */
enum load_status mesh_dump_materials(const struct scene_desc *desc, FILE *out);

#endif
