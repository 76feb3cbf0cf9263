/* SPDX-License-Identifier: MIT */
#pragma once

#include <stdbool.h>
#include <stddef.h>

#include "event.h"
#include "screen.h"

/*
 * Where the on-screen buttons are. Pure geometry in screen pixels (origin top left, y
 * down): the renderer draws from it and the app hit-tests taps with it, so both always
 * agree.
 *
 * The bar, along the right edge of the screen, holds its buttons in two columns: the tree
 * tools in pairs from the top (3D | clone, leaf | spread, season | vine, grow), the
 * actions in pairs from the bottom (undo | redo, new | save), with the rows between them
 * left empty so the two kinds read apart. Two columns because eleven buttons in one would
 * give each less than 9 mm on a 7-inch 800x480 screen, where the screen is 92 mm tall.
 * The bar's width is the same whatever it holds, so buttons added to a group take its
 * empty places and nothing else moves.
 *
 * The side strip, along the canvas's left edge, shows what the active mode offers:
 * buttons in pairs, row by row (the parameter buttons, the propagation patterns), or
 * cards with a picture (thumbnails) down a column and on into the next (the leaf
 * suggestions, the New strip's trees).
 *
 * Every button has a target, the area a tap hits: what is drawn and half the gap around it,
 * to the screen's edge where it is the last thing before it.
 */

/* Buttons in the kiosk's bar. */
#define LAYOUT_NBUTTONS 11
/* Rows of the bar: the tree tools' from the top, the actions' from the bottom. */
#define LAYOUT_TOOL_ROWS 4
#define LAYOUT_ACTION_ROWS 2
#define LAYOUT_BAR_MAX (2 * (LAYOUT_TOOL_ROWS + LAYOUT_ACTION_ROWS))

struct layout_rect {
	double x, y, w, h;
};

struct layout_button {
	enum button button;
	double x, y, w, h;         /* the visible button */
	struct layout_rect target; /* where a tap presses it */
};

/*
 * What a bar holds: buttons[0..ntools) are the tree tools, left to right and top to
 * bottom from the top, the rest the actions likewise, their last row at the bottom. At
 * most 2 * LAYOUT_TOOL_ROWS tools and 2 * LAYOUT_ACTION_ROWS actions.
 */
struct layout_bar_list {
	const enum button *buttons;
	size_t n, ntools;
};
/* The kiosk's: 3D, clone, leaf, propagate, season, vine, grow; undo, redo, new, export. */
extern const struct layout_bar_list layout_kiosk_bar;

/*
 * Fills out[0..max) with the buttons of a bar (NULL: the kiosk's), in the list's order,
 * and returns how many there are, even when max is smaller, like snprintf; 0 for a list
 * that does not fit the rows.
 */
size_t layout_bar_buttons(const struct screen *v, const struct layout_bar_list *list,
			  struct layout_button *out, size_t max);
/* The index in a bar's list (NULL: the kiosk's) of the button whose target holds (x, y). */
bool layout_bar_hit(const struct screen *v, const struct layout_bar_list *list, double x, double y,
		    size_t *index);

/* The kiosk's bar: layout_bar_buttons and layout_bar_hit with the kiosk's list. */
size_t layout_buttons(const struct screen *v, struct layout_button *out, size_t max);
bool layout_hit(const struct screen *v, double x, double y, enum button *button);

/*
 * The "front view" button of a 3D tree: a side-strip button, in the canvas's bottom left
 * corner, where a turned tree rarely reaches. Shown and hit only while the tree is 3D (the
 * app decides).
 */
struct layout_button layout_view_button(const struct screen *v);
bool layout_hit_view_button(const struct screen *v, double x, double y);

/* What the side strip holds: all its items are of one kind. */
enum layout_side_kind {
	LAYOUT_SIDE_BUTTONS,     /* in pairs, row by row: slot 2k | 2k + 1 */
	LAYOUT_SIDE_CARDS,       /* square pictures, down a column, then the next */
	LAYOUT_SIDE_NAMED_CARDS, /* the same with a word under each picture */
};

/*
 * Slot i of the side strip (the visible button or card), and its target. Buttons are as
 * large as the front view button; cards are 1.6 times a button's height wide, and a named
 * card is taller by a band for its word. A column of cards stops above the front view
 * button.
 */
struct layout_rect layout_side_slot(const struct screen *v, size_t i, enum layout_side_kind kind);
struct layout_rect layout_side_target(const struct screen *v, size_t i, enum layout_side_kind kind);
/* The slot, of n, whose target holds (x, y). */
bool layout_side_hit(const struct screen *v, double x, double y, size_t n,
		     enum layout_side_kind kind, size_t *slot);
/* The picture's part of a card slot: all of a card, the square above a named card's word. */
struct layout_rect layout_card_picture(struct layout_rect card, enum layout_side_kind kind);

/* The strip the bar's buttons sit on. */
struct layout_rect layout_bar(const struct screen *v);

/* The drawing area: the screen minus the bar. */
struct layout_rect layout_canvas(const struct screen *v);
