/* SPDX-License-Identifier: MIT */
/*
 * Cloning (clone mode: one more child on a branch, one less). The median time of one
 * clone_add: on a trunk with 5..500 children and nothing else; on seeded synthetic trees
 * of 100..1,000 branches (synth_tree) on the branch with the most children; and on
 * drawn trees of 100..1,000 strokes lifted to 3D as the 3D button does, on the trunk.
 * Each add is undone by clone_remove, timed apart, so every sample sees the same tree
 * (the remove's time is printed for the synthetic trees). Medians; growth with size.
 */
#include <stdio.h>
#include <stdlib.h>

#include "bench_draw.h"
#include "bench_util.h"
#include "clone.h"
#include "doc.h"
#include "lift.h"
#include "sketch.h"
#include "synth_tree.h"

#define REPS 201
#define SEED 2024

/* A trunk 6 m tall of 60 points with k children of 12 points at random places all round
 * it. 0 or < 0. */
static int build_parent(struct tree *t, int k, struct rng *rng)
{
	struct vec3 p[60];
	double r[60];

	tree_init(t);
	for (int i = 0; i < 60; i++) {
		p[i] = vec3(0.1 * sin(i * 0.2), 6.0 * i / 59.0, 0.05 * cos(i * 0.3));
		r[i] = 0.25 * (1.0 - 0.8 * i / 59.0);
	}
	if (tree_add_branch(t, -1, 0, ORIGIN_SKETCH, p, r, 60) < 0)
		return -1;
	for (int c = 0; c < k; c++) {
		double pt = rng_range(rng, 0.1, 0.95), az = rng_range(rng, 0, 2 * VEC_PI);
		double down = rng_range(rng, 0.6, 1.3), len = 2.0 * (1.1 - pt);
		struct clone_turtle tu = clone_turtle_at(&t->branches[0], pt);
		struct vec3 d = vec3_add(vec3_scale(tu.head, cos(down)),
					 vec3_scale(vec3_add(vec3_scale(tu.up, cos(az)),
							     vec3_scale(tu.left, sin(az))),
						    sin(down)));

		for (int i = 0; i < 12; i++) {
			double s = i / 11.0;

			p[i] = vec3_add(tu.origin, vec3_add(vec3_scale(d, s * len),
							    vec3(0, -0.1 * len * s * s, 0)));
			r[i] = 0.04 * (1.0 - 0.7 * s);
		}
		if (tree_add_branch(t, 0, pt, ORIGIN_SKETCH, p, r, 12) < 0)
			return -1;
	}
	t->lifted = true;
	return 0;
}

static int most_children(const struct tree *t, int *count)
{
	int best = 0, *n = calloc(t->nbranches, sizeof(*n));

	*count = 0;
	if (!n)
		return -1;
	for (size_t i = 0; i < t->nbranches; i++)
		if (t->branches[i].parent >= 0)
			n[t->branches[i].parent]++;
	for (size_t i = 0; i < t->nbranches; i++)
		if (n[i] > n[best])
			best = (int)i;
	*count = n[best];
	free(n);
	return best;
}

/* Median seconds of one clone_add and of one clone_remove on parent. */
static int time_clone(struct tree *t, int parent, double *add_s, double *remove_s)
{
	double add[REPS], rem[REPS];
	int reps = bench_reps(REPS);
	struct rng rng;

	rng_seed(&rng, SEED);
	for (int r = 0; r < reps; r++) {
		double t0 = bench_now(), t1, t2;

		if (clone_add(t, parent, &rng) < 0)
			return -1;
		t1 = bench_now();
		if (clone_remove(t, parent) < 0)
			return -1;
		t2 = bench_now();
		add[r] = t1 - t0;
		rem[r] = t2 - t1;
	}
	*add_s = bench_median(add, (size_t)reps);
	*remove_s = bench_median(rem, (size_t)reps);
	return 0;
}

static int by_children(void)
{
	static const int sizes[] = { 5, 10, 20, 50, 100, 200, 500 };
	double pn = 0, pt = 0;

	printf("clone_add on a trunk with k children (the tree is only those)\n");
	for (size_t s = 0; s < BENCH_COUNT(sizes); s++) {
		struct tree t;
		struct rng rng;
		double add, rem;
		char name[64];

		rng_seed(&rng, SEED);
		if (build_parent(&t, sizes[s], &rng) < 0 || time_clone(&t, 0, &add, &rem) < 0)
			return 1;
		snprintf(name, sizeof(name), "add, %d ch: %.1f us", sizes[s], add * 1e6);
		bench_row(name, sizes[s], add, &pn, &pt);
		tree_finish(&t);
	}
	return 0;
}

static int by_tree_size(void)
{
	static const int sizes[] = { 100, 200, 500, 1000 };
	double pn = 0, pt = 0, rn = 0, rt = 0;

	printf("synthetic trees of n branches, on the branch with the most children\n");
	for (size_t s = 0; s < BENCH_COUNT(sizes); s++) {
		struct tree t;
		double add, rem;
		char name[64];
		int parent, k;

		tree_init(&t);
		if (synth_tree(&t, sizes[s], 0, SEED) < 0)
			return 1;
		parent = most_children(&t, &k);
		if (parent < 0 || time_clone(&t, parent, &add, &rem) < 0)
			return 1;
		snprintf(name, sizeof(name), "add, %d ch: %.1f us", k, add * 1e6);
		bench_row(name, sizes[s], add, &pn, &pt);
		snprintf(name, sizeof(name), "remove: %.2f us", rem * 1e6);
		bench_row(name, sizes[s], rem, &rn, &rt);
		tree_finish(&t);
	}
	return 0;
}

static int drawn_lifted(void)
{
	static const int sizes[] = { 100, 250, 500, 1000 };
	double pn = 0, pt = 0;

	printf("drawn trees lifted to 3D (with the merge), on the trunk\n");
	for (size_t s = 0; s < BENCH_COUNT(sizes); s++) {
		struct bench_pen pen = { .pen.now_us = 1000 };
		struct app *app = bench_draw_tree(&pen, sizes[s]);
		struct tree t;
		struct rng rng;
		double add, rem;
		char name[64];
		int k = 0;

		if (!app)
			return 1;
		tree_init(&t);
		rng_seed(&rng, app->doc.seed);
		for (size_t i = 0; i < app->doc.cursor; i++)
			if (doc_apply_stroke(&t, &app->doc.ops[i]) < 0)
				return 1;
		if (lift_tree(&t, &rng, true) < 0)
			return 1;
		for (size_t i = 0; i < t.nbranches; i++)
			k += t.branches[i].parent == 0;
		if (time_clone(&t, 0, &add, &rem) < 0)
			return 1;
		snprintf(name, sizeof(name), "add, %zu br %d ch: %.1f us", t.nbranches, k, add * 1e6);
		bench_row(name, sizes[s], add, &pn, &pt);
		tree_finish(&t);
		app_destroy(app);
	}
	return 0;
}

int main(int argc, char **argv)
{
	if (bench_init(&argc, argv, NULL))
		return 1;
	printf("median of %d: one clone_add (each undone by clone_remove); size, ms, growth\n",
	       bench_reps(REPS));
	if (by_children() || by_tree_size() || drawn_lifted())
		return 1;
	return 0;
}
