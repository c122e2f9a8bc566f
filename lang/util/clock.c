/* clock.c: seconds on the monotonic clock (see clock.h). */
#include "clock.h"

#include <time.h>

static double seconds_of(clockid_t clock)
{
	struct timespec ts;
	clock_gettime(clock, &ts);
	return (double)ts.tv_sec + ts.tv_nsec * 1e-9;
}

double clock_now(void)
{
	return seconds_of(CLOCK_MONOTONIC);
}

double clock_now_coarse(void)
{
#ifdef CLOCK_MONOTONIC_COARSE
	return seconds_of(CLOCK_MONOTONIC_COARSE);
#else
	return clock_now();
#endif
}
