/* camera.c: framing and primary rays, in double precision, pixel centres at (i + 0.5) / W
 * with nothing divided by W - 1 (NUMERICS.md section 10). */
#include "camera.h"

#include <math.h>

void camera_setup(struct camera *c, struct vec3 eye, struct vec3 look_at, struct vec3 up, double fov,
                  int width, int height)
{
	c->kind = CAMERA_PINHOLE;
	c->eye = eye;
	c->dir = vunit(vsub(look_at, eye));
	c->right = vunit(vcross(vunit(up), c->dir));
	c->up = vcross(c->dir, c->right);
	c->tan_half = tan(fov * (M_PI / 360));
	c->view_width = 0;
	c->lens_radius = 0;
	c->focal_distance = 0;
	c->width = width;
	c->height = height;
}

void camera_set_orthographic(struct camera *c, double view_width)
{
	c->kind = CAMERA_ORTHOGRAPHIC;
	c->view_width = view_width;
}

struct ray camera_ray(const struct camera *c, double u, double v)
{
	if (c->kind == CAMERA_ORTHOGRAPHIC) {
		/* povray-equivalence.md 15: the origin moves across the view, |right| = width and
		 * |up| = width H / W; every ray runs along D */
		double sx = (u - 0.5) * c->view_width;
		double sy = (0.5 - v) * c->view_width * ((double)c->height / c->width);
		return (struct ray){ vadd(c->eye, vadd(vscale(c->right, sx), vscale(c->up, sy))), c->dir };
	}
	double sx = (2 * u - 1) * c->tan_half;
	double sy = (1 - 2 * v) * c->tan_half * ((double)c->height / c->width);
	struct vec3 d = vadd(c->dir, vadd(vscale(c->right, sx), vscale(c->up, sy)));
	return (struct ray){ c->eye, vnorm(d) };
}

void camera_set_lens(struct camera *c, double aperture, struct vec3 focal_point)
{
	/* POV-Ray's lens (tracepixel.cpp, JitterCameraRay) spreads its samples over a disc of
	 * radius 0.5 scaled by aperture / 2; the sharp plane is at the focal point's distance
	 * from the camera, measured straight, not along the view */
	c->lens_radius = aperture / 4;
	c->focal_distance = vlen(vsub(focal_point, c->eye));
}

struct ray camera_lens_ray(const struct camera *c, struct ray r, double x, double y)
{
	/* the point of the sharp plane the pinhole ray reaches, then from the lens to it */
	struct vec3 focus = vadd(r.o, vscale(r.d, c->focal_distance / vdot(r.d, c->dir)));
	r.o = vadd(r.o, vadd(vscale(c->right, x * c->lens_radius), vscale(c->up, y * c->lens_radius)));
	r.d = vnorm(vsub(focus, r.o));
	return r;
}
