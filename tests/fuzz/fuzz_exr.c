/* fuzz_exr.c: libFuzzer harness for the EXR reader (render/image/exr.c over
 * OpenEXRCore), with the header that a --tile part's reader asks for. */
#include "fuzz_image.h"

static int read_exr(int fd, const char *path, struct image **out, char *err, size_t errlen)
{
	struct image_exr_header h;
	int rc = image_exr_read(fd, path, out, &h, err, errlen);
	if (rc == 0)
		image_exr_header_free(&h);
	return rc;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	return fuzz_image_reader(read_exr, "sky.exr", data, size);
}
