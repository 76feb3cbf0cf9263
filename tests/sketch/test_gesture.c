/* SPDX-License-Identifier: MIT */
/* Cut and erase gestures through the app: a slash that crosses a branch once cuts it,
 * twice erases it from the base, a branch drawn from its parent is never a cut, the
 * eraser end erases what it touches; all undoable. */
#include <string.h>

#include "app.h"
#include "pen.h"
#include "sketch.h"
#include "test.h"

/* 10 motion events a leg */
static struct pen pen = { .now_us = 1000, .steps = 10 };

static void leaf(struct app *app, double cx, double cy)
{
	double xy[2 * 26];

	for (int i = 0; i < 26; i++) {
		xy[2 * i] = cx + 14 * cos(i * 0.25);
		xy[2 * i + 1] = cy + 14 * sin(i * 0.25);
	}
	pen_stroke(&pen, app, EVENT_TOOL_PEN, xy, 26);
}

/* trunk; b1 from the trunk to the right; b2 from the middle of b1 upwards; a leaf at b1's tip */
static struct app *young_tree(void)
{
	struct app *app = app_create(1280, 800, 3);

	CHECK(app);
	pen_line(&pen, app, 640, 736, 640, 236);
	pen_line(&pen, app, 640, 536, 940, 436);
	pen_line(&pen, app, 790, 486, 820, 336);
	leaf(app, 955, 425);
	CHECK_INT(app->tree.nbranches, 3);
	CHECK_INT(app->tree.branches[2].parent, 1);
	CHECK_INT(app->tree.nleaves, 1);
	CHECK_INT(app->tree.leaves[0].branch, 1);
	return app;
}

static double screen_x(const struct app *app, struct vec3 p)
{
	double x, y;

	screen_from_world(&app->screen, p, &x, &y);
	return x;
}

static void test_cut(void)
{
	struct app *app = young_tree();
	const struct branch *b1;
	size_t nops = app->doc.nops;

	/* a slash across b1 once, before b2: b1 ends at the slash, b2 and the leaf go */
	pen_line(&pen, app, 700, 420, 720, 580);
	CHECK_INT(app->doc.nops, nops + 1);
	CHECK_INT(app->tree.nbranches, 2);
	CHECK_INT(app->tree.nleaves, 0);
	b1 = &app->tree.branches[1];
	CHECK_NEAR(screen_x(app, b1->points[b1->npoints - 1]), 711, 3);
	CHECK(b1->radii[b1->npoints - 1] > 0);

	/* undo brings everything back, redo cuts again */
	pen_button(&pen, app, BUTTON_UNDO);
	CHECK_INT(app->tree.nbranches, 3);
	CHECK_INT(app->tree.nleaves, 1);
	pen_button(&pen, app, BUTTON_REDO);
	CHECK_INT(app->tree.nbranches, 2);
	app_destroy(app);
}

static void test_cut_keeps_lower_children(void)
{
	struct app *app = young_tree();

	/* a slash across the trunk above b1: the trunk is shortened, b1 and b2 stay */
	pen_line(&pen, app, 600, 300, 680, 320);
	CHECK_INT(app->tree.nbranches, 3);
	CHECK_NEAR(app->tree.branches[0].points[app->tree.branches[0].npoints - 1].y,
		   screen_to_world(&app->screen, 0, 310).y, 0.05);
	CHECK(app->tree.branches[1].parent_t > 0.4 && app->tree.branches[1].parent_t <= 1.0);
	/* a slash across the trunk below b1: b1, b2 and the leaf go */
	pen_line(&pen, app, 600, 650, 680, 660);
	CHECK_INT(app->tree.nbranches, 1);
	CHECK_INT(app->tree.nleaves, 0);
	app_destroy(app);
}

static void test_erase(void)
{
	struct app *app = young_tree();
	const double zigzag[] = { 700, 400, 712, 580, 724, 400 };

	/* crossing b1 twice erases it from its base, with b2 and the leaf */
	pen_stroke(&pen, app, EVENT_TOOL_PEN, zigzag, 3);
	CHECK_INT(app->tree.nbranches, 1);
	CHECK_INT(app->tree.nleaves, 0);
	CHECK_INT(app->tree.branches[0].npoints > 10, 1);
	app_destroy(app);
}

static void test_branch_not_cut(void)
{
	struct app *app = young_tree();

	/* from the trunk, up and right, across b1 and b2: a new branch, not a cut */
	pen_line(&pen, app, 641, 620, 900, 300);
	CHECK_INT(app->tree.nbranches, 4);
	CHECK_INT(app->tree.branches[3].parent, 0);
	/* begun just beside the trunk (20 px) and drawn across it: still a branch */
	pen_line(&pen, app, 620, 680, 500, 600);
	pen_line(&pen, app, 660, 400, 470, 330);
	CHECK_INT(app->tree.nbranches, 6);
	CHECK_INT(app->tree.branches[5].parent, 0);
	CHECK_INT(app->tree.nleaves, 1);
	app_destroy(app);
}

static void test_eraser(void)
{
	struct app *app = young_tree();
	const double tap[] = { 820, 340 };
	const double scrub[] = { 940, 400, 975, 440, 940, 445 };

	/* an eraser tap on b2's tip takes b2 only */
	pen_stroke(&pen, app, EVENT_TOOL_ERASER, tap, 1);
	CHECK_INT(app->tree.nbranches, 2);
	CHECK_INT(app->tree.nleaves, 1);
	/* scrubbing over the leaf (away from b1's tip) takes the leaf, then b1 too */
	pen_stroke(&pen, app, EVENT_TOOL_ERASER, scrub, 3);
	CHECK_INT(app->tree.nleaves, 0);
	CHECK_INT(app->tree.nbranches, 1);
	pen_button(&pen, app, BUTTON_UNDO);
	pen_button(&pen, app, BUTTON_UNDO);
	CHECK_INT(app->tree.nbranches, 3);
	CHECK_INT(app->tree.nleaves, 1);
	app_destroy(app);
}

static void test_slash_cuts_every_crossed_branch(void)
{
	struct app *app = young_tree();

	/* one horizontal slash through b1 and the trunk: both are cut there (b1 and the
	 * trunk end at the slash; b2 and the leaf, beyond b1's cut, go) */
	pen_line(&pen, app, 560, 505, 760, 505);
	CHECK_INT(app->tree.nbranches, 2);
	CHECK_NEAR(app->tree.branches[0].points[app->tree.branches[0].npoints - 1].y,
		   screen_to_world(&app->screen, 0, 505).y, 0.05);
	CHECK_NEAR(screen_x(app, app->tree.branches[1].points[app->tree.branches[1].npoints - 1]), 733, 3);
	app_destroy(app);
}

static void test_erase_all_then_3d_again(void)
{
	struct app *app = young_tree();
	const double scrub[] = { 640, 740, 640, 200, 960, 440, 820, 330 };

	pen_button(&pen, app, BUTTON_3D);
	CHECK(app->tree.lifted);
	pen_stroke(&pen, app, EVENT_TOOL_ERASER, scrub, 4);
	CHECK_INT(app->tree.nbranches, 0);
	/* the next visitor's tree starts flat and can be lifted */
	pen_line(&pen, app, 640, 736, 640, 300);
	pen_line(&pen, app, 640, 500, 800, 400);
	CHECK(!app->tree.lifted);
	pen_button(&pen, app, BUTTON_3D);
	CHECK(app->tree.lifted);
	app_destroy(app);
}

int main(void)
{
	test_slash_cuts_every_crossed_branch();
	test_erase_all_then_3d_again();
	test_cut();
	test_cut_keeps_lower_children();
	test_erase();
	test_branch_not_cut();
	test_eraser();
	return 0;
}
