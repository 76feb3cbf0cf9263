/* SPDX-License-Identifier: MIT */
/*
 * The forest's layout (src/forest/forest_layout.c, docs/forest.md "Where they stand"), on
 * 500 seeded random forests (1 to 60 trees of 0.2 to 30 m crowns, numbers anywhere in a
 * long day, max 1 to 60):
 *
 * - no two trunks closer than the sum of a third of their crowns' widths (the issue's
 *   test), nor than FOREST_GAP times it (the layout's own rule), and the scale the least
 *   that holds (one pair exactly at it, or the minimum scale);
 * - deterministic, and a tree's place moves only with the scale: the same slot for the
 *   same number, its direction from the centre the same whatever else stands;
 * - two trees in one slot, a bad width and more trees than slots are refused.
 */
#include <math.h>
#include <stdio.h>

#include "forest.h"
#include "rng.h"
#include "test.h"

#define MAXN 60

int main(void)
{
	struct rng r;
	int cases = test_cases(500);
	double worst = INFINITY;
	size_t pairs = 0;

	rng_seed(&r, 2727);
	for (int c = 0; c < cases; c++) {
		size_t max = 1 + (size_t)(rng_next(&r) % MAXN), n = 1 + (size_t)(rng_next(&r) % max);
		uint64_t numbers[MAXN], base = 1 + rng_next(&r) % 1000;
		double widths[MAXN], xz[2 * MAXN], again[2 * MAXN], scale, tight = INFINITY;

		/* n consecutive numbers of the day: distinct slots */
		for (size_t i = 0; i < n; i++) {
			numbers[i] = base + i;
			widths[i] = rng_range(&r, 0.2, rng_next(&r) % 4 ? 12.0 : 30.0);
		}
		scale = forest_layout(numbers, widths, n, max, xz);
		CHECK(scale >= FOREST_MIN_C);
		CHECK(forest_layout(numbers, widths, n, max, again) == scale);
		for (size_t i = 0; i < 2 * n; i++)
			CHECK(again[i] == xz[i]);
		for (size_t i = 0; i < n; i++) {
			for (size_t j = i + 1; j < n; j++) {
				double d = hypot(xz[2 * i] - xz[2 * j], xz[2 * i + 1] - xz[2 * j + 1]);
				double third = (widths[i] + widths[j]) / 3.0;

				CHECK(d >= third);
				CHECK(d >= FOREST_GAP * (widths[i] + widths[j]) * (1.0 - 1e-12));
				tight = fmin(tight, d / (FOREST_GAP * (widths[i] + widths[j])));
				worst = fmin(worst, d / third);
				pairs++;
			}
		}
		/* the least scale: some pair at the gap exactly, or the minimum */
		CHECK(n == 1 || scale == FOREST_MIN_C || fabs(tight - 1.0) < 1e-9);
		/* the newest tree alone, then with the others: the same direction from the centre */
		if (n > 1) {
			double alone[2];

			CHECK(forest_layout(&numbers[n - 1], &widths[n - 1], 1, max, alone) > 0);
			CHECK(fabs(atan2(alone[1], alone[0]) -
				   atan2(xz[2 * n - 1], xz[2 * n - 2])) < 1e-9);
		}
	}
	/* refused: two in one slot, a bad width, more trees than slots */
	{
		uint64_t num[2] = { 1, 41 };
		double w[2] = { 3.0, 3.0 }, xz[4];

		CHECK(forest_layout(num, w, 2, 40, xz) < 0);
		num[1] = 2;
		w[1] = NAN;
		CHECK(forest_layout(num, w, 2, 40, xz) < 0);
		w[1] = 3.0;
		CHECK(forest_layout(num, w, 2, 1, xz) < 0);
		num[0] = 0;
		CHECK(forest_layout(num, w, 1, 40, xz) < 0);
	}
	printf("forest layout: %d random forests, %zu pairs of trunks; the closest at %.3f times "
	       "the sum of a third of their crowns\n", cases, pairs, worst);
	return 0;
}
