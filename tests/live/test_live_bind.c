/* SPDX-License-Identifier: MIT */
/*
 * Binding meshes to the skeleton (src/live/live_attrs.c, live_nearest.c;
 * docs/living-trees.md, "Per-vertex data"), on the demo, the presets, seeded random
 * trees, a tree with vines and one with wood:
 *
 * - a bark vertex's skeleton point is on its own branch, within the branch's largest
 *   radius of the vertex; most are snapped to the ring they belong to;
 * - without marks the binding is the same, byte for byte; marks of another tree or a
 *   mesh of another size are refused;
 * - the grid's nearest skeleton point is the brute-force scan's (the same |p - q| - r(q)),
 *   for points on, near and far from random trees;
 * - nearest binding of the bark itself moves as the bark binding does, within 1% of H at
 *   strength 1, for all but 1% of the vertices (where random branches cross); on a
 *   vine's stems no edge stretches by more than the wind's steepest gradient, on the
 *   wood's iso-surface the fork's crease is bounded and only bark where a twig comes out
 *   of the wood goes with the twig;
 * - a leaf's vertices share their anchor; their distance from it is what `leaf` holds;
 * - the same inputs give the same bytes.
 *
 * It prints the fractions and worst figures.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "live.h"
#include "live_private.h"
#include "live_trees.h"
#include "mesh.h"
#include "rng.h"
#include "synth_vine.h"
#include "synth_wood.h"
#include "test.h"
#include "vine.h"
#include "wood.h"

#define RANDOM_TREES 200

static size_t bark_vertices, snapped, nearest_same, nearest_total;
static size_t nearest_apart;
static double worst_grid, worst_stretch;

static struct vec3 pos_of(const struct mesh *m, size_t i)
{
	return vec3(m->positions[3 * i], m->positions[3 * i + 1], m->positions[3 * i + 2]);
}

static struct vec3 point_of(const struct live_vertex *v)
{
	return vec3(v->point[0], v->point[1], v->point[2]);
}

static double max_radius(const struct branch *b)
{
	double r = 0.0;

	for (size_t j = 0; j < b->npoints; j++)
		r = fmax(r, b->radii[j]);
	return r;
}

/* Whether skeleton point p lies on branch b (within float rounding). */
static bool on_branch(const struct branch *b, struct vec3 p)
{
	for (size_t j = 0; j + 1 < b->npoints; j++) {
		struct vec3 e = vec3_sub(b->points[j + 1], b->points[j]);
		double ee = vec3_dot(e, e), f = ee > 0 ? vec3_dot(vec3_sub(p, b->points[j]), e) / ee : 0;

		f = f < 0 ? 0 : f > 1 ? 1 : f;
		if (vec3_dist(p, vec3_add(b->points[j], vec3_scale(e, f))) <= 1e-5)
			return true;
	}
	return b->npoints == 1 && vec3_dist(p, b->points[0]) <= 1e-5;
}

/* The least |p - q| - r(q) over every segment, scanned. */
static double brute_nearest(const struct tree *t, struct vec3 p)
{
	double best = INFINITY;

	for (size_t i = 0; i < t->nbranches; i++) {
		const struct branch *b = &t->branches[i];

		for (size_t j = 0; j + 1 < b->npoints; j++) {
			struct vec3 e = vec3_sub(b->points[j + 1], b->points[j]);
			double ee = vec3_dot(e, e), f = ee > 0 ? vec3_dot(vec3_sub(p, b->points[j]), e) / ee : 0;

			f = f < 0 ? 0 : f > 1 ? 1 : f;
			best = fmin(best, vec3_dist(p, vec3_add(b->points[j], vec3_scale(e, f))) -
						  (b->radii[j] + (b->radii[j + 1] - b->radii[j]) * f));
		}
	}
	return best;
}

/* The grid's answer's |p - q| - r(q), recomputed from the branch and arc length. */
static double grid_metric(const struct live_skeleton *sk, const struct tree *t, size_t b, double s,
			  struct vec3 p)
{
	const struct branch *br = &t->branches[b];
	const double *arc = &sk->arc[sk->branches[b].first];
	size_t j = 0;
	double f, r;

	while (j + 2 < br->npoints && arc[j + 1] < s)
		j++;
	f = arc[j + 1] > arc[j] ? (s - arc[j]) / (arc[j + 1] - arc[j]) : 0.0;
	r = br->radii[j] + (br->radii[j + 1] - br->radii[j]) * f;
	return vec3_dist(p, live_branch_point(sk, br, b, s)) - r;
}

static void check_grid(const struct live_skeleton *sk, const struct tree *t, struct rng *r)
{
	struct live_grid g;
	struct vec3 lo = vec3(INFINITY, INFINITY, INFINITY), hi = vec3(-INFINITY, -INFINITY, -INFINITY);

	CHECK_INT(live_grid_build(&g, sk, t), 0);
	for (size_t i = 0; i < t->nbranches; i++)
		for (size_t j = 0; j < t->branches[i].npoints; j++) {
			struct vec3 p = t->branches[i].points[j];

			lo = vec3(fmin(lo.x, p.x), fmin(lo.y, p.y), fmin(lo.z, p.z));
			hi = vec3(fmax(hi.x, p.x), fmax(hi.y, p.y), fmax(hi.z, p.z));
		}
	for (int k = 0; k < 300; k++) {
		/* around the tree's box, a third of it beyond on every side; and on branches */
		struct vec3 d = vec3_sub(hi, lo), p;
		size_t b;
		double s, want, got;

		if (k % 3 == 0) {
			size_t bi = rng_next(r) % t->nbranches;

			p = vec3_add(live_trees_point(t, bi, rng_uniform(r)),
				     vec3(rng_range(r, -0.3, 0.3), rng_range(r, -0.3, 0.3),
					  rng_range(r, -0.3, 0.3)));
		} else {
			p = vec3(lo.x + d.x * rng_range(r, -0.34, 1.34), lo.y + d.y * rng_range(r, -0.34, 1.34),
				 lo.z + (d.z + 1.0) * rng_range(r, -0.34, 1.34));
		}
		live_grid_nearest(&g, p, &b, &s);
		want = brute_nearest(t, p);
		got = grid_metric(sk, t, b, s, p);
		worst_grid = fmax(worst_grid, fabs(got - want));
		CHECK(fabs(got - want) <= 1e-9 * (1 + fabs(want)));
	}
	live_grid_finish(&g);
}

/* The largest |offset(a) - offset(b)| / |a - b| over m's edges, at strength 1. */
static double stretch(const struct live_skeleton *sk, const struct live_attrs *a,
		      const struct mesh *m)
{
	struct live_wind w;
	struct live_wind_params p = { .strength = 1.0, .angle = 0.4 };
	double worst = 0.0;

	CHECK_INT(live_wind_setup(&w, sk, &p), 0);
	for (int k = 0; k < 8; k++) {
		double t = w.loop * k / 8.0;

		for (size_t i = 0; i < m->nindices; i++) {
			uint32_t va = m->indices[i], vb = m->indices[i % 3 == 2 ? i - 2 : i + 1];
			double e = vec3_dist(pos_of(m, va), pos_of(m, vb));

			if (e > 1e-6) {
				double dd = vec3_dist(live_wind_offset(&w, &a->v[va], t),
							      live_wind_offset(&w, &a->v[vb], t));
				worst = fmax(worst, dd / e);
			}
		}
	}
	return worst;
}

static void check_tree(const struct tree *t, uint64_t seed, struct rng *r)
{
	struct live_skeleton sk;
	struct tree_mesh tm;
	struct tree_mesh_marks mk;
	struct live_attrs bark, bark2, leaves, leaves2, near;

	tree_mesh_init(&tm);
	tree_mesh_marks_init(&mk);
	live_attrs_init(&bark);
	live_attrs_init(&bark2);
	live_attrs_init(&leaves);
	live_attrs_init(&leaves2);
	live_attrs_init(&near);
	CHECK_INT(live_skeleton_init(&sk, t, seed), 0);
	CHECK_INT(tree_mesh_build_marked(&tm, t, &mk), 0);
	CHECK_INT(live_attrs_bind_bark(&bark, &sk, t, &tm.bark, &mk), 0);
	CHECK_INT(live_attrs_bind_leaves(&leaves, &sk, t, &tm.leaves, &mk), 0);
	CHECK(bark.n == tm.bark.nvertices && leaves.n == tm.leaves.nvertices);

	/* without marks: the same bytes */
	CHECK_INT(live_attrs_bind_bark(&bark2, &sk, t, &tm.bark, NULL), 0);
	CHECK_INT(live_attrs_bind_leaves(&leaves2, &sk, t, &tm.leaves, NULL), 0);
	CHECK(bark2.n == bark.n);
	CHECK(bark.n == 0 || memcmp(bark.v, bark2.v, bark.n * sizeof(*bark.v)) == 0);
	CHECK(leaves2.n == leaves.n);
	CHECK(leaves.n == 0 || memcmp(leaves.v, leaves2.v, leaves.n * sizeof(*leaves.v)) == 0);

	for (size_t b = 0; b < t->nbranches; b++) {
		const struct branch *br = &t->branches[b];
		double rmax = max_radius(br);

		for (size_t i = mk.bark[b].nvertices; i < mk.bark[b + 1].nvertices; i++) {
			struct vec3 q = point_of(&bark.v[i]), v = pos_of(&tm.bark, i);
			bool ring = false;

			CHECK(on_branch(br, q));
			CHECK(vec3_dist(v, q) <= rmax * 1.001 + 1e-5);
			CHECK(bark.v[i].leaf == 0.0f && bark.v[i].flutter[0] == 0 &&
			      bark.v[i].flutter[1] == 0 && bark.v[i].flutter[2] == 0);
			for (size_t j = 0; j < br->npoints && !ring; j++)
				ring = (float)br->points[j].x == bark.v[i].point[0] &&
				       (float)br->points[j].y == bark.v[i].point[1] &&
				       (float)br->points[j].z == bark.v[i].point[2];
			snapped += ring;
			bark_vertices++;
		}
	}
	for (size_t l = 0; l < t->nleaves; l++) {
		size_t v0 = mk.leaves[l].nvertices;

		for (size_t i = v0; i < mk.leaves[l + 1].nvertices; i++) {
			CHECK(memcmp(leaves.v[i].point, leaves.v[v0].point, sizeof(leaves.v[i].point)) == 0);
			CHECK(memcmp(leaves.v[i].flutter, leaves.v[v0].flutter, 4) == 0);
			CHECK(leaves.v[i].phase[0] == sk.leaf_phase[l]);
			CHECK_NEAR(leaves.v[i].leaf, vec3_dist(pos_of(&tm.leaves, i), point_of(&leaves.v[i])),
				   1e-6);
		}
	}

	/* nearest binding of the bark: its own branch mostly (a root ring inside its parent,
	 * a tip cone among its children go with them), and moving as the bark binding does
	 * but where branches cross (random trees cross theirs: what is nearest there is
	 * another limb's) */
	CHECK_INT(live_attrs_bind_nearest(&near, &sk, t, &tm.bark), 0);
	{
		struct live_wind w;
		struct live_wind_params p = { .strength = 1.0, .angle = 0.0 };

		CHECK_INT(live_wind_setup(&w, &sk, &p), 0);
		for (size_t b = 0; b < t->nbranches; b++)
			for (size_t i = mk.bark[b].nvertices; i < mk.bark[b + 1].nvertices; i++) {
				double dd = 0.0;

				nearest_same += on_branch(&t->branches[b], point_of(&near.v[i]));
				nearest_total++;
				for (int k = 0; k < 4; k++) {
					double tt = w.loop * k / 4.0;

					dd = fmax(dd, vec3_dist(live_wind_offset(&w, &near.v[i], tt),
								live_wind_offset(&w, &bark.v[i], tt)));
				}
				nearest_apart += dd > 0.01 * sk.height;
			}
	}
	check_grid(&sk, t, r);

	/* refused: another tree's marks, a mesh of another size */
	if (t->nbranches > 1) {
		struct tree_mesh_marks other = mk;
		struct mesh cut = tm.bark;

		other.nbark = mk.nbark - 1;
		CHECK_INT(live_attrs_bind_bark(&bark2, &sk, t, &tm.bark, &other), -EINVAL);
		if (cut.nvertices > 0) {
			cut.nvertices--;
			CHECK_INT(live_attrs_bind_bark(&bark2, &sk, t, &cut, NULL), -EINVAL);
		}
	}

	live_attrs_finish(&near);
	live_attrs_finish(&leaves2);
	live_attrs_finish(&leaves);
	live_attrs_finish(&bark2);
	live_attrs_finish(&bark);
	tree_mesh_marks_finish(&mk);
	tree_mesh_finish(&tm);
	live_skeleton_finish(&sk);
}

/* A vine's stems and leaves, bound to the nearest skeleton point. */
static void test_vines(void)
{
	struct tree t;
	struct live_skeleton sk;
	struct mesh stem, lv;
	struct live_attrs a;
	double s;

	tree_init(&t);
	mesh_init(&stem);
	mesh_init(&lv);
	live_attrs_init(&a);
	CHECK_INT(synth_vine_tree(&t, 2), 0);
	for (size_t i = 0; i < t.nvines; i++)
		CHECK_INT(vine_mesh_append(&t.vines[i], &stem, &lv), 0);
	CHECK(stem.nvertices > 0);
	CHECK_INT(live_skeleton_init(&sk, &t, 3), 0);
	CHECK_INT(live_attrs_bind_nearest(&a, &sk, &t, &stem), 0);
	CHECK(a.n == stem.nvertices);
	s = stretch(&sk, &a, &stem);
	worst_stretch = fmax(worst_stretch, s);
	printf("vines: %zu stem vertices; steepest stretch %.3f at strength 1\n", stem.nvertices, s);
	CHECK_INT(live_attrs_bind_nearest(&a, &sk, &t, &lv), 0);
	CHECK(a.n == lv.nvertices);
	live_attrs_finish(&a);
	live_skeleton_finish(&sk);
	mesh_finish(&lv);
	mesh_finish(&stem);
	tree_finish(&t);
}

/* The wood's iso-surface, bound to the nearest skeleton point. */
static void test_wood(void)
{
	struct tree t;
	struct live_skeleton sk;
	struct live_attrs a;
	size_t twig_bound = 0;
	double s;

	tree_init(&t);
	live_attrs_init(&a);
	CHECK_INT(synth_wood_tree(&t, 2, 1), 0);
	CHECK(t.wood && t.wood->bark.nvertices > 0);
	CHECK_INT(live_skeleton_init(&sk, &t, 3), 0);
	CHECK_INT(live_attrs_bind_nearest(&a, &sk, &t, &t.wood->bark), 0);
	CHECK(a.n == t.wood->bark.nvertices);
	/* the thick wood goes with the trunk and the limb; a twig takes only the bark where
	 * it comes out of the wood, which moves as the point it hangs on does */
	for (size_t i = 0; i < a.n; i++) {
		struct vec3 q = point_of(&a.v[i]);

		if (!on_branch(&t.branches[0], q) && !on_branch(&t.branches[1], q)) {
			size_t b = on_branch(&t.branches[2], q) ? 2 : 3;

			CHECK(on_branch(&t.branches[b], q));
			CHECK(a.v[i].w[sk.branches[b].band] <= 0.01);
			twig_bound++;
		}
	}
	/* a crease at the fork, where the wood is thicker than the skeleton's radii */
	s = stretch(&sk, &a, &t.wood->bark);
	printf("wood: %zu iso-surface vertices (%zu on a twig); steepest stretch %.3f at strength 1\n",
	       a.n, twig_bound, s);
	CHECK(s <= 1.5);
	live_attrs_finish(&a);
	live_skeleton_finish(&sk);
	tree_finish(&t);
}

int main(int argc, char **argv)
{
	struct tree t;
	struct rng r;
	int n = test_cases(RANDOM_TREES);

	CHECK(argc == 2);
	rng_seed(&r, 77);
	tree_init(&t);
	live_trees_demo(&t, argv[1], true);
	check_tree(&t, 1, &r);
	for (int p = 0; p < GEN_PRESET_COUNT; p++) {
		live_trees_preset(&t, (enum gen_preset)p);
		check_tree(&t, 1, &r);
	}
	for (int i = 0; i < n; i++) {
		int nb = 1 + (int)(rng_next(&r) % 80), leaves = (int)(rng_next(&r) % 4);

		live_trees_random(&t, nb, leaves, 7000 + (uint64_t)i, rng_range(&r, 2.0, 20.0));
		check_tree(&t, 7000 + (uint64_t)i, &r);
	}
	tree_finish(&t);
	test_vines();
	test_wood();
	/* the wind's steepest gradients at strength 1: a band's sway a metre (0.20 at most),
	 * the whole tree's bending 2 x 0.075 a metre at its top */
	CHECK(worst_stretch <= 0.5);
	printf("%d random trees: %zu bark vertices, %.1f%% snapped to their ring\n", n, bark_vertices,
	       100.0 * snapped / bark_vertices);
	printf("nearest binding of the bark: %.2f%% on its own branch; %.3f%% moving apart from the "
	       "bark binding by more than 1%% of H (strength 1)\n",
	       100.0 * nearest_same / nearest_total, 100.0 * nearest_apart / nearest_total);
	CHECK(nearest_apart * 100 <= nearest_total);
	printf("grid against the scan: worst %.3g m\n", worst_grid);
	CHECK(snapped > bark_vertices * 8 / 10);
	return 0;
}
