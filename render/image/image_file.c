/* image_file.c: image files whatever their format: the format chosen by the name's
 * extension and replaced atomically on write (outfile.h), told by the first bytes on
 * read, and the work handed to the format's codec (codec.h). */
#include "image_file.h"

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "codec.h"
#include "outfile.h"

/* ORDER IMAGE_FORMAT */
static const char *const format_ext[] = { "png", "exr", "ppm" };

int image_format_of(const char *path)
{
	const char *slash = strrchr(path, '/');
	const char *base = slash ? slash + 1 : path;
	const char *dot = strrchr(base, '.');
	if (!dot || dot == base)       /* ".png" alone is a hidden file's name, not an extension */
		return -1;
	for (int f = 0; f < (int)(sizeof format_ext / sizeof format_ext[0]); f++) {
		const char *a = dot + 1, *b = format_ext[f];
		/* ASCII case folding by hand: tolower() would depend on the locale */
		while (*a && *b && (*a | 0x20) == *b)
			a++, b++;
		if (!*a && !*b)
			return f;
	}
	return -1;
}

int image_file_create(struct image_file *f, const char *path, const struct image_write_options *opt,
                      char *err, size_t errlen)
{
	*f = (struct image_file){ .path = path, .format = image_format_of(path), .fd = -1,
	                          .opt = opt ? *opt : (struct image_write_options){ .bit_depth = 8 } };
	if (f->format < 0) {
		snprintf(err, errlen, "cannot write '%s': unknown image format (use .png, .exr or .ppm)", path);
		return EINVAL;
	}
	if (f->format != IMAGE_EXR && f->opt.bit_depth != 8 && f->opt.bit_depth != 16) {
		snprintf(err, errlen, "cannot write '%s': bit depth %d (must be 8 or 16)", path, f->opt.bit_depth);
		return EINVAL;
	}
	f->fd = outfile_open(path, &f->tmp, err, errlen);
	return f->fd < 0 ? -f->fd : 0;
}

int image_file_commit(struct image_file *f, const struct image *img, char *err, size_t errlen)
{
	int rc = EINVAL;
	if (!img)
		snprintf(err, errlen, "cannot write '%s': no image", f->path);
	else if (img->width <= 0 || img->height <= 0 || (int64_t)img->width * img->height > IMAGE_MAX_PIXELS)
		snprintf(err, errlen, "cannot write '%s': invalid image", f->path);
	else if (f->format == IMAGE_PNG)
		rc = image_png_write(img, f->fd, f->path, f->opt.bit_depth, err, errlen);
	else if (f->format == IMAGE_EXR)
		rc = image_exr_write(img, f->fd, f->path, f->opt.float32, f->opt.exr, err, errlen);
	else
		rc = image_ppm_write(img, f->fd, f->path, f->opt.bit_depth, err, errlen);
	rc = outfile_finish(f->fd, f->tmp, f->path, rc, err, errlen);
	f->fd = -1;
	f->tmp = NULL;
	return rc;
}

int image_write(const struct image *img, const char *path, const struct image_write_options *opt,
                char *err, size_t errlen)
{
	struct image_file f;
	int rc = image_file_create(&f, path, opt, err, errlen);
	return rc ? rc : image_file_commit(&f, img, err, errlen);
}

int image_read(const char *path, struct image **out, char *err, size_t errlen)
{
	return image_read_with(path, NULL, out, err, errlen);
}

/* image_read_with, and with h, image_read_exr_header. */
static int read_file(const char *path, const struct image_read_options *opt, struct image_exr_header *h,
                     struct image **out, char *err, size_t errlen)
{
	*out = NULL;
	int fd = open(path, O_RDONLY | O_CLOEXEC);
	if (fd < 0) {
		int e = errno;
		snprintf(err, errlen, "cannot read '%s': %s", path, strerror(e));
		return e;
	}
	struct stat st;
	int e = fstat(fd, &st) != 0 ? errno : S_ISDIR(st.st_mode) ? EISDIR : 0;
	if (e != 0) {
		snprintf(err, errlen, "cannot read '%s': %s", path, strerror(e));
		close(fd);
		return e;
	}
	unsigned char magic[8] = { 0 };
	ssize_t n = pread(fd, magic, sizeof magic, 0);
	if (n < 0) {
		e = errno;
		snprintf(err, errlen, "cannot read '%s': %s", path, strerror(e));
		close(fd);
		return e;
	}
	static const unsigned char png_magic[8] = { 0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n' };
	static const unsigned char exr_magic[4] = { 0x76, 0x2f, 0x31, 0x01 };
	int rc;
	if (errlen)
		err[0] = '\0';
	if (h && !(n >= 4 && memcmp(magic, exr_magic, 4) == 0)) {
		snprintf(err, errlen, "cannot read '%s': not an OpenEXR file", path);
		rc = EINVAL;
	} else if (n >= 8 && memcmp(magic, png_magic, 8) == 0)
		rc = image_png_read(fd, path, out, err, errlen);
	else if (n >= 4 && memcmp(magic, exr_magic, 4) == 0)
		rc = image_exr_read(fd, path, out, h, err, errlen);
	else if (n >= 2 && magic[0] == 'P' && magic[1] == '6')
		rc = image_ppm_read(fd, path, opt && opt->ppm_linear, out, err, errlen);
	else {
		snprintf(err, errlen, "cannot read '%s': %s", path,
		         n == 0 ? "empty file" : "not a PNG, OpenEXR or binary PPM (P6) image");
		rc = EINVAL;
	}
	close(fd);
	if (rc != 0) {
		image_free(*out);
		*out = NULL;
	}
	return rc;
}

int image_read_with(const char *path, const struct image_read_options *opt, struct image **out,
                    char *err, size_t errlen)
{
	return read_file(path, opt, NULL, out, err, errlen);
}

int image_read_exr_header(const char *path, struct image **out, struct image_exr_header *h,
                          char *err, size_t errlen)
{
	*h = (struct image_exr_header){ .nattrs = 0 };
	return read_file(path, NULL, h, out, err, errlen);
}
