/* SPDX-License-Identifier: MIT */
/*
 * A libinput recording of a real tablet model (Wacom Intuos Pro M: pen and pad devices in
 * one file, tilt, no resolution on some axes) replays into strokes at the right screen
 * positions. Expected positions are computed here from the raw values in the file and
 * its absinfo, independently of the importer.
 */
#include "app.h"
#include "sketch.h"
#include "test.h"
#include "trace.h"

#define W 1280
#define H 800
/* absinfo of the pen device: ABS_X 0..44800, ABS_Y 0..29600 */
#define PX(v) ((v) * (double)W / 44801.0)
#define PY(v) ((v) * (double)H / 29601.0)

static void check_screen(const struct app *app, struct vec3 p, double x, double y)
{
	double sx, sy;

	screen_from_world(&app->screen, p, &sx, &sy);
	CHECK_NEAR(sx, x, 0.5);
	CHECK_NEAR(sy, y, 0.5);
}

int main(int argc, char **argv)
{
	char path[4096];
	struct trace t;
	struct error err = { { 0 } };
	struct app *app;
	const struct branch *trunk, *side;
	size_t i;

	CHECK(argc == 2);
	snprintf(path, sizeof(path), "%s/wacom-intuos-pro-m.yml", argv[1]);
	trace_init(&t);
	if (trace_load(path, W, H, &t, &err) < 0) {
		fprintf(stderr, "%s\n", err.msg);
		return 1;
	}
	app = app_create(W, H, 1);
	CHECK(app);
	/* the two pen strokes, up to where the eraser end comes near */
	for (i = 0; i < t.nevents && t.events[i].tool != EVENT_TOOL_ERASER; i++)
		app_handle_event(app, &t.events[i]);
	CHECK_INT(app->failed, 0);
	CHECK_INT(app->doc.nops, 2);
	CHECK_INT(app->tree.nbranches, 2);
	trunk = &app->tree.branches[0];
	side = &app->tree.branches[1];
	/* the trunk from where the tip touched (22400, 26800) to where it lifted (22050, 11900) */
	check_screen(app, trunk->points[0], PX(22400), PY(26800));
	check_screen(app, trunk->points[trunk->npoints - 1], PX(22050), PY(11900));
	/* the branch keeps its drawn tip (30000, 12600); its root moved onto the trunk */
	check_screen(app, side->points[side->npoints - 1], PX(30000), PY(12600));
	CHECK_INT(side->parent, 0);
	{
		struct tree trunk_only = app->tree;

		trunk_only.nbranches = 1;
		CHECK_NEAR(sketch_nearest(&trunk_only, side->points[0]).dist, 0.0, 1e-9);
	}
	/* pressure and tilt came through from the pen device, not the pad: the first event is
	 * the pen entering proximity with ABS_TILT_X 12, ABS_TILT_Y -9 at 57 units/radian */
	CHECK(app->doc.ops[0].points[3].pressure > 0.05f);
	CHECK_INT(t.events[0].type, EVENT_PROXIMITY_IN);
	CHECK_NEAR(t.events[0].tilt_x, 12.0 / 57.0 * 180.0 / VEC_PI, 1e-9);
	CHECK_NEAR(t.events[0].tilt_y, -9.0 / 57.0 * 180.0 / VEC_PI, 1e-9);

	/* then the eraser scrubs at the branch's tip, which erases that branch */
	for (; i < t.nevents; i++)
		app_handle_event(app, &t.events[i]);
	CHECK_INT(app->doc.nops, 3);
	CHECK_INT(app->doc.ops[2].tool, EVENT_TOOL_ERASER);
	CHECK_INT(app->tree.nbranches, 1);
	app_destroy(app);
	trace_finish(&t);
	return 0;
}
