/* SPDX-License-Identifier: MIT */
#include "sketch.h"

#include <errno.h>

#include "gesture.h"
#include <stdlib.h>

/* Trunk root radius relative to its length, and how much thinner the tip gets. */
#define TRUNK_RADIUS_PER_M 0.04
#define MIN_ROOT_RADIUS_M 0.015
#define TIP_RADIUS_FRACTION 0.2
#define CHILD_RADIUS_FRACTION 0.7

static double polyline_length(const struct vec3 *p, size_t n)
{
	double len = 0.0;

	for (size_t i = 1; i < n; i++)
		len += vec3_dist(p[i - 1], p[i]);
	return len;
}

int sketch_resample(const struct vec3 *in, size_t n, double step, struct vec3 **out, size_t *nout)
{
	double len = polyline_length(in, n);
	size_t count, k = 0;
	struct vec3 *p;
	double next, walked = 0.0;

	if (!isfinite(len) || !(step > 0))
		return -EINVAL;
	if (len / step > SKETCH_MAX_SAMPLES - 2)
		step = len / (SKETCH_MAX_SAMPLES - 2);
	count = (size_t)(len / step) + 2;
	next = step;
	p = malloc(count * sizeof(*p));
	if (!p)
		return -ENOMEM;
	if (n == 0) {
		*out = p;
		*nout = 0;
		return 0;
	}
	p[k++] = in[0];
	for (size_t i = 1; i < n; i++) {
		double seg = vec3_dist(in[i - 1], in[i]);

		while (seg > 0.0 && walked + seg >= next && k < count - 1) {
			p[k++] = vec3_lerp(in[i - 1], in[i], (next - walked) / seg);
			next += step;
		}
		walked += seg;
	}
	/* Keep the drawn end exactly, replacing a sample that falls right on it. */
	if (k > 1 && vec3_dist(p[k - 1], in[n - 1]) < 0.25 * step)
		k--;
	p[k++] = in[n - 1];
	*out = p;
	*nout = k;
	return 0;
}

bool sketch_is_closed(const struct vec3 *p, size_t n)
{
	double len, gap, area = 0.0;

	if (n < 4)
		return false;
	len = polyline_length(p, n);
	gap = vec3_dist(p[0], p[n - 1]);
	if (!(gap < 0.2 * len && gap < 0.4))
		return false;
	/* Returning near the start is not enough: a V or a zigzag does too. A leaf encloses
	 * area; area / perimeter^2 is 1/(4 pi) = 0.08 for a circle, 0.037 for a 4:1 ellipse
	 * and under 0.02 for a V. */
	for (size_t i = 0; i < n; i++) {
		const struct vec3 *a = &p[i], *b = &p[(i + 1) % n];

		area += a->x * b->y - b->x * a->y;
	}
	return fabs(area) / 2 > SKETCH_MIN_LEAF_ROUNDNESS * len * len;
}

struct sketch_hit sketch_nearest(const struct tree *t, struct vec3 p)
{
	struct sketch_hit best = { .branch = -1, .dist = INFINITY };
	double best_d2 = INFINITY, walked = 0.0, total = 0.0;
	const struct branch *br;

	/* Squared distances in the hot loop; the rest only for the winner. */
	for (size_t b = 0; b < t->nbranches; b++) {
		const struct vec3 *q = t->branches[b].points;

		for (size_t i = 0; i + 1 < t->branches[b].npoints; i++) {
			double dx = q[i + 1].x - q[i].x, dy = q[i + 1].y - q[i].y;
			double dd = dx * dx + dy * dy;
			double s = dd > 0 ? ((p.x - q[i].x) * dx + (p.y - q[i].y) * dy) / dd : 0.0;
			double ex, ey, d2;

			s = s < 0 ? 0 : s > 1 ? 1 : s;
			ex = q[i].x + s * dx - p.x;
			ey = q[i].y + s * dy - p.y;
			d2 = ex * ex + ey * ey;
			if (d2 < best_d2) {
				best_d2 = d2;
				best.branch = (int)b;
				best.segment = i;
				best.seg_t = s;
			}
		}
	}
	if (best.branch < 0)
		return best;
	br = &t->branches[best.branch];
	best.point = vec3_lerp(br->points[best.segment], br->points[best.segment + 1], best.seg_t);
	best.dist = sqrt(best_d2);
	for (size_t i = 0; i + 1 < br->npoints; i++) {
		double seg = vec3_dist(br->points[i], br->points[i + 1]);

		if (i < best.segment)
			walked += seg;
		else if (i == best.segment)
			walked += best.seg_t * seg;
		total += seg;
	}
	best.param = total > 0 ? walked / total : 0.0;
	return best;
}

static double radius_at(const struct branch *b, const struct sketch_hit *h)
{
	double r0 = b->radii[h->segment];
	double r1 = b->radii[h->segment + 1 < b->npoints ? h->segment + 1 : h->segment];

	return r0 + (r1 - r0) * h->seg_t;
}

static int add_branch(struct tree *t, struct vec3 *p, size_t n)
{
	double len = polyline_length(p, n), walked = 0.0, root_r;
	struct sketch_hit hit = { .branch = -1 };
	double *radii = malloc(n * sizeof(*radii));
	int ret;

	if (!radii)
		return -ENOMEM;
	if (t->nbranches == 0) {
		root_r = fmax(MIN_ROOT_RADIUS_M * 2, TRUNK_RADIUS_PER_M * len);
	} else {
		/* Fig. 3a,b: the root moves onto the parent, the tip stays, the rest follows. */
		struct vec3 shift;

		hit = sketch_nearest(t, p[0]);
		if (hit.branch < 0) {
			free(radii);
			return 0;
		}
		shift = vec3_sub(hit.point, p[0]);
		for (size_t i = 0; i < n; i++) {
			double w = len > 0 ? 1.0 - walked / len : 0.0;

			if (i + 1 < n)
				walked += vec3_dist(p[i], p[i + 1]);
			p[i] = vec3_add(p[i], vec3_scale(shift, w));
		}
		root_r = fmax(MIN_ROOT_RADIUS_M,
			      CHILD_RADIUS_FRACTION * radius_at(&t->branches[hit.branch], &hit));
		len = polyline_length(p, n);
	}
	walked = 0.0;
	for (size_t i = 0; i < n; i++) {
		double s = len > 0 ? walked / len : 0.0;

		radii[i] = root_r * (1.0 - (1.0 - TIP_RADIUS_FRACTION) * s);
		if (i + 1 < n)
			walked += vec3_dist(p[i], p[i + 1]);
	}
	ret = tree_add_branch(t, hit.branch, hit.branch >= 0 ? hit.param : 0.0, ORIGIN_SKETCH, p,
			      radii, n);
	free(radii);
	return ret < 0 ? ret : 0;
}

static int add_leaf(struct tree *t, const struct vec3 *p, size_t n)
{
	struct sketch_hit best = { .branch = -1, .dist = INFINITY };
	int ret;

	if (t->nbranches == 0)
		return 0; /* nothing to hang it on */
	for (size_t i = 0; i < n; i++) {
		struct sketch_hit h = sketch_nearest(t, p[i]);

		if (h.dist < best.dist)
			best = h;
	}
	if (best.branch < 0)
		return 0;
	/* The polygon closes itself: drop the end point that returned to the start. */
	ret = tree_add_leaf(t, best.branch, ORIGIN_SKETCH, p, n - 1);
	if (ret < 0)
		return ret;
	t->leaves[ret].branch_t = best.param;
	return 0;
}

static size_t sketched_points(const struct tree *t)
{
	size_t n = 0;

	for (size_t i = 0; i < t->nbranches; i++)
		n += t->branches[i].origin == ORIGIN_SKETCH ? t->branches[i].npoints : 0;
	for (size_t i = 0; i < t->nleaves; i++)
		n += t->leaves[i].origin == ORIGIN_SKETCH ? t->leaves[i].npoints : 0;
	return n;
}

static int erase(struct tree *t, const struct doc_op *op)
{
	struct vec3 *raw = malloc(op->npoints * sizeof(*raw)), *p = NULL;
	size_t n;
	int ret;

	if (!raw)
		return -ENOMEM;
	for (size_t i = 0; i < op->npoints; i++)
		raw[i] = vec3(op->points[i].x, op->points[i].y, 0.0);
	ret = sketch_resample(raw, op->npoints, SKETCH_STEP_M, &p, &n);
	free(raw);
	if (ret == -EINVAL)
		return SKETCH_GREW;
	if (ret < 0)
		return ret;
	ret = gesture_eraser(t, p, n);
	free(p);
	return ret < 0 ? ret : ret > 0 ? SKETCH_CHANGED : SKETCH_GREW;
}

/*
 * An open stroke is a new branch if it starts on a branch (within GESTURE_SNAP_M), if its
 * first crossing comes within 2 x GESTURE_SNAP_M of its start (a child who began just
 * beside the parent and drew across it), or if it crosses nothing. Otherwise it is a
 * cut/erase gesture: a slash that begins away from the wood. So a branch drawn from its
 * parent is never a cut, even when it crosses other branches further on.
 */
static int open_stroke(struct tree *t, struct vec3 *p, size_t n)
{
	struct gesture_crossing *c;
	double first = INFINITY;
	size_t nc;
	int ret;

	if (t->nbranches == 0 || sketch_nearest(t, p[0]).dist <= GESTURE_SNAP_M)
		return add_branch(t, p, n);
	ret = gesture_crossings(t, p, n, &c, &nc);
	if (ret < 0)
		return ret;
	for (size_t i = 0; i < nc; i++)
		first = fmin(first, c[i].along);
	free(c);
	if (nc == 0 || first <= 2 * GESTURE_SNAP_M)
		return add_branch(t, p, n);
	ret = gesture_cut_erase(t, p, n);
	return ret < 0 ? ret : SKETCH_CHANGED;
}

int sketch_apply(struct tree *t, const struct doc_op *op, struct rng *rng)
{
	struct vec3 *raw, *p = NULL;
	size_t n;
	int ret;

	(void)rng;
	if (op->kind != DOC_OP_STROKE || op->npoints == 0)
		return SKETCH_GREW;
	if (op->tool == EVENT_TOOL_ERASER)
		return erase(t, op);
	if (op->npoints < 2)
		return SKETCH_GREW;
	raw = malloc(op->npoints * sizeof(*raw));
	if (!raw)
		return -ENOMEM;
	for (size_t i = 0; i < op->npoints; i++)
		raw[i] = vec3(op->points[i].x, op->points[i].y, 0.0);
	if (polyline_length(raw, op->npoints) < SKETCH_MIN_LENGTH_M) {
		free(raw);
		return 0;
	}
	ret = sketch_resample(raw, op->npoints, SKETCH_STEP_M, &p, &n);
	free(raw);
	if (ret == -EINVAL)
		return 0;
	if (ret < 0)
		return ret;
	if (sketched_points(t) + n > SKETCH_MAX_TREE_POINTS) {
		free(p);
		return 0;
	}
	if (sketch_is_closed(p, n))
		ret = add_leaf(t, p, n);
	else
		ret = open_stroke(t, p, n);
	free(p);
	return ret < 0 ? ret : ret == SKETCH_CHANGED ? SKETCH_CHANGED : SKETCH_GREW;
}
