/* SPDX-License-Identifier: MIT */
/*
 * Undo, redo and --load take quicker paths than replaying the whole document (marks,
 * deltas, checkpoints: src/doc/history.h, src/doc/tree_delta.h, src/app/app_history.c). After every step of
 * long random sessions (strokes, cuts, erasures, two-outline branches, leaves, 3D, turned
 * views, clones added and removed, arrangements, propagations, new, undo and redo runs)
 * the app must hold exactly what a fresh app replaying its document from scratch holds:
 * tree (every field), generator, meshes, camera. Also with checkpoints squeezed out by a
 * tiny budget, on a loaded document, and with an allocation failing at every point of an
 * undo or redo.
 */
#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "app.h"
#include "fail_alloc.h"
#include "layout.h"
#include "pen.h"
#include "rng.h"
#include "session.h"
#include "test.h"

static struct pen clock = { .now_us = 1000 }; /* the apps' events, all on one clock */
static long checks;
static long vines_planted; /* by the sessions' taps in the vine mode */
static long grows;         /* grow presses that left the tree with wood */
#define MAX_GROWS 1

/* ---- the reference: the document replayed from scratch ---- */

/* The same document with every stroke mirrored: a different tree at every state. */
static void mirror_doc(struct doc *d)
{
	for (size_t i = 0; i < d->nops; i++)
		for (size_t k = 0; k < d->ops[i].npoints; k++)
			d->ops[i].points[k].x = -d->ops[i].points[k].x;
}

static struct app *loaded(const struct app *a)
{
	struct app *b = app_create(a->screen.width, a->screen.height, a->doc.seed);
	struct doc d;

	CHECK(b);
	session_copy_doc(&d, &a->doc);
	CHECK_INT(app_load_doc(b, &d), 0);
	doc_finish(&d);
	return b;
}

/* What the app's rebuild makes of its document, and the app holds, are the same. */
static void same_as_replay(const struct app *a, bool mesh_may_be_empty)
{
	struct app *b = loaded(a);

	same_tree(&a->tree, &b->tree);
	SAME(a->rng, b->rng);
	SAME(a->camera, b->camera);
	if (!(mesh_may_be_empty && a->mesh.bark.nvertices == 0 && a->mesh.leaves.nvertices == 0)) {
		same_mesh(&a->mesh.bark, &b->mesh.bark);
		same_mesh(&a->mesh.leaves, &b->mesh.leaves);
	}
	if (!a->tree.lifted) {
		/* a sketch is drawn on (the New strip may be open on an empty canvas) */
		CHECK(a->mode == APP_MODE_SKETCH || (a->mode == APP_MODE_NEW && a->tree.nbranches == 0));
		CHECK(!a->turning);
	}
	app_destroy(b);
	checks++;
}

/* ---- a visitor ---- */

static void press(struct app *app, enum button b)
{
	pen_button(&clock, app, b);
}

static void canvas_point(const struct app *app, struct rng *r, double *x, double *y)
{
	enum button hit;

	do {
		*x = rng_range(r, 80, app->screen.width - 80);
		*y = rng_range(r, 80, app->screen.height - 80);
	} while (layout_hit(&app->screen, *x, *y, &hit) || layout_hit_view_button(&app->screen, *x, *y));
}

/* A tree from the New strip: the blank canvas or, as --generate puts them, a small
 * L-system tree, shrub or palm (the presets have hundreds to thousands of elements: the
 * sessions would take minutes; test_generate taps them). */
static void new_tree(struct app *app, struct rng *r)
{
	struct gen_params p;

	switch (rng_next(r) % 4) {
	case 0:
		press(app, BUTTON_TPL_BLANK);
		return;
	case 1:
		gen_params_default(&p, GEN_PALM);
		p.fronds = 5;
		p.leaf_amount = 6;
		break;
	case 2:
		gen_params_default(&p, GEN_LSYSTEM);
		p.levels = 4;
		break;
	default:
		gen_params_default(&p, GEN_SHRUB);
		p.levels = 3;
		break;
	}
	p.randomness = rng_uniform(r);
	CHECK_INT(app_generate(app, &p, clock.now_us), 0);
	clock.now_us += PEN_PAUSE_US;
}

/* One thing a visitor does; returns true if it was undo or redo. A gentle visitor seldom
 * cuts or erases, so the tree grows large. */
static bool act(struct app *app, struct rng *r, int *propagations, bool gentle)
{
	unsigned what = (unsigned)(rng_next(r) % 100);
	double x, y, x1, y1;

	if (gentle && what >= 33 && what < 44 && rng_next(r) % 4)
		what = 10;

	if (app->tree.nbranches == 0 && what >= 6)
		what = what < 60 ? 0 : what; /* a trunk first, mostly */
	if (what < 6) {
		canvas_point(app, r, &x, &y);
		y = app->screen.height * 0.9;
		session_stroke(&clock, app, x, y, x + rng_range(r, -30, 30), y - rng_range(r, 250, 500),
			       30, EVENT_TOOL_PEN, PEN_PAUSE_US);
	} else if (what < 33) {
		if (session_pick(app, r, false, &x, &y))
			session_stroke(&clock, app, x, y, x + rng_range(r, -160, 160),
				       y - rng_range(r, 10, 140), 24, EVENT_TOOL_PEN, PEN_PAUSE_US);
	} else if (what < 36) {
		/* anywhere: a branch, a cut or an erasure */
		canvas_point(app, r, &x, &y);
		canvas_point(app, r, &x1, &y1);
		session_stroke(&clock, app, x, y, x1, y1, 20, EVENT_TOOL_PEN, PEN_PAUSE_US);
	} else if (what < 41) {
		/* a slash across a branch, begun away from it */
		if (session_pick(app, r, false, &x, &y))
			session_stroke(&clock, app, x - 70, y - 50, x + 70, y + 50, 16, EVENT_TOOL_PEN,
				       PEN_PAUSE_US);
	} else if (what < 44) {
		if (session_pick(app, r, false, &x, &y))
			session_stroke(&clock, app, x - 15, y, x + 15, y + 5, 8, EVENT_TOOL_ERASER,
				       PEN_PAUSE_US);
	} else if (what < 48) {
		/* two outlines of one branch, drawn one right after the other */
		if (session_pick(app, r, false, &x, &y)) {
			double dx = rng_range(r, -120, 120), dy = -rng_range(r, 60, 160);

			session_stroke(&clock, app, x, y, x + dx, y + dy, 20, EVENT_TOOL_PEN, 300000);
			session_stroke(&clock, app, x + 12, y, x + dx + 6, y + dy, 20, EVENT_TOOL_PEN,
				       PEN_PAUSE_US);
		}
	} else if (what < 55) {
		if (session_pick(app, r, false, &x, &y))
			session_loop(&clock, app, x, y - 14, 12, 1.0);
	} else if (what < 57) {
		press(app, BUTTON_3D);
	} else if (what < 61) {
		app_set_camera(app, (struct camera){ (float)rng_range(r, -80, 80),
						    (float)rng_range(r, -15, 40) });
	} else if (what < 62) {
		press(app, BUTTON_VIEW);
	} else if (what < 68) {
		press(app, BUTTON_CLONE);
		if (session_pick(app, r, true, &x, &y)) {
			session_tap(&clock, app, x, y);
			if (what < 65)
				session_tap(&clock, app, x, y);
			else
				session_loop(&clock, app, x, y, 40, what < 66 ? 1.0 : -1.0);
		}
		if (app->mode == APP_MODE_CLONE)
			press(app, BUTTON_CLONE);
	} else if (what < 70) {
		if (*propagations > 0) {
			press(app, BUTTON_PROPAGATE);
			if (rng_next(r) % 2)
				press(app, rng_next(r) % 2 ? BUTTON_FIXED_COUNT : BUTTON_FIXED_SIZE);
			if (session_pick(app, r, false, &x, &y)) {
				session_tap(&clock, app, x, y);
				(*propagations)--;
			}
			if (app->mode == APP_MODE_PROPAGATE)
				press(app, BUTTON_PROPAGATE);
		}
	} else if (what < 74) {
		/* leaf mode: now and then a leaf card (issue 15), a leaf, its first suggestion */
		press(app, BUTTON_LEAF);
		if (app->mode == APP_MODE_LEAF && rng_next(r) % 2)
			press(app, (enum button)(BUTTON_LEAF_DRAWN + rng_next(r) % 4));
		if (app->mode == APP_MODE_LEAF && session_pick(app, r, false, &x, &y)) {
			struct layout_rect s = layout_side_slot(&app->screen, 0, LAYOUT_SIDE_CARDS);

			session_loop(&clock, app, x, y - 14, 12, 1.0);
			if (app->suggestions)
				session_tap(&clock, app, s.x + s.w / 2, s.y + s.h / 2);
		}
		if (app->mode == APP_MODE_LEAF)
			press(app, BUTTON_LEAF);
	} else if (what < 75) {
		if (rng_next(r) % 3 == 0) {
			press(app, BUTTON_NEW);
			/* the New strip: mostly a template, small ones (the sessions stay quick) */
			if (rng_next(r) % 3)
				new_tree(app, r);
		}
	} else if (what < 78) {
		/* a generated tree's parameter buttons, or the season (on any tree); now and then
		 * a vine tapped in at the trunk's foot, or a little beside it (issue 16) */
		if (app_generated(app) && rng_next(r) % 3) {
			press(app, (enum button)(BUTTON_GEN_MORE + rng_next(r) % 8));
		} else if (app->tree.lifted && grows < MAX_GROWS && rng_next(r) % 5 == 0) {
			/* a year of growth (issue 17): one in all, since every check after it
			 * replays its press (test_grow undoes and redoes presses) */
			press(app, BUTTON_GROW);
			grows += app->tree.wood != NULL;
		} else if (app->tree.nbranches && rng_next(r) % 3 == 0) {
			press(app, BUTTON_VINE);
			if (app->mode == APP_MODE_VINE) {
				size_t nv = app->tree.nvines;

				session_tap(&clock, app, app->screen.width / 2 + rng_range(r, -90, 90),
				    app->screen.ground_y_px - 4);
				vines_planted += app->tree.nvines > nv;
				press(app, BUTTON_VINE);
			}
		} else {
			press(app, BUTTON_SEASON);
		}
	} else if (what < 90) {
		press(app, BUTTON_UNDO);
		return true;
	} else {
		press(app, BUTTON_REDO);
		return true;
	}
	return false;
}

/* A session of n steps, checked after every undo and redo and every few other steps.
 * With a tiny budget only the two checkpoints nearest the cursor are kept. */
static void session(uint64_t seed, int n, bool tiny_budget, bool gentle)
{
	struct app *app = app_create(1280, 800, seed);
	struct app *again = app_create(1280, 800, seed); /* loads one document after another */
	struct rng r;
	int propagations = 2;

	CHECK(app && again);
	if (tiny_budget)
		app->history.budget = 1;
	rng_seed(&r, seed * 7919);
	for (int i = 0; i < n; i++) {
		bool walk = act(app, &r, &propagations, gentle);

		CHECK_INT(app->failed, 0);
		if (walk || i % 8 == 0)
			same_as_replay(app, false);
		if (tiny_budget)
			CHECK(app->history.ncps <= 2);
		/* now and then the drawing is loaded, and walked back and forth */
		if (i % 60 == 59) {
			struct app *l = loaded(app);
			int k = (int)(rng_next(&r) % 12);

			if (tiny_budget)
				l->history.budget = 1;
			for (int j = 0; j < k + 6; j++) {
				press(l, j < k || rng_next(&r) % 3 == 0 ? BUTTON_UNDO : BUTTON_REDO);
				same_as_replay(l, false);
			}
			app_destroy(l);
			/* what an app knew of the document before is forgotten on loading another */
			for (int mirrored = 1; mirrored >= 0; mirrored--) {
				struct doc d;

				session_copy_doc(&d, &app->doc);
				if (mirrored)
					mirror_doc(&d);
				CHECK_INT(app_load_doc(again, &d), 0);
				doc_finish(&d);
				same_as_replay(again, false);
				for (int j = 0; j < k + 6; j++) {
					press(again, j < k || rng_next(&r) % 3 == 0 ? BUTTON_UNDO : BUTTON_REDO);
					same_as_replay(again, false);
				}
			}
			CHECK_INT(app_reset(again, seed + 1), 0);
			same_as_replay(again, false);
		}
	}
	app_destroy(again);
	/* all the way back, and forth again */
	while (doc_can_undo(&app->doc)) {
		press(app, BUTTON_UNDO);
		same_as_replay(app, false);
	}
	while (doc_can_redo(&app->doc)) {
		press(app, BUTTON_REDO);
		same_as_replay(app, false);
	}
	app_destroy(app);
}

#if FAIL_ALLOC_HOOK /* allocation failures: not under sanitizers, which own malloc */
/* Each allocation of one undo or redo fails in turn: never a half-built tree; the state
 * is the replay's (the meshes may be left empty, with the failure reported). The app
 * first walks to state `at` the quick way, so that marks and checkpoints are used. */
static void oom_step(const struct app *orig, size_t at, enum button b)
{
	for (long n = 0;; n++) {
		struct app *a = loaded(orig);
		bool failed;
		long calls;

		while (a->doc.cursor > at)
			press(a, BUTTON_UNDO);
		fail_alloc_at(n);
		press(a, b);
		calls = fail_alloc_calls();
		fail_alloc_off();
		failed = a->failed != 0;
		CHECK(!failed || a->failed == -ENOMEM);
		same_as_replay(a, failed);
		app_destroy(a);
		if (calls <= n)
			return; /* got through without a failure */
	}
}

static void test_oom(void)
{
	struct app *app;
	struct rng r;
	int propagations = 1, changed = 0, lifts = 0;

	if (!fail_alloc_hooked())
		return;
	app = app_create(1280, 800, 3);
	CHECK(app);
	rng_seed(&r, 11);
	for (int i = 0; app->doc.nops < 90 && i < 400; i++)
		act(app, &r, &propagations, true);
	while (doc_can_redo(&app->doc))
		press(app, BUTTON_REDO);
	/* undoing ops that changed elements (from a checkpoint) and ones that appended;
	 * redoing a lift (from its checkpoint) and a stroke */
	for (size_t k = app->doc.nops; k > 0 && (changed < 3 || lifts < 1); k--) {
		const struct history_mark *m = history_mark(&app->history, k);

		if (m && !m->grew && changed < 3) {
			oom_step(app, k, BUTTON_UNDO);
			changed++;
		}
		if (app->doc.ops[k - 1].kind == DOC_OP_LIFT && lifts < 1) {
			oom_step(app, k - 1, BUTTON_REDO);
			lifts++;
		}
	}
	CHECK(changed == 3 && lifts == 1);
	oom_step(app, app->doc.nops, BUTTON_UNDO);
	oom_step(app, app->doc.nops - 1, BUTTON_REDO);
	app_destroy(app);
}
#else
static void test_oom(void)
{
}
#endif

int main(void)
{
	/* sessions of n steps, each state compared with a full replay: O(n^2), so half as
	 * long under the sanitizers (test.h); test_undo_walk.c walks 300 more sessions */
	int n = TEST_SANITIZED ? 60 : 120;

	for (uint64_t seed = 1; seed <= 4; seed++)
		session(seed, n, seed % 2 == 0, false);
	session(7, 3 * n / 2, false, true);
	session(8, n + n / 12, true, true);
	test_oom();
	fprintf(stderr, "%ld states compared with a full replay, %ld vines planted, %ld grow "
		"presses\n", checks, vines_planted, grows);
	CHECK(vines_planted > 0);
	CHECK(grows > 0);
	return 0;
}
