/* fuzz_png.c: libFuzzer harness for the PNG reader (render/image/png.c over libpng). */
#include "fuzz_image.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	return fuzz_image_reader(image_png_read, "sky.png", data, size);
}
