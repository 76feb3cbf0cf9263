/* SPDX-License-Identifier: MIT */
/*
 * The app's tree along its document's history: the full rebuild (--load, and whenever
 * nothing quicker applies), and undo and redo. Every op applied records its delta
 * (tree_delta.h) as well as its mark (history.h); undo and redo then move the elements
 * the op took out, put in or changed between the tree and the delta, and their parts of
 * the meshes with them, meshing in place only what they leave without a part. Every path
 * ends in the state a full replay gives, bit for bit (tree, generator, meshes, the camera
 * following the tree): the deltas hold the very elements the ops made, the stashed parts
 * the very parts a build makes of them.
 */
#include <errno.h>
#include <stdlib.h>

#include "app_private.h"
#include "doc.h"
#include "mesh_reuse.h"
#include "sketch.h"
#include "tree_delta.h"
#include "tree_index.h"
#include "wood.h"

/* Marks for meshes of no element. 0 or -ENOMEM. */
static int empty_marks(struct tree_mesh_marks *mk)
{
	tree_mesh_marks_finish(mk);
	mk->bark = calloc(1, sizeof(*mk->bark));
	mk->leaves = calloc(1, sizeof(*mk->leaves));
	if (!mk->bark || !mk->leaves) {
		tree_mesh_marks_finish(mk);
		return -ENOMEM;
	}
	mk->nbark = mk->nleaves = mk->cap_bark = mk->cap_leaves = 1;
	return 0;
}

static bool marks_fit(const struct tree_mesh_marks *mk, size_t nb, size_t nl)
{
	return mk->nbark == nb + 1 && mk->nleaves == nl + 1;
}

/*
 * What app_push_op and replays apply: ops[k - 1] on top of the app's tree (state k - 1),
 * recorded as state k with, unless the history has it already, the op's delta. While
 * replaying, an op that leaves little of the tree gets the meshes of the tree before it
 * kept in its delta, so that undoing it needs no meshing either. Returns apply_op's
 * SKETCH_GREW/CHANGED or < 0.
 */
static int apply_recorded(struct app *app, size_t k, bool replaying)
{
	const struct doc_op *op = &app->doc.ops[k - 1];
	size_t nb = app->tree.nbranches, nl = app->tree.nleaves;
	bool record = !history_delta(&app->history, k), copied = false, journaled = false;
	struct tree before;
	struct tree_delta d;
	struct tree_mesh stash;
	struct tree_mesh_marks stash_mk;
	bool stashed = false;
	int ret;

	tree_init(&before);
	tree_delta_init(&d);
	tree_mesh_init(&stash);
	tree_mesh_marks_init(&stash_mk);
	/* the tree is state k - 1 (a new app's first op: state 0 was never recorded) */
	if (!history_mark(&app->history, k - 1))
		history_record(&app->history, k - 1, &app->tree, &app->rng, false, false,
			       app->doc.cursor);
	/* what the op's row says of it (app_ops.c) */
	if (record && replaying && app_op_kind(op->kind)->replaces_tree && (nb || nl))
		stashed = tree_mesh_build_marked(&stash, &app->tree, &stash_mk) == 0;
	if (record && app_op_kind(op->kind)->edits_in_place)
		copied = tree_copy(&before, &app->tree) == 0;
	else if (record)
		journaled = tree_journal_begin(&app->tree) == 0;
	ret = app_apply_op(app, op);
	if (journaled && (ret < 0 || tree_journal_end(&app->tree, &d) < 0))
		journaled = false;
	if (copied && (ret < 0 || tree_delta_diff(&d, &before, &app->tree) < 0))
		copied = false;
	tree_journal_discard(&app->tree); /* an op that failed half-way */
	tree_finish(&before);
	if (ret >= 0) {
		bool grew = ret == SKETCH_GREW && app->tree.nbranches >= nb && app->tree.nleaves >= nl;

		history_record(&app->history, k, &app->tree, &app->rng, grew, replaying,
			       app->doc.cursor);
		/* an op that only appended is undone from its marks alone (one that changed
		 * no element but the sketching state, a lift of a lone trunk, keeps its
		 * empty delta: undone by the same swap) */
		if ((journaled || copied) && !(grew && tree_delta_appended_only(&d))) {
			if (stashed && marks_fit(&stash_mk, d.side[0].nbranches, d.side[0].nleaves)) {
				tree_mesh_shrink(&stash);
				d.side[0].mesh = stash;
				d.side[0].mk = stash_mk;
				d.side[0].stash = TREE_STASH_WHOLE;
				tree_mesh_init(&stash);
				tree_mesh_marks_init(&stash_mk);
			}
			(void)history_delta_put(&app->history, k, &d, app->doc.cursor);
		}
	}
	tree_delta_finish(&d);
	tree_mesh_finish(&stash);
	tree_mesh_marks_finish(&stash_mk);
	return ret;
}

int app_apply_recorded(struct app *app, size_t k)
{
	return apply_recorded(app, k, false);
}

static int mesh_rebuild(struct app *app)
{
	app->mesh_serial++;
	app->history.work.full_mesh = true;
	return tree_mesh_build_marked(&app->mesh, &app->tree, &app->mesh_marks);
}

/* The tree and generator at state `from` are the app's: replays up to the cursor. */
static int replay_from(struct app *app, size_t from)
{
	for (size_t k = from + 1; k <= app->doc.cursor; k++) {
		int ret = apply_recorded(app, k, true);

		app->history.work.replayed++;
		if (ret < 0)
			return ret;
	}
	return 0;
}

int app_rebuild(struct app *app)
{
	int ret;

	history_deltas_fit(&app->history, app->doc.cursor);
	tree_clear(&app->tree);
	tree_index_keep(&app->tree); /* a quicker way that failed may have taken it */
	rng_seed(&app->rng, app->doc.seed);
	history_record(&app->history, 0, &app->tree, &app->rng, false, true, app->doc.cursor);
	ret = replay_from(app, 0);
	app_camera_follow_tree(app);
	return ret < 0 ? ret : mesh_rebuild(app);
}

/* The meshes of the app's tree, made from those of app->before (which goes). */
static int mesh_from_before(struct app *app)
{
	int ret;

	app->mesh_serial++;
	app->history.work.full_mesh = true;
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

/* The cursor's state from the nearest checkpoint below it, or from scratch (an op whose
 * delta memory did not allow). The tree left is kept meanwhile, so that what the two
 * share is not meshed again. */
static int rebuild_from_checkpoint(struct app *app)
{
	const struct history_checkpoint *cp = history_checkpoint_below(&app->history, app->doc.cursor);

	history_deltas_fit(&app->history, app->doc.cursor);
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

/* ---- meshes from a delta ---- */

static bool in_wood(const struct wood *w, size_t i)
{
	return w && i < w->nbranches && w->voxelised[i];
}

/*
 * Where each element of the tree (now at side s of d, just come from the other side,
 * whose meshes app->mesh holds) gets its part: the old part of a shared element whose
 * parent and grandparent are shared too (a part depends on those alone, mesh.h) and that
 * the wood holds or not alike; else the stash of side s, if it has the part; else built.
 */
static bool plan_parts(const struct app *app, const struct tree_delta *d, int s, int old_sides,
		       const int *from_b, const int *from_l, int *plan_b, int *plan_l)
{
	const struct tree *t = &app->tree;
	const struct tree_delta_side *side = &d->side[s];
	const struct wood *old_wood = d->wood ? d->side[!s].wood : t->wood;
	bool parts = side->stash == TREE_STASH_PARTS &&
		     marks_fit(&side->mk, side->nb, side->nl);
	bool any_old = false;
	size_t q = 0;

	for (size_t i = 0; i < t->nbranches; i++) {
		const struct branch *b = &t->branches[i];
		int j = from_b[i], p = b->parent;
		bool listed = q < side->nb && side->branch_at[q] == i;

		plan_b[i] = listed && parts ? -2 - (int)q : TREE_MESH_BUILD;
		q += listed;
		if (j < 0 || t->sides != old_sides || in_wood(t->wood, i) != in_wood(old_wood, (size_t)j))
			continue;
		if (p >= 0 && (from_b[p] < 0 || (t->branches[p].parent >= 0 &&
						 from_b[t->branches[p].parent] < 0)))
			continue;
		plan_b[i] = j;
		any_old = true;
	}
	q = 0;
	for (size_t i = 0; i < t->nleaves; i++) {
		bool listed = q < side->nl && side->leaf_at[q] == i;

		plan_l[i] = from_l[i] >= 0 ? from_l[i] : listed && parts ? -2 - (int)q : TREE_MESH_BUILD;
		q += listed;
		any_old |= from_l[i] >= 0;
	}
	return any_old;
}

/*
 * The meshes of the tree, now at side s of d, from those of the other side that
 * app->mesh holds. The parts leaving go to the other side's stash: the listed ones, or
 * the whole meshes when nothing is kept. 0 or -ENOMEM (meshes then empty).
 */
static int mesh_to_side(struct app *app, struct tree_delta *d, int s, int old_sides,
			const int *from_b, const int *from_l)
{
	struct tree_delta_side *side = &d->side[s], *other = &d->side[!s];
	struct tree_mesh_plan plan = { 0 };
	int *plan_b, *plan_l, ret = -ENOMEM;
	bool known = marks_fit(&app->mesh_marks, other->nbranches, other->nleaves);
	size_t built = 0;

	app->mesh_serial++;
	tree_delta_drop_stash(other);
	if (side->stash == TREE_STASH_WHOLE && marks_fit(&side->mk, side->nbranches, side->nleaves)) {
		/* the very meshes of this state: a swap */
		struct tree_mesh m = app->mesh;
		struct tree_mesh_marks mk = app->mesh_marks;

		app->mesh = side->mesh;
		app->mesh_marks = side->mk;
		other->mesh = m;
		other->mk = mk;
		other->stash = known ? TREE_STASH_WHOLE : TREE_STASH_NONE;
		if (!known)
			tree_delta_drop_stash(other);
		else
			tree_mesh_shrink(&other->mesh);
		tree_mesh_init(&side->mesh);
		tree_mesh_marks_init(&side->mk);
		side->stash = TREE_STASH_NONE;
		return 0;
	}
	plan_b = malloc((app->tree.nbranches + 1) * sizeof(*plan_b));
	plan_l = malloc((app->tree.nleaves + 1) * sizeof(*plan_l));
	if (!plan_b || !plan_l || !known)
		goto full;
	if (plan_parts(app, d, s, old_sides, from_b, from_l, plan_b, plan_l)) {
		/* the parts that leave, for coming back (a cache: without memory, none) */
		if (tree_mesh_copy_parts(&other->mesh, &other->mk, &app->mesh, &app->mesh_marks,
					 other->branch_at, other->nb, other->leaf_at, other->nl) == 0)
			other->stash = TREE_STASH_PARTS;
		else
			tree_delta_drop_stash(other);
	} else {
		/* nothing stays: the meshes as they are are the other side's */
		other->mesh = app->mesh;
		other->mk = app->mesh_marks;
		other->stash = TREE_STASH_WHOLE;
		tree_mesh_shrink(&other->mesh);
		tree_mesh_init(&app->mesh);
		tree_mesh_marks_init(&app->mesh_marks);
		if (empty_marks(&app->mesh_marks) < 0)
			goto full;
	}
	if (side->stash == TREE_STASH_PARTS) {
		plan.stash = &side->mesh;
		plan.stash_mk = &side->mk;
	}
	plan.branch = plan_b;
	plan.leaf = plan_l;
	ret = tree_mesh_update(&app->mesh, &app->mesh_marks, &app->tree, &plan, &built);
	app->history.work.meshed += built;
	if (ret == 0)
		tree_delta_drop_stash(side); /* in the meshes now */
full:
	free(plan_b);
	free(plan_l);
	if (ret < 0) {
		tree_delta_drop_stash(side);
		ret = mesh_rebuild(app);
	}
	return ret;
}

/* Moves the tree to the side of op k's delta that it holds (undo: before, redo: after). */
static int swap_to(struct app *app, size_t k, struct tree_delta *d)
{
	int s = d->stored, old_sides = app->tree.sides, ret;
	const struct history_mark *m = history_mark(&app->history, s ? k : k - 1);
	int *from_b, *from_l;

	if (!m)
		return -EINVAL;
	from_b = malloc((d->side[s].nbranches + 1) * sizeof(*from_b));
	from_l = malloc((d->side[s].nleaves + 1) * sizeof(*from_l));
	ret = from_b && from_l ? tree_delta_swap(d, &app->tree, from_b, from_l) : -ENOMEM;
	if (ret < 0) {
		free(from_b);
		free(from_l);
		return ret;
	}
	history_mark_restore(m, &app->tree, &app->rng);
	app->history.work.moved += d->side[0].nb + d->side[0].nl + d->side[1].nb + d->side[1].nl;
	app_camera_follow_tree(app);
	ret = mesh_to_side(app, d, s, old_sides, from_b, from_l);
	free(from_b);
	free(from_l);
	history_delta_changed(&app->history, k, app->doc.cursor);
	return ret;
}

/* The op just undone (into state cursor + 1) only appended and left no delta: its
 * elements, and their parts of the meshes, go to a new one for redo. */
static int undo_appended(struct app *app, size_t k)
{
	const struct history_mark *now = history_mark(&app->history, k);
	const struct history_mark *to = history_mark(&app->history, k - 1);
	struct tree_delta d;
	struct tree_delta_side *after = &d.side[1];
	bool known = marks_fit(&app->mesh_marks, app->tree.nbranches, app->tree.nleaves);

	if (!now || !to || !now->grew || now->nbranches != app->tree.nbranches ||
	    now->nleaves != app->tree.nleaves || to->nbranches > now->nbranches ||
	    to->nleaves > now->nleaves)
		return -EINVAL;
	tree_delta_init(&d);
	if (tree_delta_take_appended(&d, &app->tree, to->nbranches, to->nleaves) < 0)
		return -ENOMEM;
	history_mark_restore(to, &app->tree, &app->rng);
	app->history.work.moved += after->nb + after->nl;
	app_camera_follow_tree(app);
	app->mesh_serial++;
	if (known && tree_mesh_copy_parts(&after->mesh, &after->mk, &app->mesh, &app->mesh_marks,
					  after->branch_at, after->nb, after->leaf_at, after->nl) == 0)
		after->stash = TREE_STASH_PARTS;
	else
		tree_delta_drop_stash(after);
	(void)history_delta_put(&app->history, k, &d, app->doc.cursor);
	if (tree_mesh_truncate(&app->mesh, &app->mesh_marks, app->tree.nbranches, app->tree.nleaves))
		return 0;
	return mesh_rebuild(app);
}

int app_undo(struct app *app)
{
	size_t k = app->doc.cursor + 1;
	struct tree_delta *d = history_delta(&app->history, k);
	int ret = -EINVAL;

	app->history.work = (struct history_work){ 0 };
	if (d && d->stored == 0)
		ret = swap_to(app, k, d);
	else if (!d)
		ret = undo_appended(app, k);
	if (ret == -ENOMEM)
		return rebuild_after_failure(app);
	if (ret < 0) {
		history_delta_drop(&app->history, k);
		return rebuild_from_checkpoint(app);
	}
	return ret;
}

/* The meshes after op k was applied on top of the tree (a new op or a redo): appended
 * parts, or the in-place update its delta describes, or a full build. */
static int mesh_after_op(struct app *app, size_t k, size_t nb, size_t nl, int applied)
{
	struct tree_delta *d = history_delta(&app->history, k);
	const struct history_mark *before = history_mark(&app->history, k - 1);
	int *from_b, *from_l, ret;

	if (applied == SKETCH_GREW && app->tree.nbranches >= nb && app->tree.nleaves >= nl) {
		app->mesh_serial++;
		app->history.work.meshed += app->tree.nbranches - nb + app->tree.nleaves - nl;
		return tree_mesh_append_marked(&app->mesh, &app->tree, nb, nl, &app->mesh_marks);
	}
	if (!d || d->stored != 0 || !before)
		return mesh_rebuild(app);
	from_b = malloc((app->tree.nbranches + 1) * sizeof(*from_b));
	from_l = malloc((app->tree.nleaves + 1) * sizeof(*from_l));
	if (!from_b || !from_l) {
		free(from_b);
		free(from_l);
		return mesh_rebuild(app);
	}
	tree_delta_map(d, 1, from_b, from_l);
	ret = mesh_to_side(app, d, 1, before->sides, from_b, from_l);
	free(from_b);
	free(from_l);
	history_delta_changed(&app->history, k, app->doc.cursor);
	return ret;
}

int app_mesh_after_op(struct app *app, size_t nb, size_t nl, int applied)
{
	return mesh_after_op(app, app->doc.cursor, nb, nl, applied);
}

int app_redo(struct app *app)
{
	size_t k = app->doc.cursor;
	struct tree_delta *d = history_delta(&app->history, k);
	size_t nb = app->tree.nbranches, nl = app->tree.nleaves;
	int ret;

	app->history.work = (struct history_work){ 0 };
	if (d && d->stored == 1) {
		ret = swap_to(app, k, d);
		if (ret == -ENOMEM)
			return rebuild_after_failure(app);
		if (ret == 0)
			return 0;
	}
	history_delta_drop(&app->history, k);
	/* applied again, as a new op would be */
	ret = apply_recorded(app, k, false);
	app->history.work.replayed++;
	if (ret < 0)
		return rebuild_after_failure(app); /* half an op may have been made */
	app_camera_follow_tree(app);
	return mesh_after_op(app, k, nb, nl, ret);
}
