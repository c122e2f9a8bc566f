/* ray.c: the origin of a ray spawned from a surface point (ray.h). */
#include "ray.h"

struct vec3 ray_offset_origin(const struct surface_point *sp, struct vec3 w)
{
	double dist = vdot(vabs(sp->ng), sp->p_err);
	struct vec3 off = vscale(sp->ng, dist);
	if (vdot(w, sp->ng) < 0)
		off = vneg(off);
	struct vec3 o = vadd(sp->p, off);
	/* round away from the surface: the sum above may have rounded towards it */
	return v3(vstep(o.x, off.x), vstep(o.y, off.y), vstep(o.z, off.z));
}
