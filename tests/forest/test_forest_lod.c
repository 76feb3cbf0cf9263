/* SPDX-License-Identifier: MIT */
/*
 * A tree's meshes at the forest's level of detail (src/forest/forest_lod.c, docs/forest.md
 * "Drawing it fast enough"), its size (forest_size.c) and the forest's shares:
 *
 * - on 300 seeded random trees (synth_tree: 1..1,000 branches, 0..20 leaves a branch) at
 *   two budgets from 500 to 300,000 (log-uniform), at the tree's own count and one less:
 *   never more triangles than the budget; the tree's own meshes byte for byte when they
 *   fit; the bounding box within the full meshes' grown by the largest card's half-size
 *   and the thickest ring's radius, and at least 90% of their height and of their width
 *   along x and z (the outline kept); the bark exactly the level's parts of the branches
 *   forest_lod_keep keeps; the same bytes twice; nothing not finite; every card a quad
 *   with one unit normal, counter-clockwise about it;
 * - forest_lod_keep on those trees at random caps: no branch without its parent, the
 *   trunk always, the rest within the cap unless only what holds the outline is left,
 *   and nothing kept that is worth less than something dropped (but what holds the
 *   outline, or a parent of what stays);
 * - the coarse bark (tree_mesh_build_parts_coarse): {0, 1} and NULL the bytes of
 *   tree_mesh_build_parts; a ring's sides capped; every child's root ring inside its
 *   parent's (or grandparent's) tube at every level;
 * - the least: a budget of 0 gives the trunk at the coarsest level and one card;
 * - cards face their leaves' common normal (leaves flattened into planes of x or z);
 * - colours: a leaf its own, a card the mean of its leaves' (autumn, summer, winter);
 * - the wind binds the bark and cards of a level of detail (live_attrs_bind_nearest);
 * - a grown tree and a tree with vines (synth_wood_tree, synth_vine_tree): within any
 *   budget that holds them, their parts hold the wood's bark and the vines' stems and
 *   leaves byte for byte after the tree's own (the wood's in place of the tubes it
 *   replaces); at a small budget the wood is still there (its box), made coarser;
 * - a tree's height and crown width on a few shapes, the same turned about its foot;
 * - the forest's shares: within the total, in proportion to the widths, water-filled.
 *
 * The worst margins are printed.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "forest.h"
#include "leaf_colors.h"
#include "live.h"
#include "rng.h"
#include "season.h"
#include "synth_tree.h"
#include "synth_vine.h"
#include "synth_wood.h"
#include "same.h"
#include "test.h"
#include "vine.h"
#include "wood.h"

#define TEST_PI 3.14159265358979323846
#define TUBE_MIN_RADIUS 0.0005 /* mesh_private.h: a joint shrinks a root ring no further */

static struct vec3 pos(const struct mesh *m, size_t v)
{
	return vec3(m->positions[3 * v], m->positions[3 * v + 1], m->positions[3 * v + 2]);
}

static struct vec3 nor(const struct mesh *m, size_t v)
{
	return vec3(m->normals[3 * v], m->normals[3 * v + 1], m->normals[3 * v + 2]);
}

static size_t tris(const struct mesh *m)
{
	return m->nindices / 3;
}

static double thickest(const struct tree *t)
{
	double r = 0.0;

	for (size_t i = 0; i < t->nbranches; i++)
		for (size_t k = 0; k < t->branches[i].npoints; k++)
			r = fmax(r, t->branches[i].radii[k]);
	return r;
}

/*
 * Every card of m (4 vertices, 2 triangles each, in order) a rectangle with one unit
 * normal, its triangles counter-clockwise about it. Returns the largest half-diagonal.
 */
static double check_cards(const struct mesh *m, size_t cards)
{
	double half = 0.0;

	CHECK_INT(m->nvertices, 4 * cards);
	CHECK_INT(m->nindices, 6 * cards);
	for (size_t k = 0; k < cards; k++) {
		struct vec3 n = nor(m, 4 * k), c = vec3(0, 0, 0);

		CHECK_NEAR(vec3_len(n), 1.0, 1e-6);
		for (size_t v = 4 * k; v < 4 * k + 4; v++) {
			CHECK(vec3_dist(nor(m, v), n) == 0.0);
			c = vec3_add(c, vec3_scale(pos(m, v), 0.25));
		}
		for (size_t v = 4 * k; v < 4 * k + 4; v++)
			half = fmax(half, vec3_dist(pos(m, v), c));
		for (size_t f = 2 * k; f < 2 * k + 2; f++) {
			struct vec3 a = pos(m, m->indices[3 * f]), b = pos(m, m->indices[3 * f + 1]);
			struct vec3 e = pos(m, m->indices[3 * f + 2]);

			CHECK(m->indices[3 * f] >= 4 * k && m->indices[3 * f] < 4 * k + 4);
			CHECK(vec3_dot(vec3_cross(vec3_sub(b, a), vec3_sub(e, a)), n) > 0.0);
		}
	}
	return half;
}

/* The bark forest_lod_build should have made at its level: the level's parts of the
 * branches forest_lod_keep keeps within the bark's cap. */
static void check_bark_rule(const struct tree *t, const struct tree_mesh *full, size_t budget,
			    const struct forest_lod_stats *st, const struct mesh *bark)
{
	size_t n = t->nbranches, cap, kept, nk = 0, leaves = tris(&full->leaves);
	size_t *all = malloc(n * sizeof(*all)), *tr = malloc(n * sizeof(*tr));
	size_t *which = malloc(n * sizeof(*which));
	bool *keep = malloc(n * sizeof(*keep));
	struct tree_mesh cm, pm;
	struct tree_mesh_marks cmk, pmk;

	CHECK(all && tr && which && keep);
	cap = (size_t)((double)budget * FOREST_LOD_BARK_SHARE);
	if (leaves < budget && budget - leaves > cap)
		cap = budget - leaves;
	/* what cards leave of the rest goes to the bark, if it was made coarser */
	if (st->cards && tris(&full->bark) > cap && budget > st->leaf_triangles &&
	    budget - st->leaf_triangles > cap)
		cap = budget - st->leaf_triangles;
	if (st->level == 0) {
		CHECK(tris(&full->bark) <= cap);
		CHECK(mesh_bytes_equal(bark, &full->bark));
		CHECK_INT(st->branches_kept, n);
		goto done;
	}
	tree_mesh_init(&cm);
	tree_mesh_init(&pm);
	tree_mesh_marks_init(&cmk);
	tree_mesh_marks_init(&pmk);
	for (size_t i = 0; i < n; i++)
		all[i] = i;
	/* the levels before did not fit */
	CHECK(tris(&full->bark) > cap);
	for (int l = 1; l < st->level; l++) {
		CHECK_INT(tree_mesh_build_parts_coarse(&cm, &cmk, t, all, n, NULL, 0,
						       &forest_lod_levels[l - 1]), 0);
		CHECK(tris(&cm.bark) > cap);
	}
	CHECK_INT(tree_mesh_build_parts_coarse(&cm, &cmk, t, all, n, NULL, 0,
					       &forest_lod_levels[st->level - 1]), 0);
	for (size_t i = 0; i < n; i++)
		tr[i] = (cmk.bark[i + 1].nindices - cmk.bark[i].nindices) / 3;
	CHECK_INT(forest_lod_keep(t, &full->leaves, tr, cap, keep, &kept), 0);
	CHECK_INT(kept, st->branches_kept);
	for (size_t i = 0; i < n; i++)
		if (keep[i])
			which[nk++] = i;
	CHECK_INT(tree_mesh_copy_parts(&pm, &pmk, &cm, &cmk, which, nk, NULL, 0), 0);
	CHECK(mesh_bytes_equal(bark, &pm.bark));
	/* pruning only at the coarsest level */
	CHECK(kept == n || st->level == FOREST_LOD_LEVELS);
	tree_mesh_marks_finish(&pmk);
	tree_mesh_marks_finish(&cmk);
	tree_mesh_finish(&pm);
	tree_mesh_finish(&cm);
done:
	free(keep);
	free(which);
	free(tr);
	free(all);
}

struct margins {
	double cover;      /* least share of the full extent along x, y or z */
	double card_grow;  /* most the box grew past the full one over the card half-size */
	double bark_grow;  /* most it grew without cards, over the thickest radius */
	size_t cases, full, carded, pruned;
};

/* t at budget, full its own meshes with `drawn` leaves that have triangles. */
static void check_one(const struct tree *t, const struct tree_mesh *full, size_t drawn,
		      size_t budget, bool again, struct margins *mg)
{
	struct tree_mesh out, out2;
	struct forest_lod_stats st, st2;
	struct box fb, lb;
	size_t own = tris(&full->bark) + tris(&full->leaves);
	double half = 0.0, allow;

	tree_mesh_init(&out);
	CHECK_INT(forest_lod_build(t, budget, &out, &st), 0);
	check_mesh_sane(&out.bark);
	check_mesh_sane(&out.leaves);
	CHECK_INT(st.full_triangles, own);
	CHECK_INT(st.bark_triangles, tris(&out.bark));
	CHECK_INT(st.leaf_triangles, tris(&out.leaves));
	CHECK(!st.over_budget);
	CHECK(tris(&out.bark) + tris(&out.leaves) <= budget);
	mg->cases++;
	if (own <= budget) {
		CHECK(mesh_bytes_equal(&out.bark, &full->bark));
		CHECK(mesh_bytes_equal(&out.leaves, &full->leaves));
		CHECK(st.level == 0 && st.cards == 0);
		mg->full++;
	} else {
		check_bark_rule(t, full, budget, &st, &out.bark);
		if (st.cards) {
			half = check_cards(&out.leaves, st.cards);
			CHECK_INT(st.leaves_as_cards, drawn);
			CHECK(st.cards <= drawn && st.cell > 0.0);
			mg->carded++;
		} else {
			CHECK(mesh_bytes_equal(&out.leaves, &full->leaves));
		}
		mg->pruned += st.branches_kept < t->nbranches;
	}
	if (again) {
		tree_mesh_init(&out2);
		CHECK_INT(forest_lod_build(t, budget, &out2, &st2), 0);
		CHECK(mesh_bytes_equal(&out.bark, &out2.bark));
		CHECK(mesh_bytes_equal(&out.leaves, &out2.leaves));
		CHECK(!memcmp(&st, &st2, sizeof(st)));
		tree_mesh_finish(&out2);
	}

	/* The outline: the box within the full one, grown by what a card and a coarser ring
	 * may add (a ring's corners lie on its circle, the full ring's edges as little as
	 * cos(pi / 3) of its radius from its centre), and covering nine tenths of it along
	 * each axis. */
	box_empty(&fb);
	box_add(&fb, &full->bark);
	box_add(&fb, &full->leaves);
	box_empty(&lb);
	box_add(&lb, &out.bark);
	box_add(&lb, &out.leaves);
	allow = half + 0.5 * thickest(t);
	for (int k = 0; k < 3; k++) {
		double grow = fmax(fb.lo[k] - lb.lo[k], lb.hi[k] - fb.hi[k]);
		double ext = fb.hi[k] - fb.lo[k];

		CHECK(grow <= allow + 1e-5);
		if (half > 0)
			mg->card_grow = fmax(mg->card_grow, grow / half);
		else
			mg->bark_grow = fmax(mg->bark_grow, grow / thickest(t));
		if (ext > 1e-3) {
			double cover = (lb.hi[k] - lb.lo[k]) / ext;

			if (!(cover >= 0.9))
				fprintf(stderr, "%zu branches, %zu leaves, budget %zu: axis %d covered "
						"%.3f\n", t->nbranches, t->nleaves, budget, k, cover);
			CHECK(cover >= 0.9);
			mg->cover = fmin(mg->cover, cover);
		}
	}
	tree_mesh_finish(&out);
}

/* The outline's branches as forest.h defines them, written out again. */
static void outline_held(const struct tree *t, const struct mesh *leaves, bool *held)
{
	for (int d = 0; d < 6; d++) {
		int axis = d / 2;
		double sign = d % 2 ? -1.0 : 1.0, far = -INFINITY, leaf = -INFINITY;
		size_t best = SIZE_MAX;

		for (size_t v = 0; leaves && v < leaves->nvertices; v++)
			leaf = fmax(leaf, sign * leaves->positions[3 * v + (size_t)axis]);
		for (size_t i = 0; i < t->nbranches; i++) {
			for (size_t k = 0; k < t->branches[i].npoints; k++) {
				struct vec3 p = t->branches[i].points[k];
				double x = sign * (axis == 0 ? p.x : axis == 1 ? p.y : p.z);

				if (x > far) {
					far = x;
					best = i;
				}
			}
		}
		if (!(far > leaf))
			continue;
		for (int i = (int)best; i >= 0; i = t->branches[i].parent)
			held[i] = true;
	}
}

/* a before b in the order branches go: least worth first, later first on a tie */
static bool goes_before(const double *worth, size_t a, size_t b)
{
	return worth[a] < worth[b] || (worth[a] == worth[b] && a > b);
}

/* forest_lod_keep's promises on t at cap, branch i's bark tr[i] triangles. */
static void check_keep(const struct tree *t, const struct mesh *leaves, const size_t *tr,
		       size_t cap, size_t *only_trunk)
{
	size_t n = t->nbranches, kept, sum = 0, count = 0;
	bool *keep = malloc(n * sizeof(*keep)), *held = calloc(n, sizeof(*held));
	double *worth = malloc(n * sizeof(*worth));
	/* per class (0: nothing holds it, 1: it holds the outline): the last dropped and
	 * the first kept in the order */
	size_t last_gone[2] = { SIZE_MAX, SIZE_MAX }, first_kept[2] = { SIZE_MAX, SIZE_MAX };

	CHECK(keep && held && worth);
	CHECK_INT(forest_lod_keep(t, leaves, tr, cap, keep, &kept), 0);
	outline_held(t, leaves, held);
	CHECK(keep[0]); /* synth_tree's trunk */
	for (size_t i = 0; i < n; i++) {
		int p = t->branches[i].parent;

		if (keep[i]) {
			sum += tr[i];
			count++;
			CHECK(p < 0 || keep[p]);
		}
		worth[i] = tree_branch_length(&t->branches[i]) * t->branches[i].radii[0];
	}
	CHECK_INT(count, kept);
	/* within the cap, or nothing but the trunk left */
	CHECK(sum <= cap || kept == 1);
	*only_trunk += sum > cap;
	for (size_t i = n; i-- > 1;)
		worth[t->branches[i].parent] = fmax(worth[t->branches[i].parent], worth[i]);
	for (size_t i = 1; i < n; i++) {
		int h = held[i];

		if (!keep[i] && (last_gone[h] == SIZE_MAX || goes_before(worth, last_gone[h], i)))
			last_gone[h] = i;
		if (keep[i] && (first_kept[h] == SIZE_MAX || goes_before(worth, i, first_kept[h])))
			first_kept[h] = i;
	}
	/* in each class, what went went before what stayed; the outline's only when nothing
	 * else was left */
	for (int h = 0; h < 2; h++)
		CHECK(last_gone[h] == SIZE_MAX || first_kept[h] == SIZE_MAX ||
		      goes_before(worth, last_gone[h], first_kept[h]));
	CHECK(last_gone[1] == SIZE_MAX || first_kept[0] == SIZE_MAX);
	free(worth);
	free(held);
	free(keep);
}

/* ---- the coarse bark -------------------------------------------------------------- */

/* Winding number of closed triangles [f0, f1) of m around x: 1 inside, 0 outside. */
static double winding(const struct mesh *m, size_t f0, size_t f1, struct vec3 x)
{
	double sum = 0.0;

	for (size_t f = f0; f < f1; f++) {
		struct vec3 a = vec3_sub(pos(m, m->indices[3 * f]), x);
		struct vec3 b = vec3_sub(pos(m, m->indices[3 * f + 1]), x);
		struct vec3 c = vec3_sub(pos(m, m->indices[3 * f + 2]), x);
		double la = vec3_len(a), lb = vec3_len(b), lc = vec3_len(c);
		double num = vec3_dot(a, vec3_cross(b, c));
		double den = la * lb * lc + vec3_dot(a, b) * lc + vec3_dot(a, c) * lb +
			     vec3_dot(b, c) * la;

		sum += 2.0 * atan2(num, den);
	}
	return sum / (4.0 * TEST_PI);
}

/* Distance from x to triangle (a, b, c). */
static double tri_dist(struct vec3 x, struct vec3 a, struct vec3 b, struct vec3 c)
{
	struct vec3 ab = vec3_sub(b, a), ac = vec3_sub(c, a), ax = vec3_sub(x, a);
	struct vec3 n = vec3_cross(ab, ac);
	double nn = vec3_dot(n, n);

	if (nn > 0) {
		/* inside the prism over the triangle: the distance to its plane */
		struct vec3 p = vec3_sub(x, vec3_scale(n, vec3_dot(ax, n) / nn));
		double u = vec3_dot(vec3_cross(vec3_sub(b, p), vec3_sub(c, p)), n);
		double v = vec3_dot(vec3_cross(vec3_sub(c, p), vec3_sub(a, p)), n);
		double w = vec3_dot(vec3_cross(vec3_sub(a, p), vec3_sub(b, p)), n);

		if (u >= 0 && v >= 0 && w >= 0)
			return vec3_dist(x, p);
	}
	{
		const struct vec3 e0[3] = { a, b, c }, e1[3] = { b, c, a };
		double best = INFINITY;

		for (int k = 0; k < 3; k++) {
			struct vec3 d = vec3_sub(e1[k], e0[k]);
			double dd = vec3_dot(d, d);
			double f = dd > 0 ? vec3_dot(vec3_sub(x, e0[k]), d) / dd : 0;

			f = f < 0 ? 0 : f > 1 ? 1 : f;
			best = fmin(best, vec3_dist(x, vec3_add(e0[k], vec3_scale(d, f))));
		}
		return best;
	}
}

/* Distance from x to the surface of triangles [f0, f1) of m. */
static double surface_dist(const struct mesh *m, size_t f0, size_t f1, struct vec3 x)
{
	double best = INFINITY;

	for (size_t f = f0; f < f1; f++)
		best = fmin(best, tri_dist(x, pos(m, m->indices[3 * f]), pos(m, m->indices[3 * f + 1]),
					   pos(m, m->indices[3 * f + 2])));
	return best;
}

static double max_radius(const struct branch *b)
{
	double r = 0.0;

	for (size_t k = 0; k < b->npoints; k++)
		r = fmax(r, b->radii[k]);
	return r;
}

/*
 * Every child's root ring (the first vertices of its part, as far as they lie at one
 * distance from its root point) inside its parent's closed tube or its grandparent's, or
 * shrunk to the least radius (no room at all: a root on the trunk's root disc), or, at a
 * coarse level c, within what the coarser tube may stray from the tree's own (mesh.h:
 * mesh_drop_tolerance of the parent's thickest point times c->drop_scale) of its
 * surface. Returns how many children were checked; *least counts those at the least
 * radius, *out those outside, *poke the most a root showed over what it may.
 */
static size_t check_joints(const struct tree *t, const struct tree_mesh *tm,
			   const struct tree_mesh_marks *mk, const struct mesh_coarse *c,
			   size_t *least, size_t *out, double *poke)
{
	size_t children = 0;

	for (size_t i = 1; i < t->nbranches; i++) {
		const struct branch *b = &t->branches[i];
		size_t v0 = mk->bark[i].nvertices, v1 = mk->bark[i + 1].nvertices, s0 = 0;
		int p = b->parent, gp = t->branches[p].parent;
		double r0, may = 0.0;
		bool at_least, shows = false;

		if (v1 == v0)
			continue;
		if (c && c->drop_scale > 1)
			may = mesh_drop_tolerance(max_radius(&t->branches[p])) * c->drop_scale;
		r0 = vec3_dist(pos(&tm->bark, v0), b->points[0]);
		while (s0 < MESH_MAX_SIDES && v0 + s0 < v1 &&
		       fabs(vec3_dist(pos(&tm->bark, v0 + s0), b->points[0]) - r0) < 2e-6)
			s0++;
		CHECK(s0 >= MESH_MIN_SIDES);
		CHECK(r0 <= b->radii[0] + 1e-6);
		at_least = r0 < TUBE_MIN_RADIUS + 1e-6 && b->radii[0] > TUBE_MIN_RADIUS + 1e-6;
		children++;
		*least += at_least;
		for (size_t j = 0; j < s0 && !at_least; j++) {
			struct vec3 v = pos(&tm->bark, v0 + j);
			size_t pf0 = mk->bark[p].nindices / 3, pf1 = mk->bark[p + 1].nindices / 3;
			double w = winding(&tm->bark, pf0, pf1, v), d;

			if (!(w > 0.5) && gp >= 0)
				w = winding(&tm->bark, mk->bark[gp].nindices / 3,
					    mk->bark[gp + 1].nindices / 3, v);
			if (w > 0.5)
				continue;
			shows = true;
			d = surface_dist(&tm->bark, pf0, pf1, v);
			if (gp >= 0)
				d = fmin(d, surface_dist(&tm->bark, mk->bark[gp].nindices / 3,
							 mk->bark[gp + 1].nindices / 3, v));
			if (!(d <= may))
				fprintf(stderr, "branch %zu: root vertex %zu %.2g m outside parent %d "
						"(may %.2g)\n", i, j, d, p, may);
			CHECK(d <= may);
			*poke = fmax(*poke, d / may);
		}
		*out += shows;
	}
	return children;
}

static void test_coarse(void)
{
	const struct vec3 trunk[] = { { 0, 0, 0 }, { 0, 4, 0 } };
	const double tr[] = { 0.2, 0.2 };
	struct tree t;
	struct tree_mesh a, b;
	struct tree_mesh_marks ma, mb;
	struct rng r;
	size_t all[400], leaves[400 * 4], children = 0, least = 0, out = 0;
	double poke = 0.0;
	int cases = test_cases(40);

	tree_init(&t);
	tree_mesh_init(&a);
	tree_mesh_init(&b);
	tree_mesh_marks_init(&ma);
	tree_mesh_marks_init(&mb);

	/* a straight trunk: its sides capped, at least MESH_MIN_SIDES */
	CHECK_INT(tree_add_branch(&t, -1, 0, ORIGIN_SKETCH, trunk, tr, 2), 0);
	all[0] = 0;
	for (int cap = 0; cap <= MESH_MAX_SIDES + 2; cap++) {
		struct mesh_coarse c = { cap, 1.0 };
		int s = mesh_ring_sides(tr[0]);

		s = cap == 0 || cap >= s ? s : cap < MESH_MIN_SIDES ? MESH_MIN_SIDES : cap;
		CHECK_INT(tree_mesh_build_parts_coarse(&a, &ma, &t, all, 1, NULL, 0, &c), 0);
		/* two rings, the root disc and the tip cone each a copy of one and a centre */
		CHECK_INT(a.bark.nvertices, 4 * (size_t)s + 2);
		CHECK_INT(tris(&a.bark), 4 * (size_t)s);
	}

	rng_seed(&r, 2727);
	for (int k = 0; k < cases; k++) {
		int nb = 1 + (int)(rng_next(&r) % 400), lpb = (int)(rng_next(&r) % 5);
		size_t prev = SIZE_MAX;

		CHECK_INT(synth_tree(&t, nb, lpb, 500 + (uint64_t)k), 0);
		for (size_t i = 0; i < t.nbranches; i++)
			all[i] = i;
		for (size_t i = 0; i < t.nleaves; i++)
			leaves[i] = i;
		/* no coarsening: the same bytes */
		CHECK_INT(tree_mesh_build_parts(&a, &ma, &t, all, t.nbranches, leaves, t.nleaves), 0);
		CHECK_INT(tree_mesh_build_parts_coarse(&b, &mb, &t, all, t.nbranches, leaves,
						       t.nleaves, NULL), 0);
		CHECK(mesh_bytes_equal(&a.bark, &b.bark) && mesh_bytes_equal(&a.leaves, &b.leaves));
		{
			struct mesh_coarse none = { 0, 1.0 }, finer = { 0, 0.5 };

			CHECK_INT(tree_mesh_build_parts_coarse(&b, &mb, &t, all, t.nbranches, leaves,
							       t.nleaves, &none), 0);
			CHECK(mesh_bytes_equal(&a.bark, &b.bark) && mesh_bytes_equal(&a.leaves, &b.leaves));
			CHECK_INT(tree_mesh_build_parts_coarse(&b, &mb, &t, all, t.nbranches, leaves,
							       t.nleaves, &finer), 0);
			CHECK(mesh_bytes_equal(&a.bark, &b.bark) && mesh_bytes_equal(&a.leaves, &b.leaves));
		}
		/* every level: sane, leaves untouched, joints hidden, fewer triangles (or as
		 * many) than the level before */
		for (int l = 0; l < FOREST_LOD_LEVELS; l++) {
			CHECK_INT(tree_mesh_build_parts_coarse(&b, &mb, &t, all, t.nbranches, leaves,
							       t.nleaves, &forest_lod_levels[l]), 0);
			check_mesh_sane(&b.bark);
			CHECK(mesh_bytes_equal(&a.leaves, &b.leaves));
			children += check_joints(&t, &b, &mb, &forest_lod_levels[l], &least, &out,
						 &poke);
			CHECK(tris(&b.bark) <= prev);
			prev = tris(&b.bark);
		}
	}
	printf("coarse bark: %d trees at %d levels, %zu joints: %zu root rings shrunk to the "
	       "least radius, %zu showing outside their parent by at most %.3f of its coarser "
	       "tolerance\n", cases, FOREST_LOD_LEVELS, children, least, out, poke);
	tree_mesh_marks_finish(&mb);
	tree_mesh_marks_finish(&ma);
	tree_mesh_finish(&b);
	tree_mesh_finish(&a);
	tree_finish(&t);
}

/* ---- the least, the cards' faces, colours ------------------------------------------ */

/* A budget of 0 (or 1): the trunk at the coarsest level, and one card if there are leaves. */
static void test_least(void)
{
	struct tree t;
	struct tree_mesh out, trunk;
	struct tree_mesh_marks mk;
	struct forest_lod_stats st;
	const size_t zero = 0;

	tree_init(&t);
	tree_mesh_init(&out);
	tree_mesh_init(&trunk);
	tree_mesh_marks_init(&mk);
	for (int leaves = 0; leaves <= 20; leaves += 20) {
		CHECK_INT(synth_tree(&t, 300, leaves, 31), 0);
		CHECK_INT(tree_mesh_build_parts_coarse(&trunk, &mk, &t, &zero, 1, NULL, 0,
						       &forest_lod_levels[FOREST_LOD_LEVELS - 1]), 0);
		for (size_t budget = 0; budget <= 1; budget++) {
			CHECK_INT(forest_lod_build(&t, budget, &out, &st), 0);
			CHECK(st.over_budget);
			CHECK_INT(st.level, FOREST_LOD_LEVELS);
			CHECK_INT(st.sides, MESH_MIN_SIDES);
			CHECK_INT(st.branches_kept, 1);
			CHECK(mesh_bytes_equal(&out.bark, &trunk.bark));
			CHECK_INT(st.cards, leaves ? 1 : 0);
			CHECK_INT(tris(&out.leaves), leaves ? 2 : 0);
			if (leaves)
				CHECK_INT(st.leaves_as_cards, t.nleaves);
		}
		printf("the least (%s): the trunk at the coarsest level, %zu triangles%s\n",
		       leaves ? "20 leaves a branch" : "no leaves", tris(&trunk.bark),
		       leaves ? ", and one card" : "");
	}
	/* no tree: nothing, within any budget */
	tree_clear(&t);
	CHECK_INT(forest_lod_build(&t, 0, &out, &st), 0);
	CHECK(!st.over_budget && out.bark.nvertices == 0 && out.leaves.nvertices == 0);
	tree_mesh_marks_finish(&mk);
	tree_mesh_finish(&trunk);
	tree_mesh_finish(&out);
	tree_finish(&t);
}

/* Leaves all flattened into planes across `axis` (each at its own mean), every other one
 * turned over (its points reversed: their normals cancel, their axis does not): every
 * card faces along that axis. */
static void test_flat(void)
{
	const size_t budgets[] = { 500, 3000, 12000 };
	struct tree t;
	struct tree_mesh out;
	struct forest_lod_stats st;
	double worst = 0.0;
	size_t cards = 0;

	tree_init(&t);
	tree_mesh_init(&out);
	for (int axis = 0; axis < 3; axis += 2) {
		CHECK_INT(synth_tree(&t, 200, 12, 77), 0);
		for (size_t i = 0; i < t.nleaves; i++) {
			struct leaf *l = &t.leaves[i];
			double mean = 0.0;

			for (size_t k = 0; k < l->npoints; k++)
				mean += axis == 0 ? l->points[k].x : l->points[k].z;
			mean /= (double)l->npoints;
			for (size_t k = 0; k < l->npoints; k++)
				*(axis == 0 ? &l->points[k].x : &l->points[k].z) = mean;
			for (size_t k = 0; i % 2 && k < l->npoints / 2; k++) {
				struct vec3 x = l->points[k];

				l->points[k] = l->points[l->npoints - 1 - k];
				l->points[l->npoints - 1 - k] = x;
			}
		}
		for (size_t b = 0; b < sizeof(budgets) / sizeof(budgets[0]); b++) {
			CHECK_INT(forest_lod_build(&t, budgets[b], &out, &st), 0);
			CHECK(st.cards > 0);
			for (size_t v = 0; v < out.leaves.nvertices; v++) {
				struct vec3 n = nor(&out.leaves, v);
				double along = fabs(axis == 0 ? n.x : n.z);

				worst = fmax(worst, 1.0 - along);
				CHECK(along > 1.0 - 1e-6);
			}
			cards += st.cards;
		}
	}
	printf("flat leaves: %zu cards face along their leaves' axis (|n . axis| >= 1 - %.1e)\n",
	       cards, worst);
	tree_mesh_finish(&out);
	tree_finish(&t);
}

/* Where p falls on card k of m (4 vertices, corners (0,0) (1,0) (1,1) (0,1)): in-plane
 * s, t and the distance along its normal. */
static void card_coords(const struct mesh *m, size_t k, struct vec3 p, double *s, double *t,
			double *h)
{
	struct vec3 q0 = pos(m, 4 * k), e1 = vec3_sub(pos(m, 4 * k + 1), q0);
	struct vec3 e2 = vec3_sub(pos(m, 4 * k + 3), q0), d = vec3_sub(p, q0);

	*s = vec3_dot(d, e1) / vec3_dot(e1, e1);
	*t = vec3_dot(d, e2) / vec3_dot(e2, e2);
	*h = vec3_dot(d, nor(m, 4 * k));
}

/* Every vertex of leaf mesh part [v0, v1) of lm seen along card k's normal falls on it,
 * and lies on one side of it (the card on its leaves' outer face). *side: the side so
 * far (0: none yet). Returns the most a vertex fell off, metres. */
static double check_covers(const struct mesh *cards, size_t k, const struct mesh *lm, size_t v0,
			   size_t v1, int *side)
{
	double off = 0.0, w = vec3_dist(pos(cards, 4 * k), pos(cards, 4 * k + 2));

	for (size_t v = v0; v < v1; v++) {
		double s, t, h;

		card_coords(cards, k, pos(lm, v), &s, &t, &h);
		off = fmax(off, w * fmax(fmax(-s, s - 1.0), fmax(-t, t - 1.0)));
		CHECK(s > -1e-4 && s < 1 + 1e-4 && t > -1e-4 && t < 1 + 1e-4);
		if (fabs(h) > 1e-5) {
			CHECK(*side == 0 || *side == (h > 0 ? 1 : -1));
			*side = h > 0 ? 1 : -1;
		}
	}
	return off;
}

/*
 * A budget of 0: one card for all the leaves of a few autumn trees. Its colour the mean of
 * their palette colours by area; every leaf vertex on it seen along its normal, all behind
 * it; its normal the axis their area vectors a gather round: sum (a . n)^2 / |a| at least
 * that of any of 2,000 random directions.
 */
static void test_one_card(void)
{
	struct tree t;
	struct tree_mesh out, full;
	struct tree_mesh_marks mk;
	struct forest_lod_colors col;
	struct forest_lod_stats st;
	struct rng r;
	double worst_rgb = 0.0, worst_axis = 0.0;

	tree_init(&t);
	tree_mesh_init(&out);
	tree_mesh_init(&full);
	tree_mesh_marks_init(&mk);
	forest_lod_colors_init(&col);
	rng_seed(&r, 11);
	for (int c = 0; c < 6; c++) {
		const struct season_rgb *pal;
		struct vec3 *a;
		double area = 0.0, rgb[3] = { 0, 0, 0 }, best;
		int side = 0;

		CHECK_INT(synth_tree(&t, 20 + 60 * c, 1 + c, 300 + (uint64_t)c), 0);
		t.season = SEASON_AUTUMN;
		CHECK(season_palette(t.season, &pal) > 1);
		CHECK_INT(tree_mesh_build_marked(&full, &t, &mk), 0);
		CHECK_INT(forest_lod_build_colors(&t, 0, &out, &col, &st), 0);
		CHECK_INT(st.cards, 1);
		CHECK_INT(col.n, 4);
		a = calloc(t.nleaves, sizeof(*a));
		CHECK(a);
		for (size_t i = 0; i < t.nleaves; i++) {
			const struct season_rgb *lc = &pal[season_leaf_color(t.season, &t.leaves[i])];
			size_t f0 = mk.leaves[i].nindices / 3, f1 = mk.leaves[i + 1].nindices / 3;
			double ai = 0.0;

			for (size_t f = f0; f < f1; f++) {
				struct vec3 p = pos(&full.leaves, full.leaves.indices[3 * f]);
				struct vec3 q = pos(&full.leaves, full.leaves.indices[3 * f + 1]);
				struct vec3 e = pos(&full.leaves, full.leaves.indices[3 * f + 2]);
				struct vec3 x = vec3_cross(vec3_sub(q, p), vec3_sub(e, p));

				ai += 0.5 * vec3_len(x);
				a[i] = vec3_add(a[i], vec3_scale(x, 0.5));
			}
			area += ai;
			rgb[0] += ai * lc->r;
			rgb[1] += ai * lc->g;
			rgb[2] += ai * lc->b;
			(void)check_covers(&out.leaves, 0, &full.leaves, mk.leaves[i].nvertices,
					   mk.leaves[i + 1].nvertices, &side);
		}
		for (int ch = 0; ch < 3; ch++) {
			CHECK_NEAR(col.rgb[ch], rgb[ch] / area, 1e-5);
			worst_rgb = fmax(worst_rgb, fabs(col.rgb[ch] - rgb[ch] / area));
		}
		/* the principal axis */
		{
			struct vec3 n = nor(&out.leaves, 0);
			double fn = 0.0;

			for (size_t i = 0; i < t.nleaves; i++)
				if (vec3_len(a[i]) > 0)
					fn += pow(vec3_dot(a[i], n), 2) / vec3_len(a[i]);
			best = fn;
			for (int k = 0; k < 2000; k++) {
				struct vec3 d = vec3(rng_range(&r, -1, 1), rng_range(&r, -1, 1),
						     rng_range(&r, -1, 1));
				double fd = 0.0;

				d = vec3_norm_or(d, vec3(0, 1, 0));
				for (size_t i = 0; i < t.nleaves; i++)
					if (vec3_len(a[i]) > 0)
						fd += pow(vec3_dot(a[i], d), 2) / vec3_len(a[i]);
				best = fmax(best, fd);
			}
			CHECK(fn >= best * (1.0 - 1e-6));
			worst_axis = fmax(worst_axis, 1.0 - fn / best);
		}
		free(a);
	}
	printf("one card: 6 trees, its colour the leaves' by area within %.1e, every leaf "
	       "vertex on it and behind it, its normal their axis (within %.1e of the best of "
	       "2,000 directions)\n", worst_rgb, worst_axis);
	forest_lod_colors_finish(&col);
	tree_mesh_marks_finish(&mk);
	tree_mesh_finish(&full);
	tree_mesh_finish(&out);
	tree_finish(&t);
}

static void test_colors(void)
{
	struct tree t;
	struct tree_mesh out, full;
	struct tree_mesh_marks mk;
	struct forest_lod_colors col;
	struct forest_lod_stats st;
	const struct season_rgb *pal;
	size_t npal;
	float lo[3] = { 1, 1, 1 }, hi[3] = { 0, 0, 0 }, *rgb;

	tree_init(&t);
	tree_mesh_init(&out);
	tree_mesh_init(&full);
	tree_mesh_marks_init(&mk);
	forest_lod_colors_init(&col);
	CHECK_INT(synth_tree(&t, 50, 20, 5), 0);
	t.season = SEASON_AUTUMN;
	npal = season_palette(t.season, &pal);
	CHECK(npal > 1);
	for (size_t i = 0; i < npal; i++) {
		const float c[3] = { pal[i].r, pal[i].g, pal[i].b };

		for (int ch = 0; ch < 3; ch++) {
			lo[ch] = fminf(lo[ch], c[ch]);
			hi[ch] = fmaxf(hi[ch], c[ch]);
		}
	}
	CHECK_INT(tree_mesh_build_marked(&full, &t, &mk), 0);
	rgb = malloc(full.leaves.nvertices * 3 * sizeof(*rgb));
	CHECK(rgb && leaf_colors_fill(&t, &mk, full.leaves.nvertices, rgb));

	/* as they are: leaf_colors_fill's */
	CHECK_INT(forest_lod_build_colors(&t, 1000000, &out, &col, &st), 0);
	CHECK_INT(col.n, out.leaves.nvertices);
	CHECK(!memcmp(col.rgb, rgb, col.n * 3 * sizeof(float)));

	/* a card a leaf: its leaf's colour (cards numbered in the order of their first leaf) */
	/* (the leaves' own triangles less one: the bark takes 40%, the rest holds a card a
	 * leaf at 2 triangles, since a leaf has 4 or more) */
	CHECK(tris(&full.leaves) >= 4 * t.nleaves);
	CHECK_INT(forest_lod_build_colors(&t, tris(&full.leaves) - 1, &out, &col, &st), 0);
	CHECK_INT(st.cards, t.nleaves);
	CHECK_INT(col.n, 4 * st.cards);
	for (size_t k = 0; k < st.cards; k++) {
		const struct season_rgb *c = &pal[season_leaf_color(t.season, &t.leaves[k])];
		int side = 0;

		/* and the card covers its leaf */
		(void)check_covers(&out.leaves, k, &full.leaves, mk.leaves[k].nvertices,
				   mk.leaves[k + 1].nvertices, &side);

		for (int v = 0; v < 4; v++) {
			const float *x = &col.rgb[3 * (4 * k + (size_t)v)];

			CHECK(x[0] == c->r && x[1] == c->g && x[2] == c->b);
		}
	}

	/* many leaves a card: one colour a card, between the palette's */
	CHECK_INT(forest_lod_build_colors(&t, 2000, &out, &col, &st), 0);
	CHECK(st.cards > 0 && st.cards < t.nleaves);
	CHECK_INT(col.n, 4 * st.cards);
	for (size_t k = 0; k < st.cards; k++) {
		for (int ch = 0; ch < 3; ch++) {
			float x = col.rgb[3 * 4 * k + (size_t)ch];

			CHECK(x >= lo[ch] - 1e-6f && x <= hi[ch] + 1e-6f);
			for (int v = 1; v < 4; v++)
				CHECK(col.rgb[3 * (4 * k + (size_t)v) + (size_t)ch] == x);
		}
	}
	/* summer: its one green; winter: none (the leaves are not drawn) */
	t.season = SEASON_SUMMER;
	CHECK(season_palette(t.season, &pal) == 1);
	CHECK_INT(forest_lod_build_colors(&t, 2000, &out, &col, &st), 0);
	for (size_t v = 0; v < col.n; v++)
		CHECK(col.rgb[3 * v] == pal[0].r && col.rgb[3 * v + 1] == pal[0].g &&
		      col.rgb[3 * v + 2] == pal[0].b);
	CHECK_INT(col.n, out.leaves.nvertices);
	t.season = SEASON_WINTER;
	CHECK_INT(forest_lod_build_colors(&t, 2000, &out, &col, &st), 0);
	CHECK_INT(col.n, 0);
	CHECK_INT(forest_lod_build_colors(&t, 1000000, &out, &col, &st), 0);
	CHECK_INT(col.n, 0);
	printf("colours: a leaf its own, a card a leaf its leaf's, a card of many between the "
	       "palette's; summer one, winter none\n");
	free(rgb);
	forest_lod_colors_finish(&col);
	tree_mesh_marks_finish(&mk);
	tree_mesh_finish(&full);
	tree_mesh_finish(&out);
	tree_finish(&t);
}

/* ---- sizes and shares -------------------------------------------------------------- */

static void turn_about(struct tree *t, struct vec3 foot, double angle, struct vec3 shift)
{
	double c = cos(angle), s = sin(angle);

	for (size_t i = 0; i < t->nbranches; i++) {
		for (size_t k = 0; k < t->branches[i].npoints; k++) {
			struct vec3 d = vec3_sub(t->branches[i].points[k], foot);

			t->branches[i].points[k] = vec3_add(
				vec3_add(foot, shift), vec3(c * d.x - s * d.z, d.y, s * d.x + c * d.z));
		}
	}
	for (size_t i = 0; i < t->nleaves; i++) {
		for (size_t k = 0; k < t->leaves[i].npoints; k++) {
			struct vec3 d = vec3_sub(t->leaves[i].points[k], foot);

			t->leaves[i].points[k] = vec3_add(
				vec3_add(foot, shift), vec3(c * d.x - s * d.z, d.y, s * d.x + c * d.z));
		}
	}
}

static void test_sizes(void)
{
	const struct vec3 trunk[] = { { 1, 2, 3 }, { 1, 4, 3 }, { 1, 7, 3 } };
	const double tr[] = { 0.3, 0.2, 0.1 };
	const struct vec3 side[] = { { 1, 4, 3 }, { 4, 4, 3 } };
	const double sr[] = { 0.05, 0.05 };
	const struct vec3 bad[] = { { 1, 5, 3 }, { NAN, 100, 3 }, { 1, 5.5, INFINITY } };
	const double br[] = { 0.05, 0.05, 0.05 };
	const struct vec3 leaf[] = { { 1, 9, -2 }, { 1, 8.9, -1.9 }, { 1.05, 8.9, -1.95 } };
	struct tree t;
	struct rng r;
	double worst = 0.0;
	int cases = test_cases(100);

	tree_init(&t);
	CHECK_NEAR(forest_tree_height(&t), 0.0, 0.0);
	CHECK_NEAR(forest_tree_crown_width(&t), 0.0, 0.0);
	/* a trunk: its top and its thickest point */
	CHECK_INT(tree_add_branch(&t, -1, 0, ORIGIN_SKETCH, trunk, tr, 3), 0);
	CHECK_NEAR(forest_tree_height(&t), 5.1, 1e-12);
	CHECK_NEAR(forest_tree_crown_width(&t), 0.6, 1e-12);
	/* a branch out to the side: 3 m and its radius from the trunk's axis */
	CHECK_INT(tree_add_branch(&t, 0, 0.4, ORIGIN_SKETCH, side, sr, 2), 1);
	CHECK_NEAR(forest_tree_height(&t), 5.1, 1e-12);
	CHECK_NEAR(forest_tree_crown_width(&t), 6.1, 1e-12);
	/* points that are not finite count for nothing */
	CHECK_INT(tree_add_branch(&t, 0, 0.6, ORIGIN_SKETCH, bad, br, 3), 2);
	CHECK_NEAR(forest_tree_height(&t), 5.1, 1e-12);
	CHECK_NEAR(forest_tree_crown_width(&t), 6.1, 1e-12);
	/* a leaf higher and farther (5 m from the axis, behind) */
	CHECK_INT(tree_add_leaf(&t, 0, ORIGIN_SKETCH, leaf, 3), 0);
	CHECK_NEAR(forest_tree_height(&t), 7.0, 1e-12);
	CHECK_NEAR(forest_tree_crown_width(&t), 10.0, 1e-12);

	/* random trees turned about the vertical through the foot, and moved: the same */
	rng_seed(&r, 99);
	for (int c = 0; c < cases; c++) {
		double h, w, angle = rng_range(&r, 0.0, 2.0 * TEST_PI);
		struct vec3 shift = vec3(rng_range(&r, -50, 50), rng_range(&r, -5, 5),
					 rng_range(&r, -50, 50));

		CHECK_INT(synth_tree(&t, 1 + (int)(rng_next(&r) % 300), (int)(rng_next(&r) % 6),
				     (uint64_t)c), 0);
		h = forest_tree_height(&t);
		w = forest_tree_crown_width(&t);
		CHECK(h > 5.0 && w > 0.0);
		turn_about(&t, t.branches[0].points[0], angle, shift);
		CHECK_NEAR(forest_tree_height(&t), h, 1e-9 * h + 1e-12);
		CHECK_NEAR(forest_tree_crown_width(&t), w, 1e-9 * w + 1e-12);
		worst = fmax(worst, fabs(forest_tree_crown_width(&t) - w) / w);
	}
	printf("sizes: 4 shapes; %d random trees turned and moved: crown width the same within "
	       "%.1e of itself\n", cases, worst);
	tree_finish(&t);
}

static void test_shares(void)
{
	struct rng r;
	int cases = test_cases(500);
	double worst_prop = 0.0;
	size_t worst_left = 0;

	rng_seed(&r, 4040);
	for (int c = 0; c < cases; c++) {
		size_t n = 1 + (size_t)(rng_next(&r) % 60), total = (size_t)(rng_next(&r) % 1000000);
		size_t need[60], share[60], sum = 0, open = 0;
		double w[60];
		bool use_need = rng_next(&r) % 4 != 0, zero = rng_next(&r) % 10 == 0;

		for (size_t i = 0; i < n; i++) {
			uint64_t k = rng_next(&r) % 20;

			w[i] = zero ? 0.0 : k == 0 ? -1.0 : k == 1 ? NAN : rng_range(&r, 0.2, 30.0);
			need[i] = rng_next(&r) % 3 == 0 ? (size_t)(rng_next(&r) % 3000)
							: 1000 + (size_t)(rng_next(&r) % 100000);
		}
		forest_lod_shares(w, use_need ? need : NULL, n, total, share);
		for (size_t i = 0; i < n; i++) {
			sum += share[i];
			if (use_need)
				CHECK(share[i] <= need[i]);
			open += !use_need || share[i] < need[i];
		}
		CHECK(sum <= total);
		/* all of it given, but for a triangle a tree lost to rounding, unless every
		 * tree has what it needs */
		if (open > 0) {
			CHECK(total - sum <= open);
			worst_left = total - sum > worst_left ? total - sum : worst_left;
		}
		/* the trees short of what they need share in proportion to their widths (all
		 * alike when no width counts) */
		for (size_t i = 0; i < n; i++) {
			for (size_t j = 0; j < n; j++) {
				double wi = isfinite(w[i]) && w[i] > 0 ? w[i] : 0.0;
				double wj = isfinite(w[j]) && w[j] > 0 ? w[j] : 0.0;

				if (use_need && (share[i] >= need[i] || share[j] >= need[j]))
					continue;
				if (zero) {
					CHECK(share[i] <= share[j] + 1);
					continue;
				}
				if (wj > 0) {
					double want = (double)(share[j] + 1) * wi / wj;

					CHECK((double)share[i] <= want + 1e-9 * want);
					if (wi > 0)
						worst_prop = fmax(worst_prop,
								  fabs((double)share[i] / wi -
								       (double)share[j] / wj) *
									  fmin(wi, wj));
				} else {
					CHECK(wi > 0 || share[i] == share[j]);
				}
				if (wi == 0 && wj > 0)
					CHECK_INT(share[i], 0);
			}
		}
	}
	printf("shares: %d forests: within the total, at most %zu triangles unshared, "
	       "proportional within %.3f triangles\n", cases, worst_left, worst_prop);
}

/* A part's mesh m holds part p's triangles from triangle f0 on, byte for byte (its
 * vertices after those before it, its indices moved on by as many). */
static void check_holds(const struct mesh *m, size_t f0, const struct mesh *p)
{
	size_t v0;

	CHECK(3 * f0 + p->nindices <= m->nindices);
	if (p->nindices == 0)
		return;
	v0 = m->indices[3 * f0] - p->indices[0];
	CHECK(v0 + p->nvertices <= m->nvertices);
	CHECK(!memcmp(&m->positions[3 * v0], p->positions, 3 * p->nvertices * sizeof(float)));
	CHECK(!memcmp(&m->normals[3 * v0], p->normals, 3 * p->nvertices * sizeof(float)));
	for (size_t i = 0; i < p->nindices; i++)
		CHECK(m->indices[3 * f0 + i] == p->indices[i] + v0);
}

/*
 * The wood's bark and the vines in a tree's part (issue 27): a grown tree and a tree with
 * two vines. Within a budget that holds everything, the part's bark is the tree's own
 * (its tubes, the wood's branches left out), then the wood's bark, then the vines' stems,
 * and its leaves the tree's then the vines', all byte for byte; at a small budget the
 * wood is still there, made coarser: the part reaches the wood's box.
 */
static void test_wood_vines(void)
{
	struct tree t;
	struct tree_mesh own, out;
	struct mesh stems, vleaves;
	struct forest_lod_stats st;

	tree_init(&t);
	tree_mesh_init(&own);
	tree_mesh_init(&out);
	mesh_init(&stems);
	mesh_init(&vleaves);
	for (int kind = 0; kind < 2; kind++) {
		const struct mesh *wood;
		size_t all;

		if (kind == 0)
			CHECK_INT(synth_wood_tree(&t, 2, WOOD_BROADLEAF), 0);
		else
			CHECK_INT(synth_vine_tree(&t, 2), 0);
		CHECK(kind == 0 ? t.wood != NULL : t.nvines == 2);
		wood = t.wood ? &t.wood->bark : NULL;
		CHECK(!wood || tris(wood) > 0);
		CHECK_INT(tree_mesh_build(&own, &t), 0);
		mesh_clear(&stems);
		mesh_clear(&vleaves);
		for (size_t i = 0; i < t.nvines; i++)
			CHECK_INT(vine_mesh_append(&t.vines[i], &stems, &vleaves), 0);
		all = tris(&own.bark) + (wood ? tris(wood) : 0) + tris(&stems) + tris(&own.leaves) +
		      tris(&vleaves);
		for (size_t budget = all; budget <= 4 * all; budget *= 2) {
			CHECK_INT(forest_lod_build(&t, budget, &out, &st), 0);
			CHECK_INT(st.full_triangles, all);
			CHECK_INT(tris(&out.bark), tris(&own.bark) + (wood ? tris(wood) : 0) +
							   tris(&stems));
			CHECK_INT(tris(&out.leaves), tris(&own.leaves) + tris(&vleaves));
			check_holds(&out.bark, 0, &own.bark);
			if (wood)
				check_holds(&out.bark, tris(&own.bark), wood);
			check_holds(&out.bark, tris(&out.bark) - tris(&stems), &stems);
			check_holds(&out.leaves, 0, &own.leaves);
			check_holds(&out.leaves, tris(&own.leaves), &vleaves);
		}
		if (wood) {
			struct box wb, pb;

			CHECK_INT(forest_lod_build(&t, 300, &out, &st), 0);
			CHECK(!st.over_budget && tris(&out.bark) + tris(&out.leaves) <= 300);
			box_empty(&wb);
			box_add(&wb, wood);
			box_empty(&pb);
			box_add(&pb, &out.bark);
			for (int k = 0; k < 3; k++)
				CHECK(pb.lo[k] <= wb.lo[k] && pb.hi[k] >= wb.hi[k]);
			printf("a grown tree: its wood's %zu triangles in its part; within 300, %zu "
			       "triangles of bark reach the wood's box\n", tris(wood), tris(&out.bark));
		} else {
			printf("a tree with 2 vines: their %zu stem and %zu leaf triangles in its "
			       "part\n", tris(&stems), tris(&vleaves));
		}
	}
	mesh_finish(&vleaves);
	mesh_finish(&stems);
	tree_mesh_finish(&out);
	tree_mesh_finish(&own);
	tree_finish(&t);
}

/* The wind binds a tree's levels of detail as any mesh on it (live_attrs_bind_nearest):
 * every vertex of bark and cards. */
static void test_wind(void)
{
	struct tree t;
	struct tree_mesh out;
	struct live_skeleton sk;
	struct live_attrs a;
	struct forest_lod_stats st;
	size_t bound = 0;

	tree_init(&t);
	tree_mesh_init(&out);
	live_attrs_init(&a);
	CHECK_INT(synth_tree(&t, 400, 10, 8), 0);
	CHECK_INT(live_skeleton_init(&sk, &t, 8), 0);
	for (size_t budget = 500; budget <= 8000; budget *= 4) {
		CHECK_INT(forest_lod_build(&t, budget, &out, &st), 0);
		CHECK(st.cards > 0);
		CHECK_INT(live_attrs_bind_nearest(&a, &sk, &t, &out.bark), 0);
		CHECK_INT(a.n, out.bark.nvertices);
		bound += a.n;
		CHECK_INT(live_attrs_bind_nearest(&a, &sk, &t, &out.leaves), 0);
		CHECK_INT(a.n, out.leaves.nvertices);
		bound += a.n;
	}
	printf("wind: %zu vertices of bark and cards bound at 3 budgets\n", bound);
	live_skeleton_finish(&sk);
	live_attrs_finish(&a);
	tree_mesh_finish(&out);
	tree_finish(&t);
}

static void test_random(void)
{
	struct rng r;
	int cases = test_cases(300);
	struct margins mg = { INFINITY, 0.0, 0.0, 0, 0, 0, 0 };
	size_t only_trunk = 0;

	rng_seed(&r, 27027);
	for (int c = 0; c < cases; c++) {
		int nb = 1 + (int)(rng_next(&r) % 1000), lpb = (int)(rng_next(&r) % 21);
		struct tree t;
		struct tree_mesh full;
		struct tree_mesh_marks mk;
		size_t own, drawn = 0;

		tree_init(&t);
		tree_mesh_init(&full);
		tree_mesh_marks_init(&mk);
		CHECK_INT(synth_tree(&t, nb, lpb, 100 + (uint64_t)c), 0);
		CHECK_INT(tree_mesh_build_marked(&full, &t, &mk), 0);
		CHECK_INT(mk.nleaves, t.nleaves + 1);
		for (size_t i = 0; i < t.nleaves; i++)
			drawn += mk.leaves[i + 1].nindices > mk.leaves[i].nindices;
		own = tris(&full.bark) + tris(&full.leaves);
		for (int b = 0; b < 2; b++) {
			size_t budget = (size_t)exp(rng_range(&r, log(500.0), log(300000.0)));

			check_one(&t, &full, drawn, budget, b == 0, &mg);
		}
		check_one(&t, &full, drawn, own, false, &mg);
		if (own > 500)
			check_one(&t, &full, drawn, own - 1, false, &mg);

		/* forest_lod_keep alone, on random per-branch counts and caps */
		{
			size_t *tr = malloc(t.nbranches * sizeof(*tr)), total = 0;

			CHECK(tr);
			for (size_t i = 0; i < t.nbranches; i++) {
				tr[i] = 12 + rng_next(&r) % 60;
				total += tr[i];
			}
			check_keep(&t, &full.leaves, tr, (size_t)(rng_uniform(&r) * (double)total),
				   &only_trunk);
			check_keep(&t, NULL, tr, 0, &only_trunk);
			free(tr);
		}
		tree_mesh_marks_finish(&mk);
		tree_mesh_finish(&full);
		tree_finish(&t);
	}
	printf("random trees: %d trees, %zu builds (%zu the tree's own meshes, %zu with cards, "
	       "%zu with branches left out)\n", cases, mg.cases, mg.full, mg.carded, mg.pruned);
	printf("  outline: least cover of the full extent %.4f (at least 0.9); past the full "
	       "box by at most %.3f of the largest card's half-size with cards, %.3f of the "
	       "thickest radius without\n", mg.cover, mg.card_grow, mg.bark_grow);
	printf("  forest_lod_keep: %d trees at a random cap and at 0, %zu of them over the cap "
	       "with the trunk alone\n", cases, only_trunk);
}

int main(void)
{
	test_sizes();
	test_shares();
	test_coarse();
	test_least();
	test_flat();
	test_one_card();
	test_colors();
	test_wind();
	test_wood_vines();
	test_random();
	return 0;
}
