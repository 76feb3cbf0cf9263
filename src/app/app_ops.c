/* SPDX-License-Identifier: MIT */
/*
 * What the app knows of each kind of op of the drawing (doc.h), in one row a kind: the
 * function that applies it (in its system's file: app_mode_*.c, app_generate.c,
 * app_vine.c, app_wood.c) and the facts app.c, app_history.c, app_generate.c and the
 * hooks ask. And the systems that follow every op (leaves unfolding, the bark swelling, a
 * vine growing, the tree growing in), walked by app_push_op after each op and cleared when the tree changes
 * otherwise. A new op kind is its apply function and a row here; a new system that
 * follows the ops is its hook and a line in app_op_hooks.
 */
#include "app_private.h"

/* Sized by its rows: doc.h's enum has no count, and a new kind is only its row here. */
static const struct app_op_kind kinds[] = {
	[DOC_OP_STROKE] = { .apply = app_stroke_apply },
	[DOC_OP_NEW] = { .apply = app_new_apply, .replaces_tree = true },
	[DOC_OP_LIFT] = { .apply = app_lift_apply, .edits_in_place = true, .replaces_tree = true,
			  .grows_in = true },
	[DOC_OP_CLONE_ADD] = { .apply = app_clone_add_apply },
	[DOC_OP_CLONE_REMOVE] = { .apply = app_clone_remove_apply },
	/* moves leaves, not branches */
	[DOC_OP_ARRANGE] = { .apply = app_arrange_apply, .keeps_wood = true, .edits_in_place = true },
	[DOC_OP_PROPAGATE] = { .apply = app_propagate_apply },
	/* a generated tree replaces every leaf */
	[DOC_OP_GENERATE] = { .apply = app_generate_apply, .replaces_tree = true,
			      .new_leaves = true, .grows_in = true },
	[DOC_OP_SEASON] = { .apply = app_season_apply, .keeps_wood = true, .setting_only = true },
	[DOC_OP_LEAFTYPE] = { .apply = app_leaftype_apply, .keeps_wood = true,
			      .setting_only = true },
	[DOC_OP_VINE] = { .apply = app_vine_apply, .keeps_wood = true },
	[DOC_OP_GROW] = { .apply = app_wood_apply, .keeps_wood = true, .edits_in_place = true,
			  .replaces_tree = true, .swells = true },
	[DOC_OP_IMPORT] = { .apply = app_import_apply, .replaces_tree = true },
};

/* A kind no row knows (none is read from a drawing): applied as nothing, a change. */
static const struct app_op_kind unknown = { 0 };

const struct app_op_kind *app_op_kind(enum doc_op_kind kind)
{
	return (size_t)kind < sizeof(kinds) / sizeof(*kinds) ? &kinds[kind] : &unknown;
}

/* In the order they run after an op. */
static const struct app_op_hook *const hooks[] = {
	&app_unfold_hook,
	&app_wood_hook,
	&app_vine_hook,
	&app_live_hook,
};

size_t app_op_hooks(const struct app_op_hook *const **out)
{
	*out = hooks;
	return sizeof(hooks) / sizeof(*hooks);
}

int app_op_hooks_after(struct app *app, const struct doc_op *op,
		       const struct app_op_before *before, int meshed)
{
	int ret = meshed;

	/* every hook runs; the first failure is the answer */
	for (size_t i = 0; i < sizeof(hooks) / sizeof(*hooks); i++) {
		int r = hooks[i]->after_op(app, op, before, meshed);

		ret = ret < 0 ? ret : r;
	}
	return ret;
}

void app_op_hooks_clear(struct app *app)
{
	for (size_t i = 0; i < sizeof(hooks) / sizeof(*hooks); i++)
		hooks[i]->clear(app);
}
