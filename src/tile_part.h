/* tile_part.h: a --tile part's file: the float OpenEXR image of its band, whose header
 * says where the band lies in the whole (the windows) and where the part comes from
 * (the scn* attributes), written by scn render and read back by scn merge. */
#ifndef SCN_TILE_PART_H
#define SCN_TILE_PART_H

#include <stddef.h>
#include <stdint.h>

#include "image_file.h"
#include "tile.h"

/* A part's header, as the writer fills it and the reader checks it. */
struct tile_part {
	struct tile t;
	int width, height;             /* the whole image's: the display window [0, w) x [0, h) */
	const char *version, *settings, *scene;  /* scnVersion, scnSettings, scnScene */
	bool probed;                   /* scnProbe is there: */
	double probe_sum;              /* the error estimate's sum over the part's probe pixels */
	uint64_t probe_pixels;         /* and their count (render.c) */
};

/* The EXR header of part p, for image_write_options.exr: the storage of its strings
 * that are not p's. */
struct tile_header {
	struct image_exr_header exr;
	char part[48], probe[64];
};
/* Fills *h from *p; h points into p's strings, which must outlive it. */
void tile_header_init(struct tile_header *h, const struct tile_part *p);

/* A part read back: its header and the pixels of its band. */
struct tile_file {
	struct tile_part p;
	struct image *img;
	struct image_exr_header exr;   /* owns p's strings */
};
/* Reads the part at path into *f and checks that it is one by itself: its scnPart is K/N,
 * its display window starts at 0, 0 and its data window is the band of K (tile_band) at
 * full width. Returns 0, or an errno code with a message naming path in err (EINVAL:
 * not a part); *f then holds nothing to free. */
int tile_part_read(const char *path, struct tile_file *f, char *err, size_t errlen);
void tile_file_free(struct tile_file *f);

#endif
