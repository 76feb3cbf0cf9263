/* SPDX-License-Identifier: MIT */
/* The lsystem's angles: between a parent and its children (MakeTree's theta), and round the
 * parent's axis (spread). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "gen_check.h"

/* Directions from points rounded to micrometres over branches a centimetre long and more */
#define ANGLE_TOL_DEG 0.01

/* gen_check angles MIN MAX RANDOMNESS COVER SKEL... */
int check_angles(int argc, char **argv)
{
	double lo, hi, seen_lo = INFINITY, seen_hi = -INFINITY;
	size_t n = 0;

	if (argc < 5)
		return 2;
	{
		double min = atof(argv[0]), max = atof(argv[1]), r = atof(argv[2]);
		double mid = 0.5 * (min + max), half = 0.5 * r * (max - min);

		lo = mid - half;
		hi = mid + half;
	}
	for (int f = 4; f < argc; f++) {
		struct skel s;

		load_skel(argv[f], &s);
		for (size_t i = 0; i < s.nbranches; i++) {
			const struct skel_branch *b = &s.branches[i];
			double dp[3], dc[3], a;

			if (b->parent < 0)
				continue;
			skel_direction(&s.branches[b->parent], dp);
			skel_direction(b, dc);
			a = angle_deg(dp, dc);
			if (a < lo - ANGLE_TOL_DEG || a > hi + ANGLE_TOL_DEG)
				bad("%s: branch %zu leaves its parent at %.4f degrees, outside [%g, %g]", argv[f], i,
				    a, lo, hi);
			seen_lo = fmin(seen_lo, a);
			seen_hi = fmax(seen_hi, a);
			n++;
		}
		skel_free(&s);
	}
	if (n == 0)
		bad("no children to measure");
	printf("angles: %zu children of %d trees within [%.3f, %.3f]; wanted [%g, %g]\n", n, argc - 4,
	       seen_lo, seen_hi, lo, hi);
	if (atof(argv[3]) > 0) {
		double slack = atof(argv[3]) * (hi - lo);

		/* a rule spreading them over the whole range comes near both ends */
		if (seen_lo > lo + slack || seen_hi < hi - slack)
			bad("the angles cover [%.3f, %.3f] of [%g, %g]: not within %g degrees of its ends",
			    seen_lo, seen_hi, lo, hi, slack);
	}
	return finish("angles");
}

/* gen_check spread SPREAD SKEL */
int check_spread(int argc, char **argv)
{
	struct skel s;
	double spread, worst = 0;
	int *last;
	size_t pairs = 0;

	if (argc != 2)
		return 2;
	spread = atof(argv[0]);
	load_skel(argv[1], &s);
	last = malloc((s.nbranches + 1) * sizeof(int));
	if (!last)
		return 2;
	for (size_t i = 0; i < s.nbranches; i++)
		last[i] = -1; /* each branch's child seen last */
	/* every pair of neighbouring siblings: SPREAD apart about the parent's axis */
	for (size_t i = 1; i < s.nbranches; i++) {
		const struct skel_branch *b = &s.branches[i];
		double d[3], c0[3], c1[3], diff;
		int prev = last[b->parent];

		last[b->parent] = (int)i;
		if (prev < 0)
			continue;
		skel_direction(&s.branches[b->parent], d);
		skel_direction(&s.branches[prev], c0);
		skel_direction(b, c1);
		diff = fabs(remainder(azimuth_deg(c0, c1, d) - spread, 360));
		worst = fmax(worst, diff);
		pairs++;
		if (diff > 1)
			bad("branches %d and %zu: %.3f degrees apart round their parent, want %g", prev, i,
			    azimuth_deg(c0, c1, d), spread);
	}
	/* the paper's alpha: at a vertical trunk's foot, between the ground projections of its
	 * first two children's ends */
	{
		const struct skel_branch *t = &s.branches[0];
		double up[3] = { 0, 1, 0 }, dt[3], a[3], b[3], alpha;
		int first = -1, second = -1;

		for (size_t i = 1; i < s.nbranches && second < 0; i++)
			if (s.branches[i].parent == 0)
				*(first < 0 ? &first : &second) = (int)i;
		skel_direction(t, dt);
		if (s.nbranches == 0 || second < 0 || angle_deg(dt, up) > 1e-6) {
			bad("no vertical trunk with two children");
			free(last);
			skel_free(&s);
			return finish("spread");
		}
		for (int k = 0; k < 3; k++) {
			const struct skel_branch *c = &s.branches[first], *e = &s.branches[second];

			a[k] = c->points[c->npoints - 1][k] - t->points[0][k];
			b[k] = e->points[e->npoints - 1][k] - t->points[0][k];
		}
		a[1] = b[1] = 0;
		alpha = azimuth_deg(a, b, up);
		if (fabs(remainder(alpha - spread, 360)) > 1)
			bad("at the trunk's foot the first two children's ends are %.3f degrees apart, "
			    "want %g", alpha, spread);
		printf("spread: alpha %.4f degrees (want %g); %zu sibling pairs within %.2g degrees\n", alpha,
		       spread, pairs, worst);
	}
	free(last);
	skel_free(&s);
	return finish("spread");
}
