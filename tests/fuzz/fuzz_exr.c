/* fuzz_exr.c: libFuzzer harness for the EXR reader (render/image/exr.c over
 * OpenEXRCore). */
#include "fuzz_image.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	return fuzz_image_reader(image_exr_read, "sky.exr", data, size);
}
