/* SPDX-License-Identifier: MIT */
/*
 * New after something was drawn leaves that drawing for the kiosk to archive and plant in
 * today's forest (app_take_replaced, issue 27): on 200 seeded random sessions (a few
 * strokes, sometimes 3D, sometimes a template first, then New):
 *
 * - with a tree on the canvas, New leaves exactly one drawing waiting: its tree the tree
 *   as it stood (field by field) and its cursor the ops then in effect, so the document
 *   with that cursor rebuilds the same tree; taking it twice gives it once;
 * - an empty canvas, or a second New before the first was taken, leaves nothing more;
 * - the document itself goes on as before (New recorded, undoable).
 */
#include <stdio.h>
#include <string.h>

#include "app.h"
#include "buf.h"
#include "doc.h"
#include "pen.h"
#include "rng.h"
#include "same.h"
#include "test.h"

static struct pen pen = { .now_us = 1000, .hold_us = 50000, .steps = 6 };

static void draw_some(struct app *app, struct rng *r)
{
	int strokes = 1 + (int)(rng_next(r) % 4);

	/* a trunk, then branches off it */
	pen_line(&pen, app, 640, 740, 640 + rng_range(r, -20, 20), 300 + rng_range(r, -50, 50));
	for (int i = 1; i < strokes; i++) {
		double y = rng_range(r, 420, 620);

		pen_line(&pen, app, 640, y, 640 + rng_range(r, -250, 250), y - rng_range(r, 60, 200));
	}
}

int main(void)
{
	struct rng r;
	size_t waited = 0, empty = 0, lifted = 0;
	int n = test_cases(200);

	rng_seed(&r, 2727);
	for (int c = 0; c < n; c++) {
		struct app *app = app_create(1280, 800, 1 + (uint64_t)c);
		struct app *again = app_create(1280, 800, 1 + (uint64_t)c);
		struct tree t, before;
		size_t cursor, nops;
		struct doc view;

		CHECK(app && again);
		/* New on an empty canvas: nothing to archive */
		pen_button(&pen, app, BUTTON_NEW);
		CHECK(!app_take_replaced(app, &t, &cursor));
		pen_button(&pen, app, BUTTON_NEW); /* and back out of the strip: a stroke */
		draw_some(app, &r);
		if (rng_next(&r) % 2) {
			pen_button(&pen, app, BUTTON_3D);
			lifted++;
		}
		if (app->tree.nbranches == 0) {
			empty++;
			app_destroy(app);
			app_destroy(again);
			continue;
		}
		tree_init(&before);
		CHECK(tree_copy(&before, &app->tree) == 0);
		nops = app->doc.cursor;
		pen_button(&pen, app, BUTTON_NEW);
		CHECK(app->tree.nbranches == 0);            /* the canvas is new */
		CHECK(app->doc.cursor == nops + 1);         /* New recorded */
		pen_button(&pen, app, BUTTON_NEW);          /* a second New: nothing more */
		CHECK(app_take_replaced(app, &t, &cursor));
		{
			struct tree none;
			size_t c2;

			CHECK(!app_take_replaced(app, &none, &c2));
		}
		CHECK(cursor == nops);
		same_tree(&t, &before);
		/* the document then rebuilds that tree */
		view = app->doc;
		view.cursor = cursor;
		{
			/* as the archive writes it and a reader reads it back */
			struct doc copy;
			struct error err;
			struct buf b;

			buf_init(&b);
			CHECK(doc_serialize(&view, &t, &b) == 0);
			CHECK(doc_parse((const char *)b.data, b.len, "archived", &copy, &err) == 0);
			CHECK(copy.cursor == cursor && copy.nops == nops + 1);
			CHECK(app_load_doc(again, &copy) == 0);
			same_tree(&again->tree, &before);
			buf_finish(&b);
		}
		waited++;
		tree_finish(&t);
		tree_finish(&before);
		app_destroy(app);
		app_destroy(again);
	}
	CHECK(waited > (size_t)n / 2);
	printf("New after drawing: %zu drawings left to archive (%zu lifted to 3D), each as it "
	       "stood; %zu sessions drew no tree\n", waited, lifted, empty);
	return 0;
}
