/* fuzz_scene.c: libFuzzer harness for the scene front end. The input is a .scn file and
 * goes the way of `scn check`: read, lex, parse, check (with includes), evaluate, lower
 * (which reads mesh files and sky images). Diagnostics are printed, to /dev/null, so
 * that their formatting runs too. */
#include <stdio.h>
#include <stdlib.h>

#include "fuzz.h"
#include "load.h"
#include "lower.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	static FILE *sink;
	if (!sink && !(sink = fopen("/dev/null", "w")))
		abort();
	const char *path = fuzz_file("scene.scn", data, size);
	struct diag d;
	diag_init(&d, sink);
	struct scene_desc desc;
	struct scene sc = { 0 };
	struct lower_times times;
	if (load_scene(&d, path, NULL, &desc, NULL) == LOAD_OK)
		lower_scene(&d, &desc, &sc, &times, -1);  /* as scn check: no memory count */
	diag_flush(&d);
	scene_free(&sc);
	scene_desc_free(&desc);
	diag_fini(&d);
	return 0;
}
