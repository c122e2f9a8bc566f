/* exr.c: OpenEXR through its C API (OpenEXRCore): linear half or float RGB out; R, G,
 * B (or Y) channels of any pixel type, scanline or tiled, in. */
#include "codec.h"

#include <errno.h>
#include <math.h>
#include <openexr.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "xalloc.h"

/* What the library's callbacks share with us (the context's user data). The library
 * reads and writes through our descriptor, so that an OS error keeps its errno and
 * image_file.c keeps control of the temporary file. */
struct exr_io {
	int fd;
	int error;                     /* errno of a failed read or write, or 0 */
	char msg[200];                 /* the library's first message */
};

/* The library would print its messages to stderr; keep the first for ours. */
static void on_error(exr_const_context_t ctx, exr_result_t code, const char *msg)
{
	void *ud = NULL;
	if (exr_get_user_data(ctx, &ud) != EXR_ERR_SUCCESS || !ud)
		return;
	struct exr_io *io = ud;
	if (!io->msg[0])
		snprintf(io->msg, sizeof io->msg, "%s", msg ? msg : exr_get_default_error_message(code));
}

static int64_t write_fn(exr_const_context_t ctx, void *ud, const void *buf, uint64_t n,
                        uint64_t offset, exr_stream_error_func_ptr_t error_cb)
{
	(void)ctx;
	(void)error_cb;
	struct exr_io *io = ud;
	const char *p = buf;
	uint64_t done = 0;
	while (done < n) {
		ssize_t k = pwrite(io->fd, p + done, (size_t)(n - done), (off_t)(offset + done));
		if (k < 0 && errno == EINTR)
			continue;
		if (k < 0) {
			io->error = errno;
			return -1;
		}
		done += (uint64_t)k;
	}
	return (int64_t)n;
}

static int64_t read_fn(exr_const_context_t ctx, void *ud, void *buf, uint64_t n,
                       uint64_t offset, exr_stream_error_func_ptr_t error_cb)
{
	(void)ctx;
	(void)error_cb;
	struct exr_io *io = ud;
	char *p = buf;
	uint64_t done = 0;
	while (done < n) {
		ssize_t k = pread(io->fd, p + done, (size_t)(n - done), (off_t)(offset + done));
		if (k < 0 && errno == EINTR)
			continue;
		if (k < 0) {
			io->error = errno;
			return -1;
		}
		if (k == 0)
			break;         /* a short count: the library reports the file as cut off */
		done += (uint64_t)k;
	}
	return (int64_t)done;
}

/* The file's size lets the library check offsets in the header against it. */
static int64_t size_fn(exr_const_context_t ctx, void *ud)
{
	(void)ctx;
	struct exr_io *io = ud;
	struct stat st;
	return fstat(io->fd, &st) == 0 ? (int64_t)st.st_size : -1;
}

/* The message for a failed call: the OS's reason when there was one, else the
 * library's own message, else its text for the code. Returns the errno code. */
static int fail(const struct exr_io *io, exr_result_t rv, const char *verb, const char *path,
                char *err, size_t errlen)
{
	if (io->error) {
		snprintf(err, errlen, "cannot %s '%s': %s", verb, path, strerror(io->error));
		return io->error;
	}
	snprintf(err, errlen, "cannot %s '%s': OpenEXR: %s", verb, path,
	         io->msg[0] ? io->msg : exr_get_default_error_message(rv));
	return rv == EXR_ERR_OUT_OF_MEMORY ? ENOMEM : strcmp(verb, "read") == 0 ? EINVAL : EIO;
}

/* The windows and string attributes of hdr on a part whose required attributes are
 * set for a w x h image. */
static exr_result_t set_header(exr_context_t ctx, int part, const struct image_exr_header *hdr, int w,
                               int h)
{
	exr_attr_box2i_t display = { .min.x = hdr->display[0], .min.y = hdr->display[1],
	                             .max.x = hdr->display[2] - 1, .max.y = hdr->display[3] - 1 };
	exr_attr_box2i_t data = { .min.x = hdr->data_x, .min.y = hdr->data_y,
	                          .max.x = hdr->data_x + w - 1, .max.y = hdr->data_y + h - 1 };
	exr_result_t rv = exr_set_display_window(ctx, part, &display);
	if (rv == EXR_ERR_SUCCESS)
		rv = exr_set_data_window(ctx, part, &data);
	for (int i = 0; i < hdr->nattrs && rv == EXR_ERR_SUCCESS; i++)
		rv = exr_attr_set_string(ctx, part, hdr->attrs[i].name, hdr->attrs[i].value);
	return rv;
}

void image_exr_header_free(struct image_exr_header *h)
{
	for (int i = 0; i < h->nattrs; i++) {
		free((void *)h->attrs[i].name);
		free((void *)h->attrs[i].value);
	}
	h->nattrs = 0;
}

/* The header of part 0 that image_exr_read returns: its windows and its string
 * attributes named scn..., copied, the first IMAGE_EXR_ATTRS of them. */
static exr_result_t get_header(exr_context_t ctx, const exr_attr_box2i_t *dw, struct image_exr_header *h)
{
	exr_attr_box2i_t display;
	int32_t count;
	exr_result_t rv = exr_get_display_window(ctx, 0, &display);
	if (rv == EXR_ERR_SUCCESS)
		rv = exr_get_attribute_count(ctx, 0, &count);
	if (rv != EXR_ERR_SUCCESS)
		return rv;
	/* [x0, x1): the library checks max >= min; one past an int's range stays in int64 */
	if ((int64_t)display.max.x + 1 > INT32_MAX || (int64_t)display.max.y + 1 > INT32_MAX)
		return EXR_ERR_INVALID_ATTR;
	*h = (struct image_exr_header){ { display.min.x, display.min.y, display.max.x + 1, display.max.y + 1 },
	                                dw->min.x, dw->min.y, 0, { { 0 } } };
	for (int32_t i = 0; i < count && h->nattrs < IMAGE_EXR_ATTRS; i++) {
		const exr_attribute_t *a;
		rv = exr_get_attribute_by_index(ctx, 0, EXR_ATTR_LIST_FILE_ORDER, i, &a);
		if (rv != EXR_ERR_SUCCESS)
			break;
		if (a->type != EXR_ATTR_STRING || strncmp(a->name, "scn", 3) != 0)
			continue;
		char *value = xmalloc((size_t)a->string->length + 1);
		memcpy(value, a->string->str, (size_t)a->string->length);
		value[a->string->length] = '\0';
		h->attrs[h->nattrs++] = (struct image_attr){ xstrdup(a->name), value };
	}
	return rv;
}

/* The library's compressor, which compress_chunk runs. */
struct compressor {
	exr_result_t (*run)(exr_encode_pipeline_t *enc);
};

/* OpenEXR's ZIP encoder up to 3.4.7 (its issue 2306, mended by pull request 2307) keeps
 * a chunk's zlib bytes when they are exactly as many as the chunk's raw bytes, and a
 * reader takes a chunk of that size for raw bytes: garbage, found in one-row --tile
 * parts of a mesh. This runs the library's compressor and then stores the raw bytes in
 * that case, as the mended encoder does; in any other, the bytes are the library's. */
static exr_result_t compress_chunk(exr_encode_pipeline_t *enc)
{
	const struct compressor *library = enc->encoding_user_data;
	exr_result_t rv = library->run(enc);
	if (rv == EXR_ERR_SUCCESS && enc->compressed_bytes == enc->packed_bytes &&
	    enc->compressed_buffer != enc->packed_buffer)
		memcpy(enc->compressed_buffer, enc->packed_buffer, enc->packed_bytes);
	return rv;
}

/* One scanline part, ZIP-compressed (lossless, and the usual choice for renders),
 * with only the attributes the format requires (and "type", which the library adds):
 * no dates, software or host names, so that the same image always gives the same
 * bytes (with the same OpenEXR and zlib). NaN is written as 0
 * since nothing downstream can use it; other values, negative or infinite, as they
 * are (half float turns values beyond 65504 into infinity). */
int image_exr_write(const struct image *img, int fd, const char *path, bool float32,
                    const struct image_exr_header *hdr, char *err, size_t errlen)
{
	struct exr_io io = { .fd = fd };
	exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
	init.user_data = &io;
	init.write_fn = write_fn;
	init.error_handler_fn = on_error;
	init.max_image_width = init.max_image_height = 0x7fffffff;

	exr_context_t ctx = NULL;
	exr_encode_pipeline_t enc = EXR_ENCODE_PIPELINE_INITIALIZER;
	bool enc_started = false;
	float *buf = NULL;
	int part = 0;
	int32_t lines = 0;
	exr_pixel_type_t type = float32 ? EXR_PIXEL_FLOAT : EXR_PIXEL_HALF;
	struct compressor library;
	exr_result_t rv = exr_start_write(&ctx, path, EXR_WRITE_FILE_DIRECTLY, &init);
	if (rv == EXR_ERR_SUCCESS)
		rv = exr_add_part(ctx, NULL, EXR_STORAGE_SCANLINE, &part);
	if (rv == EXR_ERR_SUCCESS)
		rv = exr_initialize_required_attr_simple(ctx, part, img->width, img->height,
		                                         EXR_COMPRESSION_ZIP);
	int y0 = hdr ? hdr->data_y : 0;    /* the data window's first row */
	if (hdr && rv == EXR_ERR_SUCCESS)
		rv = set_header(ctx, part, hdr, img->width, img->height);
	/* pLinear 0 (perceptually logarithmic), as for linear light in OpenEXR's RGBA files */
	static const char *const names[3] = { "R", "G", "B" };
	for (int c = 0; c < 3 && rv == EXR_ERR_SUCCESS; c++)
		rv = exr_add_channel(ctx, part, names[c], type, EXR_PERCEPTUALLY_LOGARITHMIC, 1, 1);
	if (rv == EXR_ERR_SUCCESS)
		rv = exr_write_header(ctx);
	if (rv == EXR_ERR_SUCCESS)
		rv = exr_get_scanlines_per_chunk(ctx, part, &lines);
	if (rv == EXR_ERR_SUCCESS && lines <= 0)
		rv = EXR_ERR_UNKNOWN;
	if (rv == EXR_ERR_SUCCESS)
		buf = xmalloc((size_t)lines * (size_t)img->width * 3 * sizeof *buf);

	for (int y = 0; y < img->height && rv == EXR_ERR_SUCCESS; y += lines) {
		exr_chunk_info_t chunk;
		rv = exr_write_scanline_chunk_info(ctx, part, y0 + y, &chunk);
		if (rv != EXR_ERR_SUCCESS)
			break;
		if (enc_started)
			rv = exr_encoding_update(ctx, part, &chunk, &enc);
		else
			rv = exr_encoding_initialize(ctx, part, &chunk, &enc);
		if (rv != EXR_ERR_SUCCESS)
			break;
		enc_started = true;
		/* the chunk's rows, NaN replaced */
		size_t n = (size_t)chunk.height * (size_t)img->width * 3;
		const float *src = img->rgb + (size_t)y * img->width * 3;
		for (size_t i = 0; i < n; i++)
			buf[i] = isnan(src[i]) ? 0.0f : src[i];
		/* the library lists channels by name (B, G, R): find each one's place */
		for (int c = 0; c < enc.channel_count; c++) {
			exr_coding_channel_info_t *ch = &enc.channels[c];
			int k = ch->channel_name[0] == 'R' ? 0 : ch->channel_name[0] == 'G' ? 1 : 2;
			ch->encode_from_ptr = (const uint8_t *)(buf + k);
			ch->user_pixel_stride = 3 * sizeof *buf;
			ch->user_line_stride = img->width * 3 * (int32_t)sizeof *buf;
			ch->user_data_type = EXR_PIXEL_FLOAT;
			ch->user_bytes_per_element = sizeof *buf;
		}
		rv = exr_encoding_choose_default_routines(ctx, part, &enc);
		if (rv == EXR_ERR_SUCCESS && enc.compress_fn) {
			library.run = enc.compress_fn;
			enc.encoding_user_data = &library;
			enc.compress_fn = compress_chunk;
		}
		if (rv == EXR_ERR_SUCCESS)
			rv = exr_encoding_run(ctx, part, &enc);
	}
	if (enc_started) {
		exr_result_t rv2 = exr_encoding_destroy(ctx, &enc);
		if (rv == EXR_ERR_SUCCESS)
			rv = rv2;
	}
	free(buf);
	/* exr_finish writes the table of chunk offsets, so its result counts too */
	if (ctx) {
		exr_result_t rv2 = exr_finish(&ctx);
		if (rv == EXR_ERR_SUCCESS)
			rv = rv2;
	}
	if (rv != EXR_ERR_SUCCESS)
		return fail(&io, rv, "write", path, err, errlen);
	return 0;
}

/* Where each colour of the image comes from in one part: the channel index of R, G
 * and B, or of Y (luminance) for all three, as in grey EXR files. */
struct exr_source {
	int channel[3];
	bool grey;
};

static const char *find_channels(const exr_attr_chlist_t *list, struct exr_source *src)
{
	int r = -1, g = -1, b = -1, y = -1;
	for (int i = 0; i < list->num_channels; i++) {
		const char *name = list->entries[i].name.str;
		if (strcmp(name, "R") == 0) r = i;
		else if (strcmp(name, "G") == 0) g = i;
		else if (strcmp(name, "B") == 0) b = i;
		else if (strcmp(name, "Y") == 0) y = i;
	}
	if (r >= 0 && g >= 0 && b >= 0)
		*src = (struct exr_source){ { r, g, b }, false };
	else if (y >= 0)
		*src = (struct exr_source){ { y, y, y }, true };
	else
		return "no R, G and B (or Y) channels";
	for (int c = 0; c < 3; c++) {
		const exr_attr_chlist_entry_t *e = &list->entries[src->channel[c]];
		if (e->x_sampling != 1 || e->y_sampling != 1)
			return "subsampled colour channels are not supported";
	}
	return NULL;
}

/* The bytes of pixel data per pixel that the channels take in the file. */
static double file_bytes_per_pixel(const exr_attr_chlist_t *list)
{
	double n = 0;
	for (int i = 0; i < list->num_channels; i++) {
		const exr_attr_chlist_entry_t *e = &list->entries[i];
		int64_t per_sample = (int64_t)e->x_sampling * e->y_sampling;  /* pixels */
		n += (e->pixel_type == EXR_PIXEL_HALF ? 2.0 : 4.0) / (per_sample > 0 ? per_sample : 1);
	}
	return n;
}

/* The most bytes of pixels one byte of a chunk decodes to, by compression (bounds, with
 * margin above what constant images reach): zlib's 1032:1 for ZIP and ZIPS, and for
 * PXR24, whose 24-bit floats add 4:3; RLE's 128-byte run in 2 bytes; PIZ's Huffman runs
 * (256 values of 16 bits in 10 bits) stay below zlib's; B44 packs a 4 x 4 block of
 * halves (32 bytes) into 14, B44A a flat one into 3; DWA (which OpenEXR 3.1's C API
 * cannot decode) can leave an 8 x 8 block of halves to one zlib-packed value. */
static unsigned max_ratio(exr_compression_t c)
{
	switch (c) {
	case EXR_COMPRESSION_NONE: return 1;
	case EXR_COMPRESSION_RLE: return 64;
	case EXR_COMPRESSION_ZIPS:
	case EXR_COMPRESSION_ZIP:
	case EXR_COMPRESSION_PIZ: return 1032;
	case EXR_COMPRESSION_PXR24: return 1376;
	case EXR_COMPRESSION_B44: return 3;
	case EXR_COMPRESSION_B44A: return 11;
	default: return 64 * 1032;
	}
}

/* Decodes one chunk into the image: out points at the chunk's top-left pixel. The
 * pipeline is set up on the first chunk (*started) and updated for the others; every
 * chunk gets the same layout, interleaved float RGB with the image's row stride, and
 * the library picks its routines for it after each update. The channels we do not use
 * (A, Z, ...) go to *scratch (grown to the chunk's size, freed by the caller), not
 * nowhere: when all channels are half, OpenEXR 3.1's fast half-to-float unpackers
 * (internal_exr_match_decode) write every channel, and one without a destination would
 * have them write through a null pointer (a file with B, G and Y: found by fuzzing). */
static exr_result_t decode_chunk(exr_context_t ctx, const exr_chunk_info_t *chunk,
                                 exr_decode_pipeline_t *dec, bool *started,
                                 const struct exr_source *src, float *out, int width,
                                 float **scratch)
{
	exr_result_t rv = *started ? exr_decoding_update(ctx, 0, chunk, dec)
	                           : exr_decoding_initialize(ctx, 0, chunk, dec);
	if (rv != EXR_ERR_SUCCESS)
		return rv;
	*started = true;
	*scratch = xrealloc(*scratch, (size_t)chunk->width * (size_t)chunk->height * sizeof **scratch);
	for (int c = 0; c < dec->channel_count; c++) {
		exr_coding_channel_info_t *ch = &dec->channels[c];
		ch->decode_to_ptr = (uint8_t *)*scratch;
		ch->user_pixel_stride = sizeof **scratch;
		ch->user_line_stride = chunk->width * (int32_t)sizeof **scratch;
		for (int k = 0; k < (src->grey ? 1 : 3); k++)
			if (c == src->channel[k]) {
				ch->decode_to_ptr = (uint8_t *)(out + k);
				ch->user_pixel_stride = 3 * sizeof *out;
				ch->user_line_stride = width * 3 * (int32_t)sizeof *out;
			}
		ch->user_data_type = EXR_PIXEL_FLOAT;
		ch->user_bytes_per_element = sizeof *out;
	}
	rv = exr_decoding_choose_default_routines(ctx, 0, dec);
	if (rv != EXR_ERR_SUCCESS)
		return rv;
	return exr_decoding_run(ctx, 0, dec);
}

/* The first part of the file is read, at full resolution (mipmap level 0), and with
 * hdr its header. */
int image_exr_read(int fd, const char *path, struct image **out, struct image_exr_header *hdr,
                   char *err, size_t errlen)
{
	struct exr_io io = { .fd = fd };
	exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
	init.user_data = &io;
	init.read_fn = read_fn;
	init.size_fn = size_fn;
	init.error_handler_fn = on_error;
	if (hdr) /* empty, so that a failure before get_header frees nothing */
		*hdr = (struct image_exr_header){ .nattrs = 0 };

	exr_context_t ctx = NULL;
	exr_decode_pipeline_t dec = EXR_DECODE_PIPELINE_INITIALIZER;
	bool dec_started = false;
	float *scratch = NULL;         /* see decode_chunk */
	const char *what = NULL;       /* what is wrong with the file, beyond the library's view */
	int rc = 0;
	exr_storage_t storage;
	exr_attr_box2i_t dw;
	const exr_attr_chlist_t *chans;
	exr_compression_t compression;
	struct exr_source src;
	int64_t w = 0, h = 0;

	exr_result_t rv = exr_start_read(&ctx, path, &init);
	if (rv == EXR_ERR_SUCCESS)
		rv = exr_get_storage(ctx, 0, &storage);
	if (rv == EXR_ERR_SUCCESS)
		rv = exr_get_data_window(ctx, 0, &dw);
	if (rv == EXR_ERR_SUCCESS)
		rv = exr_get_channels(ctx, 0, &chans);
	if (rv == EXR_ERR_SUCCESS)
		rv = exr_get_compression(ctx, 0, &compression);
	if (rv != EXR_ERR_SUCCESS)
		goto done;
	if (storage != EXR_STORAGE_SCANLINE && storage != EXR_STORAGE_TILED) {
		what = "deep images are not supported";
		goto done;
	}
	if ((what = find_channels(chans, &src)) != NULL)
		goto done;
	w = (int64_t)dw.max.x - dw.min.x + 1;
	h = (int64_t)dw.max.y - dw.min.y + 1;
	if ((rc = image_alloc_for_read(w, h, fd, (double)w * h * file_bytes_per_pixel(chans),
	                               max_ratio(compression), path, out, err, errlen)) != 0)
		goto done;
	(*out)->source = (struct image_source){ .format = IMAGE_EXR };
	for (int i = 0; i < chans->num_channels; i++)
		(*out)->source.exr_not_half |= chans->entries[i].pixel_type != EXR_PIXEL_HALF;
	float *rgb = (*out)->rgb;

	if (storage == EXR_STORAGE_SCANLINE) {
		int32_t lines;
		rv = exr_get_scanlines_per_chunk(ctx, 0, &lines);
		if (rv == EXR_ERR_SUCCESS && lines <= 0)
			what = "bad scanlines per chunk";
		for (int64_t y = dw.min.y; y <= dw.max.y && rv == EXR_ERR_SUCCESS && !what; y += lines) {
			exr_chunk_info_t chunk;
			rv = exr_read_scanline_chunk_info(ctx, 0, (int)y, &chunk);
			if (rv != EXR_ERR_SUCCESS)
				break;
			int64_t row = (int64_t)chunk.start_y - dw.min.y;
			if (row < 0 || row + chunk.height > h || chunk.width != w) {
				what = "chunk outside the data window";
				break;
			}
			rv = decode_chunk(ctx, &chunk, &dec, &dec_started, &src, rgb + row * w * 3, (int)w,
			                  &scratch);
		}
	} else {
		uint32_t tw, th;
		exr_tile_level_mode_t levels;
		exr_tile_round_mode_t round;
		rv = exr_get_tile_descriptor(ctx, 0, &tw, &th, &levels, &round);
		if (rv == EXR_ERR_SUCCESS && (tw == 0 || th == 0))
			what = "bad tile size";
		for (int64_t ty = 0; rv == EXR_ERR_SUCCESS && !what && ty * th < h; ty++) {
			for (int64_t tx = 0; rv == EXR_ERR_SUCCESS && !what && tx * tw < w; tx++) {
				exr_chunk_info_t chunk;
				rv = exr_read_tile_chunk_info(ctx, 0, (int)tx, (int)ty, 0, 0, &chunk);
				if (rv != EXR_ERR_SUCCESS)
					break;
				int64_t x0 = tx * tw, y0 = ty * th;
				if (chunk.width <= 0 || chunk.height <= 0 || x0 + chunk.width > w ||
				    y0 + chunk.height > h) {
					what = "tile outside the data window";
					break;
				}
				rv = decode_chunk(ctx, &chunk, &dec, &dec_started, &src,
				                  rgb + (y0 * w + x0) * 3, (int)w, &scratch);
			}
		}
	}
	if (rv == EXR_ERR_SUCCESS && !what) {
		size_t n = (size_t)w * (size_t)h * 3;
		for (size_t i = 0; i < n; i += 3) {
			if (src.grey)
				rgb[i + 1] = rgb[i + 2] = rgb[i];
			/* NaN is of no use to a skybox or a comparison: 0, as on write */
			for (int c = 0; c < 3; c++)
				if (isnan(rgb[i + c]))
					rgb[i + c] = 0;
		}
	}
	if (hdr && rv == EXR_ERR_SUCCESS && !what)
		rv = get_header(ctx, &dw, hdr);
done:
	if (hdr && (rc != 0 || what || rv != EXR_ERR_SUCCESS))
		image_exr_header_free(hdr);
	free(scratch);
	if (dec_started)
		exr_decoding_destroy(ctx, &dec);
	if (ctx)
		exr_finish(&ctx);
	if (rc != 0)
		return rc;
	if (what) {
		snprintf(err, errlen, "cannot read '%s': %s", path, what);
		return EINVAL;
	}
	if (rv != EXR_ERR_SUCCESS)
		return fail(&io, rv, "read", path, err, errlen);
	return 0;
}
