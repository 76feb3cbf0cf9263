/* SPDX-License-Identifier: MIT */
#pragma once

#include <SDL.h>
#include <stdbool.h>
#include <stdint.h>

#include "display.h"
#include "event.h"

/*
 * A desktop window's input as the kiosk's (docs/window.md): the mouse is the pen (the
 * left button its tip, pressure 1 while down as libinput gives a mouse; the right button
 * its barrel button; in the window is in proximity), a touch is the pen with the
 * finger's pressure, and keys press the bar's buttons (window_input_key). Events are
 * stamped with CLOCK_MONOTONIC microseconds, never going backwards.
 */

/* Where the app's picture is in the window: window points to app pixels. */
struct window_map {
	int app_w, app_h;   /* the picture, app pixels */
	int win_w, win_h;   /* the window, in the points SDL reports the mouse in */
	int draw_w, draw_h; /* the window's drawable, pixels */
};

/* The app pixel under window point (wx, wy), pure arithmetic (as offscreen_geometry
 * places the picture). Outside the picture the position is clamped to its edge. */
void window_map_point(const struct window_map *m, double wx, double wy, double *ax, double *ay);

/* The bar's button a key presses (docs/window.md); false: none. */
bool window_input_key(SDL_Keycode key, enum button *button);

struct window_input {
	display_feed_fn feed;
	void *data;
	uint64_t last_us;
	bool in, down, stylus;
	bool finger;               /* a touch is the pen */
	SDL_FingerID finger_id;
	bool keys[BUTTON_COUNT];   /* pressed by a key, released by its key up */
	double x, y;               /* the pen's last position, app pixels */
};

void window_input_init(struct window_input *wi, display_feed_fn feed, void *data);
/* One SDL event (ignored if not input) into events for the app. */
void window_input_handle(struct window_input *wi, const SDL_Event *ev, const struct window_map *m);
