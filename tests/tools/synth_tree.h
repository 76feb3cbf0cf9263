/* SPDX-License-Identifier: MIT */
#pragma once

#include <stdint.h>

#include "tree.h"

/*
 * A seeded random tree for tests and benchmarks: a trunk, then branches attached to
 * random points of earlier branches, each with `leaves_per_branch` small leaf polygons.
 * Clears t (which must be initialised) first. Same arguments, same tree. 0 or -ENOMEM.
 */
int synth_tree(struct tree *t, int nbranches, int leaves_per_branch, uint64_t seed);
