/* SPDX-License-Identifier: MIT */
#include "app.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "clone.h"
#include "layout.h"
#include "lift.h"
#include "propagate.h"
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
	app->pattern = APP_PATTERN_AUTO;
	app->selected = -1;
	app->suggest_branch = -1;
	for (int i = 0; i < ARRANGE_COUNT; i++)
		tree_mesh_init(&app->previews[i]);
	return app;
}

void app_destroy(struct app *app)
{
	if (!app)
		return;
	doc_finish(&app->doc);
	tree_finish(&app->tree);
	tree_mesh_finish(&app->mesh);
	for (int i = 0; i < ARRANGE_COUNT; i++)
		tree_mesh_finish(&app->previews[i]);
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
	/* An edit whose branch is not there (a hand-edited file) does nothing. */
	case DOC_OP_CLONE_ADD: {
		int ret = clone_add(&app->tree, op->branch, &app->rng);

		return ret == -ENOENT || ret == -ENOSPC ? SKETCH_GREW : ret < 0 ? ret : SKETCH_GREW;
	}
	case DOC_OP_CLONE_REMOVE: {
		int ret = clone_remove(&app->tree, op->branch);

		return ret == -ENOENT ? SKETCH_GREW : ret < 0 ? ret : SKETCH_CHANGED;
	}
	case DOC_OP_ARRANGE: {
		int ret = arrange_apply(&app->tree, op->branch, (enum arrange_pattern)op->pattern);

		/* whorl-add moves the leaves already there */
		return ret == -ENOENT ? SKETCH_GREW : ret < 0 ? ret : SKETCH_CHANGED;
	}
	case DOC_OP_PROPAGATE: {
		int ret = propagate_apply(&app->tree, op->branch, (enum propagate_pattern)op->pattern);

		return ret == -ENOENT || ret == -ENOSPC ? SKETCH_GREW : ret < 0 ? ret : SKETCH_GREW;
	}
	}
	return SKETCH_CHANGED;
}

static void set_camera(struct app *app, struct camera c)
{
	app->camera = c;
	app->doc.view = c; /* saved with the drawing */
}

/* Only a 3D tree can be turned or edited by example: a sketch (after undoing 3D, or an
 * empty canvas) is shown from the front, in the sketch mode. */
static void camera_follow_tree(struct app *app)
{
	if (!app->tree.lifted) {
		set_camera(app, (struct camera){ 0.0f, 0.0f });
		app->turning = false;
		app->orbiting = false;
		app->mode = APP_MODE_SKETCH;
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

/* Records an editing op (clone, arrange, propagate). A full drawing takes no more. */
static int push_edit(struct app *app, enum doc_op_kind kind, int branch, int pattern,
		     uint64_t time_us)
{
	struct doc_op op = { .kind = kind, .time_us = time_us, .branch = branch, .pattern = pattern };
	int ret = push_op(app, &op);

	return ret == -ENOSPC ? 0 : ret;
}

static bool has_child_branch(const struct tree *t, int b)
{
	for (size_t i = (size_t)b + 1; i < t->nbranches; i++)
		if (t->branches[i].parent == b)
			return true;
	return false;
}

static bool has_leaf(const struct tree *t, int b)
{
	for (size_t i = 0; i < t->nleaves; i++)
		if (t->leaves[i].branch == b)
			return true;
	return false;
}

static void clear_suggestions(struct app *app)
{
	if (app->suggestions == 0 && app->suggest_branch < 0)
		return;
	app->suggestions = 0;
	app->suggest_branch = -1;
	app->previews_serial++;
}

/* The arrangements the leaves on branch b suggest, with a small mesh for each thumbnail. */
static int update_suggestions(struct app *app, int b)
{
	clear_suggestions(app);
	if (app->mode != APP_MODE_LEAF || b < 0 || (size_t)b >= app->tree.nbranches)
		return 0;
	app->suggest_branch = b;
	app->suggestions = arrange_suggest(&app->tree, b);
	for (int p = 0; p < ARRANGE_COUNT; p++) {
		struct tree preview;
		int ret;

		if (!(app->suggestions & (1u << p)))
			continue;
		ret = arrange_preview(&app->tree, b, (enum arrange_pattern)p, &preview);
		if (ret == 0)
			ret = tree_mesh_build(&app->previews[p], &preview);
		tree_finish(&preview);
		if (ret == -ENOMEM) {
			clear_suggestions(app);
			return ret;
		}
		if (ret < 0)
			app->suggestions &= ~(1u << p);
	}
	app->previews_serial++;
	return 0;
}

size_t app_suggestions(const struct app *app, enum arrange_pattern out[ARRANGE_COUNT])
{
	size_t n = 0;

	for (int p = 0; p < ARRANGE_COUNT; p++)
		if (app->suggestions & (1u << p))
			out[n++] = (enum arrange_pattern)p;
	return n;
}

/* After undo/redo the ids the modes hold may name nothing, or something else. */
static int refresh_mode_state(struct app *app)
{
	if (app->selected >= 0 && (size_t)app->selected >= app->tree.nbranches)
		app->selected = -1;
	return update_suggestions(app, app->suggest_branch);
}

/* The branch shown within APP_TAP_M of view-space point p, or -1. */
static int branch_near(const struct app *app, struct vec3 p, double within)
{
	struct sketch_view sv;
	struct sketch_hit h;

	if (sketch_view_init(&sv, &app->tree, app->camera) < 0)
		return -1;
	h = sketch_nearest(sv.tree, p);
	sketch_view_finish(&sv);
	return h.branch >= 0 && h.dist <= within ? h.branch : -1;
}

static struct vec3 stroke_point(const struct app *app, size_t i)
{
	return view_to_world(&app->view, app->stroke.points[i].x, app->stroke.points[i].y);
}

/*
 * A clone-mode circle: how far the pen went round the stroke's centre. +1 clockwise as
 * the visitor sees it (add a child), -1 anticlockwise (remove one), 0 not a circle.
 */
static int stroke_circle(const struct app *app, double len, struct vec3 *centre)
{
	const struct app_stroke *s = &app->stroke;
	struct vec3 c = vec3(0, 0, 0);
	double turn = 0.0, prev = 0.0;

	if (s->npoints < 8 || len < APP_CIRCLE_MIN_M)
		return 0;
	for (size_t i = 0; i < s->npoints; i++)
		c = vec3_add(c, stroke_point(app, i));
	c = vec3_scale(c, 1.0 / (double)s->npoints);
	for (size_t i = 0; i < s->npoints; i++) {
		struct vec3 p = stroke_point(app, i);
		double a = atan2(p.y - c.y, p.x - c.x), d;

		if (i > 0) {
			d = a - prev;
			d = d > VEC_PI ? d - 2 * VEC_PI : d < -VEC_PI ? d + 2 * VEC_PI : d;
			turn += d;
		}
		prev = a;
	}
	*centre = c;
	/* view space has y up: a positive turn is anticlockwise */
	return fabs(turn) < APP_CIRCLE_TURN ? 0 : turn < 0 ? 1 : -1;
}

static enum propagate_pattern propagate_pattern_for(const struct app *app, int b)
{
	if (app->pattern == APP_PATTERN_FIXED_COUNT)
		return PROPAGATE_FIXED_COUNT;
	if (app->pattern == APP_PATTERN_FIXED_SIZE)
		return PROPAGATE_FIXED_SIZE;
	return has_child_branch(&app->tree, b) ? PROPAGATE_FIXED_COUNT : PROPAGATE_FIXED_SIZE;
}

/*
 * What a finished pen stroke means in the clone and propagate modes (seed 000, 3.4 and
 * 3.6): taps pick branches, circles add and remove clones. Sets *taken when the stroke
 * was one of those; anything else is sketched as in the sketch mode.
 */
static int mode_stroke(struct app *app, double len, bool *taken)
{
	const struct app_stroke *s = &app->stroke;
	uint64_t t = s->points[0].time_us;
	bool tap = s->npoints < 2 || len < SKETCH_MIN_LENGTH_M;
	struct vec3 c;
	int b, dir;

	*taken = false;
	if (s->tool != EVENT_TOOL_PEN || !app->tree.lifted)
		return 0;
	switch (app->mode) {
	case APP_MODE_CLONE:
		if (tap) {
			*taken = true;
			b = branch_near(app, stroke_point(app, 0), APP_TAP_M);
			/* a tap picks a parent; tapping it again adds a child */
			if (b < 0 || b != app->selected) {
				app->selected = b;
				return 0;
			}
			return has_child_branch(&app->tree, b) ?
				       push_edit(app, DOC_OP_CLONE_ADD, b, 0, t) : 0;
		}
		dir = stroke_circle(app, len, &c);
		if (dir == 0)
			return 0;
		*taken = true;
		b = app->selected >= 0 ? app->selected : branch_near(app, c, 1.0);
		if (b < 0 || !has_child_branch(&app->tree, b))
			return 0;
		app->selected = b;
		return push_edit(app, dir > 0 ? DOC_OP_CLONE_ADD : DOC_OP_CLONE_REMOVE, b, 0, t);
	case APP_MODE_PROPAGATE:
		if (!tap)
			return 0;
		*taken = true;
		b = branch_near(app, stroke_point(app, 0), APP_TAP_M);
		if (b < 0 || !(has_child_branch(&app->tree, b) || has_leaf(&app->tree, b)))
			return 0;
		return push_edit(app, DOC_OP_PROPAGATE, b, (int)propagate_pattern_for(app, b), t);
	case APP_MODE_SKETCH:
	case APP_MODE_LEAF:
		break;
	}
	return 0;
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
	size_t nleaves = app->tree.nleaves;
	double len = 0.0;
	bool taken;
	int ret;

	s->active = false;
	for (size_t i = 1; i < s->npoints; i++)
		len += hypot(s->points[i].x - s->points[i - 1].x, s->points[i].y - s->points[i - 1].y);
	ret = mode_stroke(app, len * app->view.m_per_px, &taken);
	if (taken) {
		s->npoints = 0;
		return ret;
	}
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
	if (ret == -ENOSPC)
		return 0;
	if (ret < 0)
		return ret;
	/* ids may have changed; a leaf drawn in leaf mode asks what its branch suggests */
	app->selected = -1;
	if (app->tree.nleaves > nleaves)
		return update_suggestions(app, app->tree.leaves[app->tree.nleaves - 1].branch);
	clear_suggestions(app);
	return 0;
}

static int press_button(struct app *app, enum button button, uint64_t time_us);

/*
 * The editing modes work on a 3D tree (sections 3.4-3.6 come after lifting): pressed on a
 * sketch they make it 3D first, as its own undoable step. On an empty canvas there is
 * nothing to edit and the pen keeps drawing. Pressing the active mode's button again goes
 * back to drawing.
 */
static int set_mode(struct app *app, enum app_mode mode, uint64_t time_us)
{
	int ret = 0;

	app->selected = -1;
	clear_suggestions(app);
	if (app->mode == mode || app->tree.nbranches == 0) {
		app->mode = APP_MODE_SKETCH;
		return 0;
	}
	if (!app->tree.lifted)
		ret = press_button(app, BUTTON_3D, time_us);
	if (ret < 0 || !app->tree.lifted)
		return ret;
	app->mode = mode;
	/* leaves drawn before: the newest one's branch says what it suggests at once */
	for (size_t i = app->tree.nleaves; i-- > 0;)
		if (app->tree.leaves[i].origin == ORIGIN_SKETCH)
			return update_suggestions(app, app->tree.leaves[i].branch);
	return 0;
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
		return set_mode(app, APP_MODE_CLONE, time_us);
	case BUTTON_LEAF:
		return set_mode(app, APP_MODE_LEAF, time_us);
	case BUTTON_PROPAGATE:
		return set_mode(app, APP_MODE_PROPAGATE, time_us);
	case BUTTON_FIXED_COUNT:
		app->pattern = APP_PATTERN_FIXED_COUNT;
		return 0;
	case BUTTON_FIXED_SIZE:
		app->pattern = APP_PATTERN_FIXED_SIZE;
		return 0;
	case BUTTON_UNDO:
		if (!doc_undo(&app->doc))
			return 0;
		ret = app_rebuild(app);
		return ret < 0 ? ret : refresh_mode_state(app);
	case BUTTON_REDO:
		if (!doc_redo(&app->doc))
			return 0;
		ret = app_rebuild(app);
		return ret < 0 ? ret : refresh_mode_state(app);
	case BUTTON_EXPORT:
		app->requests |= APP_REQUEST_EXPORT;
		return 0;
	case BUTTON_NEW:
		/* Undoable, so a visitor who pressed it by accident gets the tree back. */
		app->mode = APP_MODE_SKETCH;
		app->selected = -1;
		clear_suggestions(app);
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

/* The on-screen button at (x, y): the bar, the front view button of a 3D tree and, in
 * propagate mode, the two patterns. */
static bool ui_hit(const struct app *app, double x, double y, enum button *button)
{
	size_t slot;

	if (layout_hit(&app->view, x, y, button))
		return true;
	if (app->tree.lifted && layout_hit_view_button(&app->view, x, y)) {
		*button = BUTTON_VIEW;
		return true;
	}
	if (app->mode == APP_MODE_PROPAGATE && layout_side_hit(&app->view, x, y, 2, false, &slot)) {
		*button = slot == 0 ? BUTTON_FIXED_COUNT : BUTTON_FIXED_SIZE;
		return true;
	}
	return false;
}

/* The leaf suggestion thumbnail at (x, y), if any is shown there. */
static bool thumbnail_hit(const struct app *app, double x, double y, enum arrange_pattern *p)
{
	enum arrange_pattern list[ARRANGE_COUNT];
	size_t n = app_suggestions(app, list), slot;

	if (app->mode != APP_MODE_LEAF || !layout_side_hit(&app->view, x, y, n, true, &slot))
		return false;
	*p = list[slot];
	return true;
}

bool app_would_orbit(const struct app *app, double x, double y)
{
	enum button hit;

	enum arrange_pattern p;

	if (!app->tree.lifted || app->pen.tool != EVENT_TOOL_PEN || ui_hit(app, x, y, &hit) ||
	    thumbnail_hit(app, x, y, &p))
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
	enum arrange_pattern pattern;

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
		if (!app->ui_button_held && ui_hit(app, ev->x, ev->y, &hit)) {
			app->ui_button_held = true;
			app->ui_button = hit;
			app_fail(app, ret);
			ret = button_event(app, hit, true, ev->time_us);
			break;
		}
		/* a tap on a suggestion applies it; the pen is then held until it lifts */
		if (!app->side_held && thumbnail_hit(app, ev->x, ev->y, &pattern)) {
			int b = app->suggest_branch;

			app->side_held = true;
			app_fail(app, ret);
			ret = push_edit(app, DOC_OP_ARRANGE, b, (int)pattern, ev->time_us);
			if (ret == 0)
				ret = update_suggestions(app, b); /* tapping again keeps adding */
			break;
		}
		if (app->side_held)
			break;
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
		if (app->side_held) {
			app->side_held = false;
		} else if (app->ui_button_held) {
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
