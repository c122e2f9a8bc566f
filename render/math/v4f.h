/* v4f.h: four floats, with SSE where there is SSE (every x86-64) and GCC's generic
 * vectors elsewhere: a box corner for the BVH's build, and one coordinate of four
 * children of a node for its node test without AVX (bvh_build.c, bvh_traverse.c). */
#ifndef SCN_V4F_H
#define SCN_V4F_H

#include <string.h>

#ifdef __AVX__
#include <immintrin.h>
#endif
#ifdef __SSE2__
#include <emmintrin.h>
typedef __m128 v4f;
static inline v4f v4set(float x) { return _mm_set1_ps(x); }
static inline v4f v4load(const float p[4]) { return _mm_loadu_ps(p); }
static inline void v4store(float p[4], v4f a) { _mm_storeu_ps(p, a); }
static inline v4f v4sub(v4f a, v4f b) { return _mm_sub_ps(a, b); }
static inline v4f v4mul(v4f a, v4f b) { return _mm_mul_ps(a, b); }
static inline v4f v4add(v4f a, v4f b) { return _mm_add_ps(a, b); }
/* a > b ? a : b and a < b ? a : b, lane by lane: a NaN in a gives b */
static inline v4f v4max(v4f a, v4f b) { return _mm_max_ps(a, b); }
static inline v4f v4min(v4f a, v4f b) { return _mm_min_ps(a, b); }
/* bit c set when a[c] <= b[c] */
static inline int v4le(v4f a, v4f b) { return _mm_movemask_ps(_mm_cmple_ps(a, b)); }
/* toward zero, lane by lane */
static inline void v4trunc(v4f a, int out[4]) { _mm_storeu_si128((__m128i *)out, _mm_cvttps_epi32(a)); }
/* m ? a : b, lane by lane, for m all ones or all zeros in each lane */
static inline v4f v4pick(v4f m, v4f a, v4f b) { return _mm_or_ps(_mm_and_ps(m, a), _mm_andnot_ps(m, b)); }
/* all ones in the lanes whose sign bit is set (-0 too), else zeros */
static inline v4f v4signs(v4f a) { return _mm_castsi128_ps(_mm_srai_epi32(_mm_castps_si128(a), 31)); }
/* bit c set when a[c]'s sign bit is */
static inline int v4signbits(v4f a) { return _mm_movemask_ps(a); }
#else
typedef float v4f __attribute__((vector_size(16)));
typedef int v4i __attribute__((vector_size(16)));
static inline v4f v4set(float x) { return (v4f){ x, x, x, x }; }
static inline v4f v4load(const float p[4]) { v4f a; memcpy(&a, p, sizeof a); return a; }
static inline void v4store(float p[4], v4f a) { memcpy(p, &a, sizeof a); }
static inline v4f v4sub(v4f a, v4f b) { return a - b; }
static inline v4f v4mul(v4f a, v4f b) { return a * b; }
static inline v4f v4add(v4f a, v4f b) { return a + b; }
static inline v4f v4max(v4f a, v4f b) { v4i m = a > b; return (v4f)(((v4i)a & m) | ((v4i)b & ~m)); }
static inline v4f v4min(v4f a, v4f b) { v4i m = a < b; return (v4f)(((v4i)a & m) | ((v4i)b & ~m)); }
/* bit c set when lane c of m is set */
static inline int v4bits(v4i m)
{
	return (m[0] & 1) | (m[1] & 2) | (m[2] & 4) | (m[3] & 8);
}
static inline int v4le(v4f a, v4f b) { return v4bits(a <= b); }
static inline void v4trunc(v4f a, int out[4])
{
	for (int i = 0; i < 4; i++)
		out[i] = (int)a[i];
}
static inline v4f v4pick(v4f m, v4f a, v4f b) { return (v4f)(((v4i)m & (v4i)a) | (~(v4i)m & (v4i)b)); }
static inline v4f v4signs(v4f a) { return (v4f)((v4i)a >> 31); }
static inline int v4signbits(v4f a) { return v4bits((v4i)a >> 31); }
#endif

#endif
