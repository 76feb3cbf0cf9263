/* SPDX-License-Identifier: MIT */
/* pngio_encode_rgba / pngio_decode_rgba: round trip, determinism, other formats, damage. */
#include <libpng16/png.h> /* to write formats pngio_encode_rgba does not */

#include <errno.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "buf.h"
#include "error.h"
#include "pngio.h"
#include "test.h"

#define W 37
#define H 23

static uint8_t *make_image(void)
{
	uint8_t *rgba = malloc(W * H * 4);

	CHECK(rgba);
	for (int y = 0; y < H; y++) {
		for (int x = 0; x < W; x++) {
			uint8_t *p = rgba + (y * W + x) * 4;

			p[0] = (uint8_t)(x * 7);
			p[1] = (uint8_t)(y * 11);
			p[2] = (uint8_t)(x * y);
			p[3] = (uint8_t)(255 - x - y);
		}
	}
	return rgba;
}

static uint32_t be32(const unsigned char *p)
{
	return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | p[3];
}

/* Only the chunks pixels need: nothing that changes from run to run (tIME, text). */
static void check_chunks(const struct buf *b)
{
	size_t pos = 8;
	int nidat = 0;

	CHECK(memcmp(b->data + pos + 4, "IHDR", 4) == 0);
	while (pos + 12 <= b->len) {
		uint32_t len = be32(b->data + pos);
		const unsigned char *type = b->data + pos + 4;

		if (memcmp(type, "IDAT", 4) == 0) {
			nidat++;
		} else if (memcmp(type, "IEND", 4) == 0) {
			CHECK_INT(pos + 12, b->len);
			CHECK(nidat > 0);
			return;
		} else {
			CHECK(memcmp(type, "IHDR", 4) == 0);
		}
		pos += 12 + len;
	}
	CHECK(!"no IEND");
}

static void test_round_trip(void)
{
	uint8_t *rgba = make_image(), *back = NULL;
	struct buf a, b;
	struct error err;
	int w = 0, h = 0;

	buf_init(&a);
	buf_init(&b);
	CHECK_INT(pngio_encode_rgba(rgba, W, H, &a, &err), 0);
	CHECK_INT(pngio_encode_rgba(rgba, W, H, &b, &err), 0);
	CHECK_INT(a.len, b.len);
	CHECK(memcmp(a.data, b.data, a.len) == 0);
	check_chunks(&a);

	CHECK_INT(pngio_decode_rgba(a.data, a.len, "a.png", &back, &w, &h, &err), 0);
	CHECK_INT(w, W);
	CHECK_INT(h, H);
	CHECK(memcmp(rgba, back, W * H * 4) == 0);

	CHECK_INT(pngio_encode_rgba(rgba, 0, H, &a, &err), -EINVAL);
	free(back);
	free(rgba);
	buf_finish(&a);
	buf_finish(&b);
}

static void write_fn(png_structp png, png_bytep data, size_t len)
{
	CHECK_INT(buf_append(png_get_io_ptr(png), data, len), 0);
}

static void flush_fn(png_structp png)
{
	(void)png;
}

/* A PNG of another colour type, written with libpng itself. */
static void write_other(struct buf *out, int w, int h, int depth, int color, int interlace,
			png_bytep *rows, const png_color *palette, int npalette,
			const png_byte *trans, int ntrans)
{
	png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
	png_infop info = png_create_info_struct(png);

	CHECK(png && info);
	CHECK(setjmp(png_jmpbuf(png)) == 0);
	png_set_write_fn(png, out, write_fn, flush_fn);
	png_set_IHDR(png, info, (png_uint_32)w, (png_uint_32)h, depth, color, interlace,
		     PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
	if (palette)
		png_set_PLTE(png, info, palette, npalette);
	if (trans)
		png_set_tRNS(png, info, trans, ntrans, NULL);
	png_write_info(png, info);
	png_write_image(png, rows);
	png_write_end(png, NULL);
	png_destroy_write_struct(&png, &info);
}

static void decode_ok(const struct buf *b, int w, int h, uint8_t **rgba)
{
	struct error err;
	int dw, dh;

	CHECK_INT(pngio_decode_rgba(b->data, b->len, "other.png", rgba, &dw, &dh, &err), 0);
	CHECK_INT(dw, w);
	CHECK_INT(dh, h);
}

static void check_pixel(const uint8_t *rgba, int w, int x, int y, int r, int g, int b, int a)
{
	const uint8_t *p = rgba + (y * w + x) * 4;

	CHECK_INT(p[0], r);
	CHECK_INT(p[1], g);
	CHECK_INT(p[2], b);
	CHECK_INT(p[3], a);
}

static void test_other_formats(void)
{
	struct buf b;
	uint8_t *rgba;

	/* grey, 8 bit, interlaced */
	{
		png_byte px[2][3] = { { 0, 100, 255 }, { 7, 8, 9 } };
		png_bytep rows[2] = { px[0], px[1] };

		buf_init(&b);
		write_other(&b, 3, 2, 8, PNG_COLOR_TYPE_GRAY, PNG_INTERLACE_ADAM7, rows, NULL, 0,
			    NULL, 0);
		decode_ok(&b, 3, 2, &rgba);
		check_pixel(rgba, 3, 1, 0, 100, 100, 100, 255);
		check_pixel(rgba, 3, 2, 1, 9, 9, 9, 255);
		free(rgba);
		buf_finish(&b);
	}
	/* grey + alpha */
	{
		png_byte px[1][4] = { { 50, 60, 200, 0 } };
		png_bytep rows[1] = { px[0] };

		buf_init(&b);
		write_other(&b, 2, 1, 8, PNG_COLOR_TYPE_GRAY_ALPHA, PNG_INTERLACE_NONE, rows, NULL, 0,
			    NULL, 0);
		decode_ok(&b, 2, 1, &rgba);
		check_pixel(rgba, 2, 0, 0, 50, 50, 50, 60);
		check_pixel(rgba, 2, 1, 0, 200, 200, 200, 0);
		free(rgba);
		buf_finish(&b);
	}
	/* 4-bit palette with a transparent entry */
	{
		png_color palette[3] = { { 255, 0, 0 }, { 0, 255, 0 }, { 1, 2, 3 } };
		png_byte trans[1] = { 0 };
		png_byte px[1][2] = { { 0x01, 0x20 } }; /* indices 0 1 2 0 */
		png_bytep rows[1] = { px[0] };

		buf_init(&b);
		write_other(&b, 4, 1, 4, PNG_COLOR_TYPE_PALETTE, PNG_INTERLACE_NONE, rows, palette,
			    3, trans, 1);
		decode_ok(&b, 4, 1, &rgba);
		check_pixel(rgba, 4, 0, 0, 255, 0, 0, 0);
		check_pixel(rgba, 4, 1, 0, 0, 255, 0, 255);
		check_pixel(rgba, 4, 2, 0, 1, 2, 3, 255);
		free(rgba);
		buf_finish(&b);
	}
	/* RGB, 16 bit */
	{
		png_byte px[1][6] = { { 0x12, 0x34, 0xff, 0xff, 0x00, 0x01 } };
		png_bytep rows[1] = { px[0] };

		buf_init(&b);
		write_other(&b, 1, 1, 16, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, rows, NULL, 0,
			    NULL, 0);
		decode_ok(&b, 1, 1, &rgba);
		check_pixel(rgba, 1, 0, 0, 0x12, 0xff, 0x00, 255);
		free(rgba);
		buf_finish(&b);
	}
	/* grey, 1 bit */
	{
		png_byte px[1][1] = { { 0xa0 } }; /* 1 0 1 */
		png_bytep rows[1] = { px[0] };

		buf_init(&b);
		write_other(&b, 3, 1, 1, PNG_COLOR_TYPE_GRAY, PNG_INTERLACE_NONE, rows, NULL, 0, NULL,
			    0);
		decode_ok(&b, 3, 1, &rgba);
		check_pixel(rgba, 3, 0, 0, 255, 255, 255, 255);
		check_pixel(rgba, 3, 1, 0, 0, 0, 0, 255);
		free(rgba);
		buf_finish(&b);
	}
}

static void expect_damaged(const void *data, size_t len)
{
	struct error err;
	uint8_t *rgba = (uint8_t *)1;
	int w = -1, h = -1;

	err.msg[0] = '\0';
	CHECK_INT(pngio_decode_rgba(data, len, "bad.png", &rgba, &w, &h, &err), -EINVAL);
	CHECK(rgba == NULL);
	CHECK(strncmp(err.msg, "bad.png: ", 9) == 0);
}

static void test_damaged(void)
{
	uint8_t *rgba = make_image();
	struct buf b;
	struct error err;
	unsigned char *copy;

	buf_init(&b);
	CHECK_INT(pngio_encode_rgba(rgba, W, H, &b, &err), 0);
	copy = malloc(b.len);
	CHECK(copy);

	expect_damaged("", 0);
	expect_damaged("GIF89a, not a PNG at all", 24);
	/* cut anywhere: always refused, never a short read past the end */
	for (size_t len = 0; len < b.len; len++) {
		memcpy(copy, b.data, len);
		expect_damaged(copy, len);
	}
	/* any byte changed after the signature: a CRC, a length or the data itself breaks */
	for (size_t i = 8; i < b.len; i++) {
		memcpy(copy, b.data, b.len);
		copy[i] ^= 0x40;
		expect_damaged(copy, b.len);
	}
	/* a header asking for a huge image is refused before anything is allocated */
	{
		png_byte px[1] = { 0 };
		png_bytep rows[1] = { px };
		struct buf big;

		buf_init(&big);
		write_other(&big, 1, 1, 8, PNG_COLOR_TYPE_GRAY, PNG_INTERLACE_NONE, rows, NULL, 0,
			    NULL, 0);
		/* width field of IHDR: 8 (signature) + 8 (length, type) */
		big.data[16] = 0x7f;
		expect_damaged(big.data, big.len);
		buf_finish(&big);
	}
	free(copy);
	free(rgba);
	buf_finish(&b);
}

int main(void)
{
	test_round_trip();
	test_other_formats();
	test_damaged();
	return 0;
}
