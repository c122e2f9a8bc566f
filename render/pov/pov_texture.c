/* pov_texture.c: patterns, image maps and bump patterns as POV-Ray writes them
 * (LANGUAGE.md section 11, povray-equivalence.md section 15): the same names, colour maps
 * written out (POV-Ray's defaults differ per pattern), frequency, phase and turbulence as
 * scn's, and each own transform as `transform { M inverse }` of scn's map into the
 * pattern's space, so that POV-Ray takes points there exactly as scn does. */
#include "pov_texture.h"

#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "pov_write.h"
#include "xalloc.h"

/* ORDER TEXTURE_PATTERN */
static const char *const pattern_names[] = {
	"gradient", "radial", "onion", "wood", "marble", "leopard", "agate", "bozo", "granite", "spotted",
	"bumps", "dents", "ripples", "waves", "wrinkles",
};

static void own_transform(FILE *f, bool moved, const struct affine *to_pattern)
{
	if (!moved)
		return;
	fputs(" transform { ", f);
	pov_matrix(f, to_pattern);
	fputs(" inverse }", f);
}

/* The pattern's name and argument, then its modifiers. */
static void pattern_words(FILE *f, const struct pattern *pt, bool bump)
{
	fputs(pattern_names[pt->kind], f);
	if (pt->kind == TEXTURE_GRADIENT) {
		fputc(' ', f);
		pov_vec(f, pt->vector);
	}
	if (bump) {
		fputc(' ', f);
		pov_num(f, pt->amount);
	}
}

static void modifiers(FILE *f, const struct pattern *pt)
{
	if (pt->frequency != 1) {
		fputs(" frequency ", f);
		pov_num(f, pt->frequency);
	}
	if (pt->phase != 0) {
		fputs(" phase ", f);
		pov_num(f, pt->phase);
	}
	if (pt->turbulent) {
		fputs(" turbulence ", f);
		pov_vec(f, pt->turbulence);
		fprintf(f, " octaves %d omega ", pt->octaves);
		pov_num(f, pt->omega);
		fputs(" lambda ", f);
		pov_num(f, pt->lambda);
	}
	own_transform(f, pt->moved, &pt->to_pattern);
}

static void map_entry(FILE *f, double position, struct vec3 c, double div, double t)
{
	fputs(" [", f);
	pov_num(f, position);
	fputs(" rgbt ", f);
	pov_vec4(f, v3(c.x / div, c.y / div, c.z / div), t);
	fputc(']', f);
}

void pov_pattern_pigment(FILE *f, const struct pattern *pt, double div, double t)
{
	fputs("pigment { ", f);
	pattern_words(f, pt, false);
	fputs(" color_map {", f);
	if (pt->nmap == 0) {
		map_entry(f, 0, v3s(0), div, t);
		map_entry(f, 1, v3s(1), div, t);
	}
	for (uint32_t k = 0; k < pt->nmap; k++)
		map_entry(f, pt->map[k].position, pt->map[k].colour, div, t);
	fputs(" }", f);
	modifiers(f, pt);
	fputs(" }", f);
}

void pov_image_file(FILE *f, const struct image_source *src, const char *path, const char *pov_dir)
{
	fputs(src->format == IMAGE_PNG ? "png " : src->format == IMAGE_EXR ? "exr " : "ppm ", f);
	char *ref = pov_image_reference(path, pov_dir);
	pov_str(f, ref);
	free(ref);
	/* decode as scn does: EXR is linear; PPM is sRGB; a PNG by its chunks */
	if (src->format == IMAGE_PPM || (src->format == IMAGE_PNG && src->png_gamma == 0))
		fputs(" gamma srgb", f);
	else if (src->format == IMAGE_PNG) {
		fputs(" gamma ", f);
		pov_num(f, 1 / src->png_gamma);
	}
}

const char *pov_image_path(const struct scene *sc, const struct image *img)
{
	size_t file = 0;
	while (sc->images[file] != img)
		file++;
	return sc->image_paths[file];
}

void pov_image_pigment(FILE *f, const struct scene *sc, const struct image_map *im, double t, const char *pov_dir)
{
	/* map_type 0, 1, 2, and uv_mapping, which looks the image up as a planar map at (u, v) */
	static const int map_types[] = { [TEXTURE_MAP_PLANAR] = 0, [TEXTURE_MAP_SPHERICAL] = 1,
	                                 [TEXTURE_MAP_CYLINDRICAL] = 2, [TEXTURE_MAP_UV] = 0 };
	fprintf(f, "pigment { %simage_map { ", im->map == TEXTURE_MAP_UV ? "uv_mapping " : "");
	pov_image_file(f, &im->image->source, pov_image_path(sc, im->image), pov_dir);
	/* without interpolate, POV-Ray takes the nearest texel */
	fprintf(f, " map_type %d%s%s", map_types[im->map], im->bilinear ? " interpolate 2" : "", im->once ? " once" : "");
	if (t != 0) {
		fputs(" transmit all ", f);
		pov_num(f, t);
	}
	fputs(" }", f);
	own_transform(f, im->moved, &im->to_pattern);
	fputs(" }", f);
}

void pov_bump_normal(FILE *f, const struct pattern *pt)
{
	fputs(" normal { ", f);
	pattern_words(f, pt, true);
	modifiers(f, pt);
	fputs(" }", f);
}

char *pov_image_reference(const char *image, const char *pov_dir)
{
	char *t = realpath(image, NULL);
	char *d = pov_dir ? realpath(*pov_dir ? pov_dir : ".", NULL) : NULL;
	if (!t) {
		free(d);
		if (image[0] == '/')
			return xstrdup(image);
		char cwd[PATH_MAX];
		if (!getcwd(cwd, sizeof cwd))
			return xstrdup(image);
		char *abs = xmalloc(strlen(cwd) + strlen(image) + 2);
		sprintf(abs, "%s/%s", cwd, image);
		return abs;
	}
	if (!d)
		return t;
	size_t dl = strlen(d);
	char *ds = xmalloc(dl + 2);
	memcpy(ds, d, dl + 1);
	if (dl == 0 || ds[dl - 1] != '/')
		strcpy(ds + dl, "/");
	size_t k = 0;                  /* the common prefix, up to a '/' */
	for (size_t i = 0; t[i] && ds[i] && t[i] == ds[i]; i++)
		if (t[i] == '/')
			k = i + 1;
	size_t ups = 0;
	for (const char *s = ds + k; *s; s++)
		ups += *s == '/';
	char *rel = xmalloc(3 * ups + strlen(t + k) + 1);
	rel[0] = '\0';
	for (size_t i = 0; i < ups; i++)
		strcat(rel, "../");
	strcat(rel, t + k);
	free(t);
	free(d);
	free(ds);
	return rel;
}
