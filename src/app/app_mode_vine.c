/* SPDX-License-Identifier: MIT */
/*
 * The vine mode (issue 16, seed 004; docs/vines.md): a tap at the foot of the tree plants
 * a twining vine there, scaled to the tree; it grows on screen, circling until it touches
 * the bark and then winding up it. A tap beyond the free rod's reach plants at the nearest
 * point of the foot within reach; a tap far from the tree says where to tap. Strokes draw
 * as in sketching.
 */
#include <errno.h>
#include <math.h>
#include <stdlib.h>

#include "app_mode.h"
#include "app_private.h"
#include "camera.h"
#include "sketch.h"
#include "sketch_seen.h"
#include "vine.h"
#include "vine_presets.h"
#include "vine_support.h"

/*
 * The scale on every length of the preset: the stem a tenth of the trunk's radius at the
 * foot (so that it reads beside the trunk and winds close round it), within bounds that
 * keep it visible on a thin generated trunk; each length at most a vine file's limit.
 */
#define VINE_STEM_PER_TRUNK 0.1
#define VINE_SCALE_MIN 6.0
#define VINE_SCALE_MAX 16.0
/* Below this height of the camera (degrees) the ground is seen edge-on: a tap is taken
 * as the point of its line of sight nearest the trunk, dropped to the ground. */
#define VINE_GROUND_PITCH_DEG 10.0
/* A tap farther than this from every trunk's foot (or the crown's reach, if more) is not
 * at the foot of the tree: the kiosk says where to tap. Metres, a quarter screen. */
#define VINE_FAR_M 2.5
/* Halvings of the way from the trunk to a tap out of reach: to a 256th of it. */
#define VINE_REACH_STEPS 8

static double horizontal_dist(struct vec3 a, struct vec3 b)
{
	return hypot(a.x - b.x, a.z - b.z);
}

/* The trunk (a branch rooted on the ground) whose foot is nearest p horizontally, or -1. */
static int nearest_trunk(const struct tree *t, struct vec3 p)
{
	double best = INFINITY;
	int at = -1;

	for (size_t i = 0; i < t->nbranches; i++) {
		const struct branch *b = &t->branches[i];
		double d;

		if (b->parent >= 0 || b->npoints < 2)
			continue;
		d = horizontal_dist(b->points[0], p);
		if (d < best) {
			best = d;
			at = (int)i;
		}
	}
	return at;
}

/* How far the tree reaches sideways from trunk b's foot. */
static double crown_reach(const struct tree *t, const struct branch *trunk)
{
	double r = 0.0;

	for (size_t i = 0; i < t->nbranches; i++)
		for (size_t k = 0; k < t->branches[i].npoints; k++) {
			double d = horizontal_dist(t->branches[i].points[k], trunk->points[0]);

			r = d > r ? d : r;
		}
	return r;
}

/* The kiosk's vine scaled to trunk b: every length by one factor. */
static int scaled_params(const struct tree *t, const struct branch *trunk, uint64_t seed,
			 struct vine_params *p)
{
	struct error err = { { 0 } };
	double k;

	if (vine_preset(APP_VINE_PRESET, p, &err) < 0)
		return -EINVAL; /* compiled in and tested */
	k = VINE_STEM_PER_TRUNK * trunk->radii[0] / p->radius;
	k = k < VINE_SCALE_MIN ? VINE_SCALE_MIN : k > VINE_SCALE_MAX ? VINE_SCALE_MAX : k;
	p->internode = fmin(p->internode * k, VINE_INTERNODE_MAX);
	p->radius = fmin(p->radius * k, VINE_RADIUS_MAX);
	p->leaf_size = fmin(p->leaf_size * k, VINE_LEAF_SIZE_MAX);
	p->seed = seed + t->nvines;
	return vine_params_check(p, NULL, &err) < 0 ? -EINVAL : 0;
}

/* Where the line of sight through view-space point p meets the ground (y of the trunk's
 * foot), or, seen edge-on, its point nearest the foot dropped to the ground. */
static struct vec3 tap_on_ground(const struct app *app, struct vec3 p, struct vec3 foot)
{
	struct camera_xf xf;
	struct vec3 o, d, h;
	double s;

	camera_xf_init(&xf, app->camera, sketch_seen_pivot(&app->tree));
	o = camera_from_view(&xf, p);
	d = xf.back;
	if (fabs(d.y) > sin(VINE_GROUND_PITCH_DEG * VEC_PI / 180.0)) {
		s = (foot.y - o.y) / d.y;
	} else {
		h = vec3(d.x, 0.0, d.z);
		s = vec3_dot(h, h) > 0.0 ? vec3_dot(vec3_sub(foot, o), h) / vec3_dot(h, h) : 0.0;
	}
	o = vec3_add(o, vec3_scale(d, s));
	o.y = foot.y;
	return o;
}

/* Whether a vine planted at p touches the bark before its first apex stops. */
static int reaches(const struct vine_support *s, const struct vine_params *p, struct vec3 at,
		   bool *touched)
{
	struct vine v;
	/* the free part, then the rod's two internodes, then the two it may circle untouched */
	double points = (double)(p->free_nodes + 4) * p->points_per_internode;
	int ret;

	vine_init(&v, p, at);
	ret = vine_grow(&v, s, points * p->step_time);
	*touched = false;
	for (size_t i = 0; ret == 0 && i < v.nshoots && !*touched; i++)
		for (size_t k = 0; k < v.shoots[i].n && !*touched; k++)
			*touched = v.shoots[i].contact[k] != 0;
	vine_finish(&v);
	return ret;
}

int app_vine_plan(const struct app *app, struct vec3 p, uint64_t time_us, struct doc_op *op,
		  struct vine_support **bark)
{
	const struct tree *t = &app->tree;
	struct vine_support *s = NULL;
	struct vine_params vp;
	const struct branch *trunk;
	struct vec3 foot, at, dir;
	double far, clear;
	bool touched = false;
	int b, ret;

	b = nearest_trunk(t, sketch_seen_pivot(t));
	if (b < 0)
		return 0;
	at = tap_on_ground(app, p, t->branches[b].points[0]);
	b = nearest_trunk(t, at);
	trunk = &t->branches[b];
	foot = trunk->points[0];
	far = crown_reach(t, trunk);
	far = far > VINE_FAR_M ? far : VINE_FAR_M;
	if (horizontal_dist(at, foot) > far)
		return 0;
	if (scaled_params(t, trunk, app->doc.seed, &vp) < 0)
		return 0;
	/* never inside the trunk: a stem's width clear of its bark */
	dir = vec3_norm_or(vec3(at.x - foot.x, 0.0, at.z - foot.z), vec3(0.0, 0.0, 1.0));
	clear = trunk->radii[0] + 2.0 * vp.radius;
	if (horizontal_dist(at, foot) < clear)
		at = vec3_add(foot, vec3_scale(dir, clear));
	ret = app_vine_support(t, &s);
	if (ret == 0)
		ret = reaches(s, &vp, at, &touched);
	if (ret == 0 && !touched) {
		/* The farthest point towards the tap that the apex finds the bark from (the rod
		 * walks as it circles, so that is found by growing): the nearest within reach. */
		double lo = clear, hi = horizontal_dist(at, foot);

		for (int i = 0; i < VINE_REACH_STEPS && ret == 0; i++) {
			double mid = 0.5 * (lo + hi);

			ret = reaches(s, &vp, vec3_add(foot, vec3_scale(dir, mid)), &touched);
			if (touched)
				lo = mid;
			else
				hi = mid;
		}
		at = vec3_add(foot, vec3_scale(dir, lo));
	}
	if (ret == -ENOMEM || !bark)
		vine_support_destroy(s);
	else
		*bark = s;
	if (ret == -ENOMEM)
		return ret;
	op->kind = DOC_OP_VINE;
	op->time_us = time_us;
	op->plant[0] = at.x;
	op->plant[1] = at.y;
	op->plant[2] = at.z;
	op->vine = malloc(sizeof(*op->vine));
	if (!op->vine)
		return -ENOMEM;
	*op->vine = vp;
	return 1;
}

/* Each time the mode is entered, the hint: where to tap. */
static int vine_enter(struct app *app, uint64_t time_us)
{
	app_set_status(app, APP_STATUS_VINE_TAP, time_us);
	return 0;
}

static int vine_stroke(struct app *app, double len, bool *taken)
{
	const struct app_stroke *s = &app->stroke;
	uint64_t t = s->points[0].time_us;
	struct doc_op op = { 0 };
	int ret;

	if (!app->tree.lifted || (s->npoints >= 2 && len >= SKETCH_MIN_LENGTH_M))
		return 0; /* a stroke draws */
	*taken = true;
	if (app->tree.nvines >= TREE_MAX_VINES) {
		app_set_status(app, APP_STATUS_VINE_FULL, t);
		return 0;
	}
	ret = app_vine_plan(app, app_stroke_point(app, 0), t, &op, &app->bark_index);
	if (ret == 0)
		app_set_status(app, APP_STATUS_VINE_WHERE, t);
	if (ret <= 0)
		return ret;
	ret = app_push_op(app, &op);
	doc_op_finish(&op);
	/* lent for this op only (the growth took it, unless it failed) */
	vine_support_destroy(app->bark_index);
	app->bark_index = NULL;
	app->bark_index_op = NULL;
	if (ret == -ENOSPC) {
		app_set_status(app, APP_STATUS_VINE_FULL, t);
		return 0;
	}
	if (ret == 0)
		app->status = APP_STATUS_NONE; /* the vine answers the tap: no hint over it */
	return ret;
}

const struct app_mode_ops app_mode_vine_ops = {
	.mode = APP_MODE_VINE,
	.button = BUTTON_VINE,
	.lit = true,
	.enter = vine_enter,
	.stroke = vine_stroke,
	.taps_on_canvas = true,
};
