/* scene_desc.h: a scene after checking and evaluation: every name resolved, every
 * expression a number, loops and includes expanded. It owns its memory and outlives the
 * AST; lowering turns it into the renderer's scene. */
#ifndef SCN_SCENE_DESC_H
#define SCN_SCENE_DESC_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "diag.h"

struct camera_desc {
	double location[3], look_at[3], up[3];
	double fov;                    /* horizontal, degrees; unused when orthographic */
	bool orthographic;             /* parallel rays across a view view_width wide */
	double view_width;             /* orthographic: the view's width in scene units */
	double aperture;               /* 0: a pinhole; > 0: thin-lens focal blur */
	double focal_point[3];         /* what is sharp; look_at when not given */
	int width, height;
	bool given;                    /* false: the defaults of LANGUAGE.md */
	struct span span;
	struct span resolution_span;   /* the resolution attribute, or span when not given */
};

struct light_desc {
	bool directional;
	double vec[3];                 /* position, or the direction the light travels */
	double color[3];
	double intensity;
	bool shadowless;
	double fade_distance;          /* POV-Ray's defaults 0 and 0: no fade; it fades only */
	double fade_power;             /* when both are > 0 (LANGUAGE.md section 12) */
	bool spot;                     /* spotlight { ... }: the fields below */
	double point_at[3];
	double radius, falloff;        /* degrees from the axis, in [0, 180), radius <= falloff */
	double tightness;
	bool area;                     /* area { ... }: the fields below */
	double area_axis[2][3];        /* AXIS1, AXIS2 as written */
	int area_size[2];              /* N1, N2: whole numbers, 1 to 64 */
	bool area_jitter, area_circular, area_orient;
	struct span span;
};

/* LANGUAGE.md section 11. The names of patterns: the ten a diffuse pattern takes, then the
 * five a normal takes. ORDER PATTERN_NAME: scene_desc.c's texture_names follows it. */
enum pattern_name {
	PAT_GRADIENT, PAT_RADIAL, PAT_ONION, PAT_WOOD, PAT_MARBLE, PAT_LEOPARD, PAT_AGATE, PAT_BOZO,
	PAT_GRANITE, PAT_SPOTTED,
	PAT_BUMPS, PAT_DENTS, PAT_RIPPLES, PAT_WAVES, PAT_WRINKLES,
	PAT_COUNT
};
#define PAT_FIRST_NORMAL PAT_BUMPS

/* One entry of a colour map: the colour at a position in [0, 1]. */
struct color_map_entry {
	double position, color[3];
};

/* `pattern { ... }` (a diffuse pigment) or `normal { ... }` (a bump pattern). */
struct pattern_desc {
	uint8_t name;                  /* enum pattern_name */
	double vector[3];              /* gradient's vector, as written */
	double amount;                 /* a normal's depth (`bumps 0.6`) */
	uint32_t map, nmap;            /* its colour map: entries [map, map + nmap) of
	                                * scene_desc.color_maps, positions rising; nmap 0: black
	                                * at 0 to white at 1 */
	double frequency, phase;       /* 1 and 0 when not given */
	double turbulence[3];          /* all 0: no turbulence */
	int octaves;                   /* 6 */
	double omega, lambda;          /* 0.5 and 2 */
	int xform;                     /* its own transforms, into xforms; -1: none */
	struct span span;
};

/* ORDER IMAGE_MAP: scene_desc.c's map_names follows it. */
enum image_map_kind { IMAGE_MAP_PLANAR, IMAGE_MAP_SPHERICAL, IMAGE_MAP_CYLINDRICAL, IMAGE_MAP_UV };

/* `image { "FILE" ... }`, a diffuse pigment. */
struct image_desc {
	char *file, *path;             /* as written, and resolved against the scene's directory */
	uint8_t map;                   /* enum image_map_kind */
	bool bilinear;                 /* interpolate bilinear; else the nearest texel */
	bool once;                     /* no repeats: outside the image, the default diffuse */
	int xform;                     /* its own transforms, into xforms; -1: none */
	struct span span;
};

/* What `diffuse` holds. */
enum pigment_kind { PIGMENT_COLOR, PIGMENT_CHECKER, PIGMENT_PATTERN, PIGMENT_IMAGE };

struct material_desc {
	char *name;                    /* NULL for an inline material */
	uint8_t pigment;               /* enum pigment_kind */
	int pattern;                   /* PIGMENT_PATTERN: into patterns; PIGMENT_IMAGE: into images */
	int normal;                    /* into patterns (a normal's name), or -1: none */
	double diffuse[3], diffuse2[3], checker_size;   /* PIGMENT_COLOR, PIGMENT_CHECKER */
	double specular[3], shininess, reflect[3], transmit[3], ior, emit[3];
	bool fresnel;
	bool used;                     /* some object refers to it */
	struct span span;
};

/* An affine map p -> m[.][0..2] p + m[.][3]. */
struct xform {
	double m[3][4];
};

struct mesh_desc {
	char *file;                    /* as written in the scene, or NULL for inline data */
	char *path;                    /* file resolved against the scene's directory */
	double (*vertices)[3];
	size_t nvertices;
	uint32_t (*faces)[3];
	size_t nfaces;
	double (*normals)[3];          /* one per vertex, or NULL */
	size_t nnormals;
	double (*uvs)[2];              /* `uvs { }`: one per vertex, or NULL */
	size_t nuvs;
	bool bilinear;                 /* `interpolate bilinear`: the file's textures looked up so */
	bool has_inside_vector;        /* inside_vector given: the mesh is a solid */
	double inside_vector[3];
	struct span file_span;
};

/* LANGUAGE.md sections 5 and 9. OBJ_CSG is union, merge, intersection or difference. */
enum object_kind { OBJ_SPHERE, OBJ_PLANE, OBJ_TRIANGLE, OBJ_MESH, OBJ_BOX, OBJ_CYLINDER, OBJ_CONE, OBJ_DISC,
                   OBJ_TORUS, OBJ_CSG };
enum csg_op { CSG_UNION, CSG_MERGE, CSG_INTERSECTION, CSG_DIFFERENCE };

/* An object, as evaluation leaves it: every value checked (no degenerate shape reaches
 * lowering), the transforms of the CSGs around it composed into its own.
 * The objects of a CSG follow it in scene_desc.objects, in their order, each one's own
 * members after it (preorder): the CSG at index k holds objects k + 1 to k + u.csg.size,
 * and its direct members are the first of those and, after each, the one u.csg.size + 1
 * further on when it is a CSG itself (1 further on when not). */
struct object_desc {
	int material;                  /* index into materials: its own, else the nearest enclosing
	                                * CSG's (POV-Ray's texture inheritance); -1 is the default */
	int xform;                     /* index into xforms: its own transforms, then those of each
	                                * enclosing CSG, innermost first; -1 is the identity */
	int pattern_xform;             /* the space the material's patterns live in: xform when the
	                                * material is its own, the CSG's xform when inherited; -1 the
	                                * identity */
	struct span span;
	/* packed: a scene may hold 10^7 objects (LANG_MAX_OBJECTS) */
	uint8_t kind;                  /* enum object_kind */
	bool smooth : 1;               /* mesh */
	bool open : 1;                 /* cylinder, cone: no end discs */
	bool inverse : 1;              /* inside and outside swapped (a solid, or a CSG of solids) */
	bool solid : 1;                /* it has an inside: LANGUAGE.md section 9's list (a mesh
	                                * when its mesh_desc has an inside_vector) */
	bool inherited : 1;            /* material is an enclosing CSG's, not its own (a mesh
	                                * file's own materials win over an inherited one) */
	union {
		struct { double center[3], radius; } sphere;
		struct { double normal[3], offset; } plane;
		struct { double v[3][3]; } triangle;
		struct { int index; } mesh;    /* into meshes */
		struct { double corner[2][3]; } box;   /* as written: any two opposite corners */
		/* cylinder: radius[0] == radius[1]; cone: one of them may be 0 */
		struct { double base[3], cap[3], radius[2]; } cone;
		struct { double center[3], normal[3], radius, hole; } disc;   /* hole 0: none */
		struct { double major, minor; } torus;
		struct { enum csg_op op; uint32_t size; } csg;
	} u;
};

enum skybox_kind { SKY_NONE, SKY_COLOR, SKY_GRADIENT, SKY_IMAGE };

struct skybox_desc {
	enum skybox_kind kind;
	double color[3];               /* SKY_COLOR; SKY_GRADIENT: the zenith */
	double horizon[3];
	char *image, *image_path;      /* as written, and resolved */
	double rotate, intensity;
	struct span span;
};

/* LANGUAGE.md 12: POV-Ray's constant fog; its colour is black unless given, as POV-Ray's */
struct fog_desc {
	bool given;
	double distance;               /* > 0: what is this far away shows e^-1 of its colour */
	double color[3];
	struct span span;
};

enum sample_pattern { PATTERN_CENTER, PATTERN_GRID, PATTERN_RANDOM, PATTERN_JITTERED,
                      PATTERN_POISSON, PATTERN_COUNT };

struct samples_desc {
	int count;
	enum sample_pattern pattern;
	uint64_t seed;
	double target_error;           /* 0: not adaptive */
	bool pattern_given;            /* false: the default for count, which -s may change */
};

struct scene_desc {
	struct camera_desc camera;
	struct skybox_desc skybox;
	struct fog_desc fog;
	struct samples_desc samples;
	int max_depth;
	struct light_desc *lights;
	size_t nlights, cap_lights;
	struct material_desc *materials;
	size_t nmaterials, cap_materials;
	struct object_desc *objects;
	size_t nobjects, cap_objects;
	struct xform *xforms;
	size_t nxforms, cap_xforms;
	struct mesh_desc *meshes;
	size_t nmeshes, cap_meshes;
	struct pattern_desc *patterns;
	size_t npatterns, cap_patterns;
	struct color_map_entry *color_maps;
	size_t ncolor_maps, cap_color_maps;
	struct image_desc *images;
	size_t nimages, cap_images;
	/* the moment of an animation it was evaluated at (LANGUAGE.md 13): what the names
	 * clock and frame hold; 0 and 0 for a still */
	double clock;
	long frame;
};

/* Fills in LANGUAGE.md's defaults for everything a scene may leave out. */
void scene_desc_init(struct scene_desc *s);
void scene_desc_free(struct scene_desc *s);
/* Writes a canonical text form, one line an entity, for golden tests. */
void scene_desc_dump(const struct scene_desc *s, FILE *out);
/* The same with every number to 17 significant digits, so that two scenes whose dumps
 * are equal have the same numbers (what names a --tile part's scene). */
void scene_desc_dump_exact(const struct scene_desc *s, FILE *out);
const char *scene_desc_pattern_name(enum sample_pattern p);
/* The name of pattern p as written in a scene ("marble"). */
const char *scene_desc_texture_name(enum pattern_name p);
/* The pattern called name, or -1. */
int scene_desc_texture_lookup(const char *name);
/* The name of map kind k as written in a scene ("planar"). */
const char *scene_desc_map_name(enum image_map_kind k);

#endif
