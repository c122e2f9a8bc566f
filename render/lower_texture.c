/* lower_texture.c: textures from the description into the scene (lower_texture.h). A
 * pattern's and an image's own transforms become the map from the object's own space to
 * theirs; colour maps are copied once into the scene's pool of stops. */
#include "lower_texture.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "clock.h"
#include "image_file.h"
#include "xalloc.h"

void lower_texture_begin(struct texture_lowering *t, struct diag *d, const struct scene_desc *desc,
                         struct scene *sc)
{
	memset(t, 0, sizeof *t);
	t->diag = d;
	t->desc = desc;
	t->sc = sc;
	t->pattern_of = xmalloc((desc->npatterns ? desc->npatterns : 1) * sizeof *t->pattern_of);
	for (size_t i = 0; i < desc->npatterns; i++)
		t->pattern_of[i] = -1;
	t->image_map_of = xmalloc((desc->nimages ? desc->nimages : 1) * sizeof *t->image_map_of);
	for (size_t i = 0; i < desc->nimages; i++)
		t->image_map_of[i] = -1;
	/* sized once, so that the stops a pattern points to never move */
	sc->patterns = xcalloc(desc->npatterns ? desc->npatterns : 1, sizeof *sc->patterns);
	sc->colour_stops = xcalloc(desc->ncolor_maps ? desc->ncolor_maps : 1, sizeof *sc->colour_stops);
}

/* The map from the object's own space to one whose transforms are xform (-1: none). */
static bool own_space(const struct scene_desc *desc, int xform, struct affine *to)
{
	if (xform < 0) {
		*to = affine_identity;
		return false;
	}
	struct affine a;
	memcpy(a.m, desc->xforms[xform].m, sizeof a.m);
	*to = affine_inverse(&a);
	return true;
}

int32_t lower_texture_pattern(struct texture_lowering *t, int i)
{
	if (t->pattern_of[i] >= 0)
		return t->pattern_of[i];
	/* ORDER PATTERN_NAME */
	static const uint8_t kinds[PAT_COUNT] = {
		TEXTURE_GRADIENT, TEXTURE_RADIAL, TEXTURE_ONION, TEXTURE_WOOD, TEXTURE_MARBLE, TEXTURE_LEOPARD,
		TEXTURE_AGATE, TEXTURE_BOZO, TEXTURE_GRANITE, TEXTURE_SPOTTED,
		TEXTURE_BUMPS, TEXTURE_DENTS, TEXTURE_RIPPLES, TEXTURE_WAVES, TEXTURE_WRINKLES,
	};
	const struct pattern_desc *d = &t->desc->patterns[i];
	struct scene *sc = t->sc;
	struct colour_stop *stops = &sc->colour_stops[sc->ncolour_stops];
	for (uint32_t k = 0; k < d->nmap; k++) {
		const struct color_map_entry *e = &t->desc->color_maps[d->map + k];
		stops[k] = (struct colour_stop){ e->position, v3a(e->color) };
	}
	sc->ncolour_stops += d->nmap;
	struct vec3 turbulence = v3a(d->turbulence);
	struct pattern *p = &sc->patterns[sc->npatterns];
	*p = (struct pattern){
		.kind = kinds[d->name], .turbulent = !vzero(turbulence), .vector = vunit(v3a(d->vector)),
		.amount = d->amount, .frequency = d->frequency, .phase = d->phase, .turbulence = turbulence,
		.octaves = d->octaves, .omega = d->omega, .lambda = d->lambda, .map = d->nmap ? stops : NULL,
		.nmap = d->nmap,
	};
	if (d->name != PAT_GRADIENT)
		p->vector = v3s(0);
	p->moved = own_space(t->desc, d->xform, &p->to_pattern);
	return t->pattern_of[i] = (int32_t)sc->npatterns++;
}

/* The image read from path (or, with data, decoded from the size bytes there and named
 * path), once; NULL after an error, whose message (naming path) is in err. */
static const struct image *image_file(struct texture_lowering *t, const char *path, const unsigned char *data,
                                      size_t size, char *err, size_t errlen)
{
	struct scene *sc = t->sc;
	for (size_t i = 0; i < sc->nimages; i++)
		if (strcmp(sc->image_paths[i], path) == 0)
			return sc->images[i];
	struct image *img;
	double t0 = clock_now();
	int e = data ? image_read_png_memory(data, size, path, &img, err, errlen) : image_read(path, &img, err, errlen);
	t->seconds += clock_now() - t0;
	if (e != 0) {
		t->too_big = t->too_big || e == ENOMEM;
		return NULL;
	}
	xgrow((void **)&sc->images, &t->cap_images, sc->nimages + 1, sizeof *sc->images);
	xgrow((void **)&sc->image_paths, &t->cap_image_paths, sc->nimages + 1, sizeof *sc->image_paths);
	sc->image_paths[sc->nimages] = xstrdup(path);
	sc->images[sc->nimages] = img;
	return sc->images[sc->nimages++];
}

static int32_t add_image_map(struct texture_lowering *t, const struct image_map *im)
{
	struct scene *sc = t->sc;
	xgrow((void **)&sc->image_maps, &t->cap_image_maps, sc->nimage_maps + 1, sizeof *sc->image_maps);
	sc->image_maps[sc->nimage_maps] = *im;
	return (int32_t)sc->nimage_maps++;
}

int32_t lower_texture_image(struct texture_lowering *t, int i)
{
	if (t->image_map_of[i] != -1)
		return t->image_map_of[i] < 0 ? -1 : t->image_map_of[i];
	const struct image_desc *d = &t->desc->images[i];
	char err[512];
	const struct image *img = image_file(t, d->path, NULL, 0, err, sizeof err);
	if (!img) {
		diag_error(t->diag, d->span, "cannot read the image map: %s", err);
		t->image_map_of[i] = -2;
		return -1;
	}
	/* ORDER: enum image_map_kind and enum texture_map alike */
	static const uint8_t maps[] = {
		[IMAGE_MAP_PLANAR] = TEXTURE_MAP_PLANAR, [IMAGE_MAP_SPHERICAL] = TEXTURE_MAP_SPHERICAL,
		[IMAGE_MAP_CYLINDRICAL] = TEXTURE_MAP_CYLINDRICAL, [IMAGE_MAP_UV] = TEXTURE_MAP_UV,
	};
	struct image_map im = { .image = img, .map = maps[d->map], .bilinear = d->bilinear, .once = d->once };
	im.moved = own_space(t->desc, d->xform, &im.to_pattern);
	return t->image_map_of[i] = add_image_map(t, &im);
}

int32_t lower_texture_mesh_image(struct texture_lowering *t, const char *path, const unsigned char *data,
                                 size_t size, const char *written, const char *mesh_file, bool bilinear,
                                 struct span at)
{
	struct scene *sc = t->sc;
	char err[512];
	const struct image *img = image_file(t, path, data, size, err, sizeof err);
	if (!img) {
		diag_error(t->diag, at, "cannot read texture '%s' of mesh file '%s': %s", written, mesh_file, err);
		return -1;
	}
	/* a file's materials share one image map per image and lookup */
	for (size_t i = 0; i < sc->nimage_maps; i++) {
		const struct image_map *im = &sc->image_maps[i];
		if (im->image == img && im->map == TEXTURE_MAP_UV && im->bilinear == bilinear && !im->once && !im->moved)
			return (int32_t)i;
	}
	struct image_map im = { .image = img, .map = TEXTURE_MAP_UV, .bilinear = bilinear, .to_pattern = affine_identity };
	return add_image_map(t, &im);
}

void lower_texture_end(struct texture_lowering *t)
{
	free(t->pattern_of);
	free(t->image_map_of);
}
