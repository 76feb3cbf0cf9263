/* SPDX-License-Identifier: MIT */
/*
 * The living tree on the visitor's screen (issue 26, docs/living-trees.md): the wind's
 * strength, and a tree growing in from the trunk's foot when it becomes 3D (the 3D press,
 * a template from New: the kinds whose row in app_ops.c says grows_in; a loaded 3D
 * drawing). The app keeps the skeleton of its tree (live.h) in step with the meshes while
 * anything lives, and says for a moment of the events' clock what the renderer's shaders
 * need (app_live_at): a handful of numbers, whatever the tree's size. The model is the
 * settled tree all along: exports, the skeleton and undo never see the growth. Any pen
 * tip or button put down finishes a growth at once (app_live_input): nobody waits to draw.
 */
#include <errno.h>
#include <math.h>
#include <stdint.h>

#include "app_private.h"

void app_live_init(struct app *app)
{
	app->live.grow_in = true;
	app->live.vine_op = SIZE_MAX;
}

void app_live_finish(struct app *app)
{
	live_skeleton_finish(&app->live.sk);
	app->live.sk_valid = false;
}

static bool living(const struct app *app)
{
	return app->live.strength > 0.0 || app->live.growing;
}

int app_live_sync(struct app *app)
{
	struct app_live *l = &app->live;
	struct live_wind_params p = { .strength = l->strength, .angle = APP_WIND_ANGLE };
	int ret;

	if (!living(app) || (l->sk_valid && l->sk_of == app->mesh_serial))
		return 0;
	live_skeleton_finish(&l->sk);
	l->sk_valid = false;
	ret = live_skeleton_init(&l->sk, &app->tree, app->doc.seed);
	if (ret == 0)
		ret = live_wind_setup(&l->wind, &l->sk, &p);
	if (ret < 0) {
		/* nothing moves until it can: the tree stands still, as before wind */
		live_skeleton_finish(&l->sk);
		l->growing = false;
		return ret;
	}
	l->sk_valid = true;
	l->sk_of = app->mesh_serial;
	return 0;
}

int app_set_wind(struct app *app, double strength)
{
	if (!(strength >= 0.0 && strength <= 1.0))
		return -EINVAL;
	app->live.strength = strength;
	app->live.sk_valid = false; /* the wind's amplitudes are made with the skeleton */
	return app_live_sync(app);
}

void app_set_grow_in(struct app *app, bool on)
{
	app->live.grow_in = on;
	if (!on)
		app->live.growing = false;
}

/* The tree as it is now grows in from time_us (meshed: the skeleton is made from it). */
int app_live_grow_start(struct app *app, uint64_t time_us)
{
	struct app_live *l = &app->live;
	int ret;

	l->growing = false;
	if (!l->grow_in || app->tree.nbranches == 0 || !app->tree.lifted)
		return app_live_sync(app); /* the wind's skeleton, of the tree as it is */
	l->growing = true;
	l->sk_valid = false;
	ret = app_live_sync(app);
	if (ret < 0)
		return ret;
	live_grow_setup(&l->grow, &l->sk);
	l->grow_start_us = time_us;
	l->grow_us = (uint64_t)llround(l->grow.duration * 1e6);
	return 0;
}

void app_live_input(struct app *app, const struct event *ev)
{
	bool down = ev->type == EVENT_TIP_DOWN || (ev->type == EVENT_BUTTON && ev->pressed);

	if (!down || !app->live.growing)
		return;
	app->live.growing = false;
	/* the vine that was to climb after it shows grown */
	app->live.vine_op = SIZE_MAX;
}

uint64_t app_live_grow_end(const struct app *app)
{
	const struct app_live *l = &app->live;

	if (!l->growing || l->grow_start_us > UINT64_MAX - l->grow_us)
		return 0;
	return l->grow_start_us + l->grow_us;
}

/* A loaded 3D drawing grows in from the time of the last event; its last vine climbs
 * after (app_live_vines; the others show grown then). */
int app_live_loaded(struct app *app)
{
	struct app_live *l = &app->live;
	int ret = app_live_grow_start(app, app->last_time_us);

	l->vine_op = SIZE_MAX;
	if (ret < 0 || !l->growing || app->tree.nvines == 0)
		return ret;
	for (size_t k = app->doc.cursor; k-- > 0 && l->vine_op == SIZE_MAX;)
		if (app->doc.ops[k].kind == DOC_OP_VINE && app->doc.ops[k].vine)
			l->vine_op = k;
	return 0;
}

int app_live_vines(struct app *app, uint64_t now_us)
{
	struct app_live *l = &app->live;
	size_t k = l->vine_op;
	int ret;

	if (k == SIZE_MAX || (now_us != UINT64_MAX && now_us < app_live_grow_end(app)))
		return 0;
	l->vine_op = SIZE_MAX;
	/* the settled view, or the growth finished: the vine shows grown */
	if (now_us == UINT64_MAX || !l->growing || k >= app->doc.cursor)
		return 0;
	ret = app_vine_growth_start(app, &app->doc.ops[k]);
	if (ret == 0 && app->growth.on)
		app->growth.start_us = app_live_grow_end(app);
	return ret;
}

/* A tree that becomes 3D by an op grows in from its time; any other op on a growing tree
 * (none comes without an input, which finished it) keeps the growth as it is. */
static int live_after_op(struct app *app, const struct doc_op *op,
			 const struct app_op_before *before, int meshed)
{
	(void)before;
	if (meshed < 0)
		return 0;
	if (app_op_kind(op->kind)->grows_in)
		return app_live_grow_start(app, op->time_us);
	return app_live_sync(app);
}

/* Undo, redo, a load: no growth goes on (a loaded 3D drawing starts its own after). */
static void live_clear(struct app *app)
{
	app->live.growing = false;
	app->live.vine_op = SIZE_MAX;
}

const struct app_op_hook app_live_hook = {
	.name = "live",
	.after_op = live_after_op,
	.clear = live_clear,
};

const struct live_skeleton *app_live_skeleton(const struct app *app)
{
	const struct app_live *l = &app->live;

	return l->sk_valid && l->sk_of == app->mesh_serial ? &l->sk : NULL;
}

bool app_live_growing_at(const struct app *app, uint64_t now_us)
{
	return app->live.growing && now_us != UINT64_MAX && now_us < app_live_grow_end(app) &&
	       app_live_skeleton(app) != NULL;
}

bool app_live_at(const struct app *app, uint64_t now_us, struct app_live_frame *out)
{
	const struct app_live *l = &app->live;
	/* an empty canvas has nothing to sway: the kiosk then draws only on change */
	bool wind = l->strength > 0.0 && now_us != UINT64_MAX && app->tree.nbranches > 0 &&
		    app_live_skeleton(app);
	bool growing = app_live_growing_at(app, now_us);

	/* today's forest on the attract screen moves by itself too, whatever the drawing: its
	 * camera travels round, its trees sway, its newest grows in (render_forest.c) */
	if (!out)
		return wind || growing || app_forest_at(app, now_us);
	*out = (struct app_live_frame){ .moving = wind || growing, .growing = growing };
	if (!out->moving)
		return false;
	if (growing) {
		uint64_t age = now_us > l->grow_start_us ? now_us - l->grow_start_us : 0;

		out->front = live_grow_front(&l->grow, (double)age * 1e-6);
		out->swell = l->grow.swell;
	} else {
		/* far past every vertex (a float d may round a little past d_max): drawn
		 * whole, pulled nowhere */
		out->front = l->sk.d_max + 2.0;
		out->swell = 1.0;
	}
	if (wind) {
		double t = (double)now_us * 1e-6;

		live_wind_frame(&l->wind, t, live_wind_angle(&l->wind, t), &out->wind);
	} else {
		/* still: every amplitude 0, so the shader adds exactly nothing */
		struct live_wind still = l->wind;

		still.amp0 = still.amp_leaf = 0.0;
		for (int k = 0; k < LIVE_BANDS; k++)
			still.amp[k] = 0.0;
		live_wind_frame(&still, 0.0, 0.0, &out->wind);
	}
	return true;
}
