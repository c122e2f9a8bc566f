/* lower_texture.h: lowering's part for textures (LANGUAGE.md section 11): the description's
 * patterns, colour maps and image maps into the scene's (texture.h), only those that used
 * materials name, and the image files they read, each file read once however many image
 * maps and meshes use it. */
#ifndef SCN_LOWER_TEXTURE_H
#define SCN_LOWER_TEXTURE_H

#include <stdbool.h>
#include <stdint.h>

#include "diag.h"
#include "scene.h"
#include "scene_desc.h"

struct texture_lowering {
	struct diag *diag;
	const struct scene_desc *desc;
	struct scene *sc;
	int32_t *pattern_of;           /* desc pattern -> scene pattern, or -1 */
	int32_t *image_map_of;         /* desc image -> scene image map, or -1 (or -2: failed) */
	size_t cap_image_maps, cap_images, cap_image_paths;
	double seconds;                /* reading image files */
	bool too_big;                  /* an image needs more memory than there is */
};

void lower_texture_begin(struct texture_lowering *t, struct diag *d, const struct scene_desc *desc,
                         struct scene *sc);
/* The scene pattern of desc pattern i, made on first use. */
int32_t lower_texture_pattern(struct texture_lowering *t, int i);
/* The scene image map of desc image i, its file read on first use; -1 after an error,
 * reported at the image. */
int32_t lower_texture_image(struct texture_lowering *t, int i);
/* An image map of UV kind for a texture of a mesh file: the image at path, read once, or
 * for a texture embedded in the file, decoded once from the size bytes at data (a PNG),
 * path then naming it; -1 after an error, reported at `at` as a texture of mesh_file named
 * as written. */
int32_t lower_texture_mesh_image(struct texture_lowering *t, const char *path, const unsigned char *data,
                                 size_t size, const char *written, const char *mesh_file, bool bilinear,
                                 struct span at);
void lower_texture_end(struct texture_lowering *t);

#endif
