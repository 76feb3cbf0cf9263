/* SPDX-License-Identifier: MIT */
/* The voxel space of growing wood (wood.h): its fields, made and freed together. */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "wood.h"

#define WOOD_GRID_MAX_SIDE 1024

int wood_grid_create(struct wood_grid *g, int nx, int ny, int nz, struct vec3 origin,
		     double h)
{
	size_t n;

	memset(g, 0, sizeof(*g));
	if (nx < 1 || ny < 1 || nz < 1 || nx > WOOD_GRID_MAX_SIDE || ny > WOOD_GRID_MAX_SIDE ||
	    nz > WOOD_GRID_MAX_SIDE || !(h > 0.0) || !isfinite(h))
		return -EINVAL;
	g->nx = nx;
	g->ny = ny;
	g->nz = nz;
	g->origin = origin;
	g->h = h;
	n = wood_cells(g);
	g->density = calloc(n, sizeof(*g->density));
	g->compression = calloc(n, sizeof(*g->compression));
	g->tension = calloc(n, sizeof(*g->tension));
	g->displacement = calloc(3 * n, sizeof(*g->displacement));
	g->flags = calloc(n, sizeof(*g->flags));
	if (!g->density || !g->compression || !g->tension || !g->displacement || !g->flags) {
		wood_grid_finish(g);
		return -ENOMEM;
	}
	return 0;
}

void wood_grid_finish(struct wood_grid *g)
{
	free(g->density);
	free(g->compression);
	free(g->tension);
	free(g->displacement);
	free(g->flags);
	memset(g, 0, sizeof(*g));
}
