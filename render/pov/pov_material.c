/* pov_material.c: an scn material as the POV-Ray material that shades as it does
 * (doc/povray.md, "Materials"): the single-layer recipe where that is exact, the
 * layered general recipe otherwise, and the interior that carries the index of
 * refraction. */
#include "pov_material.h"

#include <stdbool.h>

#include "pov_texture.h"
#include "pov_write.h"

/* A colour channel this small stands in for zero where a layer must not filter to
 * exactly 0 (doc/povray.md, "Materials"): POV-Ray skips the layers below one. */
#define TINY 1e-7

static bool grey(struct vec3 v)
{
	return v.x == v.y && v.y == v.z;
}

static struct vec3 vdiv(struct vec3 a, double b)
{
	return v3(a.x / b, a.y / b, a.z / b);
}

/* a / b per channel, 0 where b is 0 (the channel contributes nothing there) */
static struct vec3 safe_div(struct vec3 a, struct vec3 b)
{
	return v3(b.x != 0 ? a.x / b.x : 0, b.y != 0 ? a.y / b.y : 0, b.z != 0 ? a.z / b.z : 0);
}

static double pov_ior(double ior)
{
	/* ior exactly 1 would continue the ray without counting a trace level (section 6) */
	return ior == 1 ? 1.0000001 : ior;
}

/* The single-layer recipe is exact when k_s and k_t are grey, 0 <= t < 1 (or t >= 1
 * and no diffuse), and emit is zero or follows a plain diffuse that is non-zero in
 * every channel where emit is. */
static bool single_layer(const struct material *m)
{
	if (!grey(m->specular) || !grey(m->transmit))
		return false;
	double t = m->transmit.x;
	bool no_diffuse = vzero(m->diffuse) && (m->pigment != MATERIAL_CHECKER || vzero(m->diffuse2));
	if (t < 0 || (t >= 1 && !no_diffuse))
		return false;
	if (vzero(m->emit))
		return true;
	if (m->pigment != MATERIAL_COLOR || t >= 1) /* emission would follow a varying pigment */
		return false;
	return (m->emit.x == 0 || m->diffuse.x != 0) && (m->emit.y == 0 || m->diffuse.y != 0) &&
	       (m->emit.z == 0 || m->diffuse.z != 0);
}

/* Where the .pov is written and what it shows: for the textures' files. */
struct pov_material_context {
	const struct scene *sc;
	const char *pov_dir;
};

/* Whether m's pigment is an image map that the twin writes as one. */
static bool image_pigment(const struct scene *sc, const struct material *m)
{
	/* a texture embedded in a mesh file (a glb's) has no file of its own for POV-Ray to
	 * read: the twin shows the material's plain diffuse colour instead */
	return m->pigment == MATERIAL_IMAGE && !sc->image_maps[m->texture].image->source.embedded;
}

/* A pigment of diffuse colours divided by div, with transmit t: plain, checker, a pattern
 * through its colour map, or an image map (whose texels the finish's diffuse divides:
 * diffuse_weight), then the bump pattern's normal. */
static void diffuse_pigment(FILE *f, const struct pov_material_context *cx, const struct material *m, double div,
                            double t)
{
	switch (m->pigment) {
	case MATERIAL_CHECKER:
		fputs("pigment { checker rgbt ", f);
		pov_vec4(f, vdiv(m->diffuse, div), t);
		fputs(", rgbt ", f);
		pov_vec4(f, vdiv(m->diffuse2, div), t);
		fputs(" scale ", f);
		pov_num(f, m->checker_size);
		fputs(" }", f);
		break;
	case MATERIAL_PATTERN:
		pov_pattern_pigment(f, &cx->sc->patterns[m->texture], div, t);
		break;
	case MATERIAL_IMAGE:
		if (image_pigment(cx->sc, m)) {
			pov_image_pigment(f, cx->sc, &cx->sc->image_maps[m->texture], t, cx->pov_dir);
			break;
		}
		fputs("// not exact: a texture embedded in a mesh file, which POV-Ray cannot read: its plain colour\n    ", f);
		/* fall through */
	default:
		fputs("pigment { rgbt ", f);
		pov_vec4(f, vdiv(m->diffuse, div), t);
		fputs(" }", f);
	}
	if (m->bump >= 0)
		pov_bump_normal(f, &cx->sc->patterns[m->bump]);
}

/* The finish's diffuse for a pigment divided by div: 1, as the colours are divided, but
 * 1 / div for an image map, whose texels cannot be. */
static void diffuse_weight(FILE *f, const struct pov_material_context *cx, const struct material *m, double div)
{
	fputs(" diffuse ", f);
	pov_num(f, image_pigment(cx->sc, m) ? 1 / div : 1);
}

/* An image map with `once` leaves the plain diffuse colour outside the image: POV-Ray's
 * image is clear there, so a layer of that colour lies under it, with no highlight or
 * mirror of its own (POV-Ray computes a clear layer's, measured). Exact with t = 0 only. */
static bool image_once(const struct pov_material_context *cx, const struct material *m)
{
	return image_pigment(cx->sc, m) && cx->sc->image_maps[m->texture].once;
}

static void roughness(FILE *f, double shininess)
{
	/* POV-Ray's exponent is 1/roughness; roughness 0 is its exponent 0 */
	fputs(" roughness ", f);
	pov_num(f, shininess > 0 ? 1 / shininess : 0);
}

static void fresnel_reflection(FILE *f, const struct material *m)
{
	fputs(" reflection { rgb 0, rgb ", f);
	pov_vec(f, m->reflect);
	fputs(" fresnel on } conserve_energy", f);
}

static void write_single_layer(FILE *f, const struct pov_material_context *cx, const struct material *m)
{
	double t = m->transmit.x;
	double s = m->specular.x;
	if (image_once(cx, m) && t < 1) {
		fputs("  texture { pigment { rgbt ", f);
		pov_vec4(f, vdiv(m->diffuse, 1 - t), t);
		fputs(" }", f);
		if (m->bump >= 0)
			pov_bump_normal(f, &cx->sc->patterns[m->bump]);
		fputs(" finish { ambient 0 diffuse 1 brilliance 1 specular 0 phong 0 } }\n", f);
	}
	fputs("  texture {\n    ", f);
	if (t >= 1) {                  /* no diffuse: nothing to divide by 1 - t */
		fputs("pigment { rgbt ", f);
		pov_vec4(f, v3s(0), t);
		fputs(" }", f);
	} else
		diffuse_pigment(f, cx, m, 1 - t, t);
	fputs("\n    finish { ambient 0", f);
	if (!vzero(m->emit)) {
		fputs(" emission rgb ", f);
		pov_vec(f, safe_div(m->emit, m->diffuse));
	}
	diffuse_weight(f, cx, m, t < 1 ? 1 - t : 1);
	fputs(" brilliance 1 specular ", f);
	pov_num(f, s);
	if (s != 0)
		roughness(f, m->shininess);
	fputs(" phong 0", f);
	if (m->fresnel)
		fresnel_reflection(f, m);
	else if (!vzero(m->reflect)) {
		fputs(" reflection { rgb ", f);
		pov_vec(f, m->reflect);
		fputs(" }", f);
	}
	fputs(" }\n  }\n", f);
}

/* The general recipe: four layers, bottom first: S (highlight, transmission, Fresnel
 * reflection), F (filters S by k_s), D (diffuse and plain reflection), E (emission). */
static void write_layers(FILE *f, const struct pov_material_context *cx, const struct material *m)
{
	bool has_emit = !vzero(m->emit);
	bool has_fs = !vzero(m->specular) || !vzero(m->transmit) || m->fresnel;
	double tE = has_emit ? 0.5 : 1, tD = has_fs ? 0.5 : 0;
	if (has_fs) {
		/* k_s' = max(k_s, TINY) where k_t is not 0, everywhere with Fresnel */
		struct vec3 ks = m->specular, kt = m->transmit;
		if ((kt.x != 0 || m->fresnel) && ks.x < TINY)
			ks.x = TINY;
		if ((kt.y != 0 || m->fresnel) && ks.y < TINY)
			ks.y = TINY;
		if ((kt.z != 0 || m->fresnel) && ks.z < TINY)
			ks.z = TINY;
		fputs("  texture { pigment { rgbf ", f);                                   /* S */
		pov_vec4(f, safe_div(kt, ks), 1);
		fputs(" }\n            finish { ambient 0 diffuse 0 specular 1", f);
		roughness(f, m->shininess);
		fputs(" phong 0", f);
		if (m->fresnel)
			fresnel_reflection(f, m);
		fputs(" } }\n", f);
		fputs("  texture { pigment { rgbf ", f);                                   /* F */
		pov_vec4(f, vdiv(ks, tE * tD), 1);
		fputs(" }\n            finish { ambient 0 diffuse 0 specular 0 phong 0 } }\n", f);
	}
	fputs("  texture { ", f);                                                     /* D */
	diffuse_pigment(f, cx, m, (1 - tD) * tE, tD);
	fputs("\n            finish { ambient 0", f);
	diffuse_weight(f, cx, m, (1 - tD) * tE);
	fputs(" brilliance 1 specular 0 phong 0", f);
	if (!m->fresnel && !vzero(m->reflect)) {
		fputs(" reflection { rgb ", f);
		pov_vec(f, m->reflect);
		fputs(" }", f);
	}
	fputs(" } }\n", f);
	if (has_emit) {
		fputs("  texture { pigment { rgbt ", f);                                  /* E */
		pov_vec4(f, vdiv(m->emit, 1 - tE), tE);
		fputs(" }\n            finish { ambient 0 emission 1 diffuse 0 specular 0 phong 0 } }\n", f);
	}
}

bool pov_material_interior(const struct material *m, double *ior)
{
	*ior = pov_ior(m->ior);
	return !vzero(m->transmit) || m->fresnel;
}

/* The material's textures, bottom first: one layer or the four of the general recipe. */
static void write_textures(FILE *f, const struct pov_material_context *cx, const struct material *m)
{
	if (single_layer(m))
		write_single_layer(f, cx, m);
	else
		write_layers(f, cx, m);
}

void pov_write_material(FILE *f, const struct scene *sc, size_t index, bool shared, bool listed, const char *pov_dir)
{
	const struct pov_material_context cx = { sc, pov_dir };
	const struct material *m = &sc->materials[index];
	fprintf(f, "// scn material %zu: diffuse ", index);
	if (m->pigment == MATERIAL_CHECKER) {
		fputs("checker(", f);
		pov_vec(f, m->diffuse);
		fputs(", ", f);
		pov_vec(f, m->diffuse2);
		fputs(", ", f);
		pov_num(f, m->checker_size);
		fputs(")", f);
	} else {
		pov_vec(f, m->diffuse);
	}
	if (m->pigment == MATERIAL_PATTERN || m->pigment == MATERIAL_IMAGE)
		fprintf(f, " (a%s)", m->pigment == MATERIAL_PATTERN ? " pattern" : "n image map");
	if (m->bump >= 0)
		fputs(" with bumps", f);
	fputs(" specular ", f);
	pov_vec(f, m->specular);
	fputs(" shininess ", f);
	pov_num(f, m->shininess);
	fputs(" reflect ", f);
	pov_vec(f, m->reflect);
	fputs(" transmit ", f);
	pov_vec(f, m->transmit);
	fputs(" ior ", f);
	pov_num(f, m->ior);
	if (m->fresnel)
		fputs(" fresnel", f);
	fputs(" emit ", f);
	pov_vec(f, m->emit);
	fputc('\n', f);
	bool single = single_layer(m);
	fprintf(f, "#declare scn_material_%zu = material {%s\n", index,
	        single ? "" : "  // general recipe: layers S, F, D, E (the last is on top)");
	if (image_once(&cx, m) && (!single || m->transmit.x != 0))
		fputs("  // not exact: outside its `once` image, POV-Ray's transmitting or layered twin shows the"
		      " layers below rather than the plain diffuse colour\n", f);
	write_textures(f, &cx, m);
	double ior;
	bool interior = pov_material_interior(m, &ior);
	if (interior) {
		fputs("  interior { ior ", f);
		pov_num(f, ior);
		fputs(" }\n", f);
	}
	fputs("}\n", f);
	if (shared && interior) {
		fprintf(f, "#declare scn_material_%zu_shared = material {  // without its interior: its solid's CSG"
		           " holds one for all its members\n", index);
		write_textures(f, &cx, m);
		fputs("}\n", f);
	}
	if (listed) {
		fprintf(f, "#declare scn_texture_%zu =  // its layers alone, for a mesh2's texture_list\n", index);
		write_textures(f, &cx, m);
	}
}

void pov_texture_ref(FILE *f, const struct scene *sc, uint32_t surface, bool world)
{
	const struct surface *s = &sc->geo.surfaces[surface];
	fprintf(f, "texture { scn_texture_%u", (unsigned)s->material);
	if (world && s->to_object >= 0 && material_textured(&sc->materials[s->material])) {
		fputs(" transform { ", f);
		pov_matrix(f, &sc->affines[s->to_object]);
		fputs(" inverse }", f);
	}
	fputs(" }", f);
}

/* A textured material in object space gets the object's transform: POV-Ray applies the
 * inverse of a transform to the point, and `inverse` makes that inverse exactly scn's
 * to_object map. */
void pov_material_ref(FILE *f, const struct scene *sc, uint32_t surface, bool shared)
{
	const struct surface *s = &sc->geo.surfaces[surface];
	double ior;
	fprintf(f, "material { scn_material_%u%s", (unsigned)s->material,
	        shared && pov_material_interior(&sc->materials[s->material], &ior) ? "_shared" : "");
	if (s->to_object >= 0 && material_textured(&sc->materials[s->material])) {
		fputs(" transform { ", f);
		pov_matrix(f, &sc->affines[s->to_object]);
		fputs(" inverse }", f);
	}
	fputs(" }", f);
}
