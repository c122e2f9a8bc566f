/* lower.h: the bridge from the front end to the renderer: scene_desc -> struct scene.
 * The only code that knows both. */
#ifndef SCN_LOWER_H
#define SCN_LOWER_H

#include <stdint.h>

#include "diag.h"
#include "load.h"
#include "scene.h"
#include "scene_desc.h"

struct lower_times {
	double load_meshes, load_images;   /* seconds */
};

/* Lowers desc into out, keeping only what the scene uses: used materials, mesh files
 * that objects name (each read once), the rays the materials and lights can need.
 * Transforms are baked into world-space geometry; the BVH is left to the caller
 * (scn check lowers without one). Reports what it cannot load, and warnings, to d (at
 * the place in the scene) and returns LOAD_SCENE_ERROR after an error; out is always
 * scene_free-able.
 * other_bytes is what the run will hold besides the scene (its images): with it, the
 * scene's objects and then each mesh as it is read are counted, with their BVH, against
 * the memory the machine has (memory.h), and the first mesh that passes it is an error
 * there, the status LOAD_TOO_BIG; nothing is built for it; and a scene whose image can
 * show nothing but the sky (no objects; no light and nothing that emits) is warned about.
 * Negative: neither (scn check and scn pov build no BVH and render nothing). */
enum load_status lower_scene(struct diag *d, const struct scene_desc *desc, struct scene *out,
                            struct lower_times *times, int64_t other_bytes);

#endif
