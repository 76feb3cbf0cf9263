/* SPDX-License-Identifier: MIT */
#pragma once

#include "display.h"
#include "error.h"
#include "window_display_config.h"

/*
 * The kiosk loop's display on a desktop (display.h): a resizable SDL2 window on X11 or
 * Wayland with a GLES context (3.0 when there is one, else 2.0). The app keeps the size
 * it started with, as on a DRM display that comes back with another mode: the picture is
 * drawn offscreen at that size (offscreen.c) and shown scaled to fit the window, aspect
 * kept, black around it; pointer positions are mapped back onto the picture. Its mouse,
 * touch and keys are the pen and the buttons (window_input.c). Closing the window stops
 * the kiosk as SIGTERM does.
 *
 * The loop's poll() wakes on the window system's connection (X11 or Wayland) and on an
 * eventfd raised when SDL already holds events that fd will not announce again (read
 * during a swap); without either, a 10 ms timer. Everything SDL runs on the loop's
 * thread.
 */
struct display *window_display_create(const struct window_display_config *cfg,
				      struct error *err);
