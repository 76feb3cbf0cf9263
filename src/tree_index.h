/* SPDX-License-Identifier: MIT */
#pragma once

#include <stdbool.h>
#include <stddef.h>

#include "tree.h"

/*
 * A grid of a tree's branch segments in x/y, so that sketch_nearest looks at the few
 * segments near a point instead of every one: without it, a history of n strokes replays
 * in O(n^2) (undo, redo, --load). Opt-in per tree (tree_index_keep; the app keeps one
 * for its tree), a cache the tree owns (t->index) and that tree.c and tree_edit.c keep
 * in step: appended branches are added when the next query comes; removals renumber it;
 * a cut only shortens a branch, which the query sees; clearing or truncating drops it.
 * A struct copy of the tree does not own it, so queries on the copy scan.
 *
 * The answer is exactly the linear scan's (every segment in order, squared distance by
 * tree_segment_d2, the first on equal distance): cells are visited until no unvisited
 * one can hold a segment at that distance (with a 1 um margin for rounding), and ties
 * go to the lowest (branch, segment).
 */
#define TREE_INDEX_CELL_M 0.1
/* Fewer segments than this are scanned: a grid would not pay. */
#define TREE_INDEX_MIN_SEGMENTS 64

struct tree_index;

/* Squared x/y distance from p to segment a-b and where along it (0..1) the nearest point
 * is: the one expression both the scan and the grid use, so they agree to the bit. */
static inline double tree_segment_d2(struct vec3 a, struct vec3 b, struct vec3 p, double *s_out)
{
	double dx = b.x - a.x, dy = b.y - a.y;
	double dd = dx * dx + dy * dy;
	double s = dd > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / dd : 0.0;
	double ex, ey;

	s = s < 0 ? 0 : s > 1 ? 1 : s;
	ex = a.x + s * dx - p.x;
	ey = a.y + s * dy - p.y;
	*s_out = s;
	return ex * ex + ey * ey;
}

struct tree_index_hit {
	int branch; /* -1: no segment at a finite distance */
	size_t segment;
	double seg_t;
	double d2;
};

/* From now on t keeps a grid for sketch_nearest (until tree_finish, or t is replaced).
 * Without memory it does nothing, and queries scan. */
void tree_index_keep(struct tree *t);
/* Frees t's grid, if t owns one (tree_finish calls it). */
void tree_index_destroy(struct tree *t);
/* The nearest segment to p, if t's grid can answer (false: scan instead). Brings the
 * grid up to date first, which is why t's cache changes through a const tree. */
bool tree_index_nearest(const struct tree *t, struct vec3 p, struct tree_index_hit *hit);

/* What tree.c and tree_edit.c tell it (no-ops without a grid). */
/* Everything may have changed: rebuilt at the next query. */
void tree_index_drop(struct tree *t);
/* Branches were renumbered: old id i < nold is now map[i], or gone if -1. */
void tree_index_renumbered(struct tree *t, const int *map, size_t nold);
/* Branches from nb on are gone. */
void tree_index_truncated(struct tree *t, size_t nb);
