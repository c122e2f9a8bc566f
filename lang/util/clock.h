/* clock.h: seconds on the monotonic clock, for the phase times that --stats, converge and
 * the progress line print. */
#ifndef SCN_CLOCK_H
#define SCN_CLOCK_H

/* Seconds since some fixed point: only differences mean anything. */
double clock_now(void);

/* The same from the coarse clock, which moves in ticks (4 ms here) but costs a fraction
 * of the exact one to read; the exact one where there is no coarse one. */
double clock_now_coarse(void);

#endif
