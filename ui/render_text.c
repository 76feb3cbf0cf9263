/* SPDX-License-Identifier: MIT */
/* The text atlas's GL texture, and the font and language the 2D layers write with. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "font.h"
#include "labels.h"
#include "render_private.h"
#include "utf8.h"

/* Room for the labels at a 1280x800 screen's sizes with space to spare; it grows (up to
 * ATLAS_MAX_SIDE, or what GL allows) for bigger screens. */
#define ATLAS_START_SIDE 512
#define ATLAS_MAX_SIDE 4096

static int start_side(const struct render *r)
{
	return r->atlas_max < ATLAS_START_SIDE ? r->atlas_max : ATLAS_START_SIDE;
}

int render_text_init(struct render *r)
{
	GLint max = 0;

	/* the largest power of two GL allows, up to ATLAS_MAX_SIDE; GLES 2 promises 64 */
	glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max);
	r->atlas_max = 64;
	while (r->atlas_max < ATLAS_MAX_SIDE && 2 * r->atlas_max <= max)
		r->atlas_max *= 2;
	if (atlas_init(&r->atlas, start_side(r), r->atlas_max) < 0) {
		fputs("render: out of memory for the text atlas\n", stderr);
		return -ENOMEM;
	}
	glGenTextures(1, &r->atlas_texture);
	glBindTexture(GL_TEXTURE_2D, r->atlas_texture);
	/* glyphs are drawn texel for texel; linear only matters off the pixel grid */
	glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
	glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
	glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
	glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
	glBindTexture(GL_TEXTURE_2D, 0);
	return 0;
}

void render_text_finish(struct render *r)
{
	font_destroy(r->text.font);
	r->text.font = NULL;
	glDeleteTextures(1, &r->atlas_texture);
	r->atlas_texture = 0;
	atlas_finish(&r->atlas);
}

int render_text_sync(struct render *r)
{
	struct atlas *a = &r->atlas;

	if (!a->pixels)
		return -ENOMEM;
	glActiveTexture(GL_TEXTURE0);
	glBindTexture(GL_TEXTURE_2D, r->atlas_texture);
	glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
	if (a->resized)
		glTexImage2D(GL_TEXTURE_2D, 0, GL_ALPHA, a->w, a->h, 0, GL_ALPHA, GL_UNSIGNED_BYTE,
			     a->pixels);
	else if (a->dirty_y1 > a->dirty_y0)
		/* whole rows: they are contiguous in the atlas */
		glTexSubImage2D(GL_TEXTURE_2D, 0, 0, a->dirty_y0, a->w, a->dirty_y1 - a->dirty_y0,
				GL_ALPHA, GL_UNSIGNED_BYTE,
				a->pixels + (size_t)a->dirty_y0 * (size_t)a->w);
	glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
	atlas_clean(a);
	return 0;
}

/* Says which characters of the language's words the face lacks (once each). */
static void check_coverage(const struct font *f, enum render_lang lang)
{
	uint32_t told[16];
	size_t ntold = 0;
	const char *s;

	for (size_t i = 0; (s = labels_nth(lang, i)); i++) {
		size_t len = strlen(s), pos = 0;

		while (pos < len) {
			uint32_t cp = utf8_next(s, len, &pos);
			bool seen = false;

			if (cp == ' ' || font_has(f, cp))
				continue;
			for (size_t k = 0; k < ntold; k++)
				seen = seen || told[k] == cp;
			if (seen)
				continue;
			if (ntold < sizeof(told) / sizeof(told[0]))
				told[ntold++] = cp;
			fprintf(stderr, "render: warning: the font has no glyph for U+%04X (in \"%s\")\n",
				(unsigned)cp, s);
		}
	}
}

int render_set_text(struct render *r, const void *font, size_t len, enum render_lang lang)
{
	struct font *f = NULL;
	int ret = 0;

	r->text.lang = lang;
	font_destroy(r->text.font);
	r->text.font = NULL;
	/* a fresh atlas: the old face's glyphs are of no more use */
	atlas_finish(&r->atlas);
	if (atlas_init(&r->atlas, start_side(r), r->atlas_max) < 0)
		return -ENOMEM;
	if (!font)
		return 0;
	ret = font_create(&f, font, len, &r->atlas);
	if (ret < 0) {
		fprintf(stderr, "render: %s\n",
			ret == -ENOMEM ? "out of memory for the font" : "FreeType cannot read the font");
		return ret;
	}
	check_coverage(f, lang);
	r->text.font = f;
	return 0;
}
