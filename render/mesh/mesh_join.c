/* mesh_join.c: joins the corners of an imported mesh that share a position (and normal
 * and UV), in one pass with a hash table. assimp's JoinIdenticalVertices step did this
 * before, and took 0.52 s of a 1M-triangle PLY's 0.6 s import (it sorts the vertices in space
 * and compares each with its neighbours); this takes a few hundredths. The result is
 * the one that step gives for the files we have (tests/unit/test_mesh_import.c):
 * vertices no face uses are dropped, the others keep their order, each joined to the
 * first with the same values. Values are compared exactly (-0 equal to +0), where
 * assimp allowed positions a few ulps apart and normals 1e-5 apart: corners written
 * from one value read back as one value, and nothing else is the same point. */
#include "mesh_join.h"

#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

#include "xalloc.h"

#define UNUSED UINT32_MAX
#define USED (UINT32_MAX - 1)
#define KEY_MAX 8              /* position, normal, UV */

/* The coordinates a vertex is joined by: its position, then its normal and its UV if
 * any; returns their number. */
static int key_of(const struct mesh_data *m, uint32_t v, double key[KEY_MAX])
{
	int n = 3;
	memcpy(key, m->vertices[v], 3 * sizeof *key);
	if (m->normals) {
		memcpy(key + n, m->normals[v], 3 * sizeof *key);
		n += 3;
	}
	if (m->uvs) {
		memcpy(key + n, m->uvs[v], 2 * sizeof *key);
		n += 2;
	}
	return n;
}

static uint64_t hash_key(const double *key, int n)
{
	uint64_t h = 0x9e3779b97f4a7c15u;
	for (int i = 0; i < n; i++) {
		double x = key[i] + 0.0; /* -0 + 0 is +0: equal values hash alike */
		uint64_t bits;
		memcpy(&bits, &x, sizeof bits);
		h = (h ^ bits) * 0xff51afd7ed558ccdu;
		h ^= h >> 32;
	}
	return h;
}

static bool same_key(const double *a, const double *b, int n)
{
	for (int i = 0; i < n; i++)
		if (!(a[i] == b[i]))
			return false;
	return true;
}

void mesh_join(struct mesh_data *m)
{
	size_t nv = m->nvertices;
	if (nv == 0)
		return;
	/* remap[v]: UNUSED, USED (not yet placed), then v's index after the join */
	uint32_t *remap = xmalloc(nv * sizeof *remap);
	for (size_t v = 0; v < nv; v++)
		remap[v] = UNUSED;
	for (size_t f = 0; f < m->nfaces; f++)
		for (int k = 0; k < 3; k++)
			remap[m->faces[f][k]] = USED;

	/* open addressing, at most half full; a slot holds a vertex's new index + 1 */
	size_t cap = 16;
	while (cap < 2 * nv)
		cap *= 2;
	uint32_t *slot = xcalloc(cap, sizeof *slot);
	uint32_t kept = 0;
	for (size_t v = 0; v < nv; v++) {
		if (remap[v] == UNUSED)
			continue;
		double key[KEY_MAX];
		int n = key_of(m, (uint32_t)v, key);
		size_t i = hash_key(key, n) & (cap - 1);
		for (; slot[i]; i = (i + 1) & (cap - 1)) {
			double other[KEY_MAX];
			key_of(m, slot[i] - 1, other);
			if (same_key(key, other, n))
				break;
		}
		if (slot[i]) {
			remap[v] = slot[i] - 1;
			continue;
		}
		/* a new vertex: moved down to its place, which no kept vertex still needs */
		memmove(m->vertices[kept], m->vertices[v], sizeof *m->vertices);
		if (m->normals)
			memmove(m->normals[kept], m->normals[v], sizeof *m->normals);
		if (m->uvs)
			memmove(m->uvs[kept], m->uvs[v], sizeof *m->uvs);
		remap[v] = kept;
		slot[i] = ++kept;
	}
	free(slot);
	for (size_t f = 0; f < m->nfaces; f++)
		for (int k = 0; k < 3; k++)
			m->faces[f][k] = remap[m->faces[f][k]];
	free(remap);
	m->nvertices = kept;
	m->vertices = xrealloc(m->vertices, kept * sizeof *m->vertices);
	if (m->normals) {
		m->nnormals = kept;
		m->normals = xrealloc(m->normals, kept * sizeof *m->normals);
	}
	if (m->uvs) {
		m->nuvs = kept;
		m->uvs = xrealloc(m->uvs, kept * sizeof *m->uvs);
	}
}
