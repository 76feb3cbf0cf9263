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
	t->wood_ops = &wood_tree_ops; /* the tree frees and copies its wood through them */
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

static void swell_clear(struct wood *w)
{
	for (int k = 0; k < w->nswell; k++)
		mesh_clear(&w->swell[k]);
	w->nswell = 0;
}

/* The iso-surface of g, as much as its wood. */
static int bark_of(const struct wood_grid *g, struct mesh *m)
{
	size_t n = wood_cells(g);
	double wood = 0.0;
	int ret = wood_iso(g, 0.5, m);

	for (size_t i = 0; i < n; i++)
		wood += g->density[i];
	if (ret == 0)
		ret = wood_iso_keep_volume(m, 0, 0, wood * g->h * g->h * g->h, g->h);
	return ret;
}

/* The frames between the field before (density `before`) and w's now. 0 or -ENOMEM (none
 * then: the screen shows the bark at once). */
static int swell_frames(struct wood *w, const double *before)
{
	struct wood_grid view = w->g;
	size_t n = wood_cells(&w->g);
	double *blend = malloc(n * sizeof(*blend));
	int ret = blend ? 0 : -ENOMEM;

	view.density = blend;
	for (int k = 1; k < WOOD_SWELL_FRAMES && ret == 0; k++) {
		double t = (double)k / WOOD_SWELL_FRAMES;

		for (size_t i = 0; i < n; i++)
			blend[i] = before[i] + (w->g.density[i] - before[i]) * t;
		ret = bark_of(&view, &w->swell[k - 1]);
		if (ret == 0)
			w->nswell = k;
	}
	free(blend);
	if (ret < 0)
		swell_clear(w);
	return ret;
}

int wood_press(struct wood *w)
{
	size_t n = wood_cells(&w->g);
	double *before = malloc(n * sizeof(*before));
	int ret = before ? 0 : -ENOMEM;

	swell_clear(w);
	if (ret == 0) {
		/* the first press swells from the swept branches' field */
		memcpy(before, w->presses ? w->g.density : w->density0, n * sizeof(*before));
		ret = wood_rest(&w->g, &w->p, w->ground_y, &w->solve);
	}
	if (ret == 0)
		ret = wood_thicken(&w->g, &w->p, &w->added, &w->lost);
	if (ret == 0) {
		mesh_clear(&w->bark);
		ret = bark_of(&w->g, &w->bark);
	}
	if (ret == 0) {
		w->presses++;
		(void)swell_frames(w, before); /* without them, the bark shows at once */
	}
	free(before);
	return ret;
}

void wood_finish(struct wood *w)
{
	wood_grid_finish(&w->g);
	free(w->density0);
	free(w->voxelised);
	mesh_finish(&w->bark);
	for (int k = 0; k < WOOD_SWELL_FRAMES - 1; k++)
		mesh_finish(&w->swell[k]);
	memset(w, 0, sizeof(*w));
}

static void *dup(const void *src, size_t n)
{
	void *p = malloc(n ? n : 1);

	if (p && n)
		memcpy(p, src, n);
	return p;
}

int wood_copy(struct wood *dst, const struct wood *src)
{
	size_t n = wood_cells(&src->g);
	const struct mesh *b = &src->bark;

	*dst = *src;
	memset(&dst->g, 0, sizeof(dst->g));
	dst->density0 = NULL;
	dst->voxelised = NULL;
	mesh_init(&dst->bark);
	for (int k = 0; k < WOOD_SWELL_FRAMES - 1; k++)
		mesh_init(&dst->swell[k]);
	dst->nswell = 0;
	if (wood_grid_create(&dst->g, src->g.nx, src->g.ny, src->g.nz, src->g.origin, src->g.h) < 0)
		goto fail;
	memcpy(dst->g.density, src->g.density, n * sizeof(double));
	memcpy(dst->g.compression, src->g.compression, n * sizeof(double));
	memcpy(dst->g.tension, src->g.tension, n * sizeof(double));
	memcpy(dst->g.displacement, src->g.displacement, 3 * n * sizeof(double));
	memcpy(dst->g.flags, src->g.flags, n);
	dst->density0 = dup(src->density0, n * sizeof(double));
	dst->voxelised = dup(src->voxelised, src->nbranches * sizeof(bool));
	if (!dst->density0 || !dst->voxelised || mesh_reserve(&dst->bark, b->nvertices, b->nindices) < 0)
		goto fail;
	memcpy(dst->bark.positions, b->positions, 3 * b->nvertices * sizeof(float));
	memcpy(dst->bark.normals, b->normals, 3 * b->nvertices * sizeof(float));
	memcpy(dst->bark.indices, b->indices, b->nindices * sizeof(uint32_t));
	dst->bark.nvertices = b->nvertices;
	dst->bark.nindices = b->nindices;
	return 0;
fail:
	wood_finish(dst);
	return -ENOMEM;
}

size_t wood_bytes(const struct wood *w)
{
	/* the grid's five fields (49 bytes a cell), density0, the bark */
	return wood_cells(&w->g) * (49 + sizeof(double)) + w->nbranches +
	       w->bark.cap_vertices * 6 * sizeof(float) + w->bark.cap_indices * sizeof(uint32_t);
}

static void tree_wood_destroy(struct wood *w)
{
	wood_finish(w);
	free(w);
}

static struct wood *tree_wood_copy(const struct wood *src)
{
	struct wood *w = malloc(sizeof(*w));

	if (!w || wood_copy(w, src) < 0) {
		free(w);
		return NULL;
	}
	return w;
}

static size_t tree_wood_bytes(const struct wood *w)
{
	return sizeof(*w) + wood_bytes(w);
}

static bool tree_wood_holds(const struct wood *w, size_t i)
{
	return i < w->nbranches && w->voxelised[i];
}

const struct tree_wood_ops wood_tree_ops = {
	.destroy = tree_wood_destroy,
	.copy = tree_wood_copy,
	.bytes = tree_wood_bytes,
	.holds = tree_wood_holds,
};

int wood_grow(struct tree *t, const struct wood_params *p)
{
	struct wood *w = t->wood;
	int ret;

	if (!w) {
		w = malloc(sizeof(*w));
		if (!w)
			return -ENOMEM;
		ret = wood_begin(w, t, p);
		if (ret < 0) {
			free(w);
			/* nothing thick enough to hold wood: the radii alone changed */
			return ret == -EINVAL ? 1 : ret;
		}
		t->wood = w;
	} else {
		/* the settings but the grid may change from press to press */
		int grid = w->p.grid;

		w->p = *p;
		w->p.grid = grid;
	}
	ret = wood_press(w);
	if (ret == -EINVAL) /* no point on the ground: nothing holds it up */
		return 1;
	if (ret < 0) {
		tree_wood_drop(t); /* half a press is no press: the document is the truth */
		return ret;
	}
	/* the new bark buries no leaf nor vine: they move out with it */
	ret = wood_move_out(w, t);
	return ret < 0 ? ret : 0;
}
