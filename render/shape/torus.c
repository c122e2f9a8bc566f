/* torus.c: placeholder until the quartic solver lands. */
#include "torus.h"

int torus_roots(double major, double minor, struct vec3 o, struct vec3 d, double tmax, double t[4])
{
	(void)major, (void)minor, (void)o, (void)d, (void)tmax, (void)t;
	return 0;
}

void torus_surface(double major, double minor, struct vec3 p, struct vec3 *on, struct vec3 *p_err, struct vec3 *normal)
{
	(void)major, (void)minor;
	*on = p;
	*p_err = v3s(0);
	*normal = v3(0, 1, 0);
}

bool torus_inside(double major, double minor, struct vec3 p)
{
	(void)major, (void)minor, (void)p;
	return false;
}
