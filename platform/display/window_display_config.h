/* SPDX-License-Identifier: MIT */
#pragma once

/* What a window's configuration may choose (window_display.c); 0: the default. */
struct window_display_config {
	int width, height; /* the app's size, the window's first size; default 1280x800 */
};
