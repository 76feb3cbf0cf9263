/* SPDX-License-Identifier: MIT */
#pragma once

#include <stdbool.h>
#include <stdint.h>

/*
 * A coverage image (one byte a texel) that small images are packed into, in rows
 * ("shelves"): the glyphs of the on-screen text. It grows, doubling, up to a limit,
 * keeping what it holds where it was: positions are in texels, so they stay valid. The
 * renderer copies it into a GL texture, uploading only the rows that changed. Its top
 * left 4x4 texels are solid (BATCH_SOLID_UV samples them): flat-coloured triangles and
 * glyphs share one texture and one draw call. No GL here.
 */
struct atlas {
	uint8_t *pixels; /* w * h, row by row from the top */
	int w, h, max;
	int shelf_x, shelf_y, shelf_h; /* the row being filled */
	int dirty_y0, dirty_y1;        /* rows changed since atlas_clean: [y0, y1) */
	bool resized;                  /* grown since atlas_clean: upload all of it */
};

/* size: the starting side (a power of two, 8..max); max: the largest side. 0, -EINVAL or
 * -ENOMEM. */
int atlas_init(struct atlas *a, int size, int max);
void atlas_finish(struct atlas *a);

/*
 * Copies a w x h image (rows pitch bytes apart) in, with a blank texel around it so that
 * linear filtering never bleeds, and returns its top left in *x, *y. 0; -ENOSPC when it
 * does not fit even at max; -ENOMEM; -EINVAL for a negative size.
 */
int atlas_add(struct atlas *a, const uint8_t *src, int w, int h, int pitch, int *x, int *y);

/* The GL copy is up to date. */
void atlas_clean(struct atlas *a);
