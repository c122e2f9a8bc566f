/* check.h: the assertions of the unit tests: CHECK prints the failing condition with its
 * place and counts it; main returns check_result(). */
#ifndef SCN_TEST_CHECK_H
#define SCN_TEST_CHECK_H

#include <stdio.h>

static int check_failures;

#define CHECK(cond) \
	((cond) ? (void)0 : (void)(fprintf(stderr, "%s:%d: CHECK failed: %s\n", __FILE__, __LINE__, #cond), \
	                           check_failures++))
/* |a - b| <= tol, with both values printed on failure */
#define CHECK_NEAR(a, b, tol) \
	do { double a_ = (a), b_ = (b); \
	     if (!(a_ - b_ <= (tol) && b_ - a_ <= (tol))) { \
	         fprintf(stderr, "%s:%d: CHECK_NEAR failed: %s = %.17g, %s = %.17g (tol %g)\n", \
	                 __FILE__, __LINE__, #a, a_, #b, b_, (double)(tol)); \
	         check_failures++; } } while (0)

static inline int check_result(void)
{
	if (check_failures)
		fprintf(stderr, "%d check(s) failed\n", check_failures);
	return check_failures ? 1 : 0;
}

#endif
