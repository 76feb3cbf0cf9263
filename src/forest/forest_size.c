/* SPDX-License-Identifier: MIT */
/*
 * A tree's height and crown width in the forest (docs/forest.md): what the layout spaces
 * the trees by and what each tree's share of the forest's triangles follows.
 */
#include <math.h>

#include "forest.h"

/* The trunk's foot: the first finite point of the first branch without a parent. */
static bool tree_foot(const struct tree *t, struct vec3 *foot)
{
	for (size_t i = 0; i < t->nbranches; i++) {
		const struct branch *b = &t->branches[i];

		if (b->parent >= 0)
			continue;
		for (size_t k = 0; k < b->npoints; k++) {
			struct vec3 p = b->points[k];

			if (isfinite(p.x) && isfinite(p.y) && isfinite(p.z)) {
				*foot = p;
				return true;
			}
		}
	}
	return false;
}

static double point_radius(const struct branch *b, size_t k)
{
	double r = b->radii ? b->radii[k] : 0.0;

	return isfinite(r) && r > 0.0 ? r : 0.0;
}

static bool finite3(struct vec3 p)
{
	return isfinite(p.x) && isfinite(p.y) && isfinite(p.z);
}

/* The largest finite f(point - foot, radius) over every branch point and leaf point
 * (radius 0), or 0. */
static double tree_reach(const struct tree *t, struct vec3 foot,
			 double (*f)(struct vec3 d, double r))
{
	double best = 0.0;

	for (size_t i = 0; i < t->nbranches; i++) {
		const struct branch *b = &t->branches[i];

		for (size_t k = 0; k < b->npoints; k++) {
			double v;

			if (!finite3(b->points[k]))
				continue;
			v = f(vec3_sub(b->points[k], foot), point_radius(b, k));
			if (v > best && isfinite(v))
				best = v;
		}
	}
	for (size_t i = 0; i < t->nleaves; i++) {
		const struct leaf *l = &t->leaves[i];

		for (size_t k = 0; k < l->npoints; k++) {
			double v;

			if (!finite3(l->points[k]))
				continue;
			v = f(vec3_sub(l->points[k], foot), 0.0);
			if (v > best && isfinite(v))
				best = v;
		}
	}
	return best;
}

static double above(struct vec3 d, double r)
{
	return d.y + r;
}

static double aside(struct vec3 d, double r)
{
	return hypot(d.x, d.z) + r;
}

double forest_tree_height(const struct tree *t)
{
	struct vec3 foot;

	return tree_foot(t, &foot) ? tree_reach(t, foot, above) : 0.0;
}

double forest_tree_crown_width(const struct tree *t)
{
	struct vec3 foot;

	return tree_foot(t, &foot) ? 2.0 * tree_reach(t, foot, aside) : 0.0;
}
