/* SPDX-License-Identifier: MIT */
/*
 * Drawing on a grown tree: the cost of each pen event while a stroke is drawn, and of
 * committing a 5,000-point stroke (resample, smooth, classify, attach, mesh), on
 * drawings of 125..1,000 branches. Medians; growth with size.
 */
#include <stdio.h>
#include <stdlib.h>

#include "bench_draw.h"
#include "bench_util.h"

#define LONG_STROKE 5000
#define REPS 5

int main(void)
{
	double pe_n = 0, pe_t = 0, c_n = 0, c_t = 0;
	double *ev = malloc(LONG_STROKE * sizeof(*ev) * REPS);

	if (!ev)
		return 1;
	printf("pen event = one motion event while drawing; commit = tip-up of a %d-point stroke\n",
	       LONG_STROKE);
	for (int n = 125; n <= 1000; n *= 2) {
		struct bench_pen pen = { .now_us = 1000 };
		struct app *app = bench_draw_tree(&pen, n);
		double commit[REPS];
		char name[64];

		if (!app)
			return 1;
		for (int r = 0; r < REPS; r++) {
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
		bench_row(name, n, 1e3 * bench_median(ev, (size_t)REPS * (LONG_STROKE - 2)), &pe_n, &pe_t);
		snprintf(name, sizeof(name), "commit 5000 pts (%zu br.)", app->tree.nbranches);
		bench_row(name, n, bench_median(commit, REPS), &c_n, &c_t);
		app_destroy(app);
	}
	free(ev);
	return 0;
}
