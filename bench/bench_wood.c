/* SPDX-License-Identifier: MIT */
/*
 * Growing wood, a whole press by its stages (issue 17): on a bundled 100-branch skeleton
 * (bench/data/tree100.json, read with skeleton_read as --skeleton reads it; argv[1] may
 * name another skeleton.json), the power law, then each stage timed by calling the wood
 * functions as wood_begin and wood_press do: voxelise (wood_prisms, wood_grid_for,
 * wood_voxelise), springs + solve (wood_rest: it builds the springs and solves in one
 * call), thicken (wood_thicken) and bark (wood_iso), at the 64 and 128 grids, with the
 * default settings. Prints each stage's median, the occupied voxels, springs, CG
 * iterations and the residual reached, and the median of the whole first press.
 * Required: 64 under 1 s and 128 under 10 s a press on one core; aims 0.2 s and 2 s.
 *
 * tree100.json: `presets/zelkova.yaml` with `levels: 7` (127 branches) through
 * `edaha --headless --generate`, its first 100 branches kept (parents come before their
 * children, so they are a tree) and its leaves dropped.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "bench_util.h"
#include "fileio.h"
#include "skeleton_read.h"
#include "wood.h"

#ifndef BENCH_WOOD_TREE
#define BENCH_WOOD_TREE "bench/data/tree100.json"
#endif

enum { VOXELISE, REST, THICKEN, BARK, TOTAL, STAGES };
static const char *const stage_names[STAGES] = { "voxelise", "springs + solve", "thicken",
						  "bark", "whole press" };
#define MAX_REPS 9

struct stats {
	size_t occupied, bark_triangles;
	struct wood_solve_stats solve;
	int nx, ny, nz;
};

static double ground_of(const struct tree *t)
{
	double y = INFINITY;

	for (size_t i = 0; i < t->nbranches; i++)
		if (t->branches[i].parent < 0 && t->branches[i].points[0].y < y)
			y = t->branches[i].points[0].y;
	return y;
}

static void must(int ret, const char *what)
{
	if (ret < 0) {
		fprintf(stderr, "bench_wood: %s failed (%d)\n", what, ret);
		exit(1);
	}
}

/* One first press of t (copied) at p's grid, each stage's time in s[]. */
static void press(const struct tree *src, const struct wood_params *p, double s[STAGES],
		  struct stats *st)
{
	struct tree t;
	struct mesh prisms, bark;
	struct wood_grid g;
	double t0, added, lost;

	tree_init(&t);
	must(tree_copy(&t, src), "tree_copy");
	must(wood_power_law(&t, WOOD_POWER_LAW_A), "wood_power_law");
	mesh_init(&prisms);
	mesh_init(&bark);
	t0 = bench_now();
	must(wood_prisms(&t, p->grid, &prisms, NULL), "wood_prisms");
	must(wood_grid_for(&prisms, p->grid, &g), "wood_grid_for");
	must(wood_voxelise(&g, &prisms), "wood_voxelise");
	s[VOXELISE] = bench_now() - t0;
	t0 = bench_now();
	must(wood_rest(&g, p, ground_of(&t), &st->solve), "wood_rest");
	s[REST] = bench_now() - t0;
	t0 = bench_now();
	must(wood_thicken(&g, p, &added, &lost), "wood_thicken");
	s[THICKEN] = bench_now() - t0;
	t0 = bench_now();
	must(wood_iso(&g, 0.5, &bark), "wood_iso");
	{
		double wood = 0.0;

		for (size_t i = 0; i < wood_cells(&g); i++)
			wood += g.density[i];
		must(wood_iso_keep_volume(&bark, 0, 0, wood * g.h * g.h * g.h, g.h),
		     "wood_iso_keep_volume");
	}
	s[BARK] = bench_now() - t0;
	s[TOTAL] = s[VOXELISE] + s[REST] + s[THICKEN] + s[BARK];
	st->occupied = 0;
	for (size_t i = 0; i < wood_cells(&g); i++)
		st->occupied += g.flags[i] & WOOD_MASS ? 1 : 0;
	st->bark_triangles = bark.nindices / 3;
	st->nx = g.nx;
	st->ny = g.ny;
	st->nz = g.nz;
	wood_grid_finish(&g);
	mesh_finish(&prisms);
	mesh_finish(&bark);
	tree_finish(&t);
}

static void bench_grid(const struct tree *t, int grid, int reps)
{
	double times[STAGES][MAX_REPS], s[STAGES];
	struct wood_params p;
	struct stats st;

	wood_params_default(&p);
	p.grid = grid;
	for (int r = 0; r < reps; r++) {
		press(t, &p, s, &st);
		for (int k = 0; k < STAGES; k++)
			times[k][r] = s[k];
	}
	printf("grid %d (%d x %d x %d cells), median of %d presses:\n", grid, st.nx, st.ny, st.nz,
	       reps);
	for (int k = 0; k < STAGES; k++)
		printf("  %-16s %9.1f ms\n", stage_names[k], 1e3 * bench_median(times[k], (size_t)reps));
	printf("  occupied voxels %zu (kept %zu, fixed %zu, dropped %zu), springs %zu, CG "
	       "iterations %d, residual %.2g, bark %zu triangles\n",
	       st.occupied, st.solve.points, st.solve.fixed, st.solve.dropped, st.solve.springs,
	       st.solve.iterations, st.solve.residual, st.bark_triangles);
}

int main(int argc, char **argv)
{
	const char *path;
	struct error err = { { 0 } };
	struct tree t;
	size_t len;
	char *data;

	if (bench_init(&argc, argv, "[TREE.json]"))
		return 1;
	path = argc > 1 ? argv[1] : BENCH_WOOD_TREE;
	tree_init(&t);
	if (fileio_read_all(path, SKELETON_READ_MAX_BYTES, &data, &len, &err) < 0 ||
	    skeleton_read(data, len, path, &t, &err) < 0) {
		fprintf(stderr, "bench_wood: %s\n", err.msg);
		return 1;
	}
	free(data);
	printf("bench_wood: %s, %zu branches; one core; targets 1 s (64), 10 s (128)\n", path,
	       t.nbranches);
	if (bench_quick) {
		bench_grid(&t, 16, 1);
		bench_grid(&t, 24, 1);
	} else {
		bench_grid(&t, 64, 7);
		bench_grid(&t, 128, 3);
	}
	tree_finish(&t);
	return 0;
}
