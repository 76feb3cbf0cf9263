/* SPDX-License-Identifier: MIT */
/*
 * Growing wood's step 6 (issue 17, docs/wood.md "Step 6: thickening"): the time to thicken
 * a synthetic field at 64^3 (the kiosk's grid) and 128^3: a vertical cylinder of density
 * 1.0 with a one-voxel fractional rim, every voxel a random compression and tension
 * (seeded), alpha = beta = 1. Prints the median of several runs, the surface voxels, how
 * many overflow, how many voxels grew, the wood added and lost; then five presses in a
 * row on the same field (each on the one before, the new voxels made mass points), where
 * the rim has grown and overflows spread further.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_util.h"
#include "rng.h"
#include "wood.h"

#define REPS 7
#define PRESSES 5

/* The cylinder about the y axis through the grid's middle, radius n/6, from n/8 to 7n/8:
 * density 1 inside, falling linearly to 0 across one voxel at its side. */
static void field(struct wood_grid *g, int n, double force)
{
	struct rng r;
	double c = 0.5 * n, R = n / 6.0;

	if (wood_grid_create(g, n, n, n, vec3(0, 0, 0), 0.01) < 0)
		exit(1);
	rng_seed(&r, 17);
	for (int z = 0; z < n; z++)
		for (int y = 0; y < n; y++)
			for (int x = 0; x < n; x++) {
				size_t i = wood_index(g, x, y, z);
				double d = hypot(x + 0.5 - c, z + 0.5 - c);
				double rho = fmin(fmax(R + 0.5 - d, 0.0), 1.0);

				if (y < n / 8 || y >= n - n / 8)
					rho = 0.0;
				g->density[i] = rho;
				g->flags[i] = rho > 0.0 ? WOOD_MASS : 0;
				g->compression[i] = force * rng_uniform(&r);
				g->tension[i] = force * rng_uniform(&r);
			}
}

struct counts {
	size_t surface, overflow;
};

static struct counts count(const struct wood_grid *g, const struct wood_params *p)
{
	struct counts k = { 0, 0 };

	for (size_t i = 0; i < wood_cells(g); i++) {
		double d = g->density[i];

		if (!(g->flags[i] & WOOD_MASS) || !(d > 0.0) || !(d < 1.0))
			continue;
		k.surface++;
		k.overflow += d + pow(p->alpha * d * g->compression[i], p->beta) > 1.0;
	}
	return k;
}

static size_t grown(const double *before, const double *after, size_t n)
{
	size_t k = 0;

	for (size_t i = 0; i < n; i++)
		k += after[i] > before[i];
	return k;
}

static void one(int n, double *prev_n, double *prev_t)
{
	struct wood_params p = { .mode = WOOD_CONIFER, .grid = n, .alpha = 1.0, .beta = 1.0 };
	struct wood_grid g;
	double t[REPS], added = 0, lost = 0, *start;
	size_t cells;
	struct counts k;
	char name[64];

	field(&g, n, 2.0);
	cells = wood_cells(&g);
	start = malloc(cells * sizeof(*start));
	if (!start)
		exit(1);
	memcpy(start, g.density, cells * sizeof(*start));
	k = count(&g, &p);
	for (int r = 0; r < bench_reps(REPS); r++) {
		double t0;

		memcpy(g.density, start, cells * sizeof(*start));
		t0 = bench_now();
		if (wood_thicken(&g, &p, &added, &lost) < 0)
			exit(1);
		t[r] = bench_now() - t0;
	}
	snprintf(name, sizeof(name), "  thicken %d^3, cells", n);
	bench_row(name, (double)cells, bench_median(t, (size_t)bench_reps(REPS)), prev_n, prev_t);
	printf("    surface %zu voxels, %zu overflow, %zu voxels grew, added %.1f, lost %.1f\n",
	       k.surface, k.overflow, grown(start, g.density, cells), added, lost);

	/* five presses in a row, the field growing */
	memcpy(g.density, start, cells * sizeof(*start));
	for (int press = 1; press <= PRESSES; press++) {
		double t0;

		memcpy(start, g.density, cells * sizeof(*start));
		for (size_t i = 0; i < cells; i++)
			g.flags[i] = g.density[i] > 0.0 ? WOOD_MASS : 0;
		k = count(&g, &p);
		t0 = bench_now();
		if (wood_thicken(&g, &p, &added, &lost) < 0)
			exit(1);
		t0 = bench_now() - t0;
		printf("    press %d: %.3f ms, surface %zu, %zu overflow, %zu grew, added %.1f, "
		       "lost %.1f\n", press, 1e3 * t0, k.surface, k.overflow,
		       grown(start, g.density, cells), added, lost);
	}
	free(start);
	wood_grid_finish(&g);
}

int main(int argc, char **argv)
{
	double pn = 0, pt = 0;

	if (bench_init(&argc, argv, NULL))
		return 1;
	printf("growing wood, step 6: thickening a cylinder (radius n/6, a one-voxel rim, random "
	       "forces 0..2, conifer, alpha = beta = 1), median of %d, ms\n", bench_reps(REPS));
	one(bench_quick ? 16 : 64, &pn, &pt);
	one(bench_quick ? 32 : 128, &pn, &pt);
	return 0;
}
