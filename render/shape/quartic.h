/* quartic.h: every real root of a monic quartic in an interval, none skipped, for the
 * torus (torus.c). */
#ifndef SCN_QUARTIC_H
#define SCN_QUARTIC_H

/* p(x) = x^4 + c[3] x^3 + c[2] x^2 + c[1] x + c[0], and p'(x) in *dp, by Estrin's scheme:
 * each term passes through at most 6 roundings, so the error is within gamma(6) sum
 * |c_i| |x|^i (Higham, Accuracy and Stability of Numerical Algorithms, section 5.1), and
 * the chain a Newton step waits on is two products shorter than Horner's. */
static inline double quartic_eval(const double c[4], double x, double *dp)
{
	double x2 = x * x;
	*dp = (4 * x + 3 * c[3]) * x2 + (2 * c[2] * x + c[1]);
	return ((x + c[3]) * x + c[2]) * x2 + (c[1] * x + c[0]);
}

/* The roots of x^4 + c[3] x^3 + c[2] x^2 + c[1] x + c[0] in [lo, hi], piece by piece in
 * ascending order: quartic_start() cuts [lo, hi] at p's inflection points, and each call of
 * quartic_next() returns the roots of the next piece, ascending (at most 4: an end's root
 * exactly at lo, two inside, one exactly at the far end), or -1 when no piece is left; a
 * caller after the first roots only stops calling. Pieces that end before from are passed
 * over unsolved. A root is found to the precision its
 * conditioning allows in double; a double root may come out as two equal roots or none.
 * lo and hi finite. Every root found lies in its piece, whose far end is then e[i]. */
struct quartic_scan {
	double e[4];            /* the pieces' ends */
	int ne, i;              /* how many ends; the next piece starts at e[i] */
	double s;               /* +1 where the next piece is convex, -1 where concave */
	double p, dp;           /* p and p' at e[i] */
	double last;            /* the last root returned, or -inf */
};
void quartic_start(struct quartic_scan *q, const double c[4], double lo, double hi);
int quartic_next(struct quartic_scan *q, const double c[4], double from, double r[4]);

#endif
