/* SPDX-License-Identifier: MIT */
#include "font.h"

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H

/*
 * Strokes are thickened by 1/EMBOLDEN_OF_EM of the em: a medium weight from a regular
 * face, the thin strokes of kana and of small Latin letters read from a metre away.
 */
#define EMBOLDEN_OF_EM 22

/* Glyphs are looked up by (code point, size) in an open-addressed table. */
struct slot {
	uint32_t cp;
	uint16_t px; /* 0: empty */
	struct font_glyph g;
};

struct font {
	FT_Library lib;
	FT_Face face;
	unsigned char *data; /* FreeType reads the face from here while it lives */
	struct atlas *atlas;
	struct slot *slots;
	size_t nslots, used; /* nslots a power of two */
	int face_px;         /* the size the face is set to, 0 if none */
};

int font_create(struct font **out, const void *data, size_t len, struct atlas *atlas)
{
	struct font *f = calloc(1, sizeof(*f));
	int ret = -ENOMEM;

	*out = NULL;
	if (!f)
		return -ENOMEM;
	f->atlas = atlas;
	f->nslots = 256;
	f->slots = calloc(f->nslots, sizeof(*f->slots));
	f->data = malloc(len ? len : 1);
	if (!f->slots || !f->data)
		goto fail;
	memcpy(f->data, data, len);
	if (len > (size_t)LONG_MAX) {
		ret = -EINVAL;
		goto fail;
	}
	if (FT_Init_FreeType(&f->lib)) {
		f->lib = NULL;
		goto fail;
	}
	if (FT_New_Memory_Face(f->lib, f->data, (FT_Long)len, 0, &f->face)) {
		f->face = NULL;
		ret = -EINVAL;
		goto fail;
	}
	/* only scalable faces with a Unicode map: labels are drawn at sizes of our choosing */
	if (!FT_IS_SCALABLE(f->face) || FT_Select_Charmap(f->face, FT_ENCODING_UNICODE)) {
		ret = -EINVAL;
		goto fail;
	}
	*out = f;
	return 0;
fail:
	font_destroy(f);
	return ret;
}

void font_destroy(struct font *f)
{
	if (!f)
		return;
	if (f->face)
		FT_Done_Face(f->face);
	if (f->lib)
		FT_Done_FreeType(f->lib);
	free(f->data);
	free(f->slots);
	free(f);
}

static size_t hash(uint32_t cp, int px, size_t mask)
{
	uint64_t k = ((uint64_t)cp << 16 | (uint64_t)px) * 0x9e3779b97f4a7c15u;

	return (size_t)(k >> 32) & mask;
}

static struct slot *find(const struct font *f, uint32_t cp, int px)
{
	size_t mask = f->nslots - 1;

	for (size_t i = hash(cp, px, mask);; i = (i + 1) & mask) {
		struct slot *s = &f->slots[i];

		if (s->px == 0 || (s->cp == cp && s->px == px))
			return s;
	}
}

static int grow_table(struct font *f)
{
	struct slot *old = f->slots;
	size_t n = f->nslots;

	f->slots = calloc(2 * n, sizeof(*f->slots));
	if (!f->slots) {
		f->slots = old;
		return -ENOMEM;
	}
	f->nslots = 2 * n;
	for (size_t i = 0; i < n; i++)
		if (old[i].px)
			*find(f, old[i].cp, old[i].px) = old[i];
	free(old);
	return 0;
}

static int rasterise(struct font *f, uint32_t cp, int px, struct font_glyph *g)
{
	FT_GlyphSlot gs;
	FT_Bitmap *bm;

	if (f->face_px != px) {
		if (FT_Set_Pixel_Sizes(f->face, 0, (FT_UInt)px))
			return -EINVAL;
		f->face_px = px;
	}
	/* light hinting: crisp horizontal stems, shapes and spacing as designed */
	if (FT_Load_Char(f->face, cp, FT_LOAD_TARGET_LIGHT))
		return -EINVAL;
	gs = f->face->glyph;
	memset(g, 0, sizeof(*g));
	g->advance_64 = (int)gs->advance.x;
	if (gs->format == FT_GLYPH_FORMAT_OUTLINE) {
		FT_Pos strength = (FT_Pos)px * 64 / EMBOLDEN_OF_EM;

		/* it grows by strength across: the advance makes room for it */
		if (FT_Outline_Embolden(&gs->outline, strength))
			return -EINVAL;
		g->advance_64 += (int)strength;
	}
	if (FT_Render_Glyph(gs, FT_RENDER_MODE_LIGHT))
		return -EINVAL;
	bm = &gs->bitmap;
	g->left = gs->bitmap_left;
	g->top = gs->bitmap_top;
	if (bm->width == 0 || bm->rows == 0)
		return 0;
	if (bm->pixel_mode != FT_PIXEL_MODE_GRAY || bm->pitch < 0)
		return -EINVAL;
	g->w = (int)bm->width;
	g->h = (int)bm->rows;
	return atlas_add(f->atlas, bm->buffer, g->w, g->h, bm->pitch, &g->x, &g->y);
}

const struct font_glyph *font_glyph(struct font *f, uint32_t cp, int px)
{
	struct slot *s;

	if (px < 1 || px > FONT_MAX_PX)
		return NULL;
	s = find(f, cp, px);
	if (s->px)
		return &s->g;
	/* at most 3/4 full, so that probes stay short and always end */
	if (4 * (f->used + 1) > 3 * f->nslots) {
		if (grow_table(f) < 0)
			return NULL;
		s = find(f, cp, px);
	}
	if (rasterise(f, cp, px, &s->g) < 0)
		return NULL;
	s->cp = cp;
	s->px = (uint16_t)px;
	f->used++;
	return &s->g;
}

bool font_has(const struct font *f, uint32_t cp)
{
	return FT_Get_Char_Index(f->face, cp) != 0;
}

void font_line(const struct font *f, int px, int *ascent, int *descent)
{
	double k = (double)px / (double)f->face->units_per_EM;

	*ascent = (int)ceil(fmax(0.0, (double)f->face->ascender * k));
	*descent = (int)ceil(fmax(0.0, -(double)f->face->descender * k));
}

size_t font_cached(const struct font *f)
{
	return f->used;
}
