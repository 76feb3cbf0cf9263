/* SPDX-License-Identifier: MIT */
/*
 * The nearest skeleton point to any point on the tree (live_private.h): a uniform grid of
 * the branches' segments, each listed in every cell its box grown by its radius touches.
 * A query visits shells of cells around its point, nearest first, and stops when the
 * best found is no farther than the unvisited cells: a segment it has not seen lies, balls
 * of its radius about its axis and all, in cells not yet visited, so its |p - q| - r(q)
 * is at least the distance from p to them. The tree_index of core is a grid of the tree as
 * a camera shows it (x, y only); this one is in 3D.
 */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "live_private.h"

/* About this many segments a cell; and no more cells than this per segment in all. */
#define GRID_SEGMENTS_PER_CELL 1.0
#define GRID_MAX_CELLS_PER_SEGMENT 4
#define GRID_MAX_DIM 512

void live_grid_finish(struct live_grid *g)
{
	free(g->segs);
	free(g->start);
	free(g->items);
	memset(g, 0, sizeof(*g));
}

static double radius_at(const struct branch *b, size_t j)
{
	double r = b->radii ? b->radii[j] : 0.0;

	return isfinite(r) && r > 0 ? r : 0.0;
}

static bool finite3(struct vec3 p)
{
	return isfinite(p.x) && isfinite(p.y) && isfinite(p.z);
}

/* The segments of every branch; a one-point branch is a segment of no length. */
static int collect(struct live_grid *g, const struct live_skeleton *sk, const struct tree *t)
{
	size_t n = 0;

	for (size_t i = 0; i < t->nbranches; i++)
		n += t->branches[i].npoints > 1 ? t->branches[i].npoints - 1 : t->branches[i].npoints;
	if (n == 0)
		return -EINVAL;
	g->segs = malloc(n * sizeof(*g->segs));
	if (!g->segs)
		return -ENOMEM;
	for (size_t i = 0; i < t->nbranches; i++) {
		const struct branch *b = &t->branches[i];
		const double *arc = &sk->arc[sk->branches[i].first];

		for (size_t j = 0; j < b->npoints && (j + 1 < b->npoints || b->npoints == 1); j++) {
			struct live_segment *s = &g->segs[g->nsegs];
			size_t k = b->npoints == 1 ? j : j + 1;

			s->a = b->points[j];
			s->e = vec3_sub(b->points[k], b->points[j]);
			s->r0 = radius_at(b, j);
			s->r1 = radius_at(b, k);
			s->s0 = arc[j];
			s->len = arc[k] - arc[j];
			s->branch = i;
			if (finite3(s->a) && finite3(s->e))
				g->nsegs++;
		}
	}
	return g->nsegs ? 0 : -EINVAL;
}

/* A segment's box grown by its larger radius. */
static void seg_box(const struct live_segment *s, struct vec3 *lo, struct vec3 *hi)
{
	struct vec3 b = vec3_add(s->a, s->e);
	double r = fmax(s->r0, s->r1);

	*lo = vec3(fmin(s->a.x, b.x) - r, fmin(s->a.y, b.y) - r, fmin(s->a.z, b.z) - r);
	*hi = vec3(fmax(s->a.x, b.x) + r, fmax(s->a.y, b.y) + r, fmax(s->a.z, b.z) + r);
}

static size_t cell_of(const struct live_grid *g, double x, double lo, int axis)
{
	double c = floor((x - lo) / g->cell);

	if (!(c > 0))
		return 0;
	return c >= (double)g->dim[axis] ? g->dim[axis] - 1 : (size_t)c;
}

static void cell_range(const struct live_grid *g, const struct live_segment *s, size_t c0[3],
		       size_t c1[3])
{
	struct vec3 lo, hi;

	seg_box(s, &lo, &hi);
	c0[0] = cell_of(g, lo.x, g->lo.x, 0);
	c0[1] = cell_of(g, lo.y, g->lo.y, 1);
	c0[2] = cell_of(g, lo.z, g->lo.z, 2);
	c1[0] = cell_of(g, hi.x, g->lo.x, 0);
	c1[1] = cell_of(g, hi.y, g->lo.y, 1);
	c1[2] = cell_of(g, hi.z, g->lo.z, 2);
}

static size_t cell_index(const struct live_grid *g, size_t x, size_t y, size_t z)
{
	return (z * g->dim[1] + y) * g->dim[0] + x;
}

/* Cells of the size that puts about GRID_SEGMENTS_PER_CELL segments in one. */
static void size_cells(struct live_grid *g, struct vec3 lo, struct vec3 hi)
{
	double ext[3] = { hi.x - lo.x, hi.y - lo.y, hi.z - lo.z }, big = 0.0, vol = 1.0;
	size_t cells;

	for (int a = 0; a < 3; a++)
		big = fmax(big, ext[a]);
	big = big > 0 ? big : 1.0;
	for (int a = 0; a < 3; a++)
		vol *= fmax(ext[a], 1e-3 * big);
	g->cell = fmax(cbrt(vol * GRID_SEGMENTS_PER_CELL / (double)g->nsegs), big / GRID_MAX_DIM);
	for (;;) {
		cells = 1;
		for (int a = 0; a < 3; a++) {
			g->dim[a] = (size_t)floor(ext[a] / g->cell) + 1;
			cells *= g->dim[a];
		}
		if (cells <= GRID_MAX_CELLS_PER_SEGMENT * g->nsegs + 64)
			break;
		g->cell *= 1.25;
	}
	g->lo = lo;
}

int live_grid_build(struct live_grid *g, const struct live_skeleton *sk, const struct tree *t)
{
	struct vec3 lo = vec3(INFINITY, INFINITY, INFINITY), hi = vec3(-INFINITY, -INFINITY, -INFINITY);
	size_t ncells, total = 0;
	int r;

	memset(g, 0, sizeof(*g));
	r = collect(g, sk, t);
	if (r < 0) {
		live_grid_finish(g);
		return r;
	}
	for (size_t i = 0; i < g->nsegs; i++) {
		struct vec3 a, b;

		seg_box(&g->segs[i], &a, &b);
		lo = vec3(fmin(lo.x, a.x), fmin(lo.y, a.y), fmin(lo.z, a.z));
		hi = vec3(fmax(hi.x, b.x), fmax(hi.y, b.y), fmax(hi.z, b.z));
	}
	size_cells(g, lo, hi);
	ncells = g->dim[0] * g->dim[1] * g->dim[2];
	g->start = calloc(ncells + 1, sizeof(*g->start));
	if (!g->start) {
		live_grid_finish(g);
		return -ENOMEM;
	}
	/* Counting, then filling: start[c + 1] counts cell c's, then becomes where it ends. */
	for (int pass = 0; pass < 2; pass++) {
		for (size_t i = 0; i < g->nsegs; i++) {
			size_t c0[3], c1[3];

			cell_range(g, &g->segs[i], c0, c1);
			for (size_t z = c0[2]; z <= c1[2]; z++)
				for (size_t y = c0[1]; y <= c1[1]; y++)
					for (size_t x = c0[0]; x <= c1[0]; x++) {
						size_t c = cell_index(g, x, y, z);

						if (pass == 0)
							g->start[c + 1]++;
						else
							g->items[g->start[c + 1]++] = i;
					}
		}
		if (pass == 0) {
			for (size_t c = 0; c < ncells; c++) {
				size_t k = g->start[c + 1];

				g->start[c + 1] = total;
				total += k;
			}
			g->items = malloc((total ? total : 1) * sizeof(*g->items));
			if (!g->items) {
				live_grid_finish(g);
				return -ENOMEM;
			}
		}
	}
	return 0;
}

/* |p - q| - r(q), q the nearest point of s's axis; f its fraction along s. */
static double seg_metric(const struct live_segment *s, struct vec3 p, double *f)
{
	double ee = vec3_dot(s->e, s->e), u = 0.0;
	struct vec3 d = vec3_sub(p, s->a);

	if (ee > 0) {
		u = vec3_dot(d, s->e) / ee;
		u = u > 0 ? (u < 1 ? u : 1.0) : 0.0;
	}
	*f = u;
	return vec3_len(vec3_sub(d, vec3_scale(s->e, u))) - (s->r0 + (s->r1 - s->r0) * u);
}

/* The distance from p to the box [lo, hi] (0 inside). */
static double box_dist(struct vec3 p, const double lo[3], const double hi[3])
{
	double q[3] = { p.x, p.y, p.z }, d2 = 0.0;

	for (int a = 0; a < 3; a++) {
		double d = q[a] < lo[a] ? lo[a] - q[a] : q[a] > hi[a] ? q[a] - hi[a] : 0.0;

		d2 += d * d;
	}
	return sqrt(d2);
}

/*
 * How near p a segment not listed in cells [c0, c1] can be: the distance from p to the
 * grid's cells outside them (the slabs either side along each axis); INFINITY when none.
 */
static double unvisited_dist(const struct live_grid *g, struct vec3 p, const size_t c0[3],
			     const size_t c1[3])
{
	double glo[3] = { g->lo.x, g->lo.y, g->lo.z }, best = INFINITY;

	for (int a = 0; a < 3; a++) {
		double lo[3], hi[3];

		for (int b = 0; b < 3; b++) {
			lo[b] = glo[b];
			hi[b] = glo[b] + (double)g->dim[b] * g->cell;
		}
		if (c0[a] > 0) {
			hi[a] = glo[a] + (double)c0[a] * g->cell;
			best = fmin(best, box_dist(p, lo, hi));
			hi[a] = glo[a] + (double)g->dim[a] * g->cell;
		}
		if (c1[a] + 1 < g->dim[a]) {
			lo[a] = glo[a] + (double)(c1[a] + 1) * g->cell;
			best = fmin(best, box_dist(p, lo, hi));
		}
	}
	return best;
}

/* Segments of cell (x, y, z) against p. */
static void visit(const struct live_grid *g, size_t x, size_t y, size_t z, struct vec3 p,
		  double *best, size_t *best_seg, double *best_f)
{
	size_t cell = cell_index(g, x, y, z);

	for (size_t i = g->start[cell]; i < g->start[cell + 1]; i++) {
		size_t si = g->items[i];
		double f, m = seg_metric(&g->segs[si], p, &f);

		/* equal: the first segment in tree order */
		if (m < *best || (m == *best && si < *best_seg)) {
			*best = m;
			*best_seg = si;
			*best_f = f;
		}
	}
}

void live_grid_nearest(const struct live_grid *g, struct vec3 p, size_t *branch, double *s)
{
	size_t c[3] = { cell_of(g, p.x, g->lo.x, 0), cell_of(g, p.y, g->lo.y, 1),
			cell_of(g, p.z, g->lo.z, 2) };
	size_t best_seg = 0;
	double best = INFINITY, best_f = 0.0;

	for (size_t k = 0;; k++) {
		size_t c0[3], c1[3];
		bool face[3][2];

		for (int a = 0; a < 3; a++) {
			c0[a] = c[a] > k ? c[a] - k : 0;
			c1[a] = c[a] + k < g->dim[a] ? c[a] + k : g->dim[a] - 1;
			/* whether the shell's face on either side is inside the grid */
			face[a][0] = c[a] >= k;
			face[a][1] = c[a] + k < g->dim[a];
		}
		/* the shell at Chebyshev distance k: the cells with an axis at c +- k */
		for (size_t z = c0[2]; z <= c1[2]; z++) {
			bool zf = (z + k == c[2] && face[2][0]) || (z == c[2] + k && face[2][1]);

			for (size_t y = c0[1]; y <= c1[1]; y++) {
				bool yf = zf || (y + k == c[1] && face[1][0]) ||
					  (y == c[1] + k && face[1][1]);

				if (yf) {
					for (size_t x = c0[0]; x <= c1[0]; x++)
						visit(g, x, y, z, p, &best, &best_seg, &best_f);
					continue;
				}
				if (face[0][0])
					visit(g, c[0] - k, y, z, p, &best, &best_seg, &best_f);
				if (face[0][1] && k > 0)
					visit(g, c[0] + k, y, z, p, &best, &best_seg, &best_f);
			}
		}
		if (best <= unvisited_dist(g, p, c0, c1))
			break;
	}
	*branch = g->segs[best_seg].branch;
	*s = g->segs[best_seg].s0 + best_f * g->segs[best_seg].len;
}
