/* SPDX-License-Identifier: MIT */
/*
 * Growing in (src/live/live_grow.c, docs/living-trees.md, "Growing in"), on the demo, the
 * presets and a few hundred seeded random trees, their meshes bound (bark and leaves):
 *
 * - each vertex's d is its skeleton point's path length from the foot, as walked here
 *   independently (within float rounding);
 * - no branch's vertex is drawn before the front has passed the branch's base (its
 *   parent's point at parent_t), at any of 400 times of the growth; no leaf's vertex
 *   before the front has passed its anchor (its branch's point at branch_t), and a leaf's
 *   vertices all appear together;
 * - the front rises from 0, never goes back, and is D_max + swell exactly at the duration;
 *   there every vertex is drawn with pull 1 exactly and lies where the mesh has it, to
 *   the bit (the settled tree is today's mesh);
 * - the duration lies in [2, 6] s;
 * - an origami leaf's unfolding keyframe (live_grow_unfold_*), at 20,000 seeded random
 *   fronts, swells, keyframe counts and anchors: the keyframe is floor(nframes x pull)
 *   (at rest once the pull is 1) but within 1e-9 of a keyframe's change; the bounds fall
 *   from the front, and a leaf's keyframe never goes back as the front runs on.
 *
 * It prints the durations' range.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "live.h"
#include "live_trees.h"
#include "mesh.h"
#include "rng.h"
#include "test.h"

#define TIMES 400
#define RANDOM_TREES 300

static double dur_lo = INFINITY, dur_hi = 0.0;
static size_t checked_vertices;

/* Path length from the foot to branch b's point at parameter u, walked without src/live. */
static double path_to(const struct tree *t, size_t b, double u)
{
	double d = u * tree_branch_length(&t->branches[b]);

	while (t->branches[b].parent >= 0) {
		const struct branch *br = &t->branches[b];

		b = (size_t)br->parent;
		d += br->parent_t * tree_branch_length(&t->branches[b]);
	}
	return d;
}

static struct vec3 pos_of(const struct mesh *m, size_t i)
{
	return vec3(m->positions[3 * i], m->positions[3 * i + 1], m->positions[3 * i + 2]);
}

static void check_tree(const char *name, const struct tree *t, uint64_t seed, bool quiet)
{
	struct live_skeleton sk;
	struct live_grow g;
	struct tree_mesh tm;
	struct tree_mesh_marks mk;
	struct live_attrs bark, leaves;
	double prev = 0.0;

	tree_mesh_init(&tm);
	tree_mesh_marks_init(&mk);
	live_attrs_init(&bark);
	live_attrs_init(&leaves);
	CHECK_INT(live_skeleton_init(&sk, t, seed), 0);
	CHECK_INT(tree_mesh_build_marked(&tm, t, &mk), 0);
	CHECK_INT(live_attrs_bind_bark(&bark, &sk, t, &tm.bark, &mk), 0);
	CHECK_INT(live_attrs_bind_leaves(&leaves, &sk, t, &tm.leaves, &mk), 0);
	live_grow_setup(&g, &sk);
	CHECK(g.duration >= 2.0 && g.duration <= 6.0);
	dur_lo = fmin(dur_lo, g.duration);
	dur_hi = fmax(dur_hi, g.duration);
	CHECK_NEAR(g.d_end, g.d_max + g.swell, 1e-6 * (1 + g.d_max) + 1e-12);
	CHECK(live_grow_front(&g, 0.0) == 0.0 && live_grow_front(&g, -1.0) == 0.0);
	CHECK(live_grow_front(&g, g.duration) == g.d_end);
	CHECK(live_grow_front(&g, g.duration + 100.0) == g.d_end);

	/* d is the path length from the foot */
	for (size_t b = 0; b < t->nbranches; b++) {
		size_t v0 = mk.bark[b].nvertices, v1 = mk.bark[b + 1].nvertices;
		double base = path_to(t, b, 0.0), len = tree_branch_length(&t->branches[b]);

		CHECK_NEAR(sk.branches[b].d0, base, 1e-9 * (1 + base));
		for (size_t i = v0; i < v1; i++) {
			CHECK(bark.v[i].d >= (float)base);
			CHECK(bark.v[i].d <= (float)(base + len));
		}
	}
	for (size_t l = 0; l < t->nleaves; l++) {
		const struct leaf *lf = &t->leaves[l];
		double d = path_to(t, (size_t)lf->branch, lf->branch_t);

		for (size_t i = mk.leaves[l].nvertices; i < mk.leaves[l + 1].nvertices; i++) {
			CHECK_NEAR(leaves.v[i].d, d, 1e-5 * (1 + d));
			CHECK(leaves.v[i].d == leaves.v[mk.leaves[l].nvertices].d);
		}
	}

	/* the order of growth, at TIMES moments */
	for (int k = 0; k <= TIMES; k++) {
		double t_s = g.duration * k / TIMES, front = live_grow_front(&g, t_s);

		CHECK(front >= prev);
		prev = front;
		for (size_t b = 0; b < t->nbranches; b++) {
			const struct branch *br = &t->branches[b];
			/* the parent's point where this branch hangs (its base, for a trunk) */
			double base_d = br->parent >= 0 ? path_to(t, (size_t)br->parent, br->parent_t) : 0.0;

			for (size_t i = mk.bark[b].nvertices; i < mk.bark[b + 1].nvertices; i++) {
				double f;

				if (!live_grow_visible(front, bark.v[i].d))
					continue;
				CHECK(front >= base_d - 1e-6 * (1 + base_d));
				f = live_grow_pull(&g, front, bark.v[i].d);
				CHECK(f >= 0.0 && f <= 1.0);
			}
		}
		for (size_t l = 0; l < t->nleaves; l++) {
			const struct leaf *lf = &t->leaves[l];
			double anchor = path_to(t, (size_t)lf->branch, lf->branch_t);

			for (size_t i = mk.leaves[l].nvertices; i < mk.leaves[l + 1].nvertices; i++)
				if (live_grow_visible(front, leaves.v[i].d))
					CHECK(front >= anchor - 1e-5 * (1 + anchor));
		}
	}

	/* settled: every vertex drawn where the mesh has it, to the bit */
	{
		double front = live_grow_front(&g, g.duration);

		for (size_t i = 0; i < bark.n; i++) {
			struct vec3 p = pos_of(&tm.bark, i), q = live_grow_position(&g, front, &bark.v[i], p);
			float qf[3] = { (float)q.x, (float)q.y, (float)q.z };

			CHECK(live_grow_visible(front, bark.v[i].d));
			CHECK(live_grow_pull(&g, front, bark.v[i].d) == 1.0);
			CHECK(memcmp(qf, &tm.bark.positions[3 * i], sizeof(qf)) == 0);
		}
		for (size_t i = 0; i < leaves.n; i++) {
			struct vec3 p = pos_of(&tm.leaves, i), q = live_grow_position(&g, front, &leaves.v[i], p);
			float qf[3] = { (float)q.x, (float)q.y, (float)q.z };

			CHECK(live_grow_visible(front, leaves.v[i].d));
			CHECK(live_grow_pull(&g, front, leaves.v[i].d) == 1.0);
			CHECK(memcmp(qf, &tm.leaves.positions[3 * i], sizeof(qf)) == 0);
		}
		checked_vertices += bark.n + leaves.n;
	}
	if (!quiet)
		printf("%-10s D_max %6.2f m  swell %.2f m  duration %.2f s  vertices %zu + %zu\n", name,
		       g.d_max, g.swell, g.duration, bark.n, leaves.n);
	live_attrs_finish(&leaves);
	live_attrs_finish(&bark);
	tree_mesh_marks_finish(&mk);
	tree_mesh_finish(&tm);
	live_skeleton_finish(&sk);
}

/* The pull: 0 at the front, rising, 1 exactly a swell behind it; not drawn beyond it. */
static void test_pull(void)
{
	struct live_skeleton sk = { .d_max = 10.0 };
	struct live_grow g;
	double prev = 0.0;
	struct live_vertex v = { .point = { 1.0f, 2.0f, 3.0f }, .d = 4.0f };
	struct vec3 p;

	live_grow_setup(&g, &sk);
	CHECK_NEAR(g.swell, LIVE_GROW_SWELL * 10.0, 1e-12);
	CHECK(live_grow_pull(&g, 4.0, 4.0) == 0.0);
	CHECK(!live_grow_visible(3.999, 4.0) && live_grow_visible(4.0, 4.0));
	for (int i = 0; i <= 100; i++) {
		double f = live_grow_pull(&g, 4.0 + g.swell * i / 100.0, 4.0);

		CHECK(f >= prev);
		prev = f;
	}
	CHECK(prev == 1.0);
	/* halfway through the swell a vertex is halfway in: from its skeleton point */
	p = live_grow_position(&g, 4.0 + 0.5 * g.swell, &v, vec3(3.0, 2.0, 3.0));
	CHECK_NEAR(p.x, 2.0, 1e-12);
	p = live_grow_position(&g, 4.0, &v, vec3(3.0, 2.0, 3.0));
	CHECK_NEAR(p.x, 1.0, 1e-12);
}

/* The unfolding keyframe is the pull's: floor(nframes f), nframes once f = 1. */
static void test_unfold(void)
{
	struct rng r;
	double bound[33];
	size_t near_change = 0;

	rng_seed(&r, 2626);
	for (int i = 0; i < 20000; i++) {
		unsigned nf = 1 + (unsigned)(rng_next(&r) % 32);
		double swell = rng_range(&r, 0.01, 3.0), front = rng_range(&r, 0.0, 25.0);
		double d = rng_range(&r, -0.5, 1.2) * front;
		struct live_skeleton sk = { .d_max = swell / LIVE_GROW_SWELL };
		struct live_grow g;
		unsigned k = live_grow_unfold_frame(front, swell, nf, d), lo = 0;
		double f, want;

		live_grow_setup(&g, &sk);
		CHECK_NEAR(g.swell, swell, 1e-9 * swell + 1e-12);
		g.swell = swell;
		f = live_grow_pull(&g, front, d);
		want = f >= 1.0 ? nf : floor(nf * f);
		live_grow_unfold_bounds(front, swell, nf, bound);
		CHECK(bound[0] == front);
		for (unsigned j = 0; j < nf; j++)
			CHECK(bound[j + 1] < bound[j]);
		/* the bounds say the same as the frame */
		while (lo < nf && d <= bound[lo + 1])
			lo++;
		CHECK(lo == k);
		if ((double)k != want) {
			/* only on a change, where rounding decides */
			double edge = fmin(fabs(nf * f - floor(nf * f + 0.5)), fabs(1.0 - f));

			CHECK(edge < 1e-9);
			near_change++;
		}
		/* the front runs on: the leaf opens further, never folds back */
		CHECK(live_grow_unfold_frame(front + 0.01 * swell, swell, nf, d) >= k);
	}
	printf("unfolding keyframes: 20000 random leaves as their pull says (%zu on a change)\n",
	       near_change);
}

int main(int argc, char **argv)
{
	struct tree t;
	struct rng r;
	int n = test_cases(RANDOM_TREES);

	CHECK(argc == 2);
	test_pull();
	test_unfold();
	tree_init(&t);
	live_trees_demo(&t, argv[1], false);
	check_tree("demo", &t, 1, false);
	live_trees_demo(&t, argv[1], true);
	check_tree("demo 3D", &t, 1, false);
	for (int p = 0; p < GEN_PRESET_COUNT; p++) {
		live_trees_preset(&t, (enum gen_preset)p);
		check_tree(gen_preset_name((enum gen_preset)p), &t, 1, false);
	}
	rng_seed(&r, 2626);
	for (int i = 0; i < n; i++) {
		int nb = 1 + (int)(rng_next(&r) % 100), leaves = (int)(rng_next(&r) % 4);

		live_trees_random(&t, nb, leaves, 5000 + (uint64_t)i, rng_range(&r, 1.0, 25.0));
		check_tree("random", &t, 5000 + (uint64_t)i, true);
	}
	tree_finish(&t);
	printf("%d random trees; %zu vertices settled to the bit; durations %.2f .. %.2f s\n", n,
	       checked_vertices, dur_lo, dur_hi);
	return 0;
}
