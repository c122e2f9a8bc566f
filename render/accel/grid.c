/* grid.c: a uniform grid (Cleary and Wyvill 1988) walked cell by cell with the 3D-DDA
 * of Amanatides and Woo ("A Fast Voxel Traversal Algorithm", 1987). pbrt-v1's resolution
 * rule: 3 cbrt(N) cells along the longest side of the box, the other sides in proportion.
 * Each primitive is listed in every cell its bounding box overlaps.
 *
 * Robustness (NUMERICS.md): one monotone function, cell_of, places both the primitives'
 * boxes and the ray, so a box that holds a point is listed in the cell that point falls
 * in. Where the DDA's rounded crossing distances cannot tell which side of a cell edge or
 * corner the ray passes, the walk also visits the cells on the other side, and it stops
 * only once the closest hit lies before the earliest the ray can really leave the cell.
 * Visiting a cell too many costs time, never a wrong answer: every hit is a real one. */
#include "grid.h"

#include <math.h>
#include <stdlib.h>

#include "xalloc.h"

enum {
	MAX_CELLS = 1 << 24,  /* 64 MiB of cell offsets at most, whatever N */
	MAX_REFS_PER_PRIM = 32, /* beyond this the resolution is halved: big primitives */
};

#define MULTI_CELL (1u << 31) /* on a reference: the primitive is listed in several cells
                               * (free: a reference is the primitive's number in
                               * shape_nth(), below shape_count() < 2^31) */

struct grid {
	double lo[3], hi[3];
	double width[3], inv_width[3];
	double edge_err[3];  /* bound on the distance between lo + i width and where cell_of steps to i */
	int n[3];
	uint32_t *start;     /* cell c lists refs[start[c], start[c + 1]) */
	uint32_t *refs;      /* primitives by their number in shape_nth(), with MULTI_CELL */
	size_t nrefs;
};

struct box {
	double lo[3], hi[3];
};

/* The cell along axis k of coordinate x. Rounding is monotone, so x <= y gives
 * cell_of(x) <= cell_of(y): everything below rests on that. */
static inline int cell_of(const struct grid *g, int k, double x)
{
	double f = (x - g->lo[k]) * g->inv_width[k];
	if (!(f >= 0))
		return 0;
	return f >= g->n[k] ? g->n[k] - 1 : (int)f;
}

static inline size_t cell_index(const struct grid *g, const int c[3])
{
	return ((size_t)c[2] * (size_t)g->n[1] + (size_t)c[1]) * (size_t)g->n[0] + (size_t)c[0];
}

static struct box prim_box(const struct geometry *geo, uint32_t prim)
{
	struct vec3 lo, hi;
	shape_bounds(geo, prim, &lo, &hi);
	/* centre -+ radius is rounded: one ulp outward holds the exact box */
	struct box bx;
	for (int k = 0; k < 3; k++) {
		bx.lo[k] = nextafter(vget(&lo, k), -INFINITY);
		bx.hi[k] = nextafter(vget(&hi, k), INFINITY);
	}
	return bx;
}

/* Sets the resolution for cells_per_unit cells per unit of length along each side. */
static void set_resolution(struct grid *g, double cells_per_unit)
{
	for (int k = 0; k < 3; k++) {
		double extent = g->hi[k] - g->lo[k];
		double n = floor(extent * cells_per_unit + 0.5);
		g->n[k] = n < 1 ? 1 : n > 4096 ? 4096 : (int)n;
		g->width[k] = extent / g->n[k];
		g->inv_width[k] = extent > 0 ? g->n[k] / extent : 0;
		/* lo + i width and the step of cell_of each carry a few roundings of numbers up to
		 * |lo| + |hi| */
		g->edge_err[k] = rounding_gamma(8) * (fabs(g->lo[k]) + fabs(g->hi[k]) + extent);
	}
}

/* The first and last cell along each axis that the box overlaps. */
static void cell_range(const struct grid *g, const struct box *bx, int first[3], int last[3])
{
	for (int k = 0; k < 3; k++) {
		first[k] = cell_of(g, k, bx->lo[k]);
		last[k] = cell_of(g, k, bx->hi[k]);
	}
}

/* The references the boxes would make at the current resolution. */
static size_t count_refs(const struct grid *g, const struct box *boxes, size_t n)
{
	size_t total = 0;
	for (size_t i = 0; i < n; i++) {
		int first[3], last[3];
		cell_range(g, &boxes[i], first, last);
		total += (size_t)(last[0] - first[0] + 1) * (size_t)(last[1] - first[1] + 1) * (size_t)(last[2] - first[2] + 1);
	}
	return total;
}

uint64_t grid_bytes(uint64_t n)
{
	double side = 3 * cbrt((double)n) + 1;
	double cells = fmin(side * side * side, MAX_CELLS) + 1;
	return (uint64_t)cells * 2 * sizeof(uint32_t) + n * sizeof(struct box) +
	       (MAX_REFS_PER_PRIM * n + ((uint64_t)1 << 20)) * sizeof(uint32_t);
}

struct grid *grid_build(const struct geometry *geo)
{
	struct grid *g = xcalloc(1, sizeof *g);
	size_t n = shape_count(geo);
	if (n == 0)
		return g;
	struct box *boxes = xcalloc(n, sizeof *boxes);
	for (int k = 0; k < 3; k++) {
		g->lo[k] = INFINITY;
		g->hi[k] = -INFINITY;
	}
	for (size_t i = 0; i < n; i++) {
		boxes[i] = prim_box(geo, shape_nth(geo, i));
		for (int k = 0; k < 3; k++) {
			g->lo[k] = fmin(g->lo[k], boxes[i].lo[k]);
			g->hi[k] = fmax(g->hi[k], boxes[i].hi[k]);
		}
	}
	double longest = fmax(g->hi[0] - g->lo[0], fmax(g->hi[1] - g->lo[1], g->hi[2] - g->lo[2]));
	double per_unit = longest > 0 ? 3 * cbrt((double)n) / longest : 0;
	set_resolution(g, per_unit);
	/* cap the cells, then the references: big overlapping primitives would otherwise be
	 * listed in a great many cells */
	while ((double)g->n[0] * g->n[1] * g->n[2] > MAX_CELLS)
		set_resolution(g, per_unit *= 0.8);
	while (count_refs(g, boxes, n) > MAX_REFS_PER_PRIM * n + ((size_t)1 << 20) && per_unit > 0)
		set_resolution(g, per_unit *= 0.5);

	size_t ncells = (size_t)g->n[0] * g->n[1] * g->n[2];
	g->start = xcalloc(ncells + 1, sizeof *g->start);
	/* count each cell's references into start[c], sum them so that start[c] is where
	 * cell c ends, then fill each cell from its end down: start[c] ends where it begins */
	int c[3], first[3], last[3];
	for (size_t i = 0; i < n; i++) {
		cell_range(g, &boxes[i], first, last);
		for (c[2] = first[2]; c[2] <= last[2]; c[2]++)
			for (c[1] = first[1]; c[1] <= last[1]; c[1]++)
				for (c[0] = first[0]; c[0] <= last[0]; c[0]++)
					g->start[cell_index(g, c)]++;
	}
	for (size_t i = 1; i <= ncells; i++)
		g->start[i] += g->start[i - 1];
	g->nrefs = g->start[ncells];
	g->refs = xcalloc(g->nrefs ? g->nrefs : 1, sizeof *g->refs);
	for (size_t i = n; i-- > 0;) {
		cell_range(g, &boxes[i], first, last);
		bool multi = first[0] != last[0] || first[1] != last[1] || first[2] != last[2];
		/* the number, not the id: a solid's id has bit 31 set */
		uint32_t ref = (uint32_t)i | (multi ? MULTI_CELL : 0);
		for (c[2] = first[2]; c[2] <= last[2]; c[2]++)
			for (c[1] = first[1]; c[1] <= last[1]; c[1]++)
				for (c[0] = first[0]; c[0] <= last[0]; c[0]++)
					g->refs[--g->start[cell_index(g, c)]] = ref;
	}
	free(boxes);
	return g;
}

void grid_free(struct grid *g)
{
	if (!g)
		return;
	free(g->start);
	free(g->refs);
	free(g);
}

void grid_shape(const struct grid *g, int cells[3], size_t *refs)
{
	for (int k = 0; k < 3; k++)
		cells[k] = g->n[k];
	*refs = g->nrefs;
}

/* ---- the walk ---- */

struct walk {
	double o[3], inv[3];
	int cell[3], step[3];
	bool active[3];      /* the ray moves along this axis */
	double next[3];      /* where the ray leaves the current cell along each active axis */
	double slack[3];     /* the error of a crossing distance, beyond its relative part */
	bool started, done;
};

static double err_of(const struct walk *w, int k, double t)
{
	return w->slack[k] + rounding_gamma(4) * fabs(t);
}

/* Where the ray crosses the edge between cells e - 1 and e along axis k. */
static double edge_t(const struct grid *g, const struct walk *w, int k, int e)
{
	return (g->lo[k] + e * g->width[k] - w->o[k]) * w->inv[k];
}

static double exit_t(const struct grid *g, const struct walk *w, int k)
{
	return edge_t(g, w, k, w->cell[k] + (w->step[k] > 0));
}

/* Starts the walk at the cell the ray enters the grid in, or at one before it where
 * rounding leaves that in doubt; false when the ray misses the grid within tmax. */
static bool walk_start(const struct grid *g, const struct ray *r, double tmax, struct walk *w)
{
	double o[3] = { r->o.x, r->o.y, r->o.z }, d[3] = { r->d.x, r->d.y, r->d.z };
	/* the slab test, ordered to discard the NaN of 0 * inf, far side widened as the BVH's */
	double tnear = 0, tfar = tmax;
	for (int k = 0; k < 3; k++) {
		w->o[k] = o[k];
		w->inv[k] = 1 / d[k];
		double t0 = (g->lo[k] - o[k]) * w->inv[k], t1 = (g->hi[k] - o[k]) * w->inv[k];
		if (w->inv[k] < 0) {
			double tmp = t0;
			t0 = t1;
			t1 = tmp;
		}
		t1 *= 1 + 2 * rounding_gamma(3);
		tnear = t0 > tnear ? t0 : tnear;
		tfar = t1 < tfar ? t1 : tfar;
	}
	if (!(tnear <= tfar))
		return false;
	w->started = w->done = false;
	for (int k = 0; k < 3; k++) {
		/* a component so small that 1 / d overflows moves the ray by less than any
		 * coordinate can show: as good as zero */
		w->active[k] = d[k] != 0 && isfinite(w->inv[k]);
		w->step[k] = d[k] < 0 ? -1 : 1;
		w->cell[k] = cell_of(g, k, w->active[k] ? o[k] + tnear * d[k] : o[k]);
		if (!w->active[k]) {
			w->next[k] = INFINITY;
			continue;
		}
		w->slack[k] = g->edge_err[k] * fabs(w->inv[k]);
		/* back up while the ray may not have crossed into this cell yet at tnear */
		for (;;) {
			int back = w->cell[k] - w->step[k];
			if (back < 0 || back >= g->n[k])
				break;
			double t = edge_t(g, w, k, w->cell[k] + (w->step[k] < 0));
			if (!(t + err_of(w, k, t) > tnear))
				break;
			w->cell[k] = back;
		}
		w->next[k] = exit_t(g, w, k);
	}
	return true;
}

/* The next cells to visit, in cells[]: the walk's next cell and, where the crossings are
 * too close to order, the cells the ray may pass through instead. Returns how many; 0
 * once the ray has left the grid or every hit beyond is farther than tmax. */
static int walk_next(const struct grid *g, struct walk *w, double tmax, size_t cells[4])
{
	if (w->done)
		return 0;
	if (!w->started) {
		w->started = true;
		cells[0] = cell_index(g, w->cell);
		return 1;
	}
	int a = -1;
	double leave = INFINITY; /* the earliest the ray can really leave this cell */
	for (int k = 0; k < 3; k++)
		if (w->active[k]) {
			if (a < 0 || w->next[k] < w->next[a])
				a = k;
			leave = fmin(leave, w->next[k] - err_of(w, k, w->next[k]));
		}
	if (a < 0 || tmax < leave) {
		w->done = true;
		return 0;
	}
	int tie[2], nt = 0;
	double latest_a = w->next[a] + err_of(w, a, w->next[a]);
	for (int k = 0; k < 3; k++)
		if (k != a && w->active[k] && w->next[k] - err_of(w, k, w->next[k]) <= latest_a)
			tie[nt++] = k;
	int n = 0;
	/* each non-empty subset of the tied axes, stepped from here */
	for (int mask = 1; mask < 1 << nt; mask++) {
		int c[3] = { w->cell[0], w->cell[1], w->cell[2] };
		bool inside = true;
		for (int j = 0; j < nt; j++)
			if (mask >> j & 1) {
				c[tie[j]] += w->step[tie[j]];
				inside &= c[tie[j]] >= 0 && c[tie[j]] < g->n[tie[j]];
			}
		if (inside)
			cells[n++] = cell_index(g, c);
	}
	w->cell[a] += w->step[a];
	if (w->cell[a] < 0 || w->cell[a] >= g->n[a]) {
		w->done = true;
	} else {
		cells[n++] = cell_index(g, w->cell);
		w->next[a] = exit_t(g, w, a);
	}
	return n;
}

bool grid_intersect(const struct grid *g, const struct geometry *geo, const struct ray *r, struct hit *h)
{
	bool hit = shape_planes_intersect(geo, r, h);
	struct walk w;
	if (!g->refs || !walk_start(g, r, h->t, &w))
		return hit;
	struct triangle_ray tr;
	shape_triangle_ray(geo, r, &tr);
	size_t cells[4];
	int n;
	/* a primitive in several cells is tested in each: cheaper than remembering it */
	while ((n = walk_next(g, &w, h->t, cells)) > 0)
		for (int i = 0; i < n; i++)
			for (uint32_t j = g->start[cells[i]]; j < g->start[cells[i] + 1]; j++)
				hit |= shape_intersect(geo, shape_nth(geo, g->refs[j] & ~MULTI_CELL), r, &tr, h);
	return hit;
}

/* ---- the shadow filter: each crossing must count once, so a primitive listed in several
 * cells is filtered only the first time the walk meets it (mailboxing) ---- */

enum {
	MAILBOX_SLOTS = 4096, /* a power of two */
	MAILBOX_MAX = 3072,   /* beyond this load the ray falls back to every primitive */
};

/* Per thread, so that the hot path allocates nothing; emptied after each ray. */
static _Thread_local struct {
	uint32_t slot[MAILBOX_SLOTS]; /* 0: empty; else a reference (MULTI_CELL makes it non-zero) */
	uint32_t used[MAILBOX_MAX];
	int n;
} mailbox;

/* Adds ref; 1 if new, 0 if already there, -1 when the mailbox is full. */
static int mailbox_add(uint32_t ref)
{
	uint32_t h = (ref * 2654435761u) & (MAILBOX_SLOTS - 1);
	while (mailbox.slot[h]) {
		if (mailbox.slot[h] == ref)
			return 0;
		h = (h + 1) & (MAILBOX_SLOTS - 1);
	}
	if (mailbox.n == MAILBOX_MAX)
		return -1;
	mailbox.slot[h] = ref;
	mailbox.used[mailbox.n++] = h;
	return 1;
}

static void mailbox_clear(void)
{
	for (int i = 0; i < mailbox.n; i++)
		mailbox.slot[mailbox.used[i]] = 0;
	mailbox.n = 0;
}

/* The filter of the grid's primitives along r; false when the mailbox overflowed. */
static bool filter_walk(const struct grid *g, const struct geometry *geo, const struct ray *r,
                        const struct triangle_ray *tr, double tmax, struct vec3 *pass)
{
	struct walk w;
	if (!walk_start(g, r, tmax, &w))
		return true;
	size_t cells[4];
	int n;
	while ((n = walk_next(g, &w, tmax, cells)) > 0)
		for (int i = 0; i < n; i++)
			for (uint32_t j = g->start[cells[i]]; j < g->start[cells[i] + 1]; j++) {
				uint32_t ref = g->refs[j];
				if (ref & MULTI_CELL) {
					int fresh = mailbox_add(ref);
					if (fresh < 0)
						return false;
					if (!fresh)
						continue;
				}
				*pass = shape_filter(geo, shape_nth(geo, ref & ~MULTI_CELL), r, tr, tmax, *pass);
				if (vzero(*pass))
					return true;
			}
	return true;
}

struct vec3 grid_transmittance(const struct grid *g, const struct geometry *geo, const struct ray *r, double tmax)
{
	struct vec3 pass = shape_planes_filter(geo, r, tmax);
	if (vzero(pass) || !g->refs)
		return pass;
	struct vec3 planes = pass;
	struct triangle_ray tr;
	shape_triangle_ray(geo, r, &tr);
	bool complete = filter_walk(g, geo, r, &tr, tmax, &pass);
	mailbox_clear();
	if (complete)
		return pass;
	/* more distinct primitives than the mailbox holds: every primitive, once each */
	pass = planes;
	for (size_t i = 0; i < shape_count(geo) && !vzero(pass); i++)
		pass = shape_filter(geo, shape_nth(geo, i), r, &tr, tmax, pass);
	return pass;
}
