/* SPDX-License-Identifier: MIT */
#pragma once

#include "camera.h"
#include "tree.h"

/*
 * The tree as the camera shows it, for sketching on a turned 3D tree: the same ids,
 * segments, parameters and radii, with points in view space (x, y on the screen's
 * sketch plane, z towards the viewer). The camera is rigid, so lengths and parameters
 * are the world's. For the front view it is the tree itself: nothing is copied and
 * results are bit for bit those of the 2D sketch.
 *
 * Of a tree that keeps a grid (tree_index.h) the copy's points are turned only as they
 * are needed, so that a stroke on a turned tree costs what is near it, not the whole
 * tree: sketch_nearest finds its hits through the tree's grid and shows them, and the
 * last branch and its ancestors are shown from the start (the two-outline test looks at
 * the last branch and its parent). Code that reads other points of the copy calls
 * sketch_seen_show_all first, before it changes the tree other than by removing its last
 * branch or appending: what is shown later is turned from the tree as it is then.
 */
struct sketch_seen {
	struct camera_xf xf;
	const struct tree *tree; /* what to query */
	struct tree shadow;      /* the turned copy, when there is one */
	struct vec3 *pool;
	const struct tree *world; /* what the copy is of */
	size_t *at;               /* where each branch's, then leaf's points go in pool */
	size_t nbranches;         /* the tree's when copied: leaves' places in at follow */
	bool lazy;                /* points not yet shown are NULL */
};

/* The pivot the camera turns about: the trunk's base (the origin without a trunk). */
struct vec3 sketch_seen_pivot(const struct tree *t);
/* 0 or -ENOMEM. */
int sketch_seen_init(struct sketch_seen *sv, const struct tree *t, struct camera c);
void sketch_seen_finish(struct sketch_seen *sv);
/* The tree's last branch was just removed: forget it here too. */
void sketch_seen_drop_last_branch(struct sketch_seen *sv);
/* Every point of the copy turned (nothing to do for the front view). */
void sketch_seen_show_all(struct sketch_seen *sv);
/* Distance on the screen (metres) from view-space point p to the nearest branch or
 * leaf; 0 inside a leaf, INFINITY on an empty tree. */
double sketch_seen_clearance(struct sketch_seen *sv, struct vec3 p);
/* Whether anything of t is within r of view-space point p on the screen through camera c:
 * the same answer as clearance <= r, without copying the tree and stopping at the first
 * hit (the cursor asks every frame). */
bool sketch_seen_near(const struct tree *t, struct camera c, struct vec3 p, double r);
