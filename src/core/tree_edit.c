/* SPDX-License-Identifier: MIT */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "tree.h"
#include "tree_index.h"
#include "tree_journal.h"

#define TREE_MIN_CUT_M 0.025

double tree_branch_length(const struct branch *b)
{
	return vec3_polyline_length(b->points, b->npoints);
}

void tree_locate(const struct branch *b, double t, size_t *segment, double *seg_t)
{
	double want = t * tree_branch_length(b), walked = 0.0;

	*segment = 0;
	*seg_t = 0.0;
	for (size_t i = 0; i + 1 < b->npoints; i++) {
		double l = vec3_dist(b->points[i], b->points[i + 1]);

		*segment = i;
		if (walked + l >= want || i + 2 == b->npoints) {
			*seg_t = l > 0 ? fmin(fmax((want - walked) / l, 0.0), 1.0) : 0.0;
			return;
		}
		walked += l;
	}
}

double tree_param(const struct branch *b, size_t segment, double seg_t)
{
	double len = tree_branch_length(b), walked = 0.0;

	if (len <= 0 || segment + 1 >= b->npoints)
		return segment + 1 >= b->npoints && len > 0 ? 1.0 : 0.0;
	for (size_t i = 0; i < segment; i++)
		walked += vec3_dist(b->points[i], b->points[i + 1]);
	walked += seg_t * vec3_dist(b->points[segment], b->points[segment + 1]);
	return walked / len;
}

/* Compacts the leaves, keeping order; map_branch gives each branch's new id or -1. */
static void compact_leaves(struct tree *t, const int *map_branch, const bool *remove_leaf)
{
	/* the journal, if any, follows the leaves that stay (without memory it gives up) */
	int *map = t->journal ? malloc((t->nleaves + 1) * sizeof(*map)) : NULL;
	size_t k = 0, n = t->nleaves;

	if (t->journal && !map)
		tree_journal_fail(t);
	for (size_t i = 0; i < t->nleaves; i++) {
		int b = map_branch ? map_branch[t->leaves[i].branch] : t->leaves[i].branch;

		if ((remove_leaf && remove_leaf[i]) || b < 0)
			tree_journal_leaf(t, i, false);
	}
	for (size_t i = 0; i < t->nleaves; i++) {
		struct leaf l = t->leaves[i];
		int b = map_branch ? map_branch[l.branch] : l.branch;

		if ((remove_leaf && remove_leaf[i]) || b < 0) {
			free(l.points);
			free(l.local);
			if (map)
				map[i] = -1;
			continue;
		}
		if (map)
			map[i] = (int)k;
		l.id = (int)k;
		l.branch = b;
		t->leaves[k++] = l;
	}
	t->nleaves = k;
	if (map)
		tree_journal_leaves_moved(t, map, n);
	free(map);
}

void tree_remove_leaves(struct tree *t, const bool *remove)
{
	compact_leaves(t, NULL, remove);
}

/* map: room for nbranches ints, so that nothing here can fail. */
static void remove_branches(struct tree *t, bool *remove, int *map)
{
	size_t k = 0, n = t->nbranches;

	/* Children come after their parents, so one pass spreads removal down the tree. */
	for (size_t i = 0; i < t->nbranches; i++) {
		int p = t->branches[i].parent;

		if (p >= 0 && remove[p])
			remove[i] = true;
	}
	/* what goes, as it was, to the journal if any: the leaves too, while their branches
	 * still have the ids it knows */
	for (size_t i = 0; i < t->nbranches; i++)
		if (remove[i])
			tree_journal_branch(t, i, false);
	for (size_t i = 0; i < t->nleaves; i++)
		if (remove[t->leaves[i].branch])
			tree_journal_leaf(t, i, false);
	for (size_t i = 0; i < t->nbranches; i++) {
		struct branch b = t->branches[i];

		if (remove[i]) {
			free(b.points);
			free(b.radii);
			map[i] = -1;
			continue;
		}
		map[i] = (int)k;
		b.id = (int)k;
		if (b.parent >= 0)
			b.parent = map[b.parent];
		t->branches[k++] = b;
	}
	t->nbranches = k;
	tree_journal_branches_moved(t, map, n);
	tree_index_renumbered(t, map, n);
	compact_leaves(t, map, NULL);
	if (k == 0)
		t->lifted = false; /* nothing left: the next drawing starts flat */
}

int tree_remove_branches(struct tree *t, bool *remove)
{
	int *map = malloc((t->nbranches + 1) * sizeof(*map));

	if (!map)
		return -ENOMEM;
	remove_branches(t, remove, map);
	free(map);
	return 0;
}

int tree_cut_branch(struct tree *t, int id, size_t segment, double seg_t)
{
	struct branch *b = &t->branches[id];
	double len = tree_branch_length(b), walked = 0.0, cut_t;
	bool *remove;
	int *map;
	size_t n = segment + 2;

	if (segment + 1 >= b->npoints)
		return 0;
	for (size_t i = 0; i < segment; i++)
		walked += vec3_dist(b->points[i], b->points[i + 1]);
	walked += seg_t * vec3_dist(b->points[segment], b->points[segment + 1]);
	cut_t = len > 0 ? walked / len : 0.0;

	remove = calloc(t->nbranches + t->nleaves + 1, sizeof(*remove));
	map = malloc((t->nbranches + 1) * sizeof(*map));
	if (!remove || !map) {
		free(remove);
		free(map);
		return -ENOMEM;
	}
	/* A cut at the very root leaves nothing worth keeping: the branch goes, as if erased
	 * (a zero-length branch would be invisible yet take children). */
	if (walked < TREE_MIN_CUT_M) {
		remove[id] = true;
		remove_branches(t, remove, map);
		free(remove);
		free(map);
		return 0;
	}
	/* The journal, if any, keeps b, and what is rescaled on it, as they were. */
	if (tree_journal_keep_cut(t, id, cut_t) < 0) {
		free(remove);
		free(map);
		return -ENOMEM;
	}
	b = &t->branches[id];
	/* The cut point replaces everything past it. */
	b->points[segment + 1] = vec3_lerp(b->points[segment], b->points[segment + 1], seg_t);
	b->radii[segment + 1] = b->radii[segment] + (b->radii[segment + 1] - b->radii[segment]) * seg_t;
	b->npoints = n;

	for (size_t i = 0; i < t->nleaves; i++) {
		struct leaf *l = &t->leaves[i];

		if (l->branch != id)
			continue;
		if (l->branch_t > cut_t)
			remove[t->nbranches + i] = true;
		else if (cut_t > 0)
			l->branch_t /= cut_t;
	}
	tree_remove_leaves(t, remove + t->nbranches);
	memset(remove, 0, t->nbranches * sizeof(*remove));
	for (size_t i = 0; i < t->nbranches; i++) {
		struct branch *c = &t->branches[i];

		if (c->parent != id)
			continue;
		if (c->parent_t > cut_t)
			remove[i] = true;
		else if (cut_t > 0)
			c->parent_t /= cut_t;
	}
	remove_branches(t, remove, map);
	free(remove);
	free(map);
	return 0;
}

struct tree_frame tree_frame_at(const struct branch *b, double t)
{
	struct tree_frame f = { .tangent = vec3(0, 1, 0), .normal = vec3(1, 0, 0),
				.binormal = vec3(0, 0, 1) };
	size_t seg;
	double s;

	if (b->npoints == 0)
		return f;
	f.origin = b->points[0];
	if (b->npoints < 2)
		return f;
	tree_locate(b, t, &seg, &s);
	f.origin = vec3_lerp(b->points[seg], b->points[seg + 1], s);
	f.tangent = vec3_norm_or(vec3_sub(b->points[seg + 1], b->points[seg]), f.tangent);
	/* The normal lies across the branch in the picture plane (z up out of the screen)
	 * unless the branch points along z. */
	f.normal = vec3_norm_or(vec3_cross(vec3(0, 0, 1), f.tangent),
				vec3_norm_or(vec3_cross(vec3(1, 0, 0), f.tangent), vec3(0, 1, 0)));
	f.binormal = vec3_cross(f.tangent, f.normal);
	return f;
}

int tree_leaf_attach(struct tree *t, size_t i)
{
	struct leaf *l = &t->leaves[i];
	struct tree_frame f = tree_frame_at(&t->branches[l->branch], l->branch_t);
	struct vec3 *local;

	if (tree_journal_leaf(t, i, true) < 0) /* the journal keeps it as it was, if any */
		return -ENOMEM;
	local = realloc(l->local, (l->npoints ? l->npoints : 1) * sizeof(*local));
	if (!local)
		return -ENOMEM;
	for (size_t k = 0; k < l->npoints; k++) {
		struct vec3 d = vec3_sub(l->points[k], f.origin);

		local[k] = vec3(vec3_dot(d, f.tangent), vec3_dot(d, f.normal), vec3_dot(d, f.binormal));
	}
	l->local = local;
	return 0;
}

void tree_leaves_follow(struct tree *t, int b)
{
	for (size_t i = 0; i < t->nleaves; i++) {
		struct leaf *l = &t->leaves[i];
		struct tree_frame f;

		if (!l->local || (b >= 0 && l->branch != b))
			continue;
		if (tree_journal_leaf(t, i, true) < 0)
			tree_journal_fail(t); /* moved all the same; its op goes without a delta */
		l = &t->leaves[i];
		f = tree_frame_at(&t->branches[l->branch], l->branch_t);
		for (size_t k = 0; k < l->npoints; k++)
			l->points[k] = vec3_add(f.origin,
						vec3_add(vec3_scale(f.tangent, l->local[k].x),
							 vec3_add(vec3_scale(f.normal, l->local[k].y),
								  vec3_scale(f.binormal, l->local[k].z))));
	}
}
