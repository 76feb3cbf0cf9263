/* SPDX-License-Identifier: MIT */
/*
 * The wind (src/live/live_wind.c, docs/living-trees.md, "Tests and figures"), on the demo
 * (as drawn and in 3D), the six presets, a 15 m tree and a few hundred seeded random trees
 * 5 to 15 m tall, at the default breeze:
 *
 * - the foot is fixed: a trunk's first point's offset is exactly 0 at every time;
 * - joints are closed: a branch's base moves as its parent's point at parent_t, within 1%
 *   of its base radius, at 200 times over the loop;
 * - the loop is seamless (offset(t) = offset(t + T_loop), T_loop <= 8 s), and the weights'
 *   first and last keyframes (u = 0 and 1) are equal to the bit;
 * - the trunk's period, measured as the dominant period of its top's offset, lies in
 *   [1, 6] s and grows with the tree's height (5, 6, ..., 15 m);
 * - the trunk's top moves at most 3% of H at the default strength (max over the loop);
 * - a branch's tip moves at least as much as the point it sits on, a leaf's farthest
 *   vertex at least as much as its anchor, measured as the root mean square of |offset|
 *   over the loop (which holds by construction: the bands run at different harmonics, so
 *   their motions add in power, and each band's weight never shrinks along a chain). The
 *   peak over the loop, which the brief named, cannot hold for every phase (cos t - 0.1
 *   cos 3t peaks at 0.9 < 1): it is measured and printed, not asserted;
 * - what a twig (a branch entering band 3) adds past where it leaves its parent's bark,
 *   and what a leaf adds, have a higher dominant frequency than the point they sit on (and
 *   their band's own);
 * - the decomposition into morph targets sums to the offset within 1e-9 m;
 * - strength 0 is still, out-of-range parameters are refused; the seed makes the phases.
 *
 * It prints the worst margins.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "live.h"
#include "live_trees.h"
#include "mesh.h"
#include "rng.h"
#include "test.h"

#define SAMPLES 256 /* a loop's samples: dominant frequencies up to 128 cycles a loop */
#define JOINT_TIMES 200
#define RANDOM_TREES 300

static const char *data_dir;

struct worst {
	double joint;       /* gap / base radius */
	double top;         /* trunk top's amplitude / H */
	double tip_rms, leaf_rms; /* least rms|tip| / rms|base|, rms|leaf vertex| / rms|anchor| */
	double tip_ratio;   /* least max|tip| / max|base| */
	double leaf_ratio;  /* least max|leaf vertex| / max|anchor| */
	size_t tip_dips, leaf_dips; /* peaks below the base's */
	double decomp;      /* largest |sum - offset| */
	double loop;        /* largest |offset(t) - offset(t + T)| */
	size_t twigs, leaves, joints, trees;
	const char *top_tree;
};

static struct worst worst = { .tip_ratio = INFINITY, .leaf_ratio = INFINITY,
			      .tip_rms = INFINITY, .leaf_rms = INFINITY };

static double len(struct vec3 v)
{
	return vec3_len(v);
}

/* A vertex's offsets over the loop, SAMPLES of them. */
static void sample(const struct live_wind *w, const struct live_vertex *v, struct vec3 *out)
{
	for (int i = 0; i < SAMPLES; i++)
		out[i] = live_wind_offset(w, v, w->loop * i / SAMPLES);
}

static double rms(const struct vec3 *x)
{
	double m = 0.0;

	for (int i = 0; i < SAMPLES; i++)
		m += vec3_dot(x[i], x[i]);
	return sqrt(m / SAMPLES);
}

static double max_len(const struct vec3 *x)
{
	double m = 0.0;

	for (int i = 0; i < SAMPLES; i++)
		m = fmax(m, len(x[i]));
	return m;
}

static void diff(const struct vec3 *a, const struct vec3 *b, struct vec3 *out)
{
	for (int i = 0; i < SAMPLES; i++)
		out[i] = vec3_sub(a[i], b[i]);
}

static struct live_vertex at(const struct live_skeleton *sk, const struct tree *t, size_t b,
			     double s)
{
	struct live_vertex v;

	CHECK(live_skeleton_vertex(sk, t, b, s, &v));
	return v;
}

/* The decomposition at a vertex: sum_j g_j(t) T_j(v) = offset(v, t) at many t. */
static void check_decomposition(const struct live_wind *w, const struct live_vertex *v,
				struct rng *r)
{
	struct vec3 tg[LIVE_WIND_TARGETS];

	live_wind_targets(w, v, tg);
	for (int i = 0; i < 16; i++) {
		double t = rng_range(r, -3.0 * w->loop, 5.0 * w->loop), g[LIVE_WIND_TARGETS];
		struct vec3 sum = vec3(0, 0, 0), o = live_wind_offset(w, v, t);

		live_wind_weights(w, t, g);
		for (int j = 0; j < LIVE_WIND_TARGETS; j++) {
			CHECK(fabs(g[j]) <= 1.0);
			sum = vec3_add(sum, vec3_scale(tg[j], g[j]));
		}
		worst.decomp = fmax(worst.decomp, vec3_dist(sum, o));
		CHECK(vec3_dist(sum, o) <= 1e-9);
		worst.loop = fmax(worst.loop, vec3_dist(o, live_wind_offset(w, v, t + w->loop)));
		CHECK(vec3_dist(o, live_wind_offset(w, v, t + w->loop)) <= 1e-9);
	}
}

/* The leaves' mesh of t bound: each leaf's vertex farthest from its anchor against it. */
static void check_leaves(const struct live_skeleton *sk, const struct live_wind *w,
			 const struct tree *t, struct rng *r)
{
	struct tree_mesh tm;
	struct tree_mesh_marks mk;
	struct live_attrs a;
	struct vec3 *x = malloc(3 * SAMPLES * sizeof(*x)), *y = x + SAMPLES, *d = y + SAMPLES;

	CHECK(x);
	tree_mesh_init(&tm);
	tree_mesh_marks_init(&mk);
	live_attrs_init(&a);
	CHECK_INT(tree_mesh_build_marked(&tm, t, &mk), 0);
	CHECK_INT(live_attrs_bind_leaves(&a, sk, t, &tm.leaves, &mk), 0);
	CHECK(a.n == tm.leaves.nvertices);
	for (size_t l = 0; l < t->nleaves; l++) {
		size_t v0 = mk.leaves[l].nvertices, v1 = mk.leaves[l + 1].nvertices, far = v0;
		struct live_vertex anchor;
		const struct leaf *lf = &t->leaves[l];
		int fa, fl;

		if (v0 == v1)
			continue;
		for (size_t i = v0; i < v1; i++)
			if (a.v[i].leaf > a.v[far].leaf)
				far = i;
		anchor = a.v[far];
		anchor.leaf = 0.0f;
		/* the anchor is the leaf's branch point, and every vertex shares it */
		{
			struct live_vertex on = at(sk, t, (size_t)lf->branch,
						   lf->branch_t * sk->branches[lf->branch].length);

			CHECK(memcmp(on.point, anchor.point, sizeof(on.point)) == 0);
			CHECK(on.d == anchor.d);
		}
		sample(w, &a.v[far], x);
		sample(w, &anchor, y);
		diff(x, y, d);
		worst.leaf_rms = fmin(worst.leaf_rms, rms(x) / fmax(rms(y), 1e-300));
		CHECK(rms(x) >= rms(y) * (1 - 1e-12));
		worst.leaf_ratio = fmin(worst.leaf_ratio, max_len(x) / fmax(max_len(y), 1e-300));
		worst.leaf_dips += max_len(x) < max_len(y);
		/* what the leaf adds flutters faster than its anchor moves */
		fl = live_trees_dominant(d, SAMPLES);
		fa = live_trees_dominant(y, SAMPLES);
		CHECK_INT(fl, w->harmonic[LIVE_BANDS]);
		CHECK(fl > fa);
		if (l % 7 == 0)
			check_decomposition(w, &a.v[far], r);
		worst.leaves++;
	}
	live_attrs_finish(&a);
	tree_mesh_marks_finish(&mk);
	tree_mesh_finish(&tm);
	free(x);
}

/* Every property on one tree at the default breeze (and wind from `angle`). */
static void check_tree(const char *name, const struct tree *t, double angle, uint64_t seed,
		       bool quiet)
{
	struct live_wind_params p = { .strength = LIVE_WIND_DEFAULT_STRENGTH, .angle = angle };
	struct live_skeleton sk;
	struct live_wind w;
	struct rng r;
	struct vec3 *x = malloc(4 * SAMPLES * sizeof(*x)), *y = x + SAMPLES, *d = y + SAMPLES,
		    *e = d + SAMPLES;
	double top_amp = 0.0;

	CHECK(x);
	rng_seed(&r, seed);
	CHECK_INT(live_skeleton_init(&sk, t, seed), 0);
	CHECK_INT(live_wind_setup(&w, &sk, &p), 0);
	CHECK(w.loop <= LIVE_WIND_LOOP_MAX_S && w.loop >= w.period);
	{
		double g0[LIVE_WIND_TARGETS], g1[LIVE_WIND_TARGETS];

		live_wind_weights_at(&w, 0.0, g0);
		live_wind_weights_at(&w, 1.0, g1);
		CHECK(memcmp(g0, g1, sizeof(g0)) == 0);
	}

	for (size_t b = 0; b < t->nbranches; b++) {
		const struct branch *br = &t->branches[b];
		const struct live_branch *lb = &sk.branches[b];
		struct live_vertex base = at(&sk, t, b, 0.0), tip = at(&sk, t, b, lb->length);

		if (br->parent < 0) {
			/* the foot: exactly still */
			for (int i = 0; i < JOINT_TIMES; i++) {
				struct vec3 o = live_wind_offset(&w, &base, w.loop * i / JOINT_TIMES);

				CHECK(o.x == 0.0 && o.y == 0.0 && o.z == 0.0);
			}
			if (b == 0) {
				sample(&w, &tip, x);
				top_amp = max_len(x);
			}
			check_decomposition(&w, &tip, &r);
			continue;
		}
		/* the joint: the base against the parent's point at parent_t */
		{
			size_t pi = (size_t)br->parent;
			struct live_vertex pv = at(&sk, t, pi, br->parent_t * sk.branches[pi].length);
			double rad = br->radii[0];

			for (int i = 0; i < JOINT_TIMES; i++) {
				double tt = w.loop * i / JOINT_TIMES;
				double gap = vec3_dist(live_wind_offset(&w, &base, tt),
						       live_wind_offset(&w, &pv, tt));

				worst.joint = fmax(worst.joint, gap / rad);
				CHECK(gap <= 0.01 * rad);
			}
			worst.joints++;
		}
		/* the tip against the point it sits on */
		sample(&w, &tip, x);
		sample(&w, &base, y);
		worst.tip_rms = fmin(worst.tip_rms, rms(x) / fmax(rms(y), 1e-300));
		CHECK(rms(x) >= rms(y) * (1 - 1e-12));
		worst.tip_ratio = fmin(worst.tip_ratio, max_len(x) / fmax(max_len(y), 1e-300));
		worst.tip_dips += max_len(x) < max_len(y);
		/* a twig (a branch entering band 3): what it adds past where it leaves its
		 * parent's bark is faster than where it sits moves (one wholly inside its parent
		 * adds nothing) */
		if (lb->band == 3 && sk.branches[br->parent].band < 3 && lb->length - lb->exit > 1e-3) {
			struct live_vertex out = at(&sk, t, b, lb->exit);
			int fb, fp;

			sample(&w, &out, e);
			diff(x, e, d);
			fb = live_trees_dominant(d, SAMPLES);
			fp = live_trees_dominant(y, SAMPLES);
			CHECK_INT(fb, w.harmonic[lb->band]);
			CHECK(fb > fp);
			worst.twigs++;
		}
		if (b % 5 == 0)
			check_decomposition(&w, &tip, &r);
	}
	/* the trunk's top: at most 3% of H */
	worst.top = fmax(worst.top, top_amp / sk.height);
	if (top_amp / sk.height >= worst.top)
		worst.top_tree = name;
	CHECK(top_amp <= 0.03 * sk.height);
	check_leaves(&sk, &w, t, &r);
	if (!quiet)
		printf("%-12s H %6.2f m  P0 %.2f s  loop %.2f s  harmonics %d %d %d %d %d  bands "
		       "%zu/%zu/%zu/%zu  trunk top %.4f m (%.2f%% of H)\n",
		       name, sk.height, w.period, w.loop, w.harmonic[0], w.harmonic[1], w.harmonic[2],
		       w.harmonic[3], w.harmonic[4], sk.counts[0], sk.counts[1], sk.counts[2],
		       sk.counts[3], top_amp, 100.0 * top_amp / sk.height);
	worst.trees++;
	live_skeleton_finish(&sk);
	free(x);
}

/* The trunk's period, measured: the dominant period of its top's offset. */
static double measured_period(const struct tree *t, double *formula)
{
	struct live_wind_params p = { .strength = LIVE_WIND_DEFAULT_STRENGTH, .angle = 0.0 };
	struct live_skeleton sk;
	struct live_wind w;
	struct vec3 x[SAMPLES];
	struct live_vertex top;

	CHECK_INT(live_skeleton_init(&sk, t, 1), 0);
	CHECK_INT(live_wind_setup(&w, &sk, &p), 0);
	top = at(&sk, t, 0, sk.branches[0].length);
	sample(&w, &top, x);
	*formula = w.period;
	live_skeleton_finish(&sk);
	return w.loop / live_trees_dominant(x, SAMPLES);
}

static void test_periods(void)
{
	struct tree t;
	double prev = 0.0;

	tree_init(&t);
	for (int h = 5; h <= 15; h++) {
		double formula, period;

		live_trees_random(&t, 40, 0, 100 + (uint64_t)h, h);
		period = measured_period(&t, &formula);
		printf("trunk period at H %2d m: %.3f s measured (formula %.3f s)\n", h, period, formula);
		CHECK_NEAR(period, formula, 1e-9);
		CHECK(period >= 1.0 && period <= 6.0);
		CHECK(period > prev);
		prev = period;
	}
	tree_finish(&t);
}

/* Strength scales every offset; 0 is still; out of range is refused. */
static void test_strength(void)
{
	struct tree t;
	struct live_skeleton sk;
	struct live_wind w0, w1, wd;
	struct live_wind_params still = { .strength = 0.0, .angle = 0.3 },
				full = { .strength = 1.0, .angle = 0.3 },
				bad = { .strength = 1.5, .angle = 0.0 },
				nan_angle = { .strength = 0.5, .angle = NAN };
	struct live_vertex top;
	double amp1 = 0.0;

	tree_init(&t);
	live_trees_random(&t, 30, 2, 5, 10.0);
	CHECK_INT(live_skeleton_init(&sk, &t, 5), 0);
	CHECK_INT(live_wind_setup(&w0, &sk, &still), 0);
	CHECK_INT(live_wind_setup(&w1, &sk, &full), 0);
	CHECK_INT(live_wind_setup(&wd, &sk, &bad), -EINVAL);
	CHECK_INT(live_wind_setup(&wd, &sk, &nan_angle), -EINVAL);
	top = at(&sk, &t, 0, sk.branches[0].length);
	for (int i = 0; i < SAMPLES; i++) {
		struct vec3 o = live_wind_offset(&w0, &top, w0.loop * i / SAMPLES);

		CHECK(o.x == 0 && o.y == 0 && o.z == 0);
		amp1 = fmax(amp1, len(live_wind_offset(&w1, &top, w1.loop * i / SAMPLES)));
	}
	printf("trunk top at strength 1: %.2f%% of H\n", 100.0 * amp1 / sk.height);
	CHECK(amp1 <= LIVE_WIND_TRUNK_SWAY * sk.height * (1 + 1e-12));
	live_skeleton_finish(&sk);
	tree_finish(&t);
}

/* The phases come from the seed: the same seed gives the same skeleton, another seed
 * other phases (and the same bands and weights). */
static void test_seed(void)
{
	struct tree t;
	struct live_skeleton a, b, c;
	size_t differ = 0;

	tree_init(&t);
	live_trees_random(&t, 80, 3, 9, 8.0);
	CHECK_INT(live_skeleton_init(&a, &t, 11), 0);
	CHECK_INT(live_skeleton_init(&b, &t, 11), 0);
	CHECK_INT(live_skeleton_init(&c, &t, 12), 0);
	CHECK(memcmp(a.branches, b.branches, t.nbranches * sizeof(*a.branches)) == 0);
	CHECK(memcmp(a.leaf_phase, b.leaf_phase, t.nleaves) == 0);
	for (size_t i = 0; i < t.nbranches; i++) {
		CHECK(a.branches[i].band == c.branches[i].band);
		CHECK(memcmp(a.branches[i].wb, c.branches[i].wb, sizeof(a.branches[i].wb)) == 0);
		differ += memcmp(a.branches[i].phase, c.branches[i].phase, LIVE_BANDS) != 0;
	}
	CHECK(differ > t.nbranches / 2);
	live_skeleton_finish(&c);
	live_skeleton_finish(&b);
	live_skeleton_finish(&a);
	tree_finish(&t);
}

/* A check of one tree: its name, the wind's angle, the seed of its phases. */
typedef void (*tree_check)(const char *name, const struct tree *t, double angle, uint64_t seed,
			   bool quiet);

/* The trees every property runs on: the demo (as drawn, in 3D), the presets, a 15 m tree
 * and `n` seeded random trees of 2..121 branches, 5..15 m. */
static void each_tree(tree_check check, int n)
{
	struct tree t;
	struct rng r;

	tree_init(&t);
	live_trees_demo(&t, data_dir, false);
	check("demo", &t, 0.0, 1, false);
	live_trees_demo(&t, data_dir, true);
	check("demo 3D", &t, 0.0, 1, false);
	for (int p = 0; p < GEN_PRESET_COUNT; p++) {
		live_trees_preset(&t, (enum gen_preset)p);
		check(gen_preset_name((enum gen_preset)p), &t, 0.0, 1, false);
	}
	live_trees_random(&t, 62, 10, 15, 15.0);
	check("15 m tree", &t, 0.0, 15, false);

	rng_seed(&r, 26);
	for (int i = 0; i < n; i++) {
		int nb = 2 + (int)(rng_next(&r) % 120), leaves = (int)(rng_next(&r) % 5);
		double h = rng_range(&r, 5.0, 15.0), angle = rng_range(&r, -VEC_PI, VEC_PI);

		live_trees_random(&t, nb, leaves, 1000 + (uint64_t)i, h);
		check("random", &t, angle, 1000 + (uint64_t)i, true);
	}
	tree_finish(&t);
}

/* What the common loop showed. */
static struct {
	double loop;        /* largest |offset(t) - offset(t + 8 s)| */
	double period;      /* largest |trunk's period - P0| / P0, trees 5..15 m tall */
	double period_h;    /* that tree's height */
	double joint;       /* largest gap / base radius */
	size_t trees, in_range, joints, points;
} common;

/* How far apart every tip (of a branch; of a leaf 5 cm from its anchor) is at t and at
 * t + period, at 8 seeded times each: the largest distance. */
static double loop_error(const struct live_skeleton *sk, const struct live_wind *w,
			 const struct tree *t, double period, struct rng *r)
{
	double err = 0.0;

	for (size_t i = 0; i < t->nbranches + t->nleaves; i++) {
		struct live_vertex v;

		if (i < t->nbranches) {
			v = at(sk, t, i, sk->branches[i].length);
		} else {
			CHECK(live_skeleton_leaf(sk, t, i - t->nbranches, vec3(0.36, 0.8, 0.48), &v));
			v.leaf = 0.05f;
		}
		for (int k = 0; k < 8; k++) {
			double tt = rng_range(r, -3.0 * period, 5.0 * period);

			err = fmax(err, vec3_dist(live_wind_offset(w, &v, tt),
						  live_wind_offset(w, &v, tt + period)));
		}
		common.points++;
	}
	return err;
}

/*
 * The common loop (the forest's, LIVE_WIND_COMMON_LOOP_S = 8 s) on one tree: the loop is
 * exactly 8 s and the motion repeats in it; the trunk sways at 8 s / n, n the whole number
 * nearest 8 s / P0, within 20% of P0 on a tree 5 to 15 m tall; the harmonics rise as the
 * tree's own rule makes them; the foot still and the joints closed as with the tree's own
 * loop; the targets (what an export stores) the same as with its own loop.
 */
static void check_loop(const char *name, const struct tree *t, double angle, uint64_t seed,
		       bool quiet)
{
	struct live_wind_params own = { .strength = LIVE_WIND_DEFAULT_STRENGTH, .angle = angle };
	struct live_wind_params p = own;
	struct live_skeleton sk;
	struct live_wind w, wo;
	struct live_vertex top;
	struct vec3 x[SAMPLES];
	struct rng r;
	double period, err;
	long n;

	p.loop = LIVE_WIND_COMMON_LOOP_S;
	rng_seed(&r, seed);
	CHECK_INT(live_skeleton_init(&sk, t, seed), 0);
	CHECK_INT(live_wind_setup(&w, &sk, &p), 0);
	CHECK_INT(live_wind_setup(&wo, &sk, &own), 0);
	CHECK(w.loop == 8.0);
	CHECK(w.period == wo.period);
	n = lround(8.0 / w.period);
	CHECK_INT(w.harmonic[0], n < 1 ? 1 : n);
	for (int k = 1; k <= LIVE_BANDS; k++) {
		CHECK(w.harmonic[k] > w.harmonic[k - 1]);
		CHECK(w.harmonic[k] != 2 * w.harmonic[0]);
	}
	CHECK(w.amp0 == wo.amp0 && w.amp_leaf == wo.amp_leaf);
	CHECK(memcmp(w.amp, wo.amp, sizeof(w.amp)) == 0);
	{
		double g0[LIVE_WIND_TARGETS], g1[LIVE_WIND_TARGETS];

		live_wind_weights_at(&w, 0.0, g0);
		live_wind_weights_at(&w, 1.0, g1);
		CHECK(memcmp(g0, g1, sizeof(g0)) == 0);
	}

	/* repeats in exactly 8 s */
	err = loop_error(&sk, &w, t, 8.0, &r);
	common.loop = fmax(common.loop, err);
	CHECK(err <= 1e-9);

	/* the trunk's period, measured as the dominant period of its top's offset */
	top = at(&sk, t, 0, sk.branches[0].length);
	for (int i = 0; i < SAMPLES; i++)
		x[i] = live_wind_offset(&w, &top, 8.0 * i / SAMPLES);
	CHECK_INT(live_trees_dominant(x, SAMPLES), w.harmonic[0]);
	period = 8.0 / live_trees_dominant(x, SAMPLES);
	if (sk.height >= 5.0 && sk.height <= 15.0) {
		double off = fabs(period - w.period) / w.period;

		if (off > common.period) {
			common.period = off;
			common.period_h = sk.height;
		}
		CHECK(off <= 0.2);
		common.in_range++;
	}

	for (size_t b = 0; b < t->nbranches; b++) {
		const struct branch *br = &t->branches[b];
		struct live_vertex base = at(&sk, t, b, 0.0), pv;
		struct vec3 tg[LIVE_WIND_TARGETS], tgo[LIVE_WIND_TARGETS];

		/* the targets do not depend on the loop */
		live_wind_targets(&w, &base, tg);
		live_wind_targets(&wo, &base, tgo);
		CHECK(memcmp(tg, tgo, sizeof(tg)) == 0);
		if (br->parent < 0) {
			/* the foot: exactly still */
			for (int i = 0; i < JOINT_TIMES; i++) {
				struct vec3 o = live_wind_offset(&w, &base, 8.0 * i / JOINT_TIMES);

				CHECK(o.x == 0.0 && o.y == 0.0 && o.z == 0.0);
			}
			continue;
		}
		pv = at(&sk, t, (size_t)br->parent,
			br->parent_t * sk.branches[br->parent].length);
		for (int i = 0; i < JOINT_TIMES; i++) {
			double tt = 8.0 * i / JOINT_TIMES;
			double gap = vec3_dist(live_wind_offset(&w, &base, tt),
					       live_wind_offset(&w, &pv, tt));

			common.joint = fmax(common.joint, gap / br->radii[0]);
			CHECK(gap <= 0.01 * br->radii[0]);
		}
		common.joints++;
	}
	if (!quiet)
		printf("%-12s H %6.2f m  P0 %.2f s  in 8 s: trunk %.3f s (%+.1f%%), harmonics "
		       "%d %d %d %d %d\n",
		       name, sk.height, w.period, period, 100.0 * (period / w.period - 1.0),
		       w.harmonic[0], w.harmonic[1], w.harmonic[2], w.harmonic[3], w.harmonic[4]);
	common.trees++;
	live_skeleton_finish(&sk);
}

/* The common loop on the same trees; loops out of bounds refused. */
static void test_common_loop(int n)
{
	static const double bad[] = { -1.0, 0.5, 60.5, NAN, INFINITY };
	struct live_wind_params p = { .strength = LIVE_WIND_DEFAULT_STRENGTH };
	struct live_skeleton sk;
	struct live_wind w;
	struct tree t;

	each_tree(check_loop, n);
	printf("common loop of 8 s: %zu trees, %zu points: repeats in 8 s within %.3g m (limit "
	       "1e-9); the trunk's period off P0 by at most %.1f%% (a %.2f m tree; %zu trees 5 "
	       "to 15 m, limit 20%%); %zu joints, worst gap %.3g of the base radius\n",
	       common.trees, common.points, common.loop, 100.0 * common.period, common.period_h,
	       common.in_range, common.joints, common.joint);
	tree_init(&t);
	live_trees_random(&t, 10, 1, 3, 9.0);
	CHECK_INT(live_skeleton_init(&sk, &t, 3), 0);
	for (size_t i = 0; i < sizeof(bad) / sizeof(*bad); i++) {
		p.loop = bad[i];
		CHECK_INT(live_wind_setup(&w, &sk, &p), -EINVAL);
	}
	/* the bounds themselves are loops */
	p.loop = LIVE_WIND_COMMON_LOOP_MIN_S;
	CHECK_INT(live_wind_setup(&w, &sk, &p), 0);
	CHECK(w.loop == LIVE_WIND_COMMON_LOOP_MIN_S && w.harmonic[0] == 1);
	p.loop = LIVE_WIND_COMMON_LOOP_MAX_S;
	CHECK_INT(live_wind_setup(&w, &sk, &p), 0);
	CHECK(w.loop == LIVE_WIND_COMMON_LOOP_MAX_S);
	live_skeleton_finish(&sk);
	tree_finish(&t);
}

int main(int argc, char **argv)
{
	int n = test_cases(RANDOM_TREES);

	CHECK(argc == 2);
	data_dir = argv[1];
	each_tree(check_tree, n);
	printf("%zu trees (%d random), %zu joints, %zu twigs, %zu leaves\n",
	       worst.trees, n, worst.joints, worst.twigs, worst.leaves);
	printf("worst joint gap: %.3g of the base radius (limit 0.01)\n", worst.joint);
	printf("worst trunk top: %.3f%% of H (%s; limit 3%%)\n", 100.0 * worst.top, worst.top_tree);
	printf("least rms tip / base: %.4f; least rms leaf / anchor: %.4f (limit 1)\n",
	       worst.tip_rms, worst.leaf_rms);
	printf("peaks (not asserted): least tip / base %.4f, below 1 at %zu of %zu tips; least "
	       "leaf / anchor %.4f, below 1 at %zu of %zu leaves\n",
	       worst.tip_ratio, worst.tip_dips, worst.joints, worst.leaf_ratio, worst.leaf_dips,
	       worst.leaves);
	printf("decomposition: %.3g m; loop: %.3g m (limit 1e-9)\n", worst.decomp, worst.loop);
	test_periods();
	test_strength();
	test_seed();
	test_common_loop(n);
	return 0;
}
