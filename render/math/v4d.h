/* v4d.h: four doubles in GCC's generic vectors, one AVX instruction a step where there
 * is AVX and two SSE2 ones otherwise, for the per-ray set-up of the box test
 * (bvh_traverse.c) and the triangle packets (tri_packet.c). Without AVX, GCC warns where
 * a function returns such a vector (its ABI differs from an AVX build's: harmless, as no
 * call with one crosses a file) and notes, past turning off, where one takes it by
 * value: what works on them here is macros, or takes pointers. */
#ifndef SCN_V4D_H
#define SCN_V4D_H

typedef double v4d __attribute__((vector_size(32)));
typedef long long v4l __attribute__((vector_size(32))); /* a v4d's bits; a comparison's lanes */

/* |a| lane by lane: the sign bits cleared */
#define V4D_ABS(a) ((v4d)((v4l)(a) & ~((v4l){ 1, 1, 1, 1 } << 63)))

#endif
