/* pov_solid.h: the solids of a lowered scene (geometry.solids and geometry.unbounded: trees
 * of part.h's parts) as POV-Ray objects (pov_solid.c). */
#ifndef SCN_POV_SOLID_H
#define SCN_POV_SOLID_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "scene.h"

/* Whether POV-Ray must be told that the solid at root is one body for refraction: it
 * is a CSG, and those of its leaves that carry an interior (pov_material_interior) all
 * have one ior. POV-Ray tells the objects a ray is inside by their interiors, one per
 * object: a ray entering through one member's surface and leaving through another's would
 * leave nothing and enter a second object. So the CSG holds the interior, which POV-Ray
 * shares with members that have none, and those members take their materials without it
 * (scn_material_N_shared): then it leaves the body, as in scn, where each surface refracts
 * by its own ior against the outside. With several iors no setting gives scn's rule; the
 * leaves keep their own interiors. When shared is not NULL, sets shared[m] for each
 * material m of those leaves. */
bool pov_solid_one_body(const struct scene *sc, uint32_t root, bool *shared);
/* Writes the part tree whose root is part `root` of sc: each leaf as POV-Ray's shape in
 * its canonical form placed by `matrix`, with `inverse` and its material, each CSG node as
 * union, intersection or merge of its members. */
void pov_write_solid(FILE *f, const struct scene *sc, uint32_t root);

/* What in a scene's solids POV-Ray will not compute as scn does (each a count), for the
 * header's notes. */
struct pov_solid_notes {
	size_t iors;                   /* solids that transmit, whose members' interiors have several iors */
	size_t open;                   /* refracting discs and open cylinders and cones: no inside */
	size_t unions;                 /* unions in a solid whose transmitting members' bounds meet */
	size_t overlaps;               /* transmitting solids whose bounds meet another transmitting
	                                  solid's or sphere's */
};
void pov_solid_notes(const struct scene *sc, struct pov_solid_notes *n);

#endif
