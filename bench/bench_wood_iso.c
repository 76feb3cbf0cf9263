/* SPDX-License-Identifier: MIT */
/*
 * Growing wood's step 7 (issue 17, docs/wood.md): the bark drawn back from the density as
 * its iso-surface at 0.5 (wood_iso, marching tetrahedra), on a tree-like field made here
 * (a trunk and five branches, capsules of density 1 with a one-voxel ramp at their
 * surfaces) in grids of 64 (the kiosk) and 128 cells along the padded box's longest side.
 * Medians, triangles and vertices, the growth with the grid as an exponent of its cells,
 * and the surface's volume against the wood's (sum of density h^3).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "bench_util.h"
#include "mesh.h"
#include "wood.h"

struct capsule {
	struct vec3 a, b;
	double r;
};

/* A small tree, metres: the trunk, three branches from it, two from those; the thinnest
 * 1.6 voxels in radius in the grid of 64, as thin as step 2 voxelises (1.5). */
static const struct capsule capsules[] = {
	{ { 0, 0, 0 }, { 0, 1.2, 0 }, 0.2 },
	{ { 0, 0.7, 0 }, { 0.6, 1.45, 0.1 }, 0.12 },
	{ { 0, 0.9, 0 }, { -0.5, 1.6, -0.2 }, 0.1 },
	{ { 0, 1.2, 0 }, { 0.05, 2.0, 0.05 }, 0.13 },
	{ { 0.3, 1.07, 0.05 }, { 0.65, 1.3, 0.45 }, 0.08 },
	{ { -0.25, 1.25, -0.1 }, { -0.55, 1.35, 0.2 }, 0.075 },
};
#define NCAPSULES (sizeof(capsules) / sizeof(capsules[0]))

static double segment_dist(struct vec3 p, struct vec3 a, struct vec3 b)
{
	struct vec3 ab = vec3_sub(b, a);
	double t = vec3_dot(vec3_sub(p, a), ab) / vec3_dot(ab, ab);

	t = t < 0 ? 0 : t > 1 ? 1 : t;
	return vec3_dist(p, vec3_add(a, vec3_scale(ab, t)));
}

/* The capsules' box padded by WOOD_PAD of its longest side, `cells` along that side. */
static void make_field(struct wood_grid *g, int cells)
{
	struct vec3 lo = vec3(INFINITY, INFINITY, INFINITY), hi = vec3(-INFINITY, -INFINITY, -INFINITY);
	double side, h;

	for (size_t c = 0; c < NCAPSULES; c++)
		for (int e = 0; e < 2; e++) {
			struct vec3 p = e ? capsules[c].b : capsules[c].a;

			lo = vec3(fmin(lo.x, p.x - capsules[c].r), fmin(lo.y, p.y - capsules[c].r),
				  fmin(lo.z, p.z - capsules[c].r));
			hi = vec3(fmax(hi.x, p.x + capsules[c].r), fmax(hi.y, p.y + capsules[c].r),
				  fmax(hi.z, p.z + capsules[c].r));
		}
	side = fmax(hi.x - lo.x, fmax(hi.y - lo.y, hi.z - lo.z));
	lo = vec3_sub(lo, vec3(WOOD_PAD * side, WOOD_PAD * side, WOOD_PAD * side));
	hi = vec3_add(hi, vec3(WOOD_PAD * side, WOOD_PAD * side, WOOD_PAD * side));
	h = (1 + 2 * WOOD_PAD) * side / cells;
	if (wood_grid_create(g, (int)ceil((hi.x - lo.x) / h), (int)ceil((hi.y - lo.y) / h),
			     (int)ceil((hi.z - lo.z) / h), lo, h) < 0)
		exit(1);
	for (int z = 0; z < g->nz; z++)
		for (int y = 0; y < g->ny; y++)
			for (int x = 0; x < g->nx; x++) {
				struct vec3 p = vec3(lo.x + (x + 0.5) * h, lo.y + (y + 0.5) * h,
						     lo.z + (z + 0.5) * h);
				double v = 0;

				for (size_t c = 0; c < NCAPSULES; c++) {
					double d = segment_dist(p, capsules[c].a, capsules[c].b);
					double w = 0.5 + (capsules[c].r - d) / h;

					v = fmax(v, fmin(1.0, fmax(0.0, w)));
				}
				g->density[wood_index(g, x, y, z)] = v;
			}
}

struct job {
	struct wood_grid g;
	struct mesh m;
	double wood; /* m^3 */
};

static void run(void *arg)
{
	struct job *j = arg;

	mesh_clear(&j->m);
	if (wood_iso(&j->g, 0.5, &j->m) < 0)
		exit(1);
}

/* The bark as a press makes it: as much as the wood (wood_iso_keep_volume). */
static void run_kept(void *arg)
{
	struct job *j = arg;

	run(j);
	if (wood_iso_keep_volume(&j->m, 0, 0, j->wood, j->g.h) < 0)
		exit(1);
}

static double mesh_volume(const struct mesh *m)
{
	double v = 0;

	for (size_t t = 0; t < m->nindices; t += 3) {
		const float *a = m->positions + 3 * m->indices[t];
		const float *b = m->positions + 3 * m->indices[t + 1];
		const float *c = m->positions + 3 * m->indices[t + 2];

		v += (a[0] * ((double)b[1] * c[2] - (double)b[2] * c[1]) -
		      a[1] * ((double)b[0] * c[2] - (double)b[2] * c[0]) +
		      a[2] * ((double)b[0] * c[1] - (double)b[1] * c[0])) / 6.0;
	}
	return v;
}

int main(int argc, char **argv)
{
	static const int sizes[] = { 64, 128 }, quick[] = { 16, 32 };
	double pn = 0, pt = 0;

	if (bench_init(&argc, argv, NULL))
		return 1;
	printf("bench_wood_iso: the bark as the iso-surface at 0.5 of a tree of 6 capsules, "
	       "median ms (growth against the grid's cells)\n");
	for (size_t s = 0; s < sizeof(sizes) / sizeof(sizes[0]); s++) {
		struct job j;
		double t, wood = 0, raw;
		char name[64];

		make_field(&j.g, bench_quick ? quick[s] : sizes[s]);
		mesh_init(&j.m);
		for (size_t i = 0; i < wood_cells(&j.g); i++)
			wood += j.g.density[i];
		wood *= j.g.h * j.g.h * j.g.h;
		t = bench_run(run, &j, bench_reps(sizes[s] > 64 ? 7 : 15));
		snprintf(name, sizeof(name), "wood_iso %d x %d x %d, cells", j.g.nx, j.g.ny, j.g.nz);
		bench_row(name, (double)wood_cells(&j.g), t, &pn, &pt);
		printf("    %zu triangles, %zu vertices, h %.1f mm; volume %+.2f%% of the wood "
		       "(%.4f m^3)\n", j.m.nindices / 3, j.m.nvertices, 1e3 * j.g.h,
		       100 * (mesh_volume(&j.m) / wood - 1), wood);
		raw = t;
		j.wood = wood;
		t = bench_run(run_kept, &j, bench_reps(sizes[s] > 64 ? 7 : 15));
		printf("  and kept to the wood (wood_iso_keep_volume): %.2f ms more; volume %+.3f%% "
		       "of the wood\n", 1e3 * (t - raw), 100 * (mesh_volume(&j.m) / wood - 1));
		mesh_finish(&j.m);
		wood_grid_finish(&j.g);
	}
	return 0;
}
