/* tile.h: --tile K/N: the fixed split of an image into N bands of rows, a part's file
 * name, and what names where a part comes from: the settings text and the scene hash
 * that scn merge compares (tile_part.h has the part's file header). */
#ifndef SCN_TILE_H
#define SCN_TILE_H

#include <stdbool.h>
#include <stddef.h>

struct scene_desc;

/* Part k (0-based) of a split into n; n 0: no --tile. */
struct tile {
	long k, n;
};

/* Reads "K/N" from s into *t. Returns NULL, or what is wrong, to follow "--tile 'S': ". */
const char *tile_parse(const char *s, struct tile *t);
/* The rows [*y0, *y1) of part k of n of an image whose rows are [top, top + height):
 * the band [top + floor(k * height / n), top + floor((k + 1) * height / n)). */
void tile_band(long k, long n, int top, int height, int *y0, int *y1);
/* A part's default file name in the current directory: the scene's name followed by
 * "-K-of-N.exr", K padded with zeros to the digits of N - 1; malloc'd. */
char *tile_default_output(const char *scene, const struct tile *t);

/* What fixes the pixels beyond the scene's text (the numbers are the scene's after the
 * command line's overrides): the output image's size, its region of the camera's image
 * if any (region NULL: none; else x0, y0, x1, y1), samples, pattern, seed, max_depth and
 * the accelerator's name. One line of text; malloc'd. */
char *tile_settings(const struct scene_desc *s, const long *region, const char *accel);
/* The 128-bit XXH3 hash, as 32 hex digits in hex, of s's exact dump, the bytes of each
 * file s reads (its skybox image, image maps and mesh files, in the dump's order) and
 * settings. Returns 0, or an errno code with a message naming the file in err. */
int tile_scene_hash(const struct scene_desc *s, const char *settings, char hex[33], char *err, size_t errlen);

#endif
