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
 *   undo     one press of undo, walking back from the end of the history to the empty
 *            canvas (after a load): of an edit that only appended elements (a stroke, a
 *            leaf, a clone added, a propagation), of one that changed some (a cut, a
 *            clone removed, 3D, a year of wood)
 *   redo     one press of redo, walking forward again to the end
 *
 * The session ends with a few cuts, so that its walk meets every kind of edit; the
 * worst press of each kind is printed too.
 * Medians, and the worst press of a walk; growth with size.
 */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "app.h"
#include "bench_draw.h"
#include "bench_util.h"

#define REPS 7
#define CUTS 10 /* on the edited drawing, at its end */

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
		struct app *b = app_create(app->screen.width, app->screen.height, app->doc.seed);
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

/* What the op undone or redone was, for the worst press of each kind. */
enum press_kind {
	PRESS_STROKE, /* a branch or a leaf drawn */
	PRESS_CUT,    /* a stroke that cut or erased */
	PRESS_CLONE_ADD,
	PRESS_CLONE_REMOVE,
	PRESS_PROPAGATE,
	PRESS_LIFT,
	PRESS_GROW,
	PRESS_OTHER,
	PRESS_KINDS
};

static const char *const press_names[PRESS_KINDS] = {
	"stroke", "cut", "clone added", "clone removed", "propagation", "3D", "grow", "other",
};

/* Press times sorted by what the op undone or redone had done: only appended (a stroke,
 * a leaf, a clone added, a propagation) or changed elements (a cut, a clone removed). */
struct walk {
	double *any, *appended, *changed;
	size_t nany, nappended, nchanged;
	double worst[PRESS_KINDS], worst_cpu[PRESS_KINDS];
	size_t count[PRESS_KINDS];
};

/* This thread's CPU seconds: on a shared machine a press's wall time may include a
 * time slice given to another process, which this leaves out. */
static double cpu_now(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
	return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static enum press_kind press_kind(const struct app *app, size_t state)
{
	const struct history_mark *m = history_mark(&app->history, state);

	switch (app->doc.ops[state - 1].kind) {
	case DOC_OP_STROKE:
		return m && !m->grew ? PRESS_CUT : PRESS_STROKE;
	case DOC_OP_CLONE_ADD:
		return PRESS_CLONE_ADD;
	case DOC_OP_CLONE_REMOVE:
		return PRESS_CLONE_REMOVE;
	case DOC_OP_PROPAGATE:
		return PRESS_PROPAGATE;
	case DOC_OP_LIFT:
		return PRESS_LIFT;
	case DOC_OP_GROW:
		return PRESS_GROW;
	default:
		return PRESS_OTHER;
	}
}

static void walk_add(struct walk *w, const struct app *app, size_t state, double dt, double cpu)
{
	const struct history_mark *m = history_mark(&app->history, state);
	enum press_kind k = press_kind(app, state);

	w->any[w->nany++] = dt;
	if (m && m->grew)
		w->appended[w->nappended++] = dt;
	else
		w->changed[w->nchanged++] = dt;
	w->count[k]++;
	if (dt > w->worst[k])
		w->worst[k] = dt;
	if (cpu > w->worst_cpu[k])
		w->worst_cpu[k] = cpu;
}

static double worst(const double *v, size_t n)
{
	double m = 0;

	for (size_t i = 0; i < n; i++)
		m = v[i] > m ? v[i] : m;
	return m;
}

static void walk_init(struct walk *w, size_t n)
{
	memset(w, 0, sizeof(*w));
	w->any = calloc(n + 1, sizeof(*w->any));
	w->appended = calloc(n + 1, sizeof(*w->appended));
	w->changed = calloc(n + 1, sizeof(*w->changed));
	if (!w->any || !w->appended || !w->changed) {
		fprintf(stderr, "bench_rebuild: out of memory\n");
		exit(1);
	}
}

static void walk_finish(struct walk *w)
{
	free(w->any);
	free(w->appended);
	free(w->changed);
}

/* Undo all the way from the end, then redo all the way. */
static void walk(struct app *app, struct walk *undo, struct walk *redo)
{
	walk_init(undo, app->doc.nops);
	walk_init(redo, app->doc.nops);
	while (doc_can_undo(&app->doc)) {
		size_t from = app->doc.cursor;
		double c0 = cpu_now(), dt = bench_press(app, BUTTON_UNDO);

		walk_add(undo, app, from, dt, cpu_now() - c0);
	}
	while (doc_can_redo(&app->doc)) {
		double c0 = cpu_now(), dt = bench_press(app, BUTTON_REDO);

		walk_add(redo, app, app->doc.cursor, dt, cpu_now() - c0);
	}
}

/* The worst press of each kind the walk met (wall time / this thread's CPU time, and
 * how many presses), and of all. */
static void print_kinds(const char *what, const struct walk *w)
{
	double cpu = 0;

	printf("  %s, worst press by kind, ms wall/cpu (presses):\n   ", what);
	for (int k = 0; k < PRESS_KINDS; k++) {
		if (!w->count[k])
			continue;
		printf(" %s %.3f/%.3f (%zu);", press_names[k], 1e3 * w->worst[k],
		       1e3 * w->worst_cpu[k], w->count[k]);
		cpu = w->worst_cpu[k] > cpu ? w->worst_cpu[k] : cpu;
	}
	printf(" all %.3f/%.3f\n", 1e3 * worst(w->any, w->nany), 1e3 * cpu);
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
		screen_from_world(&app->screen, br->points[i], &x, &y);
		screen_from_world(&app->screen, br->points[i + 1], &qx, &qy);
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
	const struct walk *c = w;

	if (c->nappended) {
		snprintf(name, sizeof(name), "%s, %s (worst %.3f)", what, appended,
			 1e3 * worst(c->appended, c->nappended));
		row(name, size, bench_median(c->appended, c->nappended), &s[0]);
	}
	if (c->nchanged) {
		snprintf(name, sizeof(name), "%s, %s (worst %.3f)", what, changed,
			 1e3 * worst(c->changed, c->nchanged));
		row(name, size, bench_median(c->changed, c->nchanged), &s[1]);
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
		walk(loaded, &undo, &redo);
		print_walk("undo", n, &undo, "a stroke", "a cut", un);
		print_walk("redo", n, &redo, "a stroke", "a cut", re);
		walk_finish(&undo);
		walk_finish(&redo);
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
	size_t kinds[DOC_OP_IMPORT + 1] = { 0 }, cuts = 0;

	if (!app)
		return 1;
	/* the long session's taps press grow once (its button is under the tree); the short
	 * one's do not: a press, so that --quick copies and frees an op that owns memory */
	if (bench_quick)
		(void)bench_press(app, BUTTON_GROW);
	/* and a few cuts, from the front, each after a stroke */
	app_set_camera(app, (struct camera){ 0, 0 });
	for (int i = 0; i < CUTS; i++) {
		bench_draw_stroke(app, &pen, 620, 380 + 20 * i, 500, 280, 32, NULL);
		cut(app, &pen, 5 * i);
	}
	for (size_t i = 0; i < app->doc.nops; i++) {
		const struct history_mark *m = history_mark(&app->history, i + 1);

		kinds[app->doc.ops[i].kind]++;
		cuts += app->doc.ops[i].kind == DOC_OP_STROKE && m && !m->grew;
	}
	printf("\n%zu edits: %zu strokes (%zu cuts), 3D, %zu clones added, %zu removed, %zu "
	       "propagations, %zu grow; %zu branches, %zu leaves\n",
	       app->doc.nops, kinds[DOC_OP_STROKE], cuts, kinds[DOC_OP_CLONE_ADD],
	       kinds[DOC_OP_CLONE_REMOVE], kinds[DOC_OP_PROPAGATE], kinds[DOC_OP_GROW],
	       app->tree.nbranches, app->tree.nleaves);
	snprintf(name, sizeof(name), "rebuild %zu ops", app->doc.nops);
	row(name, (double)app->doc.nops, bench_run(rebuild, app, bench_reps(3)), &reb);
	snprintf(name, sizeof(name), "load %zu ops", app->doc.nops);
	row(name, (double)app->doc.nops, load(app, bench_reps(3), &loaded), &ld);
	walk(loaded, &undo, &redo);
	print_walk("undo", (double)app->doc.nops, &undo, "appended", "changed", any);
	print_walk("redo", (double)app->doc.nops, &redo, "appended", "changed", any + 2);
	print_kinds("undo", &undo);
	print_kinds("redo", &redo);
	walk_finish(&undo);
	walk_finish(&redo);
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
