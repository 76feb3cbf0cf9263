/* SPDX-License-Identifier: MIT */
/*
 * Rebuilding a drawing from its history and stepping through it, for drawings of
 * 62..1,000 branch strokes with 10 leaf loops per 100 strokes, and for a session of
 * about 2,000 edits (a 500-stroke sketch made 3D, then strokes on the turned tree,
 * leaves, clones added and removed, two propagations):
 *
 *   rebuild  replaying the whole history (app_rebuild: what undo and redo did before)
 *   load     --load: a document given to the app, replayed, its checkpoints taken
 *   commit   one more stroke
 *   undo     one press of undo, walking back from the end of the history (after a load):
 *            of an edit that only appended elements (a stroke, a leaf, a clone added:
 *            cut back), of one that changed some (a cut, a clone removed: from a
 *            checkpoint)
 *   redo     one press of redo, walking forward again
 *
 * Medians, and the worst press of a walk; growth with size.
 */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app.h"
#include "bench_draw.h"
#include "bench_util.h"

#define REPS 7
#define WALK 200 /* presses of undo, then of redo, on the edited drawing */

struct series {
	double size, median; /* of the previous row */
};

static void row(const char *name, double size, double s, struct series *prev)
{
	bench_row(name, size, s, &prev->size, &prev->median);
}

static void rebuild(void *arg)
{
	app_rebuild(arg);
}

static void copy_doc(struct doc *d, const struct doc *src)
{
	doc_init(d, src->seed);
	d->ops = calloc(src->nops + 1, sizeof(*d->ops));
	d->cap = d->ops ? src->nops + 1 : 0;
	for (size_t i = 0; i < src->nops && d->ops; i++) {
		if (doc_op_copy(&d->ops[i], &src->ops[i]) < 0)
			break;
		d->nops++;
	}
	d->cursor = src->cursor < d->nops ? src->cursor : d->nops;
	d->view = src->view;
}

/* --load of app's document into a fresh app, reps times; the last app is kept. */
static double load(const struct app *app, int reps, struct app **out)
{
	double t[REPS];

	for (int i = 0; i < reps; i++) {
		struct app *b = app_create(app->view.width, app->view.height, app->doc.seed);
		struct doc d;
		double t0;

		copy_doc(&d, &app->doc);
		t0 = bench_now();
		app_load_doc(b, &d);
		t[i] = bench_now() - t0;
		doc_finish(&d);
		if (i + 1 < reps)
			app_destroy(b);
		else
			*out = b;
	}
	return bench_median(t, (size_t)reps);
}

/* Press times sorted by what the op undone or redone had done: only appended (a stroke,
 * a leaf, a clone added) or changed elements (a cut, a clone removed). */
struct walk {
	double any[2 * WALK], appended[2 * WALK], changed[2 * WALK];
	size_t nany, nappended, nchanged;
};

static void walk_add(struct walk *w, const struct app *app, size_t state, double dt)
{
	const struct history_mark *m = history_mark(&app->history, state);

	w->any[w->nany++] = dt;
	if (m && m->grew)
		w->appended[w->nappended++] = dt;
	else
		w->changed[w->nchanged++] = dt;
}

static double worst(const double *v, size_t n)
{
	double m = 0;

	for (size_t i = 0; i < n; i++)
		m = v[i] > m ? v[i] : m;
	return m;
}

/* Undo n times from the end, then redo n times. */
static void walk(struct app *app, size_t n, struct walk *undo, struct walk *redo)
{
	memset(undo, 0, sizeof(*undo));
	memset(redo, 0, sizeof(*redo));
	for (size_t i = 0; i < n && doc_can_undo(&app->doc); i++) {
		size_t from = app->doc.cursor;

		walk_add(undo, app, from, bench_press(app, BUTTON_UNDO));
	}
	for (size_t i = 0; i < n && doc_can_redo(&app->doc); i++) {
		double dt = bench_press(app, BUTTON_REDO);

		walk_add(redo, app, app->doc.cursor, dt);
	}
}

/* A slash across one of the newest branches, begun away from the wood: a cut. A slash
 * that became a branch instead is undone (the next stroke drops it) and tried elsewhere. */
static void cut(struct app *app, struct bench_pen *pen, int k)
{
	for (size_t tries = 0; tries < 200; tries++) {
		size_t b = app->tree.nbranches - 1 - (k + tries) % app->tree.nbranches;
		const struct branch *br = &app->tree.branches[b];
		size_t i = br->npoints / 2 + tries % (br->npoints / 2 + 1);
		const struct history_mark *m;
		double x, y, qx, qy, nx, ny, l;

		if (br->npoints < 4 || i + 1 >= br->npoints)
			continue;
		view_to_screen(&app->view, br->points[i], &x, &y);
		view_to_screen(&app->view, br->points[i + 1], &qx, &qy);
		l = hypot(qx - x, qy - y) + 1e-9;
		nx = -(qy - y) / l * 80;
		ny = (qx - x) / l * 80;
		bench_draw_stroke(app, pen, x + nx, y + ny, x - nx, y - ny, 16, NULL);
		m = history_mark(&app->history, app->doc.cursor);
		if (m && !m->grew)
			return;
		bench_press(app, BUTTON_UNDO);
	}
}

static void print_walk(const char *what, double size, const struct walk *w, const char *appended,
		       const char *changed, struct series *s)
{
	char name[64];
	struct walk c = *w;

	if (c.nappended) {
		snprintf(name, sizeof(name), "%s, %s (worst %.3f)", what, appended,
			 1e3 * worst(c.appended, c.nappended));
		row(name, size, bench_median(c.appended, c.nappended), &s[0]);
	}
	if (c.nchanged) {
		snprintf(name, sizeof(name), "%s, %s (worst %.3f)", what, changed,
			 1e3 * worst(c.changed, c.nchanged));
		row(name, size, bench_median(c.changed, c.nchanged), &s[1]);
	}
}

static int strokes(void)
{
	struct series reb = { 0 }, ld = { 0 }, com = { 0 }, un[2] = { { 0 } }, re[2] = { { 0 } };

	int reps = bench_reps(REPS);

	printf("%-40s %8s %12s\n", "drawn strokes", "strokes", "median");
	for (int n = 62; n <= (bench_quick ? 124 : 1000); n *= 2) {
		struct bench_pen pen = { .pen.now_us = 1000 };
		struct app *app = bench_draw_tree(&pen, n), *loaded;
		double t_rebuild, last[REPS];
		struct walk undo, redo;
		char name[64];

		if (!app)
			return 1;
		/* REPS more strokes onto a tree of about n branches */
		for (int i = 0; i < reps; i++) {
			bench_draw_stroke(app, &pen, 560, 400 + 20 * i, 700, 300, 32, NULL);
			last[i] = pen.last_commit_s;
		}
		t_rebuild = bench_run(rebuild, app, reps);
		snprintf(name, sizeof(name), "rebuild %zu strokes", app->doc.nops);
		row(name, n, t_rebuild, &reb);
		snprintf(name, sizeof(name), "commit 1 stroke (%zu branches)", app->tree.nbranches);
		row(name, n, bench_median(last, (size_t)reps), &com);
		/* then REPS cuts, each after a stroke */
		for (int i = 0; i < reps; i++) {
			bench_draw_stroke(app, &pen, 620, 380 + 20 * i, 500, 280, 32, NULL);
			cut(app, &pen, 3 * i);
		}
		snprintf(name, sizeof(name), "load %zu strokes", app->doc.nops);
		row(name, n, load(app, reps, &loaded), &ld);
		/* stepping through the loaded drawing, as after --load */
		walk(loaded, 2 * (size_t)reps, &undo, &redo);
		print_walk("undo", n, &undo, "a stroke", "a cut", un);
		print_walk("redo", n, &redo, "a stroke", "a cut", re);
		app_destroy(loaded);
		app_destroy(app);
	}
	return 0;
}

static int session(void)
{
	struct series reb = { 0 }, ld = { 0 }, any[4] = { { 0 } };
	struct bench_pen pen = { .pen.now_us = 1000 };
	struct app *app = bench_quick ? bench_draw_edited(&pen, 62, 200, 1)
				       : bench_draw_edited(&pen, 500, 2000, 2);
	struct app *loaded;
	struct walk undo, redo;
	char name[64];
	size_t kinds[DOC_OP_IMPORT + 1] = { 0 };

	if (!app)
		return 1;
	/* the long session's taps press grow once (its button is under the tree); the short
	 * one's do not: a press, so that --quick copies and frees an op that owns memory */
	if (bench_quick)
		(void)bench_press(app, BUTTON_GROW);
	for (size_t i = 0; i < app->doc.nops; i++)
		kinds[app->doc.ops[i].kind]++;
	printf("\n%zu edits: %zu strokes, 3D, %zu clones added, %zu removed, %zu propagations; "
	       "%zu branches, %zu leaves\n",
	       app->doc.nops, kinds[DOC_OP_STROKE], kinds[DOC_OP_CLONE_ADD],
	       kinds[DOC_OP_CLONE_REMOVE], kinds[DOC_OP_PROPAGATE], app->tree.nbranches,
	       app->tree.nleaves);
	snprintf(name, sizeof(name), "rebuild %zu ops", app->doc.nops);
	row(name, (double)app->doc.nops, bench_run(rebuild, app, 3), &reb);
	snprintf(name, sizeof(name), "load %zu ops", app->doc.nops);
	row(name, (double)app->doc.nops, load(app, 3, &loaded), &ld);
	walk(loaded, WALK, &undo, &redo);
	print_walk("undo", (double)app->doc.nops, &undo, "appended", "changed", any);
	print_walk("redo", (double)app->doc.nops, &redo, "appended", "changed", any + 2);
	app_destroy(loaded);
	app_destroy(app);
	return 0;
}

int main(int argc, char **argv)
{
	if (bench_init(&argc, argv, NULL))
		return 1;
	printf("rebuild = replay the whole history; load = --load; undo/redo = one press, "
	       "walking back from the end and forth again (ms)\n");
	return strokes() || session();
}
