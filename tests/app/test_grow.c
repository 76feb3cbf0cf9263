/* SPDX-License-Identifier: MIT */
/*
 * The grow button in the app (issue 17): a press is an undoable op of the drawing, the
 * first on a tree registering its thick branches; undo, redo and a saved drawing give the
 * same wood bit for bit; the voxelised branches' swept bark gives way to the wood's; an
 * edit that changes the branches drops the wood, one that adds to them keeps it.
 */
#include <errno.h>
#include <string.h>

#include "app.h"
#include "app_private.h"
#include "buf.h"
#include "doc.h"
#include "pen.h"
#include "test.h"
#include "wood.h"

static struct pen pen = { .now_us = 1000, .steps = 10, .pause_us = PEN_PAUSE_US };

/* A thick trunk and limbs, made 3D. */
static struct app *drawn_tree(void)
{
	struct app *app = app_create(1280, 800, 5);

	CHECK(app);
	pen_line(&pen, app, 640, 736, 640, 236);
	pen_line(&pen, app, 640, 536, 880, 400);
	pen_line(&pen, app, 640, 480, 410, 350);
	pen_button(&pen, app, BUTTON_3D);
	CHECK(app->tree.lifted);
	return app;
}

static bool same_wood(const struct wood *a, const struct wood *b)
{
	return a && b && a->presses == b->presses && a->g.nx == b->g.nx && a->g.ny == b->g.ny &&
	       a->g.nz == b->g.nz &&
	       memcmp(a->g.density, b->g.density, wood_cells(&a->g) * sizeof(double)) == 0 &&
	       a->bark.nindices == b->bark.nindices &&
	       memcmp(a->bark.positions, b->bark.positions, 3 * a->bark.nvertices * sizeof(float)) == 0;
}

/* The volume a closed mesh holds (the divergence theorem). */
static double volume(const struct mesh *m)
{
	double v = 0.0;

	for (size_t i = 0; i + 2 < m->nindices; i += 3) {
		const float *a = m->positions + 3 * m->indices[i];
		const float *b = m->positions + 3 * m->indices[i + 1];
		const float *c = m->positions + 3 * m->indices[i + 2];

		v += (double)a[0] * ((double)b[1] * c[2] - (double)b[2] * c[1]) -
		     (double)a[1] * ((double)b[0] * c[2] - (double)b[2] * c[0]) +
		     (double)a[2] * ((double)b[0] * c[1] - (double)b[1] * c[0]);
	}
	return v / 6.0;
}

/* A press's bark swells on screen over a second by the events' time: a frame an eighth,
 * each holding more wood than the one before, then the bark at rest; undo shows it at
 * rest at once. */
static void test_swell(void)
{
	struct app *app = drawn_tree();
	const struct wood *w;
	uint64_t t;
	double last = 0.0;

	pen_button(&pen, app, BUTTON_GROW);
	pen_button(&pen, app, BUTTON_GROW);
	w = app->tree.wood;
	CHECK(w != NULL);
	CHECK_INT(w->nswell, WOOD_SWELL_FRAMES - 1);
	t = app->doc.ops[app->doc.cursor - 1].time_us;
	CHECK(app_wood_bark_at(app, UINT64_MAX) == &w->bark);
	for (int k = 0; k < WOOD_SWELL_FRAMES; k++) {
		const struct mesh *m = app_wood_bark_at(app, t + (uint64_t)k * APP_SWELL_US /
								  WOOD_SWELL_FRAMES + 1000);
		double v = volume(m);

		CHECK(m == (k < w->nswell ? &w->swell[k] : &w->bark));
		CHECK(v >= last);
		last = v;
	}
	CHECK(app_wood_bark_at(app, t + APP_SWELL_US) == &w->bark);
	pen_button(&pen, app, BUTTON_UNDO);
	CHECK(app->tree.wood != NULL);
	CHECK(app_wood_bark_at(app, t + 1000) == &app->tree.wood->bark);
	app_destroy(app);
}

/* The kiosk's press off its loop: asked for, made on a copy (here on this thread, as the
 * kiosk's worker does), handed back; the same tree as a press on the loop, bit for bit. A
 * copy made before the tree changed is refused and made again. */
static void test_async(void)
{
	struct app *a = drawn_tree(), *s = drawn_tree();
	struct tree copy;
	struct wood_params p;
	uint64_t serial;

	a->grow_async = true;
	pen_button(&pen, a, BUTTON_GROW);
	pen_button(&pen, s, BUTTON_GROW);
	CHECK(app_take_requests(a) & APP_REQUEST_GROW);
	CHECK(a->grow_waiting && a->tree.wood == NULL);
	CHECK_INT(app_status_at(a, pen.now_us, NULL), APP_STATUS_GROWING);
	/* a second press while one is under way asks nothing more */
	pen_button(&pen, a, BUTTON_GROW);
	CHECK(!(app_take_requests(a) & APP_REQUEST_GROW));
	tree_init(&copy);
	CHECK_INT(app_grow_job(a, &copy, &p, &serial), 0);
	/* the visitor draws meanwhile: that copy is stale */
	pen_line(&pen, a, 640, 300, 560, 200);
	pen_line(&pen, s, 640, 300, 560, 200);
	CHECK_INT(wood_grow(&copy, &p), 0);
	CHECK_INT(app_grow_done(a, &copy, serial, pen.now_us), -EAGAIN);
	CHECK(a->tree.wood == NULL && a->grow_waiting);
	tree_clear(&copy);
	/* the job again, of the tree as it is now */
	CHECK_INT(app_grow_job(a, &copy, &p, &serial), 0);
	CHECK_INT(wood_grow(&copy, &p), 0);
	CHECK_INT(app_grow_done(a, &copy, serial, pen.now_us), 0);
	CHECK(!a->grow_waiting);
	CHECK_INT(app_status_at(a, pen.now_us, NULL), APP_STATUS_NONE);
	CHECK_INT(a->doc.ops[a->doc.cursor - 1].kind, DOC_OP_GROW);
	/* the same as the press made on the loop, the stroke before it */
	pen_button(&pen, s, BUTTON_UNDO);
	pen_button(&pen, s, BUTTON_UNDO);
	pen_line(&pen, s, 640, 300, 560, 200);
	pen_button(&pen, s, BUTTON_GROW);
	CHECK(same_wood(a->tree.wood, s->tree.wood));
	CHECK_INT(a->tree.nbranches, s->tree.nbranches);
	for (size_t i = 0; i < a->tree.nbranches; i++)
		CHECK(memcmp(a->tree.branches[i].radii, s->tree.branches[i].radii,
			     a->tree.branches[i].npoints * sizeof(double)) == 0);
	CHECK_INT(a->mesh.bark.nindices, s->mesh.bark.nindices);
	tree_finish(&copy);
	app_destroy(a);
	app_destroy(s);
}

static void test_presses(void)
{
	struct app *app = drawn_tree(), *back = app_create(1280, 800, 1);
	struct wood one;
	size_t bark_before = app->mesh.bark.nindices;
	struct buf b;
	struct doc d;
	struct error err = { { 0 } };

	CHECK(back);
	CHECK(app->tree.wood == NULL);
	pen_button(&pen, app, BUTTON_GROW);
	CHECK(app->tree.wood != NULL);
	CHECK_INT(app->tree.wood->presses, 1);
	CHECK_INT(app->doc.ops[app->doc.cursor - 1].kind, DOC_OP_GROW);
	/* the trunk is the wood's now: its swept tube is gone from the tree's mesh */
	CHECK(tree_branch_in_wood(&app->tree, 0));
	CHECK(app->mesh.bark.nindices < bark_before);
	CHECK(app->tree.wood->bark.nindices > 0);
	CHECK_INT(wood_copy(&one, app->tree.wood), 0);
	pen_button(&pen, app, BUTTON_GROW);
	CHECK_INT(app->tree.wood->presses, 2);
	CHECK(!same_wood(&one, app->tree.wood));
	pen_button(&pen, app, BUTTON_UNDO);
	CHECK(same_wood(&one, app->tree.wood));
	pen_button(&pen, app, BUTTON_UNDO);
	CHECK(app->tree.wood == NULL);
	CHECK_INT(app->mesh.bark.nindices, bark_before);
	pen_button(&pen, app, BUTTON_REDO);
	CHECK(same_wood(&one, app->tree.wood));
	pen_button(&pen, app, BUTTON_REDO);
	CHECK_INT(app->tree.wood->presses, 2);

	/* saved and loaded: the same wood */
	buf_init(&b);
	CHECK_INT(doc_serialize(&app->doc, &app->tree, &b), 0);
	CHECK(strstr((const char *)b.data, "\ngrow "));
	CHECK_INT(doc_parse((const char *)b.data, b.len, "g.edaha", &d, &err), 0);
	CHECK_INT(app_load_doc(back, &d), 0);
	CHECK(same_wood(back->tree.wood, app->tree.wood));
	CHECK_INT(back->mesh.bark.nindices, app->mesh.bark.nindices);
	buf_finish(&b);
	doc_finish(&d);
	wood_finish(&one);
	app_destroy(back);
	app_destroy(app);
}

/* A branch drawn on the grown tree keeps the wood (it shows its swept bark beside it); a
 * limb taken away drops it; so does a new drawing. */
static void test_edits(void)
{
	struct app *app = drawn_tree();
	size_t nb;

	pen_button(&pen, app, BUTTON_GROW);
	CHECK(app->tree.wood != NULL);
	nb = app->tree.nbranches;
	pen_line(&pen, app, 640, 420, 760, 300);
	CHECK(app->tree.nbranches > nb);
	CHECK(app->tree.wood != NULL);
	CHECK(!tree_branch_in_wood(&app->tree, app->tree.nbranches - 1));
	/* the clone mode's anticlockwise circle: the trunk's newest limb taken away */
	nb = app->tree.nbranches;
	CHECK_INT(app_push_edit(app, DOC_OP_CLONE_REMOVE, 0, 0, pen.now_us), 0);
	CHECK(app->tree.nbranches < nb);
	CHECK(app->tree.wood == NULL);
	pen_button(&pen, app, BUTTON_GROW);
	CHECK(app->tree.wood != NULL);
	pen_button(&pen, app, BUTTON_NEW);
	CHECK(app->tree.wood == NULL);
	app_destroy(app);
}

int main(void)
{
	test_presses();
	test_swell();
	test_async();
	test_edits();
	return 0;
}
