/* mesh_join.h: joins the corners of an imported mesh that share a position, normal and UV. */
#ifndef SCN_MESH_JOIN_H
#define SCN_MESH_JOIN_H

#include "mesh_import.h"

/* Makes m's corners with equal positions (and equal normals and UVs, when m has them) one
 * vertex, the first of them in m's order, and drops the vertices no face uses; the
 * vertices kept stay in their order. m has at least one face. */
void mesh_join(struct mesh_data *m);

#endif
