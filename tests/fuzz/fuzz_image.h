/* fuzz_image.h: the body of the image harnesses (fuzz_png.c, fuzz_exr.c): the input is
 * a file handed to one format's reader, as image_read hands over a skybox. */
#ifndef SCN_FUZZ_IMAGE_H
#define SCN_FUZZ_IMAGE_H

#include <fcntl.h>
#include <stdlib.h>
#include <unistd.h>

#include "codec.h"
#include "fuzz.h"

typedef int image_reader(int fd, const char *path, struct image **out, char *err, size_t errlen);

static inline int fuzz_image_reader(image_reader *read_image, const char *name,
                                    const uint8_t *data, size_t size)
{
	const char *path = fuzz_file(name, data, size);
	int fd = open(path, O_RDONLY);
	if (fd < 0)
		abort();
	struct image *img = NULL;
	char err[512];
	read_image(fd, path, &img, err, sizeof err);
	image_free(img);       /* also a partly read one, as image_read does */
	close(fd);
	return 0;
}

#endif
