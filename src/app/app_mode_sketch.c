/* SPDX-License-Identifier: MIT */
/* Sketching: every stroke is drawn. On a generated tree nobody has edited by hand yet, the
 * side strip holds the parameter buttons in pairs (docs/functional-trees.md); the first
 * hand edit puts them away, and undoing it brings them back. The stroke and lift ops'
 * rows of app_ops.c apply here. */
#include "app_mode.h"
#include "app_private.h"
#include "lift.h"
#include "sketch.h"
#include "tree_index.h"

int app_stroke_apply(struct app *app, const struct doc_op *op)
{
	return doc_apply_stroke(&app->tree, op);
}

int app_lift_apply(struct app *app, const struct doc_op *op)
{
	int ret = lift_tree(&app->tree, &app->rng, true);

	(void)op;
	tree_index_keep(&app->tree); /* the lifted tree is a new one */
	return ret < 0 ? ret : SKETCH_CHANGED;
}

static size_t sketch_side(const struct app *app, struct app_side_item *out, size_t max)
{
	static const enum button pairs[] = {
		BUTTON_GEN_MORE,   BUTTON_GEN_FEWER,   BUTTON_GEN_WIDER,   BUTTON_GEN_NARROWER,
		BUTTON_GEN_TALLER, BUTTON_GEN_SHORTER, BUTTON_GEN_LEAFIER, BUTTON_GEN_BARER,
	};
	size_t n = 0;

	if (!app_generated(app))
		return 0;
	for (size_t i = 0; i < sizeof(pairs) / sizeof(*pairs) && n < max; i++)
		out[n++] = (struct app_side_item){ .button = pairs[i] };
	return n;
}

const struct app_mode_ops app_mode_sketch_ops = {
	.mode = APP_MODE_SKETCH,
	.button = BUTTON_COUNT,
	.side = sketch_side,
};
