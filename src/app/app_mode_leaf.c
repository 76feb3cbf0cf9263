/* SPDX-License-Identifier: MIT */
/* The leaf mode (seed 000, 3.5): a leaf drawn on a branch suggests arrangements of leaves
 * for it, shown as thumbnails on the side strip; a tap applies one. Its leaf buttons pick
 * the kind of leaf placed next. The arrange and leaf-type ops' rows of app_ops.c apply
 * here. */
#include <errno.h>

#include "app_mode.h"
#include "app_private.h"
#include "ori_kinds.h"
#include "sketch.h"

/* An arrangement on a branch that is not there (a hand-edited file) does nothing. */
int app_arrange_apply(struct app *app, const struct doc_op *op)
{
	int ret = arrange_apply(&app->tree, op->branch, (enum arrange_pattern)op->pattern);

	/* whorl-add moves the leaves already there */
	return ret == -ENOENT ? SKETCH_GREW : ret < 0 ? ret : SKETCH_CHANGED;
}

int app_leaftype_apply(struct app *app, const struct doc_op *op)
{
	/* what arrangement and propagation place next: no element changes */
	if (op->pattern >= -1 && op->pattern < ORI_KIND_COUNT)
		app->tree.leaf_kind = op->pattern;
	return SKETCH_GREW;
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

/* Leaves drawn before: the newest one's branch says what it suggests at once. */
static int leaf_enter(struct app *app, uint64_t time_us)
{
	(void)time_us;
	for (size_t i = app->tree.nleaves; i-- > 0;)
		if (app->tree.leaves[i].origin == ORIGIN_SKETCH)
			return app_update_suggestions(app, app->tree.leaves[i].branch);
	return 0;
}

/*
 * The arrangements suggested, as pictures on cards; then the leaves to place (issue 15):
 * the visitor's drawn one and the origami presets, cards pressing leaf-drawn ..
 * leaf-maple with their icons, the choice in effect lit. The suggestions keep their
 * places (recorded taps land on them as before); the leaves' cards are named when no
 * suggestion shows (a strip's cards are all of one kind: its first's).
 */
static size_t leaf_side(const struct app *app, struct app_side_item *out, size_t max)
{
	enum arrange_pattern list[ARRANGE_COUNT];
	size_t n = app_suggestions(app, list), at = 0;

	for (size_t i = 0; i < n && at < max; i++)
		out[at++] = (struct app_side_item){ .thumbnail = true, .button = BUTTON_COUNT,
						    .tap = (int)list[i],
						    .preview = &app->previews[list[i]] };
	for (int b = BUTTON_LEAF_DRAWN; b <= BUTTON_LEAF_MAPLE && at < max; b++)
		out[at++] = (struct app_side_item){
			.thumbnail = true, .button = (enum button)b, .tap = 0,
			.lit = (int)(b - BUTTON_LEAF_DRAWN) - 1 == app->tree.leaf_kind };
	return at;
}

/* A tap on a suggestion applies it; tapping again keeps adding. */
static int leaf_side_tap(struct app *app, const struct app_side_item *item, uint64_t time_us)
{
	int b = app->suggest_branch;
	int ret = app_push_edit(app, DOC_OP_ARRANGE, b, item->tap, time_us);

	return ret < 0 ? ret : app_update_suggestions(app, b);
}

const struct app_mode_ops app_mode_leaf_ops = {
	.mode = APP_MODE_LEAF,
	.button = BUTTON_LEAF,
	.lit = true,
	.enter = leaf_enter,
	.side = leaf_side,
	.side_tap = leaf_side_tap,
};
