/* SPDX-License-Identifier: MIT */
/*
 * Growing wood on the visitor's tree (issue 17, seed 002; docs/wood.md): a grow op is a
 * press, the first one applying the power law and registering the tree's thick branches;
 * an import op puts a skeleton's branches on the canvas. An edit that changes the tree's
 * branches drops its wood (the field no longer holds them): app_ops.c's rows say which
 * keep it. The grow and import ops' rows apply here; app_wood_hook swells the bark after
 * a press.
 */
#include <errno.h>
#include <stdint.h>
#include <stdlib.h>

#include "app_private.h"
#include "sketch.h"
#include "tree_index.h"
#include "wood.h"

/* A press on t with the op's settings (those of t's first press stand for its grid). */
int app_wood_apply(struct app *app, const struct doc_op *op)
{
	struct tree *t = &app->tree;
	int ret;

	if (!op->wood || !t->lifted || t->nbranches == 0)
		return SKETCH_GREW; /* nothing to grow */
	if (app->grow_lent && op == app->grow_lent_op) {
		/* grown off the loop from a copy of this very tree: the same tree, bit for bit */
		tree_swap(t, app->grow_lent);
		tree_index_keep(t);
		return SKETCH_CHANGED;
	}
	ret = wood_grow(t, op->wood);
	return ret < 0 ? ret : SKETCH_CHANGED;
}

int app_grow_job(const struct app *app, struct tree *copy, struct wood_params *p,
		 uint64_t *serial)
{
	*p = app->wood_settings;
	*serial = app->mesh_serial;
	return tree_copy(copy, &app->tree);
}

int app_grow_done(struct app *app, struct tree *grown, uint64_t serial, uint64_t now_us)
{
	struct doc_op op = { .kind = DOC_OP_GROW, .time_us = now_us };
	int ret;

	if (!app->grow_waiting)
		return 0;
	if (serial != app->mesh_serial)
		return -EAGAIN;
	op.wood = malloc(sizeof(*op.wood));
	if (!op.wood)
		return -ENOMEM;
	*op.wood = app->wood_settings;
	app->grow_waiting = false;
	app->grow_lent = grown;
	ret = app_push_op(app, &op);
	app->grow_lent = NULL;
	app->grow_lent_op = NULL;
	doc_op_finish(&op);
	if (app->status == APP_STATUS_GROWING)
		app_set_status(app, APP_STATUS_NONE, now_us);
	return ret == -ENOSPC ? 0 : ret;
}

int app_import_apply(struct app *app, const struct doc_op *op)
{
	struct tree *t = &app->tree;
	const struct tree *in = op->import;

	tree_clear(t);
	if (!in)
		return SKETCH_CHANGED;
	for (size_t i = 0; i < in->nbranches; i++) {
		const struct branch *b = &in->branches[i];
		int ret = tree_add_branch(t, b->parent, b->parent_t, b->origin, b->points, b->radii,
					  b->npoints);

		if (ret < 0)
			return ret;
		t->branches[ret].generation = b->generation;
	}
	t->lifted = true; /* a skeleton is 3D */
	tree_index_keep(t);
	return SKETCH_CHANGED;
}

/* --skeleton: as a template tap puts a tree on the canvas (app_generate.c). */
int app_import(struct app *app, struct tree *branches, uint64_t time_us)
{
	struct doc_op op = { .kind = DOC_OP_IMPORT, .time_us = time_us };
	int ret;

	op.import = malloc(sizeof(*op.import));
	if (!op.import)
		return -ENOMEM;
	tree_init(op.import);
	tree_swap(op.import, branches);
	app->mode = APP_MODE_SKETCH;
	app->selected = -1;
	app_clear_suggestions(app);
	ret = app_push_op(app, &op);
	doc_op_finish(&op);
	if (ret == 0 && app->tree.lifted) {
		/* the same short swing as after 3D: it is a 3D tree */
		app->turning = true;
		app->turn_start_us = time_us;
	}
	return ret;
}

bool app_op_keeps_wood(enum doc_op_kind kind, int result)
{
	/* appended branches and leaves keep their swept bark beside the wood */
	return app_op_kind(kind)->keeps_wood || result == SKETCH_GREW;
}

/* A press swells on screen; any other change of the tree shows its bark at rest. */
static int wood_after_op(struct app *app, const struct doc_op *op,
			 const struct app_op_before *before, int meshed)
{
	(void)before;
	(void)meshed;
	app->swell_start_us = app_op_kind(op->kind)->swells && app->tree.wood ? op->time_us
									     : UINT64_MAX;
	return 0;
}

static void wood_clear(struct app *app)
{
	app->swell_start_us = UINT64_MAX;
}

const struct app_op_hook app_wood_hook = {
	.name = "wood",
	.after_op = wood_after_op,
	.clear = wood_clear,
};

/* A year of growth: a grow press with the app's wood settings, on a 3D tree (a sketch is
 * made 3D first, as the modes do). */
int app_grow(struct app *app, uint64_t time_us)
{
	struct doc_op op = { .kind = DOC_OP_GROW, .time_us = time_us };
	int ret = 0;

	if (app->tree.nbranches == 0)
		return 0;
	if (!app->tree.lifted)
		ret = app_press_button(app, BUTTON_3D, time_us);
	if (ret < 0 || !app->tree.lifted)
		return ret;
	if (app->grow_async) {
		/* the kiosk presses off its loop; one press at a time */
		if (!app->grow_waiting) {
			app->grow_waiting = true;
			app->requests |= APP_REQUEST_GROW;
			app_hold_status(app, APP_STATUS_GROWING, time_us);
		}
		return 0;
	}
	op.wood = malloc(sizeof(*op.wood));
	if (!op.wood)
		return -ENOMEM;
	*op.wood = app->wood_settings;
	ret = app_push_op(app, &op);
	doc_op_finish(&op);
	return ret == -ENOSPC ? 0 : ret;
}

const struct mesh *app_wood_bark_at(const struct app *app, uint64_t now_us)
{
	const struct wood *w = app->tree.wood;
	uint64_t age;
	size_t k;

	if (!w)
		return NULL;
	if (now_us == UINT64_MAX || app->swell_start_us == UINT64_MAX || w->nswell == 0 ||
	    now_us < app->swell_start_us)
		return &w->bark;
	age = now_us - app->swell_start_us;
	/* frame k (the field k + 1 eighths of the way) for the k-th eighth of the second */
	k = age >= APP_SWELL_US ? SIZE_MAX : (size_t)(age * WOOD_SWELL_FRAMES / APP_SWELL_US);
	return k < (size_t)w->nswell ? &w->swell[k] : &w->bark;
}
