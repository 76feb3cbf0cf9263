/* SPDX-License-Identifier: MIT */
#include "bench_draw.h"

#include <math.h>
#include <stdint.h>

#include "bench_util.h"
#include "layout.h"
#include "rng.h"
#include "sketch_seen.h"

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

		screen_from_world(&app->screen, at, &x, &y);
		bench_draw_stroke(app, pen, x, y, x + dx, y + dy, 32, NULL);
		if (i % 10 == 9)
			leaf_loop(app, pen, x + dx, y + dy - 14);
	}
	return app;
}

static void button(struct app *app, struct bench_pen *pen, enum button b)
{
	pen_button(&pen->pen, app, b);
}

/* Where a point of the tree is on the screen through the app's camera; false when it is
 * off the canvas or on a button. */
static bool seen_at(const struct app *app, struct vec3 world, double *x, double *y)
{
	struct camera_xf xf;
	enum button hit;

	camera_xf_init(&xf, app->camera, sketch_seen_pivot(&app->tree));
	screen_from_world(&app->screen, camera_to_view(&xf, world), x, y);
	return *x > 40 && *x < app->screen.width - 40 && *y > 40 && *y < app->screen.height - 40 &&
	       !layout_hit(&app->screen, *x, *y, &hit) && !layout_hit_view_button(&app->screen, *x, *y);
}

static size_t children(const struct tree *t, size_t b)
{
	size_t n = 0;

	for (size_t i = b + 1; i < t->nbranches; i++)
		n += t->branches[i].parent == (int)b;
	return n;
}

/* A random branch with at least `least` and at most `most` child branches, and a point
 * of it as seen. */
static bool pick(const struct app *app, struct rng *rng, size_t least, size_t most, double *x,
		 double *y)
{
	for (int tries = 0; tries < 50; tries++) {
		size_t b = rng_next(rng) % app->tree.nbranches;
		const struct branch *br = &app->tree.branches[b];
		size_t n = least || most < SIZE_MAX ? children(&app->tree, b) : 0;

		if (n < least || n > most)
			continue;
		if (seen_at(app, br->points[(br->npoints - 1) / 2 + rng_next(rng) % (br->npoints / 2 + 1)],
			    x, y))
			return true;
	}
	return false;
}

static void tap(struct app *app, struct bench_pen *pen, double x, double y)
{
	tip_event(app, pen, EVENT_TIP_DOWN, x, y);
	tip_event(app, pen, EVENT_TIP_UP, x, y);
	pen->pen.now_us += 300000;
}

/* A clone-mode circle round (x, y): clockwise on the screen adds a child. */
static void circle(struct app *app, struct bench_pen *pen, double x, double y, bool add)
{
	double dir = add ? 1.0 : -1.0;

	tip_event(app, pen, EVENT_TIP_DOWN, x + 40, y);
	for (int i = 1; i <= 30; i++)
		tip_event(app, pen, EVENT_MOTION, x + 40 * cos(dir * i * 0.23), y + 40 * sin(dir * i * 0.23));
	tip_event(app, pen, EVENT_TIP_UP, x + 40 * cos(dir * 30 * 0.23), y + 40 * sin(dir * 30 * 0.23));
	pen->pen.now_us += 300000;
}

struct app *bench_draw_edited(struct bench_pen *pen, int nbranches, size_t nops, int npropagate)
{
	struct app *app = bench_draw_tree(pen, nbranches);
	struct rng rng;
	double x, y;

	if (!app)
		return NULL;
	rng_seed(&rng, 43);
	button(app, pen, BUTTON_3D);
	pen->pen.now_us += APP_TURN_US;
	while (app->doc.nops < nops && app->tree.nbranches > 0) {
		unsigned what = (unsigned)(rng_next(&rng) % 100);

		if (what < 55) {
			/* a branch drawn on the tree as turned */
			app_set_camera(app, (struct camera){ (float)rng_range(&rng, -70, 70),
							    (float)rng_range(&rng, -10, 30) });
			if (pick(app, &rng, 0, SIZE_MAX, &x, &y))
				bench_draw_stroke(app, pen, x, y, x + rng_range(&rng, -150, 150),
						  y + rng_range(&rng, -120, -10), 24, NULL);
		} else if (what < 65) {
			if (pick(app, &rng, 0, SIZE_MAX, &x, &y))
				leaf_loop(app, pen, x, y - 14);
			pen->pen.now_us += PEN_PAUSE_US;
		} else if (what < 98 || npropagate == 0) {
			/* clone mode, from the front: tap a parent twice (a child more), or circle it */
			app_set_camera(app, (struct camera){ 0, 0 });
			button(app, pen, BUTTON_CLONE);
			if (pick(app, &rng, 1, SIZE_MAX, &x, &y)) {
				tap(app, pen, x, y);
				if (what < 88)
					tap(app, pen, x, y);
				else
					circle(app, pen, x, y, what < 92);
			}
			button(app, pen, BUTTON_CLONE);
		} else {
			app_set_camera(app, (struct camera){ 0, 0 });
			/* a twig of one child, copied onto every branch: each doubles the tree */
			button(app, pen, BUTTON_PROPAGATE);
			if (pick(app, &rng, 1, 1, &x, &y))
				tap(app, pen, x, y);
			button(app, pen, BUTTON_PROPAGATE);
			npropagate--;
		}
	}
	return app;
}

double bench_press(struct app *app, enum button b)
{
	struct event ev = { .type = EVENT_BUTTON, .time_us = app->last_time_us + 1000,
			    .button = (int)b, .pressed = true };
	double t0 = bench_now(), dt;

	app_handle_event(app, &ev);
	dt = bench_now() - t0;
	ev.pressed = false;
	app_handle_event(app, &ev);
	return dt;
}
