/* SPDX-License-Identifier: MIT */
/*
 * Leaf arrangement by example (seed 000, section 3.5).
 *
 * Where a leaf is. A leaf on branch b sits at arc length s = branch_t * L from the
 * branch's root (L: the branch's length). Its angle is the direction of the centroid
 * (vertex average) of its outline's (y, z) in the branch's frame at branch_t
 * (tree_frame_at: y along `normal`, z along `binormal`), atan2(z, y), measured about the
 * tangent. If the centroid is within 1e-9 m of the axis, the outline point farthest from
 * the axis gives the angle; if every point is on the axis, the angle is 0. Its reach is
 * the largest distance of an outline point from the attachment point (the frame's
 * origin). Leaves without `local` are measured as tree_leaf_attach would record them.
 * Angles at different places are each in their own frame: on a bent branch the frame
 * turns with the tangent (tree_frame_at keeps `normal` across the branch in the picture
 * plane), and so does the pattern.
 *
 * Sets. The leaves of b, sorted by s (then by id), are cut into sets: a set starts at its
 * lowest leaf and takes every next leaf whose s is at most `tol` past that first one,
 * tol = max(ARRANGE_SAME_PLACE_M = 0.15 m, ARRANGE_SAME_PLACE_REACH = 0.3 x the mean
 * reach of b's leaves). A set of one leaf is a single leaf. The newest leaf is the one
 * with the highest id (ids keep creation order). Branches shorter than 1e-9 m suggest
 * nothing.
 *
 * whorl-add. Target: of the sets with 2+ leaves, the one holding the newest leaf; when
 * no set has 2+ leaves and b has exactly one leaf, that leaf ("one more, opposite").
 * Several single leaves at different places are an alternate pattern, not a whorl, and do
 * not suggest it. A set of ARRANGE_WHORL_MAX = 16 leaves or more does not either. The set
 * of n gets a copy of its first leaf (lowest id); then all n + 1 stand at the set's mean
 * branch_t, 360 / (n + 1) degrees apart: the first leaf keeps its angle, the others take
 * the following slots counter-clockwise (increasing angle) in the order of their angle
 * counted counter-clockwise from the first leaf's (ties: lower id first), and the new
 * leaf takes the last slot. Leaves are turned about the tangent (their `local` rotated),
 * never reshaped. Applying again adds one more to the same set (it holds the new leaf,
 * now the newest).
 *
 * whorl-extend. S = the highest set with 2+ leaves; H = the set right above it, which
 * must be a single leaf and the highest leaf of b. Spacing d = s(H) - mean s(S), which
 * must exceed tol (else the repeats would read as one set). The reference leaf R is the
 * leaf of S whose angle is nearest H's (ties: lower id); rotation phi = angle(H) -
 * angle(R), wrapped to (-180, 180] degrees. Repeat k = 1, 2, ... stands at
 * s = mean s(S) + k d (repeat 1 exactly at H's branch_t) while s <= L + ARRANGE_TIP_EPS_M
 * (1e-6 m); it holds a copy of every leaf of S turned by k phi. H is kept (it is the
 * visitor's leaf) as R's copy in repeat 1; the rest of repeat 1 completes its set. S, H
 * and the other leaves stay as drawn. An opposite pair with H at 90 degrees gives
 * decussate leaves.
 *
 * spiral-extend. The two highest sets must both be single leaves A (lower) and B; spacing
 * d = s(B) - s(A) (> tol, as they are different sets), divergence delta = angle(B) -
 * angle(A) wrapped to (-180, 180]. Leaf k = 1, 2, ... is a copy of B turned by k delta at
 * s = s(B) + k d while s <= L + 1e-6 m. Suggested only if at least one leaf fits.
 *
 * To the tip: the last repeat is the last one at or before the tip (s <= L + 1e-6 m,
 * branch_t clamped to 1), so the top set is within one spacing of the tip. A pattern is
 * suggested only if it adds at least one leaf and the leaves it adds hold at most
 * ARRANGE_MAX_NEW_POINTS = 200,000 points together, an empty leaf counting as one, and
 * the tree stays within TREE_MAX_LEAVES (a damaged drawing cannot ask for a gigabyte of
 * leaves).
 *
 * What a branch suggests, for example: one leaf: whorl-add; a set: whorl-add; a set and a
 * leaf above it: whorl-add, whorl-extend; two or more single leaves: spiral-extend (and
 * whorl-add too if a set lies below them); leaves already reaching the tip: only
 * whorl-add, if a set is there; no leaves: nothing.
 *
 * Thumbnails (arrange_preview): branch b copied as the only branch (parent -1, same
 * points) with copies of its leaves in the same order, then the pattern applied to the
 * copy; it is the same as applying to the tree, leaf for leaf.
 *
 * New leaves: origin ORIGIN_ARRANGE, on b, the template's `local` rotated about the
 * tangent (x) by the turn: (x, y cos a - z sin a, y sin a + z cos a), so they are
 * congruent to the visitor's leaf; points placed from the frame exactly as
 * tree_leaves_follow() places them, so they follow the branch. Applying either succeeds
 * or leaves the tree as it was (on -ENOMEM only `local` of leaves that had none may have
 * been recorded).
 */
#include "arrange.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "ori_place.h"

#define ON_AXIS_M 1e-9
#define MIN_LENGTH_M 1e-9

static const char *const names[ARRANGE_COUNT] = { "whorl-add", "whorl-extend", "spiral-extend" };

const char *arrange_pattern_name(enum arrange_pattern p)
{
	return (unsigned)p < ARRANGE_COUNT ? names[p] : NULL;
}

bool arrange_pattern_from_name(const char *name, enum arrange_pattern *p)
{
	if (!name)
		return false;
	for (int i = 0; i < ARRANGE_COUNT; i++)
		if (strcmp(names[i], name) == 0) {
			*p = (enum arrange_pattern)i;
			return true;
		}
	return false;
}

/* Angle wrapped to (-pi, pi]. */
static double wrap(double a)
{
	a = fmod(a, 2 * VEC_PI);
	if (a <= -VEC_PI)
		a += 2 * VEC_PI;
	else if (a > VEC_PI)
		a -= 2 * VEC_PI;
	return a;
}

/* Angle wrapped to [0, 2 pi). */
static double wrap_positive(double a)
{
	a = fmod(a, 2 * VEC_PI);
	if (a < 0)
		a += 2 * VEC_PI;
	return a >= 2 * VEC_PI ? 0.0 : a;
}

struct info {
	size_t leaf;  /* index in t->leaves */
	double s;     /* arc length from the branch's root, metres */
	double angle; /* about the tangent, radians */
};

struct set {
	size_t first, n; /* range in the sorted infos */
};

struct analysis {
	struct info *info;
	size_t n;
	struct set *sets;
	size_t nsets;
	double length, tol;
};

static void analysis_finish(struct analysis *a)
{
	free(a->info);
	free(a->sets);
	memset(a, 0, sizeof(*a));
}

/* Leaf point k in the frame f (as tree_leaf_attach records it). */
static struct vec3 local_point(const struct leaf *l, const struct tree_frame *f, size_t k)
{
	struct vec3 d;

	if (l->local)
		return l->local[k];
	d = vec3_sub(l->points[k], f->origin);
	return vec3(vec3_dot(d, f->tangent), vec3_dot(d, f->normal), vec3_dot(d, f->binormal));
}

static void measure(const struct branch *br, const struct leaf *l, double *angle, double *reach)
{
	struct tree_frame f = tree_frame_at(br, l->branch_t);
	double cy = 0, cz = 0, far = 0, r = 0;

	*angle = 0.0;
	for (size_t k = 0; k < l->npoints; k++) {
		struct vec3 p = local_point(l, &f, k);

		cy += p.y;
		cz += p.z;
		r = fmax(r, vec3_len(p));
	}
	*reach = r;
	if (l->npoints == 0)
		return;
	cy /= (double)l->npoints;
	cz /= (double)l->npoints;
	if (hypot(cy, cz) > ON_AXIS_M) {
		*angle = atan2(cz, cy);
		return;
	}
	for (size_t k = 0; k < l->npoints; k++) {
		struct vec3 p = local_point(l, &f, k);
		double d = hypot(p.y, p.z);

		if (d > ON_AXIS_M && d > far) {
			far = d;
			*angle = atan2(p.z, p.y);
		}
	}
}

static int cmp_info(const void *pa, const void *pb)
{
	const struct info *a = pa, *b = pb;

	if (a->s != b->s)
		return a->s < b->s ? -1 : 1;
	return (a->leaf > b->leaf) - (a->leaf < b->leaf);
}

/* 0, -ENOENT (no such branch, or too short), -ENOMEM. */
static int analyse(const struct tree *t, int b, struct analysis *a)
{
	const struct branch *br;
	double reach = 0.0;
	size_t n = 0;

	memset(a, 0, sizeof(*a));
	if (b < 0 || (size_t)b >= t->nbranches)
		return -ENOENT;
	br = &t->branches[b];
	a->length = tree_branch_length(br);
	if (!(a->length >= MIN_LENGTH_M))
		return -ENOENT;
	for (size_t i = 0; i < t->nleaves; i++)
		n += t->leaves[i].branch == b;
	a->info = malloc((n ? n : 1) * sizeof(*a->info));
	a->sets = malloc((n ? n : 1) * sizeof(*a->sets));
	if (!a->info || !a->sets) {
		analysis_finish(a);
		return -ENOMEM;
	}
	for (size_t i = 0; i < t->nleaves; i++) {
		const struct leaf *l = &t->leaves[i];
		struct info *in = &a->info[a->n];
		double r;

		if (l->branch != b)
			continue;
		in->leaf = i;
		in->s = l->branch_t * a->length;
		measure(br, l, &in->angle, &r);
		reach += r;
		a->n++;
	}
	qsort(a->info, a->n, sizeof(*a->info), cmp_info);
	a->tol = ARRANGE_SAME_PLACE_M;
	if (a->n > 0)
		a->tol = fmax(a->tol, ARRANGE_SAME_PLACE_REACH * reach / (double)a->n);
	for (size_t i = 0; i < a->n; i++) {
		struct set *s = a->nsets ? &a->sets[a->nsets - 1] : NULL;

		if (s && a->info[i].s - a->info[s->first].s <= a->tol) {
			s->n++;
			continue;
		}
		a->sets[a->nsets++] = (struct set){ .first = i, .n = 1 };
	}
	return 0;
}

/* Leaf `from`'s outline turned by `turn` about the tangent, at branch_t `t`: a new leaf
 * (a copy) or, for a move, leaf `from` itself. */
struct job {
	size_t from;
	double t, turn;
};

/* The jobs are counted when the arrays are NULL, and written when they are not. */
struct plan {
	struct job *add, *move;
	size_t nadd, nmove, npoints;
};

static int push_add(struct plan *pl, const struct tree *t, struct job j)
{
	if (pl->add)
		pl->add[pl->nadd] = j;
	pl->nadd++;
	pl->npoints += t->leaves[j.from].npoints ? t->leaves[j.from].npoints : 1;
	/* nor past the tree's own limit, however many times patterns are applied */
	return pl->npoints > ARRANGE_MAX_NEW_POINTS || t->nleaves + pl->nadd > TREE_MAX_LEAVES ?
		       -E2BIG : 0;
}

static void push_move(struct plan *pl, struct job j)
{
	if (pl->move)
		pl->move[pl->nmove] = j;
	pl->nmove++;
}

static double set_mean_t(const struct tree *t, const struct analysis *a, const struct set *s)
{
	double sum = 0.0;

	for (size_t i = 0; i < s->n; i++)
		sum += t->leaves[a->info[s->first + i].leaf].branch_t;
	return sum / (double)s->n;
}

static int plan_whorl_add(const struct tree *t, const struct analysis *a, struct plan *pl)
{
	const struct set *target = NULL;
	const struct info *first = NULL, *order[ARRANGE_WHORL_MAX];
	size_t newest = 0, n;
	double step, mean_t;

	for (size_t k = 0; k < a->nsets; k++) {
		const struct set *s = &a->sets[k];

		for (size_t i = 0; s->n >= 2 && i < s->n; i++)
			if (!target || a->info[s->first + i].leaf > newest) {
				target = s;
				newest = a->info[s->first + i].leaf;
			}
	}
	if (!target && a->n == 1)
		target = &a->sets[0];
	if (!target || target->n >= ARRANGE_WHORL_MAX)
		return -ENOENT;
	n = target->n;
	for (size_t i = 0; i < n; i++) {
		const struct info *in = &a->info[target->first + i];

		if (!first || in->leaf < first->leaf)
			first = in;
	}
	/* the others by their angle counter-clockwise from the first's (insertion sort) */
	for (size_t i = 0, m = 0; i < n; i++) {
		const struct info *in = &a->info[target->first + i];
		double d = wrap_positive(in->angle - first->angle);
		size_t j = m;

		if (in == first)
			continue;
		while (j > 0) {
			double dj = wrap_positive(order[j - 1]->angle - first->angle);

			if (dj < d || (dj == d && order[j - 1]->leaf < in->leaf))
				break;
			order[j] = order[j - 1];
			j--;
		}
		order[j] = in;
		m++;
	}
	step = 2 * VEC_PI / (double)(n + 1);
	mean_t = set_mean_t(t, a, target);
	push_move(pl, (struct job){ first->leaf, mean_t, 0.0 });
	for (size_t j = 0; j + 1 < n; j++) {
		double slot = first->angle + (double)(j + 1) * step;

		push_move(pl, (struct job){ order[j]->leaf, mean_t, wrap(slot - order[j]->angle) });
	}
	return push_add(pl, t, (struct job){ first->leaf, mean_t, (double)n * step });
}

static double t_at(const struct analysis *a, double s)
{
	return fmin(fmax(s / a->length, 0.0), 1.0);
}

static int plan_whorl_extend(const struct tree *t, const struct analysis *a, struct plan *pl)
{
	const struct set *set = NULL, *h;
	const struct info *hi, *ref = NULL;
	double mean_s = 0.0, d, phi, best = INFINITY;
	int ret;

	for (size_t k = a->nsets; k-- > 0;)
		if (a->sets[k].n >= 2) {
			set = &a->sets[k];
			break;
		}
	if (!set || set + 2 != a->sets + a->nsets)
		return -ENOENT;
	h = set + 1;
	if (h->n != 1)
		return -ENOENT;
	hi = &a->info[h->first];
	for (size_t i = 0; i < set->n; i++) {
		const struct info *in = &a->info[set->first + i];
		double off = fabs(wrap(hi->angle - in->angle));

		mean_s += in->s;
		if (!ref || off < best || (off == best && in->leaf < ref->leaf)) {
			best = off;
			ref = in;
		}
	}
	mean_s /= (double)set->n;
	d = hi->s - mean_s;
	if (!(d > a->tol))
		return -ENOENT;
	phi = wrap(hi->angle - ref->angle);
	for (size_t k = 1;; k++) {
		double s = mean_s + (double)k * d;
		double at = k == 1 ? t->leaves[hi->leaf].branch_t : t_at(a, s);

		if (k > 1 && s > a->length + ARRANGE_TIP_EPS_M)
			break;
		for (size_t i = 0; i < set->n; i++) {
			const struct info *in = &a->info[set->first + i];

			if (k == 1 && in == ref)
				continue;
			ret = push_add(pl, t, (struct job){ in->leaf, at, (double)k * phi });
			if (ret < 0)
				return ret;
		}
	}
	return 0;
}

static int plan_spiral_extend(const struct tree *t, const struct analysis *a, struct plan *pl)
{
	const struct info *lo, *hi;
	double d, delta;
	int ret;

	if (a->nsets < 2 || a->sets[a->nsets - 1].n != 1 || a->sets[a->nsets - 2].n != 1)
		return -ENOENT;
	lo = &a->info[a->sets[a->nsets - 2].first];
	hi = &a->info[a->sets[a->nsets - 1].first];
	d = hi->s - lo->s;
	if (!(d > a->tol))
		return -ENOENT;
	delta = wrap(hi->angle - lo->angle);
	for (size_t k = 1;; k++) {
		double s = hi->s + (double)k * d;

		if (s > a->length + ARRANGE_TIP_EPS_M)
			break;
		ret = push_add(pl, t, (struct job){ hi->leaf, t_at(a, s), (double)k * delta });
		if (ret < 0)
			return ret;
	}
	return pl->nadd > 0 ? 0 : -ENOENT;
}

/* Fills (or, with NULL arrays, counts) the plan. 0 or -ENOENT (not suggested). */
static int plan(const struct tree *t, const struct analysis *a, enum arrange_pattern p,
		struct plan *pl)
{
	int ret;

	pl->nadd = pl->nmove = pl->npoints = 0;
	switch (p) {
	case ARRANGE_WHORL_ADD:
		ret = plan_whorl_add(t, a, pl);
		break;
	case ARRANGE_WHORL_EXTEND:
		ret = plan_whorl_extend(t, a, pl);
		break;
	case ARRANGE_SPIRAL_EXTEND:
		ret = plan_spiral_extend(t, a, pl);
		break;
	default:
		return -ENOENT;
	}
	if (ret < 0 || pl->nadd == 0)
		return -ENOENT; /* -E2BIG too: too many points is not a suggestion */
	return 0;
}

unsigned arrange_suggest(const struct tree *t, int b)
{
	struct analysis a;
	unsigned mask = 0;

	/* an allocation failure suggests nothing; applying would report it */
	if (analyse(t, b, &a) < 0)
		return 0;
	for (int p = 0; p < ARRANGE_COUNT; p++) {
		struct plan pl = { 0 };

		if (plan(t, &a, (enum arrange_pattern)p, &pl) == 0)
			mask |= 1u << p;
	}
	analysis_finish(&a);
	return mask;
}

static struct vec3 turn(struct vec3 p, double c, double s)
{
	return vec3(p.x, p.y * c - p.z * s, p.y * s + p.z * c);
}

/* Leaf l's points from its local outline, exactly as tree_leaves_follow() puts them. */
static void place(const struct tree *t, struct leaf *l)
{
	struct tree_frame f = tree_frame_at(&t->branches[l->branch], l->branch_t);

	for (size_t k = 0; k < l->npoints; k++)
		l->points[k] = vec3_add(f.origin,
					vec3_add(vec3_scale(f.tangent, l->local[k].x),
						 vec3_add(vec3_scale(f.normal, l->local[k].y),
							  vec3_scale(f.binormal, l->local[k].z))));
}

static int add_copy(struct tree *t, int b, const struct job *j)
{
	const struct leaf *src = &t->leaves[j->from];
	double c = cos(j->turn), s = sin(j->turn);
	struct leaf *l;
	int id;

	id = tree_add_leaf(t, b, ORIGIN_ARRANGE, src->points, src->npoints);
	if (id < 0)
		return id;
	src = &t->leaves[j->from]; /* the array may have moved */
	l = &t->leaves[id];
	l->branch_t = j->t;
	l->local = malloc((l->npoints ? l->npoints : 1) * sizeof(*l->local));
	if (!l->local)
		return -ENOMEM;
	for (size_t k = 0; k < l->npoints; k++)
		l->local[k] = turn(src->local[k], c, s);
	l->kind = src->kind;
	place(t, l);
	/* the leaf the visitor chose, in the frame of the copy it replaces */
	return ori_place_leaf(t, (size_t)id, t->leaf_kind);
}

static int apply_plan(struct tree *t, int b, const struct plan *pl)
{
	size_t n0 = t->nleaves;
	int ret;

	/* Everything that can fail comes first: outlines to copy or turn need `local`. */
	for (size_t i = 0; i < pl->nadd + pl->nmove; i++) {
		size_t from = i < pl->nadd ? pl->add[i].from : pl->move[i - pl->nadd].from;

		if (!t->leaves[from].local && (ret = tree_leaf_attach(t, from)) < 0)
			return ret;
	}
	for (size_t i = 0; i < pl->nadd; i++) {
		ret = add_copy(t, b, &pl->add[i]);
		if (ret < 0) {
			for (size_t k = n0; k < t->nleaves; k++) {
				free(t->leaves[k].points);
				free(t->leaves[k].local);
			}
			t->nleaves = n0;
			return ret;
		}
	}
	/* copies are made from the outlines as they were; now the moves */
	for (size_t i = 0; i < pl->nmove; i++) {
		struct leaf *l = &t->leaves[pl->move[i].from];
		double c = cos(pl->move[i].turn), s = sin(pl->move[i].turn);

		for (size_t k = 0; pl->move[i].turn != 0.0 && k < l->npoints; k++)
			l->local[k] = turn(l->local[k], c, s);
		l->branch_t = pl->move[i].t;
		place(t, l);
	}
	return (int)pl->nadd;
}

int arrange_apply(struct tree *t, int b, enum arrange_pattern p)
{
	struct analysis a;
	struct plan pl = { 0 };
	int ret;

	ret = analyse(t, b, &a);
	if (ret < 0)
		return ret;
	ret = plan(t, &a, p, &pl);
	if (ret < 0)
		goto out;
	pl.add = malloc(pl.nadd * sizeof(*pl.add));
	pl.move = malloc((pl.nmove ? pl.nmove : 1) * sizeof(*pl.move));
	if (!pl.add || !pl.move) {
		ret = -ENOMEM;
		goto out;
	}
	ret = plan(t, &a, p, &pl);
	if (ret == 0)
		ret = apply_plan(t, b, &pl);
out:
	free(pl.add);
	free(pl.move);
	analysis_finish(&a);
	return ret;
}

int arrange_preview(const struct tree *t, int b, enum arrange_pattern p, struct tree *out)
{
	const struct branch *br;
	int ret;

	tree_init(out);
	if (b < 0 || (size_t)b >= t->nbranches || (unsigned)p >= ARRANGE_COUNT)
		return -ENOENT;
	br = &t->branches[b];
	ret = tree_add_branch(out, -1, 0.0, br->origin, br->points, br->radii, br->npoints);
	if (ret < 0)
		return ret;
	out->lifted = t->lifted;
	out->sides = t->sides;
	out->season = t->season;
	out->leaf_kind = t->leaf_kind;
	for (size_t i = 0; i < t->nleaves; i++) {
		const struct leaf *l = &t->leaves[i];
		struct leaf *c;

		if (l->branch != b)
			continue;
		ret = tree_add_leaf(out, 0, l->origin, l->points, l->npoints);
		if (ret < 0)
			goto fail;
		c = &out->leaves[ret];
		c->branch_t = l->branch_t;
		c->kind = l->kind;
		if (l->local) {
			c->local = malloc((l->npoints ? l->npoints : 1) * sizeof(*c->local));
			if (!c->local) {
				ret = -ENOMEM;
				goto fail;
			}
			memcpy(c->local, l->local, l->npoints * sizeof(*c->local));
		}
	}
	/* the same leaves in the same order on the same polyline: the same suggestion */
	ret = arrange_apply(out, 0, p);
	if (ret >= 0)
		return 0;
fail:
	tree_finish(out);
	return ret;
}
