/* SPDX-License-Identifier: MIT */
/* The kiosk's modes (app_mode.h): entering and leaving them, and dispatching the pen's
 * strokes and the side strip's taps to the active one. What each mode does is its own
 * file: app_mode_sketch.c, app_mode_clone.c, app_mode_leaf.c, app_mode_propagate.c,
 * app_mode_new.c, app_mode_vine.c; docs/editing.md and docs/functional-trees.md say what the pen does. */
#include <errno.h>

#include "app_mode.h"
#include "app_private.h"
#include "layout.h"
#include "sketch.h"
#include "sketch_seen.h"

/* One row a mode: what it is and the button that enters it. */
static const struct app_mode_ops *const modes[APP_MODE_COUNT] = {
	[APP_MODE_SKETCH] = &app_mode_sketch_ops,
	[APP_MODE_CLONE] = &app_mode_clone_ops,
	[APP_MODE_LEAF] = &app_mode_leaf_ops,
	[APP_MODE_PROPAGATE] = &app_mode_propagate_ops,
	[APP_MODE_NEW] = &app_mode_new_ops,
	[APP_MODE_VINE] = &app_mode_vine_ops,
};

const struct app_mode_ops *app_mode_ops(enum app_mode mode)
{
	return (unsigned)mode < APP_MODE_COUNT ? modes[mode] : modes[APP_MODE_SKETCH];
}

bool app_mode_for_button(enum button b, enum app_mode *mode)
{
	for (int m = 0; m < APP_MODE_COUNT; m++) {
		if (b != BUTTON_COUNT && modes[m] && modes[m]->button == b) {
			*mode = (enum app_mode)m;
			return true;
		}
	}
	return false;
}

enum button app_mode_button(enum app_mode mode)
{
	return app_mode_ops(mode)->button;
}

enum button app_lit_button(const struct app *app)
{
	const struct app_mode_ops *m = app_mode_ops(app->mode);

	if (m->lit)
		return m->button;
	/* drawing on a 3D tree: the 3D button is lit */
	return app->tree.lifted ? BUTTON_3D : BUTTON_COUNT;
}

/* A mode's bar button: its own press, or the editing modes' way in and out. */
int app_mode_press(struct app *app, enum app_mode mode, uint64_t time_us)
{
	const struct app_mode_ops *m = app_mode_ops(mode);

	return m->press ? m->press(app, time_us) : app_set_mode(app, mode, time_us);
}

/* Records an editing op (clone, arrange, propagate, ...). A full drawing takes no more. */
int app_push_edit(struct app *app, enum doc_op_kind kind, int branch, int pattern,
		  uint64_t time_us)
{
	struct doc_op op = { .kind = kind, .time_us = time_us, .branch = branch, .pattern = pattern };
	int ret = app_push_op(app, &op);

	return ret == -ENOSPC ? 0 : ret;
}

bool app_has_child_branch(const struct tree *t, int b)
{
	for (size_t i = (size_t)b + 1; i < t->nbranches; i++)
		if (t->branches[i].parent == b)
			return true;
	return false;
}

bool app_has_leaf(const struct tree *t, int b)
{
	for (size_t i = 0; i < t->nleaves; i++)
		if (t->leaves[i].branch == b)
			return true;
	return false;
}

int app_branch_near(const struct app *app, struct vec3 p, double within)
{
	struct sketch_seen sv;
	struct sketch_hit h;

	if (sketch_seen_init(&sv, &app->tree, app->camera) < 0)
		return -1;
	h = sketch_nearest(sv.tree, p);
	sketch_seen_finish(&sv);
	return h.branch >= 0 && h.dist <= within ? h.branch : -1;
}

struct vec3 app_stroke_point(const struct app *app, size_t i)
{
	return screen_to_world(&app->screen, app->stroke.points[i].x, app->stroke.points[i].y);
}

/* After undo/redo the ids the modes hold may name nothing, or something else. */
int app_refresh_mode_state(struct app *app)
{
	if (app->selected >= 0 && (size_t)app->selected >= app->tree.nbranches)
		app->selected = -1;
	return app_update_suggestions(app, app->suggest_branch);
}

int app_mode_stroke(struct app *app, double len, bool *taken)
{
	const struct app_mode_ops *m = app_mode_ops(app->mode);

	*taken = false;
	if (app->stroke.tool != EVENT_TOOL_PEN)
		return 0;
	return m->stroke ? m->stroke(app, len, taken) : 0;
}

/*
 * The editing modes work on a 3D tree (sections 3.4-3.6 come after lifting): pressed on a
 * sketch they make it 3D first, as its own undoable step. On an empty canvas there is
 * nothing to edit and the pen keeps drawing. Pressing the active mode's button again goes
 * back to drawing.
 */
int app_set_mode(struct app *app, enum app_mode mode, uint64_t time_us)
{
	const struct app_mode_ops *m = app_mode_ops(mode);
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
	return m->enter ? m->enter(app, time_us) : 0;
}

size_t app_side_items(const struct app *app, struct app_side_item out[APP_SIDE_MAX])
{
	const struct app_mode_ops *m = app_mode_ops(app->mode);

	return m->side ? m->side(app, out, APP_SIDE_MAX) : 0;
}

/* Pictures a tap presses a button with are named (the templates); the leaf suggestions,
 * which the mode takes, are not. */
enum layout_side_kind app_side_kind(const struct app_side_item *item)
{
	if (!item->thumbnail)
		return LAYOUT_SIDE_BUTTONS;
	return item->button != BUTTON_COUNT ? LAYOUT_SIDE_NAMED_CARDS : LAYOUT_SIDE_CARDS;
}

bool app_side_hit(const struct app *app, double x, double y, struct app_side_item *item)
{
	struct app_side_item items[APP_SIDE_MAX];
	size_t n = app_side_items(app, items), slot;

	if (n == 0 || !layout_side_hit(&app->screen, x, y, n, app_side_kind(&items[0]), &slot))
		return false;
	*item = items[slot];
	return true;
}

/* A tap on the side strip: its button pressed as a GPIO one is, or the mode's own tap. */
int app_side_tap(struct app *app, const struct app_side_item *item, uint64_t time_us)
{
	const struct app_mode_ops *m = app_mode_ops(app->mode);

	if (item->button != BUTTON_COUNT)
		return app_press_button(app, item->button, time_us);
	return m->side_tap ? m->side_tap(app, item, time_us) : 0;
}
