/* SPDX-License-Identifier: MIT */
#include "tree.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "tree_index.h"
#include "tree_journal.h"

const char *origin_name(enum origin origin)
{
	switch (origin) {
	case ORIGIN_SKETCH:
		return "sketch";
	case ORIGIN_CLONE:
		return "clone";
	case ORIGIN_PROPAGATE:
		return "propagate";
	case ORIGIN_MERGE:
		return "merge";
	case ORIGIN_ARRANGE:
		return "arrange";
	case ORIGIN_GENERATE:
		return "generate";
	}
	return "sketch";
}

void tree_init(struct tree *t)
{
	memset(t, 0, sizeof(*t));
	t->last_sketched = -1;
	t->leaf_kind = -1;
}

void tree_clear(struct tree *t)
{
	tree_journal_clear(t); /* what was there goes to the journal, if any */
	for (size_t i = 0; i < t->nbranches; i++) {
		free(t->branches[i].points);
		free(t->branches[i].radii);
	}
	for (size_t i = 0; i < t->nleaves; i++) {
		free(t->leaves[i].points);
		free(t->leaves[i].local);
	}
	if (t->nvines)
		t->vine_ops->clear(t);
	tree_wood_drop(t);
	t->nbranches = 0;
	t->nleaves = 0;
	t->nvines = 0;
	tree_index_drop(t);
	/* all of it, so that a rebuilt tree depends on its document only */
	t->last_sketched = -1;
	t->last_sketched_end_us = 0;
	t->has_profile = false;
	memset(t->profile, 0, sizeof(t->profile));
	t->lifted = false;
	t->sides = 0;
	t->season = SEASON_SUMMER;
	t->leaf_kind = -1;
}

void tree_finish(struct tree *t)
{
	tree_journal_discard(t);
	tree_clear(t);
	free(t->branches);
	free(t->leaves);
	free(t->vines);
	tree_index_destroy(t);
	tree_init(t);
}

static int grow(void **array, size_t *cap, size_t n, size_t size)
{
	size_t ncap;
	void *p;

	if (n < *cap)
		return 0;
	ncap = *cap ? *cap * 2 : 16;
	p = realloc(*array, ncap * size);
	if (!p)
		return -ENOMEM;
	*array = p;
	*cap = ncap;
	return 0;
}

static void *dup_array(const void *src, size_t n, size_t size)
{
	void *p = malloc(n ? n * size : 1);

	if (p && n)
		memcpy(p, src, n * size);
	return p;
}

int tree_add_branch(struct tree *t, int parent, double parent_t, enum origin origin,
		    const struct vec3 *points, const double *radii, size_t npoints)
{
	struct branch *b;

	if (grow((void **)&t->branches, &t->cap_branches, t->nbranches, sizeof(*b)) < 0)
		return -ENOMEM;
	b = &t->branches[t->nbranches];
	memset(b, 0, sizeof(*b));
	b->points = dup_array(points, npoints, sizeof(*points));
	b->radii = dup_array(radii, npoints, sizeof(*radii));
	if (!b->points || !b->radii) {
		free(b->points);
		free(b->radii);
		return -ENOMEM;
	}
	b->id = (int)t->nbranches;
	b->parent = parent;
	b->parent_t = parent_t;
	b->generation = parent >= 0 ? t->branches[parent].generation + 1 : 0;
	b->origin = origin;
	b->npoints = npoints;
	t->nbranches++;
	return b->id;
}

void tree_wood_drop(struct tree *t)
{
	if (!t->wood)
		return;
	if (tree_journal_wood(t)) {
		t->wood = NULL; /* the journal's now */
		return;
	}
	t->wood_ops->destroy(t->wood);
	t->wood = NULL;
}

bool tree_branch_in_wood(const struct tree *t, size_t i)
{
	return t->wood && t->wood_ops->holds(t->wood, i);
}

int tree_add_leaf(struct tree *t, int branch, enum origin origin, const struct vec3 *points,
		  size_t npoints)
{
	struct leaf *l;

	if (grow((void **)&t->leaves, &t->cap_leaves, t->nleaves, sizeof(*l)) < 0)
		return -ENOMEM;
	l = &t->leaves[t->nleaves];
	memset(l, 0, sizeof(*l));
	l->points = dup_array(points, npoints, sizeof(*points));
	if (!l->points)
		return -ENOMEM;
	l->id = (int)t->nleaves;
	l->branch = branch;
	l->origin = origin;
	l->npoints = npoints;
	l->kind = -1;
	t->nleaves++;
	return l->id;
}

int tree_copy(struct tree *dst, const struct tree *src)
{
	tree_clear(dst);
	if (src->nbranches > dst->cap_branches) {
		struct branch *b = realloc(dst->branches, src->nbranches * sizeof(*b));

		if (!b)
			return -ENOMEM;
		dst->branches = b;
		dst->cap_branches = src->nbranches;
	}
	if (src->nleaves > dst->cap_leaves) {
		struct leaf *l = realloc(dst->leaves, src->nleaves * sizeof(*l));

		if (!l)
			return -ENOMEM;
		dst->leaves = l;
		dst->cap_leaves = src->nleaves;
	}
	for (size_t i = 0; i < src->nbranches; i++) {
		const struct branch *s = &src->branches[i];
		struct branch *d = &dst->branches[i];

		*d = *s;
		d->points = dup_array(s->points, s->npoints, sizeof(*s->points));
		d->radii = dup_array(s->radii, s->npoints, sizeof(*s->radii));
		if (!d->points || !d->radii) {
			free(d->points);
			free(d->radii);
			tree_clear(dst);
			return -ENOMEM;
		}
		dst->nbranches++;
	}
	for (size_t i = 0; i < src->nleaves; i++) {
		const struct leaf *s = &src->leaves[i];
		struct leaf *d = &dst->leaves[i];

		*d = *s;
		d->points = dup_array(s->points, s->npoints, sizeof(*s->points));
		d->local = s->local ? dup_array(s->local, s->npoints, sizeof(*s->local)) : NULL;
		if (!d->points || (s->local && !d->local)) {
			free(d->points);
			free(d->local);
			tree_clear(dst);
			return -ENOMEM;
		}
		dst->nleaves++;
	}
	if (src->vine_ops)
		dst->vine_ops = src->vine_ops;
	if (src->nvines && src->vine_ops->copy(dst, src) < 0) {
		tree_clear(dst);
		return -ENOMEM;
	}
	if (src->wood_ops)
		dst->wood_ops = src->wood_ops;
	if (src->wood) {
		dst->wood = src->wood_ops->copy(src->wood);
		if (!dst->wood) {
			tree_clear(dst);
			return -ENOMEM;
		}
	}
	dst->lifted = src->lifted;
	dst->sides = src->sides;
	dst->season = src->season;
	dst->leaf_kind = src->leaf_kind;
	dst->last_sketched = src->last_sketched;
	dst->last_sketched_end_us = src->last_sketched_end_us;
	dst->has_profile = src->has_profile;
	memcpy(dst->profile, src->profile, sizeof(dst->profile));
	return 0;
}

void tree_truncate(struct tree *t, size_t nb, size_t nl)
{
	tree_journal_truncate(t, nb, nl);
	for (size_t i = nb; i < t->nbranches; i++) {
		free(t->branches[i].points);
		free(t->branches[i].radii);
	}
	for (size_t i = nl; i < t->nleaves; i++) {
		free(t->leaves[i].points);
		free(t->leaves[i].local);
	}
	if (nb < t->nbranches) {
		t->nbranches = nb;
		tree_index_truncated(t, nb);
	}
	if (nl < t->nleaves)
		t->nleaves = nl;
}

size_t tree_bytes(const struct tree *t)
{
	size_t n = t->cap_branches * sizeof(*t->branches) + t->cap_leaves * sizeof(*t->leaves);

	for (size_t i = 0; i < t->nbranches; i++)
		n += t->branches[i].npoints * (sizeof(struct vec3) + sizeof(double));
	for (size_t i = 0; i < t->nleaves; i++)
		n += t->leaves[i].npoints * sizeof(struct vec3) * (t->leaves[i].local ? 2 : 1);
	if (t->cap_vines)
		n += t->vine_ops->bytes(t);
	if (t->wood)
		n += t->wood_ops->bytes(t->wood);
	return n;
}

void tree_swap(struct tree *a, struct tree *b)
{
	struct tree t = *a;

	*a = *b;
	*b = t;
	tree_index_swapped(a, b);
}
