/* SPDX-License-Identifier: MIT */
/*
 * Propagation (the propagate button) on synthetic trees of 250..1,000 branches: the
 * source is one branch off the trunk carrying either 20 leaves or 3 child branches with
 * 5 leaves each; it is copied onto every other branch but the trunk, with both patterns.
 * Median of REPS runs (the tree is rebuilt outside the timing), growth with size, how
 * much was added. Aim: 20 leaves onto each branch of a 1,000-branch tree (20,000 leaves)
 * in under 50 ms.
 */
#include <stdio.h>

#include "bench_util.h"
#include "propagate.h"
#include "synth_tree.h"
#include "tree.h"

#define REPS 9
#define SEED 2024
#define LEAF_POINTS 7

enum example { LEAVES, BRANCHES };

/* A 7-point leaf beside b at u, its outline recorded in b's frame. */
static int add_leaf(struct tree *t, int b, double u)
{
	struct tree_frame f = tree_frame_at(&t->branches[b], u);
	struct vec3 p[LEAF_POINTS];
	int id;

	for (int i = 0; i < LEAF_POINTS; i++) {
		double a = 2.0 * VEC_PI * i / LEAF_POINTS;

		p[i] = vec3_add(f.origin, vec3_add(vec3_scale(f.normal, 0.06 * (1.0 + cos(a)) + 0.02),
						   vec3_add(vec3_scale(f.tangent, 0.03 * sin(a)),
							    vec3_scale(f.binormal, 0.02 * cos(a)))));
	}
	id = tree_add_leaf(t, b, ORIGIN_SKETCH, p, LEAF_POINTS);
	if (id < 0)
		return id;
	t->leaves[id].branch_t = u;
	return tree_leaf_attach(t, (size_t)id);
}

/* A straight branch of n points from the point at pt on parent, along dir, len metres. */
static int add_branch(struct tree *t, int parent, double pt, struct vec3 dir, double len, double r0)
{
	struct vec3 p[8], root = tree_frame_at(&t->branches[parent], pt).origin;
	double r[8];

	dir = vec3_norm_or(dir, vec3(0, 1, 0));
	for (int k = 0; k < 8; k++) {
		p[k] = vec3_add(root, vec3_scale(dir, len * k / 7.0));
		r[k] = r0 * (1.0 - 0.6 * k / 7.0);
	}
	return tree_add_branch(t, parent, pt, ORIGIN_SKETCH, p, r, 8);
}

/* A tree of n branches whose last one (or last but three) is the source. Returns the
 * source's id, or < 0. */
static int build(struct tree *t, int n, enum example e)
{
	int src, ret;

	ret = synth_tree(t, e == LEAVES ? n - 1 : n - 4, 0, SEED);
	if (ret < 0)
		return ret;
	src = add_branch(t, 0, 0.5, vec3(1, 0.6, 0.2), 1.5, 0.05);
	if (src < 0)
		return src;
	if (e == LEAVES) {
		for (int i = 0; i < 20 && ret >= 0; i++)
			ret = add_leaf(t, src, 0.1 + 0.045 * i);
		return ret < 0 ? ret : src;
	}
	for (int c = 0; c < 3 && ret >= 0; c++) {
		int b = add_branch(t, src, 0.3 + 0.3 * c, vec3(0.5, 1, 0.4 * (c - 1)), 0.5, 0.02);

		if (b < 0)
			return b;
		for (int i = 0; i < 5 && ret >= 0; i++)
			ret = add_leaf(t, b, 0.2 + 0.18 * i);
	}
	return ret < 0 ? ret : src;
}

static int bench(enum example e, enum propagate_pattern p, const char *label)
{
	static const int sizes[] = { 250, 500, 1000 };
	double pn = 0, pt = 0;

	for (size_t s = 0; s < BENCH_COUNT(sizes); s++) {
		double t[REPS];
		char name[64];
		int added = 0;

		for (int r = 0; r < bench_reps(REPS); r++) {
			struct tree tree;
			int src;
			double t0;

			tree_init(&tree);
			src = build(&tree, sizes[s], e);
			if (src < 0)
				return 1;
			t0 = bench_now();
			added = propagate_apply(&tree, src, p);
			t[r] = bench_now() - t0;
			if (added < 0)
				return 1;
			tree_finish(&tree);
		}
		snprintf(name, sizeof(name), "%s (+%d)", label, added);
		bench_row(name, sizes[s], bench_median(t, (size_t)bench_reps(REPS)), &pn, &pt);
	}
	return 0;
}

int main(int argc, char **argv)
{
	if (bench_init(&argc, argv, NULL))
		return 1;
	printf("%-28s %10s %12s\n", "propagate", "branches", "median");
	if (bench(LEAVES, PROPAGATE_FIXED_COUNT, "20 leaves, count") ||
	    bench(LEAVES, PROPAGATE_FIXED_SIZE, "20 leaves, size") ||
	    bench(BRANCHES, PROPAGATE_FIXED_COUNT, "3x(1+5), count") ||
	    bench(BRANCHES, PROPAGATE_FIXED_SIZE, "3x(1+5), size"))
		return 1;
	return 0;
}
