/* image_map.c: POV-Ray's image_map lookups (map_type 0, 1, 2 and uv_mapping; nearest and
 * bilinear; once) and the uv_mapping of a sphere and a torus, as POV-Ray 3.7.0.10's
 * imageutil.cpp, spheres.cpp and torus.cpp compute them (povray-equivalence.md 15). */
#include <math.h>

#include "texture.h"

#define TWO_PI 6.283185307179586

/* POV-Ray's EPSILON, which its map_pos adds to both image coordinates. */
#define IMAGE_EPSILON 1e-10

/* v wrapped into [0, limit), as POV-Ray's wrap: fmod, plus limit when negative, and a
 * result that rounds up to limit is 0. */
static double wrap(double v, double limit)
{
	double r = fmod(v, limit);
	if (r < 0)
		r += limit;
	return r >= limit ? 0 : r;
}

/* The angle of (x, z) from +x towards +z, as a fraction of a turn in [0, 1); len is
 * sqrt(x^2 + z^2) > 0. POV-Ray's acos form, kept for its exact values on the axes. */
static double turn(double x, double z, double len)
{
	if (z == 0)
		return x > 0 ? 0 : 0.5;
	double c = x / len;
	double theta = acos(c < -1 ? -1 : c > 1 ? 1 : c);
	if (z < 0)
		theta = TWO_PI - theta;
	return theta / TWO_PI;
}

/* The image coordinates (column and row, in texels, wrapped into the image) of q, or false
 * where POV-Ray's image map gives no colour (outside with `once`, or a point where the
 * spherical or cylindrical map has no direction). */
static bool image_coords(const struct image_map *im, struct vec3 q, double *col, double *row)
{
	double w = im->image->width, h = im->image->height;
	double u = 0, v = 0;
	switch (im->map) {
	case TEXTURE_MAP_SPHERICAL: {
		double len = vlen(q);
		if (len == 0)
			return false;
		double x = q.x / len, y = q.y / len, z = q.z / len;
		double lxz = sqrt(x * x + z * z);
		u = lxz == 0 ? 0 : turn(x, z, lxz) * w;   /* a pole: any column */
		v = (0.5 + asin(y < -1 ? -1 : y > 1 ? 1 : y) / M_PI) * h;
		break;
	}
	case TEXTURE_MAP_CYLINDRICAL: {
		if (im->once && (q.y < 0 || q.y > 1))
			return false;
		v = fmod(q.y * h, h);
		/* the angle of the point's direction, as POV-Ray finds it */
		double len = vlen(q);
		if (len == 0)
			return false;
		double x = q.x / len, z = q.z / len;
		double lxz = sqrt(x * x + z * z);
		if (lxz == 0)
			return false;
		u = turn(x, z, lxz) * w;
		break;
	}
	default:                                    /* planar; uv looks up (u, v, 0) so */
		if (im->once && (q.x < 0 || q.x > 1))
			return false;
		u = fmod(q.x * w, w);
		if (im->once && (q.y < 0 || q.y > 1))
			return false;
		v = fmod(q.y * h, h);
		break;
	}
	u += IMAGE_EPSILON;
	v += IMAGE_EPSILON;
	if (im->once && (u >= w || v >= h || u < 0 || v < 0))
		return false;
	*col = wrap(u, w);
	*row = wrap(-v, h);                         /* row 0 is the image's top */
	return true;
}

/* The texel at (x, y), which may lie one texel outside the image: wrapped around, or with
 * `once` the nearest edge texel. */
static struct vec3 texel(const struct image_map *im, int x, int y)
{
	const struct image *img = im->image;
	if (im->once) {
		x = x < 0 ? 0 : x >= img->width ? img->width - 1 : x;
		y = y < 0 ? 0 : y >= img->height ? img->height - 1 : y;
	} else {
		x = x < 0 ? x + img->width : x >= img->width ? x - img->width : x;
		y = y < 0 ? y + img->height : y >= img->height ? y - img->height : y;
	}
	const float *p = img->rgb + 3 * ((size_t)y * (size_t)img->width + (size_t)x);
	return v3(p[0], p[1], p[2]);
}

bool image_map_lookup(const struct image_map *im, struct vec3 q, struct vec3 *colour)
{
	double col, row;
	if (!image_coords(im, q, &col, &row))
		return false;
	if (!im->bilinear) {
		*colour = texel(im, (int)col, (int)row);
		return true;
	}
	/* POV-Ray's bilinear: between the centres of the four texels around the point */
	col += 0.5;
	row += 0.5;
	int x = (int)col, y = (int)row;
	double p = col - x, s = row - y;
	struct vec3 c = vscale(texel(im, x, y), p * s);
	c = vmad(c, (1 - p) * s, texel(im, x - 1, y));
	c = vmad(c, p * (1 - s), texel(im, x, y - 1));
	*colour = vmad(c, (1 - p) * (1 - s), texel(im, x - 1, y - 1));
	return true;
}

void texture_uv_sphere(struct vec3 p, double *u, double *v)
{
	double len = vlen(p);
	if (len == 0) {                             /* the centre: no direction */
		*u = *v = 0;
		return;
	}
	double x = p.x / len, y = p.y / len, z = p.z / len;
	*v = 0.5 + asin(y < -1 ? -1 : y > 1 ? 1 : y) / M_PI;
	/* POV-Ray's test for a pole, on the squared distance from the axis */
	double r2 = x * x + z * z;
	*u = r2 > IMAGE_EPSILON ? turn(x, z, sqrt(r2)) : 0;
}

void texture_uv_torus(struct vec3 p, double major, double *u, double *v)
{
	*u = 1 - (atan2(p.z, p.x) + M_PI) / TWO_PI;
	double r = sqrt(p.x * p.x + p.z * p.z) - major;
	*v = (atan2(p.y, r) + M_PI) / TWO_PI;
}
