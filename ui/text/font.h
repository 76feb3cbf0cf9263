/* SPDX-License-Identifier: MIT */
#pragma once

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "atlas.h"

/*
 * A font file's face, through FreeType, with its glyphs rasterised (grey, lightly
 * hinted) into an atlas the first time each is asked for at a size and cached after:
 * what the labels need a frame costs table lookups. No I/O: the file's bytes come from
 * platform/.
 */
struct font;

struct font_glyph {
	int x, y, w, h;  /* the bitmap in the atlas (w or h 0: nothing to draw, a space) */
	int left, top;   /* from the pen position on the baseline to the bitmap's top left:
			  * right, up */
	int advance_64;  /* to the next pen position, 1/64 pixel */
};

/*
 * A face from the bytes of a TrueType/OpenType file (copied) whose glyphs go into atlas
 * (which must outlive the font). 0; -EINVAL if FreeType cannot read it; -ENOMEM.
 */
int font_create(struct font **out, const void *data, size_t len, struct atlas *atlas);
void font_destroy(struct font *f);

/*
 * Code point cp at px pixels to the em (1..FONT_MAX_PX). The face's .notdef for a
 * character it lacks. NULL if it cannot be rasterised or stored (no memory, atlas full).
 */
#define FONT_MAX_PX 512
const struct font_glyph *font_glyph(struct font *f, uint32_t cp, int px);

/* Whether the face has a glyph of its own for cp. */
bool font_has(const struct font *f, uint32_t cp);

/* How far the face's lines reach above and below the baseline at px (pixels, >= 0). */
void font_line(const struct font *f, int px, int *ascent, int *descent);

/* Glyphs rasterised so far (tests, benchmarks). */
size_t font_cached(const struct font *f);
