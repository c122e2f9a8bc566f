/* tile.c: --tile K/N: the split into bands of rows, the parts' names, and the settings
 * text and scene hash by which scn merge knows parts of the same render. */
#include "tile.h"

#include <errno.h>
#include <inttypes.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#define XXH_STATIC_LINKING_ONLY    /* XXH3_state_t on the stack: no allocation to fail */
#include <xxhash.h>

#include "cli.h"
#include "scene_desc.h"
#include "xalloc.h"

const char *tile_parse(const char *s, struct tile *t)
{
	const char *slash = strchr(s, '/');
	if (!slash)
		return "not K/N";
	char k[24];
	size_t len = (size_t)(slash - s);
	if (len >= sizeof k)
		return "not K/N";
	memcpy(k, s, len);
	k[len] = '\0';
	/* the bounds only keep the numbers in a long; N's real bound is the image's rows */
	if (!cli_int(k, 0, INT32_MAX, &t->k) || !cli_int(slash + 1, INT32_MIN, INT32_MAX, &t->n))
		return "not K/N";
	if (t->n < 1)
		return "N must be at least 1";
	if (t->k >= t->n)
		return "K must be less than N (parts are numbered from 0)";
	return NULL;
}

void tile_band(long k, long n, int top, int height, int *y0, int *y1)
{
	*y0 = top + (int)(k * (int64_t)height / n);
	*y1 = top + (int)((k + 1) * (int64_t)height / n);
}

char *tile_default_output(const char *scene, const struct tile *t)
{
	int digits = snprintf(NULL, 0, "%ld", t->n - 1);
	char ext[64];
	snprintf(ext, sizeof ext, "-%0*ld-of-%ld.exr", digits, t->k, t->n);
	return cli_default_output(scene, ext);
}

/* Closes f, an open_memstream, whose only way to fail is memory (for what). */
static void close_memory(FILE *f, const char *what)
{
	bool failed = ferror(f);
	if (fclose(f) != 0 || failed)
		xout_of_memory("%s", what);
}

char *tile_settings(const struct scene_desc *s, const long *region, const char *accel)
{
	char where[80] = "";
	int w = s->camera.width, h = s->camera.height;
	if (region) {
		snprintf(where, sizeof where, " (region %ld,%ld,%ld,%ld of %d x %d)", region[0], region[1], region[2],
		         region[3], w, h);
		w = (int)(region[2] - region[0]), h = (int)(region[3] - region[1]);
	}
	char *text = NULL;
	size_t size = 0;
	FILE *f = xcheck(open_memstream(&text, &size), "the settings text");
	fprintf(f, "%d x %d%s; %d sample%s, pattern %s, seed %" PRIu64 "; max_depth %d; accel %s", w, h, where,
	        s->samples.count, s->samples.count == 1 ? "" : "s", scene_desc_pattern_name(s->samples.pattern),
	        s->samples.seed, s->max_depth, accel);
	close_memory(f, "the settings text");
	return text;
}

/* Adds the n bytes at p, then their count, so that where one piece ends is part of
 * what is hashed. */
static void add(XXH3_state_t *st, const void *p, size_t n)
{
	uint64_t count = n;
	XXH3_128bits_update(st, p, n);
	XXH3_128bits_update(st, &count, sizeof count);
}

/* Adds the bytes of the file at path. Returns 0 or an errno code with the message. */
static int add_file(XXH3_state_t *st, const char *path, char *err, size_t errlen)
{
	FILE *f = fopen(path, "rb");
	if (!f) {
		int e = errno;
		snprintf(err, errlen, "cannot read '%s': %s", path, strerror(e));
		return e;
	}
	unsigned char buf[1 << 16];
	uint64_t total = 0;
	size_t n;
	while ((n = fread(buf, 1, sizeof buf, f)) > 0) {
		XXH3_128bits_update(st, buf, n);
		total += n;
	}
	int e = ferror(f) ? (errno ? errno : EIO) : 0;
	fclose(f);
	if (e) {
		snprintf(err, errlen, "cannot read '%s': %s", path, strerror(e));
		return e;
	}
	XXH3_128bits_update(st, &total, sizeof total);
	return 0;
}

int tile_scene_hash(const struct scene_desc *s, const char *settings, char hex[33], char *err, size_t errlen)
{
	char *dump = NULL;
	size_t size = 0;
	FILE *f = xcheck(open_memstream(&dump, &size), "the scene's dump");
	scene_desc_dump_exact(s, f);
	close_memory(f, "the scene's dump");
	XXH3_state_t st;
	XXH3_INITSTATE(&st);
	XXH3_128bits_reset(&st);
	add(&st, dump, size);
	free(dump);
	int e = 0;
	if (s->skybox.kind == SKY_IMAGE)
		e = add_file(&st, s->skybox.image_path, err, errlen);
	for (size_t i = 0; i < s->nimages && !e; i++)
		e = add_file(&st, s->images[i].path, err, errlen);
	for (size_t i = 0; i < s->nobjects && !e; i++)
		if (s->objects[i].kind == OBJ_MESH && s->meshes[s->objects[i].u.mesh.index].file)
			e = add_file(&st, s->meshes[s->objects[i].u.mesh.index].path, err, errlen);
	if (e)
		return e;
	add(&st, settings, strlen(settings));
	XXH128_hash_t hash = XXH3_128bits_digest(&st);
	snprintf(hex, 33, "%016" PRIx64 "%016" PRIx64, (uint64_t)hash.high64, (uint64_t)hash.low64);
	return 0;
}
