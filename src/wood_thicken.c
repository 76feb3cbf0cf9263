/* SPDX-License-Identifier: MIT */
/*
 * Step 6 of growing wood (wood.h, docs/wood.md "Step 6: thickening"): the surface layer's
 * growth Csi = (alpha * density * f)^beta, every Csi from the field as it was, each added
 * to its own voxel first, then what passed 1.0 spread ring by ring about its voxel in
 * proportion to 1 / distance, sources in scan order.
 */
#include <errno.h>
#include <math.h>
#include <stdlib.h>

#include "wood.h"

/* A growing voxel of the surface layer: where, its Csi, what of it passed 1.0. */
struct wood_grow {
	size_t i;
	double csi, excess;
};

/* What a pass over a ring does to each voxel below 1.0 in it. */
enum wood_pass {
	WOOD_PASS_WEIGH, /* sum the weights */
	WOOD_PASS_FILL,  /* fill those whose share reaches 1.0, to exactly 1.0 */
	WOOD_PASS_ADD,   /* add every share */
};

struct wood_ring_acc {
	double weight; /* WEIGH: the sum of 1 / distance */
	double placed; /* FILL: what the filled voxels took */
	size_t open;   /* WEIGH: voxels below 1.0; FILL, ADD: voxels brought to 1.0 */
};

static bool wood_grows(const struct wood_grid *g, size_t i)
{
	return (g->flags[i] & WOOD_MASS) && g->density[i] > 0.0 && g->density[i] < 1.0;
}

/* Csi of voxel i; 0 where alpha * density * f is not above 0 (no force, no growth: a
 * power of 0 or less would be 1 or infinite). May be NaN or infinite: the caller checks. */
static double wood_csi(const struct wood_grid *g, const struct wood_params *p, size_t i)
{
	double f = p->mode == WOOD_CONIFER ? g->compression[i] : g->tension[i];
	double base = p->alpha * g->density[i] * f;

	if (isnan(base))
		return NAN;
	if (!(base > 0.0))
		return 0.0;
	return pow(base, p->beta);
}

/* The growing voxels in scan order with their Csi, from the field before any change.
 * 0, -EINVAL (a Csi not finite) or -ENOMEM; *out NULL when there are none. */
static int wood_collect(const struct wood_grid *g, const struct wood_params *p,
			struct wood_grow **out, size_t *n)
{
	size_t cells = wood_cells(g), count = 0, k = 0;
	struct wood_grow *v;

	*out = NULL;
	*n = 0;
	for (size_t i = 0; i < cells; i++)
		count += wood_grows(g, i);
	if (count == 0)
		return 0;
	v = malloc(count * sizeof(*v));
	if (!v)
		return -ENOMEM;
	for (size_t i = 0; i < cells; i++) {
		if (!wood_grows(g, i))
			continue;
		v[k].i = i;
		v[k].csi = wood_csi(g, p, i);
		v[k].excess = 0.0;
		if (!isfinite(v[k].csi)) {
			free(v);
			return -EINVAL;
		}
		k++;
	}
	*out = v;
	*n = count;
	return 0;
}

/* Voxels that can still take wood. */
static size_t wood_open_count(const struct wood_grid *g)
{
	size_t cells = wood_cells(g), open = 0;

	for (size_t i = 0; i < cells; i++)
		open += g->density[i] < 1.0;
	return open;
}

/* Each Csi into its own voxel, up to exactly 1.0; the rest is its excess. */
static void wood_add_own(struct wood_grid *g, struct wood_grow *v, size_t n, size_t *open)
{
	for (size_t k = 0; k < n; k++) {
		double *d = &g->density[v[k].i], nv = *d + v[k].csi;

		if (nv < 1.0) {
			*d = nv;
			continue;
		}
		/* 1.0 - d is the room it had; the excess is Csi less that */
		v[k].excess = fmax(v[k].csi - (1.0 - *d), 0.0);
		*d = 1.0;
		(*open)--;
	}
}

static void wood_visit(struct wood_grid *g, size_t i, int d2, enum wood_pass pass, double t,
		       struct wood_ring_acc *acc)
{
	double *d = &g->density[i], w, nv;

	if (!(*d < 1.0))
		return;
	w = 1.0 / sqrt((double)d2);
	switch (pass) {
	case WOOD_PASS_WEIGH:
		acc->weight += w;
		acc->open++;
		return;
	case WOOD_PASS_FILL:
		nv = *d + t * w;
		if (nv >= 1.0) {
			acc->placed += 1.0 - *d;
			*d = 1.0;
			acc->open++;
		}
		return;
	case WOOD_PASS_ADD:
		nv = *d + t * w;
		/* below 1.0 by the FILL pass before; the clamp only guards rounding */
		if (nv >= 1.0) {
			nv = 1.0;
			acc->open++;
		}
		*d = nv;
		return;
	}
}

/*
 * One pass over ring r about (cx, cy, cz): the voxels inside the grid at Chebyshev
 * distance r, z then y then x ascending (a fixed order, so sums repeat bit for bit).
 */
static void wood_ring_pass(struct wood_grid *g, int cx, int cy, int cz, int r,
			   enum wood_pass pass, double t, struct wood_ring_acc *acc)
{
	int x0 = cx - r < 0 ? 0 : cx - r, x1 = cx + r >= g->nx ? g->nx - 1 : cx + r;
	int y0 = cy - r < 0 ? 0 : cy - r, y1 = cy + r >= g->ny ? g->ny - 1 : cy + r;
	int z0 = cz - r < 0 ? 0 : cz - r, z1 = cz + r >= g->nz ? g->nz - 1 : cz + r;

	for (int z = z0; z <= z1; z++) {
		int dz = z - cz;

		for (int y = y0; y <= y1; y++) {
			int dy = y - cy, dyz = dy * dy + dz * dz;

			if (abs(dz) == r || abs(dy) == r) {
				/* a face of the ring's cube: the whole row */
				for (int x = x0; x <= x1; x++)
					wood_visit(g, wood_index(g, x, y, z),
						   dyz + (x - cx) * (x - cx), pass, t, acc);
				continue;
			}
			/* inside the cube's z and y: only its two ends in x */
			if (cx - r >= 0)
				wood_visit(g, wood_index(g, cx - r, y, z), dyz + r * r, pass, t,
					   acc);
			if (cx + r < g->nx)
				wood_visit(g, wood_index(g, cx + r, y, z), dyz + r * r, pass, t,
					   acc);
		}
	}
}

/*
 * Places e in ring r, among its voxels below 1.0 in proportion to 1 / distance: those
 * whose share would reach 1.0 are filled to exactly 1.0 and the split repeated among the
 * rest (filling them only raises the others' shares, so every voxel filled in a round
 * would be filled in the end), until a round fills none and every share is added. What
 * the ring had no room for is returned.
 */
static double wood_ring_place(struct wood_grid *g, int cx, int cy, int cz, int r, double e,
			      size_t *open)
{
	for (;;) {
		struct wood_ring_acc acc = { 0 };
		double t;

		wood_ring_pass(g, cx, cy, cz, r, WOOD_PASS_WEIGH, 0.0, &acc);
		if (acc.open == 0)
			return e;
		t = e / acc.weight;
		acc.open = 0;
		wood_ring_pass(g, cx, cy, cz, r, WOOD_PASS_FILL, t, &acc);
		if (acc.open == 0) {
			wood_ring_pass(g, cx, cy, cz, r, WOOD_PASS_ADD, t, &acc);
			*open -= acc.open;
			return 0.0;
		}
		*open -= acc.open;
		e -= acc.placed;
		if (!(e > 0.0))
			return 0.0; /* all placed (below 0 only by rounding) */
	}
}

/*
 * Spreads e from voxel i outwards, ring 1, 2, ... up to the farthest ring with a voxel
 * inside the grid (so it ends); returns what found no room (the grid full about it).
 */
static double wood_spill(struct wood_grid *g, size_t i, double e, size_t *open)
{
	int cx = (int)(i % (size_t)g->nx), cy = (int)(i / (size_t)g->nx % (size_t)g->ny);
	int cz = (int)(i / ((size_t)g->nx * (size_t)g->ny));
	int rmax = cx;

	rmax = g->nx - 1 - cx > rmax ? g->nx - 1 - cx : rmax;
	rmax = cy > rmax ? cy : rmax;
	rmax = g->ny - 1 - cy > rmax ? g->ny - 1 - cy : rmax;
	rmax = cz > rmax ? cz : rmax;
	rmax = g->nz - 1 - cz > rmax ? g->nz - 1 - cz : rmax;
	/* no voxel anywhere below 1.0: no ring need be looked at */
	for (int r = 1; r <= rmax && e > 0.0 && *open > 0; r++)
		e = wood_ring_place(g, cx, cy, cz, r, e, open);
	return e;
}

int wood_thicken(struct wood_grid *g, const struct wood_params *p, double *added, double *lost)
{
	struct wood_grow *v;
	size_t n, open;
	double sum = 0.0, gone = 0.0;
	int rc;

	if (added)
		*added = 0.0;
	if (lost)
		*lost = 0.0;
	if (p->mode != WOOD_CONIFER && p->mode != WOOD_BROADLEAF)
		return -EINVAL;
	rc = wood_collect(g, p, &v, &n);
	if (rc < 0 || n == 0)
		return rc;
	open = wood_open_count(g);
	wood_add_own(g, v, n, &open);
	for (size_t k = 0; k < n; k++) {
		sum += v[k].csi;
		if (v[k].excess > 0.0)
			gone += wood_spill(g, v[k].i, v[k].excess, &open);
	}
	free(v);
	if (added)
		*added = sum;
	if (lost)
		*lost = gone;
	return 0;
}
