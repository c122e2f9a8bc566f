/* rounding.h: bounds on the rounding error of double-precision arithmetic, which the
 * shapes' hit points and the accelerators' boxes are widened by (NUMERICS.md section 2;
 * pbrt 3rd ed. section 3.9.1). */
#ifndef SCN_ROUNDING_H
#define SCN_ROUNDING_H

/* gamma(n) of pbrt: a bound on the relative error of n roundings. */
static inline double rounding_gamma(int n)
{
	const double u = 0x1p-53;
	return n * u / (1 - n * u);
}

#endif
