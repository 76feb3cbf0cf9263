/* SPDX-License-Identifier: MIT */
/*
 * The text path without GL: UTF-8 decoding, the atlas's packing, glyphs rasterised once
 * and cached, measuring and setting a line, and the labels in both languages fitting
 * their buttons at the kiosk's size. Uses the font platform/files/font_file.c finds (the
 * image's fonts-vlgothic).
 */
#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "atlas.h"
#include "batch.h"
#include "font.h"
#include "font_file.h"
#include "labels.h"
#include "layout.h"
#include "render_private.h"
#include "test.h"
#include "text.h"
#include "utf8.h"

/* Decodes all of s (n bytes) into out, returning how many code points. */
static size_t decode(const char *s, size_t n, uint32_t *out)
{
	size_t i = 0, k = 0;

	while (i < n) {
		size_t before = i;

		out[k++] = utf8_next(s, n, &i);
		CHECK(i > before && i <= n);
	}
	return k;
}

static void check_one(const char *s, size_t n, uint32_t want)
{
	uint32_t cp[8];

	CHECK_INT(decode(s, n, cp), 1);
	CHECK_INT(cp[0], want);
}

static void test_utf8(void)
{
	uint32_t cp[16];
	size_t n;

	/* the limits of each length */
	check_one("\x00", 1, 0);
	check_one("\x7f", 1, 0x7f);
	check_one("\xc2\x80", 2, 0x80);
	check_one("\xdf\xbf", 2, 0x7ff);
	check_one("\xe0\xa0\x80", 3, 0x800);
	check_one("\xef\xbf\xbf", 3, 0xffff);
	check_one("\xf0\x90\x80\x80", 4, 0x10000);
	check_one("\xf4\x8f\xbf\xbf", 4, 0x10ffff);
	check_one("あ", strlen("あ"), 0x3042);
	check_one("木", strlen("木"), 0x6728);

	/* malformed: each bad byte is one U+FFFD, and decoding goes on after it */
	static const struct {
		const char *s;
		size_t n;
	} bad[] = {
		{ "\x80", 1 },		     /* a continuation byte alone */
		{ "\xc0\x80", 2 },	     /* overlong NUL */
		{ "\xc1\xbf", 2 },	     /* overlong 0x7f */
		{ "\xe0\x80\x80", 3 },	     /* overlong 3-byte */
		{ "\xf0\x80\x80\x80", 4 },   /* overlong 4-byte */
		{ "\xed\xa0\x80", 3 },	     /* a surrogate */
		{ "\xf4\x90\x80\x80", 4 },   /* past U+10FFFF */
		{ "\xf5\x80\x80\x80", 4 },   /* no sequence starts with 0xf5 */
		{ "\xff", 1 },
		{ "\xe3\x81", 2 },	     /* cut short */
		{ "\xe3\x41\x82", 3 },	     /* an ASCII byte inside */
	};
	for (size_t i = 0; i < sizeof(bad) / sizeof(bad[0]); i++) {
		n = decode(bad[i].s, bad[i].n, cp);
		CHECK(n >= 1);
		CHECK_INT(cp[0], UTF8_REPLACEMENT);
	}
	/* what follows a bad byte is read as itself */
	n = decode("a\xe3\x81" "b\xe3\x81\x82", 7, cp);
	CHECK_INT(n, 5);
	CHECK_INT(cp[0], 'a');
	CHECK_INT(cp[1], UTF8_REPLACEMENT);
	CHECK_INT(cp[2], UTF8_REPLACEMENT);
	CHECK_INT(cp[3], 'b');
	CHECK_INT(cp[4], 0x3042);
	n = decode("\xe3\x41\x82", 3, cp);
	CHECK_INT(n, 3);
	CHECK_INT(cp[1], 'A');
	CHECK_INT(cp[2], UTF8_REPLACEMENT);
	/* the length given is the end, not a NUL */
	n = decode("\xe3\x81\x82", 2, cp);
	CHECK_INT(n, 2);
	CHECK_INT(cp[0], UTF8_REPLACEMENT);
}

static void test_atlas(void)
{
	struct atlas a;
	uint8_t img[80 * 40];
	int x[64], y[64];

	CHECK_INT(atlas_init(&a, 100, 1024), -EINVAL); /* not a power of two */
	CHECK_INT(atlas_init(&a, 64, 32), -EINVAL);
	CHECK_INT(atlas_init(&a, 64, 256), 0);
	/* the solid block BATCH_SOLID_UV samples, and a blank texel round it */
	for (int r = 0; r < 2 * BATCH_SOLID_UV; r++)
		for (int c = 0; c < 2 * BATCH_SOLID_UV; c++)
			CHECK_INT(a.pixels[r * a.w + c], 255);
	CHECK_INT(a.pixels[2 * BATCH_SOLID_UV], 0);
	CHECK(a.resized);
	atlas_clean(&a);

	/* images go in without overlapping, a blank texel apart, their pixels copied */
	memset(img, 0, sizeof(img));
	for (int i = 0; i < 20; i++) {
		int w = 5 + i % 7, h = 4 + i % 5;

		memset(img, 10 + i, sizeof(img));
		CHECK_INT(atlas_add(&a, img, w, h, 40, &x[i], &y[i]), 0);
		CHECK(x[i] >= 0 && y[i] >= 0 && x[i] + w <= a.w && y[i] + h <= a.h);
		CHECK(a.dirty_y0 <= y[i] && a.dirty_y1 >= y[i] + h);
		for (int j = 0; j < i; j++) {
			int wj = 5 + j % 7, hj = 4 + j % 5;

			CHECK(x[i] >= x[j] + wj + 1 || x[j] >= x[i] + w + 1 || y[i] >= y[j] + hj + 1 ||
			      y[j] >= y[i] + h + 1);
		}
	}
	for (int i = 0; i < 20; i++)
		CHECK_INT(a.pixels[y[i] * a.w + x[i]], 10 + i);
	CHECK(!a.resized); /* 64 x 64 was enough */

	/* it grows, keeping what it holds where it was; then it is full */
	CHECK_INT(atlas_add(&a, img, 70, 30, 80, &x[20], &y[20]), 0);
	CHECK(a.w >= 128 && a.resized);
	for (int i = 0; i < 20; i++)
		CHECK_INT(a.pixels[y[i] * a.w + x[i]], 10 + i);
	CHECK_INT(a.pixels[0], 255);
	CHECK_INT(atlas_add(&a, img, 300, 2, 0, &x[21], &y[21]), -ENOSPC);
	CHECK_INT(atlas_add(&a, img, -1, 2, 40, &x[21], &y[21]), -EINVAL);
	/* an empty image takes no room worth speaking of */
	CHECK_INT(atlas_add(&a, img, 0, 0, 0, &x[21], &y[21]), 0);
	atlas_finish(&a);
	CHECK(a.pixels == NULL);
}

struct fixture {
	struct atlas atlas;
	struct font *font;
};

static void open_font(struct fixture *f)
{
	struct error err;
	const char *used;
	char *data;
	size_t len;

	if (font_file_read(NULL, &data, &len, &used, &err) < 0) {
		fprintf(stderr, "%s\n", err.msg);
		CHECK(0);
	}
	CHECK_INT(atlas_init(&f->atlas, 256, 2048), 0);
	CHECK_INT(font_create(&f->font, data, len, &f->atlas), 0);
	/* the font keeps its own copy */
	memset(data, 0, len);
	free(data);
}

static void close_font(struct fixture *f)
{
	font_destroy(f->font);
	atlas_finish(&f->atlas);
}

static void test_font(void)
{
	static const char junk[] = "not a font at all, just words";
	struct fixture f;
	struct font *bad;
	struct atlas a;
	const struct font_glyph *g, *again;
	size_t cached;
	int ascent, descent;

	CHECK_INT(atlas_init(&a, 64, 64), 0);
	CHECK_INT(font_create(&bad, junk, sizeof(junk), &a), -EINVAL);
	CHECK(bad == NULL);
	atlas_finish(&a);

	open_font(&f);
	CHECK(font_has(f.font, 'A') && font_has(f.font, 0x3042) && font_has(f.font, 0x6728));
	CHECK(!font_has(f.font, 0x10fffd)); /* private use: in no font */
	CHECK(font_glyph(f.font, 'A', 0) == NULL);
	CHECK(font_glyph(f.font, 'A', FONT_MAX_PX + 1) == NULL);

	/* rasterised once: the second ask costs no new glyph and gives the same one */
	g = font_glyph(f.font, 0x3042, 40);
	CHECK(g && g->w > 10 && g->h > 10 && g->advance_64 > 30 * 64);
	cached = font_cached(f.font);
	again = font_glyph(f.font, 0x3042, 40);
	CHECK(again && again->x == g->x && again->y == g->y && again->w == g->w);
	CHECK_INT(font_cached(f.font), cached);
	/* the atlas holds its ink */
	{
		unsigned sum = 0;

		for (int r = 0; r < g->h; r++)
			for (int c = 0; c < g->w; c++)
				sum += f.atlas.pixels[(g->y + r) * f.atlas.w + g->x + c];
		CHECK(sum > 255u * 20);
	}
	/* another size is another glyph */
	g = font_glyph(f.font, 0x3042, 20);
	CHECK(g && g->w < 30);
	CHECK_INT(font_cached(f.font), cached + 1);
	/* a space advances and draws nothing */
	g = font_glyph(f.font, ' ', 40);
	CHECK(g && (g->w == 0 || g->h == 0) && g->advance_64 > 0);

	/* enough glyphs to make the cache's table and the atlas grow: all stay right */
	for (uint32_t cp = 0x4e00; cp < 0x4e00 + 600; cp++)
		CHECK(font_glyph(f.font, cp, 24));
	CHECK(f.atlas.w > 256);
	g = font_glyph(f.font, 0x4e00, 24);
	again = font_glyph(f.font, 0x4e00 + 599, 24);
	CHECK(g && again && (g->x != again->x || g->y != again->y));
	CHECK_INT(font_cached(f.font), cached + 2 + 600);

	font_line(f.font, 40, &ascent, &descent);
	CHECK(ascent > 25 && ascent < 50 && descent > 0 && descent < 20);
	close_font(&f);
}

static void test_measure(void)
{
	struct fixture f;
	struct text_extent e, a, b, ab;
	struct batch bt;

	open_font(&f);
	CHECK_INT(text_measure(f.font, "", 30, &e), 0);
	CHECK_INT(e.width, 0);
	CHECK_INT(e.ascent, 0);
	CHECK_INT(e.descent, 0);

	/* the width is the advances' sum */
	CHECK_INT(text_measure(f.font, "a", 30, &a), 0);
	CHECK_INT(text_measure(f.font, "b", 30, &b), 0);
	CHECK_INT(text_measure(f.font, "ab", 30, &ab), 0);
	CHECK(ab.width >= a.width + b.width - 1 && ab.width <= a.width + b.width + 1);
	/* the ink: "b" reaches higher than "a", "g" below the baseline, "a" hardly */
	CHECK(b.ascent > a.ascent);
	CHECK_INT(text_measure(f.font, "g", 30, &e), 0);
	CHECK(e.descent >= 4 && a.descent <= 1);
	/* twice the size, about twice as wide */
	CHECK_INT(text_measure(f.font, "Draw a tree", 20, &a), 0);
	CHECK_INT(text_measure(f.font, "Draw a tree", 40, &b), 0);
	CHECK(b.width > 1.8 * a.width && b.width < 2.2 * a.width);
	/* kana are about an em each */
	CHECK_INT(text_measure(f.font, "ほぞん", 30, &e), 0);
	CHECK(e.width > 2 * 30 && e.width < 3 * 32);
	/* a malformed byte shows as U+FFFD: it takes room, nothing is lost after it */
	CHECK_INT(text_measure(f.font, "a\xff" "b", 30, &e), 0);
	CHECK(e.width > ab.width);

	/* fitting: the size itself when it fits, else the largest that does */
	CHECK_INT(text_fit(f.font, "Saved!", 40, 10, 10000), 40);
	text_measure(f.font, "Saved!", 40, &e);
	{
		int px = text_fit(f.font, "Saved!", 40, 10, 0.5 * e.width);

		CHECK(px < 40 && px > 10);
		text_measure(f.font, "Saved!", px, &a);
		CHECK(a.width <= 0.5 * e.width);
		text_measure(f.font, "Saved!", px + 1, &a);
		CHECK(a.width > 0.5 * e.width);
	}
	CHECK_INT(text_fit(f.font, "Saved!", 40, 10, 1), 10);

	/* set: two triangles an inked glyph at whole pixels, none for a space, sampling the
	 * glyph's texels; its extent is what was measured */
	batch_init(&bt);
	text_draw(&bt, f.font, "a b", 30, 100.4, 200.6, (struct rgba){ 0, 0, 0, 1 });
	CHECK_INT(bt.nvertices, 12);
	text_measure(f.font, "a b", 30, &e);
	for (size_t i = 0; i < bt.nvertices; i++) {
		const float *v = bt.v + i * BATCH_FLOATS_PER_VERTEX;

		CHECK(v[0] == (float)(int)v[0] && v[1] == (float)(int)v[1]);
		CHECK(v[0] >= 100 - 3 && v[0] <= 100 + e.width + 3);
		CHECK(v[1] >= 201 - e.ascent && v[1] <= 201 + e.descent);
		CHECK(v[2] >= 0 && v[2] <= f.atlas.w && v[3] >= 0 && v[3] <= f.atlas.h);
		CHECK(v[2] != BATCH_SOLID_UV || v[3] != BATCH_SOLID_UV);
	}
	batch_finish(&bt);
	close_font(&f);
}

/* Where a button's label is drawn, at a screen size: its size, and the width it may take. */
static void label_place(const struct screen *v, enum button b, int *px, double *room)
{
	struct layout_button lb[LAYOUT_NBUTTONS];
	size_t n = layout_buttons(v, lb, LAYOUT_NBUTTONS);
	struct layout_rect r;

	for (size_t i = 0; i < n; i++) {
		if (lb[i].button == b) {
			*px = render_ui_label_px(lb[i].h);
			*room = render_ui_label_room(lb[i].w);
			return;
		}
	}
	if (b >= BUTTON_TPL_BLANK && b <= BUTTON_TPL_PALM) {
		r = layout_side_slot(v, 0, LAYOUT_SIDE_NAMED_CARDS);
		*px = render_ui_card_label_px(r.h - r.w);
		*room = render_ui_label_room(r.w);
		return;
	}
	/* the side strip's buttons and the front view button */
	r = layout_side_slot(v, 0, LAYOUT_SIDE_BUTTONS);
	*px = render_ui_label_px(r.h);
	*room = render_ui_label_room(r.w);
}

/*
 * Every word in both languages, and that the button labels fit where they are drawn at
 * the kiosk's sizes: at their full size, but for あたらしく in the bar's narrower buttons,
 * which is set a little smaller.
 */
static void test_labels(void)
{
	static const enum render_lang langs[] = { RENDER_LANG_EN, RENDER_LANG_JA };
	static const int sizes[][2] = { { 1280, 800 }, { 800, 480 } };
	struct fixture f;
	struct screen v;
	const char *s;
	size_t n;

	open_font(&f);
	for (size_t l = 0; l < 2; l++) {
		for (size_t z = 0; z < sizeof(sizes) / sizeof(sizes[0]); z++) {
			int px;
			double room;

			screen_init(&v, sizes[z][0], sizes[z][1]);
			label_place(&v, BUTTON_3D, &px, &room);
			if (z == 0)
				CHECK(px >= 20); /* 13 mm on a kiosk screen 50 cm tall */
			for (int b = 0; b < BUTTON_COUNT; b++) {
				struct text_extent e;
				bool smaller = langs[l] == RENDER_LANG_JA && b == BUTTON_NEW;
				int fit;

				s = labels_button((enum button)b, langs[l]);
				CHECK(s && s[0]);
				label_place(&v, (enum button)b, &px, &room);
				fit = text_fit(f.font, s, px, 1, room);
				CHECK_INT(text_measure(f.font, s, fit, &e), 0);
				if (e.width > room || (fit < px && !smaller))
					fprintf(stderr, "label \"%s\" at %dx%d: %d px at %d px, room %.0f\n",
						s, sizes[z][0], sizes[z][1], e.width, fit, room);
				CHECK(e.width <= room);
				CHECK(smaller ? fit >= 0.8 * px : fit == px);
			}
		}
		for (int st = APP_STATUS_NONE + 1; st < APP_STATUS_COUNT; st++) {
			s = labels_status((enum app_status)st, langs[l]);
			CHECK(s && s[0]);
		}
		CHECK(labels_status(APP_STATUS_NONE, langs[l]) == NULL);
		CHECK(labels_status(APP_STATUS_COUNT, langs[l]) == NULL);
		/* the forest's number in its place, the digits in the font; a message without
		 * '#' as it is; too little room refused, never cut */
		{
			char buf[160];

			CHECK_INT(labels_format(APP_STATUS_IN_FOREST, langs[l], 12, buf, sizeof(buf)), 0);
			CHECK(strstr(buf, "12") && !strchr(buf, '#'));
			CHECK(strlen(buf) == strlen(labels_status(APP_STATUS_IN_FOREST, langs[l])) + 1);
			CHECK_INT(labels_format(APP_STATUS_IN_FOREST, langs[l], 999999, buf, sizeof(buf)), 0);
			CHECK(strstr(buf, "999999"));
			CHECK_INT(labels_format(APP_STATUS_SAVED, langs[l], 12, buf, sizeof(buf)), 0);
			CHECK(!strcmp(buf, labels_status(APP_STATUS_SAVED, langs[l])));
			CHECK_INT(labels_format(APP_STATUS_IN_FOREST, langs[l], 12, buf, 8), -ENOSPC);
			CHECK_INT(labels_format(APP_STATUS_NONE, langs[l], 12, buf, sizeof(buf)), -EINVAL);
			for (const char *d = "0123456789"; *d; d++)
				CHECK(font_has(f.font, (uint32_t)*d));
		}
		CHECK(labels_attract(langs[l])[0]);
		/* the list covers all of them, and the font has every character */
		for (n = 0; (s = labels_nth(langs[l], n)); n++) {
			size_t len = strlen(s), i = 0;

			while (i < len) {
				uint32_t cp = utf8_next(s, len, &i);

				CHECK(cp != UTF8_REPLACEMENT);
				CHECK(cp == ' ' || font_has(f.font, cp));
			}
		}
		CHECK_INT(n, BUTTON_COUNT + APP_STATUS_COUNT - 1 + 1);
	}
	/* the languages differ, and Japanese is not ASCII */
	CHECK(strcmp(labels_button(BUTTON_3D, RENDER_LANG_EN), labels_button(BUTTON_3D, RENDER_LANG_JA)));
	CHECK((unsigned char)labels_button(BUTTON_LEAF, RENDER_LANG_JA)[0] >= 0x80);
	close_font(&f);
}

int main(void)
{
	test_utf8();
	test_atlas();
	test_font();
	test_measure();
	test_labels();
	return 0;
}
