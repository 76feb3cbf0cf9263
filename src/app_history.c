/* SPDX-License-Identifier: MIT */
/*
 * The app's tree along its document's history: the full rebuild (--load, and whenever
 * nothing quicker applies), and undo and redo, which reach the next state from what
 * history.h remembers. Every path ends in the state a full replay gives, bit for bit
 * (tree, generator, meshes, the camera following the tree): they apply the same ops to
 * the same states, or take back only what an op appended.
 */
#include <errno.h>

#include "app_private.h"
#include "doc.h"
#include "mesh_reuse.h"
#include "sketch.h"
#include "tree_index.h"

static bool slow_op(const struct doc_op *op)
{
	return op->kind == DOC_OP_LIFT || op->kind == DOC_OP_PROPAGATE || op->kind == DOC_OP_GENERATE ||
	       op->kind == DOC_OP_GROW || op->kind == DOC_OP_VINE; /* a press; a vine's growth */
}

/* What app_push_op and replays apply: op on top of the app's tree, then the state is
 * recorded as state k. Returns apply_op's SKETCH_GREW/CHANGED or < 0. */
int app_apply_recorded(struct app *app, size_t k)
{
	const struct doc_op *op = &app->doc.ops[k - 1];
	size_t nb = app->tree.nbranches, nl = app->tree.nleaves;
	int ret = app_apply_op(app, op);

	if (ret >= 0)
		history_record(&app->history, k, &app->tree, &app->rng,
			       ret == SKETCH_GREW && app->tree.nbranches >= nb && app->tree.nleaves >= nl,
			       slow_op(op), app->doc.cursor);
	return ret;
}

static int mesh_rebuild(struct app *app)
{
	app->mesh_serial++;
	return tree_mesh_build_marked(&app->mesh, &app->tree, &app->mesh_marks);
}

/* The tree and generator at state `from` are the app's: replays up to the cursor. */
static int replay_from(struct app *app, size_t from)
{
	for (size_t k = from + 1; k <= app->doc.cursor; k++) {
		int ret = app_apply_recorded(app, k);

		if (ret < 0)
			return ret;
	}
	return 0;
}

int app_rebuild(struct app *app)
{
	int ret;

	tree_clear(&app->tree);
	tree_index_keep(&app->tree); /* a quicker way that failed may have taken it */
	rng_seed(&app->rng, app->doc.seed);
	history_record(&app->history, 0, &app->tree, &app->rng, false, false, app->doc.cursor);
	ret = replay_from(app, 0);
	app_camera_follow_tree(app);
	return ret < 0 ? ret : mesh_rebuild(app);
}

/* The meshes of the app's tree, made from those of app->before (which goes). */
static int mesh_from_before(struct app *app)
{
	int ret;

	app->mesh_serial++;
	ret = tree_mesh_rebuild_from(&app->mesh, &app->mesh_marks, &app->tree, &app->before);
	tree_clear(&app->before);
	return ret;
}

/* The full rebuild when a quicker way ran out of memory: the document is the truth. */
static int rebuild_after_failure(struct app *app)
{
	tree_clear(&app->before);
	return app_rebuild(app);
}

/* The cursor's state from the nearest checkpoint below it, or from scratch. The tree
 * left is kept meanwhile, so that what the two share is not meshed again. */
static int rebuild_from_checkpoint(struct app *app)
{
	const struct history_checkpoint *cp = history_checkpoint_below(&app->history, app->doc.cursor);

	if (!cp)
		return app_rebuild(app);
	tree_swap(&app->tree, &app->before);
	if (tree_copy(&app->tree, &cp->tree) < 0)
		return rebuild_after_failure(app);
	/* the grid of the tree left serves the checkpoint's too, for what they share */
	tree_index_move(&app->tree, &app->before);
	app->rng = cp->rng;
	if (replay_from(app, cp->at) < 0)
		return rebuild_after_failure(app);
	app_camera_follow_tree(app);
	return mesh_from_before(app);
}

/* The op just undone (into state cursor + 1) only appended: take that back. */
static bool undo_appended(struct app *app)
{
	const struct history_mark *now = history_mark(&app->history, app->doc.cursor + 1);
	const struct history_mark *to = history_mark(&app->history, app->doc.cursor);

	if (!now || !to || !now->grew || now->nbranches != app->tree.nbranches ||
	    now->nleaves != app->tree.nleaves || to->nbranches > now->nbranches ||
	    to->nleaves > now->nleaves)
		return false;
	tree_truncate(&app->tree, to->nbranches, to->nleaves);
	history_mark_restore(to, &app->tree, &app->rng);
	return true;
}

int app_undo(struct app *app)
{
	if (!undo_appended(app))
		return rebuild_from_checkpoint(app);
	app_camera_follow_tree(app);
	app->mesh_serial++;
	if (tree_mesh_truncate(&app->mesh, &app->mesh_marks, app->tree.nbranches, app->tree.nleaves))
		return 0;
	return tree_mesh_build_marked(&app->mesh, &app->tree, &app->mesh_marks);
}

int app_redo(struct app *app)
{
	const struct doc_op *op = &app->doc.ops[app->doc.cursor - 1];
	const struct history_checkpoint *cp = history_checkpoint_below(&app->history, app->doc.cursor);
	const struct history_mark *m = history_mark(&app->history, app->doc.cursor);
	size_t nb = app->tree.nbranches, nl = app->tree.nleaves;
	bool reuse = false;
	int ret;

	/* a lift is redone faster from its copy than again */
	if (op->kind == DOC_OP_LIFT && cp && cp->at == app->doc.cursor)
		return rebuild_from_checkpoint(app);
	/* an op known to change elements: the tree before it is kept for its meshes */
	if (m && !m->grew)
		reuse = tree_copy(&app->before, &app->tree) == 0;
	ret = app_apply_recorded(app, app->doc.cursor);
	if (ret < 0)
		return rebuild_after_failure(app); /* half an op may have been made */
	app_camera_follow_tree(app);
	if (ret == SKETCH_GREW && app->tree.nbranches >= nb && app->tree.nleaves >= nl) {
		tree_clear(&app->before);
		app->mesh_serial++;
		return tree_mesh_append_marked(&app->mesh, &app->tree, nb, nl, &app->mesh_marks);
	}
	if (reuse)
		return mesh_from_before(app);
	return mesh_rebuild(app);
}
