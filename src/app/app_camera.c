/* SPDX-License-Identifier: MIT */
/* The orbit camera of a 3D tree as the pen and the buttons move it, the animated turn
 * into 3D, and what on-screen control the pen lands on. */
#include <math.h>

#include "app_mode.h"
#include "app_private.h"
#include "layout.h"
#include "sketch_seen.h"

void app_camera_store(struct app *app, struct camera c)
{
	app->camera = c;
	app->doc.view = c; /* saved with the drawing */
}

/* Only a 3D tree can be turned or edited by example: a sketch (after undoing 3D, or an
 * empty canvas) is shown from the front, in the sketch mode. */
void app_camera_follow_tree(struct app *app)
{
	if (!app->tree.lifted) {
		app_camera_store(app, (struct camera){ 0.0f, 0.0f });
		app->turning = false;
		app->orbiting = false;
		app->mode = APP_MODE_SKETCH;
	}
}

/* The on-screen button at (x, y): the bar, the front view button of a 3D tree and what
 * the side strip holds as buttons (the propagation patterns, the templates, the parameter
 * buttons); they press as the GPIO ones do, down on the tip and up on its lift. */
bool app_ui_hit(const struct app *app, double x, double y, enum button *button)
{
	struct app_side_item item;

	if (layout_hit(&app->screen, x, y, button))
		return true;
	if (app->tree.lifted && layout_hit_view_button(&app->screen, x, y)) {
		*button = BUTTON_VIEW;
		return true;
	}
	if (app_side_hit(app, x, y, &item) && item.button != BUTTON_COUNT) {
		*button = item.button;
		return true;
	}
	return false;
}

bool app_would_orbit(const struct app *app, double x, double y)
{
	enum button hit;
	struct app_side_item item;

	if (!app->tree.lifted || app->pen.tool != EVENT_TOOL_PEN || app_ui_hit(app, x, y, &hit) ||
	    app_side_hit(app, x, y, &item))
		return false;
	return !sketch_seen_near(&app->tree, app->camera, screen_to_world(&app->screen, x, y),
				 APP_ORBIT_CLEARANCE_M);
}

/* Dragging right turns the tree to the right, like a turntable; dragging down lets the
 * visitor look down on it. */
void app_orbit_to(struct app *app, const struct event *ev)
{
	double x = app_clamp(ev->x, 0, app->screen.width), y = app_clamp(ev->y, 0, app->screen.height);
	double k = app->screen.m_per_px * APP_ORBIT_DEG_PER_M;

	app_camera_store(app, camera_normalize(app->camera.yaw - (x - app->orbit_x) * k,
					 app->camera.pitch + (y - app->orbit_y) * k));
	app->orbit_x = x;
	app->orbit_y = y;
}

bool app_set_camera(struct app *app, struct camera c)
{
	if (!app->tree.lifted)
		return false;
	app->turning = false;
	app_camera_store(app, camera_normalize(c.yaw, c.pitch));
	return true;
}

bool app_camera_at(const struct app *app, uint64_t now_us, struct camera *out)
{
	double s, e;

	*out = app->camera;
	if (!app->turning || now_us < app->turn_start_us || now_us - app->turn_start_us >= APP_TURN_US)
		return false;
	s = (double)(now_us - app->turn_start_us) / APP_TURN_US;
	e = s * s * (3.0 - 2.0 * s); /* eased in and out */
	*out = camera_normalize(app->camera.yaw + APP_TURN_DEG * sin(2.0 * VEC_PI * e), app->camera.pitch);
	return true;
}
