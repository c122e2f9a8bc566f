/* plane.c: the hit point projected onto the plane, with a bound on its error (the test
 * itself is inline, in plane.h). */
#include "plane.h"

#include <math.h>

#include "rounding.h"

void plane_surface(const struct plane *pl, const struct ray *r, const struct hit *h, struct surface_point *sp)
{
	struct vec3 p = vmad(r->o, h->t, r->d);
	/* project onto the plane. The bound is on the magnitudes that entered the
	 * projection, not on the projected point: with a normal whose length is 1 only
	 * to a rounding (a scaled plane's), a coordinate the projection sends to about 0
	 * keeps a residue of the order of the original coordinate's rounding. */
	sp->p = vsub(p, vscale(pl->normal, vdot(pl->normal, p) - pl->offset));
	sp->p_err = vscale(vadd(vmax(vabs(p), vabs(sp->p)), v3s(fabs(pl->offset))), rounding_gamma(7));
	sp->ng = pl->normal;
	sp->ns = pl->normal;
}
