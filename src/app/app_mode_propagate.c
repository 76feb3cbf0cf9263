/* SPDX-License-Identifier: MIT */
/* The propagate mode (seed 000, 3.6): a tap on a branch copies its children onto every
 * other branch; the side strip's two buttons pick the pattern. */
#include <errno.h>

#include "app_mode.h"
#include "app_private.h"
#include "propagate.h"
#include "sketch.h"

/* A propagation from a branch that is not there (a hand-edited file) does nothing. */
int app_propagate_apply(struct app *app, const struct doc_op *op)
{
	int ret = propagate_apply(&app->tree, op->branch, (enum propagate_pattern)op->pattern);

	return ret == -ENOENT || ret == -ENOSPC ? SKETCH_GREW : ret < 0 ? ret : SKETCH_GREW;
}

static enum propagate_pattern pattern_for(const struct app *app, int b)
{
	if (app->pattern == APP_PATTERN_FIXED_COUNT)
		return PROPAGATE_FIXED_COUNT;
	if (app->pattern == APP_PATTERN_FIXED_SIZE)
		return PROPAGATE_FIXED_SIZE;
	return app_has_child_branch(&app->tree, b) ? PROPAGATE_FIXED_COUNT : PROPAGATE_FIXED_SIZE;
}

static int propagate_stroke(struct app *app, double len, bool *taken)
{
	const struct app_stroke *s = &app->stroke;
	int b;

	if (!app->tree.lifted || !(s->npoints < 2 || len < SKETCH_MIN_LENGTH_M))
		return 0;
	*taken = true;
	b = app_branch_near(app, app_stroke_point(app, 0), APP_TAP_M);
	if (b < 0 || !(app_has_child_branch(&app->tree, b) || app_has_leaf(&app->tree, b)))
		return 0;
	return app_push_edit(app, DOC_OP_PROPAGATE, b, (int)pattern_for(app, b), s->points[0].time_us);
}

static size_t propagate_side(const struct app *app, struct app_side_item *out, size_t max)
{
	static const enum button patterns[] = { BUTTON_FIXED_COUNT, BUTTON_FIXED_SIZE };
	size_t n = 0;

	for (size_t i = 0; i < 2 && n < max; i++)
		out[n++] = (struct app_side_item){
			.button = patterns[i],
			.lit = app->pattern == (i == 0 ? APP_PATTERN_FIXED_COUNT : APP_PATTERN_FIXED_SIZE),
		};
	return n;
}

const struct app_mode_ops app_mode_propagate_ops = {
	.mode = APP_MODE_PROPAGATE,
	.button = BUTTON_PROPAGATE,
	.lit = true,
	.stroke = propagate_stroke,
	.side = propagate_side,
};
