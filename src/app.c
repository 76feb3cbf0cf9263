/* SPDX-License-Identifier: MIT */
#include "app.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "layout.h"
#include "lift.h"
#include "sketch.h"
#include "sketch_view.h"

static void app_fail(struct app *app, int err)
{
	if (err < 0 && app->failed == 0)
		app->failed = err;
}

struct app *app_create(int width, int height, uint64_t seed)
{
	struct app *app = calloc(1, sizeof(*app));

	if (!app)
		return NULL;
	view_init(&app->view, width, height);
	doc_init(&app->doc, seed);
	tree_init(&app->tree);
	tree_mesh_init(&app->mesh);
	rng_seed(&app->rng, seed);
	app->pattern = APP_PATTERN_FIXED_COUNT;
	return app;
}

void app_destroy(struct app *app)
{
	if (!app)
		return;
	doc_finish(&app->doc);
	tree_finish(&app->tree);
	tree_mesh_finish(&app->mesh);
	free(app->stroke.points);
	free(app);
}

static int apply_op(struct app *app, const struct doc_op *op)
{
	switch (op->kind) {
	case DOC_OP_STROKE:
		return sketch_apply(&app->tree, op, &app->rng);
	case DOC_OP_NEW:
		tree_clear(&app->tree);
		return SKETCH_CHANGED;
	case DOC_OP_LIFT: {
		int ret = lift_tree(&app->tree, &app->rng, true);

		return ret < 0 ? ret : SKETCH_CHANGED;
	}
	}
	return SKETCH_CHANGED;
}

static void set_camera(struct app *app, struct camera c)
{
	app->camera = c;
	app->doc.view = c; /* saved with the drawing */
}

/* Only a 3D tree can be turned: a sketch (after undoing 3D, or an empty canvas) is shown
 * from the front. */
static void camera_follow_tree(struct app *app)
{
	if (!app->tree.lifted) {
		set_camera(app, (struct camera){ 0.0f, 0.0f });
		app->turning = false;
		app->orbiting = false;
	}
}

static int update_mesh(struct app *app)
{
	app->mesh_serial++;
	return tree_mesh_build(&app->mesh, &app->tree);
}

int app_rebuild(struct app *app)
{
	int ret;

	tree_clear(&app->tree);
	rng_seed(&app->rng, app->doc.seed);
	for (size_t i = 0; i < app->doc.cursor; i++) {
		ret = apply_op(app, &app->doc.ops[i]);
		if (ret < 0) {
			camera_follow_tree(app);
			return ret;
		}
	}
	camera_follow_tree(app);
	return update_mesh(app);
}

int app_load_doc(struct app *app, struct doc *doc)
{
	doc_finish(&app->doc);
	app->doc = *doc;
	doc_init(doc, doc->seed);
	app->camera = app->doc.view; /* kept if the drawing is a 3D tree */
	return app_rebuild(app);
}

/* Records an edit and applies it on top of the current tree (same result as a rebuild).
 * When the tree only grew, only the new elements are meshed: a stroke's cost does not
 * grow with the drawing. */
static int push_op(struct app *app, struct doc_op *op)
{
	size_t nb = app->tree.nbranches, nl = app->tree.nleaves;
	int ret = doc_push(&app->doc, op);

	if (ret < 0)
		return ret;
	ret = apply_op(app, &app->doc.ops[app->doc.cursor - 1]);
	if (ret < 0) {
		/* Half an edit may have been made: the document is the truth, rebuild from it. */
		(void)app_rebuild(app);
		return ret;
	}
	camera_follow_tree(app);
	if (ret == SKETCH_GREW && app->tree.nbranches >= nb && app->tree.nleaves >= nl) {
		app->mesh_serial++;
		return tree_mesh_append(&app->mesh, &app->tree, nb, nl);
	}
	return update_mesh(app);
}

static void update_pen(struct app *app, const struct event *ev)
{
	app->pen.tool = ev->tool;
	app->pen.x = ev->x;
	app->pen.y = ev->y;
	app->pen.pressure = ev->pressure;
	app->pen.tilt_x = ev->tilt_x;
	app->pen.tilt_y = ev->tilt_y;
}

/* The pen can report positions off the screen (and traces any finite number): what
 * is drawn is what lands on the screen. */
static double clamp(double v, double lo, double hi)
{
	return v < lo ? lo : v > hi ? hi : v;
}

/* Stored values avoid subnormal floats, which not every reader takes back. */
static float quantize(double v)
{
	return fabs(v) < 1e-9 ? 0.0f : (float)v;
}

static int stroke_add(struct app *app, const struct event *ev)
{
	struct app_stroke *s = &app->stroke;
	struct app_point *last = s->npoints ? &s->points[s->npoints - 1] : NULL;
	double x = clamp(ev->x, 0, app->view.width), y = clamp(ev->y, 0, app->view.height);
	double pressure = clamp(ev->pressure, 0, 1);

	if (last && last->x == x && last->y == y) {
		last->pressure = pressure > last->pressure ? pressure : last->pressure;
		return 0;
	}
	if (s->npoints == DOC_MAX_STROKE_POINTS)
		return 0; /* an endless stroke keeps its first part */
	if (s->npoints == s->cap) {
		size_t cap = s->cap ? s->cap * 2 : 256;
		struct app_point *p = realloc(s->points, cap * sizeof(*p));

		if (!p)
			return -ENOMEM;
		s->points = p;
		s->cap = cap;
	}
	s->points[s->npoints++] = (struct app_point){ x, y, pressure, ev->time_us };
	return 0;
}

static int stroke_commit(struct app *app)
{
	struct app_stroke *s = &app->stroke;
	struct doc_op op = { .kind = DOC_OP_STROKE, .tool = s->tool, .camera = app->camera };
	double len = 0.0;
	int ret;

	s->active = false;
	for (size_t i = 1; i < s->npoints; i++)
		len += hypot(s->points[i].x - s->points[i - 1].x, s->points[i].y - s->points[i - 1].y);
	/* A pen tap is not a drawing: keep it out of the history. An eraser tap erases. */
	if (s->tool == EVENT_TOOL_PEN && (s->npoints < 2 || len * app->view.m_per_px < SKETCH_MIN_LENGTH_M)) {
		s->npoints = 0;
		return 0;
	}
	op.time_us = s->points[0].time_us;
	op.points = calloc(s->npoints, sizeof(*op.points));
	if (!op.points)
		return -ENOMEM;
	op.npoints = s->npoints;
	for (size_t i = 0; i < s->npoints; i++) {
		const struct app_point *a = &s->points[i];
		struct vec3 w = view_to_world(&app->view, a->x, a->y);
		uint64_t dt = a->time_us - op.time_us;

		op.points[i] = (struct doc_point){
			.x = quantize(w.x),
			.y = quantize(w.y),
			.pressure = quantize(a->pressure),
			.dt_us = dt > UINT32_MAX ? UINT32_MAX : (uint32_t)dt,
		};
	}
	s->npoints = 0;
	ret = push_op(app, &op);
	doc_op_finish(&op);
	/* A full drawing takes no more strokes; the visitor can still undo or start anew. */
	return ret == -ENOSPC ? 0 : ret;
}

static void set_mode(struct app *app, enum app_mode mode)
{
	/* Pressing the active mode's button again goes back to drawing. */
	app->mode = app->mode == mode ? APP_MODE_SKETCH : mode;
}

static int press_button(struct app *app, enum button button, uint64_t time_us)
{
	struct doc_op op = { .kind = DOC_OP_NEW, .time_us = time_us };
	int ret;

	switch (button) {
	case BUTTON_3D:
		/* Once per drawing: a 3D tree stays 3D (undo goes back to the sketch). */
		if (app->tree.nbranches == 0 || app->tree.lifted)
			return 0;
		op.kind = DOC_OP_LIFT;
		ret = push_op(app, &op);
		if (ret == 0 && app->tree.lifted) {
			/* a short swing, so the visitor sees the tree has become 3D */
			app->turning = true;
			app->turn_start_us = time_us;
		}
		return ret == -ENOSPC ? 0 : ret;
	case BUTTON_CLONE:
		set_mode(app, APP_MODE_CLONE);
		return 0;
	case BUTTON_LEAF:
		set_mode(app, APP_MODE_LEAF);
		return 0;
	case BUTTON_PROPAGATE:
		set_mode(app, APP_MODE_PROPAGATE);
		return 0;
	case BUTTON_FIXED_COUNT:
		app->pattern = APP_PATTERN_FIXED_COUNT;
		return 0;
	case BUTTON_FIXED_SIZE:
		app->pattern = APP_PATTERN_FIXED_SIZE;
		return 0;
	case BUTTON_UNDO:
		return doc_undo(&app->doc) ? app_rebuild(app) : 0;
	case BUTTON_REDO:
		return doc_redo(&app->doc) ? app_rebuild(app) : 0;
	case BUTTON_EXPORT:
		app->requests |= APP_REQUEST_EXPORT;
		return 0;
	case BUTTON_NEW:
		/* Undoable, so a visitor who pressed it by accident gets the tree back. */
		app->mode = APP_MODE_SKETCH;
		if (app->tree.nbranches == 0 && app->tree.nleaves == 0)
			return 0;
		ret = push_op(app, &op);
		return ret == -ENOSPC ? 0 : ret;
	case BUTTON_VIEW:
		app->turning = false;
		app->orbiting = false;
		set_camera(app, (struct camera){ 0.0f, 0.0f });
		return 0;
	case BUTTON_COUNT:
		break;
	}
	return 0;
}

/* The on-screen button at (x, y): the bar, and the front view button of a 3D tree. */
static bool ui_hit(const struct app *app, double x, double y, enum button *button)
{
	if (layout_hit(&app->view, x, y, button))
		return true;
	if (app->tree.lifted && layout_hit_view_button(&app->view, x, y)) {
		*button = BUTTON_VIEW;
		return true;
	}
	return false;
}

bool app_would_orbit(const struct app *app, double x, double y)
{
	enum button hit;

	if (!app->tree.lifted || app->pen.tool != EVENT_TOOL_PEN || ui_hit(app, x, y, &hit))
		return false;
	return !sketch_view_near(&app->tree, app->camera, view_to_world(&app->view, x, y),
				 APP_ORBIT_CLEARANCE_M);
}

/* Dragging right turns the tree to the right, like a turntable; dragging down lets the
 * visitor look down on it. */
static void orbit_to(struct app *app, const struct event *ev)
{
	double x = clamp(ev->x, 0, app->view.width), y = clamp(ev->y, 0, app->view.height);
	double k = app->view.m_per_px * APP_ORBIT_DEG_PER_M;

	set_camera(app, camera_normalize(app->camera.yaw - (x - app->orbit_x) * k,
					 app->camera.pitch + (y - app->orbit_y) * k));
	app->orbit_x = x;
	app->orbit_y = y;
}

bool app_set_camera(struct app *app, struct camera c)
{
	if (!app->tree.lifted)
		return false;
	app->turning = false;
	set_camera(app, camera_normalize(c.yaw, c.pitch));
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

static int button_event(struct app *app, enum button button, bool pressed, uint64_t time_us)
{
	app->buttons_down[button] = pressed;
	return pressed ? press_button(app, button, time_us) : 0;
}

void app_handle_event(struct app *app, const struct event *ev)
{
	int ret = 0;
	enum button hit;

	app->last_time_us = ev->time_us;
	switch (ev->type) {
	case EVENT_PROXIMITY_IN:
		update_pen(app, ev);
		app->pen.in_proximity = true;
		break;
	case EVENT_PROXIMITY_OUT:
		update_pen(app, ev);
		if (app->stroke.active)
			ret = stroke_commit(app);
		app->orbiting = false;
		if (app->ui_button_held) {
			app->ui_button_held = false;
			app_fail(app, ret);
			ret = button_event(app, app->ui_button, false, ev->time_us);
		}
		app->pen.in_proximity = false;
		break;
	case EVENT_TIP_DOWN:
		update_pen(app, ev);
		app->pen.in_proximity = true;
		if (app->stroke.active)
			ret = stroke_commit(app);
		/* The pen presses on-screen buttons like the GPIO ones: down now, up on lift. */
		app->orbiting = false;
		if (!app->ui_button_held && ui_hit(app, ev->x, ev->y, &hit)) {
			app->ui_button_held = true;
			app->ui_button = hit;
			app_fail(app, ret);
			ret = button_event(app, hit, true, ev->time_us);
			break;
		}
		/* the pen takes over: the turn into 3D stops where the visitor left it */
		app->turning = false;
		if (app_would_orbit(app, ev->x, ev->y)) {
			app->orbiting = true;
			app->orbit_x = clamp(ev->x, 0, app->view.width);
			app->orbit_y = clamp(ev->y, 0, app->view.height);
			break;
		}
		app->stroke.active = true;
		app->stroke.tool = ev->tool;
		app->stroke.npoints = 0;
		if (ret == 0)
			ret = stroke_add(app, ev);
		break;
	case EVENT_MOTION:
		update_pen(app, ev);
		if (app->orbiting)
			orbit_to(app, ev);
		else if (app->stroke.active)
			ret = stroke_add(app, ev);
		break;
	case EVENT_TIP_UP:
		update_pen(app, ev);
		if (app->ui_button_held) {
			app->ui_button_held = false;
			ret = button_event(app, app->ui_button, false, ev->time_us);
		} else if (app->orbiting) {
			orbit_to(app, ev);
			app->orbiting = false;
		} else if (app->stroke.active) {
			ret = stroke_add(app, ev);
			if (ret == 0)
				ret = stroke_commit(app);
		}
		break;
	case EVENT_PEN_BUTTON:
		update_pen(app, ev);
		if (ev->button == EVENT_PEN_BUTTON_STYLUS)
			app->pen.stylus = ev->pressed;
		else
			app->pen.stylus2 = ev->pressed;
		break;
	case EVENT_BUTTON:
		if (ev->button < 0 || ev->button >= BUTTON_COUNT)
			break;
		ret = button_event(app, (enum button)ev->button, ev->pressed, ev->time_us);
		break;
	}
	app_fail(app, ret);
}

uint32_t app_take_requests(struct app *app)
{
	uint32_t r = app->requests;

	app->requests = 0;
	return r;
}
