/* SPDX-License-Identifier: MIT */
#include "pen.h"

#include <stdbool.h>

void pen_event(struct pen *pen, struct app *app, enum event_type type, enum event_tool tool,
	       double x, double y, double pressure)
{
	struct event e = { .type = type, .time_us = pen->now_us, .tool = tool, .x = x, .y = y,
			   .pressure = pressure };

	pen->now_us += PEN_EVENT_US;
	app_handle_event(app, &e);
}

void pen_stroke(struct pen *pen, struct app *app, enum event_tool tool, const double *xy,
		int npts)
{
	const double *end = xy + 2 * npts - 2;

	pen_event(pen, app, EVENT_PROXIMITY_IN, tool, xy[0], xy[1], 0.5);
	pen_event(pen, app, EVENT_TIP_DOWN, tool, xy[0], xy[1], 0.5);
	for (int k = 1; k < npts; k++)
		for (int i = 1; i <= pen->steps; i++)
			pen_event(pen, app, EVENT_MOTION, tool,
				  xy[2 * k - 2] + (xy[2 * k] - xy[2 * k - 2]) * i / pen->steps,
				  xy[2 * k - 1] + (xy[2 * k + 1] - xy[2 * k - 1]) * i / pen->steps, 0.5);
	pen_event(pen, app, EVENT_TIP_UP, tool, end[0], end[1], 0.5);
	pen_event(pen, app, EVENT_PROXIMITY_OUT, tool, end[0], end[1], 0.5);
	pen->now_us += pen->pause_us;
}

void pen_line(struct pen *pen, struct app *app, double x0, double y0, double x1, double y1)
{
	const double xy[] = { x0, y0, x1, y1 };

	pen_stroke(pen, app, EVENT_TOOL_PEN, xy, 2);
}

void pen_button(struct pen *pen, struct app *app, enum button b)
{
	struct event e = { .type = EVENT_BUTTON, .time_us = pen->now_us, .button = (int)b,
			   .pressed = true };

	app_handle_event(app, &e);
	e.pressed = false;
	e.time_us += pen->hold_us;
	app_handle_event(app, &e);
	pen->now_us += PEN_BUTTON_US;
}
