/* bvh_collapse.c: the binary tree that bvh_build.c makes, turned into the traversal's
 * WIDTH-wide nodes (bvh_impl.h) in preorder, on every thread, in the same layout
 * whatever their number. */
#include <math.h>
#include <stdlib.h>

#include "bvh_impl.h"
#include "parallel.h"
#include "xalloc.h"

/* The area of a child's box (vbox_area's), for choosing which child to open; a NaN from
 * an infinite box (a scene beyond float range) counts as the largest. */
static float child_area(const struct child *ch)
{
	float lo[4] = { ch->box[0], ch->box[1], ch->box[2], 0 }, hi[4] = { ch->box[3], ch->box[4], ch->box[5], 0 };
	float a = vbox_area((struct vbox){ v4load(lo), v4load(hi) });
	return a == a ? a : INFINITY;
}

/* The area of an interior child, for choosing which to open, and its binary node
 * fetched ahead (the collapse waits on these loads more than on anything else); -1 for
 * a leaf, which is never opened. */
static float open_area(const struct bin_node *bin, const struct child *ch)
{
	if (ch->count)
		return -1;
	__builtin_prefetch(&bin[ch->index]);
	return child_area(ch);
}

/* The children of the wide node that stands for binary node `node`: its two children,
 * then, while there are fewer than WIDTH, the interior one with the largest box
 * replaced by its own two (the area rule of Wald, Benthin and Boulos, "Getting Rid of
 * Packets", 2008: the children most rays enter are the ones worth testing together).
 * Returns how many there are. */
static int gather(const struct bin_node *bin, uint32_t node, struct child out[WIDTH])
{
	float area[WIDTH];
	int n = 0;
	for (int c = 0; c < 2; c++, n++) {
		out[n] = bin[node].kid[c];
		area[n] = open_area(bin, &out[n]);
	}
	while (n < WIDTH) {
		int open = -1;
		for (int i = 0; i < n; i++)
			if (area[i] >= 0 && (open < 0 || area[i] > area[open]))
				open = i;
		if (open < 0)
			break;
		const struct bin_node *b = &bin[out[open].index];
		int at[2] = { open, n++ };
		for (int c = 0; c < 2; c++) {
			out[at[c]] = b->kid[c];
			area[at[c]] = open_area(bin, &out[at[c]]);
		}
	}
	return n;
}

/* A subtree of the wide tree that a thread collapses on its own: below the binary child
 * ch, at the jobs' wide level; its nodes go to [offset, offset + size). */
struct wide_job {
	struct child ch;
	uint32_t offset, size;
	size_t boxes;
	int depth;
};

struct collapse {
	const struct bin_node *bin;
	struct bvh_node *out;      /* NULL: only count the nodes */
	uint32_t next;             /* nodes made so far (in out, where it starts) */
	size_t boxes;
	int depth;
	/* the top of the tree, when the rest goes to jobs: an interior child at job_level is
	 * a job, found by the counting pass and placed by the writing pass, in preorder */
	int job_level;             /* 0: no jobs */
	struct wide_job *jobs;
	size_t njobs, cap_jobs, placed;
};

/* Turns the binary subtree below interior child ch into wide nodes, in preorder;
 * returns ch as its parent sees it now. Counting and writing take the same path, so the
 * counting pass sizes the array exactly. */
static struct child collapse(struct collapse *cl, struct child ch, int level)
{
	if (ch.count)
		return ch;
	if (cl->job_level && level == cl->job_level) {
		if (!cl->out) {
			xgrow((void **)&cl->jobs, &cl->cap_jobs, cl->njobs + 1, sizeof *cl->jobs);
			cl->jobs[cl->njobs++] = (struct wide_job){ .ch = ch };
			return ch;
		}
		/* its subtree, counted by then, takes the next size nodes, its root first */
		struct wide_job *j = &cl->jobs[cl->placed++];
		j->offset = cl->next;
		cl->next += j->size;
		ch.index = j->offset;
		return ch;
	}
	if (level > cl->depth)
		cl->depth = level;
	struct child kid[WIDTH];
	int n = gather(cl->bin, ch.index, kid);
	uint32_t self = cl->next++;
	cl->boxes += (size_t)n;
	for (int c = 0; c < n; c++)
		kid[c] = collapse(cl, kid[c], level + 1);
	if (cl->out) {
		struct bvh_node *nd = &cl->out[self];
		for (int c = 0; c < WIDTH; c++) {
			for (int k = 0; k < 6; k++)
				nd->box[k][c] = c < n ? kid[c].box[k] : k < 3 ? INFINITY : -INFINITY;
			nd->index[c] = c < n ? kid[c].index : 0;
			nd->count[c] = c < n ? kid[c].count : 0;
		}
	}
	ch.index = self;
	return ch;
}

struct wide_jobs {
	const struct bin_node *bin;
	struct bvh_node *out;
	struct wide_job *jobs;
	int level;               /* theirs, the collapse's job_level */
};

static void count_job(void *ctx, size_t i)
{
	struct wide_jobs *w = ctx;
	struct wide_job *j = &w->jobs[i];
	struct collapse cl = { .bin = w->bin };
	collapse(&cl, j->ch, w->level);
	j->size = cl.next;
	j->boxes = cl.boxes;
	j->depth = cl.depth;
}

static void write_job(void *ctx, size_t i)
{
	struct wide_jobs *w = ctx;
	const struct wide_job *j = &w->jobs[i];
	struct collapse cl = { .bin = w->bin, .out = w->out, .next = j->offset };
	collapse(&cl, j->ch, w->level);
}

/* The wide tree of the binary one, which it frees: a pass to count, the array aligned
 * to cache lines, a pass to fill it. With parallel, the top two levels are collapsed on
 * this thread and the subtrees below them on all threads, in both passes (each waits on
 * its loads of binary nodes more than on anything else); the layout is the same. */
void bvh_make_wide(struct bvh *bvh, struct bin_node *bin, bool parallel)
{
	struct collapse cl = { .bin = bin, .job_level = parallel ? 2 : 0 };
	collapse(&cl, bvh->root, 0);
	struct wide_jobs w = { bin, NULL, cl.jobs, cl.job_level };
	parallel_for(cl.njobs, count_job, &w);
	size_t total = cl.next, boxes = cl.boxes;
	int depth = cl.depth;
	for (size_t i = 0; i < cl.njobs; i++) {
		total += cl.jobs[i].size;
		boxes += cl.jobs[i].boxes;
		depth = cl.jobs[i].depth > depth ? cl.jobs[i].depth : depth;
	}
	bvh->nnodes = total;
	bvh->nboxes = boxes + 1;
	bvh->depth = depth;
	if (total) {
		w.out = bvh->nodes = xaligned_alloc(64, total * sizeof *bvh->nodes);
		cl.out = bvh->nodes;
		cl.next = 0;
		bvh->root = collapse(&cl, bvh->root, 0);
		parallel_for(cl.njobs, write_job, &w);
	}
	free(cl.jobs);
	free(bin);
}
