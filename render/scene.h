/* scene.h: the renderer's scene: flat arrays of world-space primitives, materials,
 * lights, camera and sky. lower.c fills it from the front end's description, with only
 * the materials objects use; scene_free releases it. The tracer spawns a ray only for a
 * term that is not zero, so a scene without a feature costs nothing for it (LANGUAGE.md
 * section 7), which --stats shows in its ray counts. */
#ifndef SCN_SCENE_H
#define SCN_SCENE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "image.h"
#include "vec.h"

struct camera {
	struct vec3 eye;
	struct vec3 dir, right, up;    /* unit D, R, U of povray-equivalence.md section 3 */
	double tan_half;               /* tan of half the horizontal field of view */
	int width, height;
};

enum light_kind { LIGHT_POINT, LIGHT_DIRECTIONAL };

struct light {
	enum light_kind kind;
	struct vec3 pos;               /* LIGHT_POINT */
	struct vec3 to_light;          /* LIGHT_DIRECTIONAL: unit vector against the light's travel */
	struct vec3 color;             /* colour times intensity */
	bool shadowless;               /* a fill light: no shadow test, no highlight */
};

struct material {
	struct vec3 diffuse, diffuse2; /* k_d; diffuse2 is a checker's second colour */
	double checker_size;
	bool checker, fresnel;
	struct vec3 specular, reflect, transmit, emit;
	double shininess, ior;
};

/* An affine map p -> m[.][0..2] p + m[.][3]. */
struct affine {
	double m[3][4];
};

/* What a primitive is made of: a material, and for a checker the map from world space
 * back to the object's own space, where the checker is defined. */
struct surface {
	uint32_t material;
	int32_t to_object;             /* index into scene.affines; -1: the identity */
};

struct sphere {
	struct vec3 center;
	double radius;
	uint32_t surface;
};

struct plane {
	struct vec3 normal;            /* unit */
	double offset;                 /* the plane is p . normal = offset */
	uint32_t surface;
};

#define NO_NORMALS UINT32_MAX

/* A triangle by the indices of its vertices. The BVH's traversal reads their positions
 * from its packets (render/tri_packet.h), four triangles' in one run of memory, which
 * copy them; everything else (hit points, bounds, the grid) goes through v[]. */
struct triangle {
	uint32_t v[3];                 /* into scene.vertices */
	uint32_t n[3];                 /* into scene.normals, or NO_NORMALS (flat) */
	uint32_t surface;
};

enum sky_kind { SKY_BLACK, SKY_CONSTANT, SKY_ZENITH_HORIZON, SKY_LATLONG };

struct sky {
	enum sky_kind kind;
	struct vec3 color;             /* SKY_CONSTANT; SKY_ZENITH_HORIZON: the zenith */
	struct vec3 horizon;
	int width, height;             /* SKY_LATLONG: the equirectangular map, linear RGB */
	float *texels;                 /* width * height * 3, top row first */
	struct image_source file;      /* SKY_LATLONG: how its file was encoded */
	double rot_sin, rot_cos;       /* rotation about y */
	double intensity;
};

enum sample_kind { SAMPLE_CENTER, SAMPLE_GRID, SAMPLE_RANDOM, SAMPLE_JITTERED, SAMPLE_POISSON };

struct sampling {
	int count;
	enum sample_kind kind;
	uint64_t seed;
	double target_error;           /* 0: a fixed count */
};

struct bvh;
struct grid;

struct scene {
	struct camera camera;
	struct light *lights;
	size_t nlights;
	struct material *materials;
	size_t nmaterials;
	struct surface *surfaces;
	size_t nsurfaces;
	struct affine *affines;
	size_t naffines;
	struct sphere *spheres;
	size_t nspheres;
	struct plane *planes;
	size_t nplanes;
	struct vec3 *vertices;
	size_t nvertices;
	struct vec3 *normals;
	size_t nnormals;
	struct triangle *triangles;
	size_t ntriangles;
	struct sky sky;
	struct sampling sampling;
	int max_depth;
	struct bvh *bvh;               /* built by accel_build after lowering: one of these two */
	struct grid *grid;
};

void scene_free(struct scene *s);

/* A bound on the bytes a lowered scene and its accelerator (the larger of the BVH and the
 * grid) hold for nprims primitives, ntriangles of them triangles, and nvertices mesh
 * vertices (each with a normal), its arrays grown by doubling; for refusing a scene too
 * big for the machine before it is built. */
uint64_t scene_bytes(uint64_t nprims, uint64_t ntriangles, uint64_t nvertices);

#endif
