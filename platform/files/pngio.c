/* SPDX-License-Identifier: MIT */
#include "pngio.h"

/* libpng */
#include <png.h>

#include <errno.h>
#include <setjmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Larger than any screen we draw; keeps a hostile header from asking for gigabytes. */
#define PNG_MAX_SIDE 16384

/*
 * libpng reports errors through a callback that must not return: it keeps the message
 * here and longjmps. Only that callback writes msg/code, right before jumping.
 */
struct png_ctx {
	char msg[256];
	int code; /* -EINVAL, or -ENOMEM when an allocation failed */
	/* decoding: the input */
	const unsigned char *data;
	size_t len, pos;
	/* encoding: the output */
	struct buf *out;
};

static void on_error(png_structp png, png_const_charp msg)
{
	struct png_ctx *ctx = png_get_error_ptr(png);

	snprintf(ctx->msg, sizeof(ctx->msg), "%s", msg);
	ctx->code = strstr(msg, "memory") ? -ENOMEM : -EINVAL;
	png_longjmp(png, 1);
}

/* Warnings (e.g. a damaged ancillary chunk that libpng skips) do not change the pixels. */
static void on_warning(png_structp png, png_const_charp msg)
{
	(void)png;
	(void)msg;
}

static void write_fn(png_structp png, png_bytep data, size_t len)
{
	struct png_ctx *ctx = png_get_io_ptr(png);

	/* on_error maps "memory" to -ENOMEM */
	if (buf_append(ctx->out, data, len) < 0)
		png_error(png, "out of memory");
}

static void flush_fn(png_structp png)
{
	(void)png;
}

static void read_fn(png_structp png, png_bytep data, size_t len)
{
	struct png_ctx *ctx = png_get_io_ptr(png);

	if (len > ctx->len - ctx->pos)
		png_error(png, "unexpected end of data (truncated file)");
	memcpy(data, ctx->data + ctx->pos, len);
	ctx->pos += len;
}

int pngio_encode_rgba(const uint8_t *rgba, int width, int height, struct buf *out, struct error *err)
{
	struct png_ctx ctx = { .out = out };
	png_structp png;
	png_infop info = NULL;
	size_t start = out->len;

	if (width <= 0 || height <= 0 || width > PNG_MAX_SIDE || height > PNG_MAX_SIDE)
		return error_set(err, -EINVAL, "png: cannot encode a %dx%d image", width, height);
	png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &ctx, on_error, on_warning);
	if (png)
		info = png_create_info_struct(png);
	if (!png || !info) {
		png_destroy_write_struct(&png, NULL);
		return error_set(err, -ENOMEM, "png: out of memory");
	}
	if (setjmp(png_jmpbuf(png))) {
		png_destroy_write_struct(&png, &info);
		out->len = start; /* drop the partial image */
		return error_set(err, ctx.code ? ctx.code : -EINVAL, "png: %s", ctx.msg);
	}
	png_set_write_fn(png, &ctx, write_fn, flush_fn);
	/* Nothing but IHDR, IDAT and IEND: no time or text chunks, so same pixels, same bytes. */
	png_set_IHDR(png, info, (png_uint_32)width, (png_uint_32)height, 8, PNG_COLOR_TYPE_RGB_ALPHA,
		     PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
	png_write_info(png, info);
	for (int y = 0; y < height; y++)
		png_write_row(png, rgba + (size_t)y * (size_t)width * 4);
	png_write_end(png, NULL);
	png_destroy_write_struct(&png, &info);
	return 0;
}

/* Asks libpng to deliver 8-bit RGBA whatever the file holds. */
static void set_rgba8_transforms(png_structp png, png_infop info)
{
	int color = png_get_color_type(png, info);
	int depth = png_get_bit_depth(png, info);

	if (color == PNG_COLOR_TYPE_PALETTE)
		png_set_palette_to_rgb(png);
	if (color == PNG_COLOR_TYPE_GRAY && depth < 8)
		png_set_expand_gray_1_2_4_to_8(png);
	if (png_get_valid(png, info, PNG_INFO_tRNS))
		png_set_tRNS_to_alpha(png);
	if (depth == 16)
		png_set_strip_16(png);
	if (color == PNG_COLOR_TYPE_GRAY || color == PNG_COLOR_TYPE_GRAY_ALPHA)
		png_set_gray_to_rgb(png);
	if (!(color & PNG_COLOR_MASK_ALPHA) && !png_get_valid(png, info, PNG_INFO_tRNS))
		png_set_add_alpha(png, 0xff, PNG_FILLER_AFTER);
	png_set_interlace_handling(png);
	png_read_update_info(png, info);
}

int pngio_decode_rgba(const void *data, size_t len, const char *name, uint8_t **rgba, int *width,
		    int *height, struct error *err)
{
	struct png_ctx ctx = { .data = data, .len = len };
	png_structp png;
	png_infop info = NULL;
	/* assigned after setjmp and freed after a longjmp: must be volatile */
	uint8_t *volatile pixels = NULL;
	png_bytep *volatile rows = NULL;
	png_uint_32 w, h;

	*rgba = NULL;
	if (len < 8 || png_sig_cmp(data, 0, 8) != 0)
		return error_at(err, -EINVAL, name, 0, "not a PNG file");
	png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &ctx, on_error, on_warning);
	if (png)
		info = png_create_info_struct(png);
	if (!png || !info) {
		png_destroy_read_struct(&png, NULL, NULL);
		return error_at(err, -ENOMEM, name, 0, "out of memory");
	}
	if (setjmp(png_jmpbuf(png))) {
		png_destroy_read_struct(&png, &info, NULL);
		free(rows);
		free(pixels);
		return error_at(err, ctx.code ? ctx.code : -EINVAL, name, 0, "damaged PNG: %s",
				ctx.msg);
	}
	png_set_read_fn(png, &ctx, read_fn);
	png_set_user_limits(png, PNG_MAX_SIDE, PNG_MAX_SIDE);
	png_read_info(png, info);
	w = png_get_image_width(png, info);
	h = png_get_image_height(png, info);
	set_rgba8_transforms(png, info);
	if (png_get_rowbytes(png, info) != (size_t)w * 4)
		png_error(png, "cannot convert to 8-bit RGBA");

	pixels = malloc((size_t)w * h * 4);
	rows = malloc(h * sizeof(*rows));
	if (!pixels || !rows)
		png_error(png, "out of memory");
	for (png_uint_32 y = 0; y < h; y++)
		rows[y] = pixels + (size_t)y * w * 4;
	png_read_image(png, rows);
	/* reads up to IEND, so damage after the pixels (bad CRC, missing end) is caught too */
	png_read_end(png, NULL);

	png_destroy_read_struct(&png, &info, NULL);
	free(rows);
	*rgba = pixels;
	*width = (int)w;
	*height = (int)h;
	return 0;
}
