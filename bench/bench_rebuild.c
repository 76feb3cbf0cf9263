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
#include "bench_draw.h"
#include "bench_util.h"

#define REPS 7

static void rebuild(void *arg)
{
	app_rebuild(arg);
}

int main(void)
{
	double ps = 0, pt = 0, cs = 0, ct = 0;

	printf("rebuild = replay the whole history (undo/redo/--load); commit = one more stroke\n");
	for (int n = 62; n <= 500; n *= 2) {
		struct bench_pen pen = { .pen.now_us = 1000 };
		struct app *app = bench_draw_tree(&pen, n);
		double t_rebuild, last[REPS];
		char name[64];

		/* REPS more strokes onto a tree of about n branches */
		for (int i = 0; i < REPS; i++) {
			bench_draw_stroke(app, &pen, 560, 400 + 20 * i, 700, 300, 32, NULL);
			last[i] = pen.last_commit_s;
		}
		t_rebuild = bench_run(rebuild, app, REPS);
		snprintf(name, sizeof(name), "rebuild %zu strokes", app->doc.nops);
		bench_row(name, n, t_rebuild, &ps, &pt);
		snprintf(name, sizeof(name), "commit 1 stroke (%zu branches)", app->tree.nbranches);
		bench_row(name, n, bench_median(last, REPS), &cs, &ct);
		app_destroy(app);
	}
	return 0;
}
