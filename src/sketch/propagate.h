/* SPDX-License-Identifier: MIT */
#pragma once

#include "tree.h"

/*
 * Propagation by example (seed 000, section 3.6): the children of one branch (its leaves
 * and its child branches with their leaves) copied onto every other branch.
 * The algorithm and its rules: the comment at the top of propagate.c.
 */
enum propagate_pattern {
	PROPAGATE_FIXED_COUNT = 0, /* the same number, spread over the target's length */
	PROPAGATE_FIXED_SIZE,      /* the same sizes and spacing, from the tip down */
};

/* Branches shorter than this (metres) have no size to match: never a target; as the
 * source, -ENOENT. */
#define PROPAGATE_MIN_LENGTH_M 1e-6
/* Fixed size: a child at distance d from the source's tip fits a target of length L
 * when d <= L + this (metres), so rounding does not drop one that fits exactly. */
#define PROPAGATE_FIT_EPS_M 1e-9

/* Copies src's children onto the other branches (origin ORIGIN_PROPAGATE). Returns how
 * many elements it added (0 if no branch can take them), -ENOENT if src is not a branch,
 * has no children or is shorter than PROPAGATE_MIN_LENGTH_M, -ENOSPC if the copies could
 * take the tree past TREE_MAX_BRANCHES / TREE_MAX_LEAVES, -ENOMEM (the tree is then
 * unchanged). */
int propagate_apply(struct tree *t, int src, enum propagate_pattern p);
