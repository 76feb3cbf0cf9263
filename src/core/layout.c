/* SPDX-License-Identifier: MIT */
#include "layout.h"

#include <math.h>

static const enum button kiosk_buttons[LAYOUT_NBUTTONS] = {
	/* tree tools, in pairs from the top: 3D | clone, leaf | spread, season | vine, grow
	 * (the fourth row's left place, under season; its right one stays empty) */
	BUTTON_3D, BUTTON_CLONE, BUTTON_LEAF, BUTTON_PROPAGATE, BUTTON_SEASON, BUTTON_VINE,
	BUTTON_GROW,
	/* actions, in pairs up from the bottom: undo | redo over new | save */
	BUTTON_UNDO, BUTTON_REDO, BUTTON_NEW, BUTTON_EXPORT,
};

const struct layout_bar_list layout_kiosk_bar = { kiosk_buttons, LAYOUT_NBUTTONS, 7 };

/*
 * Sizes follow the button height, a fraction of the screen height, so the screen looks the
 * same at any resolution: 80 px at 1280x800 (13.5 mm on a 10-inch screen), 48 px at 800x480
 * (9.2 mm on a 7-inch one). On a narrow screen the width limits it so the canvas keeps most
 * of the screen.
 *
 * The bar's buttons are a quarter wider than tall: room for an icon over a four-kana label
 * (ひろげる) at the full label size; two columns of them leave 82% of a 1280x800 screen's
 * width to the canvas, and its left edge (1044) right of every stroke of the recorded
 * traces (tests/data: 1000 at most). The side strip's buttons and the front view button
 * are as wide as the bar's were (1.55), for the longer words of the parameter buttons
 * ("Narrower"); its margins and gaps are the bar's old ones, so its first places are
 * where the traces tap them.
 */
#define BUTTON_OF_HEIGHT 0.10
#define BUTTON_OF_WIDTH 0.09
#define BAR_WIDTH_OF_BUTTON 1.25 /* width : height */
#define BAR_SPACE_OF_BUTTON 0.15 /* bar edge, screen edge, between buttons */
#define SIDE_WIDTH_OF_BUTTON 1.55
#define SIDE_MARGIN_OF_BUTTON 0.2 /* canvas edge to button */
#define SIDE_GAP_OF_BUTTON 0.15
#define CARD_OF_BUTTON 1.6
#define CARD_NAME_OF_BUTTON 0.34 /* the band of a named card's word */

struct metrics {
	double size;      /* button height */
	double bar_wide;  /* a bar button's width */
	double bar_space; /* the bar's margins and gaps */
	double bar_x;     /* left edge of the bar */
	double wide;      /* a side button's width */
	double margin;    /* canvas edge to the side strip */
	double gap;       /* between side places */
	double card, name; /* a card's side, a named card's band */
};

/* Whole pixels, so edges land on pixel boundaries and stay crisp. */
static struct metrics metrics(const struct screen *v)
{
	double h = v->height > 0 ? v->height : 0;
	double w = v->width > 0 ? v->width : 0;
	struct metrics m;

	m.size = fmax(1.0, round(fmin(BUTTON_OF_HEIGHT * h, BUTTON_OF_WIDTH * w)));
	m.bar_wide = round(BAR_WIDTH_OF_BUTTON * m.size);
	m.bar_space = round(BAR_SPACE_OF_BUTTON * m.size);
	m.bar_x = w - (2.0 * m.bar_wide + 3.0 * m.bar_space);
	m.wide = round(SIDE_WIDTH_OF_BUTTON * m.size);
	m.margin = round(SIDE_MARGIN_OF_BUTTON * m.size);
	m.gap = round(SIDE_GAP_OF_BUTTON * m.size);
	m.card = round(CARD_OF_BUTTON * m.size);
	m.name = round(CARD_NAME_OF_BUTTON * m.size);
	return m;
}

static const struct layout_bar_list *bar_list(const struct layout_bar_list *list)
{
	return list ? list : &layout_kiosk_bar;
}

static bool bar_fits(const struct layout_bar_list *l)
{
	return l->ntools <= l->n && l->ntools <= 2 * LAYOUT_TOOL_ROWS &&
	       l->n - l->ntools <= 2 * LAYOUT_ACTION_ROWS;
}

/* Button i of a list that fits: its column, its row from the top, and the target. */
static void bar_button(const struct screen *v, const struct metrics *m,
		       const struct layout_bar_list *l, size_t i, struct layout_button *b)
{
	double half = 0.5 * m->bar_space, split = m->bar_x + m->bar_space + m->bar_wide + half;
	size_t col = i < l->ntools ? i % 2 : (i - l->ntools) % 2;
	bool top_row, bottom_row;

	b->button = l->buttons[i];
	b->x = m->bar_x + m->bar_space + (double)col * (m->bar_wide + m->bar_space);
	b->w = m->bar_wide;
	b->h = m->size;
	if (i < l->ntools) {
		size_t row = i / 2;

		b->y = m->bar_space + (double)row * (m->size + m->bar_space);
		top_row = row == 0;
		bottom_row = false;
	} else {
		size_t rows = (l->n - l->ntools + 1) / 2, row = (i - l->ntools) / 2;
		/* counted up from the bottom edge */
		double below = (double)(rows - row);

		b->y = v->height - m->bar_space - below * m->size - (below - 1.0) * m->bar_space;
		top_row = false;
		bottom_row = row + 1 == rows;
	}
	/* the screen's edges and the bar's rim belong to the buttons beside them */
	b->target.x = col == 0 ? m->bar_x : split;
	b->target.w = col == 0 ? split - m->bar_x : v->width - split;
	b->target.y = top_row ? 0.0 : b->y - half;
	b->target.h = (bottom_row ? v->height : b->y + b->h + half) - b->target.y;
}

size_t layout_bar_buttons(const struct screen *v, const struct layout_bar_list *list,
			  struct layout_button *out, size_t max)
{
	const struct layout_bar_list *l = bar_list(list);
	struct metrics m = metrics(v);

	if (!bar_fits(l))
		return 0;
	for (size_t i = 0; i < l->n && i < max; i++)
		bar_button(v, &m, l, i, &out[i]);
	return l->n;
}

static bool inside(const struct layout_rect *r, double x, double y)
{
	return x >= r->x && x < r->x + r->w && y >= r->y && y < r->y + r->h;
}

bool layout_bar_hit(const struct screen *v, const struct layout_bar_list *list, double x, double y,
		    size_t *index)
{
	const struct layout_bar_list *l = bar_list(list);
	struct metrics m = metrics(v);

	if (!bar_fits(l) || x < m.bar_x || x >= v->width || y < 0.0 || y >= v->height)
		return false;
	for (size_t i = 0; i < l->n; i++) {
		struct layout_button b;

		bar_button(v, &m, l, i, &b);
		if (inside(&b.target, x, y)) {
			*index = i;
			return true;
		}
	}
	return false;
}

size_t layout_buttons(const struct screen *v, struct layout_button *out, size_t max)
{
	return layout_bar_buttons(v, NULL, out, max);
}

bool layout_hit(const struct screen *v, double x, double y, enum button *button)
{
	size_t i;

	if (!layout_bar_hit(v, NULL, x, y, &i))
		return false;
	*button = layout_kiosk_bar.buttons[i];
	return true;
}

static struct layout_rect padded(struct layout_rect r, double pad)
{
	return (struct layout_rect){ r.x - pad, r.y - pad, r.w + 2.0 * pad, r.h + 2.0 * pad };
}

struct layout_button layout_view_button(const struct screen *v)
{
	struct metrics m = metrics(v);
	struct layout_rect r = { m.margin, v->height - m.margin - m.size, m.wide, m.size };

	return (struct layout_button){ BUTTON_VIEW, r.x, r.y, r.w, r.h, padded(r, 0.5 * m.gap) };
}

bool layout_hit_view_button(const struct screen *v, double x, double y)
{
	struct layout_button b = layout_view_button(v);

	return inside(&b.target, x, y);
}

/* How many cards a column holds: those that end above the front view button. */
static size_t card_rows(const struct screen *v, const struct metrics *m, double card_h)
{
	double bottom = v->height - m->margin - m->size - m->gap;
	double rows = floor((bottom - m->margin + m->gap) / (card_h + m->gap));

	return rows >= 1.0 ? (size_t)rows : 1;
}

struct layout_rect layout_side_slot(const struct screen *v, size_t i, enum layout_side_kind kind)
{
	struct metrics m = metrics(v);
	double w, h;
	size_t row, col;

	if (kind == LAYOUT_SIDE_BUTTONS) {
		w = m.wide;
		h = m.size;
		row = i / 2;
		col = i % 2;
	} else {
		size_t rows;

		w = m.card;
		h = m.card + (kind == LAYOUT_SIDE_NAMED_CARDS ? m.name : 0.0);
		rows = card_rows(v, &m, h);
		row = i % rows;
		col = i / rows;
	}
	return (struct layout_rect){ m.margin + (double)col * (w + m.gap),
				     m.margin + (double)row * (h + m.gap), w, h };
}

struct layout_rect layout_side_target(const struct screen *v, size_t i, enum layout_side_kind kind)
{
	struct metrics m = metrics(v);
	struct layout_rect s = layout_side_slot(v, i, kind);
	struct layout_rect t = padded(s, 0.5 * m.gap);

	/* the first column and row reach the screen's edges */
	if (s.x <= m.margin) {
		t.w += t.x;
		t.x = 0.0;
	}
	if (s.y <= m.margin) {
		t.h += t.y;
		t.y = 0.0;
	}
	return t;
}

bool layout_side_hit(const struct screen *v, double x, double y, size_t n,
		     enum layout_side_kind kind, size_t *slot)
{
	for (size_t i = 0; i < n; i++) {
		struct layout_rect t = layout_side_target(v, i, kind);

		if (inside(&t, x, y)) {
			*slot = i;
			return true;
		}
	}
	return false;
}

struct layout_rect layout_card_picture(struct layout_rect card, enum layout_side_kind kind)
{
	if (kind == LAYOUT_SIDE_NAMED_CARDS)
		card.h = card.w;
	return card;
}

struct layout_rect layout_bar(const struct screen *v)
{
	struct metrics m = metrics(v);

	return (struct layout_rect){ m.bar_x, 0.0, v->width - m.bar_x, v->height };
}

struct layout_rect layout_canvas(const struct screen *v)
{
	struct metrics m = metrics(v);

	return (struct layout_rect){ 0.0, 0.0, fmax(0.0, m.bar_x), v->height };
}
