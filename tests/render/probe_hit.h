/* probe_hit.h: what the probe's `hit` and `lambert` checks know of a scene: scn's pinhole
 * camera (render/camera.c) and exact tests of whether a ray meets a shape, written apart
 * from the renderer (the torus without a quartic), so that they judge its silhouettes.
 * They run in double: in the tests' scenes their rounding is below 1e-11 of the shape's
 * size, far inside the margin PROBE_MARGIN (long double was 4.5 times slower on the
 * torus, with the same answers). */
#ifndef SCN_PROBE_HIT_H
#define SCN_PROBE_HIT_H

#include <stdbool.h>

typedef double real;

/* scn's camera: location, look_at, up, fov as camera_setup() takes them, the image's
 * width and height, and the grid pattern's n (n x n samples a pixel at ((a + 0.5) / n,
 * (b + 0.5) / n); 1 is the pixel centre). */
struct probe_camera {
	real eye[3], dir[3], right[3], up[3], tan_half;
	int width, height, grid;
};

void probe_camera_setup(struct probe_camera *c, const double eye[3], const double look_at[3], const double up[3],
                        double fov, int width, int height, int grid);
/* The direction of sample (a, b) of pixel (px, py), not normalised: scn's sample_ray()
 * and camera_ray() for the grid pattern. */
void probe_camera_ray(const struct probe_camera *c, int px, int py, int a, int b, real d[3]);

enum probe_shape_kind { PROBE_ELLIPSOID, PROBE_TORUS, PROBE_DISC, PROBE_BOX };

/* ELLIPSOID: centre c, semi-axes a (axis-aligned).
 * TORUS: about the axis through c parallel to y, major radius major, minor radius minor.
 * DISC: centre c, normal n, radius radius.
 * BOX: lo <= p <= hi (a flat box, lo = hi on an axis, is a rectangle). */
struct probe_shape {
	enum probe_shape_kind kind;
	real c[3], a[3], n[3], major, minor, radius, lo[3], hi[3];
};

/* Whether the ray from o along d meets the shape grown by the factor g about its centre
 * (the semi-axes, the minor radius, the disc's radius, the box's half-sizes times g),
 * at some t > 0. */
bool probe_shape_hit(const struct probe_shape *s, const real o[3], const real d[3], real g);
/* How a sample ray stands with the shape: PROBE_IN when it meets the shape shrunk by
 * the relative margin, PROBE_OUT when it misses it grown by it, PROBE_EDGE (undecided)
 * when its distance from tangency is within the margin. */
enum probe_side { PROBE_OUT, PROBE_IN, PROBE_EDGE };
enum probe_side probe_shape_side(const struct probe_shape *s, const real o[3], const real d[3]);
/* The relative margin of probe_shape_side: far above long double's rounding in these
 * tests, far below a pixel. */
#define PROBE_MARGIN 1e-9

/* The outward unit normal of ellipsoid s (grown by g) where the ray from o along d first
 * meets it; false when it misses. */
bool probe_ellipsoid_normal(const struct probe_shape *s, const real o[3], const real d[3], real g, real n[3]);

#endif
