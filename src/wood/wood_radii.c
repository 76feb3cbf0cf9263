/* SPDX-License-Identifier: MIT */
/*
 * Step 1 of growing wood (seed 002, docs/wood.md "Step 1"): the radii by the paper's power
 * law, d^a = d1^a + d2^a (a = 2.5, the constant-stress model's), from the tips down.
 */
#include <errno.h>
#include <math.h>
#include <stdlib.h>

#include "wood.h"

/* Arc-length parameter (0..1) of each point of b, into t. */
static void params(const struct branch *b, double *t)
{
	double len = tree_branch_length(b), s = 0.0;

	t[0] = 0.0;
	for (size_t k = 1; k < b->npoints; k++) {
		s += vec3_dist(b->points[k - 1], b->points[k]);
		t[k] = len > 0.0 ? s / len : 1.0;
	}
}

/* The point below where a child at parent_t joins: the segment (t[k], t[k + 1]] it is on
 * (parent_t 0: point 0). */
static size_t point_below(const double *t, size_t n, double parent_t)
{
	size_t k = 0;

	while (k + 2 < n && parent_t > t[k + 1])
		k++;
	return k;
}

int wood_power_law(struct tree *t, double a)
{
	size_t most = 1;
	double *tp, *sum, *r;
	int ret = 0;

	for (size_t i = 0; i < t->nbranches; i++)
		most = t->branches[i].npoints > most ? t->branches[i].npoints : most;
	tp = malloc(most * sizeof(*tp));
	sum = malloc(t->nbranches * most * sizeof(*sum) + 1);
	r = malloc(most * sizeof(*r));
	if (!tp || !sum || !r) {
		ret = -ENOMEM;
		goto out;
	}
	for (size_t i = 0; i < t->nbranches * most; i++)
		sum[i] = 0.0;
	/* children come after their parents: each branch is done before its parent needs it */
	for (size_t i = t->nbranches; i-- > 0;) {
		struct branch *b = &t->branches[i];
		double *below = sum + i * most;
		size_t n = b->npoints;

		if (n == 0)
			continue;
		/* the tip keeps its drawn radius; between forks, the drawn taper */
		r[n - 1] = b->radii[n - 1];
		for (size_t k = n - 1; k-- > 0;) {
			if (below[k] > 0.0)
				r[k] = pow(pow(r[k + 1], a) + below[k], 1.0 / a);
			else
				r[k] = b->radii[k + 1] > 0.0 ? r[k + 1] * (b->radii[k] / b->radii[k + 1])
							     : r[k + 1];
		}
		for (size_t k = 0; k < n; k++)
			b->radii[k] = r[k];
		if (b->parent >= 0 && (size_t)b->parent < i) {
			const struct branch *p = &t->branches[b->parent];

			params(p, tp);
			sum[(size_t)b->parent * most + point_below(tp, p->npoints, b->parent_t)] +=
				pow(r[0], a);
		}
	}
out:
	free(tp);
	free(sum);
	free(r);
	return ret;
}
