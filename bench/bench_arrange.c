/* SPDX-License-Identifier: MIT */
/*
 * Leaf arrangement (src/sketch/arrange.c) on one curved 3D branch of 1..20 m, sampled every 5 cm
 * as sketching samples it, with 40-point leaves:
 *   whorl-extend   an opposite pair at 0.3 m, a leaf at 0.6 m turned 90 degrees: to the tip
 *   spiral-extend  single leaves at 0.3 and 0.55 m, 137.5 degrees apart: to the tip
 *   whorl-add      one more leaf in the top whorl of a branch already full of pairs (the
 *                  result of whorl-extend), i.e. tapping again on a leafy branch
 *   suggest        arrange_suggest on that leafy branch
 *   previews       the thumbnails: suggest, then arrange_preview for each suggestion
 * Medians of REPS runs (the tree is rebuilt outside the timing); growth vs the previous
 * length as an exponent.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>

#include "arrange.h"
#include "bench_util.h"

#define REPS 9
#define LEAF_N 40
#define DEG (VEC_PI / 180.0)

static int leaf(struct tree *t, double s, double deg)
{
	const struct branch *br = &t->branches[0];
	double bt = s / tree_branch_length(br), a = deg * DEG;
	struct tree_frame f = tree_frame_at(br, bt);
	struct vec3 p[LEAF_N];
	int id;

	for (size_t j = 0; j < LEAF_N; j++) {
		double u = 2 * VEC_PI * (double)j / LEAF_N;
		double x = 0.12 * sin(u), r = 0.03 + 0.2 * (1 - cos(u));

		p[j] = vec3_add(f.origin, vec3_add(vec3_scale(f.tangent, x),
						   vec3_add(vec3_scale(f.normal, r * cos(a)),
							    vec3_scale(f.binormal, r * sin(a)))));
	}
	id = tree_add_leaf(t, 0, ORIGIN_SKETCH, p, LEAF_N);
	if (id < 0)
		return id;
	t->leaves[id].branch_t = bt;
	return tree_leaf_attach(t, (size_t)id);
}

enum what { WHORL_EXTEND, SPIRAL_EXTEND, WHORL_ADD, SUGGEST, PREVIEWS, NWHAT };
static const char *const what_names[NWHAT] = { "whorl-extend", "spiral-extend", "whorl-add",
					       "suggest", "previews" };

/* A curved 3D branch of about `len` metres, points 5 cm apart, and the leaves for `w`. */
static int build(struct tree *t, double len, enum what w)
{
	size_t n = (size_t)ceil(len / 0.05) + 1;
	struct vec3 p[402];
	double r[402] = { 0 };
	int ret;

	tree_init(t);
	if (n > 402)
		return -EINVAL;
	for (size_t i = 0; i < n; i++) {
		double y = len * (double)i / (double)(n - 1);

		/* bends in x and z, the arc a little longer than len */
		p[i] = vec3(0.2 * len * sin(0.3 * y / len * 6), 0.97 * y,
			    0.1 * len * (1 - cos(0.25 * y / len * 6)));
	}
	ret = tree_add_branch(t, -1, 0.0, ORIGIN_SKETCH, p, r, n);
	if (ret < 0)
		return ret;
	if (w == SPIRAL_EXTEND) {
		if ((ret = leaf(t, 0.3, 0)) < 0 || (ret = leaf(t, 0.55, 137.5)) < 0)
			return ret;
		return 0;
	}
	if ((ret = leaf(t, 0.3, 0)) < 0 || (ret = leaf(t, 0.3, 180)) < 0 ||
	    (ret = leaf(t, 0.6, 90)) < 0)
		return ret;
	if (w == WHORL_EXTEND)
		return 0;
	ret = arrange_apply(t, 0, ARRANGE_WHORL_EXTEND);
	return ret < 0 ? ret : 0;
}

/* Times w once on a fresh tree; *before, *after: its leaves. Seconds, or < 0 on error. */
static double run(enum what w, double len, size_t *before, size_t *after)
{
	struct tree t, out;
	unsigned mask;
	double t0, dt;
	int ret = build(&t, len, w);

	if (ret < 0) {
		tree_finish(&t);
		return ret;
	}
	*before = t.nleaves;
	t0 = bench_now();
	switch (w) {
	case WHORL_EXTEND:
		ret = arrange_apply(&t, 0, ARRANGE_WHORL_EXTEND);
		break;
	case SPIRAL_EXTEND:
		ret = arrange_apply(&t, 0, ARRANGE_SPIRAL_EXTEND);
		break;
	case WHORL_ADD:
		ret = arrange_apply(&t, 0, ARRANGE_WHORL_ADD);
		break;
	case SUGGEST:
		ret = arrange_suggest(&t, 0) ? 0 : -ENOENT;
		break;
	default:
		mask = arrange_suggest(&t, 0);
		for (int p = 0; ret >= 0 && p < ARRANGE_COUNT; p++) {
			if (!(mask & (1u << p)))
				continue;
			ret = arrange_preview(&t, 0, (enum arrange_pattern)p, &out);
			tree_finish(&out);
		}
		break;
	}
	dt = bench_now() - t0;
	*after = t.nleaves;
	tree_finish(&t);
	return ret < 0 ? ret : dt;
}

int main(int argc, char **argv)
{
	static const double lengths[] = { 1, 2, 5, 10, 20 };
	int reps;

	if (bench_init(&argc, argv, NULL))
		return 1;
	reps = bench_reps(REPS);
	printf("branch length in metres; leaves are 40-point outlines\n");
	for (int w = 0; w < NWHAT; w++) {
		double pn = 0, pt = 0, first = 0;

		for (size_t l = 0; l < BENCH_COUNT(lengths); l++) {
			double times[REPS];
			size_t before = 0, after = 0;
			char name[64];

			for (int r = 0; r < reps; r++) {
				times[r] = run((enum what)w, lengths[l], &before, &after);
				if (times[r] < 0) {
					fprintf(stderr, "%s on %g m: %d\n", what_names[w],
						lengths[l], (int)times[r]);
					return 1;
				}
			}
			snprintf(name, sizeof(name), "%s %zu -> %zu leaves", what_names[w], before,
				 after);
			bench_row(name, lengths[l], bench_median(times, (size_t)reps), &pn, &pt);
			if (l == 0)
				first = pt;
		}
		printf("growth %s 1 -> %g m: ~L^%.2f\n\n", what_names[w],
		       pn, log(pt / first) / log(pn));
	}
	return 0;
}
