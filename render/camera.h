/* camera.h: the perspective pinhole camera of LANGUAGE.md, framed as POV-Ray frames it. */
#ifndef SCN_CAMERA_H
#define SCN_CAMERA_H

#include "ray.h"

struct camera {
	struct vec3 eye;
	struct vec3 dir, right, up;    /* unit D, R, U of povray-equivalence.md section 3 */
	double tan_half;               /* tan of half the horizontal field of view */
	int width, height;
};

/* Frames the camera: D = normalize(look_at - eye), R = normalize(up x D), U = D x R
 * (povray-equivalence.md section 3). fov is horizontal, in degrees. */
void camera_setup(struct camera *c, struct vec3 eye, struct vec3 look_at, struct vec3 up, double fov,
                  int width, int height);

/* The ray through the image-plane point (u, v) in [0,1]^2, u across from the left edge,
 * v down from the top edge: u = (i + sx) / W for pixel column i and sample offset sx. */
struct ray camera_ray(const struct camera *c, double u, double v);

#endif
