/* pov_export.c: writes a lowered scene as the POV-Ray 3.7 scene that computes the same
 * image (doc/povray.md): the header that turns POV-Ray's extras off, the camera,
 * the sky, the lights, every material (pov_material.c: the single-layer recipe where exact,
 * the layered general recipe otherwise), and the world-space geometry (meshes as mesh2
 * in single precision, as POV-Ray stores them; a mesh file that several objects use is
 * declared once in its own space and placed by a matrix; the solids of section 9 as
 * POV-Ray's shapes and CSG, pov_solid.c). The first lines are comments
 * with the povray command line that renders it and whatever POV-Ray cannot reproduce
 * exactly. */
#include "pov_export.h"


#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "outfile.h"
#include "pov_docdir.h"
#include "pov_material.h"
#include "pov_mesh.h"
#include "pov_solid.h"
#include "pov_texture.h"
#include "pov_write.h"
#include "xalloc.h"

/* How far up-wind a distant light is put, at least, and in scene radii. */
#define FAR_MIN 1e6
#define FAR_RADII 100
/* Surfaces closer than this meet as far as POV-Ray's shadow rays are concerned. */
#define CONTACT 1e-3

enum write_as { WRITE_TRIANGLE = 1, WRITE_MESH2, WRITE_UNION };

struct pov {
	FILE *f;
	const struct scene *sc;
	const struct pov_export_options *opt;
	char *notes;                   /* comment lines for the header, each ending in '\n' */
	size_t notes_len;
	unsigned char *how;            /* per first triangle of a run: enum write_as */
	/* mesh file objects (scene.mesh_uses) written as one declared mesh2 each placed */
	int32_t *use_of;               /* per surface: its mesh use, or -1 */
	int32_t *shares;               /* per mesh use: the use whose mesh2 is declared for it
	                                  (itself for that one), or -1: written alone */
	size_t *run_of;                /* per mesh use written as mesh2: its first triangle */
	/* mesh file objects with the file's own materials: one mesh2 each, with a texture_list */
	int32_t *listed;               /* per triangle: the mesh use whose triangles start there
	                                  and take more than its one surface, or -1 */
	bool *listed_material;         /* per material: a texture_list names it */
};

static void note(struct pov *p, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

static void note(struct pov *p, const char *fmt, ...)
{
	char line[512];
	va_list ap;
	va_start(ap, fmt);
	int n = vsnprintf(line, sizeof line - 1, fmt, ap);
	va_end(ap);
	if (n < 0)
		return;
	if ((size_t)n > sizeof line - 2)
		n = (int)sizeof line - 2;
	line[n++] = '\n';
	line[n] = '\0';
	p->notes = xrealloc(p->notes, p->notes_len + (size_t)n + 1);
	memcpy(p->notes + p->notes_len, line, (size_t)n + 1);
	p->notes_len += (size_t)n;
}

/* --- geometry --- */

/* triangle { ... } or smooth_triangle { ... } in double precision, without a material. */
static void triangle_body(struct pov *p, size_t i)
{
	const struct scene *sc = p->sc;
	const struct triangle *t = &sc->geo.triangles[i];
	FILE *f = p->f;
	fputs(t->n[0] == TRIANGLE_FLAT ? "triangle { " : "smooth_triangle { ", f);
	for (int k = 0; k < 3; k++) {
		pov_vec(f, sc->geo.vertices[t->v[k]]);
		if (t->n[0] != TRIANGLE_FLAT) {
			fputs(", ", f);
			pov_vec(f, sc->geo.normals[t->n[k]]);
		}
		fputs(k < 2 ? ", " : " ", f);
	}
}

static void write_triangle(struct pov *p, size_t i)
{
	triangle_body(p, i);
	pov_material_ref(p->f, p->sc, p->sc->geo.triangles[i].surface, false);
	fputs(" }\n", p->f);
}

/* Triangles [first, last) as a union of double-precision triangles. */
static void write_union(struct pov *p, size_t first, size_t last)
{
	FILE *f = p->f;
	fputs("union {  // a mesh whose faces lie on a checker boundary: in double precision, not as mesh2\n", f);
	for (size_t i = first; i < last; i++) {
		fputs("  ", f);
		triangle_body(p, i);
		fputs("}\n", f);
	}
	fputs("  ", f);
	pov_material_ref(p->f, p->sc, p->sc->geo.triangles[first].surface, false);
	fputs("\n}\n", f);
}

/* Whether surface s's material is an image looked up by UV coordinates. */
static bool uv_mapped(const struct scene *sc, uint32_t s)
{
	const struct material *m = &sc->materials[sc->geo.surfaces[s].material];
	return m->pigment == MATERIAL_IMAGE && sc->image_maps[m->texture].map == TEXTURE_MAP_UV;
}

/* What the mesh2 of triangles [first, last) carries beyond its shape: UVs where a material
 * needs them, and with listed the texture_list of its surfaces (*list, to be freed). */
static struct pov_mesh2_extra mesh2_extra(const struct pov *p, size_t first, size_t last, bool listed, uint32_t **list)
{
	const struct scene *sc = p->sc;
	struct pov_mesh2_extra x = { 0 };
	*list = NULL;
	if (listed)
		*list = xmalloc((last - first) * sizeof **list);
	for (size_t i = first; i < last; i++) {
		uint32_t s = sc->geo.triangles[i].surface;
		x.uvs |= sc->geo.uvs && uv_mapped(sc, s);
		if (!listed)
			continue;
		size_t k = 0;
		while (k < x.ntextures && (*list)[k] != s)
			k++;
		if (k == x.ntextures)
			(*list)[x.ntextures++] = s;
	}
	x.textures = *list;
	return x;
}

/* The interior of a mesh2 whose texture_list names the materials of surfaces list[0, n):
 * the mesh2 holds one for all (POV-Ray's textures have none), that of the first material
 * with one, with a comment when another's ior differs. */
static void listed_interior(struct pov *p, const uint32_t *list, size_t n)
{
	bool have = false, differ = false;
	double ior = 1;
	for (size_t k = 0; k < n; k++) {
		double r;
		if (!pov_material_interior(&p->sc->materials[p->sc->geo.surfaces[list[k]].material], &r))
			continue;
		differ |= have && r != ior;
		ior = have ? ior : r;
		have = true;
	}
	if (!have)
		return;
	fputs("  interior { ior ", p->f);
	pov_num(p->f, ior);
	fputs(" }", p->f);
	if (differ)
		fputs("  // not exact: its transmitting faces have different iors; POV-Ray's mesh2 has one", p->f);
	fputc('\n', p->f);
}

/* Triangles [first, last) as "mesh2 { ..." (pov_mesh2_body, own as there) with what their
 * materials need: UVs, and with listed the texture_list and its interior. */
static void write_mesh2_body(struct pov *p, size_t first, size_t last, const struct mesh_use *own, bool listed)
{
	uint32_t *list;
	struct pov_mesh2_extra x = mesh2_extra(p, first, last, listed, &list);
	pov_mesh2_body(p->f, p->sc, p->sc->geo.triangles, first, last, own, &x);
	if (listed)
		listed_interior(p, list, x.ntextures);
	free(list);
}

/* Triangles [first, last), of one surface or (listed) a mesh file object's with its own
 * materials, as a mesh2 in world space. */
static void write_mesh2(struct pov *p, size_t first, size_t last, bool listed)
{
	write_mesh2_body(p, first, last, NULL, listed);
	if (!listed) {
		fputs("  ", p->f);
		pov_material_ref(p->f, p->sc, p->sc->geo.triangles[first].surface, false);
		fputc('\n', p->f);
	}
	fputs("}\n", p->f);
}

/* Triangles [first, last), the mesh file object of mesh use u, placed by its transform
 * as an object of the mesh2 declared (in the file's own space) at the first use that it
 * shares. The material follows the matrix, so that it stays in world space. */
static void write_placed(struct pov *p, size_t first, size_t last, int32_t u)
{
	const struct mesh_use *use = &p->sc->mesh_uses[u];
	FILE *f = p->f;
	bool listed = p->listed[first] == u;
	if (p->shares[u] == u) {
		fprintf(f, "// scn_mesh_%u: a mesh file that several objects use, in its own coordinates;"
		           " each object { } places it\n#declare scn_mesh_%u = ", (unsigned)use->mesh, (unsigned)use->mesh);
		write_mesh2_body(p, first, last, use, listed);
		fputs("}\n", f);
	}
	fprintf(f, "object { scn_mesh_%u ", (unsigned)use->mesh);
	pov_matrix(f, &use->to_world);
	if (!listed) {
		fputs(" ", f);
		pov_material_ref(p->f, p->sc, use->surface, false);
	}
	fputs(" }\n", f);
}

/* Whether every edge of triangles [first, last) is shared by exactly two of them, once
 * in each direction: a closed, consistently wound surface, which has an inside. */
struct edge {
	uint32_t a, b;
	int dir;
};

static int edge_cmp(const void *x, const void *y)
{
	const struct edge *e = x, *g = y;
	if (e->a != g->a)
		return e->a < g->a ? -1 : 1;
	if (e->b != g->b)
		return e->b < g->b ? -1 : 1;
	return e->dir - g->dir;
}

static bool closed_surface(const struct scene *sc, size_t first, size_t last)
{
	size_t n = 3 * (last - first);
	struct edge *e = xmalloc(n * sizeof *e);
	for (size_t i = first, k = 0; i < last; i++)
		for (int j = 0; j < 3; j++, k++) {
			uint32_t a = sc->geo.triangles[i].v[j], b = sc->geo.triangles[i].v[(j + 1) % 3];
			e[k] = a < b ? (struct edge){ a, b, 0 } : (struct edge){ b, a, 1 };
		}
	qsort(e, n, sizeof *e, edge_cmp);
	bool closed = n % 2 == 0;
	for (size_t k = 0; closed && k < n; k += 2)
		closed = e[k].a == e[k + 1].a && e[k].b == e[k + 1].b && e[k].dir == 0 && e[k + 1].dir == 1 &&
		         (k + 2 >= n || e[k + 2].a != e[k].a || e[k + 2].b != e[k].b);
	free(e);
	return closed;
}

/* The point p in the checker's own space of surface s. */
static struct vec3 object_point(const struct scene *sc, const struct surface *s, struct vec3 p)
{
	return s->to_object < 0 ? p : affine_point(&sc->affines[s->to_object], p);
}

/* Whether a face of triangles [first, last) lies in a plane where its checker changes
 * colour. Its points then sit on the boundary up to rounding: scn's double precision
 * and the checker's 1e-10 bias decide them, but mesh2's single-precision vertices move
 * the face off the plane by about 1e-7, to either side. */
static bool on_checker_boundary(const struct scene *sc, size_t first, size_t last)
{
	const struct surface *s = &sc->geo.surfaces[sc->geo.triangles[first].surface];
	const struct material *m = &sc->materials[s->material];
	if (m->pigment != MATERIAL_CHECKER)
		return false;
	for (size_t i = first; i < last; i++) {
		struct vec3 c[3];
		for (int k = 0; k < 3; k++)
			c[k] = vscale(object_point(sc, s, sc->geo.vertices[sc->geo.triangles[i].v[k]]), 1 / m->checker_size);
		for (int axis = 0; axis < 3; axis++) {
			double a = vget(&c[0], axis), b = vget(&c[1], axis), d = vget(&c[2], axis);
			double r = round(a);
			if (fabs(a - r) < 1e-3 && fabs(b - r) < 1e-3 && fabs(d - r) < 1e-3)
				return true;
		}
	}
	return false;
}

/* The runs of triangles that share a surface: one object each. */
static size_t run_end(const struct scene *sc, size_t first)
{
	size_t last = first + 1;
	while (last < sc->geo.ntriangles && sc->geo.triangles[last].surface == sc->geo.triangles[first].surface)
		last++;
	return last;
}

/* The triangles written as one object from first: a run, or a mesh file object with its
 * own materials (p->listed) whole. */
static size_t unit_end(const struct pov *p, size_t first)
{
	return p->listed[first] >= 0 ? p->sc->mesh_uses[p->listed[first]].last : run_end(p->sc, first);
}

/* Which mesh file objects take more surfaces than their own (a file's own materials, face
 * by face): each is written as one mesh2 with a texture_list (p->listed, p->listed_material). */
static void find_listed(struct pov *p)
{
	const struct scene *sc = p->sc;
	p->listed = xmalloc((sc->geo.ntriangles ? sc->geo.ntriangles : 1) * sizeof *p->listed);
	for (size_t i = 0; i < sc->geo.ntriangles; i++)
		p->listed[i] = -1;
	p->listed_material = xcalloc(sc->nmaterials ? sc->nmaterials : 1, sizeof *p->listed_material);
	for (size_t u = 0; u < sc->nmesh_uses; u++) {
		const struct mesh_use *use = &sc->mesh_uses[u];
		bool own = false;
		for (size_t i = use->first; i < use->last && !own; i++)
			own = sc->geo.triangles[i].surface != use->surface;
		if (!own)
			continue;
		p->listed[use->first] = (int32_t)u;
		for (size_t i = use->first; i < use->last; i++)
			p->listed_material[sc->geo.surfaces[sc->geo.triangles[i].surface].material] = true;
	}
}

/* Whether POV-Ray keeps smooth face i: it drops a smooth_triangle unless its three
 * normals lie strictly on one side of it ("Degenerate triangle"); mesh2 keeps any. */
static bool smooth_kept(const struct scene *sc, size_t i)
{
	const struct triangle *t = &sc->geo.triangles[i];
	if (t->n[0] == TRIANGLE_FLAT)
		return true;
	struct vec3 g = pov_face_normal(sc, NULL, t);
	double d0 = vdot(g, sc->geo.normals[t->n[0]]), d1 = vdot(g, sc->geo.normals[t->n[1]]),
	       d2 = vdot(g, sc->geo.normals[t->n[2]]);
	return (d0 > 0 && d1 > 0 && d2 > 0) || (d0 < 0 && d1 < 0 && d2 < 0);
}

/* How each run of triangles is written (at its first triangle's index), and what POV-
 * Ray will not compute as scn does, found before anything is written so that the
 * header can say it. */
static void analyse(struct pov *p)
{
	const struct scene *sc = p->sc;
	size_t kept_as_mesh2 = 0, open = 0, boundary = 0, smooth_glass = 0;
	for (size_t first = 0; first < sc->geo.ntriangles;) {
		size_t last = unit_end(p, first);
		/* a transmitting face's material, else the first face's */
		const struct material *m = NULL;
		for (size_t i = first; i < last && (!m || vzero(m->transmit)); i++)
			m = &sc->materials[sc->geo.surfaces[sc->geo.triangles[i].surface].material];
		bool all_kept = true;
		for (size_t i = first; i < last && all_kept; i++)
			all_kept = smooth_kept(sc, i);
		if (p->listed[first] >= 0) {
			p->how[first] = WRITE_MESH2;
		} else if (last - first == 1 && sc->geo.uvs && uv_mapped(sc, sc->geo.triangles[first].surface)) {
			p->how[first] = WRITE_MESH2;  /* the one with uv_vectors */
		} else if (last - first == 1) {
			/* a lone triangle in double precision, unless POV-Ray would drop it */
			p->how[first] = all_kept ? WRITE_TRIANGLE : WRITE_MESH2;
			kept_as_mesh2 += !all_kept;
		} else if (on_checker_boundary(sc, first, last)) {
			/* a union of triangles has no inside to refract through */
			bool solid = !vzero(m->transmit) && m->ior != 1;
			p->how[first] = all_kept && !solid ? WRITE_UNION : WRITE_MESH2;
			boundary += p->how[first] == WRITE_MESH2;
		} else {
			p->how[first] = WRITE_MESH2;
		}
		if (!vzero(m->transmit) && m->ior != 1 && (last - first < 4 || !closed_surface(sc, first, last)))
			open++;
		else if (!vzero(m->transmit) && m->ior != 1)
			for (size_t i = first; i < last; i++)
				if (sc->geo.triangles[i].n[0] != TRIANGLE_FLAT) {
					smooth_glass++;
					break;
				}
		first = last;
	}
	if (kept_as_mesh2)
		note(p, "// %zu smooth triangle(s) have vertex normals on both sides of the face: POV-Ray drops such"
		        " a smooth_triangle, so they are written as one-face mesh2 objects, which it keeps",
		     kept_as_mesh2);
	if (boundary)
		note(p, "// %zu mesh(es) have faces on a boundary of their checker and are kept as mesh2: its single-"
		        "precision vertices move such faces off the boundary to either side (cells may swap there)",
		     boundary);
	if (open)
		note(p, "// %zu refracting triangle object(s) are not closed, consistently wound surfaces: POV-Ray"
		        " enters such an object at its first hit and leaves at the next, while scn decides by the side"
		        " of each face (not pixel-exact where rays refract through them)",
		     open);
	if (smooth_glass)
		note(p, "// %zu refracting mesh(es) are shaded smooth: a ray refracted by an interpolated normal can stay on"
		        " the side of the face it came from; POV-Ray counts it as crossed, scn goes by the side of each face"
		        " it hits (not pixel-exact near their silhouettes)",
		     smooth_glass);
	size_t nested = 0, ntransmit = 0;
	size_t *glass = xmalloc((sc->geo.nspheres ? sc->geo.nspheres : 1) * sizeof *glass);
	for (size_t i = 0; i < sc->geo.nspheres; i++)
		if (!vzero(sc->materials[sc->geo.surfaces[sc->geo.spheres[i].surface].material].transmit))
			glass[ntransmit++] = i;
	/* pairs of transmitting spheres: a bounded search, enough for any hand-made scene */
	for (size_t i = 0; i < ntransmit && ntransmit <= 4096; i++) {
		const struct sphere *a = &sc->geo.spheres[glass[i]];
		for (size_t j = 0; j < ntransmit; j++) {
			const struct sphere *b = &sc->geo.spheres[glass[j]];
			if (j != i && vlen(vsub(a->center, b->center)) < a->radius + b->radius) {
				nested++;
				break;
			}
		}
	}
	free(glass);
	struct pov_solid_notes sn;
	pov_solid_notes(sc, &sn);
	if (sn.open)
		note(p, "// %zu refracting disc(s) and open cylinder(s) or cone(s) have no inside: POV-Ray enters such an"
		        " object at its first hit and leaves at the next, while scn decides by the side of each surface"
		        " (not pixel-exact where rays refract through them)",
		     sn.open);
	if (sn.iors)
		note(p, "// %zu transmitting solid(s) have members of different iors: POV-Ray tracks a ray's medium by"
		        " object, scn refracts at each surface by its own ior against air (not pixel-exact where a ray"
		        " enters through one member's surface and leaves through another's)",
		     sn.iors);
	if (sn.unions)
		note(p, "// %zu union(s) inside a solid have transmitting members that may overlap: POV-Ray leaves a"
		        " medium where scn enters a second member's surface (not pixel-exact where rays cross the overlap;"
		        " merge is the one-body form)",
		     sn.unions);
	if (sn.overlaps)
		note(p, "// %zu transmitting solid(s) may overlap another transmitting object: POV-Ray refracts by the"
		        " ratio of the two objects' iors where a ray passes from one into the other, scn by each surface's"
		        " ior against air (not pixel-exact there)",
		     sn.overlaps);
	size_t touching = 0;
	for (size_t i = 0; i < sc->geo.nspheres; i++) {
		const struct sphere *a = &sc->geo.spheres[i];
		bool touch = false;
		for (size_t k = 0; k < sc->geo.nplanes && !touch; k++)
			touch = fabs(fabs(vdot(sc->geo.planes[k].normal, a->center) - sc->geo.planes[k].offset) - a->radius) < CONTACT;
		for (size_t j = 0; j < sc->geo.nspheres && sc->geo.nspheres <= 4096 && !touch; j++)
			touch = j != i && fabs(vlen(vsub(a->center, sc->geo.spheres[j].center)) - a->radius -
			                       sc->geo.spheres[j].radius) < CONTACT;
		touching += touch;
	}
	if (touching)
		note(p, "// %zu sphere(s) touch a plane or another sphere: POV-Ray ignores hits closer than 1e-4 and"
		        " shadow occluders closer than 1e-3, scn has no such absolute tolerances (pixels whose rays pass"
		        " near a contact may differ)",
		     touching);
	if (nested)
		note(p, "// %zu transmitting sphere(s) overlap another: POV-Ray refracts by the ratio of the two"
		        " objects' iors where a ray passes from one into the other, scn by each surface's ior against"
		        " air (not pixel-exact there)",
		     nested);
}

/* Whether the n faces from a and those from b have the same materials, each the same
 * wherever it is placed: a plain colour, or an image looked up by UV coordinates (a
 * texture_list in the file's own space is moved by each placement, which these ignore). */
static bool same_textures(const struct scene *sc, size_t a, size_t b, size_t n)
{
	for (size_t i = 0; i < n; i++) {
		uint32_t sa = sc->geo.triangles[a + i].surface, sb = sc->geo.triangles[b + i].surface;
		const struct material *m = &sc->materials[sc->geo.surfaces[sa].material];
		if (sc->geo.surfaces[sa].material != sc->geo.surfaces[sb].material || m->bump >= 0 ||
		    (material_textured(m) && !uv_mapped(sc, sa)))
			return false;
	}
	return true;
}

/* Which mesh file objects written as mesh2 place one declared mesh2 (p->shares): those
 * with the same faces as the first such use of the same file, shaded alike; the others
 * (their faces differ where lowering dropped some) are written alone. */
static void find_shared(struct pov *p)
{
	const struct scene *sc = p->sc;
	p->use_of = xmalloc((sc->geo.nsurfaces ? sc->geo.nsurfaces : 1) * sizeof *p->use_of);
	for (size_t i = 0; i < sc->geo.nsurfaces; i++)
		p->use_of[i] = -1;
	size_t nuses = sc->nmesh_uses ? sc->nmesh_uses : 1;
	p->shares = xmalloc(nuses * sizeof *p->shares);
	p->run_of = xmalloc(nuses * sizeof *p->run_of);
	for (size_t u = 0; u < sc->nmesh_uses; u++) {
		p->use_of[sc->mesh_uses[u].surface] = (int32_t)u;
		p->shares[u] = -1;
	}
	int32_t *first_use = xmalloc((sc->nmesh_sources ? sc->nmesh_sources : 1) * sizeof *first_use);
	for (size_t m = 0; m < sc->nmesh_sources; m++)
		first_use[m] = -1;
	for (size_t first = 0; first < sc->geo.ntriangles;) {
		size_t last = unit_end(p, first);
		int32_t u = p->listed[first] >= 0 ? p->listed[first] : p->use_of[sc->geo.triangles[first].surface];
		if (u >= 0 && p->how[first] == WRITE_MESH2) {
			const struct mesh_use *use = &sc->mesh_uses[u];
			int32_t d = first_use[use->mesh];
			p->run_of[u] = first;
			if (d < 0)
				first_use[use->mesh] = u;
			else if (unit_end(p, p->run_of[d]) - p->run_of[d] == last - first &&
			         (p->listed[first] >= 0) == (p->listed[p->run_of[d]] >= 0) &&
			         pov_same_faces(sc, p->run_of[d], first, last - first, sc->mesh_uses[d].mirrored != use->mirrored) &&
			         (p->listed[first] < 0 || same_textures(sc, p->run_of[d], first, last - first)))
				p->shares[u] = p->shares[d] = d;
		}
		first = last;
	}
	free(first_use);
}

/* --- camera, sky, lights --- */

/* The centre and radius of a ball holding everything finite in the scene and reaching
 * every plane. */
static void scene_ball(const struct scene *sc, struct vec3 *centre, double *radius)
{
	struct vec3 lo = sc->camera.eye, hi = sc->camera.eye;
	for (size_t i = 0; i < sc->geo.nspheres; i++) {
		lo = vmin(lo, vsub(sc->geo.spheres[i].center, v3s(sc->geo.spheres[i].radius)));
		hi = vmax(hi, vadd(sc->geo.spheres[i].center, v3s(sc->geo.spheres[i].radius)));
	}
	for (size_t i = 0; i < sc->geo.nvertices; i++) {
		lo = vmin(lo, sc->geo.vertices[i]);
		hi = vmax(hi, sc->geo.vertices[i]);
	}
	for (size_t i = 0; i < sc->geo.nparts; i++) {
		const struct part *pt = &sc->geo.parts[i];
		if (pt->kind != PART_CSG && pt->kind != PART_PLANE) {  /* a leaf's surface bounds */
			lo = vmin(lo, pt->lo);
			hi = vmax(hi, pt->hi);
		}
	}
	for (size_t i = 0; i < sc->nlights; i++)
		if (sc->lights[i].kind == LIGHT_POINT) {
			lo = vmin(lo, sc->lights[i].pos);
			hi = vmax(hi, sc->lights[i].pos);
		}
	*centre = vscale(vadd(lo, hi), 0.5);
	double r = vlen(vsub(hi, lo)) / 2;
	for (size_t i = 0; i < sc->geo.nplanes; i++)
		r = fmax(r, fabs(sc->geo.planes[i].offset - vdot(sc->geo.planes[i].normal, *centre)));
	for (size_t i = 0; i < sc->geo.nparts; i++) {
		const struct part *pt = &sc->geo.parts[i];
		if (pt->kind == PART_PLANE)
			r = fmax(r, fabs(pt->a[3] - vdot(v3(pt->a[0], pt->a[1], pt->a[2]), *centre)));
	}
	*radius = r;
}

/* Focal blur: POV-Ray's aperture is four times scn's lens radius (camera_set_lens), and
 * its sharp plane lies at the focal point's distance, which the point on the view's axis
 * at that distance gives. Each pixel traces blur_samples rays, as many as scn's samples,
 * all of them (variance 0 turns off its early stop); POV-Ray places them on the lens and
 * in the pixel by its own rule, so the images agree in mean only. */
static void write_lens(struct pov *p)
{
	const struct camera *c = &p->sc->camera;
	if (!(c->lens_radius > 0))
		return;
	fputs(" aperture ", p->f);
	pov_num(p->f, 4 * c->lens_radius);
	fputs(" focal_point ", p->f);
	pov_vec(p->f, vadd(c->eye, vscale(c->dir, c->focal_distance)));
	fprintf(p->f, " blur_samples %d variance 0", p->sc->sampling.count);
}

static void write_camera(struct pov *p)
{
	const struct camera *c = &p->sc->camera;
	const struct pov_export_options *o = p->opt;
	FILE *f = p->f;
	bool given = o->look_at && o->up && o->fov > 0;
	bool ortho = c->kind == CAMERA_ORTHOGRAPHIC;
	fputs(ortho ? "camera { orthographic location " : "camera { perspective location ", f);
	pov_vec(f, c->eye);
	fputs(" look_at ", f);
	pov_vec(f, given ? v3a(o->look_at) : vadd(c->eye, c->dir));
	fputs(" sky ", f);
	pov_vec(f, given ? v3a(o->up) : c->up);
	if (ortho) {
		/* without an angle, POV-Ray's orthographic view spans right and up, whose lengths
		 * look_at keeps: the view's width, and the height as camera_ray computes it */
		fputs(" right x*", f);
		pov_num(f, c->view_width);
		fputs(" up y*", f);
		pov_num(f, c->view_width);
		fprintf(f, "*(%d/%d)", c->height, c->width);
		write_lens(p);
		fputs(" }\n", f);
		return;
	}
	fprintf(f, " right x*%d/%d up y angle ", c->width, c->height);
	pov_num(f, given ? o->fov : 2 * atan(c->tan_half) * (180 / M_PI));
	write_lens(p);
	fputs(" }\n", f);
}

/* POV-Ray's constant fog is scn's (povray-equivalence.md 15): e^(-t/D) on the segments of
 * the rays it follows outside every object (not hollow by default, as scn's solids), the
 * fog's colour on a ray that escapes, none on shadow rays. */
static void write_fog(struct pov *p)
{
	const struct fog *fog = &p->sc->fog;
	if (!(fog->distance > 0))
		return;
	fputs("fog { fog_type 1 distance ", p->f);
	pov_num(p->f, fog->distance);
	fputs(" color rgb ", p->f);
	pov_vec(p->f, fog->color);
	fputs(" }\n", p->f);
}

static void write_sky(struct pov *p)
{
	const struct sky *sky = &p->sc->sky;
	FILE *f = p->f;
	fputs("background { rgb ", f);
	pov_vec(f, sky->kind == SKY_CONSTANT ? sky->color : v3s(0));
	fputs(" }\n", f);
	if (sky->kind == SKY_ZENITH_HORIZON) {
		/* t = clamp(d.y, 0, 1); a plain gradient y would wrap below the horizon */
		fputs("sky_sphere { pigment { function { min(max(y, 0), 1) } color_map { [0 rgb ", f);
		pov_vec(f, sky->horizon);
		fputs("] [1 rgb ", f);
		pov_vec(f, sky->color);
		fputs("] } } }\n", f);
	} else if (sky->kind == SKY_LATLONG) {
		fputs("sky_sphere { pigment { image_map { ", f);
		pov_image_file(f, &sky->file, p->opt->sky_image, p->opt->pov_dir);
		fputs(" map_type 1 interpolate 2 } }", f);
		if (sky->intensity != 1) {
			fputs(" emission rgb ", f);
			pov_num(f, sky->intensity);
		}
		double deg = p->opt->sky_rotate ? *p->opt->sky_rotate : atan2(sky->rot_sin, sky->rot_cos) * (180 / M_PI);
		if (deg != 0) {
			fputs(" rotate <0, ", f);
			pov_num(f, deg);
			fputs(", 0>", f);
		}
		fputs(" }\n", f);
	}
}

static void write_lights(struct pov *p)
{
	const struct scene *sc = p->sc;
	FILE *f = p->f;
	struct vec3 centre;
	double radius;
	scene_ball(sc, &centre, &radius);
	double far = fmax(FAR_MIN, FAR_RADII * radius);
	for (size_t i = 0; i < sc->nlights; i++) {
		const struct light *l = &sc->lights[i];
		fputs("light_source { ", f);
		if (l->kind == LIGHT_POINT) {
			pov_vec(f, l->pos);
			fputs(" color rgb ", f);
			pov_vec(f, l->color);
		} else {
			/* far up-wind; shading uses exactly the direction to point_at */
			pov_vec(f, vadd(centre, vscale(l->to_light, far)));
			fputs(" color rgb ", f);
			pov_vec(f, l->color);
			fputs(" parallel point_at ", f);
			pov_vec(f, centre);
		}
		if (l->spot) {
			fputs(" spotlight point_at ", f);
			pov_vec(f, l->point_at);
			fputs(" radius ", f);
			pov_num(f, l->radius);
			fputs(" falloff ", f);
			pov_num(f, l->falloff);
			fputs(" tightness ", f);
			pov_num(f, l->tightness);
		}
		if (l->area >= 0) {
			/* POV-Ray's area_light without adaptive subdivides its grid fully (its
			 * Adaptive_Level defaults to 100): the weights scn computes; a lower level,
			 * when asked for, skips where the corners agree */
			const struct area_light *a = &sc->area_lights[l->area];
			fputs(" area_light ", f);
			pov_vec(f, a->axis[0]);
			fputs(", ", f);
			pov_vec(f, a->axis[1]);
			fprintf(f, ", %d, %d%s%s%s", a->size[0], a->size[1], a->jitter ? " jitter" : "",
			        a->circular ? " circular" : "", a->orient ? " orient" : "");
			if (p->opt->area_adaptive > 0)
				fprintf(f, " adaptive %d", p->opt->area_adaptive - 1);
		}
		if (l->fade_power > 0) {
			fputs(" fade_distance ", f);
			pov_num(f, l->fade_distance);
			fputs(" fade_power ", f);
			pov_num(f, l->fade_power);
		}
		if (l->shadowless)
			fputs(" shadowless", f);
		fputs(" }\n", f);
	}
}

/* --- the command line --- */

/* A word for the shell: quoted unless it is plain. */
static void shell_word(FILE *f, const char *prefix, const char *s)
{
	bool plain = *s != '\0';
	for (const char *c = s; *c; c++)
		plain &= (*c >= 'a' && *c <= 'z') || (*c >= 'A' && *c <= 'Z') || (*c >= '0' && *c <= '9') ||
		         strchr("._-/+,=@%:", *c) != NULL;
	if (plain) {
		fprintf(f, "%s%s", prefix, s);
		return;
	}
	fprintf(f, "'%s", prefix);
	for (const char *c = s; *c; c++) {
		if (*c == '\'')
			fputs("'\\''", f);
		else
			fputc(*c == '\n' ? ' ' : *c, f);
	}
	fputc('\'', f);
}

static void write_header(struct pov *p)
{
	const struct scene *sc = p->sc;
	const struct sampling *sp = &sc->sampling;
	FILE *f = p->f;
	const char *name = p->opt->pov_name ? p->opt->pov_name : "scene.pov";
	size_t len = strlen(name);
	size_t stem = len > 4 && strcmp(name + len - 4, ".pov") == 0 ? len - 4 : len;
	/* NAME-pov.png: NAME.png is what scn render writes by default, which POV-Ray's
	 * image must not overwrite */
	char *png = xmalloc(stem + 9);
	memcpy(png, name, stem);
	memcpy(png + stem, "-pov.png", 9);

	int scale = 1;                 /* grid: render n times the size and average n x n blocks */
	char aa[64] = "-A";
	if (sc->camera.lens_radius > 0) {
		/* focal blur samples the pixel itself (write_lens) */
	} else if (sp->count > 1 && sp->kind == SAMPLE_GRID) {
		scale = (int)lround(sqrt((double)sp->count));
	} else if (sp->count > 1) {
		/* +AM2 +Rd samples a (2^(d-1)+1)^2 lattice over the pixel: about count samples */
		int d = 1 + (int)lround(log2(sqrt((double)sp->count)));
		d = d < 1 ? 1 : d > 9 ? 9 : d;
		snprintf(aa, sizeof aa, "+A0.0 +AM2 +R%d -J", d);
	}

	fputs("// ", f);
	pov_comment_text(f, name);
	fputs(": the POV-Ray 3.7 equivalent of ", f);
	pov_comment_text(f, p->opt->source ? p->opt->source : "an scn scene");
	if (p->opt->generator) {
		fputs(", written by ", f);
		pov_comment_text(f, p->opt->generator);
	}
	fputs(".\n// Render it in this file's folder (a 16-bit linear PNG):\n// Render: povray -D ", f);
	fprintf(f, "%s +W%ld +H%ld +FN16 File_Gamma=1.0 ", aa, (long)sc->camera.width * scale,
	        (long)sc->camera.height * scale);
	shell_word(f, "+I", name);
	fputc(' ', f);
	shell_word(f, "+O", png);
	fputc('\n', f);
	free(png);
	fputs("// How each feature is translated, and where POV-Ray's image differs: " POV_DOCDIR "/povray.md"
	      " (doc/povray.md in scn's source).\n", f);

	static const char *const pattern[] = { "center", "grid", "random", "jittered", "poisson" };
	if (scale > 1)
		fprintf(f,
		        "// samples { count %d pattern grid }: that renders %d x %d, one ray through each pixel centre;"
		        " the mean of each %d x %d block of its pixels is the %d x %d image (scn diff SCN.png THIS.png"
		        " --downsample %d), except where a block has pixels brighter than 1, which POV-Ray clips before"
		        " the mean is taken.\n",
		        sp->count, sc->camera.width * scale, sc->camera.height * scale, scale, scale, sc->camera.width,
		        sc->camera.height, scale);
	else if (sp->kind != SAMPLE_CENTER && sp->kind != SAMPLE_GRID)
		fprintf(f,
		        "// samples { count %d pattern %s }: NOT pixel-exact: POV-Ray cannot place scn's random samples;"
		        " %s is its nearest anti-aliasing.\n",
		        sp->count, pattern[sp->kind], aa);
	if (sp->target_error > 0 && sp->count > 1)
		fprintf(f, "// target_error %g: NOT pixel-exact: scn stops sampling a pixel early where its error is small,"
		           " POV-Ray does not.\n", sp->target_error);
	if (sc->camera.lens_radius > 0 && sc->camera.kind == CAMERA_ORTHOGRAPHIC)
		fputs("// focal blur with an orthographic camera: NOT pixel-exact: POV-Ray 3.7 renders it black (measured).\n",
		      f);
	else if (sc->camera.lens_radius > 0)
		fputs("// focal blur: NOT pixel-exact: POV-Ray places its blur_samples on the lens and in the pixel by its own"
		      " rule; the images agree in their mean.\n", f);
	for (size_t i = 0; i < sc->narea_lights; i++)
		if (sc->area_lights[i].jitter) {
			fputs("// area_light jitter: NOT pixel-exact: POV-Ray jitters by its own random numbers; the images"
			      " agree in their mean.\n", f);
			break;
		}
	if (p->notes)
		fputs(p->notes, f);
	fprintf(f, "#version 3.7;\nglobal_settings { assumed_gamma 1.0 max_trace_level %d adc_bailout 0"
	           " ambient_light rgb 0 }\n", sc->max_depth);
}

/* "sphere { C, r MATERIAL }", "plane { N, d MATERIAL }": POV-Ray spells both alike. */
static void write_vec_num_shape(struct pov *p, const char *keyword, struct vec3 v, double x, uint32_t surface)
{
	fprintf(p->f, "%s { ", keyword);
	pov_vec(p->f, v);
	fputs(", ", p->f);
	pov_num(p->f, x);
	fputc(' ', p->f);
	pov_material_ref(p->f, p->sc, surface, false);
	fputs(" }\n", p->f);
}

/* A sphere whose material is an image looked up by UV coordinates, turned as its object is:
 * POV-Ray's uv_mapping reads the sphere's own rotation (its Trans), which a world-space
 * sphere lacks, so it is written about the origin and placed by the object's map with the
 * scale taken out (the radius carries it). The material follows the placement, so that a
 * bump pattern's object transform applies once; a uv-mapped pigment ignores it. */
static bool write_turned_uv_sphere(struct pov *p, const struct sphere *s)
{
	const struct scene *sc = p->sc;
	const struct surface *srf = &sc->geo.surfaces[s->surface];
	if (srf->to_object < 0 || !uv_mapped(sc, s->surface))
		return false;
	/* to_object's linear part is R^-1 / s for a rotation (or mirror) R and a scale s */
	const struct affine *to = &sc->affines[srf->to_object];
	double k = 1 / vlen(v3(to->m[0][0], to->m[0][1], to->m[0][2]));
	struct affine to_own;
	for (int r = 0; r < 3; r++) {
		for (int c = 0; c < 3; c++)
			to_own.m[r][c] = to->m[r][c] * k;
		to_own.m[r][3] = -(to_own.m[r][0] * s->center.x + to_own.m[r][1] * s->center.y + to_own.m[r][2] * s->center.z);
	}
	fputs("sphere { <0, 0, 0>, ", p->f);
	pov_num(p->f, s->radius);
	fputs(" transform { ", p->f);
	pov_matrix(p->f, &to_own);
	fputs(" inverse } ", p->f);
	pov_material_ref(p->f, sc, s->surface, false);
	fputs(" }\n", p->f);
	return true;
}

static void write_objects(struct pov *p)
{
	const struct scene *sc = p->sc;
	for (size_t i = 0; i < sc->geo.nspheres; i++)
		if (!write_turned_uv_sphere(p, &sc->geo.spheres[i]))
			write_vec_num_shape(p, "sphere", sc->geo.spheres[i].center, sc->geo.spheres[i].radius,
			                    sc->geo.spheres[i].surface);
	for (size_t i = 0; i < sc->geo.nplanes; i++)
		write_vec_num_shape(p, "plane", sc->geo.planes[i].normal, sc->geo.planes[i].offset, sc->geo.planes[i].surface);
	for (size_t first = 0; first < sc->geo.ntriangles;) {
		size_t last = unit_end(p, first);
		int32_t placed = p->listed[first] >= 0 ? p->listed[first] : p->use_of[sc->geo.triangles[first].surface];
		if (p->how[first] == WRITE_TRIANGLE)
			write_triangle(p, first);
		else if (p->how[first] == WRITE_UNION)
			write_union(p, first, last);
		else if (placed >= 0 && p->shares[placed] >= 0)
			write_placed(p, first, last, placed);
		else
			write_mesh2(p, first, last, p->listed[first] >= 0);
		first = last;
	}
	for (size_t i = 0; i < sc->geo.nsolids; i++)
		pov_write_solid(p->f, sc, sc->geo.solids[i]);
	for (size_t i = 0; i < sc->geo.nunbounded; i++)
		pov_write_solid(p->f, sc, sc->geo.unbounded[i]);
}

/* pov_export, naming the output what in its messages. */
static int export_to(const struct scene *sc, const struct pov_export_options *opt, FILE *out, const char *what,
                     char *err, size_t errlen)
{
	static const struct pov_export_options none = { 0 };
	struct pov p = { .f = out, .sc = sc, .opt = opt ? opt : &none };
	if (errlen)
		err[0] = '\0';
	if (sc->sky.kind == SKY_LATLONG) {
		if (!p.opt->sky_image) {
			snprintf(err, errlen, "the skybox image's file name is not known");
			return EINVAL;
		}
		if (sc->sky.file.exr_not_half)
			note(&p, "// The skybox image has 32-bit float channels: POV-Ray reads OpenEXR as half floats, so"
			         " its sky differs by up to about 2.4e-4 of each value (half-float images agree exactly)");
	}
	p.how = xcalloc(sc->geo.ntriangles ? sc->geo.ntriangles : 1, sizeof *p.how);
	find_listed(&p);
	analyse(&p);
	find_shared(&p);
	write_header(&p);
	write_camera(&p);
	write_sky(&p);
	write_fog(&p);
	write_lights(&p);
	/* the materials that members of a one-body solid take without their interior */
	bool *shared = xcalloc(sc->nmaterials ? sc->nmaterials : 1, sizeof *shared);
	for (size_t i = 0; i < sc->geo.nsolids + sc->geo.nunbounded; i++)
		pov_solid_one_body(sc, i < sc->geo.nsolids ? sc->geo.solids[i] : sc->geo.unbounded[i - sc->geo.nsolids], shared);
	for (size_t i = 0; i < sc->nmaterials; i++)
		pov_write_material(out, sc, i, shared[i], p.listed_material[i], p.opt->pov_dir);
	free(shared);
	write_objects(&p);
	free(p.how);
	free(p.use_of);
	free(p.shares);
	free(p.run_of);
	free(p.listed);
	free(p.listed_material);
	free(p.notes);
	int rc = 0;
	errno = 0;
	if (fflush(out) != 0 || ferror(out)) {
		rc = errno ? errno : EIO;
		snprintf(err, errlen, "cannot write %s: %s", what, strerror(rc));
	}
	return rc;
}

int pov_export(const struct scene *sc, const struct pov_export_options *opt, FILE *out, char *err, size_t errlen)
{
	return export_to(sc, opt, out, "the POV-Ray scene", err, errlen);
}

int pov_export_file(const struct scene *sc, const struct pov_export_options *opt, const char *path, char *err,
                    size_t errlen)
{
	char *tmp;
	int fd = outfile_open(path, &tmp, err, errlen);
	if (fd < 0)
		return -fd;
	/* a stream on a second descriptor: fclose flushes and closes it, and outfile_finish
	 * syncs and closes the first */
	int dup_fd = dup(fd);
	FILE *f = dup_fd >= 0 ? fdopen(dup_fd, "w") : NULL;
	if (!f) {
		int e = errno;
		if (dup_fd >= 0)
			close(dup_fd);
		return outfile_finish(fd, tmp, path, e, err, errlen);
	}
	char *what = xmalloc(strlen(path) + 3);
	sprintf(what, "'%s'", path);
	int rc = export_to(sc, opt, f, what, err, errlen);
	free(what);
	if (fclose(f) != 0 && rc == 0)
		rc = errno ? errno : EIO;
	return outfile_finish(fd, tmp, path, rc, err, errlen);
}
