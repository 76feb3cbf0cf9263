/* SPDX-License-Identifier: MIT */
#include "sketch.h"

#include <errno.h>
#include <stdlib.h>

#include "gesture.h"
#include "sketch_seen.h"
#include "tree_index.h"

/* Trunk root radius relative to its length, and how much thinner the tip gets. */
#define TRUNK_RADIUS_PER_M 0.04
#define MIN_ROOT_RADIUS_M 0.015
#define TIP_RADIUS_FRACTION 0.2
#define CHILD_RADIUS_FRACTION 0.7
/* A branch is never thicker at its root than a quarter of its length: a short twig on a
 * thick limb is a twig, not a stump. */
#define MAX_ROOT_RADIUS_PER_LENGTH 0.25

int sketch_resample(const struct vec3 *in, size_t n, double step, struct vec3 **out, size_t *nout)
{
	double len = vec3_polyline_length(in, n);
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

void sketch_smooth(struct vec3 *p, size_t n, bool closed)
{
	/* A turn sharper than this is a corner the child meant, and stays. */
	const double corner_cos = cos(SKETCH_CORNER_DEG * VEC_PI / 180.0);
	struct vec3 prev, cur;

	if (n < 3)
		return;
	for (int pass = 0; pass < SKETCH_SMOOTH_PASSES; pass++) {
		size_t first = closed ? 0 : 1, last = closed ? n : n - 1;

		prev = closed ? p[n - 1] : p[0];
		for (size_t i = first; i < last; i++) {
			struct vec3 next = closed ? p[(i + 1) % n] : p[i + 1];
			struct vec3 d0 = vec3_sub(p[i], prev), d1 = vec3_sub(next, p[i]);
			double l = vec3_len(d0) * vec3_len(d1);

			cur = p[i];
			if (l > 0 && vec3_dot(d0, d1) / l >= corner_cos)
				p[i] = vec3_add(vec3_scale(cur, 0.5), vec3_scale(vec3_add(prev, next), 0.25));
			prev = cur;
		}
	}
}

bool sketch_is_closed(const struct vec3 *p, size_t n)
{
	double len, gap, area = 0.0;

	if (n < 4)
		return false;
	len = vec3_polyline_length(p, n);
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

/* Every segment in order, squared distances; the first of equal ones wins. */
static struct sketch_hit nearest_scan(const struct tree *t, struct vec3 p, double *best_d2)
{
	struct sketch_hit best = { .branch = -1, .dist = INFINITY };

	*best_d2 = INFINITY;
	for (size_t b = 0; b < t->nbranches; b++) {
		const struct vec3 *q = t->branches[b].points;

		for (size_t i = 0; i + 1 < t->branches[b].npoints; i++) {
			double s, d2 = tree_segment_d2(q[i], q[i + 1], p, &s);

			if (d2 < *best_d2) {
				*best_d2 = d2;
				best.branch = (int)b;
				best.segment = i;
				best.seg_t = s;
			}
		}
	}
	return best;
}

/* The rest of the hit, only for the winner. */
static struct sketch_hit nearest_finish(const struct tree *t, struct sketch_hit best, double d2)
{
	double walked = 0.0, total = 0.0;
	const struct branch *br;

	if (best.branch < 0)
		return best;
	br = &t->branches[best.branch];
	best.point = vec3_lerp(br->points[best.segment], br->points[best.segment + 1], best.seg_t);
	best.dist = sqrt(d2);
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

struct sketch_hit sketch_nearest_scan(const struct tree *t, struct vec3 p)
{
	double d2;
	struct sketch_hit best = nearest_scan(t, p, &d2);

	return nearest_finish(t, best, d2);
}

struct sketch_hit sketch_nearest(const struct tree *t, struct vec3 p)
{
	struct tree_index_hit h;
	struct sketch_hit best = { .branch = -1, .dist = INFINITY };

	/* a tree that keeps a grid of its segments looks only near p: the same answer */
	if (!tree_index_nearest(t, p, &h))
		return sketch_nearest_scan(t, p);
	best.branch = h.branch;
	best.segment = h.segment;
	best.seg_t = h.seg_t;
	return nearest_finish(t, best, h.d2);
}

static double radius_at(const struct branch *b, const struct sketch_hit *h)
{
	double r0 = b->radii[h->segment];
	double r1 = b->radii[h->segment + 1 < b->npoints ? h->segment + 1 : h->segment];

	return r0 + (r1 - r0) * h->seg_t;
}

/* A branch's radius at arc-length parameter s (0..1). */
static double radius_at_param(const struct branch *b, double s)
{
	double len = vec3_polyline_length(b->points, b->npoints), want = s * len, walked = 0.0;

	for (size_t i = 0; i + 1 < b->npoints; i++) {
		double seg = vec3_dist(b->points[i], b->points[i + 1]);

		if (walked + seg >= want && seg > 0)
			return b->radii[i] + (b->radii[i + 1] - b->radii[i]) * (want - walked) / seg;
		walked += seg;
	}
	return b->radii[b->npoints - 1];
}

/* Radius at s (0..1) as a fraction of the root's: the drawn profile once there is one. */
static double profile_at(const struct tree *t, double s)
{
	double x, f;
	int i;

	if (!t->has_profile)
		return 1.0 - (1.0 - TIP_RADIUS_FRACTION) * s;
	x = s * (TREE_PROFILE_N - 1);
	i = (int)x;
	if (i >= TREE_PROFILE_N - 1)
		return t->profile[TREE_PROFILE_N - 1];
	f = x - i;
	return t->profile[i] + (t->profile[i + 1] - t->profile[i]) * f;
}

/*
 * Adds p as a branch: the trunk if the tree is empty, otherwise attached to the nearest
 * branch point. radii, when given, are the drawn ones (two-stroke branches); otherwise
 * the root radius follows from the parent and the profile gives the rest.
 */
static int add_branch(struct tree *t, const struct sketch_seen *sv, struct vec3 *p, size_t n,
		      const double *drawn)
{
	double len = vec3_polyline_length(p, n), walked = 0.0, root_r;
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

		hit = sketch_nearest(sv->tree, p[0]);
		if (hit.branch < 0) {
			free(radii);
			return 0;
		}
		/* In 3D the stroke lies on the plane through the attachment point that faces
		 * the camera (view space looks along -z). */
		for (size_t i = 0; i < n; i++)
			p[i].z = hit.point.z;
		shift = vec3_sub(hit.point, p[0]);
		for (size_t i = 0; i < n; i++) {
			double w = len > 0 ? 1.0 - walked / len : 0.0;

			if (i + 1 < n)
				walked += vec3_dist(p[i], p[i + 1]);
			p[i] = vec3_add(p[i], vec3_scale(shift, w));
		}
		root_r = fmax(MIN_ROOT_RADIUS_M,
			      CHILD_RADIUS_FRACTION * radius_at(&t->branches[hit.branch], &hit));
		len = vec3_polyline_length(p, n);
	}
	root_r = fmin(root_r, MAX_ROOT_RADIUS_PER_LENGTH * len);
	walked = 0.0;
	for (size_t i = 0; i < n; i++) {
		double s = len > 0 ? walked / len : 0.0;

		radii[i] = drawn ? fmin(fmax(drawn[i], MIN_ROOT_RADIUS_M / 4), MAX_ROOT_RADIUS_PER_LENGTH * len)
				 : root_r * profile_at(t, s);
		if (i + 1 < n)
			walked += vec3_dist(p[i], p[i + 1]);
	}
	for (size_t i = 0; i < n; i++)
		p[i] = camera_from_view(&sv->xf, p[i]);
	ret = tree_add_branch(t, hit.branch, hit.branch >= 0 ? hit.param : 0.0, ORIGIN_SKETCH, p,
			      radii, n);
	free(radii);
	if (ret < 0)
		return ret;
	t->last_sketched = ret;
	return 0;
}

static int add_leaf(struct tree *t, const struct sketch_seen *sv, struct vec3 *p, size_t n)
{
	struct sketch_hit best = { .branch = -1, .dist = INFINITY };
	int ret;

	if (t->nbranches == 0)
		return 0; /* nothing to hang it on */
	for (size_t i = 0; i < n; i++) {
		struct sketch_hit h = sketch_nearest(sv->tree, p[i]);

		if (h.dist < best.dist)
			best = h;
	}
	if (best.branch < 0)
		return 0;
	for (size_t i = 0; i < n; i++) {
		p[i].z = best.point.z; /* see add_branch */
		p[i] = camera_from_view(&sv->xf, p[i]);
	}
	/* The polygon closes itself: drop the end point that returned to the start. */
	ret = tree_add_leaf(t, best.branch, ORIGIN_SKETCH, p, n - 1);
	if (ret < 0)
		return ret;
	t->leaves[ret].branch_t = best.param;
	/* in the branch's frame, so it follows the branch when it moves (lifting to 3D) */
	return tree_leaf_attach(t, (size_t)ret);
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

static int erase(struct tree *t, struct sketch_seen *sv, const struct sketch_stroke *st)
{
	struct vec3 *p = NULL;
	size_t n;
	int ret;

	ret = sketch_resample(st->points, st->npoints, SKETCH_STEP_M, &p, &n);
	if (ret == -EINVAL)
		return SKETCH_GREW;
	if (ret < 0)
		return ret;
	sketch_seen_show_all(sv); /* the eraser looks at everything */
	ret = gesture_eraser(t, sv->tree, p, n);
	free(p);
	return ret < 0 ? ret : ret > 0 ? SKETCH_CHANGED : SKETCH_GREW;
}

/* The point at fraction s (0..1) of a polyline's arc length. */
static struct vec3 point_at(const struct vec3 *p, size_t n, double len, double s)
{
	double want = s * len, walked = 0.0;

	for (size_t i = 0; i + 1 < n; i++) {
		double seg = vec3_dist(p[i], p[i + 1]);

		if (walked + seg >= want && seg > 0)
			return vec3_lerp(p[i], p[i + 1], (want - walked) / seg);
		walked += seg;
	}
	return p[n - 1];
}

/*
 * Fig. 4: one branch drawn as its two outlines. The stroke b is taken as the second
 * outline of the branch `prev` the previous stroke drew when it came within
 * SKETCH_OUTLINE_PAUSE_US of it, is about as long, runs the same way, and runs beside
 * it as a branch's two edges do (docs/sketching.md): apart at the root by at least a
 * thin branch's thickness and at most half the length, never opening up toward the
 * tip, and closing in by at most SKETCH_OUTLINE_MAX_TAPER. A fan or a V of branches drawn
 * one after the other meets at the root and opens up, so it stays two branches.
 * Returns 1 when it merged them, 0 when not, or -ENOMEM.
 */
static int outline_pair(struct tree *t, struct sketch_seen *sv, const struct vec3 *b, size_t nb,
			uint64_t start_us, int prev)
{
	enum { N = 48 };
	const struct branch *a;
	struct vec3 axis[N], a0, a1, b0, b1, ca, cb;
	double radii[N], gap[N], la, lb, lmin, cosang, narrowest;
	bool reversed;
	bool *remove;
	int ret;

	if (prev < 0 || (size_t)prev + 1 != t->nbranches || start_us < t->last_sketched_end_us ||
	    start_us - t->last_sketched_end_us > SKETCH_OUTLINE_PAUSE_US)
		return 0;
	a = &sv->tree->branches[prev];
	la = vec3_polyline_length(a->points, a->npoints);
	lb = vec3_polyline_length(b, nb);
	lmin = fmin(la, lb);
	if (lmin <= 0 || la > 1.6 * lb || lb > 1.6 * la)
		return 0;
	a0 = a->points[0];
	a1 = a->points[a->npoints - 1];
	/* the second outline may be drawn either way */
	reversed = vec3_dist(a0, b[nb - 1]) + vec3_dist(a1, b[0]) < vec3_dist(a0, b[0]) + vec3_dist(a1, b[nb - 1]);
	b0 = reversed ? b[nb - 1] : b[0];
	b1 = reversed ? b[0] : b[nb - 1];
	ca = vec3_sub(a1, a0);
	cb = vec3_sub(b1, b0);
	cosang = vec3_dot(ca, cb) / (vec3_len(ca) * vec3_len(cb) + 1e-12);
	if (cosang < cos(SKETCH_OUTLINE_MAX_CHORD_DEG * VEC_PI / 180.0))
		return 0;
	for (int i = 0; i < N; i++) {
		double s = (double)i / (N - 1);
		struct vec3 pa = point_at(a->points, a->npoints, la, s);
		struct vec3 pb = point_at(b, nb, lb, reversed ? 1.0 - s : s);

		/* compared on the screen: on a 3D tree the first outline lies at its parent's
		 * depth, the second is still on the screen's plane */
		pb.z = pa.z;
		gap[i] = vec3_dist(pa, pb);
		axis[i] = vec3_lerp(pa, pb, 0.5);
	}
	/* as far apart at the root as a branch is thick: more than the thinnest branch, a
	 * root radius of at most a quarter of the length, and no wider than the parent there
	 * (two branches drawn one above the other on a trunk are as parallel as outlines) */
	if (gap[0] < SKETCH_OUTLINE_MIN_GAP_M ||
	    0.5 * gap[0] > MAX_ROOT_RADIUS_PER_LENGTH * vec3_polyline_length(axis, N))
		return 0;
	if (a->parent >= 0 &&
	    0.5 * gap[0] > radius_at_param(&sv->tree->branches[a->parent], a->parent_t))
		return 0;
	/* never wider than anywhere nearer the root (but for a hand's wobble), and not
	 * closing in to a point */
	narrowest = gap[0];
	for (int i = 1; i < N; i++) {
		if (gap[i] > SKETCH_OUTLINE_WIDEN * narrowest + SKETCH_OUTLINE_WOBBLE_M)
			return 0;
		narrowest = fmin(narrowest, gap[i]);
	}
	if (gap[N - 1] * SKETCH_OUTLINE_MAX_TAPER < gap[0])
		return 0;
	/* the radius the wobble left: non-increasing from the root */
	radii[0] = 0.5 * gap[0];
	for (int i = 1; i < N; i++)
		radii[i] = fmin(radii[i - 1], 0.5 * gap[i]);

	/* The first outline's branch becomes the branch between the two. */
	remove = calloc(t->nbranches, sizeof(*remove));
	if (!remove)
		return -ENOMEM;
	remove[prev] = true;
	ret = tree_remove_branches(t, remove);
	free(remove);
	if (ret < 0)
		return ret;
	sketch_seen_drop_last_branch(sv);
	ret = add_branch(t, sv, axis, N, radii);
	if (ret < 0)
		return ret;
	/* Later single strokes taper like this one (radius relative to the root's). */
	for (int i = 0; i < TREE_PROFILE_N; i++) {
		double x = (double)i * (N - 1) / (TREE_PROFILE_N - 1);
		int k = (int)x;
		double r = k + 1 < N ? radii[k] + (radii[k + 1] - radii[k]) * (x - k) : radii[N - 1];

		/* never 0: a twig, not a needle */
		t->profile[i] = fmin(fmax(r / radii[0], 0.25 * TIP_RADIUS_FRACTION), 1.0);
	}
	t->has_profile = true;
	return 1;
}

/*
 * An open stroke is a new branch if it starts on a branch (within GESTURE_SNAP_M), if its
 * first crossing comes within 2 x GESTURE_SNAP_M of its start (a child who began just
 * beside the parent and drew across it), or if it crosses nothing. Otherwise it is a
 * cut/erase gesture: a slash that begins away from the wood. So a branch drawn from its
 * parent is never a cut, even when it crosses other branches further on.
 */
static int open_stroke(struct tree *t, struct sketch_seen *sv, struct vec3 *p, size_t n,
		       uint64_t start_us, int prev)
{
	struct gesture_crossing *c;
	double first = INFINITY;
	size_t nc;
	int ret;

	ret = outline_pair(t, sv, p, n, start_us, prev);
	if (ret != 0)
		return ret < 0 ? ret : SKETCH_CHANGED;

	if (t->nbranches == 0 || sketch_nearest(sv->tree, p[0]).dist <= GESTURE_SNAP_M)
		return add_branch(t, sv, p, n, NULL);
	sketch_seen_show_all(sv); /* crossings look at every branch */
	ret = gesture_crossings(sv->tree, p, n, &c, &nc);
	if (ret < 0)
		return ret;
	for (size_t i = 0; i < nc; i++)
		first = fmin(first, c[i].along);
	free(c);
	if (nc == 0 || first <= 2 * GESTURE_SNAP_M)
		return add_branch(t, sv, p, n, NULL);
	ret = gesture_cut_erase(t, sv->tree, p, n);
	return ret < 0 ? ret : SKETCH_CHANGED;
}

/* The stroke's points on the screen's sketch plane (view space), resampled and smoothed.
 * 1 = got a stroke, 0 = nothing to draw, <0 error. */
static int prepare(const struct sketch_stroke *st, size_t sketched, struct vec3 **out,
		   size_t *nout, bool *closed)
{
	struct vec3 *p = NULL;
	size_t n;
	int ret;

	if (st->npoints < 2)
		return 0;
	if (vec3_polyline_length(st->points, st->npoints) < SKETCH_MIN_LENGTH_M)
		return 0;
	ret = sketch_resample(st->points, st->npoints, SKETCH_STEP_M, &p, &n);
	if (ret == -EINVAL)
		return 0;
	if (ret < 0)
		return ret;
	if (sketched + n > SKETCH_MAX_TREE_POINTS) {
		free(p);
		return 0;
	}
	*closed = sketch_is_closed(p, n);
	sketch_smooth(p, n, *closed);
	*out = p;
	*nout = n;
	return 1;
}

int sketch_stroke(struct tree *t, const struct sketch_stroke *st)
{
	struct sketch_seen sv;
	struct vec3 *p = NULL;
	size_t n = 0;
	bool closed = false;
	int ret, sketched;

	if (st->npoints == 0)
		return SKETCH_GREW;
	/* Only a branch drawn by the stroke right before can get a second outline. */
	sketched = t->last_sketched;
	t->last_sketched = -1;
	if (st->tool != EVENT_TOOL_ERASER) {
		ret = prepare(st, sketched_points(t), &p, &n, &closed);
		if (ret <= 0)
			return ret < 0 ? ret : SKETCH_GREW;
	}
	/* On a turned 3D tree everything is decided as the screen shows it. */
	ret = sketch_seen_init(&sv, t, st->camera);
	if (ret < 0) {
		free(p);
		return ret;
	}
	if (st->tool == EVENT_TOOL_ERASER)
		ret = erase(t, &sv, st);
	else if (closed)
		ret = add_leaf(t, &sv, p, n);
	else
		ret = open_stroke(t, &sv, p, n, st->time_us, sketched);
	sketch_seen_finish(&sv);
	free(p);
	if (t->last_sketched >= 0) /* this stroke drew a branch */
		t->last_sketched_end_us = st->end_us;
	return ret < 0 ? ret : ret == SKETCH_CHANGED ? SKETCH_CHANGED : SKETCH_GREW;
}
