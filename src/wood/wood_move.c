/* SPDX-License-Identifier: MIT */
/*
 * Leaves and vines move out with the growing bark (issue 17; docs/wood.md, "Leaves and
 * vines move out"): after a press, whatever the new wood buried is pushed outwards to just
 * beyond the surface at density 0.5. Pure in the field: reads w, moves t's leaves and
 * vines' raw axes; no allocation.
 */
#include <errno.h>
#include <math.h>

#include "wood.h"

/* Outward marching step and the bisection's iterations: half a voxel brackets the surface,
 * 40 halvings put it within 2^-41 voxel. */
#define MOVE_STEP 0.5
#define MOVE_BISECT 40
/* A moved leaf ends this far (voxels) past the shift that just unburies it. */
#define MOVE_LEAF_MARGIN 0.05
#define MOVE_ISO 0.5

/* Sample (x, y, z) of the field, 0 outside the grid. */
static double sample(const struct wood_grid *g, int x, int y, int z)
{
	if (x < 0 || y < 0 || z < 0 || x >= g->nx || y >= g->ny || z >= g->nz)
		return 0.0;
	return g->density[wood_index(g, x, y, z)];
}

double wood_density_at(const struct wood_grid *g, struct vec3 p)
{
	/* in voxels from the first voxel's centre */
	double u = (p.x - g->origin.x) / g->h - 0.5, v = (p.y - g->origin.y) / g->h - 0.5,
	       w = (p.z - g->origin.z) / g->h - 0.5;
	double fu, fv, fw, c[2][2][2], d = 0.0;
	int x, y, z;

	if (!(u > -2.0 && v > -2.0 && w > -2.0 && u < g->nx + 1.0 && v < g->ny + 1.0 &&
	      w < g->nz + 1.0))
		return 0.0; /* far outside (or NaN): no sample reaches */
	x = (int)floor(u);
	y = (int)floor(v);
	z = (int)floor(w);
	fu = u - x;
	fv = v - y;
	fw = w - z;
	for (int k = 0; k < 2; k++)
		for (int j = 0; j < 2; j++)
			for (int i = 0; i < 2; i++)
				c[k][j][i] = sample(g, x + i, y + j, z + k);
	for (int k = 0; k < 2; k++)
		for (int j = 0; j < 2; j++) {
			double a = c[k][j][0] + fu * (c[k][j][1] - c[k][j][0]);

			d += a * (k ? fw : 1.0 - fw) * (j ? fv : 1.0 - fv);
		}
	return d;
}

static bool buried(const struct wood_grid *g, struct vec3 p)
{
	return wood_density_at(g, p) > MOVE_ISO;
}

/* Points p[0..n) shifted by s along d: is any buried? */
static bool any_buried(const struct wood_grid *g, const struct vec3 *p, size_t n, struct vec3 d,
		       double s)
{
	for (size_t k = 0; k < n; k++)
		if (buried(g, vec3_add(p[k], vec3_scale(d, s))))
			return true;
	return false;
}

/* A shift along d past which p[0..n) are all out of the grid's reach. */
static double far_bound(const struct wood_grid *g, const struct vec3 *p, size_t n)
{
	struct vec3 size = vec3(g->nx * g->h, g->ny * g->h, g->nz * g->h);
	struct vec3 centre = vec3_add(g->origin, vec3_scale(size, 0.5));
	double far = 0.0;

	for (size_t k = 0; k < n; k++) {
		double r = vec3_dist(p[k], centre);

		far = r > far ? r : far;
	}
	return far + vec3_len(size) + 2.0 * g->h;
}

/*
 * The smallest shift s >= 0 along d (unit) that unburies p[0..n): marched out in half
 * voxels to the first clear shift, then bisected back to the surface. 0 if nothing is
 * buried. The field may be clear at s yet buried a little further (a fork's crotch): the
 * caller checks its own final shift.
 */
static double unbury_shift(const struct wood_grid *g, const struct vec3 *p, size_t n,
			   struct vec3 d)
{
	double step = MOVE_STEP * g->h, far = far_bound(g, p, n), lo = 0.0, hi = step;

	if (!any_buried(g, p, n, d, 0.0))
		return 0.0;
	while (hi < far && any_buried(g, p, n, d, hi)) {
		lo = hi;
		hi += step;
	}
	if (hi >= far)
		return far;
	for (int i = 0; i < MOVE_BISECT; i++) {
		double mid = 0.5 * (lo + hi);

		if (any_buried(g, p, n, d, mid))
			lo = mid;
		else
			hi = mid;
	}
	return hi;
}

/* From s on, the first shift (in half voxels) at which p[0..n) are clear. */
static double clear_from(const struct wood_grid *g, const struct vec3 *p, size_t n,
			 struct vec3 d, double s)
{
	double far = far_bound(g, p, n);

	while (s < far && any_buried(g, p, n, d, s))
		s += MOVE_STEP * g->h;
	return s;
}

/* Any unit vector across t (unit), as tree_frame_at picks its normal. */
static struct vec3 across(struct vec3 t)
{
	return vec3_norm_or(vec3_cross(vec3(0, 0, 1), t),
			    vec3_norm_or(vec3_cross(vec3(1, 0, 0), t), vec3(0, 1, 0)));
}

/* The unit direction from the axis point o (tangent t, unit) to p, across the axis. */
static struct vec3 away_from_axis(struct vec3 o, struct vec3 t, struct vec3 p)
{
	struct vec3 v = vec3_sub(p, o);

	v = vec3_sub(v, vec3_scale(t, vec3_dot(v, t)));
	return vec3_norm_or(v, across(t));
}

static bool in_wood(const struct wood *w, const struct tree *t, int b)
{
	return b >= 0 && (size_t)b < w->nbranches && (size_t)b < t->nbranches && w->voxelised[b];
}

/*
 * The unit direction from the nearest voxelised branch's axis (its polyline) to p, across
 * the segment nearest (from its end, radially, past a tip). false if no branch is
 * voxelised. Ties go to the first in branch and point order: deterministic.
 */
static bool away_from_wood(const struct wood *w, const struct tree *t, struct vec3 p,
			   struct vec3 *dir)
{
	double best = INFINITY;

	for (size_t i = 0; i < t->nbranches; i++) {
		const struct branch *b = &t->branches[i];

		if (!in_wood(w, t, (int)i))
			continue;
		for (size_t k = 0; k + 1 < b->npoints; k++) {
			struct vec3 a = b->points[k], e = vec3_sub(b->points[k + 1], a);
			double ee = vec3_dot(e, e), s = 0.0, dd;
			struct vec3 q;

			if (ee > 0.0) {
				s = vec3_dot(vec3_sub(p, a), e) / ee;
				s = s < 0.0 ? 0.0 : s > 1.0 ? 1.0 : s;
			}
			q = vec3_add(a, vec3_scale(e, s));
			dd = vec3_dist(p, q);
			if (dd < best) {
				best = dd;
				*dir = away_from_axis(q, vec3_norm_or(e, vec3(0, 1, 0)), p);
			}
		}
	}
	return best < INFINITY;
}

/* The leaf's centroid: its vertices' mean (the attachment that is never on the axis). */
static struct vec3 centroid(const struct leaf *l)
{
	struct vec3 c = vec3(0, 0, 0);

	for (size_t k = 0; k < l->npoints; k++)
		c = vec3_add(c, l->points[k]);
	return vec3_scale(c, 1.0 / (double)l->npoints);
}

/* Records l's points in its branch's frame, in its existing `local` (as tree_leaf_attach
 * does, without allocating). */
static void leaf_reattach(const struct tree *t, struct leaf *l)
{
	struct tree_frame f = tree_frame_at(&t->branches[l->branch], l->branch_t);

	for (size_t k = 0; k < l->npoints; k++) {
		struct vec3 d = vec3_sub(l->points[k], f.origin);

		l->local[k] = vec3(vec3_dot(d, f.tangent), vec3_dot(d, f.normal),
				   vec3_dot(d, f.binormal));
	}
}

/* Leaf l out of the wood, rigidly; left as it was (bit for bit) when nothing is buried. */
static void leaf_out(const struct wood *w, struct tree *t, struct leaf *l)
{
	const struct wood_grid *g = &w->g;
	struct vec3 d, c;
	double s;

	if (l->npoints == 0 || !any_buried(g, l->points, l->npoints, vec3(0, 0, 0), 0.0))
		return;
	c = centroid(l);
	if (in_wood(w, t, l->branch)) {
		struct tree_frame f = tree_frame_at(&t->branches[l->branch], l->branch_t);

		d = away_from_axis(f.origin, f.tangent, c);
	} else if (!away_from_wood(w, t, c, &d)) {
		return;
	}
	s = unbury_shift(g, l->points, l->npoints, d) + MOVE_LEAF_MARGIN * g->h;
	s = clear_from(g, l->points, l->npoints, d, s);
	for (size_t k = 0; k < l->npoints; k++)
		l->points[k] = vec3_add(l->points[k], vec3_scale(d, s));
	/* so a later tree_leaves_follow keeps it out */
	if (l->local && l->branch >= 0 && (size_t)l->branch < t->nbranches)
		leaf_reattach(t, l);
}

/* A buried vine point to the surface plus the stem's radius, away from the nearest
 * voxelised axis. */
static void vine_point_out(const struct wood *w, const struct tree *t, double radius,
			   struct vec3 *p)
{
	const struct wood_grid *g = &w->g;
	struct vec3 d;
	double s;

	if (!buried(g, *p) || !away_from_wood(w, t, *p, &d))
		return;
	s = unbury_shift(g, p, 1, d) + radius;
	s = clear_from(g, p, 1, d, s);
	*p = vec3_add(*p, vec3_scale(d, s));
}

struct vine_move {
	const struct wood *w;
	const struct tree *t;
};

/* Each point of the vines (the tree's hook: the vines are theirs), the root too, where
 * the main axis starts: the same point moves the same way. */
static void vine_out(struct vec3 *p, double radius, void *ctx)
{
	const struct vine_move *m = ctx;

	vine_point_out(m->w, m->t, radius, p);
}

int wood_move_out(const struct wood *w, struct tree *t)
{
	if (!w->g.density || w->g.h <= 0.0)
		return -EINVAL;
	/* every leaf: on a voxelised branch, or buried by a neighbour's wood */
	for (size_t i = 0; i < t->nleaves; i++)
		leaf_out(w, t, &t->leaves[i]);
	if (t->nvines) {
		struct vine_move m = { w, t };

		t->vine_ops->each_point(t, vine_out, &m);
	}
	return 0;
}
