/* fuzz_part.c: libFuzzer harness for scn merge's reading of a part (src/tile_part.c):
 * the EXR reader with the header, then the checks of the part's attributes and windows
 * against the split. */
#include <stdio.h>

#include "fuzz.h"
#include "tile_part.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	const char *path = fuzz_file("part.exr", data, size);
	struct tile_file f;
	char err[512];
	if (tile_part_read(path, &f, err, sizeof err) == 0)
		tile_file_free(&f);
	return 0;
}
