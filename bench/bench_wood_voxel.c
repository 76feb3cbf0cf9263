/* SPDX-License-Identifier: MIT */
/*
 * Growing wood, steps 2-3 (docs/wood.md): the time to make the thick branches' prisms
 * (wood_prisms) and to register them in the voxel space (wood_grid_for, wood_voxelise),
 * on trees of 100 and 1,000 branches made here (a trunk forking in two at every tip,
 * radii by the power law d^2.5 from tips of one radius: 4 cm, and a stout 12 cm, as a
 * child's drawing may have), at grids of 32 to 256 cells. "grid" is wood_grid_for and
 * the field's pages touched (memset), so "voxelise" is the rays' work alone.
 * Prints the branches voxelised, the triangles, the voxels occupied (density above 0)
 * and full (density 1), medians, and how each grows with the grid and with the tree.
 * Times are the thread's CPU time (page faults included), not wall time, so that a
 * machine shared with other work gives the same numbers; single-threaded, they are the
 * wall time of an idle kiosk. Printed, never judged.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "bench_util.h"
#include "mesh.h"
#include "tree.h"
#include "wood.h"

#define REPS 15
#define POINTS 6
#define TRUNK_LENGTH 2.0

static double cpu_now(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
	return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

/* Unit vector d turned by angle a towards unit side s (perpendicular to d). */
static struct vec3 turn(struct vec3 d, struct vec3 s, double a)
{
	return vec3_add(vec3_scale(d, cos(a)), vec3_scale(s, sin(a)));
}

/* A unit vector perpendicular to unit d, at azimuth phi. */
static struct vec3 side(struct vec3 d, double phi)
{
	struct vec3 ref = fabs(d.y) < 0.9 ? vec3(0, 1, 0) : vec3(1, 0, 0);
	struct vec3 a = vec3_norm_or(vec3_cross(d, ref), vec3(0, 0, 1)), b = vec3_cross(d, a);

	return vec3_add(vec3_scale(a, cos(phi)), vec3_scale(b, sin(phi)));
}

/*
 * n branches as a binary heap: branch i's children are 2i + 1 and 2i + 2, both from its
 * tip, 25 and 40 degrees off it on either side, at an azimuth turning by the golden angle,
 * 0.78 of its length, each slightly bent. Tips have tip_radius; a parent's radius to the
 * 2.5th power is its children's sum (no continuation: it ends at the fork).
 */
static void make_tree(struct tree *t, int n, double tip_radius)
{
	double *r = calloc((size_t)n, sizeof(*r)), *len = calloc((size_t)n, sizeof(*len));
	struct vec3 *dir = calloc((size_t)n, sizeof(*dir)), *tip = calloc((size_t)n, sizeof(*tip));

	if (!r || !len || !dir || !tip)
		exit(1);
	for (int i = n - 1; i >= 0; i--) {
		double s = 0.0;

		for (int c = 2 * i + 1; c <= 2 * i + 2 && c < n; c++)
			s += pow(r[c], WOOD_POWER_LAW_A);
		r[i] = s > 0.0 ? pow(s, 1.0 / WOOD_POWER_LAW_A) : tip_radius;
	}
	tree_clear(t);
	for (int i = 0; i < n; i++) {
		int parent = i == 0 ? -1 : (i - 1) / 2;
		struct vec3 p[POINTS], root, bend;
		double radii[POINTS];

		if (parent < 0) {
			root = vec3(0, 0, 0);
			dir[i] = vec3(0, 1, 0);
			len[i] = TRUNK_LENGTH;
		} else {
			double phi = 2.39996 * parent + (i % 2 ? 0.0 : VEC_PI);

			root = tip[parent];
			dir[i] = turn(dir[parent], side(dir[parent], phi), i % 2 ? 0.44 : 0.70);
			len[i] = 0.78 * len[parent];
		}
		bend = side(dir[i], 1.3 * i);
		for (int k = 0; k < POINTS; k++) {
			double s = (double)k / (POINTS - 1);

			p[k] = vec3_add(root, vec3_add(vec3_scale(dir[i], s * len[i]),
						       vec3_scale(bend, 0.08 * len[i] * s * s)));
			radii[k] = r[i];
		}
		tip[i] = p[POINTS - 1];
		if (tree_add_branch(t, parent, 1.0, ORIGIN_SKETCH, p, radii, POINTS) < 0)
			exit(1);
	}
	free(r);
	free(len);
	free(dir);
	free(tip);
}

struct result {
	double prisms_s, voxelise_s, grid_s;
	size_t voxelised, triangles, cells, occupied, full;
};

static int cmp(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;

	return (x > y) - (x < y);
}

static double median(double *v)
{
	qsort(v, (size_t)bench_reps(REPS), sizeof(*v), cmp);
	return v[bench_reps(REPS) / 2];
}

static void run(const struct tree *t, int cells, struct result *res)
{
	double tp[REPS], tv[REPS], tg[REPS];
	bool *vox = calloc(t->nbranches, sizeof(*vox));
	struct mesh m;
	struct wood_grid g;

	if (!vox)
		exit(1);
	mesh_init(&m);
	for (int k = 0; k < bench_reps(REPS); k++) {
		double t0 = cpu_now(), t1, t2, t3;

		mesh_clear(&m);
		if (wood_prisms(t, cells, &m, vox) < 0)
			exit(1);
		t1 = cpu_now();
		if (wood_grid_for(&m, cells, &g) < 0)
			exit(1);
		/* the field's pages touched here, not in the first writes of the rays */
		memset(g.density, 0, wood_cells(&g) * sizeof(*g.density));
		t2 = cpu_now();
		if (wood_voxelise(&g, &m) < 0)
			exit(1);
		t3 = cpu_now();
		tp[k] = t1 - t0;
		tg[k] = t2 - t1;
		tv[k] = t3 - t2;
		if (k + 1 < bench_reps(REPS))
			wood_grid_finish(&g);
	}
	memset(res, 0, sizeof(*res));
	res->prisms_s = median(tp);
	res->grid_s = median(tg);
	res->voxelise_s = median(tv);
	for (size_t b = 0; b < t->nbranches; b++)
		res->voxelised += vox[b];
	res->triangles = m.nindices / 3;
	res->cells = wood_cells(&g);
	for (size_t i = 0; i < wood_cells(&g); i++) {
		res->occupied += g.density[i] > 0.0;
		res->full += g.density[i] == 1.0;
	}
	wood_grid_finish(&g);
	mesh_finish(&m);
	free(vox);
}

static void print(int n, double tip, int cells, const struct result *r)
{
	printf("%5d %5.2f %5d %6zu %7zu %10zu %9zu %8zu %9.3f %8.3f %9.3f %9.3f\n", n, tip, cells, r->voxelised,
	       r->triangles, r->cells, r->occupied, r->full, r->prisms_s * 1e3, r->grid_s * 1e3,
	       r->voxelise_s * 1e3, (r->prisms_s + r->voxelise_s) * 1e3);
}

int main(int argc, char **argv)
{
	static const struct {
		int n;
		double tip;
	} trees[] = { { 100, 0.04 }, { 100, 0.12 }, { 1000, 0.04 } };
	static const int grids[] = { 32, 64, 128, 256 };
	struct tree t;

	if (bench_init(&argc, argv, NULL))
		return 1;
	tree_init(&t);
	printf("binary-fork trees (power law d^2.5), medians of %d, CPU ms\n", bench_reps(REPS));
	printf("%5s %5s %5s %6s %7s %10s %9s %8s %9s %8s %9s %9s\n", "tree", "tips", "grid", "voxd",
	       "tris", "cells", "occupied", "full", "prisms", "grid", "voxelise", "p+v");
	for (size_t s = 0; s < BENCH_COUNT(trees); s++) {
		double prev_n = 0, prev_s = 0;
		struct result res[4];

		make_tree(&t, trees[s].n, trees[s].tip);
		for (size_t k = 0; k < BENCH_COUNT(grids); k++) {
			run(&t, grids[k], &res[k]);
			print(trees[s].n, trees[s].tip, grids[k], &res[k]);
		}
		for (size_t k = 0; k < BENCH_COUNT(grids); k++) {
			char name[64];

			snprintf(name, sizeof(name), "%d/%.2f, p+v by grid", trees[s].n, trees[s].tip);
			bench_row(name, grids[k], res[k].prisms_s + res[k].voxelise_s, &prev_n, &prev_s);
		}
	}
	tree_finish(&t);
	return 0;
}
