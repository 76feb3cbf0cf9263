/* SPDX-License-Identifier: MIT */
#include "mesh_reuse.h"

#include <errno.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* Old elements by a key of what their mesh depends on; a match is then checked in full,
 * so the key only has to be cheap and mostly different. */
struct table {
	uint64_t *key;
	int *first; /* per place: an old element with this place's key, -1 if none */
	int *next;  /* per old element: the next one in its place */
	size_t cap;
};

static uint64_t mix(uint64_t h, uint64_t v)
{
	h ^= v + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
	h *= 0xff51afd7ed558ccdULL;
	return h ^ (h >> 32);
}

static uint64_t bits(double v)
{
	uint64_t u;

	memcpy(&u, &v, sizeof(u));
	return u;
}

static uint64_t point_key(uint64_t h, struct vec3 p)
{
	return mix(mix(mix(h, bits(p.x)), bits(p.y)), bits(p.z));
}

/* Branch b's own key (its parent's comes in through `up`). */
static uint64_t branch_key(const struct branch *b, uint64_t up)
{
	uint64_t h = mix(mix(up, b->npoints), bits(b->parent_t));

	if (b->npoints) {
		h = point_key(h, b->points[0]);
		h = point_key(h, b->points[b->npoints - 1]);
		h = mix(h, b->radii ? bits(b->radii[0]) : 1);
	}
	return h;
}

static uint64_t leaf_key(const struct leaf *l)
{
	uint64_t h = mix(7, l->npoints);

	return l->npoints ? point_key(point_key(h, l->points[0]), l->points[l->npoints - 1]) : h;
}

static int table_init(struct table *tb, size_t n)
{
	tb->cap = 16;
	while (tb->cap < 2 * n)
		tb->cap *= 2;
	tb->key = malloc(tb->cap * sizeof(*tb->key));
	tb->first = malloc(tb->cap * sizeof(*tb->first));
	tb->next = malloc((n + 1) * sizeof(*tb->next));
	if (!tb->key || !tb->first || !tb->next)
		return -ENOMEM;
	for (size_t i = 0; i < tb->cap; i++)
		tb->first[i] = -1;
	return 0;
}

static void table_finish(struct table *tb)
{
	free(tb->key);
	free(tb->first);
	free(tb->next);
}

/* The place of key k: the one holding it, or the free one it would go to. */
static size_t place(const struct table *tb, uint64_t k)
{
	size_t i = (size_t)k & (tb->cap - 1);

	while (tb->first[i] >= 0 && tb->key[i] != k)
		i = (i + 1) & (tb->cap - 1);
	return i;
}

static void table_add(struct table *tb, uint64_t k, int id)
{
	size_t i = place(tb, k);

	tb->key[i] = k;
	tb->next[id] = tb->first[i];
	tb->first[i] = id;
}

static bool same_points(const struct vec3 *a, const struct vec3 *b, size_t n)
{
	return n == 0 || memcmp(a, b, n * sizeof(*a)) == 0;
}

/* Whether new branch b and old branch o mesh alike: their own data, and parents that
 * were matched to each other (whose parents were, in turn). */
static bool same_branch(const struct branch *b, const struct branch *o, const int *map)
{
	if (b->npoints != o->npoints || bits(b->parent_t) != bits(o->parent_t) ||
	    (b->parent < 0) != (o->parent < 0) || (b->parent >= 0 && map[b->parent] != o->parent) ||
	    !same_points(b->points, o->points, b->npoints) || (b->radii == NULL) != (o->radii == NULL))
		return false;
	return !b->radii || b->npoints == 0 ||
	       memcmp(b->radii, o->radii, b->npoints * sizeof(*b->radii)) == 0;
}

/* For each of t's branches the old one with the same part of the bark, or -1. */
static int match_branches(const struct tree *t, const struct tree *old, int *map)
{
	struct table tb;
	uint64_t *up = malloc((old->nbranches + t->nbranches + 1) * sizeof(*up));
	uint64_t *key_new = up + old->nbranches;
	int ret = table_init(&tb, old->nbranches);

	if (ret < 0 || !up) {
		table_finish(&tb);
		free(up);
		return -ENOMEM;
	}
	/* parents come first, so their keys are there for their children's */
	for (size_t i = 0; i < old->nbranches; i++) {
		const struct branch *o = &old->branches[i];
		bool parent_ok = o->parent >= 0 && (size_t)o->parent < i;

		up[i] = branch_key(o, parent_ok ? up[o->parent] : 0);
		table_add(&tb, up[i], (int)i);
	}
	for (size_t i = 0; i < t->nbranches; i++) {
		const struct branch *b = &t->branches[i];
		bool parent_ok = b->parent >= 0 && (size_t)b->parent < i;
		size_t at;

		key_new[i] = branch_key(b, parent_ok ? key_new[b->parent] : 0);
		map[i] = -1;
		if (b->parent >= 0 && !parent_ok)
			continue; /* not a tree the mesher knows how to share */
		at = place(&tb, key_new[i]);
		for (int o = tb.first[at]; o >= 0 && tb.key[at] == key_new[i]; o = tb.next[o])
			if ((old->branches[o].parent < o) && same_branch(b, &old->branches[o], map)) {
				map[i] = o;
				break;
			}
	}
	table_finish(&tb);
	free(up);
	return 0;
}

static int match_leaves(const struct tree *t, const struct tree *old, int *map)
{
	struct table tb;
	int ret = table_init(&tb, old->nleaves);

	if (ret < 0) {
		table_finish(&tb);
		return ret;
	}
	for (size_t i = 0; i < old->nleaves; i++)
		table_add(&tb, leaf_key(&old->leaves[i]), (int)i);
	for (size_t i = 0; i < t->nleaves; i++) {
		const struct leaf *l = &t->leaves[i];
		uint64_t k = leaf_key(l);
		size_t at = place(&tb, k);

		map[i] = -1;
		for (int o = tb.first[at]; o >= 0 && tb.key[at] == k; o = tb.next[o])
			if (old->leaves[o].npoints == l->npoints && old->leaves[o].kind == l->kind &&
			    same_points(old->leaves[o].points, l->points, l->npoints)) {
				map[i] = o;
				break;
			}
	}
	table_finish(&tb);
	return 0;
}

int tree_mesh_rebuild_from(struct tree_mesh *tm, struct tree_mesh_marks *mk, const struct tree *t,
			   const struct tree *old)
{
	int *reuse_branch = NULL, *reuse_leaf = NULL;
	struct tree_mesh out;
	struct tree_mesh_marks out_mk;
	int ret;

	/* the old parts must be known, made with the same sides, and ids fit the maps */
	/* (a tree's wood decides which branches have parts: not compared, rebuilt) */
	if (old->sides != t->sides || old->wood || t->wood || mk->nbark != old->nbranches + 1 || mk->nleaves != old->nleaves + 1 ||
	    t->nbranches >= INT32_MAX || old->nbranches >= INT32_MAX || old->nleaves >= INT32_MAX)
		return tree_mesh_build_marked(tm, t, mk);
	reuse_branch = malloc((t->nbranches + 1) * sizeof(*reuse_branch));
	reuse_leaf = malloc((t->nleaves + 1) * sizeof(*reuse_leaf));
	if (!reuse_branch || !reuse_leaf || match_branches(t, old, reuse_branch) < 0 ||
	    match_leaves(t, old, reuse_leaf) < 0) {
		free(reuse_branch);
		free(reuse_leaf);
		return tree_mesh_build_marked(tm, t, mk);
	}
	tree_mesh_init(&out);
	tree_mesh_marks_init(&out_mk);
	ret = tree_mesh_build_reusing(&out, &out_mk, t, tm, mk, reuse_branch, reuse_leaf);
	free(reuse_branch);
	free(reuse_leaf);
	if (ret < 0) {
		tree_mesh_finish(&out);
		tree_mesh_marks_finish(&out_mk);
		return tree_mesh_build_marked(tm, t, mk);
	}
	tree_mesh_finish(tm);
	tree_mesh_marks_finish(mk);
	*tm = out;
	*mk = out_mk;
	return 0;
}
