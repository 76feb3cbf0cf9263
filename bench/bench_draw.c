/* SPDX-License-Identifier: MIT */
#include "bench_draw.h"

#include <math.h>

#include "bench_util.h"
#include "rng.h"

/* One event of the pen's tip, at the pressure of all of them. */
static void tip_event(struct app *app, struct bench_pen *pen, enum event_type type, double x,
		      double y)
{
	pen_event(&pen->pen, app, type, EVENT_TOOL_PEN, x, y, 0.6);
}

void bench_draw_stroke(struct app *app, struct bench_pen *pen, double x0, double y0, double x1,
		       double y1, int npoints, double *event_s)
{
	double t0;

	tip_event(app, pen, EVENT_TIP_DOWN, x0, y0);
	for (int i = 1; i < npoints - 1; i++) {
		double t = (double)i / (npoints - 1);

		t0 = bench_now();
		tip_event(app, pen, EVENT_MOTION, x0 + (x1 - x0) * t + 4 * sin(t * 9), y0 + (y1 - y0) * t);
		if (event_s)
			event_s[i - 1] = bench_now() - t0;
	}
	t0 = bench_now();
	tip_event(app, pen, EVENT_TIP_UP, x1, y1);
	pen->last_commit_s = bench_now() - t0;
	/* a pause, so strokes are never taken for two outlines of one branch */
	pen->pen.now_us += PEN_PAUSE_US;
}

static void leaf_loop(struct app *app, struct bench_pen *pen, double cx, double cy)
{
	tip_event(app, pen, EVENT_TIP_DOWN, cx + 12, cy);
	for (int i = 1; i <= 24; i++)
		tip_event(app, pen, EVENT_MOTION, cx + 12 * cos(i * 0.26), cy + 12 * sin(i * 0.26));
	tip_event(app, pen, EVENT_TIP_UP, cx + 12 * cos(24 * 0.26), cy + 12 * sin(24 * 0.26));
}

struct app *bench_draw_tree(struct bench_pen *pen, int nbranches)
{
	struct app *app = app_create(1280, 800, 1);
	struct rng rng;

	if (!app)
		return NULL;
	rng_seed(&rng, 42);
	bench_draw_stroke(app, pen, 560, 736, 555, 200, 32, NULL);
	for (int i = 0; i < nbranches; i++) {
		/* from a random point of a random branch, as children draw them */
		const struct branch *b = &app->tree.branches[rng_next(&rng) % app->tree.nbranches];
		struct vec3 at = b->points[rng_next(&rng) % b->npoints];
		double dx = rng_range(&rng, -200, 200), dy = rng_range(&rng, -150, -20), x, y;

		view_to_screen(&app->view, at, &x, &y);
		bench_draw_stroke(app, pen, x, y, x + dx, y + dy, 32, NULL);
		if (i % 10 == 9)
			leaf_loop(app, pen, x + dx, y + dy - 14);
	}
	return app;
}
