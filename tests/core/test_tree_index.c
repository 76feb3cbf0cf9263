/* SPDX-License-Identifier: MIT */
/* sketch_nearest through a tree's grid (tree_index.c) answers exactly what the linear scan
 * does, ties included, on random trees and through every kind of edit. */
#include <errno.h>
#include <string.h>

#include "rng.h"
#include "sketch.h"
#include "sketch_seen.h"
#include "test.h"
#include "tree.h"
#include "tree_index.h"

static long queries;

static void same_hit(struct sketch_hit a, struct sketch_hit b)
{
	CHECK_INT(a.branch, b.branch);
	if (a.branch < 0)
		return;
	CHECK_INT(a.segment, b.segment);
	CHECK(memcmp(&a.seg_t, &b.seg_t, sizeof(a.seg_t)) == 0);
	CHECK(memcmp(&a.param, &b.param, sizeof(a.param)) == 0);
	CHECK(memcmp(&a.dist, &b.dist, sizeof(a.dist)) == 0);
	CHECK(memcmp(&a.point, &b.point, sizeof(a.point)) == 0);
}

static void check_at(const struct tree *t, struct vec3 p)
{
	same_hit(sketch_nearest(t, p), sketch_nearest_scan(t, p));
	queries++;
}

/* Points near the tree (on its vertices, on its segments, a little off, on the grid's cell
 * lines) and far from it. */
static void check_many(const struct tree *t, struct rng *r, int n)
{
	for (int i = 0; i < n; i++) {
		struct vec3 p;
		int kind = (int)(rng_next(r) % 6);

		if (t->nbranches == 0 || kind == 0) {
			p = vec3(rng_range(r, -30, 30), rng_range(r, -30, 30), 0);
		} else {
			const struct branch *b = &t->branches[rng_next(r) % t->nbranches];
			struct vec3 q;

			if (b->npoints == 0)
				continue;
			q = b->points[rng_next(r) % b->npoints];
			if (kind == 1)
				p = q;
			else if (kind == 2)
				p = vec3(q.x + rng_range(r, -0.05, 0.05), q.y + rng_range(r, -0.05, 0.05), 0);
			else if (kind == 3)
				p = vec3(q.x + rng_range(r, -1.5, 1.5), q.y + rng_range(r, -1.5, 1.5), 0);
			else if (kind == 4) /* on a cell boundary */
				p = vec3(TREE_INDEX_CELL_M * (double)(long)(q.x / TREE_INDEX_CELL_M), q.y, 0);
			else
				p = vec3(q.x + rng_range(r, -8, 8), q.y + rng_range(r, -8, 8), 0);
		}
		check_at(t, p);
	}
}

/* A wavy polyline of n points, 5 cm apart as sketching makes them, sometimes with a
 * repeated point or a long straight part. */
static int add_random_branch(struct tree *t, struct rng *r)
{
	struct vec3 p[80];
	double radii[80];
	size_t n = 1 + rng_next(r) % 60;
	int parent = t->nbranches ? (int)(rng_next(r) % t->nbranches) : -1;
	double a = rng_range(r, 0, 2 * VEC_PI), step = rng_next(r) % 9 == 0 ? 0.9 : 0.05;

	p[0] = vec3(rng_range(r, -6, 6), rng_range(r, 0, 10), rng_range(r, -1, 1));
	if (parent >= 0 && rng_next(r) % 2) {
		const struct branch *b = &t->branches[parent];

		if (b->npoints)
			p[0] = b->points[rng_next(r) % b->npoints];
	}
	for (size_t i = 0; i < n; i++) {
		radii[i] = 0.05;
		if (i == 0)
			continue;
		a += rng_range(r, -0.3, 0.3);
		p[i] = rng_next(r) % 17 == 0 ? p[i - 1]
					      : vec3_add(p[i - 1], vec3(step * cos(a), step * sin(a), 0));
	}
	return tree_add_branch(t, parent, 0.5, ORIGIN_SKETCH, p, radii, n);
}

/* Ties: mirror images about a line through the query points, and exact duplicates. */
static void test_ties(void)
{
	struct tree t;
	struct rng r;
	double radii[2] = { 0.1, 0.1 };

	tree_init(&t);
	tree_index_keep(&t);
	rng_seed(&r, 7);
	for (int i = 0; i < 40; i++)
		CHECK(add_random_branch(&t, &r) >= 0);
	/* the same horizontal segment above and below y = 5, and a copy of each, in an order
	 * that puts later ids in cells the query reaches first */
	for (int k = 0; k < 2; k++) {
		struct vec3 hi[2] = { vec3(20.0, 5.3, 0), vec3(21.0, 5.3, 0) };
		struct vec3 lo[2] = { vec3(20.0, 4.7, 0), vec3(21.0, 4.7, 0) };

		CHECK(tree_add_branch(&t, -1, 0, ORIGIN_SKETCH, hi, radii, 2) >= 0);
		CHECK(tree_add_branch(&t, -1, 0, ORIGIN_SKETCH, lo, radii, 2) >= 0);
	}
	for (int i = 0; i <= 40; i++) {
		struct vec3 p = vec3(19.5 + i * 0.05, 5.0, 0);
		struct sketch_hit h = sketch_nearest(&t, p);

		check_at(&t, p);
		CHECK_INT(h.branch, 40); /* the first of four at the same distance */
	}
	/* a point as far from a vertex shared by consecutive segments of one branch */
	for (size_t b = 0; b < t.nbranches; b++)
		for (size_t i = 0; i < t.branches[b].npoints; i++)
			check_at(&t, t.branches[b].points[i]);
	tree_finish(&t);
}

/* Random trees edited every way the tree module can; queries after every edit. */
static void test_edits(uint64_t seed)
{
	struct tree t, copy;
	struct rng r;

	tree_init(&t);
	tree_init(&copy);
	tree_index_keep(&t);
	rng_seed(&r, seed);
	for (int step = 0; step < 600; step++) {
		int what = (int)(rng_next(&r) % 20);

		if (what < 12 || t.nbranches < 3) {
			CHECK(add_random_branch(&t, &r) >= 0);
		} else if (what < 14) {
			bool remove[512] = { false };

			CHECK(t.nbranches < 512);
			remove[1 + rng_next(&r) % (t.nbranches - 1)] = true;
			CHECK_INT(tree_remove_branches(&t, remove), 0);
		} else if (what < 16) {
			int b = (int)(rng_next(&r) % t.nbranches);
			size_t n = t.branches[b].npoints;

			if (n >= 2)
				CHECK_INT(tree_cut_branch(&t, b, rng_next(&r) % (n - 1), rng_uniform(&r)), 0);
		} else if (what < 17) {
			tree_truncate(&t, t.nbranches - 1 - rng_next(&r) % 3, t.nleaves);
		} else if (what < 18) {
			/* a copy made, the original changed, then given back */
			CHECK_INT(tree_copy(&copy, &t), 0);
			CHECK(add_random_branch(&t, &r) >= 0);
			check_many(&t, &r, 10);
			CHECK_INT(tree_copy(&t, &copy), 0);
		} else if (what < 19) {
			/* a struct copy with fewer branches does not use the original's grid */
			struct tree part = t;

			part.nbranches = t.nbranches / 2;
			check_many(&part, &r, 10);
		} else if (rng_next(&r) % 8 == 0) {
			tree_clear(&t);
		}
		/* a few edits at a time: the grid catches up with all of them at once */
		if (rng_next(&r) % 3 == 0)
			check_many(&t, &r, 30);
	}
	/* points moved in place are seen once the grid is told */
	for (size_t b = 0; b < t.nbranches; b++)
		for (size_t i = 0; i < t.branches[b].npoints; i++)
			t.branches[b].points[i].x += 3.0;
	tree_index_drop(&t);
	check_many(&t, &r, 200);
	tree_finish(&t);
	tree_finish(&copy);
}

/* Far-off and odd geometry: segments spanning many cells or none, points past the grid's
 * range, an empty tree, a tree of single points. */
static void test_odd(void)
{
	struct tree t;
	struct rng r;
	struct vec3 far[3] = { vec3(-1e9, 3, 0), vec3(1e9, 3.2, 0), vec3(1e9, 1e12, 0) };
	struct vec3 one = vec3(1, 1, 0);
	double radii[3] = { 0.1, 0.1, 0.1 };

	tree_init(&t);
	tree_index_keep(&t);
	rng_seed(&r, 99);
	check_at(&t, vec3(0, 0, 0));
	for (int i = 0; i < 100; i++)
		CHECK(tree_add_branch(&t, -1, 0, ORIGIN_SKETCH, &one, radii, 1) >= 0);
	check_at(&t, vec3(0, 0, 0));
	for (int i = 0; i < 80; i++)
		CHECK(add_random_branch(&t, &r) >= 0);
	CHECK(tree_add_branch(&t, -1, 0, ORIGIN_SKETCH, far, radii, 3) >= 0);
	check_many(&t, &r, 500);
	check_at(&t, vec3(5e8, 3.1, 0));
	check_at(&t, vec3(1e30, -1e30, 0));
	check_at(&t, vec3(NAN, 0, 0));
	check_at(&t, vec3(3, INFINITY, 0));
	tree_finish(&t);
}

/* A 3D tree (branches at every depth, leaves) seen through random cameras: the copy a
 * sketch_seen turns lazily through the tree's grid answers as a copy turned whole and
 * scanned does, and what it shows is that copy's points. */
static void test_views(uint64_t seed)
{
	struct tree t;
	struct rng r;

	tree_init(&t);
	tree_index_keep(&t);
	rng_seed(&r, seed);
	for (int i = 0; i < 150; i++) {
		int id = add_random_branch(&t, &r);
		struct branch *b;

		CHECK(id >= 0);
		/* depth along the branch, as lifting gives it */
		b = &t.branches[id];
		for (size_t k = 1; k < b->npoints; k++)
			b->points[k].z = b->points[k - 1].z + rng_range(&r, -0.04, 0.04);
		if (i % 7 == 3 && b->npoints > 2) {
			struct vec3 leaf[6];

			for (int k = 0; k < 6; k++)
				leaf[k] = vec3_add(b->points[1], vec3(0.1 * cos(k), 0.1 * sin(k), 0.05 * k));
			CHECK(tree_add_leaf(&t, id, ORIGIN_SKETCH, leaf, 6) >= 0);
		}
	}
	tree_index_drop(&t); /* the depths were changed in place */
	for (int v = 0; v < 40; v++) {
		struct camera c = v == 0 ? (struct camera){ 0, 0 }
					 : camera_normalize(rng_range(&r, -180, 180), rng_range(&r, -20, 75));
		struct tree plain = t;
		struct sketch_seen lazy, eager;

		plain.index = NULL; /* a copy without the grid: turned whole, scanned */
		CHECK_INT(sketch_seen_init(&lazy, &t, c), 0);
		CHECK_INT(sketch_seen_init(&eager, &plain, c), 0);
		for (int i = 0; i < 60; i++) {
			const struct branch *b = &eager.tree->branches[rng_next(&r) % t.nbranches];
			struct vec3 p = b->npoints ? b->points[rng_next(&r) % b->npoints] : vec3(0, 0, 0);

			if (i % 3 == 1)
				p = vec3(p.x + rng_range(&r, -0.6, 0.6), p.y + rng_range(&r, -0.6, 0.6), 0);
			else if (i % 3 == 2)
				p = vec3(rng_range(&r, -12, 12), rng_range(&r, -4, 14), 0);
			same_hit(sketch_nearest(lazy.tree, p), sketch_nearest_scan(eager.tree, p));
			queries++;
		}
		/* the last branch and its ancestors are there from the start; the rest turned
		 * alike */
		for (int b = (int)t.nbranches - 1; b >= 0; b = t.branches[b].parent)
			CHECK(lazy.tree->branches[b].points != NULL);
		sketch_seen_show_all(&lazy);
		for (size_t i = 0; i < t.nbranches; i++)
			CHECK(memcmp(lazy.tree->branches[i].points, eager.tree->branches[i].points,
				     t.branches[i].npoints * sizeof(struct vec3)) == 0);
		for (size_t i = 0; i < t.nleaves; i++)
			CHECK(memcmp(lazy.tree->leaves[i].points, eager.tree->leaves[i].points,
				     t.leaves[i].npoints * sizeof(struct vec3)) == 0);
		sketch_seen_finish(&lazy);
		sketch_seen_finish(&eager);
	}
	tree_finish(&t);
}

int main(void)
{
	test_ties();
	for (uint64_t seed = 1; seed <= 12; seed++)
		test_edits(seed);
	test_odd();
	for (uint64_t seed = 1; seed <= 3; seed++)
		test_views(seed);
	fprintf(stderr, "%ld queries agree with the scan\n", queries);
	return 0;
}
