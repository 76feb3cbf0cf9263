/* SPDX-License-Identifier: MIT */
#include "app.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "app_mode.h"
#include "app_private.h"
#include "gen.h"
#include "sketch.h"
#include "tree_index.h"
#include "vine_support.h"
#include "wood.h"

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
	screen_init(&app->screen, width, height);
	doc_init(&app->doc, seed);
	tree_init(&app->tree);
	tree_index_keep(&app->tree); /* strokes find their branch in it, not by a scan */
	tree_mesh_init(&app->mesh);
	tree_mesh_marks_init(&app->mesh_marks);
	history_init(&app->history);
	tree_init(&app->before);
	tree_init(&app->replaced.tree);
	rng_seed(&app->rng, seed);
	app->pattern = APP_PATTERN_AUTO;
	app->selected = -1;
	app->suggest_branch = -1;
	for (int i = 0; i < ARRANGE_COUNT; i++)
		tree_mesh_init(&app->previews[i]);
	for (int i = 0; i < GEN_PRESET_COUNT; i++)
		tree_mesh_init(&app->templates[i]);
	tree_mesh_init(&app->vines_mesh);
	tree_mesh_init(&app->growth.mesh);
	wood_params_default(&app->wood_settings);
	app->swell_start_us = UINT64_MAX;
	app_live_init(app);
	return app;
}

void app_destroy(struct app *app)
{
	if (!app)
		return;
	doc_finish(&app->doc);
	tree_finish(&app->tree);
	tree_mesh_finish(&app->mesh);
	tree_mesh_marks_finish(&app->mesh_marks);
	history_finish(&app->history);
	tree_finish(&app->before);
	tree_finish(&app->replaced.tree);
	for (int i = 0; i < ARRANGE_COUNT; i++)
		tree_mesh_finish(&app->previews[i]);
	for (int i = 0; i < GEN_PRESET_COUNT; i++)
		tree_mesh_finish(&app->templates[i]);
	app_vine_growth_clear(app);
	vine_support_destroy(app->bark_index);
	tree_mesh_finish(&app->vines_mesh);
	tree_mesh_finish(&app->growth.mesh);
	app_live_finish(app);
	free(app->stroke.points);
	free(app);
}

/* An op on the tree, as its kind's row says (app_ops.c); one that changed its branches
 * drops its wood (app_wood.c). */
int app_apply_op(struct app *app, const struct doc_op *op)
{
	const struct app_op_kind *k = app_op_kind(op->kind);
	int ret = k->apply ? k->apply(app, op) : SKETCH_CHANGED;

	if (ret >= 0 && !app_op_keeps_wood(op->kind, ret))
		tree_wood_drop(&app->tree);
	return ret;
}

int app_load_doc(struct app *app, struct doc *doc)
{
	int ret, r2;

	doc_finish(&app->doc);
	history_clear(&app->history);
	app->doc = *doc;
	doc_init(doc, doc->seed);
	app_op_hooks_clear(app);
	app->camera = app->doc.view; /* kept if the drawing is a 3D tree */
	ret = app_rebuild(app);
	r2 = app_vines_refresh(app);
	ret = ret < 0 ? ret : r2;
	/* a 3D drawing grows in as it comes on the screen */
	r2 = app_live_loaded(app);
	return ret < 0 ? ret : r2;
}

int app_reset(struct app *app, uint64_t seed)
{
	struct doc fresh;

	app->mode = APP_MODE_SKETCH;
	app->pattern = APP_PATTERN_AUTO;
	app->selected = -1;
	app->turning = false;
	app->orbiting = false;
	app_clear_suggestions(app);
	doc_init(&fresh, seed);
	return app_load_doc(app, &fresh);
}

bool app_take_replaced(struct app *app, struct tree *t, size_t *cursor)
{
	if (!app->replaced.pending)
		return false;
	*t = app->replaced.tree;
	*cursor = app->replaced.cursor;
	tree_init(&app->replaced.tree);
	app->replaced.pending = false;
	return true;
}

int app_show_tree(struct app *app, struct tree *t)
{
	int ret, r2;

	tree_finish(&app->tree);
	app->tree = *t;
	tree_init(t);
	app_op_hooks_clear(app);
	app->mesh_serial++;
	ret = tree_mesh_build_marked(&app->mesh, &app->tree, &app->mesh_marks);
	r2 = app_live_sync(app);
	return ret < 0 ? ret : r2;
}

/* Records an edit and applies it on top of the current tree (same result as a rebuild).
 * When the tree only grew, only the new elements are meshed: a stroke's cost does not
 * grow with the drawing. */
int app_push_op(struct app *app, struct doc_op *op)
{
	struct app_op_before before = { app->tree.nbranches, app->tree.nleaves, app->tree.nvines };
	int ret = doc_push(&app->doc, op);

	if (ret < 0)
		return ret;
	/* the ops that could be redone are gone, and what was known of their states */
	history_forget_after(&app->history, app->doc.cursor - 1);
	app->grow_lent_op = app->grow_lent ? &app->doc.ops[app->doc.cursor - 1] : NULL;
	app->bark_index_op = app->bark_index ? &app->doc.ops[app->doc.cursor - 1] : NULL;
	ret = app_apply_recorded(app, app->doc.cursor);
	if (ret < 0) {
		/* Half an edit may have been made: the document is the truth, rebuild from it. */
		(void)app_rebuild(app);
		return ret;
	}
	app_camera_follow_tree(app);
	app->mesh_serial++;
	/* appended parts, or those the op's delta says changed (app_history.c) */
	ret = app_mesh_after_op(app, before.nbranches, before.nleaves, ret);
	/* then what follows the ops (app_ops.c); op is the caller's again: the doc's copy */
	return app_op_hooks_after(app, &app->doc.ops[app->doc.cursor - 1], &before, ret);
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

/* Stored values avoid subnormal floats, which not every reader takes back. */
static float quantize(double v)
{
	return fabs(v) < 1e-9 ? 0.0f : (float)v;
}

static int stroke_add(struct app *app, const struct event *ev)
{
	struct app_stroke *s = &app->stroke;
	struct app_point *last = s->npoints ? &s->points[s->npoints - 1] : NULL;
	double x = app_clamp(ev->x, 0, app->screen.width), y = app_clamp(ev->y, 0, app->screen.height);
	double pressure = app_clamp(ev->pressure, 0, 1);

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
	size_t nleaves = app->tree.nleaves;
	double len = 0.0;
	bool taken;
	int ret;

	s->active = false;
	for (size_t i = 1; i < s->npoints; i++)
		len += hypot(s->points[i].x - s->points[i - 1].x, s->points[i].y - s->points[i - 1].y);
	ret = app_mode_stroke(app, len * app->screen.m_per_px, &taken);
	if (taken) {
		s->npoints = 0;
		return ret;
	}
	/* A pen tap is not a drawing: keep it out of the history. An eraser tap erases. */
	if (s->tool == EVENT_TOOL_PEN && (s->npoints < 2 || len * app->screen.m_per_px < SKETCH_MIN_LENGTH_M)) {
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
		struct vec3 w = screen_to_world(&app->screen, a->x, a->y);
		uint64_t dt = a->time_us - op.time_us;

		op.points[i] = (struct doc_point){
			.x = quantize(w.x),
			.y = quantize(w.y),
			.pressure = quantize(a->pressure),
			.dt_us = dt > UINT32_MAX ? UINT32_MAX : (uint32_t)dt,
		};
	}
	s->npoints = 0;
	ret = app_push_op(app, &op);
	doc_op_finish(&op);
	/* A full drawing takes no more strokes; the visitor can still undo or start anew. */
	if (ret == -ENOSPC)
		return 0;
	if (ret < 0)
		return ret;
	/* ids may have changed; a leaf drawn in leaf mode asks what its branch suggests */
	app->selected = -1;
	if (app->tree.nleaves > nleaves)
		return app_update_suggestions(app, app->tree.leaves[app->tree.nleaves - 1].branch);
	app_clear_suggestions(app);
	return 0;
}

/* Undo or redo: the cursor's state, without what showed the last ops (app_op_hooks_clear). */
static int history_step(struct app *app, bool undo)
{
	int ret;

	if (!(undo ? doc_undo(&app->doc) : doc_redo(&app->doc)))
		return 0;
	app_op_hooks_clear(app);
	ret = undo ? app_undo(app) : app_redo(app);
	if (ret == 0)
		ret = app_vines_refresh(app);
	if (ret == 0)
		ret = app_live_sync(app);
	return ret < 0 ? ret : app_refresh_mode_state(app);
}

/* The modes' buttons and the templates are their tables' (app_modes.c, app_mode_new.c). */
int app_press_button(struct app *app, enum button button, uint64_t time_us)
{
	struct doc_op op = { .kind = DOC_OP_LIFT, .time_us = time_us };
	const struct app_template *tpl = app_template_of(button);
	enum app_mode mode;
	int ret;

	if (app_mode_for_button(button, &mode))
		return app_mode_press(app, mode, time_us);
	if (tpl)
		return app_press_template(app, tpl, time_us);
	switch (button) {
	case BUTTON_3D:
		/* Once per drawing: a 3D tree stays 3D (undo goes back to the sketch). */
		if (app->tree.nbranches == 0 || app->tree.lifted)
			return 0;
		ret = app_push_op(app, &op);
		if (ret == 0 && app->tree.lifted) {
			/* a short swing, so the visitor sees the tree has become 3D */
			app->turning = true;
			app->turn_start_us = time_us;
		}
		return ret == -ENOSPC ? 0 : ret;
	case BUTTON_GROW:
		return app_grow(app, time_us);
	case BUTTON_FIXED_COUNT:
		app->pattern = APP_PATTERN_FIXED_COUNT;
		return 0;
	case BUTTON_FIXED_SIZE:
		app->pattern = APP_PATTERN_FIXED_SIZE;
		return 0;
	case BUTTON_UNDO:
	case BUTTON_REDO:
		return history_step(app, button == BUTTON_UNDO);
	case BUTTON_EXPORT:
		app->requests |= APP_REQUEST_EXPORT | (app->event_on_forest ? APP_REQUEST_FOREST : 0);
		return 0;
	case BUTTON_VIEW:
		app->turning = false;
		app->orbiting = false;
		app_camera_store(app, (struct camera){ 0.0f, 0.0f });
		return 0;
	case BUTTON_SEASON:
	case BUTTON_GEN_MORE:
	case BUTTON_GEN_FEWER:
	case BUTTON_GEN_WIDER:
	case BUTTON_GEN_NARROWER:
	case BUTTON_GEN_TALLER:
	case BUTTON_GEN_SHORTER:
	case BUTTON_GEN_LEAFIER:
	case BUTTON_GEN_BARER:
		return app_press_functional(app, button, time_us);
	case BUTTON_LEAF_DRAWN:
	case BUTTON_LEAF_ENTIRE:
	case BUTTON_LEAF_HOP:
	case BUTTON_LEAF_MAPLE: {
		/* the order of enum button is ori_kinds.h's, the drawn leaf first */
		int kind = (int)(button - BUTTON_LEAF_DRAWN) - 1;

		if (kind == app->tree.leaf_kind)
			return 0; /* the choice in effect: nothing to undo */
		return app_push_edit(app, DOC_OP_LEAFTYPE, 0, kind, time_us);
	}
	default:
		break; /* BUTTON_COUNT, and the tables' above */
	}
	return 0;
}

/* An orbit that went nowhere was a tap: the modes that take taps on the canvas get it as
 * a stroke of one point where the tip went down. */
static int canvas_tap(struct app *app, const struct event *ev)
{
	struct app_stroke *s = &app->stroke;
	struct event down = *ev;
	double moved = hypot(app_clamp(ev->x, 0, app->screen.width) - app->orbit_x0,
			     app_clamp(ev->y, 0, app->screen.height) - app->orbit_y0);
	int ret;

	if (!app_mode_ops(app->mode)->taps_on_canvas ||
	    moved * app->screen.m_per_px >= SKETCH_MIN_LENGTH_M)
		return 0;
	down.x = app->orbit_x0;
	down.y = app->orbit_y0;
	down.time_us = app->orbit_t0_us;
	s->tool = ev->tool;
	s->npoints = 0;
	ret = stroke_add(app, &down);
	return ret < 0 ? ret : stroke_commit(app);
}

static int button_event(struct app *app, enum button button, bool pressed, uint64_t time_us)
{
	app->buttons_down[button] = pressed;
	return pressed ? app_press_button(app, button, time_us) : 0;
}

void app_handle_event(struct app *app, const struct event *ev)
{
	int ret = 0;
	enum button hit;
	struct app_side_item item;

	app->event_on_forest = app_forest_at(app, ev->time_us);
	app->last_time_us = ev->time_us;
	/* a pen tip or a button put down finishes a tree growing in: nobody waits to draw */
	app_live_input(app, ev);
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
		app->side_held = false;
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
		if (!app->ui_button_held && app_ui_hit(app, ev->x, ev->y, &hit)) {
			app->ui_button_held = true;
			app->ui_button = hit;
			app_fail(app, ret);
			ret = button_event(app, hit, true, ev->time_us);
			break;
		}
		/* a tap on the side strip (a suggestion): the pen is then held until it lifts */
		if (!app->side_held && app_side_hit(app, ev->x, ev->y, &item)) {
			app->side_held = true;
			app_fail(app, ret);
			ret = app_side_tap(app, &item, ev->time_us);
			break;
		}
		if (app->side_held)
			break;
		/* the pen takes over: the turn into 3D stops where the visitor left it */
		app->turning = false;
		if (app_would_orbit(app, ev->x, ev->y)) {
			app->orbiting = true;
			app->orbit_x = app_clamp(ev->x, 0, app->screen.width);
			app->orbit_y = app_clamp(ev->y, 0, app->screen.height);
			app->orbit_x0 = app->orbit_x;
			app->orbit_y0 = app->orbit_y;
			app->orbit_t0_us = ev->time_us;
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
			app_orbit_to(app, ev);
		else if (app->stroke.active)
			ret = stroke_add(app, ev);
		break;
	case EVENT_TIP_UP:
		update_pen(app, ev);
		if (app->side_held) {
			app->side_held = false;
		} else if (app->ui_button_held) {
			app->ui_button_held = false;
			ret = button_event(app, app->ui_button, false, ev->time_us);
		} else if (app->orbiting) {
			app_orbit_to(app, ev);
			app->orbiting = false;
			ret = canvas_tap(app, ev);
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
