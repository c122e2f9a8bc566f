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

/* The roots of x^4 + c[3] x^3 + c[2] x^2 + c[1] x + c[0] in [lo, hi], ascending, at most
 * 4; returns how many. A root is found to the precision its conditioning allows in
 * double; a double root may come out as two equal roots or none. lo and hi finite. */
int quartic_roots(const double c[4], double lo, double hi, double x[4]);

#endif
