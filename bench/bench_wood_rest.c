/* SPDX-License-Identifier: MIT */
/*
 * Growing wood's rest state (issue 17, steps 4-5, wood_rest): the time to build the
 * springs of a voxel field and solve their static equilibrium under gravity, on fields of
 * density-1 voxels made here: vertical rods and horizontal cantilevers of growing length,
 * and a procedural tree (a trunk, a leader, four inclined branches with a side branch
 * each, as capsules) in grids of 32, 64 and 128 cells, 15% padded like wood_grid_for's.
 * Prints the median time, points, springs, CG iterations and residual, and how the time
 * grows with the points. Targets for a whole press: 64 under 1 s, 128 under 10 s.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "bench_util.h"
#include "wood.h"

struct capsule {
	double a[3], b[3]; /* voxel units */
	double ra, rb;     /* radius at a and at b */
};

/* Whether point q lies in the capsule (radius interpolated along it). */
static int in_capsule(const struct capsule *c, const double q[3])
{
	double ab[3], aq[3], l2 = 0.0, t = 0.0, d2 = 0.0, r;

	for (int k = 0; k < 3; k++) {
		ab[k] = c->b[k] - c->a[k];
		aq[k] = q[k] - c->a[k];
		l2 += ab[k] * ab[k];
		t += ab[k] * aq[k];
	}
	t = l2 > 0.0 ? fmin(fmax(t / l2, 0.0), 1.0) : 0.0;
	for (int k = 0; k < 3; k++) {
		double e = aq[k] - t * ab[k];

		d2 += e * e;
	}
	r = c->ra + t * (c->rb - c->ra);
	return d2 <= r * r;
}

/* Density 1 in every voxel whose centre is in a capsule and not below the ground. */
static void fill(struct wood_grid *g, const struct capsule *c, size_t nc, double ground)
{
	for (int z = 0; z < g->nz; z++)
		for (int y = 0; y < g->ny; y++)
			for (int x = 0; x < g->nx; x++) {
				double q[3] = { x + 0.5, y + 0.5, z + 0.5 };

				if (q[1] < ground)
					continue;
				for (size_t i = 0; i < nc; i++)
					if (in_capsule(c + i, q)) {
						g->density[wood_index(g, x, y, z)] = 1.0;
						break;
					}
			}
}

static struct capsule cap(double ax, double ay, double az, double bx, double by, double bz,
			  double ra, double rb)
{
	struct capsule c = { { ax, ay, az }, { bx, by, bz }, ra, rb };

	return c;
}

/* The procedural tree in a cube of n cells, its ground 15% up; thick scales the radii. */
static size_t tree(int n, double thick, struct capsule *c)
{
	double G = n, ground = 0.15 * G, H = 0.7 * G, m = 0.5 * G, top = ground + 0.55 * H;
	double r0 = fmax(0.05 * thick * G, 2.0), r1 = fmax(0.035 * thick * G, 1.8),
	       rb = fmax(0.03 * thick * G, 1.6), rt = 1.5;
	size_t k = 0;

	c[k++] = cap(m, ground - r0, m, m, top, m, r0, r1);
	c[k++] = cap(m, top, m, m, ground + 0.97 * H, m, r1, rt);
	for (int i = 0; i < 4; i++) {
		double az = (i * 90.0 + 20.0) * VEC_PI / 180.0, el = 40.0 * VEC_PI / 180.0;
		double y0 = ground + (0.3 + 0.08 * i) * H, len = 0.4 * H;
		double dx = cos(az) * cos(el), dy = sin(el), dz = sin(az) * cos(el);
		double mx = m + 0.5 * len * dx, my = y0 + 0.5 * len * dy, mz = m + 0.5 * len * dz;
		/* a side branch from the middle, more level, turned 35 degrees */
		double az2 = az + 35.0 * VEC_PI / 180.0, l2 = 0.3 * H;

		c[k++] = cap(m, y0, m, m + len * dx, y0 + len * dy, m + len * dz, rb, rt);
		c[k++] = cap(mx, my, mz, mx + l2 * cos(az2) * 0.95, my + l2 * 0.3,
			     mz + l2 * sin(az2) * 0.95, fmax(0.7 * rb, 1.5), rt);
	}
	return k;
}

struct job {
	struct wood_grid g;
	struct wood_params p;
	double ground_y;
	struct wood_solve_stats st;
	int rc;
};

static void solve(void *arg)
{
	struct job *j = arg;

	j->rc = wood_rest(&j->g, &j->p, j->ground_y, &j->st);
}

/* This process's CPU seconds: on a shared machine the wall time counts others' too. */
static double cpu_now(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
	return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

static void run(const char *name, struct job *j, int reps, double *pn, double *pt)
{
	double t, cpu[9], umax = 0.0;

	memset(&j->p, 0, sizeof(j->p));
	j->p.gravity = 1e-6;
	t = bench_run(solve, j, reps);
	for (int r = 0; r < reps; r++) {
		double c0 = cpu_now();

		solve(j);
		cpu[r] = cpu_now() - c0;
	}
	if (j->rc != 0) {
		fprintf(stderr, "bench_wood_rest: %s: wood_rest %d\n", name, j->rc);
		exit(1);
	}
	for (size_t i = 0; i < 3 * wood_cells(&j->g); i++)
		umax = fmax(umax, fabs(j->g.displacement[i]));
	bench_row(name, (double)j->st.points, t, pn, pt);
	printf("    %zu points (%zu fixed, %zu dropped), %zu springs, %d iterations, residual "
	       "%.2g, largest displacement %.3g voxels; CPU median %.1f ms, %.1f us a point\n",
	       j->st.points, j->st.fixed, j->st.dropped, j->st.springs, j->st.iterations,
	       j->st.residual, umax, 1e3 * bench_median(cpu, (size_t)reps),
	       1e6 * bench_median(cpu, (size_t)reps) / (double)j->st.points);
}

static void grid(struct job *j, int nx, int ny, int nz)
{
	if (wood_grid_create(&j->g, nx, ny, nz, (struct vec3){ 0, 0, 0 }, 1.0) < 0)
		exit(1);
	j->ground_y = 0.0;
}

/* A vertical rod of radius 3 and n voxels, on the ground. */
static void rods(void)
{
	static const int len[] = { 16, 32, 64, 128 };
	double pn = 0, pt = 0;

	printf("vertical rods, radius 3 voxels, on the ground: median of 3\n");
	for (size_t i = 0; i < BENCH_COUNT(len); i++) {
		struct job j;
		struct capsule c = cap(5, -5, 5, 5, len[i], 5, 3.2, 3.2);
		char name[64];

		grid(&j, 11, len[i], 11);
		fill(&j.g, &c, 1, 0.0);
		snprintf(name, sizeof(name), "  rod, %d voxels, points", len[i]);
		run(name, &j, bench_reps(3), &pn, &pt);
		wood_grid_finish(&j.g);
	}
}

/* A post 8 high (radius 3) with a horizontal arm of radius 3 and length n. */
static void cantilevers(void)
{
	static const int len[] = { 16, 32, 64 };
	double pn = 0, pt = 0;

	printf("horizontal cantilevers, radius 3 voxels, from a post 12 high: median of 3\n");
	for (size_t i = 0; i < BENCH_COUNT(len); i++) {
		struct job j;
		struct capsule c[2] = { cap(5, -5, 5, 5, 12, 5, 3.2, 3.2),
					cap(5, 8, 5, 5 + len[i], 8, 5, 3.2, 3.2) };
		char name[64];

		grid(&j, len[i] + 10, 13, 11);
		fill(&j.g, c, 2, 0.0);
		snprintf(name, sizeof(name), "  arm, %d voxels, points", len[i]);
		run(name, &j, bench_reps(3), &pn, &pt);
		wood_grid_finish(&j.g);
	}
}

static void trees(double thick)
{
	static const int cells[] = { 32, 64, 128 };
	double pn = 0, pt = 0;

	printf("a procedural tree (trunk r = %.3g n, leader, 4 branches with a side branch each) "
	       "in a grid of n^3 cells: median of 5 (3 at 128)\n",
	       0.05 * thick);
	for (size_t i = 0; i < BENCH_COUNT(cells); i++) {
		struct job j;
		struct capsule c[16];
		size_t nc = tree(cells[i], thick, c);
		char name[64];

		grid(&j, cells[i], cells[i], cells[i]);
		j.ground_y = 0.15 * cells[i];
		fill(&j.g, c, nc, j.ground_y);
		snprintf(name, sizeof(name), "  tree, grid %d, points", cells[i]);
		run(name, &j, bench_reps(cells[i] >= 128 ? 3 : 5), &pn, &pt);
		wood_grid_finish(&j.g);
	}
}

int main(int argc, char **argv)
{
	if (bench_init(&argc, argv, NULL))
		return 1;
	printf("bench_wood_rest: the springs' rest state (wood_rest: build, preconditioned CG "
	       "to 1e-6, forces), gravity 1e-6 (the forces and displacements in proportion to it), one core\n");
	rods();
	cantilevers();
	trees(1.0);
	trees(1.6);
	return 0;
}
