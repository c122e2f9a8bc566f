/* scene.h: the renderer's scene: its geometry (geometry.h), materials, lights, camera
 * and sky, and the accelerator built over the geometry. lower.c fills it from the front
 * end's description, with only the materials objects use; scene_free releases it. The tracer spawns a ray only for a
 * term that is not zero, so a scene without a feature costs nothing for it (LANGUAGE.md
 * section 7), which --stats shows in its ray counts. */
#ifndef SCN_SCENE_H
#define SCN_SCENE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "accel.h"
#include "affine.h"
#include "camera.h"
#include "geometry.h"
#include "image.h"
#include "sampler.h"
#include "texture.h"

enum light_kind { LIGHT_POINT, LIGHT_DIRECTIONAL };

struct light {
	enum light_kind kind;
	struct vec3 pos;               /* LIGHT_POINT */
	struct vec3 to_light;          /* LIGHT_DIRECTIONAL: unit vector against the light's travel */
	struct vec3 color;             /* colour times intensity */
	bool shadowless;               /* a fill light: no shadow test, no highlight */
	double fade_distance;          /* LIGHT_POINT: POV-Ray's 2 / (1 + (d / D)^P), d the */
	double fade_power;             /* distance to pos; none unless P > 0 and D > 0 */
	bool spot;                     /* LIGHT_POINT: a spotlight, the fields below */
	struct vec3 point_at;          /* for scn pov */
	struct vec3 axis;              /* unit vector from pos towards point_at */
	double radius, falloff;        /* degrees, for scn pov */
	double cos_radius, cos_falloff, tightness;
	int32_t area;                  /* LIGHT_POINT: into scene.area_lights; -1: a point */
};

enum { AREA_MAX = 64 };            /* test points along an area light's axis, at most */

/* area { AXIS1, AXIS2, N1, N2 ... } of LANGUAGE.md section 12, POV-Ray's area_light
 * without adaptive (povray-equivalence.md section 15): shading towards the light's
 * position, times a weighted average of size[0] x size[1] shadow tests. */
struct area_light {
	struct vec3 axis[2];
	int size[2];                   /* 1 to AREA_MAX; 1: no extent along that axis */
	bool jitter;                   /* each test point at random in its cell, per sample */
	bool circular;                 /* the grid pulled in onto a disc */
	bool orient;                   /* turned to face each lit point (and so circular) */
	double inv_span[2];            /* 1 / (size - 1), 0 for a size of 1 (no division per test) */
	int tests;                     /* size[0] * size[1] less those of weight 0 */
	double weight_sum;             /* of the tests' weights, added in the tests' order */
	double weight[2][AREA_MAX];    /* along each axis, POV-Ray's recursive corner weights:
	                                * the test at (u, v) weighs weight[0][u] * weight[1][v] */
};

/* What a material's k_d is: a colour, a checker of two, a pattern through its colour map,
 * or an image map. */
enum material_pigment { MATERIAL_COLOR, MATERIAL_CHECKER, MATERIAL_PATTERN, MATERIAL_IMAGE };

struct material {
	struct vec3 diffuse, diffuse2; /* k_d; diffuse2 is a checker's second colour; diffuse is
	                                * also an image map's colour outside a `once` image */
	double checker_size;
	uint8_t pigment;               /* enum material_pigment */
	bool fresnel;
	int32_t texture;               /* MATERIAL_PATTERN: into scene.patterns; MATERIAL_IMAGE:
	                                * into scene.image_maps */
	int32_t bump;                  /* a bump pattern perturbing the shading normal, into
	                                * scene.patterns; -1: none */
	struct vec3 specular, reflect, transmit, emit;
	double shininess, ior;
};

/* Whether m varies over a surface, and so needs the object's own space (surface.to_object). */
static inline bool material_textured(const struct material *m)
{
	return m->pigment != MATERIAL_COLOR || m->bump >= 0;
}

/* An object made of a mesh file, as lowering placed it: its triangles are those of surface,
 * in world space, where to_world put the file's vertices (to_object maps back). Uses with
 * the same mesh number are the same file shaded alike (smooth or flat), so that the POV-Ray
 * export can write the mesh once and place it per use; the renderer ignores them. */
struct mesh_use {
	uint32_t surface;              /* into geo.surfaces */
	uint32_t mesh;                 /* 0 .. nmesh_sources - 1 */
	bool mirrored;                 /* to_world mirrors: lowering swapped each face's corners 1 and 2 */
	struct affine to_world, to_object;
	/* its triangles, geo.triangles[first, last): surface's, and with a file's own materials
	 * also the surfaces lowering made for them, face by face */
	size_t first, last;
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

/* POV-Ray's constant fog (LANGUAGE.md 12) on the rays the tracer follows through the open */
struct fog {
	double distance;               /* 0: no fog */
	struct vec3 color;
};

struct scene {
	struct camera camera;
	struct light *lights;
	size_t nlights;
	struct area_light *area_lights;
	size_t narea_lights;
	bool streams;                  /* a sample draws numbers beyond its place in the pixel
	                                * (stream.h): for the lens, or a jittered area light */
	struct material *materials;
	size_t nmaterials;
	struct affine *affines;
	size_t naffines;
	struct geometry geo;           /* the primitives, and what each is made of */
	struct mesh_use *mesh_uses;
	size_t nmesh_uses, nmesh_sources;
	struct sky sky;
	struct fog fog;
	/* textures (texture.h): patterns (colour and bump), their colour maps, image maps, and
	 * the images those read, each file once */
	struct pattern *patterns;
	size_t npatterns;
	struct colour_stop *colour_stops;
	size_t ncolour_stops;
	struct image_map *image_maps;
	size_t nimage_maps;
	struct image **images;
	char **image_paths;            /* the file each image was read from (for scn pov) */
	size_t nimages;
	struct sampling sampling;
	int max_depth;
	struct accel accel;            /* built by accel_build after lowering */
};

void scene_free(struct scene *s);

/* A bound on the bytes a lowered scene and its accelerator (the larger of the BVH and the
 * grid) hold for nprims primitives, ntriangles of them triangles, and nvertices mesh
 * vertices (each with a normal), its arrays grown by doubling; for refusing a scene too
 * big for the machine before it is built. */
uint64_t scene_bytes(uint64_t nprims, uint64_t ntriangles, uint64_t nvertices);

#endif
