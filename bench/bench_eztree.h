/* SPDX-License-Identifier: MIT */
#pragma once

#include <stddef.h>

/*
 * ez-tree (npm @dgreenheck/ez-tree 1.1.0, three.js, under node) timed by
 * bench/eztree/bench.mjs, for bench_generate's comparison. tools/setup-eztree.sh
 * installs it into bench/eztree/node_modules; node is taken from $NODE, else `node`.
 */

/* One ez-tree tree matched to one of ours. */
struct eztree_result {
	char label[16];   /* the size it stands for ("5k") */
	size_t target;    /* our triangles it was matched to */
	size_t triangles; /* ez-tree's: bark + leaves, as the indices it generates */
	size_t bark, leaves;
	double median_s;  /* one Tree.generate(), median after warm-up */
	double cpu_s;     /* its CPU time, median: node's every thread (GC, JIT) */
	int reps;
	char options[256]; /* the preset and what was changed, as the script says it */
};

/*
 * Runs the script for trees of n sizes (labels[i], matched to targets[i] triangles), reps
 * timed runs each, and reads its figures into out[0..n) in the same order. Returns n, or
 * 0 when ez-tree or node is not there (having said so and how to install it), or -1 when
 * the script failed (its output printed).
 */
int eztree_run(const char *const *labels, const size_t *targets, size_t n, int reps,
	       struct eztree_result *out);
