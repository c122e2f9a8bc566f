/* tri_packet.h: up to four triangles of a BVH leaf stored lane by lane (each coordinate
 * of each vertex as four doubles, in one run of memory), tested against a ray in one
 * pass of vector arithmetic. Lane by lane it performs the very operations of
 * triangle_intersect(), in the same order, so that a packet gives the scalar test's hits
 * to the bit; the rare lane whose edge function is exactly zero goes to
 * triangle_intersect() itself, whose extended-precision step has no vector form. */
#ifndef SCN_TRI_PACKET_H
#define SCN_TRI_PACKET_H

#include "shape.h"

enum { PACKET_LANES = 4 };

/* 320 bytes, five cache lines: 36 doubles and the lanes' triangles. */
struct tri_packet {
	double p[3][3][PACKET_LANES]; /* vertex, world axis, lane */
	uint32_t tri[PACKET_LANES];   /* the lane's index in geometry.triangles */
	uint32_t lanes;               /* lanes in use, from lane 0 */
	uint32_t pad[3];
};

/* Packs geo->triangles[first, first + n), n in [1, PACKET_LANES]. */
void tri_packet_fill(struct tri_packet *pk, const struct geometry *geo, uint32_t first, uint32_t n);

/* shape_intersect() of each of the packet's triangles in lane order: the same h, the same
 * result. */
bool tri_packet_intersect(const struct tri_packet *pk, const struct geometry *geo, const struct triangle_ray *tr,
                          struct hit *h);

/* shape_filter() of each of the packet's triangles in lane order, stopping once pass is
 * black: the same pass. */
struct vec3 tri_packet_filter(const struct tri_packet *pk, const struct geometry *geo, const struct triangle_ray *tr,
                              double tmax, struct vec3 pass);

#endif
