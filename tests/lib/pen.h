/* SPDX-License-Identifier: MIT */
#pragma once

#include <stdint.h>

#include "app.h"

/*
 * A visitor's pen and the kiosk's buttons, as the events app_handle_event gets: each
 * event is stamped with the pen's clock, which then moves on, so a test's events come at
 * the same times on every run. One struct pen per test program; its apps share the clock.
 */
#define PEN_EVENT_US 8000    /* from one pen event to the next (125 Hz) */
#define PEN_BUTTON_US 100000 /* from a button press to the next event */
#define PEN_PAUSE_US 4000000 /* long enough that two strokes are never taken for one
			      * branch's two outlines */

struct pen {
	uint64_t now_us;   /* time of the next event */
	int steps;         /* motion events per leg of a stroke */
	uint64_t pause_us; /* the clock moves on this much more after each stroke */
	uint64_t hold_us;  /* a button is released this long after it is pressed */
};

/* One pen event (proximity, tip or motion) at pen->now_us. */
void pen_event(struct pen *pen, struct app *app, enum event_type type, enum event_tool tool,
	       double x, double y, double pressure);
/* A stroke through npts screen points (xy: x, y pairs) at pressure 0.5: proximity in,
 * tip down at the first point, pen->steps motion events along each leg, tip up and
 * proximity out at the last point. */
void pen_stroke(struct pen *pen, struct app *app, enum event_tool tool, const double *xy,
		int npts);
/* A straight stroke of the pen's tip from (x0, y0) to (x1, y1). */
void pen_line(struct pen *pen, struct app *app, double x0, double y0, double x1, double y1);
/* A press of the kiosk's button b: down, then up pen->hold_us later. */
void pen_button(struct pen *pen, struct app *app, enum button b);
