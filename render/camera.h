/* camera.h: the perspective pinhole and the orthographic camera of LANGUAGE.md, framed as
 * POV-Ray frames them. */
#ifndef SCN_CAMERA_H
#define SCN_CAMERA_H

#include "ray.h"

enum camera_kind { CAMERA_PINHOLE, CAMERA_ORTHOGRAPHIC };

struct camera {
	enum camera_kind kind;         /* set once by camera_setup: one branch per ray, always taken alike */
	struct vec3 eye;
	struct vec3 dir, right, up;    /* unit D, R, U of povray-equivalence.md section 3 */
	double tan_half;               /* pinhole: tan of half the horizontal field of view */
	double view_width;             /* orthographic: |right| of povray-equivalence.md 15 */
	double lens_radius;            /* 0: a pinhole; else the thin lens's, across right and up */
	double focal_distance;         /* along dir, to the plane that is sharp */
	int width, height;
};

/* Frames the camera: D = normalize(look_at - eye), R = normalize(up x D), U = D x R
 * (povray-equivalence.md section 3). fov is horizontal, in degrees. A pinhole camera. */
void camera_setup(struct camera *c, struct vec3 eye, struct vec3 look_at, struct vec3 up, double fov,
                  int width, int height);

/* Makes c, framed by camera_setup, orthographic: a view view_width wide in scene units,
 * its height following the aspect. */
void camera_set_orthographic(struct camera *c, double view_width);

/* Gives c a thin lens (LANGUAGE.md section 12) as POV-Ray's focal blur: its aperture
 * (> 0) and the point that is sharp. */
void camera_set_lens(struct camera *c, double aperture, struct vec3 focal_point);

/* Ray r of camera_ray, moved to pass through the lens at (x, y) of the unit disc and
 * still reach the point of the sharp plane it reached. */
struct ray camera_lens_ray(const struct camera *c, struct ray r, double x, double y);

/* The ray through the image-plane point (u, v) in [0,1]^2, u across from the left edge,
 * v down from the top edge: u = (i + sx) / W for pixel column i and sample offset sx. */
struct ray camera_ray(const struct camera *c, double u, double v);

#endif
