/* SPDX-License-Identifier: MIT */
#include "gesture.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>

/*
 * Segment a-b against c-d in x/y; on a crossing sets *t (along a-b) and *u (along c-d)
 * and returns true. Parameters are half-open [0, 1) on both, so a polyline passing
 * through a vertex counts once.
 */
static bool segments_cross(struct vec3 a, struct vec3 b, struct vec3 c, struct vec3 d, double *t_ab,
			   double *u)
{
	double rx = b.x - a.x, ry = b.y - a.y, sx = d.x - c.x, sy = d.y - c.y;
	double den = rx * sy - ry * sx, t, v;

	if (fabs(den) < 1e-15)
		return false; /* parallel: touching along a line is not a crossing */
	t = ((c.x - a.x) * sy - (c.y - a.y) * sx) / den;
	v = ((c.x - a.x) * ry - (c.y - a.y) * rx) / den;
	if (t < 0 || t >= 1 || v < 0 || v >= 1)
		return false;
	*t_ab = t;
	*u = v;
	return true;
}

struct box {
	double x0, y0, x1, y1;
};

static struct box bounds(const struct vec3 *p, size_t n, double grow)
{
	struct box b = { INFINITY, INFINITY, -INFINITY, -INFINITY };

	for (size_t i = 0; i < n; i++) {
		b.x0 = fmin(b.x0, p[i].x);
		b.y0 = fmin(b.y0, p[i].y);
		b.x1 = fmax(b.x1, p[i].x);
		b.y1 = fmax(b.y1, p[i].y);
	}
	b.x0 -= grow;
	b.y0 -= grow;
	b.x1 += grow;
	b.y1 += grow;
	return b;
}

static bool overlap(struct box a, struct box b)
{
	return a.x0 <= b.x1 && b.x0 <= a.x1 && a.y0 <= b.y1 && b.y0 <= a.y1;
}

int gesture_crossings(const struct tree *t, const struct vec3 *p, size_t n,
		      struct gesture_crossing **out, size_t *nout)
{
	struct gesture_crossing *c = malloc((t->nbranches + 1) * sizeof(*c));
	struct box sb = bounds(p, n, 0.0);
	size_t k = 0;

	if (!c)
		return -ENOMEM;
	for (size_t b = 0; b < t->nbranches; b++) {
		const struct branch *br = &t->branches[b];
		struct gesture_crossing x = { .branch = (int)b };

		if (!overlap(sb, bounds(br->points, br->npoints, 0.0)))
			continue;
		double along = 0.0;

		x.along = INFINITY;
		for (size_t i = 0; i + 1 < n; i++) {
			double seg = vec3_dist(p[i], p[i + 1]);

			for (size_t j = 0; j + 1 < br->npoints; j++) {
				double u, v;

				if (!segments_cross(p[i], p[i + 1], br->points[j], br->points[j + 1], &v, &u))
					continue;
				x.count++;
				if (along + v * seg < x.along) {
					x.segment = j;
					x.seg_t = u;
					x.along = along + v * seg;
				}
			}
			along += seg;
		}
		if (x.count > 0)
			c[k++] = x;
	}
	*out = c;
	*nout = k;
	return 0;
}

int gesture_cut_erase(struct tree *t, const struct tree *seen, const struct vec3 *p, size_t n)
{
	struct gesture_crossing *c;
	size_t nc;
	int edits = 0, ret;

	/* Every crossed branch once, newest first: an edit removes or renumbers only
	 * branches after the one it edits, so the older ids stay valid. (Crossings are not
	 * looked for again: a cut end lying on the slash must not be cut twice.) */
	ret = gesture_crossings(seen, p, n, &c, &nc);
	if (ret < 0)
		return ret;
	for (size_t k = nc; k-- > 0;) {
		const struct gesture_crossing *x = &c[k];

		if ((size_t)x->branch >= t->nbranches)
			continue; /* defensive: edits only renumber ids above the one edited */
		if (x->count >= 2) {
			bool *remove = calloc(t->nbranches, sizeof(*remove));

			if (!remove) {
				ret = -ENOMEM;
				break;
			}
			remove[x->branch] = true;
			ret = tree_remove_branches(t, remove);
			free(remove);
		} else {
			ret = tree_cut_branch(t, x->branch, x->segment, x->seg_t);
		}
		if (ret < 0)
			break;
		edits++;
	}
	free(c);
	return ret < 0 ? ret : edits;
}

/* Distance in x/y from q to segment a-b. */
static double segment_distance(struct vec3 q, struct vec3 a, struct vec3 b)
{
	double dx = b.x - a.x, dy = b.y - a.y, dd = dx * dx + dy * dy;
	double s = dd > 0 ? ((q.x - a.x) * dx + (q.y - a.y) * dy) / dd : 0.0;

	s = s < 0 ? 0 : s > 1 ? 1 : s;
	return hypot(a.x + s * dx - q.x, a.y + s * dy - q.y);
}

/* Whether any point of poly lies within r of the trail, or the trail enters poly. */
static bool trail_touches(const struct vec3 *trail, size_t n, const struct vec3 *poly, size_t m,
			  double r)
{
	for (size_t j = 0; j < m; j++) {
		if (n == 1 && hypot(poly[j].x - trail[0].x, poly[j].y - trail[0].y) <= r)
			return true;
		for (size_t i = 0; i + 1 < n; i++)
			if (segment_distance(poly[j], trail[i], trail[i + 1]) <= r)
				return true;
	}
	/* ...or the trail runs along the polyline's segments between its points */
	for (size_t i = 0; i < n; i++)
		for (size_t j = 0; j + 1 < m; j++)
			if (segment_distance(trail[i], poly[j], poly[j + 1]) <= r)
				return true;
	return false;
}

int gesture_eraser(struct tree *t, const struct tree *seen, const struct vec3 *p, size_t n)
{
	struct box trail = bounds(p, n, GESTURE_ERASER_RADIUS_M);
	bool *rb = calloc(t->nbranches + 1, sizeof(*rb));
	bool *rl = calloc(t->nleaves + 1, sizeof(*rl));
	int touched = 0, ret = 0;

	if (!rb || !rl) {
		ret = -ENOMEM;
		goto out;
	}
	for (size_t i = 0; i < t->nleaves; i++) {
		const struct leaf *l = &seen->leaves[i];

		if (overlap(trail, bounds(l->points, l->npoints, 0.0)) &&
		    trail_touches(p, n, l->points, l->npoints, GESTURE_ERASER_RADIUS_M)) {
			rl[i] = true;
			touched++;
		}
	}
	for (size_t i = 0; i < t->nbranches; i++) {
		const struct branch *b = &seen->branches[i];

		if (overlap(trail, bounds(b->points, b->npoints, 0.0)) &&
		    trail_touches(p, n, b->points, b->npoints, GESTURE_ERASER_RADIUS_M)) {
			rb[i] = true;
			touched++;
		}
	}
	if (touched == 0)
		goto out;
	tree_remove_leaves(t, rl);
	ret = tree_remove_branches(t, rb);
out:
	free(rb);
	free(rl);
	return ret < 0 ? ret : touched;
}
