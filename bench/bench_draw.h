/* SPDX-License-Identifier: MIT */
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "app.h"
#include "pen.h"

/*
 * Drawings made the way a visitor makes them, through pen events: a trunk and
 * `nbranches` wavy branch strokes from random points of the trunk's area outwards, with
 * a leaf loop every tenth branch. Seeded, so every run draws the same.
 */
struct bench_pen {
	struct pen pen;       /* its clock (tests/lib/pen.h) */
	double last_commit_s; /* wall time of the latest tip-up (the commit) */
};

struct app *bench_draw_tree(struct bench_pen *pen, int nbranches);
/*
 * A drawing of about `nops` edits the way a long session goes: bench_draw_tree's sketch
 * of `nbranches` strokes, the 3D button, then strokes and leaves drawn on the tree turned
 * this way and that, clone-mode taps and circles (children added and removed), and now
 * and then a propagation (at most `npropagate`). Seeded.
 */
struct app *bench_draw_edited(struct bench_pen *pen, int nbranches, size_t nops, int npropagate);
/* A wavy stroke of npoints points from (x0,y0) to (x1,y1). If event_s is given, the wall
 * time of each motion event is stored there (npoints - 2 entries). */
void bench_draw_stroke(struct app *app, struct bench_pen *pen, double x0, double y0, double x1,
		       double y1, int npoints, double *event_s);
/* Seconds app_handle_event takes over one press of b (released afterwards, untimed). */
double bench_press(struct app *app, enum button b);
