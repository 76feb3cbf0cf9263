/* SPDX-License-Identifier: MIT */
/* The clone mode (seed 000, 3.4): a tap picks a branch and tapping it again adds a child;
 * a circle drawn clockwise round it adds one, anticlockwise takes one away. */
#include <errno.h>
#include <math.h>

#include "app_mode.h"
#include "app_private.h"
#include "clone.h"
#include "sketch.h"

/* An edit whose branch is not there (a hand-edited file) does nothing. */
int app_clone_add_apply(struct app *app, const struct doc_op *op)
{
	int ret = clone_add(&app->tree, op->branch, &app->rng);

	return ret == -ENOENT || ret == -ENOSPC ? SKETCH_GREW : ret < 0 ? ret : SKETCH_GREW;
}

int app_clone_remove_apply(struct app *app, const struct doc_op *op)
{
	int ret = clone_remove(&app->tree, op->branch);

	return ret == -ENOENT ? SKETCH_GREW : ret < 0 ? ret : SKETCH_CHANGED;
}

/*
 * How far the pen went round the stroke's centre: +1 clockwise as the visitor sees it
 * (add a child), -1 anticlockwise (remove one), 0 not a circle.
 */
static int stroke_circle(const struct app *app, double len, struct vec3 *centre)
{
	const struct app_stroke *s = &app->stroke;
	struct vec3 c = vec3(0, 0, 0);
	double turn = 0.0, prev = 0.0;

	if (s->npoints < 8 || len < APP_CIRCLE_MIN_M)
		return 0;
	for (size_t i = 0; i < s->npoints; i++)
		c = vec3_add(c, app_stroke_point(app, i));
	c = vec3_scale(c, 1.0 / (double)s->npoints);
	for (size_t i = 0; i < s->npoints; i++) {
		struct vec3 p = app_stroke_point(app, i);
		double a = atan2(p.y - c.y, p.x - c.x), d;

		if (i > 0) {
			d = a - prev;
			d = d > VEC_PI ? d - 2 * VEC_PI : d < -VEC_PI ? d + 2 * VEC_PI : d;
			turn += d;
		}
		prev = a;
	}
	*centre = c;
	/* view space has y up: a positive turn is anticlockwise */
	return fabs(turn) < APP_CIRCLE_TURN ? 0 : turn < 0 ? 1 : -1;
}

static int clone_stroke(struct app *app, double len, bool *taken)
{
	const struct app_stroke *s = &app->stroke;
	uint64_t t = s->points[0].time_us;
	struct vec3 c;
	int b, dir;

	if (!app->tree.lifted)
		return 0;
	if (s->npoints < 2 || len < SKETCH_MIN_LENGTH_M) {
		*taken = true;
		b = app_branch_near(app, app_stroke_point(app, 0), APP_TAP_M);
		/* a tap picks a parent; tapping it again adds a child */
		if (b < 0 || b != app->selected) {
			app->selected = b;
			return 0;
		}
		return app_has_child_branch(&app->tree, b) ?
			       app_push_edit(app, DOC_OP_CLONE_ADD, b, 0, t) : 0;
	}
	dir = stroke_circle(app, len, &c);
	if (dir == 0)
		return 0;
	*taken = true;
	b = app->selected >= 0 ? app->selected : app_branch_near(app, c, 1.0);
	if (b < 0 || !app_has_child_branch(&app->tree, b))
		return 0;
	app->selected = b;
	return app_push_edit(app, dir > 0 ? DOC_OP_CLONE_ADD : DOC_OP_CLONE_REMOVE, b, 0, t);
}

const struct app_mode_ops app_mode_clone_ops = {
	.mode = APP_MODE_CLONE,
	.button = BUTTON_CLONE,
	.lit = true,
	.stroke = clone_stroke,
};
