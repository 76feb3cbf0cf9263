/* SPDX-License-Identifier: MIT */
#pragma once

#include <stdbool.h>
#include <stddef.h>

#include "event.h"
#include "view.h"

/*
 * Where the on-screen buttons are: a strip along the right edge of the screen with
 * large pen-friendly buttons, over half as wide again as tall (an icon over a label).
 * The four kiosk modes sit at the top, the actions at the bottom, with a wider gap
 * between the groups so the two kinds read apart. Pure geometry in screen pixels (origin
 * top left, y down): the renderer draws from it and the app hit-tests taps with it, so
 * both always agree.
 */

/* Buttons in the bar, top to bottom. */
#define LAYOUT_NBUTTONS 8

struct layout_rect {
	double x, y, w, h;
};

struct layout_button {
	enum button button;
	double x, y, w, h; /* the visible button */
};

/*
 * Fills out[0..max) with the buttons of the bar, top to bottom, and returns how many
 * there are (LAYOUT_NBUTTONS), even when max is smaller, like snprintf.
 */
size_t layout_buttons(const struct view *v, struct layout_button *out, size_t max);

/*
 * The button under screen point (x, y). Each button's target reaches half a gap
 * beyond what is drawn, so a tap between two buttons still lands on the nearer one.
 */
bool layout_hit(const struct view *v, double x, double y, enum button *button);

/*
 * The "front view" button of a 3D tree: the size of the bar's buttons, in the canvas's
 * bottom left corner, where a turned tree rarely reaches. Shown and hit only while the
 * tree is 3D (the app decides).
 */
struct layout_button layout_view_button(const struct view *v);
bool layout_hit_view_button(const struct view *v, double x, double y);

/*
 * The strip along the canvas's left edge that shows what the active mode offers: in leaf
 * mode the suggested arrangements as square thumbnails (1.6 x a button's height), in
 * propagate mode the two patterns as buttons. Slot i counts from the top.
 */
struct layout_rect layout_side_slot(const struct view *v, size_t i, bool thumbnail);
/* The slot of n under (x, y), with the same half-gap margin as the bar. */
bool layout_side_hit(const struct view *v, double x, double y, size_t n, bool thumbnail,
		     size_t *slot);

/* The strip the buttons sit on. */
struct layout_rect layout_bar(const struct view *v);

/* The drawing area: the screen minus the bar. */
struct layout_rect layout_canvas(const struct view *v);
