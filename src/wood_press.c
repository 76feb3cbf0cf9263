/* SPDX-License-Identifier: MIT */
/* Growing wood's presses (wood.h, docs/wood.md): the steps in their order. */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "wood.h"

/* The lowest foot of a trunk (a branch rooted on the ground), or NaN. */
static double ground_of(const struct tree *t)
{
	double y = NAN;

	for (size_t i = 0; i < t->nbranches; i++)
		if (t->branches[i].parent < 0 && t->branches[i].npoints > 0 &&
		    !(t->branches[i].points[0].y >= y))
			y = t->branches[i].points[0].y;
	return y;
}

int wood_begin(struct wood *w, struct tree *t, const struct wood_params *p)
{
	struct mesh prisms;
	size_t n;
	int ret;

	memset(w, 0, sizeof(*w));
	w->p = *p;
	w->ground_y = ground_of(t);
	if (isnan(w->ground_y))
		return -EINVAL;
	ret = wood_power_law(t, WOOD_POWER_LAW_A);
	if (ret < 0)
		return ret;
	w->nbranches = t->nbranches;
	w->voxelised = calloc(t->nbranches ? t->nbranches : 1, sizeof(*w->voxelised));
	if (!w->voxelised)
		return -ENOMEM;
	mesh_init(&prisms);
	ret = wood_prisms(t, p->grid, &prisms, w->voxelised);
	if (ret == 0)
		ret = wood_grid_for(&prisms, p->grid, &w->g);
	if (ret == 0)
		ret = wood_voxelise(&w->g, &prisms);
	mesh_finish(&prisms);
	if (ret == 0) {
		n = wood_cells(&w->g);
		w->density0 = malloc(n * sizeof(*w->density0));
		if (!w->density0)
			ret = -ENOMEM;
		else
			memcpy(w->density0, w->g.density, n * sizeof(*w->density0));
	}
	if (ret < 0)
		wood_finish(w);
	return ret;
}

int wood_press(struct wood *w)
{
	int ret = wood_rest(&w->g, &w->p, w->ground_y, &w->solve);

	if (ret == 0)
		ret = wood_thicken(&w->g, &w->p, &w->added, &w->lost);
	if (ret == 0)
		w->presses++;
	return ret;
}

void wood_finish(struct wood *w)
{
	wood_grid_finish(&w->g);
	free(w->density0);
	free(w->voxelised);
	memset(w, 0, sizeof(*w));
}
