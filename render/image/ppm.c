/* ppm.c: binary PPM (P6), sRGB-encoded, 8-bit or 16-bit big-endian samples. */
#include "codec.h"

#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "outfile.h"
#include "xalloc.h"

int image_ppm_write(const struct image *img, int fd, const char *path, int bit_depth,
                    char *err, size_t errlen)
{
	unsigned maxval = bit_depth == 16 ? 65535 : 255;
	size_t bps = bit_depth == 16 ? 2 : 1;     /* bytes per sample */
	/* no comment lines, unlike POV-Ray's: nothing in the file may vary between runs */
	char header[64];
	int hlen = snprintf(header, sizeof header, "P6\n%d %d\n%u\n", img->width, img->height, maxval);
	int rc = outfile_write(fd, header, (size_t)hlen);
	size_t rowlen = (size_t)img->width * 3 * bps;
	unsigned char *row = xmalloc(rowlen);
	for (int y = 0; y < img->height && rc == 0; y++) {
		const float *src = img->rgb + (size_t)y * img->width * 3;
		unsigned char *p = row;
		for (size_t i = 0; i < (size_t)img->width * 3; i++) {
			unsigned v = image_srgb_sample(src[i], maxval);
			if (bps == 2)
				*p++ = (unsigned char)(v >> 8);
			*p++ = (unsigned char)v;
		}
		rc = outfile_write(fd, row, rowlen);
	}
	free(row);
	if (rc != 0)
		snprintf(err, errlen, "cannot write '%s': %s", path, strerror(rc));
	return rc;
}

/* A buffered reader on a descriptor: the header is read a byte at a time. */
struct reader {
	int fd;
	int error;                     /* errno of a failed read, or 0 */
	size_t pos, len;
	unsigned char buf[1 << 16];
};

static bool refill(struct reader *r)
{
	for (;;) {
		ssize_t n = read(r->fd, r->buf, sizeof r->buf);
		if (n < 0 && errno == EINTR)
			continue;
		if (n < 0)
			r->error = errno;
		r->pos = 0;
		r->len = n > 0 ? (size_t)n : 0;
		return n > 0;
	}
}

/* The next byte, or -1 at the end of the file or on an error. */
static int next_byte(struct reader *r)
{
	if (r->pos == r->len && !refill(r))
		return -1;
	return r->buf[r->pos++];
}

/* Copies n bytes to dst; false if the file ends first. */
static bool read_bytes(struct reader *r, unsigned char *dst, size_t n)
{
	while (n > 0) {
		if (r->pos == r->len && !refill(r))
			return false;
		size_t k = r->len - r->pos < n ? r->len - r->pos : n;
		memcpy(dst, r->buf + r->pos, k);
		r->pos += k;
		dst += k;
		n -= k;
	}
	return true;
}

static bool is_space(int c)
{
	return c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r';
}

/* Reads one header number after skipping white space and '#' comments (which run to
 * the end of the line; POV-Ray writes some). *after gets the byte that ended the
 * number. Returns the number, or -1 if there is none or it is over INT_MAX. */
static long header_number(struct reader *r, int *after)
{
	int c = next_byte(r);
	for (;;) {
		if (c == '#') {
			while (c != '\n' && c != '\r' && c != -1)
				c = next_byte(r);
		} else if (is_space(c)) {
			c = next_byte(r);
		} else {
			break;
		}
	}
	if (c < '0' || c > '9')
		return -1;
	long v = 0;
	while (c >= '0' && c <= '9') {
		v = v * 10 + (c - '0');
		if (v > INT_MAX)
			return -1;
		c = next_byte(r);
	}
	*after = c;
	return v;
}

/* Samples are taken as sRGB-encoded, the mirror of image_ppm_write, or as linear when
 * the caller says so. POV-Ray writes PPMs in File_Gamma's encoding and reads a PPM
 * image_map as linear unless told otherwise (povray-equivalence.md sections 1 and 9);
 * telling the two apart is left to the caller, since a P6 file has no place to record
 * its encoding. */
int image_ppm_read(int fd, const char *path, bool linear, struct image **out, char *err,
                   size_t errlen)
{
	struct reader *r = xmalloc(sizeof *r);
	r->fd = fd;
	r->error = 0;
	r->pos = r->len = 0;
	unsigned char *row = NULL;
	float *table = NULL;
	const char *what = NULL;       /* what is wrong with the file's contents */
	int rc = 0;

	int after = 0;
	long w = -1, h = -1, maxval = -1;
	if (next_byte(r) != 'P' || next_byte(r) != '6')
		what = "not a binary PPM (P6) file";
	else if ((w = header_number(r, &after)) < 0 || !is_space(after) ||
	         (h = header_number(r, &after)) < 0 || !is_space(after) ||
	         (maxval = header_number(r, &after)) < 0 || !is_space(after))
		what = "malformed PPM header";
	else if (w == 0 || h == 0)
		what = "image has no pixels";
	else if (maxval < 1 || maxval > 65535)
		what = "PPM maxval must be between 1 and 65535";
	if (what || r->error)
		goto done;
	/* the one white space byte after maxval, read above as `after`, ends the header */
	if ((rc = image_alloc_for_read(w, h, fd, (double)w * h * 3 * (maxval > 255 ? 2 : 1), 1, path, out,
	                               err, errlen)) != 0)
		goto done;
	(*out)->source = (struct image_source){ .format = IMAGE_PPM };

	size_t bps = maxval > 255 ? 2 : 1;
	size_t rowlen = (size_t)w * 3 * bps;
	row = xmalloc(rowlen);
	table = image_decode_table((unsigned)maxval, linear ? 1.0 : 0);
	for (long y = 0; y < h; y++) {
		if (!read_bytes(r, row, rowlen)) {
			what = "unexpected end of file";
			goto done;
		}
		float *dst = (*out)->rgb + (size_t)y * (size_t)w * 3;
		for (size_t i = 0; i < (size_t)w * 3; i++) {
			unsigned v = bps == 2 ? (unsigned)row[2 * i] << 8 | row[2 * i + 1] : row[i];
			if (v > (unsigned long)maxval) {
				what = "sample value above the header's maxval";
				goto done;
			}
			dst[i] = table[v];
		}
	}
done:
	if (r->error) {
		rc = r->error;
		snprintf(err, errlen, "cannot read '%s': %s", path, strerror(rc));
	} else if (what) {
		rc = EINVAL;
		snprintf(err, errlen, "cannot read '%s': %s", path, what);
	}
	free(table);
	free(row);
	free(r);
	return rc;
}
