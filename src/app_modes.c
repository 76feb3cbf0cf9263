/* SPDX-License-Identifier: MIT */
/* The editing modes on the pen (seed 000, sections 3.4-3.6): clone taps and circles, the
 * leaf arrangement suggestions, propagation taps. The algorithms are clone.c, arrange.c
 * and propagate.c; docs/editing.md says what the pen does. */
#include <errno.h>
#include <math.h>

#include "app_private.h"
#include "layout.h"
#include "propagate.h"
#include "sketch.h"
#include "sketch_view.h"

/* Records an editing op (clone, arrange, propagate). A full drawing takes no more. */
int app_push_edit(struct app *app, enum doc_op_kind kind, int branch, int pattern,
		  uint64_t time_us)
{
	struct doc_op op = { .kind = kind, .time_us = time_us, .branch = branch, .pattern = pattern };
	int ret = app_push_op(app, &op);

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

void app_clear_suggestions(struct app *app)
{
	if (app->suggestions == 0 && app->suggest_branch < 0)
		return;
	app->suggestions = 0;
	app->suggest_branch = -1;
	app->previews_serial++;
}

/* The arrangements the leaves on branch b suggest, with a small mesh for each thumbnail. */
int app_update_suggestions(struct app *app, int b)
{
	app_clear_suggestions(app);
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
			app_clear_suggestions(app);
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
int app_refresh_mode_state(struct app *app)
{
	if (app->selected >= 0 && (size_t)app->selected >= app->tree.nbranches)
		app->selected = -1;
	return app_update_suggestions(app, app->suggest_branch);
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
int app_mode_stroke(struct app *app, double len, bool *taken)
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
				       app_push_edit(app, DOC_OP_CLONE_ADD, b, 0, t) : 0;
		}
		dir = stroke_circle(app, len, &c);
		if (dir == 0)
			return 0;
		*taken = true;
		b = app->selected >= 0 ? app->selected : branch_near(app, c, 1.0);
		if (b < 0 || !has_child_branch(&app->tree, b))
			return 0;
		app->selected = b;
		return app_push_edit(app, dir > 0 ? DOC_OP_CLONE_ADD : DOC_OP_CLONE_REMOVE, b, 0, t);
	case APP_MODE_PROPAGATE:
		if (!tap)
			return 0;
		*taken = true;
		b = branch_near(app, stroke_point(app, 0), APP_TAP_M);
		if (b < 0 || !(has_child_branch(&app->tree, b) || has_leaf(&app->tree, b)))
			return 0;
		return app_push_edit(app, DOC_OP_PROPAGATE, b, (int)propagate_pattern_for(app, b), t);
	case APP_MODE_SKETCH:
	case APP_MODE_LEAF:
		break;
	}
	return 0;
}

/*
 * The editing modes work on a 3D tree (sections 3.4-3.6 come after lifting): pressed on a
 * sketch they make it 3D first, as its own undoable step. On an empty canvas there is
 * nothing to edit and the pen keeps drawing. Pressing the active mode's button again goes
 * back to drawing.
 */
int app_set_mode(struct app *app, enum app_mode mode, uint64_t time_us)
{
	int ret = 0;

	app->selected = -1;
	app_clear_suggestions(app);
	if (app->mode == mode || app->tree.nbranches == 0) {
		app->mode = APP_MODE_SKETCH;
		return 0;
	}
	if (!app->tree.lifted)
		ret = app_press_button(app, BUTTON_3D, time_us);
	if (ret < 0 || !app->tree.lifted)
		return ret;
	app->mode = mode;
	/* leaves drawn before: the newest one's branch says what it suggests at once */
	for (size_t i = app->tree.nleaves; i-- > 0;)
		if (app->tree.leaves[i].origin == ORIGIN_SKETCH)
			return app_update_suggestions(app, app->tree.leaves[i].branch);
	return 0;
}

/* The leaf suggestion thumbnail at (x, y), if any is shown there. */
bool app_thumbnail_hit(const struct app *app, double x, double y, enum arrange_pattern *p)
{
	enum arrange_pattern list[ARRANGE_COUNT];
	size_t n = app_suggestions(app, list), slot;

	if (app->mode != APP_MODE_LEAF || !layout_side_hit(&app->view, x, y, n, true, &slot))
		return false;
	*p = list[slot];
	return true;
}
