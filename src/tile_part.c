/* tile_part.c: a --tile part's OpenEXR header: the scn* attributes written from a
 * struct tile_part, and read back and checked against the split. */
#include "tile_part.h"

#include <errno.h>
#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

static void set(struct image_exr_header *h, const char *name, const char *value)
{
	h->attrs[h->nattrs++] = (struct image_attr){ name, value };
}

void tile_header_init(struct tile_header *h, const struct tile_part *p)
{
	int y0, y1;
	tile_band(p->t.k, p->t.n, 0, p->height, &y0, &y1);
	h->exr = (struct image_exr_header){ { 0, 0, p->width, p->height }, 0, y0, 0, { { 0 } } };
	snprintf(h->part, sizeof h->part, "%ld/%ld", p->t.k, p->t.n);
	snprintf(h->probe, sizeof h->probe, "%.17g %" PRIu64, p->probe_sum, p->probe_pixels);
	set(&h->exr, "scnVersion", p->version);
	set(&h->exr, "scnPart", h->part);
	set(&h->exr, "scnSettings", p->settings);
	set(&h->exr, "scnScene", p->scene);
	if (p->probed)
		set(&h->exr, "scnProbe", h->probe);
}

/* The value of the attribute name in h, or NULL. */
static const char *attr(const struct image_exr_header *h, const char *name)
{
	for (int i = 0; i < h->nattrs; i++)
		if (strcmp(h->attrs[i].name, name) == 0)
			return h->attrs[i].value;
	return NULL;
}

/* Fills f->p from f->exr and f->img. Returns NULL or what is wrong with the part. */
static const char *check(struct tile_file *f, char *why, size_t whylen)
{
	const struct image_exr_header *h = &f->exr;
	struct tile_part *p = &f->p;
	const char *part = attr(h, "scnPart"), *probe = attr(h, "scnProbe");
	if (!part)
		return "not a part of a --tile render (no scnPart attribute)";
	const char *bad = tile_parse(part, &p->t);
	if (bad) {
		snprintf(why, whylen, "bad scnPart '%s': %s", part, bad);
		return why;
	}
	p->version = attr(h, "scnVersion");
	p->settings = attr(h, "scnSettings");
	p->scene = attr(h, "scnScene");
	if (!p->version || !p->settings || !p->scene)
		return "a part without scnVersion, scnSettings or scnScene";
	if (probe) {
		char tail;
		p->probed = sscanf(probe, "%lg %" SCNu64 "%c", &p->probe_sum, &p->probe_pixels, &tail) == 2;
		if (!p->probed || !isfinite(p->probe_sum) || p->probe_sum < 0) {
			snprintf(why, whylen, "bad scnProbe '%s'", probe);
			return why;
		}
	}
	if (h->display[0] != 0 || h->display[1] != 0)
		return "its display window does not start at 0, 0";
	p->width = h->display[2];
	p->height = h->display[3];
	if (p->t.n > p->height) {
		snprintf(why, whylen, "part %ld of %ld of an image of %d rows", p->t.k, p->t.n, p->height);
		return why;
	}
	int y0, y1;
	tile_band(p->t.k, p->t.n, 0, p->height, &y0, &y1);
	if (h->data_x != 0 || h->data_y != y0 || f->img->width != p->width || f->img->height != y1 - y0) {
		snprintf(why, whylen,
		         "its data window, columns %d to %d and rows %d to %d, is not part %ld of %ld of the %d x %d "
		         "image: all columns, rows %d to %d", h->data_x, h->data_x + f->img->width - 1, h->data_y,
		         h->data_y + f->img->height - 1, p->t.k, p->t.n, p->width, p->height, y0, y1 - 1);
		return why;
	}
	return NULL;
}

int tile_part_read(const char *path, struct tile_file *f, char *err, size_t errlen)
{
	*f = (struct tile_file){ .img = NULL };
	int rc = image_read_exr_header(path, &f->img, &f->exr, err, errlen);
	if (rc)
		return rc;
	char why[256];
	const char *bad = check(f, why, sizeof why);
	if (!bad)
		return 0;
	snprintf(err, errlen, "'%s': %s", path, bad);
	tile_file_free(f);
	return EINVAL;
}

void tile_file_free(struct tile_file *f)
{
	image_free(f->img);
	image_exr_header_free(&f->exr);
	*f = (struct tile_file){ .img = NULL };
}
