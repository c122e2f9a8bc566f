/* pov_solid.c: the solids of LANGUAGE.md section 9 as POV-Ray objects. Each leaf is POV-
 * Ray's shape in the canonical form scn intersects it in (part.h), placed by the matrix of
 * its to_world map, so that both programs compute in the same space; each CSG node is
 * POV-Ray's union, intersection or merge of its members. Lowering pushed inversion down to
 * the leaves as POV-Ray inverts a CSG (De Morgan), so a difference arrives as an
 * intersection whose cutters are inverse leaves: POV-Ray's own reading of difference. */
#include "pov_solid.h"

#include "pov_material.h"
#include "pov_mesh.h"
#include "pov_write.h"

/* The part a CSG of one member stands for: that member (or its own such member). */
static uint32_t collapse(const struct scene *sc, uint32_t index)
{
	while (sc->geo.parts[index].kind == PART_CSG && sc->geo.parts[index].count == 1)
		index = sc->geo.members[sc->geo.parts[index].first];
	return index;
}

/* Goes over the leaves under part index that carry an interior: counts them in *n, sets
 * *distinct when their iors are not all *ior (the first one's), and with mark sets
 * mark[material] for each. */
static void interiors(const struct scene *sc, uint32_t index, double *ior, size_t *n, bool *distinct, bool *mark)
{
	const struct part *p = &sc->geo.parts[index];
	if (p->kind == PART_CSG) {
		for (uint32_t k = 0; k < p->count; k++)
			interiors(sc, sc->geo.members[p->first + k], ior, n, distinct, mark);
		return;
	}
	uint32_t m = sc->geo.surfaces[p->surface].material;
	double leaf_ior;
	if (!pov_material_interior(&sc->materials[m], &leaf_ior))
		return;
	if ((*n)++ == 0)
		*ior = leaf_ior;
	*distinct |= leaf_ior != *ior;
	if (mark)
		mark[m] = true;
}

/* Whether the solid at root is one body (pov_solid.h); *ior its interior's ior. */
static bool one_body(const struct scene *sc, uint32_t root, double *ior, bool *shared)
{
	root = collapse(sc, root);
	if (sc->geo.parts[root].kind != PART_CSG)
		return false;
	size_t n = 0;
	bool distinct = false;
	interiors(sc, root, ior, &n, &distinct, NULL);
	if (n == 0 || distinct)
		return false;
	if (shared)
		interiors(sc, root, ior, &n, &distinct, shared);
	return true;
}

bool pov_solid_one_body(const struct scene *sc, uint32_t root, bool *shared)
{
	double ior;
	return one_body(sc, root, &ior, shared);
}

static void indent(FILE *f, int depth)
{
	for (int i = 0; i < depth; i++)
		fputs("  ", f);
}

/* A leaf: its shape, matrix, inverse and material, on one line (a mesh2 on several, at
 * the left margin). */
static void write_leaf(FILE *f, const struct scene *sc, const struct part *p, int depth, bool shared)
{
	indent(f, depth);
	switch (p->kind) {
	case PART_SPHERE:
		fputs("sphere { <0, 0, 0>, 1", f);
		break;
	case PART_BOX:
		fputs("box { ", f);
		pov_vec(f, v3(p->a[0], p->a[1], p->a[2]));
		fputs(", ", f);
		pov_vec(f, v3(p->a[3], p->a[4], p->a[5]));
		break;
	case PART_CONE:
		/* part_make_cone scales the larger radius to exactly 1: a cylinder has both 1 */
		if (p->a[0] == 1 && p->a[1] == 1) {
			fputs("cylinder { <0, 0, 0>, <0, 1, 0>, 1", f);
		} else {
			fputs("cone { <0, 0, 0>, ", f);
			pov_num(f, p->a[0]);
			fputs(", <0, 1, 0>, ", f);
			pov_num(f, p->a[1]);
		}
		if (p->open)
			fputs(" open", f);
		break;
	case PART_DISC:
		fputs("disc { <0, 0, 0>, <0, 1, 0>, 1", f);
		if (p->a[0] > 0) {
			fputs(", ", f);
			pov_num(f, p->a[0]);
		}
		break;
	case PART_TORUS:
		fputs("torus { ", f);
		pov_num(f, p->a[0]);
		fputs(", ", f);
		pov_num(f, p->a[1]);
		break;
	case PART_PLANE:               /* in world space already */
		fputs("plane { ", f);
		pov_vec(f, v3(p->a[0], p->a[1], p->a[2]));
		fputs(", ", f);
		pov_num(f, p->a[3]);
		break;
	case PART_MESH:                /* world-space triangles, in single precision as any mesh2 */
		pov_mesh2_body(f, sc, sc->geo.part_triangles, p->first, p->first + p->count, NULL, NULL);
		fputs("  inside_vector ", f);
		pov_vec(f, v3(p->a[0], p->a[1], p->a[2]));
		break;
	case PART_CSG:
		break;
	}
	if (p->moved) {
		fputc(' ', f);
		pov_matrix(f, &p->to_world);
	}
	if (p->inverse)
		fputs(" inverse", f);
	/* after the matrix, so that the material stays in world space: its pattern space is
	 * the surface's own (LANGUAGE.md: the object's, or the CSG's it inherits from) */
	fputc(' ', f);
	pov_material_ref(f, sc, p->surface, shared);
	fputs(p->kind == PART_MESH ? "\n}\n" : " }\n", f);
}

/* Part index and its members, at depth; shared: the materials without their interiors.
 * ior: the interior the solid's root holds, or NULL. */
static void write_part(FILE *f, const struct scene *sc, uint32_t index, int depth, bool shared, const double *ior)
{
	index = collapse(sc, index);   /* POV-Ray warns of a CSG of one member */
	const struct part *p = &sc->geo.parts[index];
	if (p->kind != PART_CSG) {
		write_leaf(f, sc, p, depth, shared);
		return;
	}
	static const char *const keyword[] = {
		[PART_ALL] = "union", [PART_INTERSECT] = "intersection", [PART_MERGE] = "merge",
	};
	indent(f, depth);
	fprintf(f, "%s {\n", keyword[p->op]);
	for (uint32_t k = 0; k < p->count; k++)
		write_part(f, sc, sc->geo.members[p->first + k], depth + 1, shared, NULL);
	if (ior) {
		indent(f, depth + 1);
		fputs("interior { ior ", f);
		pov_num(f, *ior);
		fputs(" }  // the one interior of all its members\n", f);
	}
	indent(f, depth);
	fputs("}\n", f);
}

/* Whether leaf p's material transmits; refracts: and bends (ior not 1). */
static bool leaf_transmits(const struct scene *sc, const struct part *p, bool refracts)
{
	const struct material *m = &sc->materials[sc->geo.surfaces[p->surface].material];
	return !vzero(m->transmit) && (!refracts || m->ior != 1);
}

/* Whether a leaf under part index transmits. */
static bool transmits(const struct scene *sc, uint32_t index)
{
	const struct part *p = &sc->geo.parts[index];
	if (p->kind != PART_CSG)
		return leaf_transmits(sc, p, false);
	for (uint32_t k = 0; k < p->count; k++)
		if (transmits(sc, sc->geo.members[p->first + k]))
			return true;
	return false;
}

static bool boxes_meet(struct vec3 alo, struct vec3 ahi, struct vec3 blo, struct vec3 bhi)
{
	return alo.x < bhi.x && blo.x < ahi.x && alo.y < bhi.y && blo.y < ahi.y && alo.z < bhi.z && blo.z < ahi.z;
}

/* Adds to n what under part index POV-Ray will not compute as scn does: refracting open
 * leaves, and unions whose transmitting members' bounds meet. */
static void notes_under(const struct scene *sc, uint32_t index, struct pov_solid_notes *n)
{
	const struct part *p = &sc->geo.parts[index];
	if (p->kind != PART_CSG) {
		n->open += (p->kind == PART_DISC || (p->kind == PART_CONE && p->open)) && leaf_transmits(sc, p, true);
		return;
	}
	const uint32_t *members = sc->geo.members + p->first;
	bool meet = false;
	for (uint32_t k = 0; k < p->count; k++) {
		notes_under(sc, members[k], n);
		for (uint32_t j = 0; j < k && p->op == PART_ALL && !meet; j++) {
			const struct part *a = &sc->geo.parts[members[j]], *b = &sc->geo.parts[members[k]];
			meet = boxes_meet(a->lo, a->hi, b->lo, b->hi) && transmits(sc, members[j]) && transmits(sc, members[k]);
		}
	}
	n->unions += meet;
}

void pov_solid_notes(const struct scene *sc, struct pov_solid_notes *n)
{
	*n = (struct pov_solid_notes){ 0 };
	const struct geometry *g = &sc->geo;
	for (size_t i = 0; i < g->nsolids + g->nunbounded; i++) {
		uint32_t root = i < g->nsolids ? g->solids[i] : g->unbounded[i - g->nsolids];
		notes_under(sc, root, n);
		double ior;
		size_t count = 0;
		bool distinct = false;
		interiors(sc, root, &ior, &count, &distinct, NULL);
		n->iors += distinct && transmits(sc, root);
		/* bounded transmitting solids against each other and transmitting spheres: a
		 * bounded search, enough for any hand-made scene */
		if (i >= g->nsolids || g->nsolids + g->nspheres > 4096 || !transmits(sc, root))
			continue;
		const struct part *a = &g->parts[root];
		bool meet = false;
		for (size_t j = 0; j < g->nsolids && !meet; j++)
			meet = j != i && boxes_meet(a->lo, a->hi, g->parts[g->solids[j]].lo, g->parts[g->solids[j]].hi) &&
			       transmits(sc, g->solids[j]);
		for (size_t j = 0; j < g->nspheres && !meet; j++) {
			const struct sphere *b = &g->spheres[j];
			meet = boxes_meet(a->lo, a->hi, vsub(b->center, v3s(b->radius)), vadd(b->center, v3s(b->radius))) &&
			       !vzero(sc->materials[g->surfaces[b->surface].material].transmit);
		}
		n->overlaps += meet;
	}
}

void pov_write_solid(FILE *f, const struct scene *sc, uint32_t root)
{
	double ior;
	bool shared = one_body(sc, root, &ior, NULL);
	write_part(f, sc, root, 0, shared, shared ? &ior : NULL);
}
