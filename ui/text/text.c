/* SPDX-License-Identifier: MIT */
#include "text.h"

#include <errno.h>
#include <math.h>
#include <string.h>

#include "utf8.h"

int text_measure(struct font *f, const char *s, int px, struct text_extent *e)
{
	size_t len = strlen(s), i = 0;
	int pen_64 = 0, ret = 0;
	bool ink = false;

	memset(e, 0, sizeof(*e));
	while (i < len) {
		const struct font_glyph *g = font_glyph(f, utf8_next(s, len, &i), px);

		if (!g) {
			ret = -ENOMEM;
			continue;
		}
		if (g->w > 0 && g->h > 0) {
			int up = g->top, down = g->h - g->top;

			if (!ink || up > e->ascent)
				e->ascent = up;
			if (!ink || down > e->descent)
				e->descent = down;
			ink = true;
		}
		pen_64 += g->advance_64;
	}
	e->width = (pen_64 + 32) >> 6;
	if (e->ascent < 0)
		e->ascent = 0;
	if (e->descent < 0)
		e->descent = 0;
	return ret;
}

int text_fit(struct font *f, const char *s, int px, int min_px, double max_width)
{
	struct text_extent e;

	for (; px > min_px; px--) {
		text_measure(f, s, px, &e);
		if (e.width <= max_width)
			break;
	}
	return px > min_px ? px : min_px;
}

void text_draw(struct batch *b, struct font *f, const char *s, int px, double x,
	       double baseline, struct rgba c)
{
	size_t len = strlen(s), i = 0;
	double x0 = round(x), y0 = round(baseline);
	int pen_64 = 0;

	while (i < len) {
		const struct font_glyph *g = font_glyph(f, utf8_next(s, len, &i), px);

		if (!g)
			continue;
		if (g->w > 0 && g->h > 0)
			batch_image(b, x0 + ((pen_64 + 32) >> 6) + g->left, y0 - g->top, g->w, g->h,
				    g->x, g->y, c);
		pen_64 += g->advance_64;
	}
}
