/* SPDX-License-Identifier: MIT */
#include "session.h"

#include <math.h>
#include <stdlib.h>

#include "layout.h"
#include "sketch_seen.h"
#include "wood.h"

/* ---- the reference ---- */

void session_copy_doc(struct doc *d, const struct doc *src)
{
	doc_init(d, src->seed);
	d->ops = calloc(src->nops + 1, sizeof(*d->ops));
	CHECK(d->ops);
	d->cap = src->nops + 1;
	for (size_t i = 0; i < src->nops; i++)
		CHECK_INT(doc_op_copy(&d->ops[i], &src->ops[i]), 0);
	d->nops = src->nops;
	d->cursor = src->cursor;
	d->view = src->view;
}

/* ---- a visitor ---- */

static void tip(struct pen *pen, struct app *app, enum event_type type, double x, double y,
		enum event_tool tool)
{
	pen_event(pen, app, type, tool, x, y, 0.6);
}

void session_stroke(struct pen *pen, struct app *app, double x0, double y0, double x1, double y1,
		    int n, enum event_tool tool, uint64_t pause_us)
{
	tip(pen, app, EVENT_TIP_DOWN, x0, y0, tool);
	for (int i = 1; i < n; i++) {
		double t = (double)i / (n - 1);

		tip(pen, app, EVENT_MOTION, x0 + (x1 - x0) * t + 5 * sin(t * 7), y0 + (y1 - y0) * t,
		    tool);
	}
	tip(pen, app, EVENT_TIP_UP, x1, y1, tool);
	pen->now_us += pause_us;
}

void session_loop(struct pen *pen, struct app *app, double cx, double cy, double r, double dir)
{
	tip(pen, app, EVENT_TIP_DOWN, cx + r, cy, EVENT_TOOL_PEN);
	for (int i = 1; i <= 30; i++)
		tip(pen, app, EVENT_MOTION, cx + r * cos(dir * i * 0.23), cy + r * sin(dir * i * 0.23),
		    EVENT_TOOL_PEN);
	tip(pen, app, EVENT_TIP_UP, cx + r * cos(dir * 30 * 0.23), cy + r * sin(dir * 30 * 0.23),
	    EVENT_TOOL_PEN);
	pen->now_us += PEN_PAUSE_US;
}

void session_tap(struct pen *pen, struct app *app, double x, double y)
{
	tip(pen, app, EVENT_TIP_DOWN, x, y, EVENT_TOOL_PEN);
	tip(pen, app, EVENT_TIP_UP, x, y, EVENT_TOOL_PEN);
	pen->now_us += 300000;
}

bool session_pick(const struct app *app, struct rng *r, bool parent, double *x, double *y)
{
	struct camera_xf xf;
	enum button hit;

	if (app->tree.nbranches == 0)
		return false;
	camera_xf_init(&xf, app->camera, sketch_seen_pivot(&app->tree));
	for (int tries = 0; tries < 40; tries++) {
		size_t b = rng_next(r) % app->tree.nbranches;
		const struct branch *br = &app->tree.branches[b];
		bool kids = false;

		for (size_t i = b + 1; i < app->tree.nbranches && parent && !kids; i++)
			kids = app->tree.branches[i].parent == (int)b;
		if ((parent && !kids) || br->npoints == 0)
			continue;
		screen_from_world(&app->screen, camera_to_view(&xf, br->points[rng_next(r) % br->npoints]), x, y);
		if (*x > 60 && *x < app->screen.width - 60 && *y > 60 && *y < app->screen.height - 60 &&
		    !layout_hit(&app->screen, *x, *y, &hit) && !layout_hit_view_button(&app->screen, *x, *y))
			return true;
	}
	return false;
}
