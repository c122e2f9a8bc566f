/* test_mesh_import.c: mesh_import on the small files of tests/unit/meshes/: what it reads
 * (materials and UVs too), what it leaves out, the messages it gives for broken files, that
 * assimp stays quiet, and that Debian's assimp test models read sanely where installed. */
#include <errno.h>
#include <ftw.h>
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

#include "check.h"
#include "image_file.h"
#include "mesh_import.h"

#if defined(__SANITIZE_ADDRESS__)
#define HAVE_LSAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define HAVE_LSAN 1
#endif
#endif
#ifdef HAVE_LSAN
#include <sanitizer/lsan_interface.h>
#endif

/* The fixture's path: under $SCN_SRCDIR, which the harness sets, or under the current
 * directory when the test is run by hand from the source tree. */
static const char *fixture(const char *name)
{
	static char path[4096];
	const char *dir = getenv("SCN_SRCDIR");
	snprintf(path, sizeof path, "%s/tests/unit/meshes/%s", dir && *dir ? dir : ".", name);
	return path;
}

/* Imports a fixture that must load; on failure prints why and leaves *m empty. */
static bool load(const char *name, struct mesh_data *m)
{
	char err[512];
	if (mesh_import(fixture(name), m, err, sizeof err) == 0)
		return true;
	fprintf(stderr, "%s: unexpected error: %s\n", name, err);
	check_failures++;
	return false;
}

static void corner(const struct mesh_data *m, size_t f, int k, double p[3])
{
	memcpy(p, m->vertices[m->faces[f][k]], sizeof(double[3]));
}

/* The face's (B-A) x (C-A): its geometric normal, twice its area long. */
static void face_cross(const struct mesh_data *m, size_t f, double n[3])
{
	double a[3], b[3], c[3];
	corner(m, f, 0, a), corner(m, f, 1, b), corner(m, f, 2, c);
	double e[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
	double g[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
	n[0] = e[1] * g[2] - e[2] * g[1];
	n[1] = e[2] * g[0] - e[0] * g[2];
	n[2] = e[0] * g[1] - e[1] * g[0];
}

static double total_area(const struct mesh_data *m)
{
	double sum = 0;
	for (size_t f = 0; f < m->nfaces; f++) {
		double n[3];
		face_cross(m, f, n);
		sum += 0.5 * sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
	}
	return sum;
}

static bool indices_in_range(const struct mesh_data *m)
{
	for (size_t f = 0; f < m->nfaces; f++)
		for (int k = 0; k < 3; k++)
			if (m->faces[f][k] >= m->nvertices)
				return false;
	return true;
}

/* Whether some vertex of m is within tol of p. */
static bool has_vertex(const struct mesh_data *m, double x, double y, double z, double tol)
{
	for (size_t i = 0; i < m->nvertices; i++)
		if (fabs(m->vertices[i][0] - x) <= tol && fabs(m->vertices[i][1] - y) <= tol &&
		    fabs(m->vertices[i][2] - z) <= tol)
			return true;
	return false;
}

/* Checks that every face of m faces along +z, with the winding of the file. */
static void check_faces_up(const struct mesh_data *m)
{
	for (size_t f = 0; f < m->nfaces; f++) {
		double n[3];
		face_cross(m, f, n);
		CHECK(n[2] > 0 && n[0] == 0 && n[1] == 0);
	}
}

static void test_obj(void)
{
	struct mesh_data m;
	if (!load("square.obj", &m))
		return;
	CHECK(m.nvertices == 4);
	CHECK(m.nfaces == 2);
	CHECK(m.nnormals == 0 && m.normals == NULL);
	CHECK(indices_in_range(&m));
	CHECK(has_vertex(&m, 0, 0, 0, 0) && has_vertex(&m, 1, 0, 0, 0) && has_vertex(&m, 1, 1, 0, 0) &&
	      has_vertex(&m, 0, 1, 0, 0));
	CHECK_NEAR(total_area(&m), 1, 1e-15);
	check_faces_up(&m);
	mesh_import_free(&m);
	CHECK(m.vertices == NULL && m.faces == NULL && m.nvertices == 0 && m.nfaces == 0);
	mesh_import_free(&m); /* freeing an empty one is harmless */
}

static void test_quad(void)
{
	struct mesh_data m;
	if (!load("quad.obj", &m))
		return;
	CHECK(m.nvertices == 4);
	CHECK(m.nfaces == 2);
	CHECK(indices_in_range(&m));
	CHECK_NEAR(total_area(&m), 2, 1e-15);
	check_faces_up(&m);
	mesh_import_free(&m);
}

static void test_normals(void)
{
	struct mesh_data m;
	if (!load("normals.obj", &m))
		return;
	/* the two ridge corners are split by their normals: 3 + 3 vertices */
	CHECK(m.nfaces == 2);
	CHECK(m.nvertices == 6);
	CHECK(m.nnormals == m.nvertices && m.normals != NULL);
	if (m.nnormals != m.nvertices) {
		mesh_import_free(&m);
		return;
	}
	for (size_t f = 0; f < m.nfaces; f++) {
		double g[3];
		face_cross(&m, f, g);
		double side = g[0] < 0 ? -1 : 1; /* the left or the right slope of the roof */
		for (int k = 0; k < 3; k++) {
			const double *n = m.normals[m.faces[f][k]];
			CHECK_NEAR(n[0], side * sqrt(0.5), 1e-15);
			CHECK_NEAR(n[1], sqrt(0.5), 1e-15);
			CHECK(n[2] == 0);
		}
	}
	mesh_import_free(&m);
}

static void test_partial_normals(void)
{
	struct mesh_data m;
	if (!load("partial_normals.obj", &m))
		return;
	CHECK(m.nnormals == 0 && m.normals == NULL);
	CHECK(m.nfaces == 2);
	CHECK(m.nvertices == 4); /* joined again once the normals are gone */
	CHECK(indices_in_range(&m));
	mesh_import_free(&m);
}

static void test_ascii_ply(void)
{
	struct mesh_data m;
	if (!load("ascii.ply", &m))
		return;
	CHECK(m.nvertices == 5);
	CHECK(m.nfaces == 3); /* the quad split in two, and the triangle */
	CHECK(indices_in_range(&m));
	CHECK(has_vertex(&m, 0.5, 0.5, 1, 0));
	CHECK_NEAR(total_area(&m), 1 + 0.5 * sqrt(1.25), 1e-15);
	CHECK(m.nnormals == 5);
	for (size_t i = 0; i < m.nnormals; i++)
		CHECK(m.normals[i][0] == 0 && m.normals[i][1] == 0 && m.normals[i][2] == 1);
	mesh_import_free(&m);
}

static void test_binary_ply(void)
{
	struct mesh_data m;
	if (!load("binary.ply", &m))
		return;
	CHECK(m.nvertices == 4);
	CHECK(m.nfaces == 2);
	CHECK(m.nnormals == 0);
	CHECK(indices_in_range(&m));
	CHECK(has_vertex(&m, 0.25, 0.5, -1.5, 0));
	CHECK(has_vertex(&m, 1, 1, 0, 0));
	mesh_import_free(&m);
}

/* Header lines that assimp reads past pass the header checks, which guard only memory:
 * the file loads as assimp reads it. */
static void test_unknown_header_lines(void)
{
	struct mesh_data m;
	if (!load("unknown_lines.ply", &m))
		return;
	CHECK(m.nvertices == 3 && m.nfaces == 1);
	CHECK(has_vertex(&m, 1, 0, 0, 0) && has_vertex(&m, 0, 1, 0, 0));
	mesh_import_free(&m);
}

/* One triangle placed by two nodes: the transforms are applied, normals included. */
static void test_nodes(void)
{
	struct mesh_data m;
	if (!load("nodes.gltf", &m))
		return;
	CHECK(m.nfaces == 2);
	CHECK(m.nvertices == 6);
	CHECK(indices_in_range(&m));
	/* float transforms: exact to about 1e-7 of the size */
	const double tol = 1e-6;
	CHECK(has_vertex(&m, 10, 0, 0, tol) && has_vertex(&m, 11, 0, 0, tol) && has_vertex(&m, 10, 1, 0, tol));
	CHECK(has_vertex(&m, 0, 0, 10, tol) && has_vertex(&m, 0, 0, 8, tol) && has_vertex(&m, 0, 2, 10, tol));
	CHECK(m.nnormals == 6);
	for (size_t f = 0; m.nnormals == 6 && f < m.nfaces; f++) {
		bool moved = m.vertices[m.faces[f][0]][0] > 5; /* the first node's copy */
		for (int k = 0; k < 3; k++) {
			const double *n = m.normals[m.faces[f][k]];
			CHECK_NEAR(n[0], moved ? 0 : 1, tol);
			CHECK_NEAR(n[2], moved ? 1 : 0, tol);
		}
	}
	mesh_import_free(&m);
}

static void test_points_and_lines_left_out(void)
{
	struct mesh_data m;
	if (!load("mixed.obj", &m))
		return;
	CHECK(m.nfaces == 1);
	CHECK(indices_in_range(&m));
	for (size_t f = 0; f < m.nfaces; f++)
		for (int k = 0; k < 3; k++)
			CHECK(m.vertices[m.faces[f][k]][0] != 5);
	mesh_import_free(&m);
}

/* mesh_import, for a file on which assimp's reader throws and leaks what it had built:
 * assimp 5.2's PLY reader its aiMesh (~PLYImporter does not free mGeneratedMesh; later
 * assimp does). The leak is inside libassimp, so LeakSanitizer ignores what is allocated
 * during this one call, and still checks every other import for a scene we forgot to
 * release. */
static int import_leaky(const char *path, struct mesh_data *m, char *err, size_t errlen)
{
#ifdef HAVE_LSAN
	__lsan_disable();
#endif
	int rc = mesh_import(path, m, err, errlen);
#ifdef HAVE_LSAN
	__lsan_enable();
#endif
	return rc;
}

/* Imports a file that must fail (through import_leaky if assimp leaks on it), and checks
 * that the message names it and contains want and also (unless NULL), that it ends
 * without a full stop or newline, and that *out is left empty. */
static void expect_error(const char *path, bool leaks, const char *want, const char *also)
{
	struct mesh_data m;
	char err[512] = "";
	int rc = leaks ? import_leaky(path, &m, err, sizeof err) : mesh_import(path, &m, err, sizeof err);
	size_t len = strlen(err);
	if (rc == 0 || !strstr(err, path) || !strstr(err, want) || (also && !strstr(err, also)) || len == 0 ||
	    err[len - 1] == '.' || err[len - 1] == '\n') {
		fprintf(stderr, "%s: rc %d, message: %s\n  expected one with '%s'%s%s%s\n", path, rc, err, want,
		        also ? " and '" : "", also ? also : "", also ? "'" : "");
		check_failures++;
	}
	CHECK(m.vertices == NULL && m.normals == NULL && m.faces == NULL);
	CHECK(m.nvertices == 0 && m.nnormals == 0 && m.nfaces == 0);
	mesh_import_free(&m);
}

/* Writes text into the file name in dir and returns its path (a static buffer). */
static const char *write_file(const char *dir, const char *name, const char *text)
{
	static char path[4096];
	snprintf(path, sizeof path, "%s/%s", dir, name);
	FILE *f = fopen(path, "w");
	CHECK(f && fputs(text, f) >= 0 && fclose(f) == 0);
	return path;
}

/* Whether a corner of face f of m is at (x, y, 0). */
static bool has_corner(const struct mesh_data *m, size_t f, double x, double y)
{
	for (int k = 0; k < 3; k++) {
		const double *v = m->vertices[m->faces[f][k]];
		if (v[0] == x && v[1] == y && v[2] == 0)
			return true;
	}
	return false;
}

static void check_rgb(const double c[3], double r, double g, double b)
{
	CHECK(c[0] == r && c[1] == g && c[2] == b);
}

/* PLY's texture coordinates, by either pair of names: (x / 2, 3y / 4) at each vertex. */
static void test_ply_uvs(void)
{
	static const char *const names[] = { "uv.ply", "st.ply" };
	for (size_t i = 0; i < sizeof names / sizeof *names; i++) {
		struct mesh_data m;
		if (!load(names[i], &m))
			continue;
		CHECK(m.nvertices == 4 && m.nfaces == 2);
		CHECK(m.uvs != NULL && m.nuvs == 4);
		for (size_t v = 0; m.uvs && v < m.nvertices; v++)
			CHECK(m.uvs[v][0] == 0.5 * m.vertices[v][0] && m.uvs[v][1] == 0.75 * m.vertices[v][1]);
		mesh_import_free(&m);
	}
}

/* The bytes of a fixture file, into buf (at most n); returns their number. */
static size_t read_fixture(const char *name, unsigned char *buf, size_t n)
{
	FILE *f = fopen(fixture(name), "rb");
	size_t got = f ? fread(buf, 1, n, f) : 0;
	if (f)
		fclose(f);
	return got;
}

/* An embedded texture's bytes decode as the file they came from does, and when cut
 * short are refused with a message naming what the caller calls them. */
static void check_png_memory(const unsigned char *data, size_t size)
{
	struct image *mem, *file;
	char err[512];
	CHECK(image_read_png_memory(data, size, "box.glb's texture *0", &mem, err, sizeof err) == 0);
	CHECK(image_read(fixture("textures/checker.png"), &file, err, sizeof err) == 0);
	if (mem && file) {
		CHECK(mem->width == 2 && mem->height == 2 && file->width == 2 && file->height == 2);
		CHECK(memcmp(mem->rgb, file->rgb, 2 * 2 * 3 * sizeof *mem->rgb) == 0);
		CHECK(mem->rgb[0] == 1 && mem->rgb[3] == 0); /* white, then black */
	}
	image_free(mem);
	image_free(file);
	CHECK(image_read_png_memory(data, size - 20, "box.glb's texture *0", &mem, err, sizeof err) == EINVAL);
	CHECK(mem == NULL && strstr(err, "cannot read 'box.glb's texture *0': truncated PNG file") != NULL);
}

/* glTF: a base colour texture as a file, then embedded; TEXCOORD_0, whose v runs down
 * in the file and up here; alpha modes; a primitive without a material. */
static void test_gltf_materials(void)
{
	struct mesh_data m;
	if (load("textured.gltf", &m)) {
		CHECK(m.nvertices == 4 && m.nfaces == 2 && m.nuvs == 4);
		for (size_t v = 0; m.uvs && v < m.nvertices; v++)
			CHECK(m.uvs[v][0] == m.vertices[v][0] && m.uvs[v][1] == m.vertices[v][1]);
		/* its one material; the one assimp adds for primitives without is not used */
		CHECK(m.nmaterials == 1);
		for (size_t f = 0; m.face_material && f < m.nfaces; f++)
			CHECK(m.face_material[f] == 0);
		for (size_t i = 0; i < m.nmaterials; i++) {
			const struct mesh_material *l = &m.materials[i];
			CHECK(strcmp(l->name, "label") == 0);
			check_rgb(l->diffuse, 1, 0.5, 0.25);
			CHECK(l->opacity == 0.5); /* alpha mode BLEND */
			check_rgb(l->emission, 0, 0.25, 0);
			check_rgb(l->specular, 0, 0, 0);
			CHECK(l->ior == 1);
			CHECK(l->texture && strcmp(l->texture, "textures/checker.png") == 0);
			CHECK(l->texture_path && strcmp(l->texture_path, fixture("textures/checker.png")) == 0);
			CHECK(l->texture_data == NULL);
		}
		mesh_import_free(&m);
	}
	if (!load("embedded.gltf", &m))
		return;
	CHECK(m.nfaces == 3 && m.nvertices == 7 && m.nuvs == 7);
	CHECK(m.nmaterials == 1 && m.face_material != NULL);
	for (size_t f = 0; m.face_material && m.uvs && f < m.nfaces; f++) {
		bool side = has_corner(&m, f, 3, 0); /* the triangle without a material or UVs */
		CHECK(m.face_material[f] == (side ? MESH_NO_MATERIAL : 0));
		for (int k = 0; k < 3; k++) {
			const double *v = m.vertices[m.faces[f][k]], *uv = m.uvs[m.faces[f][k]];
			CHECK(uv[0] == (side ? 0 : v[0]) && uv[1] == (side ? 0 : v[1]));
		}
	}
	unsigned char png[256];
	size_t npng = read_fixture("textures/checker.png", png, sizeof png);
	CHECK(npng == 73);
	for (size_t i = 0; i < m.nmaterials; i++) {
		const struct mesh_material *e = &m.materials[i];
		CHECK(strcmp(e->name, "") == 0);
		check_rgb(e->diffuse, 0.5, 0.5, 0.5);
		CHECK(e->opacity == 1); /* alpha 0.5, but the alpha mode is OPAQUE */
		CHECK(e->texture && strcmp(e->texture, "*0") == 0);
		CHECK(e->texture_path == NULL);
		CHECK(strcmp(e->texture_format, "png") == 0);
		CHECK(e->texture_data && e->texture_size == npng && memcmp(e->texture_data, png, npng) == 0);
		if (e->texture_data)
			check_png_memory(e->texture_data, e->texture_size);
	}
	mesh_import_free(&m);
}

/* The UV that materials.obj gives the corner at (x, y) in a face of material mat. */
static void materials_obj_uv(uint32_t mat, double x, double y, double uv[2])
{
	if (mat == 0) { /* the quad from (0, 0) to (1, 1), its UVs its positions */
		uv[0] = x, uv[1] = y;
		return;
	}
	static const double quad[4][4] = { { 1, 0, 0, 0 }, { 2, 0, 0.5, 0.25 }, { 2, 1, 0.75, 1 }, { 1, 1, 1, 1 } };
	for (int i = 0; i < 4; i++)
		if (quad[i][0] == x && quad[i][1] == y)
			uv[0] = quad[i][2], uv[1] = quad[i][3];
}

/* An OBJ with an MTL of two materials used and one not, UVs and a seam. */
static void test_obj_materials(void)
{
	struct mesh_data m;
	if (!load("materials.obj", &m))
		return;
	CHECK(m.nfaces == 4);
	/* six positions, the seam's at (1, 0, 0) twice; the corner at (1, 1, 0) has the
	 * same UV in both quads, and its two materials do not split it */
	CHECK(m.nvertices == 7);
	CHECK(m.nnormals == 7);
	CHECK(m.uvs != NULL && m.nuvs == m.nvertices);
	CHECK(indices_in_range(&m));
	CHECK(m.nmaterials == 2 && m.materials != NULL && m.face_material != NULL);
	if (m.nmaterials != 2 || !m.uvs || !m.face_material) {
		mesh_import_free(&m);
		return;
	}
	const struct mesh_material *red = &m.materials[0], *tex = &m.materials[1];
	CHECK(strcmp(red->name, "red") == 0);
	check_rgb(red->diffuse, 1, 0, 0);
	CHECK(red->texture == NULL && red->texture_path == NULL && red->texture_data == NULL);
	CHECK(red->texture_size == 0 && red->texture_format[0] == '\0');
	check_rgb(red->specular, 0.5, 0.25, 0.125);
	CHECK(red->exponent == 64);
	CHECK(red->opacity == 0.75);
	CHECK(red->ior == 1.5);
	check_rgb(red->emission, 0.25, 0.5, 0);

	CHECK(strcmp(tex->name, "textured") == 0);
	check_rgb(tex->diffuse, 0.5, 0.5, 0.5);
	CHECK(tex->texture && strcmp(tex->texture, "textures/checker.png") == 0);
	CHECK(tex->texture_path && strcmp(tex->texture_path, fixture("textures/checker.png")) == 0);
	CHECK(tex->texture_data == NULL && tex->texture_format[0] == '\0');
	check_rgb(tex->specular, 0, 0, 0);
	CHECK(tex->exponent == 0); /* assimp's OBJ reader gives 0 for a material without Ns */
	CHECK(tex->opacity == 1 && tex->ior == 1);
	check_rgb(tex->emission, 0, 0, 0);

	size_t per_material[2] = { 0, 0 };
	for (size_t f = 0; f < m.nfaces; f++) {
		uint32_t mat = m.face_material[f];
		CHECK(mat < 2);
		if (mat >= 2)
			continue;
		per_material[mat]++;
		for (int k = 0; k < 3; k++) {
			uint32_t v = m.faces[f][k];
			double want[2] = { -1, -1 };
			materials_obj_uv(mat, m.vertices[v][0], m.vertices[v][1], want);
			CHECK(m.uvs[v][0] == want[0] && m.uvs[v][1] == want[1]);
		}
	}
	CHECK(per_material[0] == 2 && per_material[1] == 2);
	mesh_import_free(&m);
	CHECK(m.uvs == NULL && m.face_material == NULL && m.materials == NULL && m.nmaterials == 0 && m.nuvs == 0);
}

/* A material written on Windows, with Tr, on a triangle without UVs. */
static void test_obj_tr_and_backslash(void)
{
	struct mesh_data m;
	if (!load("glass.obj", &m))
		return;
	CHECK(m.uvs == NULL && m.nuvs == 0);
	CHECK(m.nmaterials == 1);
	for (size_t i = 0; i < m.nmaterials; i++) {
		const struct mesh_material *g = &m.materials[i];
		CHECK(strcmp(g->name, "glass") == 0);
		CHECK(g->opacity == 0.75); /* Tr 0.25 */
		CHECK(g->diffuse[0] == (float)0.6); /* assimp's OBJ default, in float */
		CHECK(g->texture && strcmp(g->texture, "textures\\checker.png") == 0);
		CHECK(g->texture_path && strcmp(g->texture_path, fixture("textures/checker.png")) == 0);
	}
	for (size_t f = 0; m.face_material && f < m.nfaces; f++)
		CHECK(m.face_material[f] == 0);
	mesh_import_free(&m);
}

/* Files without materials of their own: assimp makes one up for each, which is not
 * taken (embedded.gltf mixes such faces with others). An OBJ's usemtl of a material its
 * MTL lacks is another matter: assimp gives it its default values under that name, and
 * it is the file's. */
static void test_made_up_materials(void)
{
	static const char *const names[] = { "square.obj", "uv.ply", "ascii.ply", "nodes.gltf" };
	for (size_t i = 0; i < sizeof names / sizeof *names; i++) {
		struct mesh_data m;
		if (!load(names[i], &m))
			continue;
		CHECK(m.nmaterials == 0 && m.materials == NULL && m.face_material == NULL);
		mesh_import_free(&m);
	}

	char tmp[] = "/tmp/scn-test-mesh-XXXXXX";
	CHECK(mkdtemp(tmp) != NULL);
	char mtl[64];
	snprintf(mtl, sizeof mtl, "%s", write_file(tmp, "some.mtl", "newmtl blue\nKd 0 0 1\n"));
	const char *path = write_file(tmp, "some.obj", "mtllib some.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n"
	                              "usemtl blue\nf 2 4 3\nusemtl missing\nf 1 2 3\n");
	struct mesh_data m;
	char err[512];
	CHECK(mesh_import(path, &m, err, sizeof err) == 0);
	CHECK(m.nfaces == 2 && m.nmaterials == 2 && m.face_material != NULL);
	if (m.nmaterials == 2 && m.face_material) {
		CHECK(strcmp(m.materials[0].name, "blue") == 0);
		check_rgb(m.materials[0].diffuse, 0, 0, 1);
		CHECK(strcmp(m.materials[1].name, "missing") == 0);
		check_rgb(m.materials[1].diffuse, (float)0.6, (float)0.6, (float)0.6);
		for (size_t f = 0; f < m.nfaces; f++)
			CHECK(m.face_material[f] == (has_corner(&m, f, 0, 0) ? 1 : 0));
	}
	mesh_import_free(&m);
	unlink(path);
	unlink(mtl);
	rmdir(tmp);
}

static void test_errors(void)
{
	expect_error(fixture("no_such_file.obj"), false, "cannot read mesh file '", strerror(ENOENT));
	/* the fixture directory itself: it opens, but cannot be read */
	char dir[4096];
	snprintf(dir, sizeof dir, "%s", fixture(""));
	dir[strlen(dir) - 1] = '\0';
	expect_error(dir, false, "cannot read mesh file '", strerror(EISDIR));
	expect_error(fixture("empty.obj"), false, "malformed mesh file '", NULL);
	expect_error(fixture("garbage.bin"), false, "malformed mesh file '", NULL);
	expect_error(fixture("bad_index.obj"), false, "malformed mesh file '", "out of range");
	expect_error(fixture("bad_number.ply"), true, "malformed mesh file '", "oops");
	expect_error(fixture("truncated.ply"), false, "malformed mesh file '", NULL);
	expect_error(fixture("lines.obj"), false, "no triangles in '", NULL);
	/* assimp's PLY reader would loop forever on this one */
	expect_error(fixture("no_end_header.ply"), false, "malformed mesh file '", "end_header");
	/* and would ask for gigabytes for a header's counts that the file cannot hold */
	expect_error(fixture("cut_faces.ply"), false, "malformed mesh file '",
	             "its PLY header declares 2 'face' elements, more than its 24 bytes can hold");
	/* the same for an OFF header; the keyword is read as assimp reads it */
	static const char *const off[] = { "OFF\n# big\n1000 2000 0\n0 0 0\n", "CnOFF 3\n1000 2000\n",
		"OFF1000 2000 0\n0 0 0\n", "1000 2000 0\n" };
	char tmp[] = "/tmp/scn-test-mesh-XXXXXX", path[64];
	CHECK(mkdtemp(tmp) != NULL);
	snprintf(path, sizeof path, "%s/big.off", tmp);
	for (size_t i = 0; i < sizeof off / sizeof *off; i++) {
		FILE *f = fopen(path, "w");
		CHECK(f && fputs(off[i], f) >= 0 && fclose(f) == 0);
		expect_error(path, false, "malformed mesh file '",
		             "its OFF header declares 1000 vertices and 2000 faces, more than its");
	}
	unlink(path);
	/* a PLY header that repeats an element, on which assimp 5.2 can write past its
	 * buffers, is refused at the line; other header lines are assimp's to judge, and
	 * refused with its message, even those it hung on once scn's checks let them by */
	static const struct { const char *text, *want; } ply[] = {
		{ "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nelement vertex 2\nend_header\n0 0\n",
		  "line 5 of its PLY header, 'element vertex 2', declares element 'vertex' again" },
		{ "ply\nformat ascii 1.0\nelement face 1\nproperty list uchar int vertex_indices\n"
		  "element vertex 3\nelement face 3\nend_header\n3 0 1 2 0 0 0\n",
		  "line 6 of its PLY header, 'element face 3', declares element 'face' again" },
		{ "ply0ply\nformat ascii 1.0\nend_header\n0\n", "Invalid .ply file" },
		{ "\n\nplyformat ascii 1.0\nend_header\n0\n", "Incorrect magic number" },
		{ "ply\nformat text 1.0\nend_header\n0\n", "Unknown file format" },
		{ "ply\nformat ascii 1.0\n\nelement vertex 1\nproperty quad x\nend_header\n0\n", "Invalid .ply file" },
		{ "ply\nformat ascii 1.0\ncomment ok\nvertex 1\nend_header\n0\n", "Invalid .ply file" },
	};
	snprintf(path, sizeof path, "%s/bad.ply", tmp);
	for (size_t i = 0; i < sizeof ply / sizeof *ply; i++) {
		FILE *f = fopen(path, "w");
		CHECK(f && fputs(ply[i].text, f) >= 0 && fclose(f) == 0);
		expect_error(path, false, "malformed mesh file '", ply[i].want);
	}
	unlink(path);
	/* vertices that are not finite: a glTF's float inf, an OBJ's inf, nan and 1e39 */
	expect_error(fixture("infinite.gltf"), false, "mesh file '",
	             "': 2 of its 3 vertices have coordinates that are not finite (inf or nan, or beyond float's 3.4e38)");
	expect_error(fixture("infinite.obj"), false, "mesh file '", "': 3 of its 5 vertices have coordinates");
	/* UVs too: a PLY's u beyond float's range, and nan (assimp's OBJ reader reads
	 * such a vt as 0) */
	write_file(tmp, "uv.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
	           "property float z\nproperty float u\nproperty float v\nelement face 1\n"
	           "property list uchar int vertex_indices\nend_header\n0 0 0 0 0\n1 0 0 1e39 0\n0 1 0 0 nan\n3 0 1 2\n");
	snprintf(path, sizeof path, "%s/uv.ply", tmp);
	expect_error(path, false, "mesh file '", "': 2 of its 3 vertices have texture coordinates that are not finite");
	unlink(path);
	rmdir(tmp);
	/* and its Triangulate would abort the process on this one */
	expect_error(fixture("empty_faces.ply"), false, "malformed mesh file '", "face 1 has no vertices");

	/* a short buffer gets a cut, terminated message */
	struct mesh_data m;
	char err[8];
	memset(err, 'x', sizeof err);
	CHECK(mesh_import(fixture("lines.obj"), &m, err, sizeof err) != 0);
	CHECK(memchr(err, '\0', sizeof err) != NULL);
}

/* What test_real_models found, for its summary (nftw's callback takes no argument). */
static struct { size_t read, refused, textured, embedded; } real;

/* Whether m, read from path, is sane: its arrays as mesh_import.h says, every index in
 * range, every number finite; prints what is not. */
static bool sane(const char *path, const struct mesh_data *m)
{
	bool ok = m->nvertices > 0 && m->nfaces > 0 && indices_in_range(m) && (m->uvs != NULL) == (m->nuvs > 0) &&
	          (m->nuvs == 0 || m->nuvs == m->nvertices) && (m->normals != NULL) == (m->nnormals > 0) &&
	          (m->nnormals == 0 || m->nnormals == m->nvertices) && (m->materials != NULL) == (m->nmaterials > 0) &&
	          (m->face_material != NULL) == (m->nmaterials > 0);
	for (size_t i = 0; ok && i < m->nuvs; i++)
		ok = isfinite(m->uvs[i][0]) && isfinite(m->uvs[i][1]);
	for (size_t f = 0; ok && m->face_material && f < m->nfaces; f++)
		ok = m->face_material[f] < m->nmaterials || m->face_material[f] == MESH_NO_MATERIAL;
	for (size_t i = 0; ok && i < m->nmaterials; i++) {
		const struct mesh_material *t = &m->materials[i];
		ok = t->name && (!t->texture || *t->texture) && (!t->texture_path || *t->texture_path) &&
		     (!t->texture_path || t->texture) && (!t->texture_data || (t->texture && !t->texture_path)) &&
		     (!t->texture_data || (t->texture_size >= 8 && memcmp(t->texture_data, "\x89PNG", 4) == 0)) &&
		     t->opacity >= 0 && t->opacity <= 1 && t->ior > 0 && isfinite(t->exponent);
		for (int k = 0; ok && k < 3; k++)
			ok = isfinite(t->diffuse[k]) && isfinite(t->specular[k]) && isfinite(t->emission[k]);
		real.textured += t->texture != NULL;
		real.embedded += t->texture_data != NULL;
	}
	if (!ok)
		fprintf(stderr, "%s: read, but its arrays are not sane\n", path);
	return ok;
}

static int read_model(const char *path, const struct stat *st, int type, struct FTW *ftw)
{
	(void)st, (void)ftw;
	if (type != FTW_F)
		return 0;
	struct mesh_data m;
	char err[512];
	/* assimp's own leaks on malformed files (see import_leaky) are not ours to find */
	if (import_leaky(path, &m, err, sizeof err) != 0) {
		real.refused++;
		return 0;
	}
	real.read++;
	CHECK(sane(path, &m));
	mesh_import_free(&m);
	return 0;
}

/* Every file of Debian's assimp-testmodels (some 600, of 40 formats, malformed ones
 * among them, and images), where the package is installed: each is read or refused
 * without a crash, and what is read is sane. About 3 s. */
static void test_real_models(void)
{
	const char *dir = "/usr/share/assimp/models";
	if (access(dir, R_OK) != 0) {
		printf("test_real_models: skipped, no %s (Debian's assimp-testmodels)\n", dir);
		return;
	}
	CHECK(nftw(dir, read_model, 16, FTW_PHYS) == 0);
	printf("test_real_models: %zu files read, %zu refused; %zu materials with a texture, %zu of them an "
	       "embedded PNG\n", real.read, real.refused, real.textured, real.embedded);
	CHECK(real.read > 0);
}

/* assimp logs only through a logger we never attach, and must print nothing, whatever the
 * file: stdout and stderr are pointed at a temporary file while every fixture loads. */
static void test_quiet(void)
{
	static const char *const names[] = {
		"square.obj", "quad.obj", "normals.obj", "partial_normals.obj", "mixed.obj", "lines.obj",
		"bad_index.obj", "empty.obj", "ascii.ply", "binary.ply", "bad_number.ply", "truncated.ply",
		"garbage.bin", "nodes.gltf", "no_such_file.obj", "no_end_header.ply", "cut_faces.ply",
		"empty_faces.ply", "unknown_lines.ply", "infinite.gltf", "infinite.obj", "materials.obj", "glass.obj",
		"uv.ply", "st.ply", "textured.gltf", "embedded.gltf",
	};
	FILE *tmp = tmpfile();
	if (!tmp) {
		fprintf(stderr, "test_quiet: tmpfile: %s\n", strerror(errno));
		check_failures++;
		return;
	}
	fflush(stdout);
	fflush(stderr);
	int saved_out = dup(1), saved_err = dup(2);
	dup2(fileno(tmp), 1);
	dup2(fileno(tmp), 2);
	for (size_t i = 0; i < sizeof names / sizeof *names; i++) {
		struct mesh_data m;
		char err[512];
		const char *path = fixture(names[i]);
		bool leaks = strcmp(names[i], "bad_number.ply") == 0;
		if ((leaks ? import_leaky(path, &m, err, sizeof err) : mesh_import(path, &m, err, sizeof err)) == 0)
			mesh_import_free(&m);
	}
	fflush(stdout);
	fflush(stderr);
	dup2(saved_out, 1);
	dup2(saved_err, 2);
	close(saved_out);
	close(saved_err);
	/* the output went in through the descriptor, so ask it, not the FILE */
	off_t size = lseek(fileno(tmp), 0, SEEK_END);
	if (size != 0) {
		char buf[1024];
		ssize_t n = pread(fileno(tmp), buf, sizeof buf - 1, 0);
		buf[n > 0 ? n : 0] = '\0';
		fprintf(stderr, "test_quiet: the importer printed %lld bytes:\n%s\n", (long long)size, buf);
		check_failures++;
	}
	fclose(tmp);
}

int main(void)
{
	test_obj();
	test_quad();
	test_normals();
	test_partial_normals();
	test_ascii_ply();
	test_binary_ply();
	test_unknown_header_lines();
	test_nodes();
	test_points_and_lines_left_out();
	test_obj_materials();
	test_obj_tr_and_backslash();
	test_made_up_materials();
	test_ply_uvs();
	test_gltf_materials();
	test_errors();
	test_quiet();
	test_real_models();
	return check_result();
}
