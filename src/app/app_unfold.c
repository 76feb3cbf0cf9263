/* SPDX-License-Identifier: MIT */
/*
 * New origami leaves unfold from the bud (seed 003, docs/origami-leaves.md): the leaves an
 * edit adds are drawn at keyframes of ori_unfold_frames for APP_UNFOLD_US after it, by the
 * time of the events (a replay draws the same), then at rest as any leaf. The model is at
 * rest all along: exports, the skeleton and undo never see the unfolding. app_unfold_hook
 * notes each op's new leaves.
 */
#include "app_private.h"
#include "ori.h"

void app_unfold_clear(struct app *app)
{
	app->nunfold = 0;
}

static void unfold_note(struct app *app, size_t first, uint64_t time_us)
{
	bool origami = false;

	/* spans of leaves an edit took away (or replaced) are gone */
	while (app->nunfold && app->unfold[app->nunfold - 1].first >= first)
		app->nunfold--;
	for (size_t i = first; i < app->tree.nleaves && !origami; i++)
		origami = app->tree.leaves[i].kind >= 0;
	if (!origami)
		return;
	/* the oldest has long settled, or soon will: its leaves are at rest from now on */
	if (app->nunfold == APP_UNFOLD_MAX) {
		for (size_t i = 1; i < APP_UNFOLD_MAX; i++)
			app->unfold[i - 1] = app->unfold[i];
		app->nunfold--;
	}
	app->unfold[app->nunfold++] = (struct app_unfold){ .first = first, .start_us = time_us };
}

/* The leaves an op added unfold; one that replaced every leaf (a generated tree), all. */
static int unfold_after_op(struct app *app, const struct doc_op *op,
			   const struct app_op_before *before, int meshed)
{
	size_t nl = before->nleaves;

	(void)meshed;
	unfold_note(app, app_op_kind(op->kind)->new_leaves || app->tree.nleaves < nl ? 0 : nl,
		    op->time_us);
	return 0;
}

const struct app_op_hook app_unfold_hook = {
	.name = "unfold",
	.after_op = unfold_after_op,
	.clear = app_unfold_clear,
};

size_t app_unfold_at(const struct app *app, uint64_t now_us, struct app_unfold_span *out,
		     size_t max)
{
	size_t n = 0;

	if (now_us == UINT64_MAX)
		return 0;
	for (size_t i = 0; i < app->nunfold && n < max; i++) {
		const struct app_unfold *u = &app->unfold[i];
		size_t end = i + 1 < app->nunfold ? app->unfold[i + 1].first : app->tree.nleaves;
		uint64_t age = now_us > u->start_us ? now_us - u->start_us : 0;

		end = end < app->tree.nleaves ? end : app->tree.nleaves;
		if (age >= APP_UNFOLD_US || u->first >= end)
			continue;
		out[n++] = (struct app_unfold_span){
			.first = u->first, .end = end,
			.frame = (unsigned)(age * ORI_UNFOLD_FRAMES / APP_UNFOLD_US)
		};
	}
	return n;
}
