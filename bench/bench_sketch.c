/* SPDX-License-Identifier: MIT */
/*
 * Drawing on a grown tree: the cost of each pen event while a stroke is drawn, and of
 * committing a 5,000-point stroke (resample, smooth, classify, attach, mesh), on
 * drawings of 125..1,000 branches; then the same on the 3D tree turned by the orbit
 * camera (the tree is seen through sketch_seen), and the check a frame makes for the
 * cursor: would a drag here turn the tree. Medians; growth with size.
 */
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>

#include "bench_draw.h"
#include "bench_util.h"

#define LONG_STROKE 5000
#define REPS 5

static void press(struct app *app, enum button b)
{
	struct event e = { .type = EVENT_BUTTON, .button = (int)b, .pressed = true };

	app_handle_event(app, &e);
	e.pressed = false;
	app_handle_event(app, &e);
}

static int run(bool turned)
{
	double pe_n = 0, pe_t = 0, c_n = 0, c_t = 0, o_n = 0, o_t = 0;
	double *ev = malloc(LONG_STROKE * sizeof(*ev) * REPS);
	int reps = bench_reps(REPS);

	if (!ev)
		return 1;
	for (int n = 125; n <= (bench_quick ? 250 : 1000); n *= 2) {
		struct bench_pen pen = { .pen.now_us = 1000 };
		struct app *app = bench_draw_tree(&pen, n);
		double commit[REPS], orbit[REPS * 10];
		char name[64];

		if (!app)
			return 1;
		if (turned) {
			press(app, BUTTON_3D);
			if (!app_set_camera(app, (struct camera){ 60.0f, 20.0f }))
				return 1;
			for (int r = 0; r < reps * 10; r++) {
				double t0 = bench_now();

				(void)app_would_orbit(app, 100.0 + r, 100.0);
				orbit[r] = bench_now() - t0;
			}
			snprintf(name, sizeof(name), "orbit check (%zu br.)", app->tree.nbranches);
			bench_row(name, n, bench_median(orbit, (size_t)reps * 10), &o_n, &o_t);
		}
		for (int r = 0; r < reps; r++) {
			struct event undo = { .type = EVENT_BUTTON, .button = BUTTON_UNDO, .pressed = true };

			/* a long wandering branch from the trunk, then undone for the next run */
			bench_draw_stroke(app, &pen, 557, 600, 980, 150, LONG_STROKE,
					  ev + (size_t)r * (LONG_STROKE - 2));
			commit[r] = pen.last_commit_s;
			app_handle_event(app, &undo);
			undo.pressed = false;
			app_handle_event(app, &undo);
		}
		snprintf(name, sizeof(name), "pen event, us (%zu br.)", app->tree.nbranches);
		/* microseconds in the ms column: events are far below a millisecond */
		bench_row(name, n, 1e3 * bench_median(ev, (size_t)reps * (LONG_STROKE - 2)), &pe_n, &pe_t);
		snprintf(name, sizeof(name), "commit 5000 pts (%zu br.)", app->tree.nbranches);
		bench_row(name, n, bench_median(commit, (size_t)reps), &c_n, &c_t);
		app_destroy(app);
	}
	free(ev);
	return 0;
}

int main(int argc, char **argv)
{
	if (bench_init(&argc, argv, NULL))
		return 1;
	printf("pen event = one motion event while drawing; commit = tip-up of a %d-point stroke\n",
	       LONG_STROKE);
	if (run(false))
		return 1;
	printf("\nthe same on the 3D tree turned to yaw 60, pitch 20 (with its merged branches)\n");
	return run(true);
}
