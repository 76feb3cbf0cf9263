/* SPDX-License-Identifier: MIT */
#pragma once

/*
 * Where a tablet point lands on the display: pure arithmetic, tested on its own
 * (tests/platform/test_input_map.c). The tablet may be turned on the desk (rotation,
 * clockwise, in 90-degree steps) and only part of it may be used (area): by default the
 * largest centred part with the display's aspect, so a circle drawn stays a circle.
 */
#include <stdbool.h>

#include "config_file.h"

struct input_map {
	int rotation;      /* 0, 90, 180, 270 */
	double area[4];    /* left, top, right, bottom of the turned tablet, 0..1 */
	double screen_w, screen_h;
};

/*
 * tablet_w/h: the tablet's physical size (any unit; <= 0 when unknown: then the whole
 * tablet is used, stretched). area CONFIG_AREA_RECT uses rect. Direct devices (screen
 * tablets, touchscreens) should be given CONFIG_AREA_STRETCH.
 */
void input_map_init(struct input_map *m, int rotation, enum config_area area,
		    const double rect[4], double tablet_w, double tablet_h, int screen_w,
		    int screen_h);

/* u, v: the position on the tablet as a fraction 0..1 of its width and height (as the
 * tablet reports it, unturned). Gives screen pixels, clamped to the screen. */
void input_map_point(const struct input_map *m, double u, double v, double *x, double *y);

/* Turns a tilt (degrees along the tablet's x and y) the way the tablet is turned. */
void input_map_tilt(const struct input_map *m, double tx, double ty, double *sx, double *sy);

/* (u, v) turned by rotation degrees clockwise, within the unit square. */
void input_map_rotate(int rotation, double u, double v, double *ru, double *rv);
