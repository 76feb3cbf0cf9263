/* SPDX-License-Identifier: MIT */
/* Propagation (src/sketch/propagate.c): fixed count copies every child to the same parameter,
 * scaled; fixed size copies the tip-most children that fit, at the same distance from
 * the tip and the same size; copies are ORIGIN_PROPAGATE, rooted on their target,
 * congruent; the trunk only takes copies from another trunk; -ENOENT;
 * deterministic. Trees are built by hand, bent and out of the picture plane. */
#include <errno.h>
#include <string.h>

#include "propagate.h"
#include "test.h"

#define EPS 1e-9

/* A bent branch from `root` (or, with parent >= 0, from the point at pt on parent),
 * heading along dir and curving towards bend, of arc length exactly len (to rounding). */
static int add_bent(struct tree *t, int parent, double pt, struct vec3 root, struct vec3 dir,
		    struct vec3 bend, double len, int n, double r0)
{
	struct vec3 p[16];
	double r[16], l0;

	CHECK(n >= 2 && n <= 16);
	if (parent >= 0)
		root = tree_frame_at(&t->branches[parent], pt).origin;
	for (int k = 0; k < n; k++) {
		double s = (double)k / (n - 1);

		p[k] = vec3_add(vec3_scale(dir, s), vec3_scale(bend, s * s));
		r[k] = r0 * (1.0 - 0.7 * s);
	}
	l0 = vec3_polyline_length(p, (size_t)n);
	for (int k = 0; k < n; k++)
		p[k] = vec3_add(root, vec3_scale(p[k], len / l0));
	return tree_add_branch(t, parent, parent >= 0 ? pt : 0.0, ORIGIN_SKETCH, p, r, (size_t)n);
}

/* A lobed 7-point leaf beside branch b at u, size `size`, tilted out of plane. */
static int add_leaf(struct tree *t, int b, double u, double size, bool attach)
{
	struct tree_frame f = tree_frame_at(&t->branches[b], u);
	struct vec3 p[7];
	int id;

	for (int i = 0; i < 7; i++) {
		double a = 2.0 * VEC_PI * i / 7, lobe = i % 2 ? 0.6 : 1.0;

		p[i] = vec3_add(f.origin,
				vec3_add(vec3_scale(f.normal, 0.05 + size * lobe * (1.0 + cos(a))),
					 vec3_add(vec3_scale(f.tangent, 0.4 * size * lobe * sin(a)),
						  vec3_scale(f.binormal, 0.3 * size * (1.0 + cos(a))))));
	}
	id = tree_add_leaf(t, b, ORIGIN_SKETCH, p, 7);
	CHECK(id >= 0);
	t->leaves[id].branch_t = u;
	if (attach)
		CHECK(tree_leaf_attach(t, (size_t)id) == 0);
	return id;
}

struct fixture {
	int trunk, a, a1, a2, e, b, c, d;
};

/* trunk (4 m) -> A (2 m, the source) -> A1 (0.6 m) -> E (0.2 m)
 *                                     -> A2 (0.4 m)
 *             -> B (1 m, half of A) -> D (0.5 m)
 *             -> C (3 m)
 * A2's root is 3 cm off A's axis.
 * Leaves: 5 on A (u 0.2 0.45 0.5 0.7 0.95: distances from its tip 1.6 1.1 1.0 0.6 0.1),
 * 2 on A1, 1 on A2, 1 on E, 1 on B, 2 on the trunk. */
static struct fixture build(struct tree *t, bool attach)
{
	struct fixture x;
	static const double au[] = { 0.2, 0.45, 0.5, 0.7, 0.95 };

	tree_init(t);
	x.trunk = add_bent(t, -1, 0, vec3(0.1, 0, -0.2), vec3(0, 1, 0), vec3(0.3, 0, 0.2), 4.0, 9,
			   0.2);
	x.a = add_bent(t, x.trunk, 0.5, vec3(0, 0, 0), vec3(1, 0.5, 0.3), vec3(0, 0.2, -0.3), 2.0,
		       7, 0.08);
	x.a1 = add_bent(t, x.a, 0.3, vec3(0, 0, 0), vec3(0.2, 1, -0.5), vec3(0.1, 0, 0.1), 0.6, 5,
			0.03);
	x.a2 = add_bent(t, x.a, 0.8, vec3(0, 0, 0), vec3(0.3, -0.4, 1), vec3(0, 0.2, 0), 0.4, 4,
			0.02);
	x.e = add_bent(t, x.a1, 0.5, vec3(0, 0, 0), vec3(1, 1, 0), vec3(0, 0, 0.1), 0.2, 3, 0.01);
	x.b = add_bent(t, x.trunk, 0.7, vec3(0, 0, 0), vec3(-1, 0.4, -0.2), vec3(0, 0.3, 0.1), 1.0,
		       5, 0.06);
	x.c = add_bent(t, x.trunk, 0.9, vec3(0, 0, 0), vec3(0.2, 1, -0.8), vec3(-0.4, 0, 0), 3.0, 10,
		       0.07);
	x.d = add_bent(t, x.b, 0.6, vec3(0, 0, 0), vec3(-0.3, 0.5, 0.9), vec3(0.1, 0.1, 0), 0.5, 4,
		       0.02);
	CHECK_INT(x.d, 7);
	/* A2 was drawn from A's bark, not its axis: its copies still start on their target */
	{
		struct vec3 off = vec3_scale(tree_frame_at(&t->branches[x.a], 0.8).normal, 0.03);

		for (size_t k = 0; k < t->branches[x.a2].npoints; k++)
			t->branches[x.a2].points[k] = vec3_add(t->branches[x.a2].points[k], off);
	}
	for (int i = 0; i < 5; i++)
		add_leaf(t, x.a, au[i], 0.05 + 0.01 * i, attach);
	add_leaf(t, x.a1, 0.4, 0.03, attach);
	add_leaf(t, x.a1, 0.9, 0.02, attach);
	add_leaf(t, x.a2, 0.7, 0.025, attach);
	add_leaf(t, x.e, 0.5, 0.01, true);
	add_leaf(t, x.b, 0.5, 0.04, true);
	add_leaf(t, x.trunk, 0.3, 0.1, true);
	add_leaf(t, x.trunk, 0.6, 0.1, true);
	return x;
}

/* Distance from p to b's polyline. */
static double poly_dist(const struct branch *b, struct vec3 p)
{
	double best = INFINITY;

	for (size_t i = 0; i + 1 < b->npoints; i++) {
		struct vec3 a = b->points[i], d = vec3_sub(b->points[i + 1], a);
		double dd = vec3_dot(d, d), s = dd > 0 ? vec3_dot(vec3_sub(p, a), d) / dd : 0.0;

		s = fmin(fmax(s, 0.0), 1.0);
		best = fmin(best, vec3_dist(p, vec3_add(a, vec3_scale(d, s))));
	}
	return best;
}

static double edge(const struct leaf *l, size_t k)
{
	return vec3_dist(l->points[k], l->points[(k + 1) % l->npoints]);
}

/* l's outline in its branch's frame, computed afresh (not its stored local). */
static struct vec3 local_of(const struct tree *t, const struct leaf *l, size_t k)
{
	struct tree_frame f = tree_frame_at(&t->branches[l->branch], l->branch_t);
	struct vec3 d = vec3_sub(l->points[k], f.origin);

	return vec3(vec3_dot(d, f.tangent), vec3_dot(d, f.normal), vec3_dot(d, f.binormal));
}

static void check_vec(struct vec3 a, struct vec3 b, double eps)
{
	CHECK_NEAR(a.x, b.x, eps);
	CHECK_NEAR(a.y, b.y, eps);
	CHECK_NEAR(a.z, b.z, eps);
}

/* Copy leaf c is source leaf s scaled by k: same size of outline, same shape in its frame;
 * its stored local is that shape. */
static void check_leaf_copy(const struct tree *t, const struct leaf *c, const struct leaf *s,
			    double k)
{
	CHECK_INT(c->origin, ORIGIN_PROPAGATE);
	CHECK_INT(c->npoints, s->npoints);
	CHECK(c->local != NULL);
	for (size_t i = 0; i < s->npoints; i++) {
		CHECK_NEAR(edge(c, i), k * edge(s, i), EPS);
		check_vec(local_of(t, c, i), vec3_scale(local_of(t, s, i), k), EPS);
		check_vec(c->local[i], vec3_scale(s->local[i], k), EPS);
	}
}

/* Copy branch c is source child s scaled by k: root on its parent's polyline, the same
 * polyline in the frame at its parent_t, radii and length scaled. */
static void check_branch_copy(const struct tree *t, const struct branch *c, const struct branch *s,
			      double k)
{
	struct tree_frame fc = tree_frame_at(&t->branches[c->parent], c->parent_t);
	struct tree_frame fs = tree_frame_at(&t->branches[s->parent], s->parent_t);

	CHECK_INT(c->origin, ORIGIN_PROPAGATE);
	CHECK_INT(c->npoints, s->npoints);
	CHECK_INT(c->generation, t->branches[c->parent].generation + 1);
	CHECK(poly_dist(&t->branches[c->parent], c->points[0]) <= EPS);
	check_vec(c->points[0], fc.origin, EPS);
	CHECK_NEAR(tree_branch_length(c), k * tree_branch_length(s), EPS);
	for (size_t i = 0; i < s->npoints; i++) {
		struct vec3 dc = vec3_sub(c->points[i], c->points[0]);
		struct vec3 ds = vec3_sub(s->points[i], s->points[0]);

		CHECK_NEAR(c->radii[i], k * s->radii[i], EPS);
		CHECK_NEAR(vec3_dot(dc, fc.tangent), k * vec3_dot(ds, fs.tangent), EPS);
		CHECK_NEAR(vec3_dot(dc, fc.normal), k * vec3_dot(ds, fs.normal), EPS);
		CHECK_NEAR(vec3_dot(dc, fc.binormal), k * vec3_dot(ds, fs.binormal), EPS);
	}
}

#define MAX_OUT 16

/* Leaves with ids in [from, to) on branch b, into out (MAX_OUT); returns how many. */
static int leaves_in(const struct tree *t, int b, size_t from, size_t to, int *out)
{
	int n = 0;

	for (size_t i = from; i < to && i < t->nleaves; i++)
		if (t->leaves[i].branch == b) {
			CHECK(n < MAX_OUT);
			out[n++] = (int)i;
		}
	return n;
}

/* Leaves (ids >= from) on branch b. */
static int leaves_on(const struct tree *t, int b, size_t from, int *out)
{
	return leaves_in(t, b, from, t->nleaves, out);
}

/* Branches (ids >= from) attached to b, into out (MAX_OUT); returns how many. */
static int children_of(const struct tree *t, int b, size_t from, int *out)
{
	int n = 0;

	for (size_t i = from; i < t->nbranches; i++)
		if (t->branches[i].parent == b) {
			CHECK(n < MAX_OUT);
			out[n++] = (int)i;
		}
	return n;
}

/* Every copy is ORIGIN_PROPAGATE and no copy took copies: leaves on a copied branch are
 * the copies of a child's leaves, no branch hangs from a copy. */
static void check_copies(const struct tree *t, size_t nb0, size_t nl0)
{
	for (size_t i = nb0; i < t->nbranches; i++) {
		CHECK_INT(t->branches[i].id, i);
		CHECK_INT(t->branches[i].origin, ORIGIN_PROPAGATE);
		CHECK(t->branches[i].parent >= 0 && (size_t)t->branches[i].parent < nb0);
	}
	for (size_t i = nl0; i < t->nleaves; i++) {
		CHECK_INT(t->leaves[i].id, i);
		CHECK_INT(t->leaves[i].origin, ORIGIN_PROPAGATE);
	}
}

/* The points of copied leaves are where their branch's frame puts them. */
static void check_follow(struct tree *t, size_t nl0)
{
	size_t n = 0;
	struct vec3 *before;

	for (size_t i = nl0; i < t->nleaves; i++)
		n += t->leaves[i].npoints;
	before = malloc((n + 1) * sizeof(*before));
	CHECK(before);
	n = 0;
	for (size_t i = nl0; i < t->nleaves; i++)
		for (size_t k = 0; k < t->leaves[i].npoints; k++)
			before[n++] = t->leaves[i].points[k];
	tree_leaves_follow(t, -1);
	n = 0;
	for (size_t i = nl0; i < t->nleaves; i++)
		for (size_t k = 0; k < t->leaves[i].npoints; k++)
			check_vec(t->leaves[i].points[k], before[n++], 1e-12);
	free(before);
}

static void test_fixed_count(void)
{
	struct tree t;
	struct fixture x = build(&t, true);
	size_t nb0 = t.nbranches, nl0 = t.nleaves;
	int src_leaves[MAX_OUT], src_kids[MAX_OUT], targets[] = { x.a1, x.a2, x.e, x.b, x.c, x.d };
	int nsl = leaves_in(&t, x.a, 0, nl0, src_leaves), nsk = children_of(&t, x.a, 0, src_kids);
	double ls = tree_branch_length(&t.branches[x.a]);

	CHECK_INT(nsl, 5);
	CHECK_INT(nsk, 2);
	/* 6 targets x (5 leaves + 2 branches + 3 leaves on those) */
	CHECK_INT(propagate_apply(&t, x.a, PROPAGATE_FIXED_COUNT), 60);
	CHECK_INT(t.nbranches, nb0 + 12);
	CHECK_INT(t.nleaves, nl0 + 48);
	check_copies(&t, nb0, nl0);
	check_follow(&t, nl0);

	for (size_t j = 0; j < sizeof(targets) / sizeof(targets[0]); j++) {
		int tg = targets[j], cl[MAX_OUT], ck[MAX_OUT];
		double k = tree_branch_length(&t.branches[tg]) / ls;

		CHECK_INT(leaves_on(&t, tg, nl0, cl), nsl);
		for (int i = 0; i < nsl; i++) {
			CHECK_NEAR(t.leaves[cl[i]].branch_t, t.leaves[src_leaves[i]].branch_t, 1e-15);
			check_leaf_copy(&t, &t.leaves[cl[i]], &t.leaves[src_leaves[i]], k);
		}
		CHECK_INT(children_of(&t, tg, nb0, ck), nsk);
		for (int i = 0; i < nsk; i++) {
			int sl[MAX_OUT], cll[MAX_OUT];
			int n = leaves_in(&t, src_kids[i], 0, nl0, sl);

			CHECK_NEAR(t.branches[ck[i]].parent_t, t.branches[src_kids[i]].parent_t, 1e-15);
			check_branch_copy(&t, &t.branches[ck[i]], &t.branches[src_kids[i]], k);
			/* the child's own leaves came along, at the same parameters on the copy */
			CHECK_INT(leaves_on(&t, ck[i], nl0, cll), n);
			for (int m = 0; m < n; m++) {
				CHECK_NEAR(t.leaves[cll[m]].branch_t, t.leaves[sl[m]].branch_t, 1e-15);
				check_leaf_copy(&t, &t.leaves[cll[m]], &t.leaves[sl[m]], k);
			}
			/* not deeper: E hangs from A1 but is not copied */
			CHECK_INT(children_of(&t, ck[i], 0, cll), 0);
		}
	}
	/* the trunk and the source took nothing */
	CHECK_INT(children_of(&t, x.trunk, nb0, src_kids), 0);
	CHECK_INT(leaves_on(&t, x.trunk, nl0, src_leaves), 0);
	CHECK_INT(children_of(&t, x.a, nb0, src_kids), 0);
	CHECK_INT(leaves_on(&t, x.a, nl0, src_leaves), 0);
	/* scaled both ways: B is half as long as A, C one and a half times */
	CHECK_NEAR(tree_branch_length(&t.branches[x.b]) / ls, 0.5, 1e-12);
	CHECK_NEAR(tree_branch_length(&t.branches[x.c]) / ls, 1.5, 1e-12);
	tree_finish(&t);
}

/* Fixed size: on each target exactly the source's children with d <= target length. */
static void test_fixed_size(void)
{
	struct tree t;
	struct fixture x = build(&t, true);
	size_t nb0 = t.nbranches, nl0 = t.nleaves;
	int src_leaves[MAX_OUT], src_kids[MAX_OUT], targets[] = { x.a1, x.a2, x.e, x.b, x.c, x.d };
	int nsl = leaves_in(&t, x.a, 0, nl0, src_leaves), nsk = children_of(&t, x.a, 0, src_kids);
	double ls = tree_branch_length(&t.branches[x.a]);
	int ret, total = 0;

	ret = propagate_apply(&t, x.a, PROPAGATE_FIXED_SIZE);
	check_copies(&t, nb0, nl0);
	check_follow(&t, nl0);

	for (size_t j = 0; j < sizeof(targets) / sizeof(targets[0]); j++) {
		int tg = targets[j], cl[MAX_OUT], ck[MAX_OUT], n = 0, nk = 0;
		double lt = tree_branch_length(&t.branches[tg]);
		int ncl = leaves_on(&t, tg, nl0, cl), nck = children_of(&t, tg, nb0, ck);

		for (int i = 0; i < nsl; i++) {
			const struct leaf *s = &t.leaves[src_leaves[i]];
			double d = (1.0 - s->branch_t) * ls;

			if (d > lt + 1e-9)
				continue;
			CHECK(n < ncl);
			CHECK_NEAR((1.0 - t.leaves[cl[n]].branch_t) * lt, d, EPS);
			check_leaf_copy(&t, &t.leaves[cl[n]], s, 1.0);
			n++;
		}
		CHECK_INT(ncl, n);
		for (int i = 0; i < nsk; i++) {
			const struct branch *s = &t.branches[src_kids[i]];
			double d = (1.0 - s->parent_t) * ls;
			int sl[MAX_OUT], cll[MAX_OUT], m;

			if (d > lt + 1e-9)
				continue;
			CHECK(nk < nck);
			CHECK_NEAR((1.0 - t.branches[ck[nk]].parent_t) * lt, d, EPS);
			check_branch_copy(&t, &t.branches[ck[nk]], s, 1.0);
			m = leaves_in(&t, src_kids[i], 0, nl0, sl);
			CHECK_INT(leaves_on(&t, ck[nk], nl0, cll), m);
			for (int q = 0; q < m; q++) {
				CHECK_NEAR(t.leaves[cll[q]].branch_t, t.leaves[sl[q]].branch_t, 1e-15);
				check_leaf_copy(&t, &t.leaves[cll[q]], &t.leaves[sl[q]], 1.0);
			}
			total += m;
			nk++;
		}
		CHECK_INT(nck, nk);
		total += n + nk;
	}
	CHECK_INT(ret, total);

	/* B, half as long as A, took the tip-most half: leaves at 1.0 (just fits), 0.6 and
	 * 0.1 m from the tip, and A2 (0.4 m from the tip) with its leaf; not A1 (1.4 m). */
	{
		int cl[MAX_OUT], ck[MAX_OUT], n;

		CHECK_INT(leaves_on(&t, x.b, nl0, cl), 3);
		CHECK_NEAR(t.leaves[cl[0]].branch_t, 0.0, 1e-9);
		CHECK_NEAR(t.leaves[cl[1]].branch_t, 0.4, 1e-9);
		CHECK_NEAR(t.leaves[cl[2]].branch_t, 0.9, 1e-9);
		CHECK_INT(children_of(&t, x.b, nb0, ck), 1);
		CHECK_NEAR(t.branches[ck[0]].parent_t, 0.6, 1e-9);
		CHECK_NEAR(tree_branch_length(&t.branches[ck[0]]), 0.4, 1e-9);
		n = leaves_on(&t, ck[0], nl0, cl);
		CHECK_INT(n, 1);
		/* C, longer, took everything, nearer its root than on A */
		CHECK_INT(leaves_on(&t, x.c, nl0, cl), 5);
		CHECK_NEAR(t.leaves[cl[0]].branch_t, 1.0 - 1.6 / 3.0, 1e-9);
		CHECK_INT(children_of(&t, x.c, nb0, ck), 2);
		/* E (0.2 m) only the leaf 0.1 m from the tip */
		CHECK_INT(leaves_on(&t, x.e, nl0, cl), 1);
		CHECK_NEAR(t.leaves[cl[0]].branch_t, 0.5, 1e-9);
		CHECK_INT(children_of(&t, x.e, nb0, ck), 0);
	}
	CHECK_INT(children_of(&t, x.trunk, nb0, src_kids), 0);
	CHECK_INT(leaves_on(&t, x.trunk, nl0, src_leaves), 0);
	tree_finish(&t);
}

/* The trunk takes copies only from another trunk; a trunk as source reaches everything. */
static void test_trunk(void)
{
	struct tree t;
	struct fixture x = build(&t, true);
	int root2 = add_bent(&t, -1, 0, vec3(3, 0, 0), vec3(0, 1, 0), vec3(0.2, 0, 0), 2.0, 5, 0.1);
	size_t nb0 = t.nbranches, nl0 = t.nleaves;
	int out[MAX_OUT];

	CHECK(propagate_apply(&t, x.a, PROPAGATE_FIXED_COUNT) > 0);
	CHECK_INT(children_of(&t, root2, nb0, out), 0);
	CHECK_INT(leaves_on(&t, root2, nl0, out), 0);
	CHECK_INT(children_of(&t, x.trunk, nb0, out), 0);
	tree_finish(&t);

	x = build(&t, true);
	root2 = add_bent(&t, -1, 0, vec3(3, 0, 0), vec3(0, 1, 0), vec3(0.2, 0, 0), 2.0, 5, 0.1);
	nb0 = t.nbranches;
	nl0 = t.nleaves;
	/* the trunk's children: 2 leaves, A B C, and their leaves (5 + 1); 8 targets */
	CHECK_INT(propagate_apply(&t, x.trunk, PROPAGATE_FIXED_COUNT), 8 * (2 + 3 + 6));
	check_copies(&t, nb0, nl0);
	for (int b = 0; b < (int)nb0; b++) {
		int nk = children_of(&t, b, nb0, out), nlv = leaves_on(&t, b, nl0, out);

		CHECK_INT(nk, b == x.trunk ? 0 : 3);
		CHECK_INT(nlv, b == x.trunk ? 0 : 2);
	}
	tree_finish(&t);
}

static void test_errors(void)
{
	struct tree t;
	struct fixture x = build(&t, true);
	size_t nb0 = t.nbranches, nl0 = t.nleaves;
	struct vec3 dot[3] = { vec3(1, 1, 0), vec3(1, 1, 0), vec3(1, 1, 0) };
	double r[3] = { 0.01, 0.01, 0.01 };
	int zero;

	CHECK_INT(propagate_apply(&t, x.d, PROPAGATE_FIXED_COUNT), -ENOENT);
	CHECK_INT(propagate_apply(&t, x.d, PROPAGATE_FIXED_SIZE), -ENOENT);
	CHECK_INT(propagate_apply(&t, -1, PROPAGATE_FIXED_COUNT), -ENOENT);
	CHECK_INT(propagate_apply(&t, (int)nb0, PROPAGATE_FIXED_COUNT), -ENOENT);
	CHECK_INT(t.nbranches, nb0);
	CHECK_INT(t.nleaves, nl0);

	/* a zero-length branch: never a target; as a source with a leaf, -ENOENT */
	zero = tree_add_branch(&t, x.c, 0.5, ORIGIN_SKETCH, dot, r, 3);
	CHECK(zero >= 0);
	nb0 = t.nbranches;
	nl0 = t.nleaves;
	CHECK(propagate_apply(&t, x.a, PROPAGATE_FIXED_COUNT) > 0);
	for (size_t i = nl0; i < t.nleaves; i++)
		CHECK(t.leaves[i].branch != zero);
	for (size_t i = nb0; i < t.nbranches; i++)
		CHECK(t.branches[i].parent != zero);
	tree_finish(&t);

	x = build(&t, true);
	zero = tree_add_branch(&t, x.c, 0.5, ORIGIN_SKETCH, dot, r, 3);
	CHECK(tree_add_leaf(&t, zero, ORIGIN_SKETCH, dot, 3) >= 0);
	nb0 = t.nbranches;
	nl0 = t.nleaves;
	CHECK_INT(propagate_apply(&t, zero, PROPAGATE_FIXED_SIZE), -ENOENT);
	CHECK_INT(t.nbranches, nb0);
	CHECK_INT(t.nleaves, nl0);
	tree_finish(&t);
}

static void check_same(const struct tree *a, const struct tree *b, double eps)
{
	CHECK_INT(a->nbranches, b->nbranches);
	CHECK_INT(a->nleaves, b->nleaves);
	for (size_t i = 0; i < a->nbranches; i++) {
		const struct branch *x = &a->branches[i], *y = &b->branches[i];

		CHECK_INT(x->parent, y->parent);
		CHECK_INT(x->origin, y->origin);
		CHECK_INT(x->npoints, y->npoints);
		CHECK_NEAR(x->parent_t, y->parent_t, eps);
		for (size_t k = 0; k < x->npoints; k++) {
			check_vec(x->points[k], y->points[k], eps);
			CHECK_NEAR(x->radii[k], y->radii[k], eps);
		}
	}
	for (size_t i = 0; i < a->nleaves; i++) {
		const struct leaf *x = &a->leaves[i], *y = &b->leaves[i];

		CHECK_INT(x->branch, y->branch);
		CHECK_INT(x->origin, y->origin);
		CHECK_INT(x->npoints, y->npoints);
		CHECK_NEAR(x->branch_t, y->branch_t, eps);
		for (size_t k = 0; k < x->npoints; k++)
			check_vec(x->points[k], y->points[k], eps);
	}
}

/* Same tree, same result, bit for bit, twice over (copies of copies included); leaves
 * never attached are taken as tree_leaf_attach would have recorded them. */
static void test_determinism(void)
{
	struct tree a, b;
	struct fixture x;

	for (int p = 0; p < 2; p++) {
		x = build(&a, true);
		build(&b, true);
		CHECK(propagate_apply(&a, x.a, (enum propagate_pattern)p) > 0);
		CHECK(propagate_apply(&b, x.a, (enum propagate_pattern)p) > 0);
		CHECK(propagate_apply(&a, x.c, (enum propagate_pattern)p) > 0);
		CHECK(propagate_apply(&b, x.c, (enum propagate_pattern)p) > 0);
		check_same(&a, &b, 0.0);
		tree_finish(&a);
		tree_finish(&b);

		x = build(&a, true);
		build(&b, false);
		CHECK(propagate_apply(&a, x.a, (enum propagate_pattern)p) > 0);
		CHECK(propagate_apply(&b, x.a, (enum propagate_pattern)p) > 0);
		check_same(&a, &b, 0.0);
		tree_finish(&a);
		tree_finish(&b);
	}
}

/* A propagation that could pass the tree's limits is refused and changes nothing. */
static void test_limits(void)
{
	struct tree t;
	int trunk, src;
	size_t nl;

	tree_init(&t);
	trunk = add_bent(&t, -1, 0, vec3(0, 0, 0), vec3(0, 4, 0), vec3(0.3, 0, 0.2), 4.0, 8, 0.1);
	/* 400 branches along the trunk; the first carries 200 leaves */
	for (int i = 0; i < 400; i++)
		CHECK(add_bent(&t, trunk, 0.1 + 0.8 * i / 400.0, vec3(0, 0, 0), vec3(1, 0.3, 0.1 * (i % 7)),
			       vec3(0, 0.2, 0), 1.0, 4, 0.02) > 0);
	src = 1;
	for (int i = 0; i < 200; i++)
		add_leaf(&t, src, 0.05 + 0.9 * i / 200.0, 0.05, true);
	nl = t.nleaves;
	/* 399 targets x 200 leaves = 79,800 > TREE_MAX_LEAVES */
	CHECK(399u * 200u > TREE_MAX_LEAVES);
	CHECK_INT(propagate_apply(&t, src, PROPAGATE_FIXED_COUNT), -ENOSPC);
	CHECK_INT(t.nleaves, nl);
	CHECK_INT(t.nbranches, 401);
	tree_finish(&t);
}

int main(void)
{
	test_limits();
	test_fixed_count();
	test_fixed_size();
	test_trunk();
	test_errors();
	test_determinism();
	return 0;
}
