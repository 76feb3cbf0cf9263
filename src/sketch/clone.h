/* SPDX-License-Identifier: MIT */
#pragma once

#include "rng.h"
#include "tree.h"

/*
 * Example-based cloning (seed 000, sections 3.4 and 4.4): one more child on a parent
 * branch, learnt from the children it already has, so the tree keeps its shape whatever
 * the count; and one less. The rules are at the top of clone.c.
 */

/* A new child's rotation angle about the parent's head stays within this of up, where
 * the parent is inclined (see CLONE_UPRIGHT_DEG). */
#define CLONE_MAX_ROTATION_DEG 120.0
/* A parent whose head at the new child's parameter is within this of the vertical (up or
 * down) is upright: the rotation angle does not change how far a child points down, so
 * it is chosen over the full circle, not within CLONE_MAX_ROTATION_DEG of up. */
#define CLONE_UPRIGHT_DEG 30.0
/* Below this |up - (up . head) head| the head counts as vertical and the turtle's up is
 * world +z (towards the front viewer) instead of the world up made perpendicular. */
#define CLONE_VERTICAL_EPS 1e-9

/* The turtle frame on a parent at arc-length parameter t: origin on its polyline (as
 * tree_locate puts it), head = its unit tangent, up = world up (0,1,0) made perpendicular
 * to head (world +z when head is vertical), left = up x head: orthonormal, and
 * head x left = up as for the L-system turtle's H, L, U. */
struct clone_turtle {
	struct vec3 origin, head, up, left;
};

struct clone_turtle clone_turtle_at(const struct branch *parent, double t);

/* Adds one child to branch `parent` (origin ORIGIN_CLONE). Returns the new branch's id,
 * -ENOENT if parent is not a branch or has no child branch to learn from (none with two
 * points and a root apart from its tip), -ENOSPC if the tree has TREE_MAX_BRANCHES
 * already, -ENOMEM (tree unchanged). Draws one number from rng (none on -ENOENT or
 * -ENOSPC). */
int clone_add(struct tree *t, int parent, struct rng *rng);

/* Removes parent's newest child branch (the highest id), with everything attached to it.
 * Returns the id it had, -ENOENT if there is none, -ENOMEM. */
int clone_remove(struct tree *t, int parent);
