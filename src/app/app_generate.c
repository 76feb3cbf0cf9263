/* SPDX-License-Identifier: MIT */
/*
 * Functional trees on the kiosk (seed 001, docs/functional-trees.md): the New strip's
 * templates, the parameter buttons of a generated tree and the season button. Each is an
 * op of the drawing: a generated tree is stored as its parameters and seed (DOC_OP_GENERATE),
 * never as points, and every button press is one undoable step. The generate and season
 * ops' rows of app_ops.c apply here.
 */
#include <errno.h>
#include <stdlib.h>

#include "app_mode.h"
#include "app_private.h"
#include "gen.h"
#include "sketch.h"

const struct doc_op *app_generated(const struct app *app)
{
	/* a setting (a season, a leaf type) changes no branch: the tree is still as generated */
	for (size_t i = app->doc.cursor; i-- > 0;) {
		const struct doc_op *op = &app->doc.ops[i];

		if (app_op_kind(op->kind)->setting_only)
			continue;
		return op->kind == DOC_OP_GENERATE && op->params ? op : NULL;
	}
	return NULL;
}

/* A new tree's generator seed: the drawing's seed and where in its history the tree is
 * made, mixed (splitmix64), so that every template tap gives its own tree and the same
 * drawing always gives the same ones. */
static uint64_t template_seed(const struct app *app)
{
	uint64_t z = app->doc.seed + 0x9e3779b97f4a7c15ULL * ((uint64_t)app->doc.cursor + 1);

	z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
	z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
	return z ^ (z >> 31);
}

static int push_generate(struct app *app, const struct gen_params *p, uint64_t seed,
			 uint64_t time_us)
{
	struct doc_op op = { .kind = DOC_OP_GENERATE, .time_us = time_us, .seed = seed };
	int ret;

	op.params = malloc(sizeof(*op.params));
	if (!op.params)
		return -ENOMEM;
	*op.params = *p;
	/* a tree made now grows as this edaha grows it (an older drawing's ops keep theirs) */
	op.params->gen_version = GEN_VERSION;
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
	return ret == -ENOSPC ? 0 : ret;
}

int app_generate(struct app *app, const struct gen_params *p, uint64_t time_us)
{
	return push_generate(app, p, template_seed(app), time_us);
}

int app_press_template(struct app *app, const struct app_template *tpl, uint64_t time_us)
{
	struct doc_op op = { .kind = DOC_OP_NEW, .time_us = time_us };
	struct gen_params p;
	struct error err;
	int ret;

	if (tpl->preset < 0) {
		/* the blank canvas: as New, and the visitor draws */
		app->mode = APP_MODE_SKETCH;
		if (app->tree.nbranches == 0 && app->tree.nleaves == 0)
			return 0;
		ret = app_push_op(app, &op);
		return ret == -ENOSPC ? 0 : ret;
	}
	ret = gen_preset((enum gen_preset)tpl->preset, &p, &err);
	return ret < 0 ? ret : app_generate(app, &p, time_us);
}

static bool adjust_of(enum button b, enum gen_adjust *a)
{
	static const enum button order[GEN_ADJUST_COUNT] = {
		[GEN_MORE] = BUTTON_GEN_MORE,       [GEN_FEWER] = BUTTON_GEN_FEWER,
		[GEN_WIDER] = BUTTON_GEN_WIDER,     [GEN_NARROWER] = BUTTON_GEN_NARROWER,
		[GEN_TALLER] = BUTTON_GEN_TALLER,   [GEN_SHORTER] = BUTTON_GEN_SHORTER,
		[GEN_LEAFIER] = BUTTON_GEN_LEAFIER, [GEN_BARER] = BUTTON_GEN_BARER,
	};

	for (int i = 0; i < GEN_ADJUST_COUNT; i++) {
		if (order[i] == b) {
			*a = (enum gen_adjust)i;
			return true;
		}
	}
	return false;
}

bool app_gen_possible(const struct app *app, enum button b)
{
	const struct doc_op *op = app_generated(app);
	struct gen_params q;
	enum gen_adjust a;

	return op && adjust_of(b, &a) && gen_adjust(op->params, a, &q);
}

int app_press_functional(struct app *app, enum button b, uint64_t time_us)
{
	const struct doc_op *op;
	struct gen_params q;
	enum gen_adjust a;

	if (b == BUTTON_SEASON) {
		/* every tree has a season, drawn or generated; an empty canvas has none to show */
		if (app->tree.nbranches == 0)
			return 0;
		return app_push_edit(app, DOC_OP_SEASON, 0, (int)season_next(app->tree.season), time_us);
	}
	/* the parameter buttons act on a generated tree nobody has edited by hand */
	op = app_generated(app);
	if (!op || !adjust_of(b, &a) || !gen_adjust(op->params, a, &q))
		return 0;
	q.season = app->tree.season; /* the visitor's season, not the file's */
	return push_generate(app, &q, op->seed, time_us);
}

int app_generate_apply(struct app *app, const struct doc_op *op)
{
	/* a drawing's parameters were checked when read: nothing else is refused */
	int ret = op->params ? gen_build(&app->tree, op->params, op->seed) : -EINVAL;

	return ret == -EINVAL ? SKETCH_CHANGED : ret < 0 ? ret : SKETCH_CHANGED;
}

int app_season_apply(struct app *app, const struct doc_op *op)
{
	/* the leaves' colours: no element changes */
	if ((unsigned)op->pattern < SEASON_COUNT)
		app->tree.season = (enum season)op->pattern;
	return SKETCH_GREW;
}
