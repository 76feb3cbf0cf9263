/* SPDX-License-Identifier: MIT */
/*
 * The grow button in the app (issue 17): a press is an undoable op of the drawing, the
 * first on a tree registering its thick branches; undo, redo and a saved drawing give the
 * same wood bit for bit; the voxelised branches' swept bark gives way to the wood's; an
 * edit that changes the branches drops the wood, one that adds to them keeps it.
 */
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
	test_edits();
	return 0;
}
