/* SPDX-License-Identifier: MIT */
/*
 * Step 6 of growing wood (wood.h, docs/wood.md "Step 6: thickening"): the surface layer's
 * growth Csi = (alpha * density * f)^beta, every Csi from the field as it was, each added
 * to its own voxel first, then what passed 1.0 spread ring by ring about its voxel in
 * proportion to 1 / distance, every source at once.
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
	WOOD_PASS_WEIGH,  /* sum the weights */
	WOOD_PASS_DEMAND, /* add the source's share to the voxel's demand */
	WOOD_PASS_TAKE,   /* sum what of its shares the voxels can take */
	WOOD_PASS_APPLY,  /* each voxel takes its demand, or fills to exactly 1.0 */
};

struct wood_ring_acc {
	double weight; /* WEIGH: the sum of 1 / distance */
	double placed; /* TAKE: what of the source's shares is taken */
	size_t open;   /* WEIGH: voxels below 1.0; APPLY: voxels brought to 1.0 */
};

/* A source of overflow: where, what it still has to place, and the ring it is on. */
struct wood_source {
	int cx, cy, cz, r, rmax;
	double e, t; /* t: its share per unit weight this round */
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

static void wood_visit(struct wood_grid *g, double *demand, size_t i, int d2,
		       enum wood_pass pass, double t, struct wood_ring_acc *acc)
{
	double *d = &g->density[i], w, room;

	if (!(*d < 1.0))
		return;
	w = 1.0 / sqrt((double)d2);
	room = 1.0 - *d;
	switch (pass) {
	case WOOD_PASS_WEIGH:
		acc->weight += w;
		acc->open++;
		return;
	case WOOD_PASS_DEMAND:
		demand[i] += t * w;
		return;
	case WOOD_PASS_TAKE:
		/* a voxel asked for more than its room shares it out in proportion */
		acc->placed += demand[i] > room ? t * w * (room / demand[i]) : t * w;
		return;
	case WOOD_PASS_APPLY:
		if (!(demand[i] > 0.0))
			return; /* none asked, or applied already from another ring */
		if (demand[i] >= room) {
			*d = 1.0;
			acc->open++;
		} else {
			*d += demand[i];
		}
		demand[i] = 0.0;
		return;
	}
}

/*
 * One pass over ring r about (cx, cy, cz): the voxels inside the grid at Chebyshev
 * distance r, z then y then x ascending (a fixed order, so sums repeat bit for bit).
 */
static void wood_ring_pass(struct wood_grid *g, double *demand, const struct wood_source *s,
			   enum wood_pass pass, struct wood_ring_acc *acc)
{
	int cx = s->cx, cy = s->cy, cz = s->cz, r = s->r;
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
					wood_visit(g, demand, wood_index(g, x, y, z),
						   dyz + (x - cx) * (x - cx), pass, s->t, acc);
				continue;
			}
			/* inside the cube's z and y: only its two ends in x */
			if (cx - r >= 0)
				wood_visit(g, demand, wood_index(g, cx - r, y, z), dyz + r * r,
					   pass, s->t, acc);
			if (cx + r < g->nx)
				wood_visit(g, demand, wood_index(g, cx + r, y, z), dyz + r * r,
					   pass, s->t, acc);
		}
	}
}

/* A source at voxel i with excess e, on ring 1; rmax its farthest ring inside the grid. */
static struct wood_source wood_source_at(const struct wood_grid *g, size_t i, double e)
{
	struct wood_source s = { 0 };

	s.cx = (int)(i % (size_t)g->nx);
	s.cy = (int)(i / (size_t)g->nx % (size_t)g->ny);
	s.cz = (int)(i / ((size_t)g->nx * (size_t)g->ny));
	s.rmax = s.cx;
	s.rmax = g->nx - 1 - s.cx > s.rmax ? g->nx - 1 - s.cx : s.rmax;
	s.rmax = s.cy > s.rmax ? s.cy : s.rmax;
	s.rmax = g->ny - 1 - s.cy > s.rmax ? g->ny - 1 - s.cy : s.rmax;
	s.rmax = s.cz > s.rmax ? s.cz : s.rmax;
	s.rmax = g->nz - 1 - s.cz > s.rmax ? g->nz - 1 - s.cz : s.rmax;
	s.r = 1;
	s.e = e;
	return s;
}

/*
 * Every source's excess spread at once, each outward ring by ring about its voxel (no
 * source first: the result does not depend on the order of the sources, up to rounding).
 * A round: each source with excess offers it to the voxels below 1.0 in its ring in
 * proportion to 1 / distance; a voxel offered no more than its room takes it all, one
 * offered more fills to exactly 1.0 and its room is shared among its offers in their
 * proportion; each source keeps what was not taken for the next round, on the same ring
 * while it has voxels below 1.0, else the next. A round that fills no voxel places
 * everything offered. Returns what found no room (the grid full about its sources).
 */
static double wood_spread(struct wood_grid *g, double *demand, struct wood_source *src,
			  size_t n, size_t *open)
{
	double lost = 0.0;
	size_t active = n;

	while (active > 0 && *open > 0) {
		size_t filled = 0;

		active = 0;
		for (size_t k = 0; k < n; k++) {
			struct wood_source *s = &src[k];

			if (!(s->e > 0.0))
				continue;
			for (; s->r <= s->rmax; s->r++) {
				struct wood_ring_acc acc = { 0 };

				wood_ring_pass(g, demand, s, WOOD_PASS_WEIGH, &acc);
				if (acc.open > 0) {
					s->t = s->e / acc.weight;
					break;
				}
			}
			if (s->r > s->rmax) {
				lost += s->e;
				s->e = 0.0;
				continue;
			}
			wood_ring_pass(g, demand, s, WOOD_PASS_DEMAND, NULL);
			active++;
		}
		if (active == 0)
			break;
		for (size_t k = 0; k < n; k++) {
			struct wood_ring_acc acc = { 0 };

			if (!(src[k].e > 0.0))
				continue;
			wood_ring_pass(g, demand, &src[k], WOOD_PASS_TAKE, &acc);
			src[k].e -= acc.placed;
		}
		for (size_t k = 0; k < n; k++) {
			struct wood_ring_acc acc = { 0 };

			/* a source that placed all still lists its ring's demands: apply them */
			if (src[k].t > 0.0) {
				wood_ring_pass(g, demand, &src[k], WOOD_PASS_APPLY, &acc);
				filled += acc.open;
			}
			src[k].t = 0.0;
		}
		*open -= filled;
		for (size_t k = 0; k < n; k++)
			if (filled == 0 || !(src[k].e > 0.0))
				src[k].e = 0.0; /* all offered was taken (below 0 only by rounding) */
	}
	for (size_t k = 0; k < n; k++)
		lost += src[k].e > 0.0 ? src[k].e : 0.0;
	return lost;
}

int wood_thicken(struct wood_grid *g, const struct wood_params *p, double *added, double *lost)
{
	struct wood_grow *v;
	struct wood_source *src = NULL;
	double *demand = NULL;
	size_t n, open, nsrc = 0;
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
	src = malloc(n * sizeof(*src));
	demand = calloc(wood_cells(g), sizeof(*demand));
	if (!src || !demand) {
		free(v);
		free(src);
		free(demand);
		return -ENOMEM;
	}
	open = wood_open_count(g);
	wood_add_own(g, v, n, &open);
	for (size_t k = 0; k < n; k++) {
		sum += v[k].csi;
		if (v[k].excess > 0.0)
			src[nsrc++] = wood_source_at(g, v[k].i, v[k].excess);
	}
	if (nsrc > 0 && open > 0)
		gone = wood_spread(g, demand, src, nsrc, &open);
	else
		for (size_t k = 0; k < nsrc; k++)
			gone += src[k].e;
	free(v);
	free(src);
	free(demand);
	if (added)
		*added = sum;
	if (lost)
		*lost = gone;
	return 0;
}
