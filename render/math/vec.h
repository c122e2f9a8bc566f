/* vec.h: double-precision 3-vectors for geometry and colour (NUMERICS.md section 1:
 * everything geometric is double). */
#ifndef SCN_VEC_H
#define SCN_VEC_H

#include <math.h>
#include <stdint.h>
#include <string.h>

struct vec3 {
	double x, y, z;
};

static inline struct vec3 v3(double x, double y, double z) { return (struct vec3){ x, y, z }; }
static inline struct vec3 v3s(double s) { return (struct vec3){ s, s, s }; }
static inline struct vec3 v3a(const double a[3]) { return (struct vec3){ a[0], a[1], a[2] }; }
static inline struct vec3 vadd(struct vec3 a, struct vec3 b) { return v3(a.x + b.x, a.y + b.y, a.z + b.z); }
static inline struct vec3 vsub(struct vec3 a, struct vec3 b) { return v3(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline struct vec3 vmul(struct vec3 a, struct vec3 b) { return v3(a.x * b.x, a.y * b.y, a.z * b.z); }
static inline struct vec3 vscale(struct vec3 a, double s) { return v3(a.x * s, a.y * s, a.z * s); }
static inline struct vec3 vneg(struct vec3 a) { return v3(-a.x, -a.y, -a.z); }
static inline struct vec3 vabs(struct vec3 a) { return v3(fabs(a.x), fabs(a.y), fabs(a.z)); }
static inline double vdot(struct vec3 a, struct vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline struct vec3 vcross(struct vec3 a, struct vec3 b)
{
	return v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static inline double vlen(struct vec3 a) { return sqrt(vdot(a, a)); }
/* Unit vector along a; a must not be zero. */
static inline struct vec3 vnorm(struct vec3 a) { return vscale(a, 1 / vlen(a)); }
/* Unit vector along a for any finite nonzero a, also one whose squared length under- or
 * overflows (a direction of 1e-310 or 1e200): a is first divided by its largest
 * component. For directions given by a scene, not for the hot path. */
static inline struct vec3 vunit(struct vec3 a)
{
	double m = fmax(fabs(a.x), fmax(fabs(a.y), fabs(a.z)));
	return vnorm(v3(a.x / m, a.y / m, a.z / m));
}
static inline struct vec3 vmin(struct vec3 a, struct vec3 b) { return v3(fmin(a.x, b.x), fmin(a.y, b.y), fmin(a.z, b.z)); }
static inline struct vec3 vmax(struct vec3 a, struct vec3 b) { return v3(fmax(a.x, b.x), fmax(a.y, b.y), fmax(a.z, b.z)); }
/* Coordinate axis of *a, without a branch on axis (an incoherent ray's triangle test
 * indexes by its own axes) and without a copy of *a. */
static inline double vget(const struct vec3 *a, int axis)
{
	_Static_assert(sizeof(struct vec3) == 3 * sizeof(double), "vget indexes struct vec3");
	return *(const double *)((const char *)a + (size_t)axis * sizeof(double));
}
static inline double vmaxc(struct vec3 a) { return fmax(a.x, fmax(a.y, a.z)); }
static inline int vzero(struct vec3 a) { return a.x == 0 && a.y == 0 && a.z == 0; }
/* a + s b */
static inline struct vec3 vmad(struct vec3 a, double s, struct vec3 b) { return v3(a.x + s * b.x, a.y + s * b.y, a.z + s * b.z); }

/* The double next to finite x in the direction of the sign of s (x itself for s = 0):
 * nextafter(x, s * inf) without the library call, for the hot path. */
static inline double vstep(double x, double s)
{
	if (s == 0)
		return x;
	if (x == 0)
		return copysign(0x1p-1074, s);
	uint64_t u;
	memcpy(&u, &x, sizeof u);
	u += (x > 0) == (s > 0) ? 1 : (uint64_t)-1; /* away from zero: the bits grow */
	memcpy(&x, &u, sizeof x);
	return x;
}

#endif
