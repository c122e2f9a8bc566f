/* png.c: PNG through libpng: sRGB-encoded 8- or 16-bit RGB out; any PNG in, decoded
 * to linear light by its sRGB or gAMA chunk as POV-Ray does. */
#include "codec.h"
#include "image_file.h"

#include <errno.h>
#include <png.h>
#include <setjmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "outfile.h"
#include "xalloc.h"

/* State shared with libpng's callbacks. It lives on the heap, not in the function
 * that calls setjmp, so that what the callbacks and the code after setjmp change in
 * it is still valid after a longjmp (C11 7.13.2.1p3). */
struct png_io {
	int fd;                        /* -1 when reading from mem */
	const unsigned char *mem;      /* a PNG file in memory (len bytes), or NULL */
	int error;                     /* errno of a failed read or write, or 0 */
	bool eof;                      /* the file ended before libpng was done */
	char msg[200];                 /* libpng's message */
	size_t pos, len;               /* of buf */
	unsigned char buf[1 << 16];
	/* owned by the reader or writer, freed on every path */
	unsigned char *data;
	float *table;
};

/* libpng's ways of saying that memory ran out (its own, and zlib's through it). */
static bool says_out_of_memory(const char *msg)
{
	return strstr(msg, "Out of memory") || strstr(msg, "Out of Memory") || strstr(msg, "insufficient memory");
}

static void on_error(png_structp png, png_const_charp msg)
{
	struct png_io *io = png_get_error_ptr(png);
	snprintf(io->msg, sizeof io->msg, "%s", msg);
	if (!io->error && says_out_of_memory(msg))
		io->error = ENOMEM;   /* status 4, as for any allocation that fails */
	png_longjmp(png, 1);
}

/* Warnings (an odd iCCP profile, an unknown ancillary chunk) don't stop a read, and
 * the renderer's library prints nothing by itself (STYLE.md section 1). */
static void on_warning(png_structp png, png_const_charp msg)
{
	(void)png;
	(void)msg;
}

static struct png_io *io_new(int fd)
{
	struct png_io *io = xcalloc(1, sizeof *io);
	io->fd = fd;
	return io;
}

static void io_free(struct png_io *io)
{
	free(io->data);
	free(io->table);
	free(io);
}

/* libpng hands over small pieces (chunk headers, CRCs): collect them in buf. */
static void write_fn(png_structp png, png_bytep data, size_t n)
{
	struct png_io *io = png_get_io_ptr(png);
	if (io->len + n > sizeof io->buf) {
		if ((io->error = outfile_write(io->fd, io->buf, io->len)) != 0)
			png_error(png, "write failed");
		io->len = 0;
	}
	if (n > sizeof io->buf) {
		if ((io->error = outfile_write(io->fd, data, n)) != 0)
			png_error(png, "write failed");
		return;
	}
	memcpy(io->buf + io->len, data, n);
	io->len += n;
}

static void flush_fn(png_structp png)
{
	struct png_io *io = png_get_io_ptr(png);
	if ((io->error = outfile_write(io->fd, io->buf, io->len)) != 0)
		png_error(png, "write failed");
	io->len = 0;
}

/* 8- and 16-bit files are both sRGB-encoded and say so with an sRGB chunk (and the
 * gAMA and cHRM that libpng writes beside it), as POV-Ray's default 16-bit output
 * does: 16 bits then only add precision, and every reader gets the same pixels. */
int image_png_write(const struct image *img, int fd, const char *path, int bit_depth,
                    char *err, size_t errlen)
{
	struct png_io *io = io_new(fd);
	png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, io, on_error, on_warning);
	png_infop info = png ? png_create_info_struct(png) : NULL;
	if (!info) {
		png_destroy_write_struct(&png, NULL);
		io_free(io);
		snprintf(err, errlen, "cannot write '%s': libpng could not start", path);
		return ENOMEM;
	}
	unsigned maxval = bit_depth == 16 ? 65535 : 255;
	size_t bps = bit_depth == 16 ? 2 : 1;
	io->data = xmalloc((size_t)img->width * 3 * bps);
	if (setjmp(png_jmpbuf(png))) {
		int rc = io->error ? io->error : EIO;
		if (io->error)
			snprintf(err, errlen, "cannot write '%s': %s", path, strerror(io->error));
		else
			snprintf(err, errlen, "cannot write '%s': libpng: %s", path, io->msg);
		png_destroy_write_struct(&png, &info);
		io_free(io);
		return rc;
	}
	png_set_write_fn(png, io, write_fn, flush_fn);
	/* the pixel limit is image.h's; libpng's default of a million per side is lower */
	png_set_user_limits(png, 0x7fffffff, 0x7fffffff);
	png_set_IHDR(png, info, (png_uint_32)img->width, (png_uint_32)img->height, bit_depth,
	             PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
	             PNG_FILTER_TYPE_DEFAULT);
	/* zlib level 3, not its default 6: measured on the 1280 x 1024 headline image, the
	 * write takes 0.09 s instead of 0.18 s (7% of the whole run) for a file 7% larger */
	png_set_compression_level(png, 3);
	png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
	/* no tIME or text chunks: the same image always gives the same bytes */
	png_write_info(png, info);
	for (int y = 0; y < img->height; y++) {
		const float *src = img->rgb + (size_t)y * img->width * 3;
		unsigned char *p = io->data;
		for (size_t i = 0; i < (size_t)img->width * 3; i++) {
			unsigned v = image_srgb_sample(src[i], maxval);
			if (bps == 2)
				*p++ = (unsigned char)(v >> 8);   /* PNG is big-endian */
			*p++ = (unsigned char)v;
		}
		png_write_row(png, io->data);
	}
	png_write_end(png, NULL);
	flush_fn(png);
	png_destroy_write_struct(&png, &info);
	io_free(io);
	return 0;
}

static void read_fn(png_structp png, png_bytep data, size_t n)
{
	struct png_io *io = png_get_io_ptr(png);
	if (io->mem) {
		if (io->len - io->pos < n) {
			io->eof = true;
			png_error(png, "unexpected end of file");
		}
		memcpy(data, io->mem + io->pos, n);
		io->pos += n;
		return;
	}
	while (n > 0) {
		if (io->pos == io->len) {
			ssize_t k = read(io->fd, io->buf, sizeof io->buf);
			if (k < 0 && errno == EINTR)
				continue;
			if (k < 0) {
				io->error = errno;
				png_error(png, "read failed");
			}
			if (k == 0) {
				io->eof = true;
				png_error(png, "unexpected end of file");
			}
			io->pos = 0;
			io->len = (size_t)k;
		}
		size_t k = io->len - io->pos < n ? io->len - io->pos : n;
		memcpy(data, io->buf + io->pos, k);
		io->pos += k;
		data += k;
		n -= k;
	}
}

/* Any colour type and depth comes out as 8- or 16-bit RGB: palettes and grey are
 * expanded, alpha (and tRNS transparency) dropped. The transfer curve is POV-Ray's
 * choice (its png_pov.cpp): an sRGB chunk means the sRGB curve, otherwise a gAMA
 * chunk means the power law of its value, otherwise the file is taken as sRGB, as
 * the PNG specification recommends for untagged files. ICC profiles are not applied;
 * the test is POV-Ray's own (png_get_valid), so both programs agree on every file. */
static int read_png(struct png_io *io, const char *path, struct image **out, char *err, size_t errlen)
{
	png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, io, on_error, on_warning);
	png_infop info = png ? png_create_info_struct(png) : NULL;
	if (!info) {
		png_destroy_read_struct(&png, NULL, NULL);
		io_free(io);
		snprintf(err, errlen, "cannot read '%s': libpng could not start", path);
		return ENOMEM;
	}
	if (setjmp(png_jmpbuf(png))) {
		int rc = io->error ? io->error : EINVAL;
		if (io->error)
			snprintf(err, errlen, "cannot read '%s': %s", path, strerror(io->error));
		else if (io->eof)
			snprintf(err, errlen, "cannot read '%s': truncated PNG file", path);
		else
			snprintf(err, errlen, "cannot read '%s': corrupt PNG file: %s", path, io->msg);
		png_destroy_read_struct(&png, &info, NULL);
		io_free(io);
		return rc;       /* image_read frees *out */
	}
	png_set_read_fn(png, io, read_fn);
	png_set_user_limits(png, 0x7fffffff, 0x7fffffff);
	/* libpng reads an ancillary chunk whole into memory, allocating the length its header
	 * claims: a tEXt chunk in a 124-byte file claiming 1.6 GB got 1.6 GB (found by
	 * fuzzing), as Debian's libpng has no limit, and a limit only makes it warn. So
	 * the chunks libpng would keep and we never use are skipped unread (read past in
	 * small pieces, not allocated), and iCCP, the one of variable length we let libpng
	 * read (an sRGB profile can mark the file sRGB), is held to libpng's upstream
	 * default limit of 8 MB. */
	static const png_byte unused[] = "tEXt\0zTXt\0iTXt\0sPLT\0eXIf\0pCAL\0sCAL\0";
	png_set_keep_unknown_chunks(png, PNG_HANDLE_CHUNK_NEVER, unused, (int)(sizeof unused / 5));
	png_set_chunk_malloc_max(png, 8000000);
	png_read_info(png, info);

	png_uint_32 w, h;
	int depth, color;
	png_get_IHDR(png, info, &w, &h, &depth, &color, NULL, NULL, NULL);
	/* the rows as stored, each after its filter byte, before any conversion */
	double data_bytes = (double)h * ((double)png_get_rowbytes(png, info) + 1);
	double gamma = 0;              /* 0: the sRGB curve */
	png_fixed_point file_gamma;
	if (!png_get_valid(png, info, PNG_INFO_sRGB) && png_get_valid(png, info, PNG_INFO_gAMA) &&
	    png_get_gAMA_fixed(png, info, &file_gamma) && file_gamma > 0)
		gamma = file_gamma / 100000.0;

	if (color == PNG_COLOR_TYPE_PALETTE)
		png_set_palette_to_rgb(png);
	if (color == PNG_COLOR_TYPE_GRAY && depth < 8)
		png_set_expand_gray_1_2_4_to_8(png);
	if (color == PNG_COLOR_TYPE_GRAY || color == PNG_COLOR_TYPE_GRAY_ALPHA)
		png_set_gray_to_rgb(png);
	png_set_strip_alpha(png);
	int passes = png_set_interlace_handling(png);
	png_read_update_info(png, info);
	depth = png_get_bit_depth(png, info);
	size_t bps = depth == 16 ? 2 : 1;
	if (png_get_channels(png, info) != 3 || (depth != 8 && depth != 16) ||
	    png_get_rowbytes(png, info) != (size_t)w * 3 * bps)
		png_error(png, "unexpected pixel layout after conversion to RGB");

	/* deflate packs 1032 bytes into one at best (image_alloc_for_read checks a file) */
	enum { MAX_RATIO = 1032 };
	if (io->mem && data_bytes > (double)io->len * MAX_RATIO)
		png_error(png, "its pixels cannot fit in its bytes");
	int rc = image_alloc_for_read(w, h, io->fd, data_bytes, MAX_RATIO, path, out, err, errlen);
	if (rc != 0) {
		png_destroy_read_struct(&png, &info, NULL);
		io_free(io);
		return rc;
	}
	(*out)->source = (struct image_source){ .format = IMAGE_PNG, .png_gamma = gamma };
	io->table = image_decode_table(depth == 16 ? 65535 : 255, gamma);
	/* An interlaced image is only complete after the last pass, and libpng merges
	 * each pass into the rows of the previous ones: it needs all rows in memory.
	 * Otherwise one row at a time is enough. */
	size_t rowlen = (size_t)w * 3 * bps;
	io->data = xmalloc(rowlen * (passes > 1 ? h : 1));
	for (int pass = 0; pass < passes; pass++) {
		for (png_uint_32 y = 0; y < h; y++) {
			png_bytep row = io->data + (passes > 1 ? y * rowlen : 0);
			png_read_row(png, row, NULL);
			if (pass < passes - 1)
				continue;
			float *dst = (*out)->rgb + (size_t)y * w * 3;
			for (size_t i = 0; i < (size_t)w * 3; i++)
				dst[i] = io->table[bps == 2 ? (unsigned)row[2 * i] << 8 | row[2 * i + 1] : row[i]];
		}
	}
	/* reading up to IEND checks the CRCs of the last chunks: a cut-off file is an error */
	png_read_end(png, NULL);
	png_destroy_read_struct(&png, &info, NULL);
	io_free(io);
	return 0;
}

int image_png_read(int fd, const char *path, struct image **out, char *err, size_t errlen)
{
	return read_png(io_new(fd), path, out, err, errlen);
}

int image_read_png_memory(const unsigned char *data, size_t size, const char *name, struct image **out,
                          char *err, size_t errlen)
{
	struct png_io *io = io_new(-1);
	io->mem = data;
	io->len = size;
	*out = NULL;
	int rc = read_png(io, name, out, err, errlen);
	if (rc != 0) {
		image_free(*out);
		*out = NULL;
	} else {
		(*out)->source.embedded = true;
	}
	return rc;
}
