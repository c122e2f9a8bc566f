/* replay.c: a main() for a harness built with the normal compiler, for `make check`
 * (tests/fuzz/replay.sh): runs the harness once on each file named on the command line,
 * as libFuzzer does when given files. A crash or a sanitizer report fails the run. */
#include <stdio.h>
#include <stdlib.h>

#include "fuzz.h"
#include "xalloc.h"

int main(int argc, char **argv)
{
	for (int i = 1; i < argc; i++) {
		FILE *f = fopen(argv[i], "rb");
		if (!f) {
			perror(argv[i]);
			return 2;
		}
		size_t cap = 4096, n = 0, k;
		uint8_t *buf = xmalloc(cap);
		while ((k = fread(buf + n, 1, cap - n, f)) > 0)
			if ((n += k) == cap)
				buf = xrealloc(buf, cap *= 2);
		int bad = ferror(f);
		fclose(f);
		if (bad) {
			perror(argv[i]);
			return 2;
		}
		LLVMFuzzerTestOneInput(buf, n);
		free(buf);
	}
	return 0;
}
