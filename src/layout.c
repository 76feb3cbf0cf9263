/* SPDX-License-Identifier: MIT */
#include "layout.h"

#include <math.h>

static const enum button bar_order[LAYOUT_NBUTTONS] = {
	BUTTON_3D, BUTTON_CLONE, BUTTON_LEAF, BUTTON_PROPAGATE, /* modes, at the top */
	BUTTON_UNDO, BUTTON_REDO, BUTTON_NEW, BUTTON_EXPORT,     /* actions, at the bottom */
};

/* How many of bar_order are in the top group. */
#define LAYOUT_NTOP 4

/*
 * A button's height is a fraction of the screen height, so the bar looks the same at any
 * resolution: ~5 cm on a kiosk screen 50 cm tall. It is over half as wide again: room for
 * an icon with a label under it that reads from a metre away (あたらしく, the longest).
 * On a narrow screen the width limits it so the canvas keeps most of the screen. Spacing
 * follows the button size.
 */
#define BUTTON_OF_HEIGHT 0.10
#define BUTTON_OF_WIDTH 0.15
#define WIDTH_OF_BUTTON 1.55 /* width : height */
#define MARGIN_OF_BUTTON 0.2 /* bar edge to button */
#define GAP_OF_BUTTON 0.15   /* between buttons of a group */

struct metrics {
	double size;   /* button height */
	double wide;   /* button width */
	double margin; /* bar edge to button */
	double gap;    /* between buttons of a group */
	double bar_x;  /* left edge of the bar */
};

/* Whole pixels, so edges land on pixel boundaries and stay crisp. */
static struct metrics metrics(const struct view *v)
{
	double h = v->height > 0 ? v->height : 0;
	double w = v->width > 0 ? v->width : 0;
	struct metrics m;

	m.size = fmax(1.0, round(fmin(BUTTON_OF_HEIGHT * h, BUTTON_OF_WIDTH * w)));
	m.wide = round(WIDTH_OF_BUTTON * m.size);
	m.margin = round(MARGIN_OF_BUTTON * m.size);
	m.gap = round(GAP_OF_BUTTON * m.size);
	m.bar_x = w - (m.wide + 2.0 * m.margin);
	return m;
}

static void button_rect(const struct view *v, const struct metrics *m, size_t i,
			struct layout_button *b)
{
	b->button = bar_order[i];
	b->x = m->bar_x + m->margin;
	b->w = m->wide;
	b->h = m->size;
	if (i < LAYOUT_NTOP) {
		b->y = m->margin + (double)i * (m->size + m->gap);
	} else {
		/* counted up from the bottom edge */
		double below = (double)(LAYOUT_NBUTTONS - i);

		b->y = v->height - m->margin - below * m->size - (below - 1.0) * m->gap;
	}
}

size_t layout_buttons(const struct view *v, struct layout_button *out, size_t max)
{
	struct metrics m = metrics(v);

	for (size_t i = 0; i < LAYOUT_NBUTTONS && i < max; i++)
		button_rect(v, &m, i, &out[i]);
	return LAYOUT_NBUTTONS;
}

bool layout_hit(const struct view *v, double x, double y, enum button *button)
{
	struct metrics m = metrics(v);
	double pad = 0.5 * m.gap;

	if (x < m.bar_x || x >= v->width || y < 0.0 || y >= v->height)
		return false;
	for (size_t i = 0; i < LAYOUT_NBUTTONS; i++) {
		struct layout_button b;

		button_rect(v, &m, i, &b);
		/* the whole bar width counts: a pen landing on the bar's rim still hits */
		if (y >= b.y - pad && y < b.y + b.h + pad) {
			*button = b.button;
			return true;
		}
	}
	return false;
}

struct layout_button layout_view_button(const struct view *v)
{
	struct metrics m = metrics(v);

	return (struct layout_button){ BUTTON_VIEW, m.margin, v->height - m.margin - m.size, m.wide,
				       m.size };
}

bool layout_hit_view_button(const struct view *v, double x, double y)
{
	struct layout_button b = layout_view_button(v);
	double pad = 0.5 * metrics(v).gap;

	return x >= b.x - pad && x < b.x + b.w + pad && y >= b.y - pad && y < b.y + b.h + pad;
}

#define THUMB_OF_BUTTON 1.6

struct layout_rect layout_side_slot(const struct view *v, size_t i, bool thumbnail)
{
	struct metrics m = metrics(v);
	double side = thumbnail ? round(THUMB_OF_BUTTON * m.size) : m.size;
	double wide = thumbnail ? side : m.wide;

	return (struct layout_rect){ m.margin, m.margin + (double)i * (side + m.gap), wide, side };
}

bool layout_side_hit(const struct view *v, double x, double y, size_t n, bool thumbnail,
		     size_t *slot)
{
	double pad = 0.5 * metrics(v).gap;

	for (size_t i = 0; i < n; i++) {
		struct layout_rect r = layout_side_slot(v, i, thumbnail);

		if (x >= r.x - pad && x < r.x + r.w + pad && y >= r.y - pad && y < r.y + r.h + pad) {
			*slot = i;
			return true;
		}
	}
	return false;
}

struct layout_rect layout_bar(const struct view *v)
{
	struct metrics m = metrics(v);

	return (struct layout_rect){ m.bar_x, 0.0, v->width - m.bar_x, v->height };
}

struct layout_rect layout_canvas(const struct view *v)
{
	struct metrics m = metrics(v);

	return (struct layout_rect){ 0.0, 0.0, fmax(0.0, m.bar_x), v->height };
}
