/* noise_bench.c: nanoseconds a call of scn's noise (render/texture/noise.c) and of the
 * octave sums the patterns make of it, at points along a line through the lattice: the
 * figures README's "Performance" quotes for the surfaces. Built on demand:
 *   make bench/noise_bench && bench/noise_bench [calls] */
#include <stdio.h>
#include <stdlib.h>

#include "clock.h"
#include "texture.h"

/* Another point of the line for each call, so that no two are alike. */
static struct vec3 point(long i)
{
	return v3(i * 0.0123, i * 0.0071, i * 0.0037);
}

int main(int argc, char **argv)
{
	long n = argc > 1 ? atol(argv[1]) : 4000000;
	if (n < 4) {
		fprintf(stderr, "usage: noise_bench [calls, at least 4]\n");
		return 2;
	}
	double sum = 0, t0;
	t0 = clock_now();
	for (long i = 0; i < n; i++)
		sum += noise_value(point(i));
	printf("noise_value              %6.1f ns\n", (clock_now() - t0) / n * 1e9);
	t0 = clock_now();
	for (long i = 0; i < n; i++)
		sum += noise_gradient(point(i)).x;
	printf("noise_gradient           %6.1f ns\n", (clock_now() - t0) / n * 1e9);
	t0 = clock_now();
	for (long i = 0; i < n; i++)
		sum += noise_vector(point(i)).x;
	printf("noise_vector             %6.1f ns\n", (clock_now() - t0) / n * 1e9);
	t0 = clock_now();
	for (long i = 0; i < n / 4; i++)
		sum += noise_turbulence(point(i), 6, 0.5, 2).x;
	printf("turbulence, 6 octaves    %6.1f ns\n", (clock_now() - t0) / (n / 4) * 1e9);
	t0 = clock_now();
	for (long i = 0; i < n / 4; i++)
		sum += noise_fbm(point(i), 6, 0.5, 2);
	printf("fbm, 6 octaves           %6.1f ns\n", (clock_now() - t0) / (n / 4) * 1e9);
	/* the sum, so that no call is optimised away */
	printf("(checksum %g)\n", sum);
	return 0;
}
