/* SPDX-License-Identifier: MIT */
/* The New strip: after New, the side strip offers trees to start from, a blank canvas and
 * the presets (presets/\*.yaml) as rendered thumbnails; a tap puts one on the canvas as a
 * 3D tree (app_generate.c). Drawing on the canvas instead closes it. The templates are
 * app_templates[] below, the only list of them. */
#include <errno.h>
#include <math.h>

#include "app_mode.h"
#include "app_private.h"
#include "gen.h"
#include "sketch.h"

const struct app_template app_templates[APP_TEMPLATE_COUNT] = {
	{ BUTTON_TPL_BLANK, "blank", -1, APP_TEMPLATE_SHEET },
	{ BUTTON_TPL_CHERRY, "cherry", GEN_PRESET_CHERRY, APP_TEMPLATE_TREE },
	{ BUTTON_TPL_ZELKOVA, "zelkova", GEN_PRESET_ZELKOVA, APP_TEMPLATE_TREE },
	{ BUTTON_TPL_HEDGE, "hedge", GEN_PRESET_HEDGE, APP_TEMPLATE_TREE },
	{ BUTTON_TPL_BALL, "ball", GEN_PRESET_BALL, APP_TEMPLATE_TREE },
	{ BUTTON_TPL_CONE, "cone", GEN_PRESET_CONE, APP_TEMPLATE_TREE },
	{ BUTTON_TPL_PALM, "palm", GEN_PRESET_PALM, APP_TEMPLATE_TREE },
};

const struct app_template *app_template_of(enum button b)
{
	for (size_t i = 0; i < APP_TEMPLATE_COUNT; i++)
		if (app_templates[i].button == b)
			return &app_templates[i];
	return NULL;
}

/*
 * A thumbnail is about 130 pixels square: the preset with its levels and leaves capped
 * is the same tree to the eye, and takes a fraction of the time to make.
 */
#define PREVIEW_MAX_LEVELS 7
#define PREVIEW_MAX_SHRUB_LEVELS 6 /* a shrub's crown of 3 children a fork is full at 6 */
#define PREVIEW_MAX_LEAVES 3
#define PREVIEW_PRECISION 5
/* leaves a pixel long say nothing: a thumbnail's leaves are drawn larger, so that the crown
 * reads as leafy (or blossoming) at a glance, a shrub's as solid */
#define PREVIEW_LEAF_SCALE 5.0
#define PREVIEW_SHRUB_LEAF_SCALE 1.6

/* The New button's op: the canvas cleared. */
int app_new_apply(struct app *app, const struct doc_op *op)
{
	(void)op;
	tree_clear(&app->tree);
	return SKETCH_CHANGED;
}

static int build_template(struct tree_mesh *tm, enum gen_preset which)
{
	struct gen_params p;
	struct error err;
	struct tree t;
	int ret = gen_preset(which, &p, &err);

	if (ret < 0)
		return ret;
	if (p.levels > (p.type == GEN_SHRUB ? PREVIEW_MAX_SHRUB_LEVELS : PREVIEW_MAX_LEVELS))
		p.levels = p.type == GEN_SHRUB ? PREVIEW_MAX_SHRUB_LEVELS : PREVIEW_MAX_LEVELS;
	if (p.type != GEN_PALM && p.leaf_amount > PREVIEW_MAX_LEAVES)
		p.leaf_amount = PREVIEW_MAX_LEAVES;
	if (p.type != GEN_PALM)
		p.leaf_size = fmin(5.0, p.leaf_size * (p.type == GEN_SHRUB ? PREVIEW_SHRUB_LEAF_SCALE
									    : PREVIEW_LEAF_SCALE));
	p.precision = PREVIEW_PRECISION;
	tree_init(&t);
	/* the seed a template tap on an empty canvas of seed 1 uses: what the kiosk shows first */
	ret = gen_build(&t, &p, 1);
	if (ret == 0)
		ret = tree_mesh_build(tm, &t);
	tree_finish(&t);
	return ret;
}

int app_templates_build(struct app *app)
{
	if (app->templates_ready)
		return 0;
	for (int i = 0; i < GEN_PRESET_COUNT; i++) {
		int ret = build_template(&app->templates[i], (enum gen_preset)i);

		/* a preset that would not build (its test says it does) shows an empty card */
		if (ret == -ENOMEM)
			return ret;
	}
	app->templates_ready = true;
	app->previews_serial++;
	return 0;
}

static int new_enter(struct app *app, uint64_t time_us)
{
	(void)time_us;
	return app_templates_build(app);
}

/* New: undoable, so a visitor who pressed it by accident gets the tree back; then the side
 * strip offers trees to start from. */
static int new_press(struct app *app, uint64_t time_us)
{
	struct doc_op op = { .kind = DOC_OP_NEW, .time_us = time_us };
	int ret = 0;

	app->selected = -1;
	app_clear_suggestions(app);
	/* a drawing with a tree is done: the kiosk archives it (and plants it in today's
	 * forest) as it stood, whatever comes after; the first waiting is kept */
	if (app->tree.nbranches != 0 && !app->replaced.pending) {
		ret = tree_copy(&app->replaced.tree, &app->tree);
		if (ret < 0)
			return ret;
		app->replaced.cursor = app->doc.cursor;
		app->replaced.pending = true;
	}
	if (app->tree.nbranches != 0 || app->tree.nleaves != 0)
		ret = app_push_op(app, &op);
	if (ret < 0 && ret != -ENOSPC)
		return ret;
	app->mode = APP_MODE_NEW;
	return new_enter(app, time_us);
}

static size_t new_side(const struct app *app, struct app_side_item *out, size_t max)
{
	size_t n = 0;

	for (size_t i = 0; i < APP_TEMPLATE_COUNT && n < max; i++) {
		const struct app_template *tpl = &app_templates[i];
		bool tree = tpl->picture == APP_TEMPLATE_TREE;

		out[n++] = (struct app_side_item){
			.thumbnail = true,
			.button = tpl->button,
			.preview = tree && app->templates_ready ? &app->templates[tpl->preset] : NULL,
			.template = tree,
		};
	}
	return n;
}

/* Drawing instead of choosing: the strip closes, and the stroke is drawn. */
static int new_stroke(struct app *app, double len, bool *taken)
{
	(void)len;
	*taken = false;
	app->mode = APP_MODE_SKETCH;
	return 0;
}

const struct app_mode_ops app_mode_new_ops = {
	.mode = APP_MODE_NEW,
	.button = BUTTON_NEW,
	.press = new_press,
	.enter = new_enter,
	.stroke = new_stroke,
	.side = new_side,
};
