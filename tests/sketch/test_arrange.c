/* SPDX-License-Identifier: MIT */
/*
 * Leaf arrangement by example (src/sketch/arrange.c): whorl-add, whorl-extend and spiral-extend
 * on a straight vertical branch, an inclined one and a curved 3D one. Trees are built
 * directly: leaves are drawn in their branch's frame at a chosen angle, then attached.
 * Angles are measured here from the leaves' world points (centroid in the frame at
 * branch_t), not from the code under test.
 */
#include <errno.h>
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "arrange.h"
#include "fail_alloc.h"
#include "test.h"

#define DEG (VEC_PI / 180.0)
#define LEAF_N 12
#define ADD (1u << ARRANGE_WHORL_ADD)
#define EXTEND (1u << ARRANGE_WHORL_EXTEND)
#define SPIRAL (1u << ARRANGE_SPIRAL_EXTEND)

enum shape { VERTICAL, INCLINED, CURVED, NSHAPES };
static const char *const shape_names[NSHAPES] = { "vertical", "inclined", "curved 3D" };

/* A trunk (branch 0, a stub) and the branch under test (branch 1) on it. */
static int add_test_branch(struct tree *t, enum shape shape)
{
	struct vec3 p[121], stub[2] = { vec3(0, -1, 0), vec3(0, 0, 0) };
	double r[121] = { 0 };
	size_t n = 0;

	CHECK_INT(tree_add_branch(t, -1, 0.0, ORIGIN_SKETCH, stub, r, 2), 0);
	switch (shape) {
	case VERTICAL: /* 5 m, 0.1 m apart */
		for (n = 0; n <= 50; n++)
			p[n] = vec3(0, 0.1 * (double)n, 0);
		break;
	case INCLINED: /* 4.2 m at 35 degrees from the vertical, leaning back 20 degrees too */
		for (n = 0; n <= 42; n++) {
			double s = 0.1 * (double)n;

			p[n] = vec3(s * sin(35 * DEG) * cos(20 * DEG), s * cos(35 * DEG),
				    -s * sin(35 * DEG) * sin(20 * DEG));
		}
		break;
	case CURVED: /* bends in x and z as it rises: a 3D curve */
		for (n = 0; n <= 120; n++) {
			double y = 0.05 * (double)n;

			p[n] = vec3(1.5 * sin(0.3 * y), y, 1.0 - cos(0.25 * y));
		}
		break;
	default:
		abort();
	}
	CHECK_INT(tree_add_branch(t, 0, 1.0, ORIGIN_SKETCH, p, r, n), 1);
	return 1;
}

/* The outline of a leaf in its frame before turning: x along the tangent, r outwards, w
 * across; lopsided along x, wobbling in w (zero mean), so its centroid's angle is 0. */
static struct vec3 leaf_shape(size_t j, size_t n, double scale)
{
	double u = 2 * VEC_PI * (double)j / (double)n;

	return vec3(scale * 0.12 * sin(u) * (1 + 0.3 * cos(u)), 0.03 + scale * 0.2 * (1 - cos(u)),
		    scale * 0.03 * sin(2 * u));
}

/* Draws a leaf of n points on b at arc length s (metres) pointing at `deg` degrees;
 * returns its id. */
static int draw_leaf_n(struct tree *t, int b, double s, double deg, double scale, bool attach,
		       size_t n)
{
	const struct branch *br = &t->branches[b];
	double bt = s / tree_branch_length(br), a = deg * DEG;
	struct tree_frame f = tree_frame_at(br, bt);
	struct vec3 *p = malloc(n * sizeof(*p));
	int id;

	CHECK(p);
	for (size_t j = 0; j < n; j++) {
		struct vec3 q = leaf_shape(j, n, scale);
		double y = q.y * cos(a) - q.z * sin(a), z = q.y * sin(a) + q.z * cos(a);

		p[j] = vec3_add(f.origin, vec3_add(vec3_scale(f.tangent, q.x),
						   vec3_add(vec3_scale(f.normal, y),
							    vec3_scale(f.binormal, z))));
	}
	id = tree_add_leaf(t, b, ORIGIN_SKETCH, p, n);
	free(p);
	CHECK(id >= 0);
	t->leaves[id].branch_t = bt;
	if (attach)
		CHECK_INT(tree_leaf_attach(t, (size_t)id), 0);
	return id;
}

static int draw_leaf(struct tree *t, int b, double s, double deg, double scale, bool attach)
{
	return draw_leaf_n(t, b, s, deg, scale, attach, LEAF_N);
}

/* The leaf's angle in degrees [0, 360), from its world points. */
static double leaf_deg(const struct tree *t, size_t i)
{
	const struct leaf *l = &t->leaves[i];
	struct tree_frame f = tree_frame_at(&t->branches[l->branch], l->branch_t);
	double cy = 0, cz = 0, a;

	for (size_t k = 0; k < l->npoints; k++) {
		struct vec3 d = vec3_sub(l->points[k], f.origin);

		cy += vec3_dot(d, f.normal);
		cz += vec3_dot(d, f.binormal);
	}
	a = atan2(cz, cy) / DEG;
	return a < 0 ? a + 360 : a;
}

/* Signed difference a - b in degrees, wrapped to (-180, 180]. */
static double deg_diff(double a, double b)
{
	double d = fmod(a - b, 360.0);

	if (d <= -180)
		d += 360;
	else if (d > 180)
		d -= 360;
	return d;
}

static double leaf_s(const struct tree *t, size_t i)
{
	return t->leaves[i].branch_t * tree_branch_length(&t->branches[t->leaves[i].branch]);
}

static bool congruent(const struct tree *t, size_t a, size_t b)
{
	const struct leaf *la = &t->leaves[a], *lb = &t->leaves[b];

	if (la->npoints != lb->npoints)
		return false;
	for (size_t k = 0; k < la->npoints; k++) {
		size_t k1 = (k + 1) % la->npoints;
		double ea = vec3_dist(la->points[k], la->points[k1]);
		double eb = vec3_dist(lb->points[k], lb->points[k1]);

		if (fabs(ea - eb) > 1e-9)
			return false;
	}
	return true;
}

/* A leaf is where its branch's frame puts its local outline (1e-12 m). */
static void check_attached(const struct tree *t, size_t i)
{
	const struct leaf *l = &t->leaves[i];
	struct tree_frame f = tree_frame_at(&t->branches[l->branch], l->branch_t);

	CHECK(l->local != NULL);
	for (size_t k = 0; k < l->npoints; k++) {
		struct vec3 q = l->local[k];
		struct vec3 w = vec3_add(f.origin, vec3_add(vec3_scale(f.tangent, q.x),
							    vec3_add(vec3_scale(f.normal, q.y),
								     vec3_scale(f.binormal, q.z))));

		CHECK(vec3_dist(w, l->points[k]) < 1e-12);
	}
}

static void test_names(void)
{
	enum arrange_pattern p;

	CHECK(strcmp(arrange_pattern_name(ARRANGE_WHORL_ADD), "whorl-add") == 0);
	CHECK(strcmp(arrange_pattern_name(ARRANGE_WHORL_EXTEND), "whorl-extend") == 0);
	CHECK(strcmp(arrange_pattern_name(ARRANGE_SPIRAL_EXTEND), "spiral-extend") == 0);
	CHECK(arrange_pattern_name(ARRANGE_COUNT) == NULL);
	for (int i = 0; i < ARRANGE_COUNT; i++) {
		CHECK(arrange_pattern_from_name(arrange_pattern_name((enum arrange_pattern)i), &p));
		CHECK_INT(p, i);
	}
	CHECK(!arrange_pattern_from_name("whorl", &p));
	CHECK(!arrange_pattern_from_name("", &p));
	CHECK(!arrange_pattern_from_name(NULL, &p));
}

/* Nothing to learn from: no suggestion, -ENOENT everywhere, the tree untouched. */
static void test_nothing(enum shape shape)
{
	struct tree t, out;
	int b;

	tree_init(&t);
	b = add_test_branch(&t, shape);
	CHECK_INT(arrange_suggest(&t, b), 0);
	CHECK_INT(arrange_suggest(&t, 0), 0);
	CHECK_INT(arrange_suggest(&t, 2), 0);
	CHECK_INT(arrange_suggest(&t, -1), 0);
	for (int p = 0; p < ARRANGE_COUNT; p++) {
		CHECK_INT(arrange_apply(&t, b, (enum arrange_pattern)p), -ENOENT);
		CHECK_INT(arrange_apply(&t, 7, (enum arrange_pattern)p), -ENOENT);
		CHECK_INT(arrange_preview(&t, b, (enum arrange_pattern)p, &out), -ENOENT);
		CHECK_INT(out.nbranches + out.nleaves, 0);
		tree_finish(&out);
	}
	CHECK_INT(arrange_preview(&t, -3, ARRANGE_WHORL_ADD, &out), -ENOENT);
	tree_finish(&out);
	/* a leaf on the trunk suggests nothing for the branch */
	draw_leaf(&t, 0, 0.5, 0, 1.0, true);
	CHECK_INT(arrange_suggest(&t, b), 0);
	CHECK_INT(arrange_suggest(&t, 0), ADD);
	CHECK_INT(t.nleaves, 1);
	CHECK_INT(arrange_apply(&t, b, ARRANGE_COUNT), -ENOENT);
	tree_finish(&t);
}

/* Leaves at branch_t within 1e-9 of each other, in id order: the set holding leaf i. */
static size_t set_of(const struct tree *t, size_t i, size_t *ids)
{
	size_t n = 0;

	for (size_t k = 0; k < t->nleaves; k++)
		if (t->leaves[k].branch == t->leaves[i].branch &&
		    fabs(t->leaves[k].branch_t - t->leaves[i].branch_t) < 1e-9)
			ids[n++] = k;
	return n;
}

/* n leaves evenly around: sorted by angle from the first, each gap 360 / n (1 degree). */
static void check_whorl(const struct tree *t, const size_t *ids, size_t n)
{
	double off[64];

	CHECK(n <= 64);
	for (size_t i = 0; i < n; i++) {
		double d = fmod(leaf_deg(t, ids[i]) - leaf_deg(t, ids[0]) + 720.0, 360.0);

		off[i] = d > 359.0 ? d - 360.0 : d; /* the first one may come back as 359.99 */
	}
	for (size_t i = 1; i < n; i++) /* insertion sort */
		for (size_t j = i; j > 0 && off[j - 1] > off[j]; j--) {
			double x = off[j];

			off[j] = off[j - 1];
			off[j - 1] = x;
		}
	for (size_t i = 0; i < n; i++) {
		double next = i + 1 < n ? off[i + 1] : off[0] + 360.0;

		CHECK_NEAR(next - off[i], 360.0 / (double)n, 1.0);
	}
}

/* One drawn leaf, then whorl-add again and again: 2..6 leaves, 360/n apart. */
static void test_whorl_add(enum shape shape)
{
	struct tree t;
	struct vec3 first_pts[LEAF_N];
	double first_deg, bt;
	size_t ids[64];
	int b;

	tree_init(&t);
	b = add_test_branch(&t, shape);
	draw_leaf(&t, b, 2.0, 30.0, 1.0, true);
	first_deg = leaf_deg(&t, 0);
	CHECK_NEAR(first_deg, 30.0, 1e-6);
	bt = t.leaves[0].branch_t;
	memcpy(first_pts, t.leaves[0].points, sizeof(first_pts));
	CHECK_INT(arrange_suggest(&t, b), ADD); /* a single leaf: one more, opposite */
	for (size_t n = 2; n <= 6; n++) {
		CHECK(arrange_suggest(&t, b) & ADD);
		CHECK_INT(arrange_apply(&t, b, ARRANGE_WHORL_ADD), 1);
		CHECK_INT(t.nleaves, n);
		CHECK_INT(t.leaves[n - 1].origin, ORIGIN_ARRANGE);
		CHECK_INT(t.leaves[n - 1].branch, b);
		CHECK_INT(set_of(&t, 0, ids), n);
		CHECK_NEAR(t.leaves[0].branch_t, bt, 1e-12);
		check_whorl(&t, ids, n);
		CHECK_NEAR(deg_diff(leaf_deg(&t, 0), first_deg), 0.0, 1e-6);
		for (size_t i = 0; i < n; i++) {
			CHECK(congruent(&t, 0, i));
			check_attached(&t, i);
		}
		if (n == 2)
			CHECK_NEAR(fabs(deg_diff(leaf_deg(&t, 1), first_deg)), 180.0, 1e-6);
		/* the set is a whorl: only more of it (no higher leaf to extend to) */
		CHECK_INT(arrange_suggest(&t, b), ADD);
	}
	/* the first leaf stayed exactly where it was drawn (same t, not turned) */
	for (size_t k = 0; k < LEAF_N; k++)
		CHECK(vec3_dist(first_pts[k], t.leaves[0].points[k]) < 1e-12);
	/* up to ARRANGE_WHORL_MAX, then no more */
	while (t.nleaves < ARRANGE_WHORL_MAX)
		CHECK_INT(arrange_apply(&t, b, ARRANGE_WHORL_ADD), 1);
	CHECK_INT(set_of(&t, 0, ids), ARRANGE_WHORL_MAX);
	check_whorl(&t, ids, ARRANGE_WHORL_MAX);
	CHECK_INT(arrange_suggest(&t, b), 0);
	CHECK_INT(arrange_apply(&t, b, ARRANGE_WHORL_ADD), -ENOENT);
	CHECK_INT(t.nleaves, ARRANGE_WHORL_MAX);
	tree_finish(&t);
}

/* A drawn, uneven pair a little apart along the branch: three at their mean, 120 apart. */
static void test_whorl_add_uneven(enum shape shape)
{
	struct tree t;
	size_t ids[8];
	double bt;
	int b;

	tree_init(&t);
	b = add_test_branch(&t, shape);
	draw_leaf(&t, b, 1.50, 200.0, 1.0, true);
	draw_leaf(&t, b, 1.62, 10.0, 1.3, false); /* not attached: arrange attaches it */
	bt = 0.5 * (t.leaves[0].branch_t + t.leaves[1].branch_t);
	CHECK_INT(arrange_suggest(&t, b), ADD);
	CHECK_INT(arrange_apply(&t, b, ARRANGE_WHORL_ADD), 1);
	CHECK_INT(set_of(&t, 0, ids), 3);
	CHECK_NEAR(t.leaves[0].branch_t, bt, 1e-12);
	check_whorl(&t, ids, 3);
	CHECK_NEAR(deg_diff(leaf_deg(&t, 0), 200.0), 0.0, 1e-6);
	/* the second leaf is turned to the next slot counter-clockwise, not reshaped */
	CHECK_NEAR(deg_diff(leaf_deg(&t, 1), 320.0), 0.0, 1e-6);
	CHECK_NEAR(deg_diff(leaf_deg(&t, 2), 80.0), 0.0, 1e-6);
	CHECK(congruent(&t, 0, 2));
	CHECK(!congruent(&t, 1, 2));
	for (size_t i = 0; i < 3; i++)
		check_attached(&t, i);
	tree_finish(&t);
}

/*
 * A set of `n` drawn leaves at s0 (angles from `deg`, alternately scaled 1.0 / 1.2) and a
 * leaf at s0 + d turned by `rot` from the first: whorl-extend to the tip.
 */
static void check_whorl_extend(enum shape shape, size_t n, const double *deg, double rot,
			       double s0, double d)
{
	struct tree t;
	struct vec3 h_pts[LEAF_N];
	double len, last_s = -1;
	size_t h, drawn, sets = 0, expect_sets, ids[64];
	int b, added;

	tree_init(&t);
	b = add_test_branch(&t, shape);
	len = tree_branch_length(&t.branches[b]);
	for (size_t i = 0; i < n; i++)
		draw_leaf(&t, b, s0, deg[i], i % 2 ? 1.2 : 1.0, true);
	h = (size_t)draw_leaf(&t, b, s0 + d, deg[0] + rot, 0.9, true);
	drawn = t.nleaves;
	memcpy(h_pts, t.leaves[h].points, sizeof(h_pts));
	CHECK_INT(arrange_suggest(&t, b), ADD | EXTEND);
	expect_sets = (size_t)floor((len - s0) / d + 1e-9); /* repeats above the drawn set */
	added = arrange_apply(&t, b, ARRANGE_WHORL_EXTEND);
	CHECK_INT(added, expect_sets * n - 1);
	CHECK_INT(t.nleaves, drawn + (size_t)added);
	/* the visitor's higher leaf is kept as it was */
	CHECK(memcmp(h_pts, t.leaves[h].points, sizeof(h_pts)) == 0);
	/* repeat k: n leaves at s0 + k d, the drawn set turned by k rot */
	for (size_t k = 1; k <= expect_sets; k++) {
		double s = s0 + (double)k * d;
		size_t m = 0;

		for (size_t i = 0; i < t.nleaves; i++)
			if (fabs(leaf_s(&t, i) - s) < 0.01 * d)
				ids[m++] = i;
		CHECK_INT(m, n);
		for (size_t i = 0; i < n; i++) {
			size_t l = ids[i];
			bool found = false;

			CHECK(l == h || t.leaves[l].origin == ORIGIN_ARRANGE);
			if (l != h)
				CHECK(congruent(&t, 0, l) || congruent(&t, 1, l));
			for (size_t j = 0; j < n; j++) {
				double want = deg[j] + (double)k * rot;

				found |= fabs(deg_diff(leaf_deg(&t, l), want)) < 1.0;
			}
			CHECK(found);
			check_attached(&t, l);
		}
		/* spacing to the previous set (the drawn one for k = 1): d within 1% */
		CHECK_NEAR(leaf_s(&t, ids[0]) - (k == 1 ? s0 : last_s), d, 0.01 * d);
		last_s = leaf_s(&t, ids[0]);
		sets++;
	}
	/* to the tip: at or before it, and within one spacing of it */
	CHECK(last_s <= len + 1e-6);
	CHECK(len - last_s < d);
	CHECK_INT(sets, expect_sets);
	/* every leaf is in one of the sets counted */
	CHECK_INT(t.nleaves, n * (expect_sets + 1));
	/* done: nothing more to extend (more of the top whorl is still offered) */
	CHECK_INT(arrange_suggest(&t, b), ADD);
	CHECK_INT(arrange_apply(&t, b, ARRANGE_WHORL_EXTEND), -ENOENT);
	tree_finish(&t);
}

static void test_whorl_extend(enum shape shape)
{
	static const double pair[] = { 0, 180 }, three[] = { 10, 130, 250 },
			    four[] = { 0, 90, 180, 270 };

	/* opposite pairs and a leaf at 90 degrees: decussate */
	check_whorl_extend(shape, 2, pair, 90.0, 0.6, 0.45);
	check_whorl_extend(shape, 2, pair, -90.0, 1.0, 0.8);
	check_whorl_extend(shape, 3, three, 40.0, 0.5, 0.7);
	check_whorl_extend(shape, 4, four, 20.0, 0.3, 0.33);
	/* not turned at all: the same set repeated */
	check_whorl_extend(shape, 2, pair, 0.0, 0.5, 1.1);
}

/* Single leaves at s0 and s0 + d, turned by div: spiral-extend to the tip. */
static void check_spiral(enum shape shape, double s0, double d, double deg0, double div,
			 size_t before)
{
	struct tree t;
	double len;
	size_t top, n0, expect;
	int b, added;

	tree_init(&t);
	b = add_test_branch(&t, shape);
	len = tree_branch_length(&t.branches[b]);
	/* leaves drawn lower down (before) at a different rhythm do not matter */
	for (size_t i = 0; i < before; i++)
		draw_leaf(&t, b, 0.05 + 0.2 * (double)i, 77.0 * (double)i, 0.8, true);
	draw_leaf(&t, b, s0, deg0, 1.1, true);
	top = (size_t)draw_leaf(&t, b, s0 + d, deg0 + div, 1.0, true);
	n0 = t.nleaves;
	CHECK_INT(arrange_suggest(&t, b), SPIRAL);
	expect = (size_t)floor((len - s0 - d) / d + 1e-9);
	added = arrange_apply(&t, b, ARRANGE_SPIRAL_EXTEND);
	CHECK_INT(added, expect);
	CHECK_INT(t.nleaves, n0 + expect);
	for (size_t i = n0; i < t.nleaves; i++) {
		size_t prev = i == n0 ? top : i - 1;

		CHECK_INT(t.leaves[i].origin, ORIGIN_ARRANGE);
		CHECK(congruent(&t, top, i));
		CHECK_NEAR(leaf_s(&t, i) - leaf_s(&t, prev), d, 0.01 * d);
		CHECK_NEAR(deg_diff(deg_diff(leaf_deg(&t, i), leaf_deg(&t, prev)), div), 0.0, 1.0);
		check_attached(&t, i);
	}
	CHECK(leaf_s(&t, t.nleaves - 1) <= len + 1e-6);
	CHECK(len - leaf_s(&t, t.nleaves - 1) < d);
	/* done: the pattern reached the tip */
	CHECK_INT(arrange_suggest(&t, b), 0);
	CHECK_INT(arrange_apply(&t, b, ARRANGE_SPIRAL_EXTEND), -ENOENT);
	tree_finish(&t);
}

static void test_spiral(enum shape shape)
{
	check_spiral(shape, 0.4, 0.5, 0.0, 137.5, 0);    /* the golden angle */
	check_spiral(shape, 1.0, 0.3, 180.0, 180.0, 0);  /* alternate, as drawn in 2D */
	check_spiral(shape, 0.9, 0.21, 45.0, -100.0, 3); /* clockwise, after other leaves */
	check_spiral(shape, 2.0, 1.0, 300.0, 90.0, 0);
}

/* What each configuration suggests. */
static void test_suggest(enum shape shape)
{
	static const struct {
		const char *what;
		size_t n;
		double s[5], deg[5], scale;
		unsigned want;
	} cases[] = {
		{ "one leaf", 1, { 1.0 }, { 0 }, 1.0, ADD },
		{ "a pair", 2, { 1.0, 1.05 }, { 0, 180 }, 1.0, ADD },
		{ "a pair at one point", 2, { 1.0, 1.0 }, { 0, 90 }, 1.0, ADD },
		{ "a pair and a leaf above", 3, { 1.0, 1.0, 1.5 }, { 0, 180, 90 }, 1.0,
		  ADD | EXTEND },
		{ "a leaf, then a pair above", 3, { 0.5, 1.0, 1.0 }, { 0, 180, 90 }, 1.0, ADD },
		{ "two single leaves", 2, { 1.0, 1.5 }, { 0, 180 }, 1.0, SPIRAL },
		{ "three single leaves", 3, { 1.0, 1.4, 1.8 }, { 0, 137, 274 }, 1.0, SPIRAL },
		{ "a pair, two single leaves", 4, { 0.5, 0.5, 1.0, 1.4 }, { 0, 180, 90, 200 }, 1.0,
		  ADD | SPIRAL },
		{ "a pair, a leaf, a pair", 5, { 0.5, 0.5, 1.0, 1.6, 1.6 }, { 0, 180, 90, 0, 180 },
		  1.0, ADD },
		{ "a pair, a leaf, a loose pair", 5, { 0.5, 0.5, 1.0, 1.6, 1.7 },
		  { 0, 180, 90, 0, 180 }, 1.0, ADD },
		{ "a pair and two leaves above", 4, { 0.5, 0.5, 1.0, 1.6 }, { 0, 180, 90, 0 },
		  1.0, ADD | SPIRAL },
		/* 0.16 m from the pair's first: a place of its own, but only 0.11 m from the
		 * pair's mean: repeats would merge with it, so no extending */
		{ "a leaf just above a pair", 3, { 1.0, 1.1, 1.16 }, { 0, 180, 90 }, 1.0, ADD },
		/* leaves reaching 0.43 m: the same place is 0.15 m */
		{ "leaves 0.149 m apart", 2, { 1.0, 1.149 }, { 0, 180 }, 1.0, ADD },
		{ "leaves 0.151 m apart", 2, { 1.0, 1.151 }, { 0, 180 }, 1.0, SPIRAL },
		/* leaves reaching 1.03 m: 0.3 x 1.03 = 0.309 m */
		{ "big leaves 0.3 m apart", 2, { 1.0, 1.3 }, { 0, 180 }, 2.5, ADD },
		{ "big leaves 0.32 m apart", 2, { 1.0, 1.32 }, { 0, 180 }, 2.5, SPIRAL },
	};

	for (size_t c = 0; c < sizeof(cases) / sizeof(cases[0]); c++) {
		struct tree t;
		int b;

		tree_init(&t);
		b = add_test_branch(&t, shape);
		for (size_t i = 0; i < cases[c].n; i++)
			draw_leaf(&t, b, cases[c].s[i], cases[c].deg[i], cases[c].scale, true);
		if (arrange_suggest(&t, b) != cases[c].want) {
			fprintf(stderr, "%s, %s: suggests %#x, not %#x\n", shape_names[shape],
				cases[c].what, arrange_suggest(&t, b), cases[c].want);
			exit(1);
		}
		tree_finish(&t);
	}
	/* two single leaves whose next one would be past the tip suggest nothing; one that
	 * lands on the tip fits */
	for (int fits = 0; fits < 2; fits++) {
		struct tree t;
		double len;
		int b;

		tree_init(&t);
		b = add_test_branch(&t, shape);
		len = tree_branch_length(&t.branches[b]);
		draw_leaf(&t, b, (fits ? 0.6 : 0.5) * len, 0, 1.0, true);
		draw_leaf(&t, b, 0.8 * len, 180, 1.0, true);
		CHECK_INT(arrange_suggest(&t, b), fits ? SPIRAL : 0);
		if (fits) {
			CHECK_INT(arrange_apply(&t, b, ARRANGE_SPIRAL_EXTEND), 1);
			CHECK_NEAR(t.leaves[2].branch_t, 1.0, 1e-9);
		}
		tree_finish(&t);
	}
}

/* A pattern whose new leaves would hold more than ARRANGE_MAX_NEW_POINTS points is not
 * suggested: 16-leaf whorls of 1,000-point leaves on a 5 m branch. */
static void test_limit(void)
{
	for (int fits = 0; fits < 2; fits++) {
		struct tree t;
		double d = fits ? 0.4 : 0.2;
		size_t sets = (size_t)floor((5.0 - 1.0) / d + 1e-9);
		int b;

		tree_init(&t);
		b = add_test_branch(&t, VERTICAL);
		draw_leaf_n(&t, b, 1.0, 0, 1.0, true, 1000);
		while (t.nleaves < ARRANGE_WHORL_MAX)
			CHECK_INT(arrange_apply(&t, b, ARRANGE_WHORL_ADD), 1);
		draw_leaf_n(&t, b, 1.0 + d, 10, 1.0, true, 1000);
		CHECK((sets * 16 - 1) * 1000 > ARRANGE_MAX_NEW_POINTS || fits);
		CHECK((sets * 16 - 1) * 1000 <= ARRANGE_MAX_NEW_POINTS || !fits);
		CHECK_INT(arrange_suggest(&t, b), fits ? EXTEND : 0);
		CHECK_INT(arrange_apply(&t, b, ARRANGE_WHORL_EXTEND),
			  fits ? (int)(sets * 16 - 1) : -ENOENT);
		tree_finish(&t);
	}
}

/* A pattern not suggested is refused and changes nothing. */
static void test_enoent(enum shape shape)
{
	struct tree t;
	struct vec3 before[3][LEAF_N];
	int b;

	tree_init(&t);
	b = add_test_branch(&t, shape);
	draw_leaf(&t, b, 1.0, 0, 1.0, true);
	draw_leaf(&t, b, 1.5, 180, 1.0, true);
	draw_leaf(&t, b, 1.9, 0, 1.0, true);
	for (size_t i = 0; i < 3; i++)
		memcpy(before[i], t.leaves[i].points, sizeof(before[i]));
	CHECK_INT(arrange_suggest(&t, b), SPIRAL);
	CHECK_INT(arrange_apply(&t, b, ARRANGE_WHORL_ADD), -ENOENT);
	CHECK_INT(arrange_apply(&t, b, ARRANGE_WHORL_EXTEND), -ENOENT);
	CHECK_INT(arrange_apply(&t, 0, ARRANGE_SPIRAL_EXTEND), -ENOENT);
	CHECK_INT(arrange_apply(&t, -1, ARRANGE_SPIRAL_EXTEND), -ENOENT);
	CHECK_INT(arrange_apply(&t, 2, ARRANGE_SPIRAL_EXTEND), -ENOENT);
	CHECK_INT(arrange_apply(&t, b, (enum arrange_pattern)-1), -ENOENT);
	CHECK_INT(t.nleaves, 3);
	for (size_t i = 0; i < 3; i++)
		CHECK(memcmp(before[i], t.leaves[i].points, sizeof(before[i])) == 0);
	tree_finish(&t);
}

/* The drawing of test_determinism, then whorl-add, whorl-extend, whorl-add. */
static void build_sequence(struct tree *t, enum shape shape)
{
	int b;

	tree_init(t);
	b = add_test_branch(t, shape);
	draw_leaf(t, b, 0.7, 15, 1.0, true);
	draw_leaf(t, b, 0.75, 160, 1.3, true);
	draw_leaf(t, b, 1.3, 80, 0.9, true);
	CHECK_INT(arrange_apply(t, b, ARRANGE_WHORL_ADD), 1);
	CHECK(arrange_apply(t, b, ARRANGE_WHORL_EXTEND) > 0);
	CHECK_INT(arrange_apply(t, b, ARRANGE_WHORL_ADD), 1);
}

static void test_determinism(enum shape shape)
{
	struct tree a, b;

	build_sequence(&a, shape);
	build_sequence(&b, shape);
	CHECK_INT(a.nleaves, b.nleaves);
	for (size_t i = 0; i < a.nleaves; i++) {
		CHECK_INT(a.leaves[i].npoints, b.leaves[i].npoints);
		CHECK(memcmp(&a.leaves[i].branch_t, &b.leaves[i].branch_t, sizeof(double)) == 0);
		CHECK(memcmp(a.leaves[i].points, b.leaves[i].points,
			     a.leaves[i].npoints * sizeof(struct vec3)) == 0);
		CHECK(memcmp(a.leaves[i].local, b.leaves[i].local,
			     a.leaves[i].npoints * sizeof(struct vec3)) == 0);
	}
	tree_finish(&a);
	tree_finish(&b);
}

static double edge(const struct leaf *l, size_t k)
{
	return vec3_dist(l->points[k], l->points[(k + 1) % l->npoints]);
}

/* After arranging, the leaves follow their branch: placed as tree_leaves_follow places
 * them (bit for bit), and still attached, congruent and arranged when it moves. */
static void test_follow(enum shape shape)
{
	struct tree t;
	struct branch *br;
	struct vec3 before[64][LEAF_N];
	double deg[64], edges[64][LEAF_N], reach[64];
	size_t n;
	int b = 1;

	build_sequence(&t, shape);
	draw_leaf(&t, b, 0.2, 0, 1.0, true); /* a drawn leaf lower down moves along too */
	n = t.nleaves;
	CHECK(n <= 64);
	for (size_t i = 0; i < n; i++) {
		struct tree_frame f = tree_frame_at(&t.branches[b], t.leaves[i].branch_t);

		CHECK_INT(t.leaves[i].npoints, LEAF_N);
		memcpy(before[i], t.leaves[i].points, sizeof(before[i]));
		deg[i] = leaf_deg(&t, i);
		reach[i] = vec3_dist(t.leaves[i].points[LEAF_N / 2], f.origin);
		for (size_t k = 0; k < LEAF_N; k++)
			edges[i][k] = edge(&t.leaves[i], k);
	}
	/* arranged (new or moved) leaves are exactly where following puts them */
	tree_leaves_follow(&t, b);
	for (size_t i = 0; i < n; i++)
		if (t.leaves[i].origin == ORIGIN_ARRANGE || i < 2)
			CHECK(memcmp(before[i], t.leaves[i].points, sizeof(before[i])) == 0);
	/* move the branch: turn it about the vertical, shift it, bend it */
	br = &t.branches[b];
	for (size_t k = 0; k < br->npoints; k++) {
		struct vec3 p = br->points[k];
		double c = cos(0.7), sn = sin(0.7), h = p.y;

		p = vec3(c * p.x + sn * p.z, p.y, -sn * p.x + c * p.z);
		br->points[k] = vec3(p.x + 0.3 + 0.04 * h * h, p.y + 0.5, p.z - 0.2);
	}
	tree_leaves_follow(&t, b);
	for (size_t i = 0; i < n; i++) {
		struct tree_frame f = tree_frame_at(br, t.leaves[i].branch_t);

		check_attached(&t, i);
		CHECK(vec3_dist(before[i][0], t.leaves[i].points[0]) > 0.1); /* it did move */
		CHECK_NEAR(vec3_dist(t.leaves[i].points[LEAF_N / 2], f.origin), reach[i], 1e-9);
		for (size_t k = 0; k < LEAF_N; k++)
			CHECK_NEAR(edge(&t.leaves[i], k), edges[i][k], 1e-9);
		/* a whorl shares a frame: the angles between its leaves are kept */
		for (size_t j = 0; j < i; j++)
			if (t.leaves[i].branch_t == t.leaves[j].branch_t)
				CHECK_NEAR(deg_diff(deg_diff(leaf_deg(&t, i), leaf_deg(&t, j)),
						   deg_diff(deg[i], deg[j])), 0.0, 1e-6);
	}
	tree_finish(&t);
}

static void copy_tree(struct tree *dst, const struct tree *t)
{
	tree_init(dst);
	for (size_t i = 0; i < t->nbranches; i++)
		CHECK(tree_add_branch(dst, t->branches[i].parent, t->branches[i].parent_t,
				      t->branches[i].origin, t->branches[i].points,
				      t->branches[i].radii, t->branches[i].npoints) >= 0);
	for (size_t i = 0; i < t->nleaves; i++) {
		int id = tree_add_leaf(dst, t->leaves[i].branch, t->leaves[i].origin,
				       t->leaves[i].points, t->leaves[i].npoints);

		CHECK(id >= 0);
		dst->leaves[id].branch_t = t->leaves[i].branch_t;
		CHECK_INT(tree_leaf_attach(dst, (size_t)id), 0);
		memcpy(dst->leaves[id].local, t->leaves[i].local,
		       t->leaves[i].npoints * sizeof(struct vec3));
	}
}

/* The thumbnail: branch 1 alone, as trunk, with the leaves applying would give. */
static void test_preview(enum shape shape)
{
	struct tree t, ref, out;
	size_t n_on = 0, previews = 0;
	int b;

	tree_init(&t);
	b = add_test_branch(&t, shape);
	draw_leaf(&t, 0, 0.5, 0, 1.0, true); /* on the trunk: not in the preview */
	draw_leaf(&t, b, 0.6, 0, 1.0, true);
	draw_leaf(&t, b, 0.6, 180, 1.1, true);
	draw_leaf(&t, b, 1.1, 90, 1.0, true);
	CHECK_INT(arrange_suggest(&t, b), ADD | EXTEND);
	for (int p = 0; p < ARRANGE_COUNT; p++) {
		bool suggested = arrange_suggest(&t, b) & (1u << p);
		int ret = arrange_preview(&t, b, (enum arrange_pattern)p, &out);

		CHECK_INT(t.nleaves, 4); /* the tree itself is not changed */
		if (!suggested) {
			CHECK_INT(ret, -ENOENT);
			CHECK_INT(out.nbranches + out.nleaves, 0);
			tree_finish(&out);
			continue;
		}
		CHECK_INT(ret, 0);
		CHECK_INT(out.nbranches, 1);
		CHECK_INT(out.branches[0].parent, -1);
		CHECK_INT(out.branches[0].npoints, t.branches[b].npoints);
		CHECK(memcmp(out.branches[0].points, t.branches[b].points,
			     t.branches[b].npoints * sizeof(struct vec3)) == 0);
		/* the same leaves as applying to (a copy of) the tree itself */
		copy_tree(&ref, &t);
		CHECK(arrange_apply(&ref, b, (enum arrange_pattern)p) > 0);
		n_on = 0;
		for (size_t i = 0; i < ref.nleaves; i++) {
			if (ref.leaves[i].branch != b)
				continue;
			CHECK(n_on < out.nleaves);
			CHECK_INT(out.leaves[n_on].branch, 0);
			CHECK_INT(out.leaves[n_on].origin, ref.leaves[i].origin);
			CHECK(memcmp(out.leaves[n_on].points, ref.leaves[i].points,
				     ref.leaves[i].npoints * sizeof(struct vec3)) == 0);
			n_on++;
		}
		CHECK_INT(n_on, out.nleaves);
		CHECK(n_on > 3);
		previews++;
		tree_finish(&ref);
		tree_finish(&out);
	}
	CHECK_INT(previews, 2);
	tree_finish(&t);
}

#if FAIL_ALLOC_HOOK /* allocation failures: not under sanitizers, which own malloc */
/* Fails each allocation of applying (and previewing) p in turn: -ENOMEM, the tree as it
 * was, nothing leaked; then it gets through. */
static void check_oom(const struct tree *orig, int b, enum arrange_pattern p, bool preview)
{
	for (long n = 0;; n++) {
		struct tree t, out;
		long before;
		int r;

		copy_tree(&t, orig);
		before = fail_alloc_live();
		fail_alloc_at(n);
		r = preview ? arrange_preview(&t, b, p, &out) : arrange_apply(&t, b, p);
		fail_alloc_off();
		if (preview) {
			if (r < 0)
				CHECK_INT(out.nbranches + out.nleaves, 0);
			tree_finish(&out);
		}
		CHECK_INT(fail_alloc_live() - before, r < 0 || preview ? 0 : 2 * r);
		if (fail_alloc_calls() <= n) {
			CHECK(r >= 0);
			CHECK(n > 0);
			tree_finish(&t);
			return;
		}
		CHECK_INT(r, -ENOMEM);
		CHECK_INT(t.nleaves, orig->nleaves);
		for (size_t i = 0; i < t.nleaves; i++) {
			CHECK(t.leaves[i].branch_t == orig->leaves[i].branch_t);
			CHECK(memcmp(t.leaves[i].points, orig->leaves[i].points,
				     t.leaves[i].npoints * sizeof(struct vec3)) == 0);
			CHECK(memcmp(t.leaves[i].local, orig->leaves[i].local,
				     t.leaves[i].npoints * sizeof(struct vec3)) == 0);
		}
		tree_finish(&t);
	}
}

static void test_oom(enum shape shape)
{
	struct tree t;
	int b;

	if (!fail_alloc_hooked())
		return;
	tree_init(&t);
	b = add_test_branch(&t, shape);
	draw_leaf(&t, b, 0.6, 0, 1.0, true);
	draw_leaf(&t, b, 0.62, 170, 1.1, true);
	draw_leaf(&t, b, 1.1, 90, 1.0, true);
	draw_leaf(&t, b, 1.5, 230, 1.0, true);
	CHECK_INT(arrange_suggest(&t, b), ADD | SPIRAL);
	for (int preview = 0; preview < 2; preview++) {
		check_oom(&t, b, ARRANGE_WHORL_ADD, preview);
		check_oom(&t, b, ARRANGE_SPIRAL_EXTEND, preview);
	}
	tree_finish(&t);
	tree_init(&t);
	b = add_test_branch(&t, shape);
	draw_leaf(&t, b, 0.6, 0, 1.0, true);
	draw_leaf(&t, b, 0.62, 170, 1.1, true);
	draw_leaf(&t, b, 1.1, 90, 1.0, true);
	CHECK_INT(arrange_suggest(&t, b), ADD | EXTEND);
	check_oom(&t, b, ARRANGE_WHORL_EXTEND, false);
	check_oom(&t, b, ARRANGE_WHORL_EXTEND, true);
	tree_finish(&t);
}
#else
static void test_oom(enum shape shape)
{
	(void)shape;
}
#endif

int main(void)
{
	test_names();
	test_limit();
	for (int s = 0; s < NSHAPES; s++) {
		fprintf(stderr, "%s branch\n", shape_names[s]);
		test_nothing((enum shape)s);
		test_whorl_add((enum shape)s);
		test_whorl_add_uneven((enum shape)s);
		test_whorl_extend((enum shape)s);
		test_spiral((enum shape)s);
		test_suggest((enum shape)s);
		test_enoent((enum shape)s);
		test_determinism((enum shape)s);
		test_follow((enum shape)s);
		test_preview((enum shape)s);
		test_oom((enum shape)s);
	}
	return 0;
}
