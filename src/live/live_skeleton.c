/* SPDX-License-Identifier: MIT */
/* The skeleton as the living tree reads it: bands, path lengths, band weights and phases
 * per branch; a skeleton point's data (live.h). */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "live_private.h"
#include "rng.h"

/* Streams of the phases' generator: a branch's and a leaf's never coincide. */
#define PHASE_STREAM_BRANCH 0x6272616e6368ULL /* "branch" */
#define PHASE_STREAM_LEAF 0x6c656166ULL       /* "leaf" */

/* A phase in 1/256 turns from the document's seed, a stream and an element's id. */
static uint8_t phase_of(uint64_t seed, uint64_t stream, size_t id)
{
	struct rng r;

	rng_seed(&r, seed ^ (stream * 0x9e3779b97f4a7c15ULL) ^ ((uint64_t)id * 0xd1b54a32d192ed03ULL));
	return (uint8_t)(rng_next(&r) >> 56);
}

void live_skeleton_finish(struct live_skeleton *sk)
{
	free(sk->branches);
	free(sk->arc);
	free(sk->hmax);
	free(sk->leaf_phase);
	memset(sk, 0, sizeof(*sk));
}

/* Whether branch i hangs on an earlier branch (ids are dense, children after parents). */
static bool has_parent(const struct tree *t, size_t i)
{
	int p = t->branches[i].parent;

	return p >= 0 && (size_t)p < i;
}

static double base_radius(const struct branch *b)
{
	return b->radii && b->npoints > 0 && isfinite(b->radii[0]) && b->radii[0] > 0 ? b->radii[0] : 0.0;
}

/* A branch's own band by its size: radius relative to its trunk's, length to the tree's
 * height (live.h). */
static int own_band(const struct branch *b, double length, const struct branch *trunk,
		    double height)
{
	double rt = base_radius(trunk), r = base_radius(b);
	double rr = rt > 0 ? r / rt : 1.0, lr = height > 0 ? length / height : 1.0;
	double sigma = sqrt(rr * lr);

	if (sigma >= LIVE_BAND1_SIZE)
		return 1;
	return sigma >= LIVE_BAND2_SIZE ? 2 : 3;
}

/* The segment of a polyline of n > 1 points holding arc length s, and the fraction along it. */
static size_t locate(const double *arc, size_t n, double s, double *f)
{
	size_t lo = 0, hi = n - 1;
	double seg;

	if (!(s > 0)) {
		*f = 0.0;
		return 0;
	}
	if (s >= arc[hi]) {
		*f = 1.0;
		return hi - 1;
	}
	/* invariant: arc[lo] <= s < arc[hi] */
	while (hi - lo > 1) {
		size_t mid = lo + (hi - lo) / 2;

		if (arc[mid] <= s)
			lo = mid;
		else
			hi = mid;
	}
	seg = arc[lo + 1] - arc[lo];
	*f = seg > 0 ? (s - arc[lo]) / seg : 0.0;
	return lo;
}

struct vec3 live_branch_point(const struct live_skeleton *sk, const struct branch *b, size_t id,
			      double s)
{
	size_t j;
	double f;

	if (b->npoints < 2)
		return b->npoints ? b->points[0] : vec3(0, 0, 0);
	j = locate(&sk->arc[sk->branches[id].first], b->npoints, s, &f);
	return f >= 1.0 ? b->points[j + 1] : vec3_lerp(b->points[j], b->points[j + 1], f);
}

/*
 * The height (world y, as its chain gives it) of branch id's point at arc length s, and
 * the highest along its chain from the foot up to it: a branch that droops hangs from
 * its highest point, and the tree's bending does not lessen along it.
 */
static double chain_height(const struct live_skeleton *sk, const struct branch *b, size_t id,
			   double s)
{
	const struct live_branch *lb = &sk->branches[id];
	struct vec3 p = live_branch_point(sk, b, id, s);
	double h = p.y + lb->dy;

	if (b->npoints > 1) {
		double f;
		size_t j = locate(&sk->arc[lb->first], b->npoints, s, &f);

		h = fmax(h, sk->hmax[lb->first + (f >= 1.0 ? j + 1 : j)]);
	} else if (b->npoints == 1) {
		h = fmax(h, sk->hmax[lb->first]);
	}
	return h;
}

/* Arc length on its parent (lp) where branch b hangs. */
static double parent_arc(const struct branch *b, const struct live_branch *lp)
{
	double sp = fmin(fmax(b->parent_t, 0.0), 1.0) * lp->length;

	return isfinite(sp) ? sp : 0.0;
}

/* Band weights w_1..w_3 of branch i at arc length s: wb, plus in its own band the path
 * from where it leaves its parent's bark. */
static void band_weights(const struct live_branch *lb, double s, double w[LIVE_BANDS])
{
	for (int k = 1; k < LIVE_BANDS; k++)
		w[k] = lb->wb[k] + (k == lb->band && s > lb->exit ? s - lb->exit : 0.0);
}

/* How far p is outside the tube of branch b (its radius there), and > 0 outside. */
static double outside(const struct branch *b, struct vec3 p)
{
	double best = INFINITY;

	for (size_t j = 0; j + 1 < b->npoints; j++) {
		struct vec3 e = vec3_sub(b->points[j + 1], b->points[j]), d = vec3_sub(p, b->points[j]);
		double ee = vec3_dot(e, e), f = ee > 0 ? vec3_dot(d, e) / ee : 0.0, r0, r1;

		f = f > 0 ? (f < 1 ? f : 1.0) : 0.0;
		r0 = b->radii ? b->radii[j] : 0.0;
		r1 = b->radii ? b->radii[j + 1] : 0.0;
		best = fmin(best, vec3_len(vec3_sub(d, vec3_scale(e, f))) - (r0 + (r1 - r0) * f));
	}
	return b->npoints == 1 ? vec3_dist(p, b->points[0]) - (b->radii ? b->radii[0] : 0.0) : best;
}

/*
 * Where branch b (arc lengths arc) leaves its parent's tube: the first arc length at which
 * its axis is farther from the parent's axis than the parent's radius there (between two
 * points, where the excess crosses 0); its length if it never does.
 */
static double exit_arc(const struct branch *b, const double *arc, const struct branch *parent)
{
	double prev = 0.0;

	for (size_t j = 0; j < b->npoints; j++) {
		double m = outside(parent, b->points[j]);

		if (!(m <= 0)) {
			if (j == 0 || !isfinite(m))
				return 0.0;
			return arc[j - 1] + (arc[j] - arc[j - 1]) * (-prev / (m - prev));
		}
		prev = m;
	}
	return b->npoints ? arc[b->npoints - 1] : 0.0;
}

int live_skeleton_init(struct live_skeleton *sk, const struct tree *t, uint64_t seed)
{
	size_t narc = 0;
	int *root;

	memset(sk, 0, sizeof(*sk));
	for (size_t i = 0; i < t->nbranches; i++)
		narc += t->branches[i].npoints;
	sk->branches = calloc(t->nbranches ? t->nbranches : 1, sizeof(*sk->branches));
	sk->arc = malloc((narc ? narc : 1) * sizeof(*sk->arc));
	sk->hmax = malloc((narc ? narc : 1) * sizeof(*sk->hmax));
	sk->leaf_phase = malloc(t->nleaves ? t->nleaves : 1);
	root = malloc((t->nbranches ? t->nbranches : 1) * sizeof(*root));
	if (!sk->branches || !sk->arc || !sk->hmax || !sk->leaf_phase || !root) {
		free(root);
		live_skeleton_finish(sk);
		return -ENOMEM;
	}
	sk->nbranches = t->nbranches;
	sk->narc = narc;
	sk->nleaves = t->nleaves;
	if (t->nbranches > 0 && t->branches[0].npoints > 0)
		sk->foot_y = t->branches[0].points[0].y;

	/* First the path lengths and chain heights (a parent comes before its children)... */
	narc = 0;
	for (size_t i = 0; i < t->nbranches; i++) {
		const struct branch *b = &t->branches[i];
		struct live_branch *lb = &sk->branches[i];
		double acc = 0.0, high = -INFINITY;

		lb->first = narc;
		for (size_t j = 0; j < b->npoints; j++) {
			if (j > 0)
				acc += vec3_dist(b->points[j - 1], b->points[j]);
			sk->arc[narc++] = acc;
		}
		lb->length = acc;
		root[i] = (int)i; /* a trunk: band 0, from its own foot */
		if (has_parent(t, i)) {
			size_t p = (size_t)b->parent;
			const struct live_branch *lp = &sk->branches[p];
			const struct branch *pb = &t->branches[p];
			double sp = parent_arc(b, lp);

			root[i] = root[p];
			lb->exit = exit_arc(b, &sk->arc[lb->first], pb);
			lb->d0 = lp->d0 + sp;
			lb->dy = b->npoints ? live_branch_point(sk, pb, p, sp).y + lp->dy - b->points[0].y
					    : 0.0;
			high = chain_height(sk, pb, p, sp);
		}
		for (size_t j = 0; j < b->npoints; j++) {
			high = fmax(high, b->points[j].y + lb->dy);
			sk->hmax[lb->first + j] = high;
		}
		sk->d_max = fmax(sk->d_max, lb->d0 + lb->length);
		if (isfinite(high))
			sk->height = fmax(sk->height, high - sk->foot_y);
	}
	/* ...then the bands, which measure a branch by the tree's height. */
	for (size_t i = 0; i < t->nbranches; i++) {
		const struct branch *b = &t->branches[i];
		struct live_branch *lb = &sk->branches[i];

		if (has_parent(t, i)) {
			size_t p = (size_t)b->parent;
			const struct live_branch *lp = &sk->branches[p];
			double wp[LIVE_BANDS];
			int own = own_band(b, lb->length, &t->branches[root[i]], sk->height);

			lb->band = own > lp->band ? own : lp->band;
			band_weights(lp, parent_arc(b, lp), wp);
			/* Lower bands go on as at the parent's point; its own band goes on from
			 * there if the parent was in it, else starts here with a phase of its own. */
			for (int k = 1; k < LIVE_BANDS; k++) {
				if (k < lb->band || (k == lb->band && lp->band == k)) {
					lb->wb[k] = wp[k];
					lb->phase[k] = lp->phase[k];
				} else if (k == lb->band) {
					lb->phase[k] = phase_of(seed, PHASE_STREAM_BRANCH, i);
				}
			}
		}
		sk->counts[lb->band]++;
	}
	for (size_t i = 0; i < t->nleaves; i++)
		sk->leaf_phase[i] = phase_of(seed, PHASE_STREAM_LEAF, i);
	free(root);
	return 0;
}

bool live_skeleton_vertex(const struct live_skeleton *sk, const struct tree *t, size_t b, double s,
			  struct live_vertex *out)
{
	const struct live_branch *lb;
	struct vec3 p;
	double h, w[LIVE_BANDS];

	if (b >= sk->nbranches || b >= t->nbranches)
		return false;
	lb = &sk->branches[b];
	s = s > 0 ? (s < lb->length ? s : lb->length) : 0.0; /* NaN: 0 */
	p = live_branch_point(sk, &t->branches[b], b, s);
	memset(out, 0, sizeof(*out));
	out->point[0] = (float)p.x;
	out->point[1] = (float)p.y;
	out->point[2] = (float)p.z;
	out->d = (float)(lb->d0 + s);
	h = chain_height(sk, &t->branches[b], b, s) - sk->foot_y;
	h = h > 0 ? (h < sk->height ? h : sk->height) : 0.0;
	out->w[0] = sk->height > 0 ? (float)((h / sk->height) * (h / sk->height)) : 0.0f;
	band_weights(lb, s, w);
	for (int k = 1; k < LIVE_BANDS; k++) {
		out->w[k] = (float)w[k];
		out->phase[k] = lb->phase[k];
	}
	return true;
}

void live_snorm(struct vec3 n, int8_t out[4])
{
	n = vec3_norm_or(n, vec3(0, 0, 0));
	out[0] = (int8_t)lround(n.x * 127.0);
	out[1] = (int8_t)lround(n.y * 127.0);
	out[2] = (int8_t)lround(n.z * 127.0);
	out[3] = 0;
}

bool live_skeleton_leaf(const struct live_skeleton *sk, const struct tree *t, size_t i,
			struct vec3 normal, struct live_vertex *out)
{
	const struct leaf *l;
	double s;

	if (i >= t->nleaves || i >= sk->nleaves)
		return false;
	l = &t->leaves[i];
	if (l->branch < 0 || (size_t)l->branch >= t->nbranches || (size_t)l->branch >= sk->nbranches)
		return false;
	s = l->branch_t * sk->branches[l->branch].length;
	if (!live_skeleton_vertex(sk, t, (size_t)l->branch, isfinite(s) ? s : 0.0, out))
		return false;
	out->phase[0] = sk->leaf_phase[i];
	live_snorm(normal, out->flutter);
	return true;
}
