/* SPDX-License-Identifier: MIT */
/* The state machine: events in, document and tree out; undo/redo/new; rebuild = incremental. */
#include <string.h>

#include "app.h"
#include "layout.h"
#include "pen.h"
#include "test.h"

/* buttons held 50 ms */
static struct pen pen = { .now_us = 1000, .hold_us = 50000 };

static void draw_line(struct app *app, double x0, double y0, double x1, double y1)
{
	pen_event(&pen, app, EVENT_PROXIMITY_IN, EVENT_TOOL_PEN, x0, y0, 0);
	pen_event(&pen, app, EVENT_TIP_DOWN, EVENT_TOOL_PEN, x0, y0, 0.3);
	for (int i = 1; i <= 30; i++)
		pen_event(&pen, app, EVENT_MOTION, EVENT_TOOL_PEN, x0 + (x1 - x0) * i / 30,
			  y0 + (y1 - y0) * i / 30, 0.6);
	pen_event(&pen, app, EVENT_TIP_UP, EVENT_TOOL_PEN, x1, y1, 0);
	pen_event(&pen, app, EVENT_PROXIMITY_OUT, EVENT_TOOL_PEN, x1, y1, 0);
}

static void draw_loop(struct app *app, double cx, double cy, double r)
{
	pen_event(&pen, app, EVENT_TIP_DOWN, EVENT_TOOL_PEN, cx + r, cy, 0.5);
	for (int i = 1; i <= 36; i++)
		pen_event(&pen, app, EVENT_MOTION, EVENT_TOOL_PEN, cx + r * cos(i * 0.17),
			  cy + r * sin(i * 0.17), 0.5);
	pen_event(&pen, app, EVENT_TIP_UP, EVENT_TOOL_PEN, cx + r * cos(36 * 0.17),
		  cy + r * sin(36 * 0.17), 0);
}

static void same_mesh(const struct mesh *a, const struct mesh *b)
{
	CHECK_INT(a->nvertices, b->nvertices);
	CHECK_INT(a->nindices, b->nindices);
	CHECK(memcmp(a->positions, b->positions, a->nvertices * 3 * sizeof(float)) == 0);
	CHECK(memcmp(a->normals, b->normals, a->nvertices * 3 * sizeof(float)) == 0);
	CHECK(memcmp(a->indices, b->indices, a->nindices * sizeof(uint32_t)) == 0);
}

static void same_tree(const struct tree *a, const struct tree *b)
{
	CHECK_INT(a->nbranches, b->nbranches);
	CHECK_INT(a->nleaves, b->nleaves);
	for (size_t i = 0; i < a->nbranches; i++) {
		CHECK_INT(a->branches[i].npoints, b->branches[i].npoints);
		CHECK(memcmp(a->branches[i].points, b->branches[i].points,
			     a->branches[i].npoints * sizeof(struct vec3)) == 0);
	}
}

int main(void)
{
	struct app *app = app_create(1280, 800, 5), *copy;
	struct tree snapshot;
	struct doc d;
	struct buf buf;
	struct error err = { { 0 } };
	double tx, ty;

	CHECK(app);
	draw_line(app, 640, 736, 630, 330);  /* trunk */
	draw_line(app, 636, 520, 860, 380);  /* starts on the trunk */
	draw_line(app, 660, 440, 420, 300);  /* starts a little off it */
	draw_loop(app, 880, 370, 20);        /* leaf near the first branch's tip */
	CHECK_INT(app->failed, 0);
	CHECK_INT(app->doc.nops, 4);
	CHECK_INT(app->tree.nbranches, 3);
	CHECK_INT(app->tree.nleaves, 1);
	CHECK_INT(app->tree.branches[1].parent, 0);
	CHECK_INT(app->tree.branches[2].parent, 0);
	CHECK_INT(app->tree.leaves[0].branch, 1);
	CHECK(app->mesh.bark.nindices > 0 && app->mesh.leaves.nindices > 0);
	/* meshes grown stroke by stroke are the bytes of a full rebuild */
	{
		struct tree_mesh full;

		tree_mesh_init(&full);
		CHECK_INT(tree_mesh_build(&full, &app->tree), 0);
		same_mesh(&full.bark, &app->mesh.bark);
		same_mesh(&full.leaves, &app->mesh.leaves);
		tree_mesh_finish(&full);
	}
	/* the tip of a drawn branch stays where the pen lifted, to 0.5 px */
	screen_from_world(&app->screen, app->tree.branches[2].points[app->tree.branches[2].npoints - 1],
		       &tx, &ty);
	CHECK_NEAR(tx, 420, 0.5);
	CHECK_NEAR(ty, 300, 0.5);

	/* undo twice, redo twice: the same tree */
	tree_init(&snapshot);
	for (size_t i = 0; i < app->tree.nbranches; i++) {
		const struct branch *b = &app->tree.branches[i];

		CHECK(tree_add_branch(&snapshot, b->parent, b->parent_t, b->origin, b->points, b->radii,
				      b->npoints) >= 0);
	}
	for (size_t i = 0; i < app->tree.nleaves; i++) {
		const struct leaf *l = &app->tree.leaves[i];

		CHECK(tree_add_leaf(&snapshot, l->branch, l->origin, l->points, l->npoints) >= 0);
	}
	pen_button(&pen, app, BUTTON_UNDO);
	pen_button(&pen, app, BUTTON_UNDO);
	CHECK_INT(app->tree.nbranches, 2);
	CHECK_INT(app->tree.nleaves, 0);
	pen_button(&pen, app, BUTTON_REDO);
	pen_button(&pen, app, BUTTON_REDO);
	pen_button(&pen, app, BUTTON_REDO); /* nothing left to redo */
	same_tree(&app->tree, &snapshot);

	/* new clears, and is itself undoable */
	pen_button(&pen, app, BUTTON_NEW);
	CHECK_INT(app->tree.nbranches, 0);
	pen_button(&pen, app, BUTTON_UNDO);
	same_tree(&app->tree, &snapshot);

	/* the pen taps the on-screen buttons: undo, then redo */
	{
		struct layout_button buttons[LAYOUT_NBUTTONS];
		size_t n = layout_buttons(&app->screen, buttons, LAYOUT_NBUTTONS);

		for (size_t i = 0; i < n; i++) {
			double cx = buttons[i].x + buttons[i].w / 2, cy = buttons[i].y + buttons[i].h / 2;

			if (buttons[i].button != BUTTON_UNDO && buttons[i].button != BUTTON_REDO)
				continue;
			pen_event(&pen, app, EVENT_TIP_DOWN, EVENT_TOOL_PEN, cx, cy, 0.5);
			CHECK(app->buttons_down[buttons[i].button]);
			CHECK(!app->stroke.active);
			pen_event(&pen, app, EVENT_TIP_UP, EVENT_TOOL_PEN, cx, cy, 0);
			CHECK(!app->buttons_down[buttons[i].button]);
			CHECK_INT(app->tree.nleaves, buttons[i].button == BUTTON_UNDO ? 0 : 1);
		}
		CHECK_INT(app->doc.nops, 5);
	}

	/* modes toggle; on a sketch an editing mode makes it 3D first, as its own undoable
	 * step (undoing it goes back to the sketch mode); export is a request for platform/ */
	pen_button(&pen, app, BUTTON_LEAF);
	CHECK_INT(app->mode, APP_MODE_LEAF);
	CHECK(app->tree.lifted);
	CHECK_INT(app->doc.ops[app->doc.cursor - 1].kind, DOC_OP_LIFT);
	pen_button(&pen, app, BUTTON_LEAF);
	CHECK_INT(app->mode, APP_MODE_SKETCH);
	pen_button(&pen, app, BUTTON_CLONE);
	CHECK_INT(app->mode, APP_MODE_CLONE);
	CHECK_INT(app->doc.ops[app->doc.cursor - 2].kind, DOC_OP_STROKE); /* already 3D */
	pen_button(&pen, app, BUTTON_UNDO);
	CHECK(!app->tree.lifted);
	CHECK_INT(app->mode, APP_MODE_SKETCH);
	pen_button(&pen, app, BUTTON_EXPORT);
	CHECK_INT(app_take_requests(app), APP_REQUEST_EXPORT);
	CHECK_INT(app_take_requests(app), 0);
	/* the answer: a message for APP_STATUS_US; a held one (saving) until the next */
	{
		uint64_t until;

		app_set_status(app, APP_STATUS_SAVED, 1000);
		CHECK_INT(app_status_at(app, 999, NULL), APP_STATUS_NONE);
		CHECK_INT(app_status_at(app, 1000, &until), APP_STATUS_SAVED);
		CHECK_INT(until, 1000 + APP_STATUS_US);
		CHECK_INT(app_status_at(app, until, NULL), APP_STATUS_NONE);
		app_hold_status(app, APP_STATUS_SAVING, 2000);
		CHECK_INT(app_status_at(app, 2000 + 3600u * 1000000u, &until), APP_STATUS_SAVING);
		CHECK(until == UINT64_MAX);
		app_set_status(app, APP_STATUS_SAVED_USB, 5000);
		CHECK_INT(app_status_at(app, 5000 + APP_STATUS_US, NULL), APP_STATUS_NONE);
		app_hold_status(app, APP_STATUS_NONE, 6000);
		CHECK(!app->status_held);
		app_set_status(app, APP_STATUS_COUNT, 7000); /* out of range: none */
		CHECK_INT(app_status_at(app, 7000, NULL), APP_STATUS_NONE);
	}

	/* 3D: the lift is one undoable edit; the front view stays the sketch */
	{
		size_t nb = app->tree.nbranches;
		struct vec3 tip = app->tree.branches[1].points[app->tree.branches[1].npoints - 1];
		const struct branch *nb3;
		double z;

		pen_button(&pen, app, BUTTON_3D);
		CHECK(app->tree.lifted);
		CHECK_INT(app->doc.ops[app->doc.cursor - 1].kind, DOC_OP_LIFT);
		CHECK(app->tree.nbranches > nb); /* the turned copy was merged in */
		CHECK_NEAR(app->tree.branches[1].points[app->tree.branches[1].npoints - 1].x, tip.x, 1e-9);
		CHECK_NEAR(app->tree.branches[1].points[app->tree.branches[1].npoints - 1].y, tip.y, 1e-9);
		pen_button(&pen, app, BUTTON_3D); /* once is enough */
		CHECK_INT(app->doc.ops[app->doc.cursor - 2].kind, DOC_OP_STROKE);
		/* a branch drawn on the 3D tree lies in the plane of its attachment point */
		draw_line(app, 634, 600, 500, 560);
		nb3 = &app->tree.branches[app->tree.nbranches - 1];
		z = nb3->points[0].z;
		CHECK_INT(nb3->parent, 0);
		for (size_t i = 0; i < nb3->npoints; i++)
			CHECK_NEAR(nb3->points[i].z, z, 1e-12);
		pen_button(&pen, app, BUTTON_UNDO);
		pen_button(&pen, app, BUTTON_UNDO);
		CHECK(!app->tree.lifted);
		CHECK_INT(app->tree.nbranches, nb);
		pen_button(&pen, app, BUTTON_REDO);
		CHECK(app->tree.lifted);
	}

	/* saved and loaded, the document rebuilds the same tree */
	buf_init(&buf);
	CHECK_INT(doc_serialize(&app->doc, &app->tree, &buf), 0);
	CHECK_INT(doc_parse((const char *)buf.data, buf.len, "t.edaha", &d, &err), 0);
	copy = app_create(640, 400, 99);
	CHECK(copy);
	CHECK_INT(app_load_doc(copy, &d), 0);
	same_tree(&copy->tree, &app->tree);
	CHECK(copy->doc.seed == 5);

	buf_finish(&buf);
	tree_finish(&snapshot);
	app_destroy(copy);
	app_destroy(app);
	return 0;
}
