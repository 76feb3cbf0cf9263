/* SPDX-License-Identifier: MIT */
/* The 3D phase: orbiting the camera with the pen, the front view button, the animated
 * turn into 3D, and strokes and gestures on a turned tree (placed on the plane through
 * the attachment point facing the camera, tested against what the screen shows). */
#include <string.h>

#include "app.h"
#include "gesture.h"
#include "layout.h"
#include "pen.h"
#include "sketch_seen.h"
#include "test.h"

/* 10 motion events a leg; a pause after each stroke: no two strokes here are one
 * branch's outlines */
static struct pen pen = { .now_us = 1000, .steps = 10, .pause_us = PEN_PAUSE_US };

/* A broad young tree, lifted. */
static struct app *lifted_tree(void)
{
	struct app *app = app_create(1280, 800, 7);

	CHECK(app);
	pen_line(&pen, app, 560, 736, 560, 236);
	pen_line(&pen, app, 560, 536, 800, 400);
	pen_line(&pen, app, 560, 480, 330, 350);
	pen_line(&pen, app, 560, 400, 700, 250);
	pen_line(&pen, app, 560, 360, 420, 220);
	CHECK_INT(app->tree.nbranches, 5);
	pen_button(&pen, app, BUTTON_3D);
	CHECK(app->tree.lifted);
	CHECK(camera_is_front(app->camera));
	return app;
}

/* Where a world point shows on the screen through the app's camera. */
static void to_screen(const struct app *app, struct vec3 p, double *x, double *y)
{
	struct camera_xf xf;

	camera_xf_init(&xf, app->camera, sketch_seen_pivot(&app->tree));
	screen_from_world(&app->screen, camera_to_view(&xf, p), x, y);
}

/* Screen distance (metres) from a screen point to the tree as the camera shows it. */
static double clearance(const struct app *app, double x, double y)
{
	struct sketch_seen sv;
	double d;

	CHECK_INT(sketch_seen_init(&sv, &app->tree, app->camera), 0);
	d = sketch_seen_clearance(&sv, screen_to_world(&app->screen, x, y));
	sketch_seen_finish(&sv);
	return d;
}

static void test_camera_math(void)
{
	struct camera_xf xf;
	struct vec3 p = vec3(1.25, 2.5, -0.75), q;
	float m[16];

	camera_xf_init(&xf, (struct camera){ 0, 0 }, vec3(3, 0, 1));
	q = camera_to_view(&xf, p);
	CHECK(q.x == p.x && q.y == p.y && q.z == p.z); /* the front view is exact */
	/* from the right (yaw 90), +x comes towards the viewer and +z goes left */
	camera_xf_init(&xf, (struct camera){ 90, 0 }, vec3(0, 0, 0));
	q = camera_to_view(&xf, vec3(1, 0, 0));
	CHECK_NEAR(q.x, 0, 1e-12);
	CHECK_NEAR(q.z, 1, 1e-12);
	q = camera_to_view(&xf, vec3(0, 0, 1));
	CHECK_NEAR(q.x, -1, 1e-12);
	/* seen from above, a point over the pivot is nearer the camera and foreshortened */
	camera_xf_init(&xf, (struct camera){ -30, 40 }, vec3(0.5, 0, -0.25));
	q = camera_from_view(&xf, camera_to_view(&xf, p));
	CHECK_NEAR(vec3_dist(p, q), 0, 1e-12);
	CHECK_NEAR(vec3_dist(camera_to_view(&xf, xf.pivot), xf.pivot), 0, 1e-12);
	q = camera_to_view(&xf, vec3(0.5, 1, -0.25));
	CHECK(q.z - xf.pivot.z > 0.5 && q.y < 0.9);
	camera_matrix(&xf, m);
	q = camera_to_view(&xf, p);
	CHECK_NEAR(m[0] * p.x + m[4] * p.y + m[8] * p.z + m[12], q.x, 1e-5);
	CHECK_NEAR(m[1] * p.x + m[5] * p.y + m[9] * p.z + m[13], q.y, 1e-5);
	CHECK_NEAR(m[2] * p.x + m[6] * p.y + m[10] * p.z + m[14], q.z, 1e-5);
	/* wrapping and clamping */
	CHECK(camera_normalize(190, 0).yaw == -170.0f);
	CHECK(camera_normalize(-540, 0).yaw == -180.0f);
	CHECK(camera_normalize(0, 100).pitch == CAMERA_PITCH_MAX_DEG);
	CHECK(camera_normalize(0, -100).pitch == CAMERA_PITCH_MIN_DEG);
	CHECK(camera_is_front(camera_normalize(NAN, INFINITY)));
}

static void test_orbit_drag(void)
{
	struct app *app = lifted_tree();
	size_t nops = app->doc.nops;
	struct camera before;

	/* far from the tree, in the sky on the left: the drag turns the camera */
	CHECK(app_would_orbit(app, 120, 150));
	CHECK(!app_would_orbit(app, 560, 500)); /* on the trunk */
	pen_line(&pen, app, 120, 150, 320, 150);
	CHECK_INT(app->doc.nops, nops); /* nothing drawn */
	CHECK_NEAR(app->camera.yaw, -200 * app->screen.m_per_px * APP_ORBIT_DEG_PER_M, 1e-3);
	CHECK_NEAR(app->camera.pitch, 0, 1e-6);
	CHECK(app->doc.view.yaw == app->camera.yaw); /* saved with the drawing */
	/* dragging down looks from above, as far as the limit */
	pen_line(&pen, app, 120, 100, 120, 700);
	CHECK(app->camera.pitch > 50);
	pen_line(&pen, app, 120, 100, 120, 700);
	CHECK(app->camera.pitch == CAMERA_PITCH_MAX_DEG);
	before = app->camera;
	/* a stroke starting on the trunk draws, the camera stays */
	{
		double x, y;

		to_screen(app, app->tree.branches[0].points[app->tree.branches[0].npoints / 2], &x, &y);
		CHECK(!app_would_orbit(app, x, y));
		pen_line(&pen, app, x, y, x + 120, y - 60);
	}
	CHECK_INT(app->doc.nops, nops + 1);
	CHECK(app->camera.yaw == before.yaw && app->camera.pitch == before.pitch);
	/* a leaf at a branch tip, drawn on the turned tree */
	{
		const struct branch *b1 = &app->tree.branches[1];
		double x, y, xy[2 * 25];

		to_screen(app, b1->points[b1->npoints - 1], &x, &y);
		for (int i = 0; i < 25; i++) {
			xy[2 * i] = x + 12 + 16 * cos(i * 2 * VEC_PI / 24);
			xy[2 * i + 1] = y + 16 * sin(i * 2 * VEC_PI / 24);
		}
		pen_stroke(&pen, app, EVENT_TOOL_PEN, xy, 25);
		CHECK_INT(app->tree.nleaves, 1);
	}
	/* the quick test the cursor uses agrees with the full clearance everywhere */
	for (int y = 10; y < 800; y += 37)
		for (int x = 10; x < 1160; x += 41) {
			double c = clearance(app, x, y);

			if (fabs(c - APP_ORBIT_CLEARANCE_M) > 1e-6)
				CHECK(sketch_seen_near(&app->tree, app->camera, screen_to_world(&app->screen, x, y),
						       APP_ORBIT_CLEARANCE_M) == (c <= APP_ORBIT_CLEARANCE_M));
		}
	/* the eraser never orbits */
	app->pen.tool = EVENT_TOOL_ERASER;
	CHECK(!app_would_orbit(app, 120, 150));
	app_destroy(app);

	/* a sketch does not turn: the drag is a stroke */
	app = app_create(1280, 800, 7);
	pen_line(&pen, app, 560, 736, 560, 236);
	CHECK(!app_would_orbit(app, 120, 150));
	pen_line(&pen, app, 120, 150, 320, 150);
	CHECK(camera_is_front(app->camera));
	CHECK_INT(app->doc.nops, 2);
	app_destroy(app);
}

static void test_view_button_and_undo(void)
{
	struct app *app = lifted_tree();
	struct layout_button vb = layout_view_button(&app->screen);

	pen_line(&pen, app, 120, 150, 420, 250);
	CHECK(!camera_is_front(app->camera));
	/* the pen taps the front view button */
	pen_line(&pen, app, vb.x + vb.w / 2, vb.y + vb.h / 2, vb.x + vb.w / 2 + 1, vb.y + vb.h / 2);
	CHECK(camera_is_front(app->camera));
	/* ...and so does the GPIO/--press button */
	pen_line(&pen, app, 120, 150, 420, 250);
	pen_button(&pen, app, BUTTON_VIEW);
	CHECK(camera_is_front(app->camera));
	/* undoing 3D goes back to the sketch, seen from the front; the button is gone */
	pen_line(&pen, app, 120, 150, 420, 250);
	pen_button(&pen, app, BUTTON_UNDO);
	CHECK(!app->tree.lifted);
	CHECK(camera_is_front(app->camera));
	CHECK(!app_would_orbit(app, vb.x + vb.w / 2, vb.y + vb.h / 2));
	app_destroy(app);
}

static void test_turn_animation(void)
{
	struct app *app = app_create(1280, 800, 7);
	struct camera c;
	uint64_t t0;

	pen_line(&pen, app, 560, 736, 560, 236);
	pen_line(&pen, app, 560, 536, 800, 400);
	t0 = pen.now_us;
	pen_button(&pen, app, BUTTON_3D);
	CHECK(app->turning);
	CHECK(app_camera_at(app, t0 + APP_TURN_US / 8, &c));
	CHECK(c.yaw > 10); /* swinging one way */
	CHECK(app_camera_at(app, t0 + APP_TURN_US * 3 / 4, &c));
	CHECK(c.yaw < -10); /* ...and the other */
	CHECK(!app_camera_at(app, t0 + APP_TURN_US, &c));
	CHECK(camera_is_front(c)); /* and settles where the sketch was drawn */
	CHECK(!app_camera_at(app, UINT64_MAX, &c));
	/* the pen stops it */
	app->pen.tool = EVENT_TOOL_PEN;
	pen_event(&pen, app, EVENT_TIP_DOWN, EVENT_TOOL_PEN, 100, 100, 0.5);
	pen_event(&pen, app, EVENT_TIP_UP, EVENT_TOOL_PEN, 100, 100, 0.5);
	CHECK(!app->turning);
	app_destroy(app);
}

/* Stroke on a tree seen from the right: the new branch is rooted on its parent, lies on
 * the plane through the attachment point facing the camera and shows where it was drawn. */
static void test_stroke_on_turned_tree(void)
{
	struct app *app = lifted_tree();
	struct camera_xf xf;
	const struct branch *b;
	double x, y, tx = 900, ty = 200;
	struct vec3 root_v;

	CHECK(app_set_camera(app, (struct camera){ 90, 15 }));
	to_screen(app, app->tree.branches[0].points[app->tree.branches[0].npoints * 3 / 4], &x, &y);
	pen_line(&pen, app, x, y, tx, ty);
	CHECK_INT(app->tree.nbranches, 10); /* 5 drawn + 4 merged + this one */
	b = &app->tree.branches[9];
	CHECK_INT(b->parent, 0);
	CHECK(app->doc.ops[app->doc.cursor - 1].camera.yaw == 90.0f);
	/* the tip shows where the pen lifted (0.5 px) */
	to_screen(app, b->points[b->npoints - 1], &x, &y);
	CHECK_NEAR(x, tx, 0.5);
	CHECK_NEAR(y, ty, 0.5);
	/* the root lies on the trunk in 3D */
	{
		const struct branch *trunk = &app->tree.branches[0];
		double best = INFINITY;

		for (size_t i = 0; i + 1 < trunk->npoints; i++) {
			struct vec3 a = trunk->points[i], d = vec3_sub(trunk->points[i + 1], a);
			double s = vec3_dot(vec3_sub(b->points[0], a), d) / vec3_dot(d, d);

			s = s < 0 ? 0 : s > 1 ? 1 : s;
			best = fmin(best, vec3_dist(b->points[0], vec3_add(a, vec3_scale(d, s))));
		}
		CHECK(best < 1e-9);
	}
	/* every point at the attachment point's depth as the camera sees it */
	camera_xf_init(&xf, app->camera, sketch_seen_pivot(&app->tree));
	root_v = camera_to_view(&xf, b->points[0]);
	for (size_t i = 0; i < b->npoints; i++)
		CHECK_NEAR(camera_to_view(&xf, b->points[i]).z, root_v.z, 1e-9);
	/* seen from the front it is no longer in the sketch plane: it went sideways in depth */
	CHECK(fabs(b->points[b->npoints - 1].z - b->points[0].z) > 1.0);
	app_destroy(app);
}

/* A slash across a branch as the turned screen shows it cuts it there. */
static void test_gestures_on_turned_tree(void)
{
	struct app *app = lifted_tree();
	double sx = 0, sy = 0, ex = 0, ey = 0, full = 0;
	int target = -1;

	CHECK(app_set_camera(app, (struct camera){ 60, 20 }));
	/* a first-generation branch, and a place across it where a slash can start clear of
	 * the wood (a crowded turned tree has few) */
	for (size_t i = 1; i < app->tree.nbranches && target < 0; i++) {
		const struct branch *b = &app->tree.branches[i];
		double x0, y0, x1, y1, len;

		to_screen(app, b->points[0], &x0, &y0);
		to_screen(app, b->points[b->npoints - 1], &x1, &y1);
		len = hypot(x1 - x0, y1 - y0);
		if (b->parent != 0 || len < 120)
			continue;
		for (int k = 5; k <= 8 && target < 0; k++) {
			for (int side = -1; side <= 1 && target < 0; side += 2) {
				double mx, my, nx = -side * (y1 - y0) / len, ny = side * (x1 - x0) / len;

				to_screen(app, b->points[b->npoints * k / 10], &mx, &my);
				if (clearance(app, mx + 70 * nx, my + 70 * ny) < 2 * GESTURE_SNAP_M ||
				    app_would_orbit(app, mx + 70 * nx, my + 70 * ny))
					continue;
				sx = mx + 70 * nx, sy = my + 70 * ny;
				ex = mx - 30 * nx, ey = my - 30 * ny;
				target = (int)i;
				full = tree_branch_length(b);
			}
		}
	}
	CHECK(target > 0);
	pen_line(&pen, app, sx, sy, ex, ey);
	CHECK_INT(app->tree.branches[target].parent, 0);
	CHECK(tree_branch_length(&app->tree.branches[target]) < 0.9 * full);
	CHECK(tree_branch_length(&app->tree.branches[target]) > 0.3 * full);
	/* the eraser on the trunk's screen picture erases the whole tree */
	{
		const struct branch *trunk = &app->tree.branches[0];
		double tx, ty, xy[4];

		to_screen(app, trunk->points[trunk->npoints / 2], &tx, &ty);
		xy[0] = tx - 20;
		xy[1] = ty;
		xy[2] = tx + 20;
		xy[3] = ty;
		pen_stroke(&pen, app, EVENT_TOOL_ERASER, xy, 2);
		CHECK_INT(app->tree.nbranches, 0);
		CHECK(!app->tree.lifted);
		CHECK(camera_is_front(app->camera));
	}
	app_destroy(app);
}

/* A drawing made on a turned tree loads back to the same tree, camera and all. */
static void test_reload(void)
{
	struct app *app = lifted_tree(), *again = app_create(1280, 800, 1);
	struct buf b;
	struct doc d;
	struct error err = { { 0 } };
	double x, y;

	CHECK(again);
	pen_line(&pen, app, 120, 150, 380, 230);
	to_screen(app, app->tree.branches[0].points[app->tree.branches[0].npoints / 2], &x, &y);
	pen_line(&pen, app, x, y, x - 150, y - 120);
	pen_line(&pen, app, 120, 150, 200, 100);
	buf_init(&b);
	CHECK_INT(doc_serialize(&app->doc, &app->tree, &b), 0);
	CHECK_INT(doc_parse((const char *)b.data, b.len, "reload", &d, &err), 0);
	CHECK_INT(app_load_doc(again, &d), 0);
	CHECK(again->camera.yaw == app->camera.yaw && again->camera.pitch == app->camera.pitch);
	CHECK_INT(again->tree.nbranches, app->tree.nbranches);
	for (size_t i = 0; i < app->tree.nbranches; i++) {
		CHECK_INT(again->tree.branches[i].npoints, app->tree.branches[i].npoints);
		CHECK(memcmp(again->tree.branches[i].points, app->tree.branches[i].points,
			     app->tree.branches[i].npoints * sizeof(struct vec3)) == 0);
	}
	buf_finish(&b);
	doc_finish(&d);
	app_destroy(again);
	app_destroy(app);
}

int main(void)
{
	test_camera_math();
	test_orbit_drag();
	test_view_button_and_undo();
	test_turn_animation();
	test_stroke_on_turned_tree();
	test_gestures_on_turned_tree();
	test_reload();
	return 0;
}
