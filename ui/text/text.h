/* SPDX-License-Identifier: MIT */
#pragma once

#include "batch.h"
#include "font.h"

/*
 * A line of UTF-8 text set left to right, glyph after glyph at its advance (no shaping:
 * enough for English and for Japanese kana and kanji), each glyph at a whole pixel so
 * that it is drawn texel for texel from the atlas, crisp.
 */

struct text_extent {
	int width;   /* from the first pen position to the last: what to centre on */
	int ascent;  /* the ink's reach above the baseline and below it (>= 0; 0 if none) */
	int descent;
};

/* The extent of s at px pixels to the em. 0, or -ENOMEM if a glyph could not be
 * rasterised (it counts as nothing). */
int text_measure(struct font *f, const char *s, int px, struct text_extent *e);

/* The largest size from px down to min_px at which s is at most max_width wide (min_px if
 * none is). */
int text_fit(struct font *f, const char *s, int px, int min_px, double max_width);

/* Draws s with its first pen position at (x, baseline), rounded to whole pixels. */
void text_draw(struct batch *b, struct font *f, const char *s, int px, double x,
	       double baseline, struct rgba c);
