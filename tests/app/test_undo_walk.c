/* SPDX-License-Identifier: MIT */
/*
 * The property behind undo and redo (docs/editing.md, "Undo and redo"), on 300 seeded
 * random sessions: strokes, cuts, erasures, leaves, 3D, turned views, clones added and
 * removed, arrangements, propagations, the season, leaf kinds, vines, generated trees
 * and their parameter buttons, a year of wood now and then; undo and redo pressed in
 * random runs, the whole history walked back and forth at the end. After every press of
 * undo or redo the app must hold exactly what a fresh app replaying its document holds:
 * tree (every field), generator, meshes (bytes), camera.
 *
 * And each press must cost what its op changed, not what the drawing holds: no op
 * replayed, no meshes built whole, and parts built only for elements the op took out,
 * put in or changed and those hanging on them (a part depends on its branch's parent and
 * grandparent, mesh.h). The worst share of the tree's elements one press meshed is
 * printed, as are the counts.
 */
#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "app.h"
#include "gen.h"
#include "layout.h"
#include "pen.h"
#include "rng.h"
#include "session.h"
#include "test.h"
#include "tree_delta.h"
#include "wood.h"

#define SESSIONS 300

static struct pen clock = { .now_us = 1000 };
static struct app *ref; /* replays each document */
static long presses, states, grows, vines, generated, removals, cuts_or_erasures;
static double worst_share; /* parts meshed by one press / elements of the tree */
static size_t worst_meshed;

/* ---- the reference ---- */

static void same_as_replay(const struct app *a)
{
	struct doc d;

	session_copy_doc(&d, &a->doc);
	CHECK_INT(app_load_doc(ref, &d), 0);
	doc_finish(&d);
	same_tree(&a->tree, &ref->tree);
	SAME(a->rng, ref->rng);
	SAME(a->camera, ref->camera);
	same_mesh(&a->mesh.bark, &ref->mesh.bark);
	same_mesh(&a->mesh.leaves, &ref->mesh.leaves);
	states++;
}

/* ---- what one press may cost ---- */

/* Branches of t (at side s of d) whose parts a press to it may have to build: those side s
 * lists, and those hanging on them within two generations (their parts depend on them). */
static size_t may_mesh(const struct tree *t, const struct tree_delta *d, int s)
{
	const struct tree_delta_side *side = &d->side[s];
	bool *dirty = calloc(t->nbranches + 1, sizeof(*dirty));
	size_t n = side->nl;

	CHECK(dirty);
	for (size_t q = 0; q < side->nb; q++)
		dirty[side->branch_at[q]] = true;
	for (size_t i = 0; i < t->nbranches; i++) {
		int p = t->branches[i].parent;
		bool up = p >= 0 && (dirty[p] || (t->branches[p].parent >= 0 &&
						  dirty[t->branches[p].parent]));

		/* (dirty[] of a parent counts its own listing only: two generations) */
		n += dirty[i] || up;
	}
	free(dirty);
	/* wood that came or went changes the parts of the branches it holds (mesh.h) */
	if (d->wood)
		for (int k = 0; k < 2; k++) {
			const struct wood *w = k == s ? t->wood : d->side[k].wood;

			for (size_t i = 0; w && i < w->nbranches; i++)
				n += w->voxelised[i];
		}
	return n;
}

/* Undo or redo, checked against a replay, and its cost against what its op changed. */
static void step(struct app *app, enum button b)
{
	bool undo = b == BUTTON_UNDO;
	size_t k = undo ? app->doc.cursor : app->doc.cursor + 1;
	const struct tree_delta *d;
	size_t bound, total;
	int to;

	if (undo ? !doc_can_undo(&app->doc) : !doc_can_redo(&app->doc))
		return;
	pen_button(&clock, app, b);
	CHECK_INT(app->failed, 0);
	presses++;
	/* the delta the press used: op k's, now holding the side the tree left */
	d = history_delta(&app->history, k);
	CHECK_INT(app->history.work.replayed, 0);
	CHECK(!app->history.work.full_mesh);
	to = undo ? 0 : 1;
	if (d) {
		CHECK_INT(d->stored, !to);
		bound = may_mesh(&app->tree, d, to);
	} else {
		/* an op that only appended, redone: its parts at most */
		const struct history_mark *m = history_mark(&app->history, k - 1);

		CHECK(!undo && m);
		bound = app->tree.nbranches - m->nbranches + app->tree.nleaves - m->nleaves;
	}
	CHECK(app->history.work.meshed <= bound);
	total = app->tree.nbranches + app->tree.nleaves;
	if (total && (double)app->history.work.meshed / (double)total > worst_share)
		worst_share = (double)app->history.work.meshed / (double)total;
	if (app->history.work.meshed > worst_meshed)
		worst_meshed = app->history.work.meshed;
	same_as_replay(app);
}

/* ---- a visitor ---- */

static void press(struct app *app, enum button b)
{
	pen_button(&clock, app, b);
}

/* A small generated tree, as the New strip's templates and --generate make them. */
static void generate(struct app *app, struct rng *r)
{
	struct gen_params p;

	switch (rng_next(r) % 3) {
	case 0:
		gen_params_default(&p, GEN_PALM);
		p.fronds = 4;
		p.leaf_amount = 4;
		break;
	case 1:
		gen_params_default(&p, GEN_LSYSTEM);
		p.levels = 3;
		break;
	default:
		gen_params_default(&p, GEN_SHRUB);
		p.levels = 3;
		break;
	}
	p.randomness = rng_uniform(r);
	CHECK_INT(app_generate(app, &p, clock.now_us), 0);
	clock.now_us += PEN_PAUSE_US;
	generated++;
}

/* One thing a visitor does (undo and redo runs included). */
static void act(struct app *app, struct rng *r, int *propagations, bool may_grow)
{
	unsigned what = (unsigned)(rng_next(r) % 100);
	size_t nb = app->tree.nbranches;
	double x, y;

	if (app->tree.nbranches == 0 && what >= 8 && what < 80)
		what = rng_next(r) % 4 ? 0 : 79; /* a trunk first, or a generated tree */
	if (what < 8) {
		x = rng_range(r, 300, app->screen.width - 300);
		y = app->screen.height * 0.9;
		session_stroke(&clock, app, x, y, x + rng_range(r, -30, 30), y - rng_range(r, 250, 450),
			       30, EVENT_TOOL_PEN, PEN_PAUSE_US);
	} else if (what < 34) {
		if (session_pick(app, r, false, &x, &y))
			session_stroke(&clock, app, x, y, x + rng_range(r, -160, 160),
				       y - rng_range(r, 10, 140), 24, EVENT_TOOL_PEN, PEN_PAUSE_US);
	} else if (what < 41) {
		/* a slash across a branch, begun away from it: a cut */
		if (session_pick(app, r, false, &x, &y))
			session_stroke(&clock, app, x - 70, y - 50, x + 70, y + 50, 16, EVENT_TOOL_PEN,
				       PEN_PAUSE_US);
		cuts_or_erasures += app->tree.nbranches < nb;
	} else if (what < 44) {
		if (session_pick(app, r, false, &x, &y))
			session_stroke(&clock, app, x - 15, y, x + 15, y + 5, 8, EVENT_TOOL_ERASER,
				       PEN_PAUSE_US);
		cuts_or_erasures += app->tree.nbranches < nb;
	} else if (what < 50) {
		if (session_pick(app, r, false, &x, &y))
			session_loop(&clock, app, x, y - 14, 12, 1.0);
	} else if (what < 53) {
		press(app, BUTTON_3D);
	} else if (what < 55) {
		app_set_camera(app, (struct camera){ (float)rng_range(r, -80, 80),
						    (float)rng_range(r, -15, 40) });
	} else if (what < 62) {
		/* clone mode: a child more (two taps), or one less (a counter-clockwise circle) */
		press(app, BUTTON_CLONE);
		if (app->mode == APP_MODE_CLONE && session_pick(app, r, true, &x, &y)) {
			session_tap(&clock, app, x, y);
			if (what < 58)
				session_tap(&clock, app, x, y);
			else
				session_loop(&clock, app, x, y, 40, -1.0);
		}
		if (app->mode == APP_MODE_CLONE)
			press(app, BUTTON_CLONE);
		removals += app->tree.nbranches < nb;
	} else if (what < 66) {
		/* leaf mode: now and then a leaf kind, a leaf, its first suggestion */
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
	} else if (what < 69) {
		if (*propagations > 0) {
			press(app, BUTTON_PROPAGATE);
			if (app->mode == APP_MODE_PROPAGATE && session_pick(app, r, false, &x, &y)) {
				session_tap(&clock, app, x, y);
				(*propagations)--;
			}
			if (app->mode == APP_MODE_PROPAGATE)
				press(app, BUTTON_PROPAGATE);
		}
	} else if (what < 71) {
		press(app, BUTTON_SEASON);
	} else if (what < 74) {
		if (app_generated(app))
			press(app, (enum button)(BUTTON_GEN_MORE + rng_next(r) % 8));
		else if (app->tree.nbranches && app->tree.lifted && rng_next(r) % 2) {
			size_t nv = app->tree.nvines;

			press(app, BUTTON_VINE);
			if (app->mode == APP_MODE_VINE) {
				session_tap(&clock, app, app->screen.width / 2 + rng_range(r, -90, 90), app->screen.ground_y_px - 4);
				press(app, BUTTON_VINE);
			}
			vines += app->tree.nvines > nv;
		}
	} else if (what < 76) {
		if (may_grow && app->tree.lifted && app->tree.nbranches && app->tree.nbranches < 80) {
			press(app, BUTTON_GROW);
			grows += app->tree.wood != NULL;
		}
	} else if (what < 80) {
		if (rng_next(r) % 2)
			press(app, BUTTON_NEW);
		generate(app, r);
	} else {
		/* a run of undo or redo */
		enum button b = what < 92 ? BUTTON_UNDO : BUTTON_REDO;
		int n = 1 + (int)(rng_next(r) % 4);

		for (int i = 0; i < n; i++)
			step(app, b);
	}
	CHECK_INT(app->failed, 0);
}

static void session(uint64_t seed)
{
	struct app *app = app_create(1280, 800, seed);
	struct rng r;
	int propagations = 2, n;

	CHECK(app);
	rng_seed(&r, seed * 104729 + 7);
	n = 16 + (int)(rng_next(&r) % 20);
	for (int i = 0; i < n; i++)
		act(app, &r, &propagations, seed % 20 == 3); /* wood: slow to replay */
	/* all the way back and forth, then at random */
	while (doc_can_undo(&app->doc))
		step(app, BUTTON_UNDO);
	while (doc_can_redo(&app->doc))
		step(app, BUTTON_REDO);
	for (int i = 0; i < 16; i++)
		step(app, rng_next(&r) % 3 ? BUTTON_UNDO : BUTTON_REDO);
	app_destroy(app);
}

int main(void)
{
	int sessions = test_cases(SESSIONS);

	ref = app_create(1280, 800, 1);
	CHECK(ref);
	for (uint64_t seed = 1; seed <= (uint64_t)sessions; seed++)
		session(seed);
	app_destroy(ref);
	fprintf(stderr,
		"%d sessions: %ld presses of undo or redo, %ld states compared with a full replay; "
		"%ld clone removals, %ld cuts or erasures, %ld generated trees, %ld vines, %ld "
		"grow presses; worst press meshed %zu parts, %.1f%% of its tree's elements\n",
		sessions, presses, states, removals, cuts_or_erasures, generated, vines, grows,
		worst_meshed, 100.0 * worst_share);
	CHECK(removals > 0 && cuts_or_erasures > 0 && generated > 0 && vines > 0 && grows > 0);
	return 0;
}
