/* SPDX-License-Identifier: MIT */
/*
 * Where the trees of the forest stand (docs/forest.md, "Where they stand"): a sunflower
 * spiral of max slots, a tree's slot by its number, the spiral's scale the least that
 * keeps every two trunks apart by FOREST_GAP times their crowns' widths.
 */
#include <math.h>

#include "forest.h"

#define GOLDEN_ANGLE 2.39996322972865332 /* pi (3 - sqrt 5) */

/* Slot k of the unit spiral. */
static void unit(size_t k, double *x, double *z)
{
	double r = sqrt((double)k + 0.5), a = (double)k * GOLDEN_ANGLE;

	*x = r * cos(a);
	*z = r * sin(a);
}

double forest_layout(const uint64_t *numbers, const double *widths, size_t n, size_t max,
		     double *xz)
{
	double c = FOREST_MIN_C;

	if (max == 0 || n > max)
		return -1.0;
	for (size_t i = 0; i < n; i++) {
		if (numbers[i] == 0 || !(widths[i] >= 0.0) || !isfinite(widths[i]))
			return -1.0;
		unit((size_t)((numbers[i] - 1) % max), &xz[2 * i], &xz[2 * i + 1]);
	}
	for (size_t i = 0; i < n; i++) {
		for (size_t j = i + 1; j < n; j++) {
			double d = hypot(xz[2 * i] - xz[2 * j], xz[2 * i + 1] - xz[2 * j + 1]);
			double want = FOREST_GAP * (widths[i] + widths[j]);

			if ((numbers[i] - 1) % max == (numbers[j] - 1) % max)
				return -1.0;
			if (want > c * d)
				c = want / d;
		}
	}
	for (size_t i = 0; i < 2 * n; i++)
		xz[i] *= c;
	return c;
}
