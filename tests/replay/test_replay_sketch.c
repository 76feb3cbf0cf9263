/* SPDX-License-Identifier: MIT */
/*
 * Sketching replays (tests/data/sketch-*.edaha-trace, made by gen-sketch-traces.py),
 * asserting on skeleton.json as exported and on the drawing: branches and their parents,
 * tips where the pen lifted, roots on their parents, leaves on the right branch, cuts,
 * erasures, the eraser, the two-outline profile, and undo + redo giving identical files.
 */
#include <json-c/json.h>
#include <string.h>

#include "app.h"
#include "replay_util.h"
#include "export.h"
#include "test.h"
#include "trace.h"

#define W 1280
#define H 800

static const char *dir;

/* docs/skeleton-format.md: x = (px - W/2) * 10/H, y = (0.92 H - py) * 10/H */
static double to_px_x(double x) { return x * H / 10.0 + W / 2.0; }
static double to_px_y(double y) { return 0.92 * H - y * H / 10.0; }

static json_object *skeleton(const struct app *app)
{
	return replay_skeleton_json(&app->tree);
}

static json_object *branch(json_object *s, int i)
{
	return json_object_array_get_idx(replay_get(s, "branches"), (size_t)i);
}

static size_t count(json_object *s, const char *what)
{
	return json_object_array_length(replay_get(s, what));
}

static int parent(json_object *s, int i)
{
	return json_object_get_int(replay_get(branch(s, i), "parent"));
}

/* point k of branch i (k < 0 counts from the end), in screen pixels */
static void point_px(json_object *s, int i, int k, double *x, double *y)
{
	json_object *pts = replay_get(branch(s, i), "points");
	size_t n = json_object_array_length(pts);
	json_object *p = json_object_array_get_idx(pts, k < 0 ? n + (size_t)k : (size_t)k);

	*x = to_px_x(json_object_get_double(json_object_array_get_idx(p, 0)));
	*y = to_px_y(json_object_get_double(json_object_array_get_idx(p, 1)));
}

static double radius(json_object *s, int i, int k)
{
	json_object *r = replay_get(branch(s, i), "radii");
	size_t n = json_object_array_length(r);

	return json_object_get_double(json_object_array_get_idx(r, k < 0 ? n + (size_t)k : (size_t)k));
}

/* undo then redo restores identical skeleton and drawing bytes */
static void undo_redo_identical(struct app *app)
{
	struct buf s0, d0, s1, d1;

	buf_init(&s0), buf_init(&d0), buf_init(&s1), buf_init(&d1);
	CHECK_INT(export_skeleton(&app->tree, &s0), 0);
	CHECK_INT(doc_serialize(&app->doc, &app->tree, &d0), 0);
	replay_press(app, BUTTON_UNDO);
	replay_press(app, BUTTON_REDO);
	CHECK_INT(export_skeleton(&app->tree, &s1), 0);
	CHECK_INT(doc_serialize(&app->doc, &app->tree, &d1), 0);
	CHECK(s0.len == s1.len && memcmp(s0.data, s1.data, s0.len) == 0);
	CHECK(d0.len == d1.len && memcmp(d0.data, d1.data, d0.len) == 0);
	buf_finish(&s0), buf_finish(&d0), buf_finish(&s1), buf_finish(&d1);
}

static void test_branch_across(void)
{
	struct app *app = replay_trace(dir, "sketch-branch-across.edaha-trace", W, H, 1);
	json_object *s = skeleton(app);
	double x, y;

	/* trunk + 3 branches: b1 on the trunk, b2 on b1, b3 (drawn across b1, b2) on the trunk */
	CHECK_INT(count(s, "branches"), 4);
	CHECK_INT(parent(s, 0), -1);
	CHECK_INT(parent(s, 1), 0);
	CHECK_INT(parent(s, 2), 1);
	CHECK_INT(parent(s, 3), 0);
	/* tips where the pen lifted, to 0.5 px; roots on the parent */
	point_px(s, 3, -1, &x, &y);
	CHECK_NEAR(x, 900, 0.5);
	CHECK_NEAR(y, 300, 0.5);
	point_px(s, 2, -1, &x, &y);
	CHECK_NEAR(x, 820, 0.5);
	CHECK_NEAR(y, 336, 0.5);
	point_px(s, 3, 0, &x, &y);
	CHECK_NEAR(x, 640, 0.5); /* the trunk is the line x = 640 */
	/* the leaf loop is a leaf on b1 */
	CHECK_INT(count(s, "leaves"), 1);
	CHECK_INT(json_object_get_int(replay_get(json_object_array_get_idx(replay_get(s, "leaves"), 0), "branch")), 1);
	/* the drawing: 5 pen strokes, all in effect */
	CHECK_INT(app->doc.nops, 5);
	CHECK_INT(app->doc.cursor, 5);
	undo_redo_identical(app);
	json_object_put(s);
	app_destroy(app);
}

static void test_cut(void)
{
	struct app *app = replay_trace(dir, "sketch-cut.edaha-trace", W, H, 1);
	json_object *s = skeleton(app);
	double x, y;

	/* b1 ends at the slash, (700,420)-(720,580) crosses b1's line y = 536 - (x-640)/3
	 * at x = 711; b2 (attached beyond) and the leaf are gone */
	CHECK_INT(count(s, "branches"), 2);
	CHECK_INT(count(s, "leaves"), 0);
	point_px(s, 1, -1, &x, &y);
	CHECK_NEAR(x, 711.1, 1.0);
	CHECK_NEAR(y, 536 - (x - 640) / 3, 1.0);
	CHECK_INT(app->doc.nops, 5);
	undo_redo_identical(app);
	json_object_put(s);
	app_destroy(app);
}

static void test_erase(void)
{
	struct app *app = replay_trace(dir, "sketch-erase.edaha-trace", W, H, 1);
	json_object *s = skeleton(app);

	/* crossed twice: b1 erased from its base with b2 and the leaf; the trunk stays */
	CHECK_INT(count(s, "branches"), 1);
	CHECK_INT(parent(s, 0), -1);
	CHECK_INT(count(s, "leaves"), 0);
	undo_redo_identical(app);
	json_object_put(s);
	app_destroy(app);
}

static void test_eraser(void)
{
	struct app *app = replay_trace(dir, "sketch-eraser.edaha-trace", W, H, 1);
	json_object *s = skeleton(app);

	/* the eraser tap took b2 only; the drawing keeps the eraser stroke */
	CHECK_INT(count(s, "branches"), 2);
	CHECK_INT(count(s, "leaves"), 1);
	CHECK_INT(app->doc.ops[4].tool, EVENT_TOOL_ERASER);
	undo_redo_identical(app);
	json_object_put(s);
	app_destroy(app);
}

static void test_outlines(void)
{
	struct app *app = replay_trace(dir, "sketch-outlines.edaha-trace", W, H, 1);
	json_object *s = skeleton(app);
	double x, y;

	/* the two outlines are one trunk, 40 px radius at the ground and 10 at the top */
	CHECK_INT(count(s, "branches"), 2);
	CHECK_NEAR(radius(s, 0, 0) * H / 10.0, 40, 1);
	CHECK_NEAR(radius(s, 0, -1) * H / 10.0, 10, 1);
	point_px(s, 0, 0, &x, &y);
	CHECK_NEAR(x, 640, 0.5);
	/* the single stroke after it tapers the same way: tip / root = 10 / 40 */
	CHECK_NEAR(radius(s, 1, -1) / radius(s, 1, 0), 0.25, 0.02);
	CHECK_INT(app->doc.nops, 3);
	undo_redo_identical(app);
	json_object_put(s);
	app_destroy(app);
}

int main(int argc, char **argv)
{
	CHECK(argc == 2);
	dir = argv[1];
	test_branch_across();
	test_cut();
	test_erase();
	test_eraser();
	test_outlines();
	return 0;
}
