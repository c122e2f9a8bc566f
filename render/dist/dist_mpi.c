/* dist_mpi.c: dist.h in scn-mpi: the processes of an MPI launcher share one image's
 * tiles, or an animation's frames, from a queue that process 0 keeps.
 *
 * Only each process's main thread calls MPI (MPI_THREAD_FUNNELED); its render threads
 * never wait for a message. A main thread that waits polls (MPI_Iprobe, MPI_Test) and
 * sleeps between polls rather than blocking in MPI, whose blocking calls spin and would
 * take a core from the render threads. Every process renders with the same scene and
 * seed, and a pixel depends on nothing else, so the image does not depend on who
 * rendered which tile. */
#include "config.h"

#include <mpi.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "cleanup.h"
#include "clock.h"
#include "dist.h"
#include "launch.h"
#include "xalloc.h"

enum { TAG_ASK = 1, TAG_GRANT, TAG_TILES, TAG_DONE, TAG_FRAME, TAG_FRAME_TEXT, TAG_FRAME_PIXELS };

/* Between polls of a waiting main thread, 1 ms: short against the work each process holds
 * in hand (LOW_PER_THREAD tiles a thread, a millisecond or more each), and long enough
 * that polling takes nothing measurable from the render threads. */
static void pause_briefly(void)
{
	nanosleep(&(struct timespec){ 0, 1000 * 1000 }, NULL);
}

int dist_start(char **argv, struct dist_world *w)
{
	(void)argv; /* MPI is given none: it needs none of scn's arguments */
	*w = (struct dist_world){ 0, 1, "" };
	if (!dist_launcher())
		return 0;
	gethostname(w->host, sizeof w->host - 1);
	int provided;
	if (MPI_Init_thread(NULL, NULL, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS) {
		fprintf(stderr, "scn: error: MPI did not start\n");
		return 4; /* main.c's status for a render that failed */
	}
	MPI_Comm_rank(MPI_COMM_WORLD, &w->rank);
	MPI_Comm_size(MPI_COMM_WORLD, &w->size);
	char name[128];
	snprintf(name, sizeof name, "process %d of %d (on %s): ", w->rank, w->size, w->host);
	cleanup_name_process(name);
	if (provided < MPI_THREAD_FUNNELED) {
		if (w->rank == 0)
			fprintf(stderr, "scn: error: this MPI cannot run a process with threads (MPI_THREAD_FUNNELED)\n");
		MPI_Finalize();
		return 4;
	}
	return 0;
}

void dist_end(const struct dist_world *w)
{
	(void)w;
	int started;
	MPI_Initialized(&started);
	if (started)
		MPI_Finalize();
}

int dist_agree(const struct dist_world *w, int status, const char *messages)
{
	if (w->size == 1)
		return status;
	int *all = xmalloc((size_t)w->size * sizeof *all);
	MPI_Allgather(&status, 1, MPI_INT, all, 1, MPI_INT, MPI_COMM_WORLD);
	int first = 0;
	for (int r = 0; r < w->size && !first; r++)
		first = all[r];
	/* the others' messages, each after a line naming its process and machine, for
	 * process 0 to print when it did not fail itself */
	char *mine = NULL;
	if (status && w->rank != 0) {
		const char *m = messages ? messages : "";
		size_t size = strlen(m) + sizeof w->host + 128;
		mine = xmalloc(size);
		snprintf(mine, size, "scn: error: process %d of %d (on %s) failed where process 0 did not:\n%s", w->rank,
		         w->size, w->host, m);
	}
	int len = mine ? (int)strlen(mine) : 0;
	int *lens = w->rank == 0 ? xmalloc((size_t)w->size * sizeof *lens) : NULL;
	MPI_Gather(&len, 1, MPI_INT, lens, 1, MPI_INT, 0, MPI_COMM_WORLD);
	int *at = NULL;
	char *text = NULL;
	if (w->rank == 0) {
		at = xmalloc((size_t)w->size * sizeof *at);
		size_t total = 0;
		for (int r = 0; r < w->size; r++) {
			at[r] = (int)total;
			total += (size_t)lens[r];
		}
		text = xmalloc(total + 1);
	}
	MPI_Gatherv(mine, len, MPI_CHAR, text, lens, at, MPI_CHAR, 0, MPI_COMM_WORLD);
	if (w->rank == 0 && status == 0)
		for (int r = 1; r < w->size; r++)
			fprintf(stderr, "%.*s", lens[r], text + at[r]);
	free(mine);
	free(text);
	free(at);
	free(lens);
	free(all);
	return first;
}

/* ---- One image's tiles ---- */

/* A range of tiles granted to a process other than 0, and its message back: the range,
 * each tile's probe sum, then each tile's pixels, w * h * 3 floats, tile after tile. */
struct chunk {
	int first, count;
	atomic_int done;
	size_t *offset;                /* per tile, its first float in pixels */
	char *msg;                     /* what is sent: header, probes, pixels */
	size_t bytes;
	double *probes;
	float *pixels;
};

struct chunk_header {
	int32_t first, count;
};

static void chunk_init(struct chunk *c, const struct render_options *opt, int first, int count)
{
	c->first = first;
	c->count = count;
	atomic_init(&c->done, 0);
	c->offset = xmalloc(((size_t)count + 1) * sizeof *c->offset);
	size_t floats = 0;
	for (int i = 0; i < count; i++) {
		int x, y, tw, th;
		render_tile_rect(opt, first + i, &x, &y, &tw, &th);
		c->offset[i] = floats;
		floats += 3 * (size_t)tw * (size_t)th;
	}
	c->bytes = sizeof(struct chunk_header) + (size_t)count * sizeof(double) + floats * sizeof(float);
	c->msg = xmalloc(c->bytes);
	*(struct chunk_header *)c->msg = (struct chunk_header){ first, count };
	c->probes = (double *)(c->msg + sizeof(struct chunk_header));
	c->pixels = (float *)(c->probes + count);
}

static void chunk_free(struct chunk *c)
{
	free(c->offset);
	free(c->msg);
}

/* The chunks a process other than 0 holds: at most two granted ahead of the one its
 * threads are on, so a short list searched under a lock once per tile. */
enum { MAX_CHUNKS = 4 };
struct chunks {
	const struct render_options *opt;
	pthread_mutex_t lock;
	struct chunk *c[MAX_CHUNKS];
	int n;
};

static struct chunk *chunk_of(struct chunks *cs, int t)
{
	struct chunk *found = NULL;
	pthread_mutex_lock(&cs->lock);
	for (int i = 0; i < cs->n && !found; i++)
		if (t >= cs->c[i]->first && t < cs->c[i]->first + cs->c[i]->count)
			found = cs->c[i];
	pthread_mutex_unlock(&cs->lock);
	return found;
}

static float *chunk_pixels(void *ctx, int t, size_t *stride)
{
	struct chunks *cs = ctx;
	struct chunk *c = chunk_of(cs, t);
	int x, y, w, h;
	render_tile_rect(cs->opt, t, &x, &y, &w, &h);
	*stride = 3 * (size_t)w;
	return c->pixels + c->offset[t - c->first];
}

static void chunk_done(void *ctx, int t)
{
	atomic_fetch_add(&chunk_of(ctx, t)->done, 1);
}

/* How many tiles a process asks for at a time, ASK_PER_THREAD per thread; it asks again
 * when LOW_PER_THREAD per thread are left, so that its threads do not run dry while the
 * answer comes, which takes a poll on each side and, on a machine whose cores are all
 * rendering, the wait for a core to run process 0's main thread. On the headline (2
 * processes of 1 thread on 2 cores, tiles of about 1 ms), process 1 got 39% of the
 * tiles with 2 and 1 (and polls every 0.25 ms), 36-40% with 8 and 4, 44-46% with 16 and
 * 8; the cost is a tail of at most ASK_PER_THREAD tiles a thread. */
enum { ASK_PER_THREAD = 16, LOW_PER_THREAD = 8 };
static int ask_size(int threads)
{
	return ASK_PER_THREAD * threads;
}

/* A process other than 0: asks for tiles, renders them, sends them back, and at the end
 * its ray counts. */
static int render_share(const struct scene *sc, const struct render_options *opt, struct ray_stats *st)
{
	struct chunks cs = { .opt = opt };
	pthread_mutex_init(&cs.lock, NULL);
	struct render_pool *pool = render_pool_start(sc, opt, &(struct render_sink){ chunk_pixels, chunk_done, &cs });
	if (!pool) {
		fprintf(stderr, "scn: error: cannot start the render threads\n");
		MPI_Abort(MPI_COMM_WORLD, 4);
	}
	int threads = render_pool_threads(pool), want = ask_size(threads), grant[2];
	int fed = 0;                      /* tiles fed to the pool */
	bool asking = false, no_more = false;
	MPI_Request req = MPI_REQUEST_NULL;
	for (;;) {
		bool busy = false;
		if (!asking && !no_more && cs.n < MAX_CHUNKS - 1 && fed - render_pool_done(pool) <= LOW_PER_THREAD * threads) {
			MPI_Send(&want, 1, MPI_INT, 0, TAG_ASK, MPI_COMM_WORLD);
			MPI_Irecv(grant, 2, MPI_INT, 0, TAG_GRANT, MPI_COMM_WORLD, &req);
			asking = true;
		}
		if (asking) {
			int got;
			MPI_Test(&req, &got, MPI_STATUS_IGNORE);
			if (got) {
				asking = false;
				busy = true;
				if (grant[1] == 0) {
					no_more = true;
					render_pool_close(pool);
				} else {
					struct chunk *c = xmalloc(sizeof *c);
					chunk_init(c, opt, grant[0], grant[1]);
					pthread_mutex_lock(&cs.lock);
					cs.c[cs.n++] = c;
					pthread_mutex_unlock(&cs.lock);
					render_pool_feed(pool, grant[0], grant[1]);
					fed += grant[1];
				}
			}
		}
		/* the oldest chunk goes back once its threads are done with it */
		if (cs.n > 0 && atomic_load(&cs.c[0]->done) == cs.c[0]->count) {
			struct chunk *c = cs.c[0];
			const double *probes = render_pool_tile_probes(pool);
			for (int i = 0; i < c->count; i++)
				c->probes[i] = probes[c->first + i];
			MPI_Send(c->msg, (int)c->bytes, MPI_BYTE, 0, TAG_TILES, MPI_COMM_WORLD);
			pthread_mutex_lock(&cs.lock);
			memmove(cs.c, cs.c + 1, (size_t)--cs.n * sizeof *cs.c);
			pthread_mutex_unlock(&cs.lock);
			chunk_free(c);
			free(c);
			busy = true;
		}
		if (no_more && cs.n == 0)
			break;
		if (!busy)
			pause_briefly();
	}
	render_pool_finish(pool, NULL, st);
	pthread_mutex_destroy(&cs.lock);
	MPI_Send(st, (int)sizeof *st, MPI_BYTE, 0, TAG_DONE, MPI_COMM_WORLD);
	return 0;
}

/* Process 0's side of one image: the queue, its own threads' share, and the others'
 * tiles copied into the image as they come. */
struct server {
	const struct render_options *opt;
	struct render_target target;   /* the image */
	struct render_pool *pool;
	int ntiles, next;              /* the queue: tiles next .. ntiles - 1 are left */
	int remote_done;               /* tiles done by the others */
	int working;                   /* other processes that have not sent their counts */
	int processes;
	struct ray_stats others;
	struct dist_traffic traffic;
};

/* Takes up to want tiles from the queue for one process, but no more than a share of
 * what is left, 1 / (2 * processes) of it (guided self-scheduling), so that as the queue
 * empties the grants shrink and no process is left with a long tail of tiles while the
 * others have finished. */
static int take(struct server *s, int want)
{
	int left = s->ntiles - s->next, share = left / (2 * s->processes);
	int n = want < share ? want : share > 0 ? share : 1;
	if (n > left)
		n = left;
	s->next += n;
	return n;
}

/* Handles one message from another process, if one is waiting; true if it did. */
static bool serve(struct server *s)
{
	int waiting;
	MPI_Status status;
	MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &waiting, &status);
	if (!waiting)
		return false;
	int from = status.MPI_SOURCE;
	if (status.MPI_TAG == TAG_ASK) {
		int want, grant[2];
		MPI_Recv(&want, 1, MPI_INT, from, TAG_ASK, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
		grant[0] = s->next;
		grant[1] = take(s, want);
		MPI_Send(grant, 2, MPI_INT, from, TAG_GRANT, MPI_COMM_WORLD);
	} else if (status.MPI_TAG == TAG_TILES) {
		double t0 = clock_now();
		int bytes;
		MPI_Get_count(&status, MPI_BYTE, &bytes);
		char *msg = xmalloc((size_t)bytes);
		MPI_Recv(msg, bytes, MPI_BYTE, from, TAG_TILES, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
		const struct chunk_header *h = (const struct chunk_header *)msg;
		const double *probes = (const double *)(msg + sizeof *h);
		const float *px = (const float *)(probes + h->count);
		double *tile_probes = render_pool_tile_probes(s->pool);
		for (int i = 0; i < h->count; i++) {
			int t = h->first + i, x, y, w, hh;
			render_tile_rect(s->opt, t, &x, &y, &w, &hh);
			size_t stride;
			float *to = render_image_pixels(&s->target, t, &stride);
			for (int row = 0; row < hh; row++, px += 3 * w)
				memcpy(to + row * stride, px, 3 * (size_t)w * sizeof *px);
			tile_probes[t] = probes[i];
		}
		s->remote_done += h->count;
		s->traffic.tiles += h->count;
		s->traffic.messages++;
		s->traffic.bytes += bytes;
		free(msg);
		s->traffic.gather_s += clock_now() - t0;
	} else { /* TAG_DONE */
		struct ray_stats st;
		MPI_Recv(&st, (int)sizeof st, MPI_BYTE, from, TAG_DONE, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
		trace_stats_add(&s->others, &st);
		s->working--;
	}
	return true;
}

static int render_served(const struct dist_world *w, const struct scene *sc, const struct render_options *opt,
                         struct image *img, struct ray_stats *st, struct dist_traffic *traffic)
{
	struct server s = { .opt = opt, .target = { opt, img }, .ntiles = render_tile_count(opt), .working = w->size - 1,
	                    .processes = w->size };
	s.pool = render_pool_start(sc, opt, &(struct render_sink){ render_image_pixels, NULL, &s.target });
	if (!s.pool) {
		fprintf(stderr, "scn: error: cannot start the render threads\n");
		MPI_Abort(MPI_COMM_WORLD, 4);
	}
	int threads = render_pool_threads(s.pool), fed = 0;
	bool closed = false;
	double t0 = clock_now(), shown = t0;
	for (;;) {
		bool busy = serve(&s);
		/* this process's own threads take from the same queue, a few tiles ahead */
		if (!closed && fed - render_pool_done(s.pool) <= LOW_PER_THREAD * threads) {
			int first = s.next, n = take(&s, ask_size(threads));
			render_pool_feed(s.pool, first, n);
			fed += n;
		}
		if (!closed && s.next == s.ntiles) {
			render_pool_close(s.pool);
			closed = true;
		}
		int done = s.remote_done + render_pool_done(s.pool);
		if (done == s.ntiles && s.working == 0)
			break;
		if (opt->progress && clock_now() - shown > 0.2) {
			render_progress_show(done, s.ntiles, clock_now() - t0);
			shown = clock_now();
		}
		if (!busy)
			pause_briefly();
	}
	if (opt->progress) {
		render_progress_show(s.ntiles, s.ntiles, clock_now() - t0);
		fputc('\n', stderr);
	}
	render_pool_finish(s.pool, &s.others, st);
	*traffic = s.traffic;
	return 0;
}

int dist_render_image(const struct dist_world *w, const struct scene *sc, const struct render_options *opt,
                      struct image *img, struct ray_stats *st, struct dist_traffic *traffic)
{
	*traffic = (struct dist_traffic){ 0 };
	if (w->size == 1)
		return render_image(sc, opt, img, st);
	return w->rank == 0 ? render_served(w, sc, opt, img, st, traffic) : render_share(sc, opt, st);
}

/* ---- Whole frames ---- */

struct frame_head {
	int64_t k;
	int32_t status, samples, width, height, nmessages, nstats;
	double render_s, rmse;
};

static void send_frame(const struct dist_frame *f)
{
	struct frame_head h = { f->k, f->status, f->samples, f->img ? f->img->width : 0, f->img ? f->img->height : 0,
	                        f->messages ? (int32_t)strlen(f->messages) : 0, f->stats ? (int32_t)strlen(f->stats) : 0,
	                        f->render_s, f->rmse };
	MPI_Send(&h, (int)sizeof h, MPI_BYTE, 0, TAG_FRAME, MPI_COMM_WORLD);
	if (h.nmessages + h.nstats > 0) {
		char *text = xmalloc((size_t)h.nmessages + (size_t)h.nstats);
		if (h.nmessages)
			memcpy(text, f->messages, (size_t)h.nmessages);
		if (h.nstats)
			memcpy(text + h.nmessages, f->stats, (size_t)h.nstats);
		MPI_Send(text, h.nmessages + h.nstats, MPI_CHAR, 0, TAG_FRAME_TEXT, MPI_COMM_WORLD);
		free(text);
	}
	if (f->img)
		MPI_Send(f->img->rgb, 3 * h.width * h.height, MPI_FLOAT, 0, TAG_FRAME_PIXELS, MPI_COMM_WORLD);
}

static char *text_part(const char *text, int n)
{
	if (n == 0)
		return NULL;
	char *s = xmalloc((size_t)n + 1);
	memcpy(s, text, (size_t)n);
	s[n] = '\0';
	return s;
}

static void recv_frame(int from, struct dist_frame *f)
{
	struct frame_head h;
	MPI_Recv(&h, (int)sizeof h, MPI_BYTE, from, TAG_FRAME, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
	*f = (struct dist_frame){ .k = h.k, .status = h.status, .samples = h.samples, .render_s = h.render_s,
	                          .rmse = h.rmse };
	if (h.nmessages + h.nstats > 0) {
		char *text = xmalloc((size_t)h.nmessages + (size_t)h.nstats);
		MPI_Recv(text, h.nmessages + h.nstats, MPI_CHAR, from, TAG_FRAME_TEXT, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
		f->messages = text_part(text, h.nmessages);
		f->stats = text_part(text + h.nmessages, h.nstats);
		free(text);
	}
	if (h.width > 0) {
		f->img = image_new(h.width, h.height);
		if (!f->img) {
			fprintf(stderr, "scn: error: cannot allocate a %d x %d image for frame %lld\n", h.width, h.height,
			        (long long)h.k);
			MPI_Abort(MPI_COMM_WORLD, 4);
		}
		MPI_Recv(f->img->rgb, 3 * h.width * h.height, MPI_FLOAT, from, TAG_FRAME_PIXELS, MPI_COMM_WORLD,
		         MPI_STATUS_IGNORE);
	}
}

/* A process other than 0: asks for a frame, renders it, sends it, until told none is left. */
static void render_frames_share(const struct dist_frames *job)
{
	for (;;) {
		int one = 1;
		long long k;
		MPI_Send(&one, 1, MPI_INT, 0, TAG_ASK, MPI_COMM_WORLD);
		MPI_Recv(&k, 1, MPI_LONG_LONG, 0, TAG_GRANT, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
		if (k < 0)
			return;
		struct dist_frame f;
		job->render(job->ctx, (long)k, &f);
		send_frame(&f);
		dist_frame_free(&f);
	}
}

/* Process 0's own frames render on a thread of their own, so that its main thread keeps
 * serving the queue meanwhile. */
struct local_frame {
	const struct dist_frames *job;
	pthread_t thread;
	bool running;
	atomic_bool finished;
	struct dist_frame f;
	long k;
};

static void *local_frame_run(void *arg)
{
	struct local_frame *l = arg;
	l->job->render(l->job->ctx, l->k, &l->f);
	atomic_store(&l->finished, true);
	return NULL;
}

/* Process 0's queue of frames: what is left, what failed, what was written. */
struct frame_queue {
	const struct dist_frames *job;
	long next, failed, written;
	int status;
};

static long next_frame(struct frame_queue *q)
{
	return q->next < q->job->end && q->failed < 0 ? q->next++ : -1;
}

static void deliver(struct frame_queue *q, struct dist_frame *f)
{
	long k = f->k;
	int rc = q->job->deliver(q->job->ctx, f);
	dist_frame_free(f);
	if (rc == 0)
		q->written++;
	else if (q->failed < 0 || k < q->failed) {
		q->failed = k;
		q->status = rc;
	}
}

static void render_frames_served(const struct dist_world *w, struct frame_queue *q)
{
	struct local_frame l = { .job = q->job };
	int told = 0;                  /* processes told that no frame is left */
	for (;;) {
		bool busy = false;
		if (!l.running && (l.k = next_frame(q)) >= 0) {
			atomic_store(&l.finished, false);
			sigset_t mask;
			cleanup_block_signals(&mask);
			if (pthread_create(&l.thread, NULL, local_frame_run, &l) != 0) {
				fprintf(stderr, "scn: error: cannot start a render thread\n");
				MPI_Abort(MPI_COMM_WORLD, 4);
			}
			cleanup_restore_signals(&mask);
			l.running = true;
		}
		int waiting;
		MPI_Status status;
		MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &waiting, &status);
		if (waiting && status.MPI_TAG == TAG_ASK) {
			int one;
			MPI_Recv(&one, 1, MPI_INT, status.MPI_SOURCE, TAG_ASK, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
			long long k = next_frame(q);
			MPI_Send(&k, 1, MPI_LONG_LONG, status.MPI_SOURCE, TAG_GRANT, MPI_COMM_WORLD);
			told += k < 0;
			busy = true;
		} else if (waiting) { /* TAG_FRAME */
			struct dist_frame f;
			recv_frame(status.MPI_SOURCE, &f);
			deliver(q, &f);
			busy = true;
		}
		if (l.running && atomic_load(&l.finished)) {
			pthread_join(l.thread, NULL);
			l.running = false;
			deliver(q, &l.f);
			busy = true;
		}
		if (told == w->size - 1 && !l.running && (q->next == q->job->end || q->failed >= 0))
			break;
		if (!busy)
			pause_briefly();
	}
}

int dist_render_frames(const struct dist_world *w, const struct dist_frames *job, long *failed, long *written)
{
	struct frame_queue q = { .job = job, .next = job->first, .failed = -1 };
	if (w->rank == 0)
		render_frames_served(w, &q);
	else
		render_frames_share(job);
	*failed = q.failed;
	*written = q.written;
	return q.status;
}
