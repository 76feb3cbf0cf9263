/* SPDX-License-Identifier: MIT */
#pragma once
/* Density fields made by hand for the iso-surface's tests and samples (wood_iso). */

#include <math.h>
#include <stdlib.h>

#include "test.h"
#include "wood.h"

/* A grid of zeros, or the test fails. */
static inline void iso_grid(struct wood_grid *g, int nx, int ny, int nz, struct vec3 origin,
			    double h)
{
	CHECK_INT(wood_grid_create(g, nx, ny, nz, origin, h), 0);
}

static inline struct vec3 iso_voxel_centre(const struct wood_grid *g, int x, int y, int z)
{
	return vec3(g->origin.x + (x + 0.5) * g->h, g->origin.y + (y + 0.5) * g->h,
		    g->origin.z + (z + 0.5) * g->h);
}

static inline double iso_clamp01(double v)
{
	return v < 0.0 ? 0.0 : v > 1.0 ? 1.0 : v;
}

/* A ball of radius R (metres) about c as a distance-like density, 0.5 on its sphere,
 * rising by 1 a voxel inwards: clamp(0.5 + (R - |x - c|) / h, 0, 1), kept where the
 * field already has more (so balls add up as a union). */
static inline void iso_ball(struct wood_grid *g, struct vec3 c, double R)
{
	for (int z = 0; z < g->nz; z++)
		for (int y = 0; y < g->ny; y++)
			for (int x = 0; x < g->nx; x++) {
				double r = vec3_dist(iso_voxel_centre(g, x, y, z), c);
				double v = iso_clamp01(0.5 + (R - r) / g->h);
				double *d = g->density + wood_index(g, x, y, z);

				*d = v > *d ? v : *d;
			}
}

/* Voxels [x0, x1) x [y0, y1) x [z0, z1) set to v. */
static inline void iso_block(struct wood_grid *g, int x0, int y0, int z0, int x1, int y1, int z1,
			     double v)
{
	for (int z = z0; z < z1; z++)
		for (int y = y0; y < y1; y++)
			for (int x = x0; x < x1; x++)
				g->density[wood_index(g, x, y, z)] = v;
}

/* The wood in the field: sum of density h^3, cubic metres. */
static inline double iso_wood(const struct wood_grid *g)
{
	double s = 0.0;

	for (size_t i = 0; i < wood_cells(g); i++)
		s += g->density[i];
	return s * g->h * g->h * g->h;
}
