/* pov_mesh.c: triangles as POV-Ray's mesh2, in single precision as POV-Ray stores them,
 * in world space or in a mesh file's own space (a use that a matrix places). */
#include "pov_mesh.h"

#include "pov_material.h"
#include "pov_write.h"

/* A mesh2's coordinates: in world space, or, for own (a mesh file's use), in the file's
 * own space, into which own's to_object map takes the world-space vertices back and the
 * transpose of its to_world map the normals (POV-Ray's matrix then brings them out). */
static struct vec3 mesh_vertex(const struct scene *sc, const struct mesh_use *own, uint32_t v)
{
	return own ? affine_point(&own->to_object, sc->geo.vertices[v]) : sc->geo.vertices[v];
}

static struct vec3 mesh_normal(const struct scene *sc, const struct mesh_use *own, uint32_t n)
{
	struct vec3 w = sc->geo.normals[n];
	return own ? vunit(affine_normal(&own->to_world, w)) : w;
}

struct vec3 pov_face_normal(const struct scene *sc, const struct mesh_use *own, const struct triangle *t)
{
	struct vec3 a = mesh_vertex(sc, own, t->v[0]), b = mesh_vertex(sc, own, t->v[1]), c = mesh_vertex(sc, own, t->v[2]);
	return vcross(vsub(b, a), vsub(c, a));
}

/* The vertices and normals that triangles [first, last) use, as index ranges. */
struct mesh_span {
	uint32_t vmin, vmax, nmin, nmax;
	size_t flat, smooth;           /* faces of each kind */
	bool per_vertex;               /* normal k of a face is its vertex k's, shifted alike */
};

static struct mesh_span mesh_span(const struct triangle *tris, size_t first, size_t last)
{
	struct mesh_span m = { UINT32_MAX, 0, UINT32_MAX, 0, 0, 0, true };
	for (size_t i = first; i < last; i++) {
		const struct triangle *t = &tris[i];
		for (int k = 0; k < 3; k++) {
			m.vmin = t->v[k] < m.vmin ? t->v[k] : m.vmin;
			m.vmax = t->v[k] > m.vmax ? t->v[k] : m.vmax;
			if (t->n[0] != TRIANGLE_FLAT) {
				m.nmin = t->n[k] < m.nmin ? t->n[k] : m.nmin;
				m.nmax = t->n[k] > m.nmax ? t->n[k] : m.nmax;
			}
		}
		if (t->n[0] == TRIANGLE_FLAT)
			m.flat++;
		else
			m.smooth++;
	}
	if (m.smooth)
		for (size_t i = first; i < last && m.per_vertex; i++) {
			const struct triangle *t = &tris[i];
			for (int k = 0; k < 3; k++)
				m.per_vertex &= t->n[0] != TRIANGLE_FLAT && t->n[k] - m.nmin == t->v[k] - m.vmin;
		}
	m.per_vertex &= m.smooth && m.nmax - m.nmin == m.vmax - m.vmin;
	return m;
}

bool pov_same_faces(const struct scene *sc, size_t a, size_t b, size_t n, bool swap)
{
	const struct triangle *tris = sc->geo.triangles;
	struct mesh_span sa = mesh_span(tris, a, a + n), sb = mesh_span(tris, b, b + n);
	if (sa.vmax - sa.vmin != sb.vmax - sb.vmin || sa.smooth != sb.smooth ||
	    (sa.smooth && sa.nmax - sa.nmin != sb.nmax - sb.nmin))
		return false;
	static const int kept[3] = { 0, 1, 2 }, swapped[3] = { 0, 2, 1 };
	const int *corner = swap ? swapped : kept;
	for (size_t i = 0; i < n; i++) {
		const struct triangle *s = &tris[a + i], *t = &tris[b + i];
		if ((s->n[0] == TRIANGLE_FLAT) != (t->n[0] == TRIANGLE_FLAT))
			return false;
		for (int k = 0; k < 3; k++)
			if (s->v[k] - sa.vmin != t->v[corner[k]] - sb.vmin ||
			    (s->n[0] != TRIANGLE_FLAT && s->n[k] - sa.nmin != t->n[corner[k]] - sb.nmin))
				return false;
	}
	return true;
}

/* The index in extra's texture_list of face t's surface. */
static size_t texture_index(const struct pov_mesh2_extra *extra, const struct triangle *t)
{
	size_t k = 0;
	while (extra->textures[k] != t->surface)
		k++;
	return k;
}

void pov_mesh2_body(FILE *f, const struct scene *sc, const struct triangle *tris, size_t first, size_t last,
                    const struct mesh_use *own, const struct pov_mesh2_extra *extra)
{
	struct mesh_span m = mesh_span(tris, first, last);
	fprintf(f, "mesh2 {\n  vertex_vectors { %lu", (unsigned long)(m.vmax - m.vmin + 1));
	for (uint32_t v = m.vmin; v <= m.vmax; v++) {
		fputs(v % 4 == m.vmin % 4 ? ",\n    " : ", ", f);
		pov_fvec(f, mesh_vertex(sc, own, v));
	}
	fputs(" }\n", f);
	if (m.smooth) {
		/* a flat face among smooth ones gets three copies of its geometric normal,
		 * which POV-Ray shades flat */
		size_t nn = (size_t)(m.nmax - m.nmin + 1) + m.flat;
		fprintf(f, "  normal_vectors { %zu", nn);
		size_t k = 0;
		for (uint32_t n = m.nmin; n <= m.nmax; n++, k++) {
			fputs(k % 4 == 0 ? ",\n    " : ", ", f);
			pov_fvec(f, mesh_normal(sc, own, n));
		}
		for (size_t i = first; i < last; i++)
			if (tris[i].n[0] == TRIANGLE_FLAT) {
				fputs(k++ % 4 == 0 ? ",\n    " : ", ", f);
				pov_fvec(f, vnorm(pov_face_normal(sc, own, &tris[i])));
			}
		fputs(" }\n", f);
	}
	if (extra && extra->uvs) {
		/* in double, as POV-Ray stores them (unlike the vertices) */
		fprintf(f, "  uv_vectors { %lu", (unsigned long)(m.vmax - m.vmin + 1));
		for (uint32_t v = m.vmin; v <= m.vmax; v++)
			fprintf(f, "%s<%.17g, %.17g>", v % 4 == m.vmin % 4 ? ",\n    " : ", ", sc->geo.uvs[v].u, sc->geo.uvs[v].v);
		fputs(" }\n", f);
	}
	bool listed = extra && extra->textures;
	if (listed) {
		fprintf(f, "  texture_list { %zu", extra->ntextures);
		for (size_t k = 0; k < extra->ntextures; k++) {
			fputs(",\n    ", f);
			pov_texture_ref(f, sc, extra->textures[k], own == NULL);
		}
		fputs(" }\n", f);
	}
	fprintf(f, "  face_indices { %zu", last - first);
	for (size_t i = first; i < last; i++) {
		const uint32_t *v = tris[i].v;
		fprintf(f, "%s<%lu,%lu,%lu>", (i - first) % 8 == 0 ? ",\n    " : ", ", (unsigned long)(v[0] - m.vmin),
		        (unsigned long)(v[1] - m.vmin), (unsigned long)(v[2] - m.vmin));
		if (listed)
			fprintf(f, ", %zu", texture_index(extra, &tris[i]));
	}
	fputs(" }\n", f);
	if (m.smooth && !m.per_vertex) {
		fprintf(f, "  normal_indices { %zu", last - first);
		size_t extra = (size_t)(m.nmax - m.nmin + 1);
		for (size_t i = first; i < last; i++) {
			const uint32_t *n = tris[i].n;
			unsigned long a, b, c;
			if (n[0] == TRIANGLE_FLAT)
				a = b = c = (unsigned long)extra++;
			else
				a = n[0] - m.nmin, b = n[1] - m.nmin, c = n[2] - m.nmin;
			fprintf(f, "%s<%lu,%lu,%lu>", (i - first) % 8 == 0 ? ",\n    " : ", ", a, b, c);
		}
		fputs(" }\n", f);
	}
}
