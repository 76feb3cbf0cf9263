/* SPDX-License-Identifier: MIT */
#pragma once

/* The trees the living tree's tests and bench run on (live_trees.c). */
#include <stdbool.h>
#include <stdint.h>

#include "gen.h"
#include "live.h"
#include "mesh.h"
#include "tree.h"

/* The demo drawing (tests/data/demo.edaha-trace) replayed through the app as the headless
 * run does (1280x800, seed 1), lifted to 3D with the 3D button if `lift`: into t
 * (initialised). */
void live_trees_demo(struct tree *t, const char *data_dir, bool lift);
/* A functional tree's preset, built with seed 1. */
void live_trees_preset(struct tree *t, enum gen_preset p);
/*
 * A seeded random tree (tests/tools/synth_tree.c: a 6 m trunk, branches on earlier
 * branches, leaves_per_branch leaves on each), each leaf's branch_t set where its centroid
 * projects onto its branch (synth_tree leaves it 0), scaled about the trunk's foot to
 * `height` metres from the foot to its highest point.
 */
void live_trees_random(struct tree *t, int nbranches, int leaves_per_branch, uint64_t seed,
		       double height);
/* Scales t about branch 0's foot by k: points, radii, leaves. */
void live_trees_scale(struct tree *t, double k);
/* The skeleton point of branch b at arc-length parameter u (0..1). */
struct vec3 live_trees_point(const struct tree *t, size_t b, double u);

/*
 * Dominant frequency of a sampled vector signal over one loop (n samples at t = i T / n):
 * the harmonic m in 1..n/2 with the most power (its three components' |DFT|^2 summed).
 */
int live_trees_dominant(const struct vec3 *x, int n);
