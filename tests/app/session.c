/* SPDX-License-Identifier: MIT */
#include "session.h"

#include <math.h>
#include <stdlib.h>

#include "layout.h"
#include "sketch_seen.h"
#include "wood.h"

/* ---- the reference ---- */

void session_copy_doc(struct doc *d, const struct doc *src)
{
	doc_init(d, src->seed);
	d->ops = calloc(src->nops + 1, sizeof(*d->ops));
	CHECK(d->ops);
	d->cap = src->nops + 1;
	for (size_t i = 0; i < src->nops; i++)
		CHECK_INT(doc_op_copy(&d->ops[i], &src->ops[i]), 0);
	d->nops = src->nops;
	d->cursor = src->cursor;
	d->view = src->view;
}

void session_same_mesh(const struct mesh *a, const struct mesh *b)
{
	CHECK_INT(a->nvertices, b->nvertices);
	CHECK_INT(a->nindices, b->nindices);
	if (a->nvertices) {
		CHECK(memcmp(a->positions, b->positions, a->nvertices * 3 * sizeof(float)) == 0);
		CHECK(memcmp(a->normals, b->normals, a->nvertices * 3 * sizeof(float)) == 0);
	}
	if (a->nindices)
		CHECK(memcmp(a->indices, b->indices, a->nindices * sizeof(uint32_t)) == 0);
}

void session_same_tree(const struct tree *a, const struct tree *b)
{
	CHECK_INT(a->nbranches, b->nbranches);
	CHECK_INT(a->nleaves, b->nleaves);
	CHECK_INT(a->lifted, b->lifted);
	CHECK_INT(a->sides, b->sides);
	CHECK_INT(a->season, b->season);
	CHECK_INT(a->leaf_kind, b->leaf_kind);
	CHECK_INT(a->last_sketched, b->last_sketched);
	CHECK_INT(a->last_sketched_end_us, b->last_sketched_end_us);
	CHECK_INT(a->has_profile, b->has_profile);
	SAME(a->profile, b->profile);
	for (size_t i = 0; i < a->nbranches; i++) {
		const struct branch *x = &a->branches[i], *y = &b->branches[i];

		CHECK_INT(x->id, y->id);
		CHECK_INT(x->parent, y->parent);
		SAME(x->parent_t, y->parent_t);
		CHECK_INT(x->generation, y->generation);
		CHECK_INT(x->level, y->level);
		CHECK_INT(x->origin, y->origin);
		CHECK_INT(x->npoints, y->npoints);
		CHECK(memcmp(x->points, y->points, x->npoints * sizeof(*x->points)) == 0);
		CHECK(memcmp(x->radii, y->radii, x->npoints * sizeof(*x->radii)) == 0);
	}
	for (size_t i = 0; i < a->nleaves; i++) {
		const struct leaf *x = &a->leaves[i], *y = &b->leaves[i];

		CHECK_INT(x->id, y->id);
		CHECK_INT(x->branch, y->branch);
		SAME(x->branch_t, y->branch_t);
		CHECK_INT(x->kind, y->kind);
		CHECK_INT(x->origin, y->origin);
		CHECK_INT(x->npoints, y->npoints);
		CHECK(memcmp(x->points, y->points, x->npoints * sizeof(*x->points)) == 0);
		CHECK((x->local == NULL) == (y->local == NULL));
		CHECK(!x->local || memcmp(x->local, y->local, x->npoints * sizeof(*x->local)) == 0);
	}
	CHECK((a->wood == NULL) == (b->wood == NULL));
	if (a->wood && b->wood) {
		CHECK_INT(a->wood->presses, b->wood->presses);
		CHECK(wood_cells(&a->wood->g) == wood_cells(&b->wood->g));
		CHECK(memcmp(a->wood->g.density, b->wood->g.density,
			     wood_cells(&a->wood->g) * sizeof(double)) == 0);
		CHECK_INT(a->wood->nbranches, b->wood->nbranches);
		CHECK(memcmp(a->wood->voxelised, b->wood->voxelised,
			     a->wood->nbranches * sizeof(*a->wood->voxelised)) == 0);
	}
	CHECK_INT(a->nvines, b->nvines);
	for (size_t i = 0; i < a->nvines && i < b->nvines; i++) {
		const struct vine *x = &a->vines[i], *y = &b->vines[i];

		SAME(x->p, y->p);
		SAME(x->plant, y->plant);
		CHECK_INT(x->nshoots, y->nshoots);
		for (size_t k = 0; k < x->nshoots && k < y->nshoots; k++) {
			CHECK_INT(x->shoots[k].n, y->shoots[k].n);
			CHECK(memcmp(x->shoots[k].axis, y->shoots[k].axis,
				     x->shoots[k].n * sizeof(*x->shoots[k].axis)) == 0);
		}
	}
}

/* ---- a visitor ---- */

static void tip(struct pen *pen, struct app *app, enum event_type type, double x, double y,
		enum event_tool tool)
{
	pen_event(pen, app, type, tool, x, y, 0.6);
}

void session_stroke(struct pen *pen, struct app *app, double x0, double y0, double x1, double y1,
		    int n, enum event_tool tool, uint64_t pause_us)
{
	tip(pen, app, EVENT_TIP_DOWN, x0, y0, tool);
	for (int i = 1; i < n; i++) {
		double t = (double)i / (n - 1);

		tip(pen, app, EVENT_MOTION, x0 + (x1 - x0) * t + 5 * sin(t * 7), y0 + (y1 - y0) * t,
		    tool);
	}
	tip(pen, app, EVENT_TIP_UP, x1, y1, tool);
	pen->now_us += pause_us;
}

void session_loop(struct pen *pen, struct app *app, double cx, double cy, double r, double dir)
{
	tip(pen, app, EVENT_TIP_DOWN, cx + r, cy, EVENT_TOOL_PEN);
	for (int i = 1; i <= 30; i++)
		tip(pen, app, EVENT_MOTION, cx + r * cos(dir * i * 0.23), cy + r * sin(dir * i * 0.23),
		    EVENT_TOOL_PEN);
	tip(pen, app, EVENT_TIP_UP, cx + r * cos(dir * 30 * 0.23), cy + r * sin(dir * 30 * 0.23),
	    EVENT_TOOL_PEN);
	pen->now_us += PEN_PAUSE_US;
}

void session_tap(struct pen *pen, struct app *app, double x, double y)
{
	tip(pen, app, EVENT_TIP_DOWN, x, y, EVENT_TOOL_PEN);
	tip(pen, app, EVENT_TIP_UP, x, y, EVENT_TOOL_PEN);
	pen->now_us += 300000;
}

bool session_pick(const struct app *app, struct rng *r, bool parent, double *x, double *y)
{
	struct camera_xf xf;
	enum button hit;

	if (app->tree.nbranches == 0)
		return false;
	camera_xf_init(&xf, app->camera, sketch_seen_pivot(&app->tree));
	for (int tries = 0; tries < 40; tries++) {
		size_t b = rng_next(r) % app->tree.nbranches;
		const struct branch *br = &app->tree.branches[b];
		bool kids = false;

		for (size_t i = b + 1; i < app->tree.nbranches && parent && !kids; i++)
			kids = app->tree.branches[i].parent == (int)b;
		if ((parent && !kids) || br->npoints == 0)
			continue;
		screen_from_world(&app->screen, camera_to_view(&xf, br->points[rng_next(r) % br->npoints]), x, y);
		if (*x > 60 && *x < app->screen.width - 60 && *y > 60 && *y < app->screen.height - 60 &&
		    !layout_hit(&app->screen, *x, *y, &hit) && !layout_hit_view_button(&app->screen, *x, *y))
			return true;
	}
	return false;
}
