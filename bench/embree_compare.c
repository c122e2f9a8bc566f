/* embree_compare.c: raw traversal speed of scn's BVH against Intel Embree 3 on the same
 * primitives and the same rays, one ray at a time (bvh_intersect against rtcIntersect1),
 * on 1 and 2 threads: coherent camera rays (the scene's pinhole camera, one ray through
 * each pixel centre) and incoherent rays (random origins in the primitives' bounds,
 * random directions). Triangles go to Embree as a triangle mesh, spheres as its sphere
 * points (in float, where scn's are double); planes are left out of both.
 * With --scaling, one line per scene instead: camera rays on 1 thread, for the growth
 * of the time per ray with the scene's size.
 * bench/run builds it (make bench/embree_compare) where libembree-dev is installed; it is
 * no part of the build or of make check. */
#include "config.h"

#include <embree3/rtcore.h>
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "accel.h"
#include "camera.h"
#include "clock.h"
#include "diag.h"
#include "load.h"
#include "lower.h"
#include "random.h"
#include "scene_desc.h"
#include "xalloc.h"

enum { REPEATS = 5 }; /* the median of this many passes over the rays */

struct job {
	const struct scene *sc;
	RTCScene rtc;
	bool embree;
	const struct ray *rays;
	size_t first, count;
	size_t hits;
};

static void *trace_some(void *arg)
{
	struct job *j = arg;
	size_t hits = 0;
	if (j->embree) {
		struct RTCIntersectContext ctx;
		rtcInitIntersectContext(&ctx);
		for (size_t i = j->first; i < j->first + j->count; i++) {
			const struct ray *r = &j->rays[i];
			struct RTCRayHit rh = { 0 };
			rh.ray.org_x = (float)r->o.x, rh.ray.org_y = (float)r->o.y, rh.ray.org_z = (float)r->o.z;
			rh.ray.dir_x = (float)r->d.x, rh.ray.dir_y = (float)r->d.y, rh.ray.dir_z = (float)r->d.z;
			rh.ray.tnear = 0;
			rh.ray.tfar = INFINITY;
			rh.ray.mask = ~0u;
			rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
			rtcIntersect1(j->rtc, &ctx, &rh);
			hits += rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
		}
	} else {
		for (size_t i = j->first; i < j->first + j->count; i++) {
			struct hit h = { .t = INFINITY };
			hits += accel_intersect(&j->sc->accel, &j->sc->geo, &j->rays[i], &h);
		}
	}
	j->hits = hits;
	return NULL;
}

static int by_value(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return (x > y) - (x < y);
}

/* Mrays/s of one pass of one engine over the rays on threads threads. */
static double pass(const struct scene *sc, RTCScene rtc, bool embree, const struct ray *rays, size_t n, int threads,
                   size_t *hits)
{
	struct job jobs[2];
	pthread_t tid[2];
	double t0 = clock_now();
	for (int k = 0; k < threads; k++) {
		jobs[k] = (struct job){ sc, rtc, embree, rays, n * k / threads, n * (k + 1) / threads - n * k / threads, 0 };
		if (pthread_create(&tid[k], NULL, trace_some, &jobs[k]) != 0) {
			fprintf(stderr, "embree_compare: cannot start a thread\n");
			exit(1);
		}
	}
	*hits = 0;
	for (int k = 0; k < threads; k++) {
		pthread_join(tid[k], NULL);
		*hits += jobs[k].hits;
	}
	return (double)n / (clock_now() - t0) * 1e-6;
}

/* Mrays/s of scn (rate[0]) and Embree (rate[1]) on threads threads: the median of
 * REPEATS passes each, after one pass each unmeasured, the two engines taking turns so
 * that a change of the machine's speed during the run falls on both alike (this shared
 * machine has slow spells: scn's single-thread rate on the bunny's camera rays measured
 * 14 to 25 Mrays/s from one run to the next within the hour). */
static void measure(const struct scene *sc, RTCScene rtc, const struct ray *rays, size_t n, int threads,
                    double rate[2], size_t hits[2])
{
	double r[2][REPEATS];
	for (int e = 0; e < 2; e++)
		pass(sc, rtc, e, rays, n, threads, &hits[e]);
	for (int rep = 0; rep < REPEATS; rep++)
		for (int e = 0; e < 2; e++)
			r[e][rep] = pass(sc, rtc, e, rays, n, threads, &hits[e]);
	for (int e = 0; e < 2; e++) {
		qsort(r[e], REPEATS, sizeof r[e][0], by_value);
		rate[e] = r[e][REPEATS / 2];
	}
}

/* Commits g and hands it to s. */
static void attach(RTCScene s, RTCGeometry g)
{
	rtcCommitGeometry(g);
	rtcAttachGeometry(s, g);
	rtcReleaseGeometry(g);
}

static void embree_spheres(RTCDevice dev, RTCScene s, const struct scene *sc)
{
	RTCGeometry g = rtcNewGeometry(dev, RTC_GEOMETRY_TYPE_SPHERE_POINT);
	float *v = rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float),
	                                   sc->geo.nspheres);
	if (!v) {
		fprintf(stderr, "embree_compare: Embree could not allocate the spheres\n");
		exit(1);
	}
	for (size_t i = 0; i < sc->geo.nspheres; i++) {
		v[4 * i] = (float)sc->geo.spheres[i].center.x;
		v[4 * i + 1] = (float)sc->geo.spheres[i].center.y;
		v[4 * i + 2] = (float)sc->geo.spheres[i].center.z;
		v[4 * i + 3] = (float)sc->geo.spheres[i].radius;
	}
	attach(s, g);
}

static void embree_triangles(RTCDevice dev, RTCScene s, const struct scene *sc)
{
	RTCGeometry g = rtcNewGeometry(dev, RTC_GEOMETRY_TYPE_TRIANGLE);
	float *v = rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float),
	                                   sc->geo.nvertices);
	unsigned *ix = rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned),
	                                       sc->geo.ntriangles);
	if (!v || !ix) {
		fprintf(stderr, "embree_compare: Embree could not allocate the mesh\n");
		exit(1);
	}
	for (size_t i = 0; i < sc->geo.nvertices; i++) {
		v[3 * i] = (float)sc->geo.vertices[i].x;
		v[3 * i + 1] = (float)sc->geo.vertices[i].y;
		v[3 * i + 2] = (float)sc->geo.vertices[i].z;
	}
	for (size_t i = 0; i < sc->geo.ntriangles; i++)
		for (int k = 0; k < 3; k++)
			ix[3 * i + k] = sc->geo.triangles[i].v[k];
	attach(s, g);
}

static RTCScene embree_scene(RTCDevice dev, const struct scene *sc)
{
	RTCScene s = rtcNewScene(dev);
	if (sc->geo.nspheres)
		embree_spheres(dev, s, sc);
	if (sc->geo.ntriangles)
		embree_triangles(dev, s, sc);
	rtcCommitScene(s);
	return s;
}

/* One ray through each pixel centre, and as many random rays from inside the bounds. */
static struct ray *make_rays(const struct scene *sc, size_t *n)
{
	int w = sc->camera.width, h = sc->camera.height;
	*n = (size_t)w * (size_t)h;
	struct ray *rays = xcalloc(2 * *n, sizeof *rays);
	for (int y = 0; y < h; y++)
		for (int x = 0; x < w; x++)
			rays[(size_t)y * (size_t)w + (size_t)x] = camera_ray(&sc->camera, (x + 0.5) / w, (y + 0.5) / h);
	struct vec3 lo = v3s(INFINITY), hi = v3s(-INFINITY);
	for (size_t i = 0; i < sc->geo.nvertices; i++) {
		lo = vmin(lo, sc->geo.vertices[i]);
		hi = vmax(hi, sc->geo.vertices[i]);
	}
	for (size_t i = 0; i < sc->geo.nspheres; i++) {
		lo = vmin(lo, vsub(sc->geo.spheres[i].center, v3s(sc->geo.spheres[i].radius)));
		hi = vmax(hi, vadd(sc->geo.spheres[i].center, v3s(sc->geo.spheres[i].radius)));
	}
	rng_seed(12345);
	for (size_t i = *n; i < 2 * *n; i++) {
		rays[i].o = v3(urange(lo.x, hi.x), urange(lo.y, hi.y), urange(lo.z, hi.z));
		rays[i].d = rand_unit();
	}
	return rays;
}

/* The full table of a scene, or with scaling one line: camera rays on 1 thread. */
static int compare(RTCDevice dev, const char *path, bool scaling)
{
	struct diag d;
	diag_init(&d, stderr);
	struct scene_desc desc;
	struct scene sc = { 0 };
	struct lower_times lt;
	bool ok = load_scene(&d, path, NULL, &desc, NULL) == 0 && lower_scene(&d, &desc, &sc, &lt, -1) == 0;
	diag_flush(&d);
	diag_fini(&d);
	if (!ok || sc.geo.ntriangles + sc.geo.nspheres == 0) {
		fprintf(stderr, "embree_compare: %s: %s\n", path, ok ? "no triangles or spheres" : "cannot load it");
		return 1;
	}
	sc.geo.nplanes = 0;
	double t0 = clock_now();
	accel_build(&sc.accel, &sc.geo, ACCEL_BVH);
	double scn_build = clock_now() - t0;
	t0 = clock_now();
	RTCScene rtc = embree_scene(dev, &sc);
	double rtc_build = clock_now() - t0;
	size_t n;
	struct ray *rays = make_rays(&sc, &n);

	const char *base = strrchr(path, '/');
	base = base ? base + 1 : path;
	if (scaling) {
		size_t hits[2];
		double rate[2];
		measure(&sc, rtc, rays, n, 1, rate, hits);
		printf("  %-22s %9zu %12.2f %15.2f %10.0f%%  %zu/%zu\n", base, sc.geo.nspheres + sc.geo.ntriangles, rate[0],
		       rate[1], 100 * rate[0] / rate[1], hits[0], hits[1]);
	} else {
		printf("%s: %zu triangles, %zu spheres; build: scn %.3f s, Embree %.3f s\n", base, sc.geo.ntriangles,
		       sc.geo.nspheres, scn_build, rtc_build);
		printf("  %-20s %7s %12s %15s %11s  %s\n", "rays", "threads", "scn Mrays/s", "Embree Mrays/s",
		       "scn/Embree", "hits scn/Embree");
		static const char *const kinds[2] = { "camera (coherent)", "random (incoherent)" };
		for (int kind = 0; kind < 2; kind++)
			for (int threads = 1; threads <= 2; threads++) {
				size_t hits[2];
				double rate[2];
				measure(&sc, rtc, rays + kind * n, n, threads, rate, hits);
				printf("  %-20s %7d %12.2f %15.2f %10.0f%%  %zu/%zu\n", kinds[kind], threads, rate[0], rate[1],
				       100 * rate[0] / rate[1], hits[0], hits[1]);
			}
	}
	fflush(stdout);
	free(rays);
	rtcReleaseScene(rtc);
	scene_free(&sc);
	scene_desc_free(&desc);
	return 0;
}

int main(int argc, char **argv)
{
	bool scaling = argc > 1 && strcmp(argv[1], "--scaling") == 0;
	if (argc < 2 + scaling) {
		fprintf(stderr, "usage: embree_compare [--scaling] SCENE...\n");
		return 2;
	}
	RTCDevice dev = rtcNewDevice(NULL);
	if (!dev) {
		fprintf(stderr, "embree_compare: rtcNewDevice failed\n");
		return 1;
	}
	if (scaling)
		printf("  %-22s %9s %12s %15s %11s  %s\n", "scene", "prims", "scn Mrays/s", "Embree Mrays/s",
		       "scn/Embree", "hits scn/Embree");
	int rc = 0;
	for (int i = 1 + scaling; i < argc; i++)
		rc |= compare(dev, argv[i], scaling);
	rtcReleaseDevice(dev);
	return rc;
}
