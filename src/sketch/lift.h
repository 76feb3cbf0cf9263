/* SPDX-License-Identifier: MIT */
#pragma once

#include <stdbool.h>

#include "rng.h"
#include "tree.h"

/*
 * Lifting the 2D sketch to a 3D tree (seed 000, sections 4.1-4.3). Every branch keeps its
 * drawn x and y (so the tree looks like the sketch from the front) and gets depth z:
 *
 * 4.1 Branches are taken as chords (segments from start to end) as the front view shows
 *     them and placed from the trunk outwards, generation by generation, in a seeded
 *     random order within a generation. A branch's start sits on its placed parent; the
 *     depth of its end is the sparsest admissible one on a LIFT_FIELD_N^2 distance field
 *     of all branches placed so far, projected on the ground, among those that leave the
 *     most of its children a depth keeping every rule, and, looking three generations
 *     down, the fewest descendants breaking the angle rule or the hull. Admissible: between 45 and 135
 *     degrees from the view direction; at most 1.2 x the largest drawn angle between the
 *     parent and its children from the parent's chord; inside the sqrt(2)-scaled hull
 *     (the sketch's 2D convex hull swept as discs from its lowest to its highest point);
 *     at most 1.2 x the parent's length. The depths keeping them are computed exactly;
 *     where no depth keeps a rule with those before it, the one breaking it least is
 *     taken (docs/lifting.md, "When a rule cannot hold").
 * 4.3 The points along each branch get depth by the constant-curvature rule, so a wavy
 *     stroke becomes a helix; both ends stay where 4.1 put them.
 * 4.2 With `merge`, this is done twice with different random streams; the second tree,
 *     turned 90 degrees about the vertical through the trunk's base, is merged into the
 *     first without its trunk (origin ORIGIN_MERGE): the branches a child leaves out
 *     because they point at the viewer. The second lift starts from the first tree's
 *     distance field and sees its own branches where the merge will put them, so they go
 *     where both trees are sparsest, and its ends inside the hull as merged (or, where no
 *     depth is, as near as the other rules let them), its first generation's angles to the
 *     first tree's trunk; the first tree is what a lift without it makes.
 *
 * Leaves follow their branches. A lifted tree (t->lifted) is left as it is. Returns 0 or
 * -ENOMEM (tree unchanged).
 */
#define LIFT_FIELD_N 128
#define LIFT_HULL_SCALE 1.41421356237309504880
#define LIFT_MAX_LENGTH_RATIO 1.2
#define LIFT_MAX_ANGLE_RATIO 1.2
#define LIFT_MIN_VIEW_ANGLE_DEG 45.0

/* How 4.1 chooses among the admissible depths of a branch end. */
enum lift_pick {
	LIFT_PICK_SPARSEST = 0, /* where the branches placed so far are sparsest (the paper) */
	LIFT_PICK_RANDOM,       /* a random admissible one: the baseline the tests measure
				 * the sparsest rule against (tests/replay/test_replay_lift.c) */
};

int lift_tree(struct tree *t, struct rng *rng, bool merge);
/* lift_tree with a choice of rule; lift_tree(t, rng, merge) is
 * lift_tree_with(t, rng, merge, LIFT_PICK_SPARSEST). */
int lift_tree_with(struct tree *t, struct rng *rng, bool merge, enum lift_pick pick);
