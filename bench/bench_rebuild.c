/* SPDX-License-Identifier: MIT */
/*
 * Rebuilding a drawing from its history (what undo, redo and --load do) and committing
 * one more stroke to it, for drawings of 62..500 branch strokes and 10 leaf loops per
 * 10 branches. Prints medians and growth with size.
 */
#include <math.h>
#include <stddef.h>
#include <stdio.h>

#include "app.h"
#include "bench_util.h"
#include "rng.h"

#define W 1280
#define H 800
#define REPS 7

static uint64_t now_us;
/* Wall time of each stroke's commit (the tip-up event), most recent last. */
static double commit_s[1024];
static size_t ncommits;

static void pen(struct app *app, enum event_type type, double x, double y)
{
	struct event ev = { .type = type, .time_us = now_us, .x = x, .y = y, .pressure = 0.6 };

	now_us += 8000;
	app_handle_event(app, &ev);
}

/* A wavy stroke of ~30 points from (x0,y0) to (x1,y1). */
static void stroke(struct app *app, double x0, double y0, double x1, double y1)
{
	pen(app, EVENT_TIP_DOWN, x0, y0);
	for (int i = 1; i <= 30; i++) {
		double t = i / 30.0;

		pen(app, EVENT_MOTION, x0 + (x1 - x0) * t + 4 * sin(t * 9), y0 + (y1 - y0) * t);
	}
	{
		double t0 = bench_now();

		pen(app, EVENT_TIP_UP, x1, y1);
		commit_s[ncommits++ % 1024] = bench_now() - t0;
	}
}

static void loop(struct app *app, double cx, double cy)
{
	pen(app, EVENT_TIP_DOWN, cx + 12, cy);
	for (int i = 1; i <= 24; i++)
		pen(app, EVENT_MOTION, cx + 12 * cos(i * 0.26), cy + 12 * sin(i * 0.26));
	pen(app, EVENT_TIP_UP, cx + 12 * cos(24 * 0.26), cy + 12 * sin(24 * 0.26));
}

/* Trunk, then branches from random points of the canvas' upper part outwards. */
static struct app *draw_tree(int nbranches)
{
	struct app *app = app_create(W, H, 1);
	struct rng rng;

	rng_seed(&rng, 42);
	stroke(app, 560, 736, 555, 200);
	for (int i = 0; i < nbranches; i++) {
		double y = rng_range(&rng, 250, 650), x = 557 + rng_range(&rng, -150, 150);
		double dx = rng_range(&rng, -200, 200), dy = rng_range(&rng, -150, -20);

		stroke(app, x, y, x + dx, y + dy);
		if (i % 10 == 9)
			loop(app, x + dx, y + dy - 14);
	}
	return app;
}

static void rebuild(void *arg)
{
	app_rebuild(arg);
}

int main(void)
{
	double ps = 0, pt = 0, cs = 0, ct = 0;

	printf("rebuild = replay the whole history (undo/redo/--load); commit = one more stroke\n");
	for (int n = 62; n <= 500; n *= 2) {
		struct app *app;
		double t_rebuild, last[REPS];
		char name[64];

		ncommits = 0;
		app = draw_tree(n);
		/* the last REPS branch strokes were committed onto a tree of about n branches */
		for (int i = 0; i < REPS; i++)
			last[i] = commit_s[(ncommits - 1 - (size_t)i * 2) % 1024];
		t_rebuild = bench_run(rebuild, app, REPS);
		snprintf(name, sizeof(name), "rebuild %zu strokes", app->doc.nops);
		bench_row(name, n, t_rebuild, &ps, &pt);
		snprintf(name, sizeof(name), "commit 1 stroke (%zu branches)", app->tree.nbranches);
		bench_row(name, n, bench_median(last, REPS), &cs, &ct);
		app_destroy(app);
	}
	return 0;
}
