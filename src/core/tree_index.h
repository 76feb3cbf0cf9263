/* SPDX-License-Identifier: MIT */
#pragma once

#include <stdbool.h>
#include <stddef.h>

#include "camera.h"
#include "tree.h"

/*
 * A grid of a tree's branch segments in space, so that sketch_nearest looks at the few
 * segments near a point as the screen shows them instead of every one: without it, a
 * history of n strokes replays in O(n^2) (undo, redo, --load). Opt-in per tree
 * (tree_index_keep; the app keeps one for its tree), a cache the tree owns (t->index)
 * and that tree.c and tree_edit.c keep in step: appended branches are added when the next
 * query comes; removals renumber it; a cut only shortens a branch, which the query sees;
 * clearing or truncating drops it. A struct copy of the tree does not own it, so
 * queries on the copy scan.
 *
 * The cells are cubes, so one grid serves every camera: the points a screen shows at
 * (x, y) lie on a line along the view direction, and a query visits the cells near that
 * line, slab by slab along the axis it runs closest to, widening until no unvisited cell
 * can hold a nearer segment (with a 1 um margin for rounding). The answer is exactly the
 * linear scan's of the tree as the camera shows it (every segment in order, squared
 * distance by tree_segment_d2 on the view-space points camera_to_view gives, the first
 * on equal distance). A sketch_seen's copy of a turned tree answers through the tree's
 * grid (tree_index_keep_view).
 */
#define TREE_INDEX_CELL_M 0.1
#define TREE_INDEX_DEPTH_M 0.5
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
/*
 * view (sketch_seen.c's copy of world, its points turned by xf into view space, the same
 * ids and segments) answers sketch_nearest from world's grid, if world keeps one: the
 * points of a branch are computed only when needed. show(ctx, b) is called to put branch
 * b's points into view before a hit on it is returned; show(ctx, -1) to put all of them
 * there before the query falls back to a scan (world without a grid, or changed since).
 * xf and ctx must outlive view's use. Without memory, nothing (view scans; show first).
 * False if view must be shown whole now.
 */
bool tree_index_keep_view(struct tree *view, const struct tree *world, const struct camera_xf *xf,
			  void (*show)(void *ctx, int branch), void *ctx);
/* Frees t's grid, if t owns one (tree_finish calls it). */
void tree_index_destroy(struct tree *t);
/* The nearest segment to p (x, y as t shows it), if t's grid can answer (false: scan
 * instead). Brings the grid up to date first, which is why t's cache changes through a
 * const tree. */
bool tree_index_nearest(const struct tree *t, struct vec3 p, struct tree_index_hit *hit);

/* What tree.c and tree_edit.c tell it (no-ops without a grid). */
/* Everything may have changed: rebuilt at the next query. */
void tree_index_drop(struct tree *t);
/* Branches were renumbered: old id i < nold is now map[i], or gone if -1. */
void tree_index_renumbered(struct tree *t, const int *map, size_t nold);
/* The branches were replaced (undo, redo): old id i < nold is now map[i], with the same
 * points, or gone if -1; the branches no old one maps to are added now. */
void tree_index_replaced(struct tree *t, const int *map, size_t nold);
/* Branches from nb on are gone. */
void tree_index_truncated(struct tree *t, size_t nb);
/* a and b were swapped, their grids with them (tree_swap). */
void tree_index_swapped(struct tree *a, struct tree *b);
/* dst's content was just put in place of src's (a checkpoint put back): src's grid goes
 * to dst, keeping the branches of dst with the same points as one of src's (renumbered)
 * and adding the others. Quicker than a new grid when the two share most branches. */
void tree_index_move(struct tree *dst, struct tree *src);
