/* SPDX-License-Identifier: MIT */
/* The lsystem's structure, the thickness rules and the palm (docs/functional-trees.md). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gen_check.h"

/* skeleton.json rounds to micrometres: two roundings apart at most this */
#define ROUND_M 1.01e-6
#define LENGTH_RATIO_TOL 1e-4

static const double *tip(const struct skel_branch *b)
{
	return b->points[b->npoints - 1];
}

static bool same_point(const double a[3], const double b[3])
{
	return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
}

static int *leaves_per_branch(const struct skel *s)
{
	int *n = calloc(s->nbranches + 1, sizeof(int));

	if (!n)
		exit(2);
	for (size_t i = 0; i < s->nleaves; i++)
		n[s->leaves[i].branch]++;
	return n;
}

/* gen_check tree SKEL LEVELS CHILDREN RATIOS LEAVES */
int check_tree(int argc, char **argv)
{
	struct skel s;
	double ratios[3], worst = 0;
	int levels, children, amount, *rank, *nkids, *nleaves;
	size_t want = 0, layer = 1, tips = 0;

	if (argc != 5)
		return 2;
	levels = atoi(argv[1]);
	children = atoi(argv[2]);
	amount = atoi(argv[4]);
	if (parse_list(argv[3], ratios, 3) != children)
		return 2;
	load_skel(argv[0], &s);
	for (int l = 0; l < levels; l++, layer *= (size_t)children) {
		want += layer;
		tips = layer;
	}
	if (s.nbranches != want) {
		bad("%zu branches, want %zu for %d levels of %d children", s.nbranches, want, levels,
		    children);
		return finish("tree");
	}
	family(&s, &rank, &nkids);
	nleaves = leaves_per_branch(&s);
	for (size_t i = 0; i < s.nbranches; i++) {
		const struct skel_branch *b = &s.branches[i], *p = b->parent >= 0 ? &s.branches[b->parent] : NULL;

		if (strcmp(b->origin, "generate"))
			bad("branch %zu: origin \"%s\"", i, b->origin);
		if (b->npoints < 2) {
			bad("branch %zu: %zu points", i, b->npoints);
			continue;
		}
		if (!p) {
			if (i != 0 || b->level != levels || b->generation != 0)
				bad("branch %zu: a trunk at level %d generation %d, want branch 0 at level %d", i,
				    b->level, b->generation, levels);
		} else {
			double want_len = ratios[rank[i] % children] * skel_length(p);
			double err = fabs(skel_length(b) / want_len - 1);

			if (b->level != p->level - 1 || b->generation != p->generation + 1)
				bad("branch %zu: level %d generation %d under a branch of level %d generation %d", i,
				    b->level, b->generation, p->level, p->generation);
			if (!same_point(b->points[0], tip(p)) || b->parent_t != 1)
				bad("branch %zu starts at (%g, %g, %g), t %g; its parent's tip is (%g, %g, %g)", i,
				    b->points[0][0], b->points[0][1], b->points[0][2], b->parent_t, tip(p)[0],
				    tip(p)[1], tip(p)[2]);
			if (err > LENGTH_RATIO_TOL)
				bad("branch %zu (child %d): length %.7g, want %.7g x %.7g", i, rank[i],
				    skel_length(b), ratios[rank[i] % children], skel_length(p));
			worst = fmax(worst, err);
		}
		if (nkids[i] != (b->level > 1 ? children : 0))
			bad("branch %zu at level %d has %d children", i, b->level, nkids[i]);
		if (nleaves[i] != (b->level == 1 ? amount : 0))
			bad("branch %zu at level %d has %d leaves, want %d", i, b->level, nleaves[i],
			    b->level == 1 ? amount : 0);
	}
	if (s.nleaves != tips * (size_t)amount)
		bad("%zu leaves, want %zu tips x %d", s.nleaves, tips, amount);
	for (size_t i = 0; i < s.nleaves; i++)
		if (strcmp(s.leaves[i].origin, "generate"))
			bad("leaf %zu: origin \"%s\"", i, s.leaves[i].origin);
	printf("tree: %zu branches, %zu leaves; lengths within %.2g of their ratios\n", s.nbranches,
	       s.nleaves, worst);
	free(rank);
	free(nkids);
	free(nleaves);
	skel_free(&s);
	return finish("tree");
}

/* Radius along b linear in arc length between its ends. */
static void check_linear(const struct skel_branch *b, size_t id)
{
	double len = skel_length(b), r0 = b->radii[0], r1 = b->radii[b->npoints - 1], s = 0;

	for (size_t k = 1; k + 1 < b->npoints; k++) {
		double want;

		s += dist3(b->points[k - 1], b->points[k]);
		want = r0 + (r1 - r0) * s / len;
		if (fabs(b->radii[k] - want) > ROUND_M + 1e-4 * fabs(r1 - r0))
			bad("branch %zu point %zu: radius %.7g, linear gives %.7g", id, k, b->radii[k], want);
	}
}

/* gen_check radii TYPE THICKNESS RATIO SKEL: the trunk's base is THICKNESS and its tip RATIO
 * of that; a child's base is its parent's tip (lsystem, shrub); an lsystem branch's tip is
 * RATIO of its base (a shrub's clipped branches end early, thicker: between); a palm's
 * fronds taper; every radius is linear along its branch. */
int check_radii(int argc, char **argv)
{
	struct skel s;
	double thickness, ratio;
	const char *type;

	if (argc != 4)
		return 2;
	type = argv[0];
	thickness = atof(argv[1]);
	ratio = atof(argv[2]);
	load_skel(argv[3], &s);
	if (s.nbranches == 0)
		bad("no branches");
	for (size_t i = 0; i < s.nbranches; i++) {
		const struct skel_branch *b = &s.branches[i];
		double r0 = b->radii[0], r1 = b->radii[b->npoints - 1];

		if (b->npoints < 2)
			continue;
		check_linear(b, i);
		if (b->parent < 0) {
			if (fabs(r0 - thickness) > ROUND_M || fabs(r1 - ratio * r0) > ROUND_M)
				bad("trunk: radii %.7g to %.7g, want %.7g to %.7g x it", r0, r1, thickness, ratio);
			continue;
		}
		if (!strcmp(type, "palm")) {
			if (!(r1 < r0) || r0 > s.branches[b->parent].radii[s.branches[b->parent].npoints - 1])
				bad("frond %zu: radii %.7g to %.7g", i, r0, r1);
			continue;
		}
		if (r0 != s.branches[b->parent].radii[s.branches[b->parent].npoints - 1])
			bad("branch %zu: base radius %.7g, its parent's tip %.7g", i, r0,
			    s.branches[b->parent].radii[s.branches[b->parent].npoints - 1]);
		if (!strcmp(type, "lsystem") ? fabs(r1 - ratio * r0) > ROUND_M
					     : r1 < ratio * r0 - ROUND_M || r1 > r0 + ROUND_M)
			bad("branch %zu: tip radius %.7g from a base of %.7g (ratio %g)", i, r1, r0, ratio);
	}
	printf("radii: %zu branches\n", s.nbranches);
	skel_free(&s);
	return finish("radii");
}

/* gen_check palm FRONDS LEAVES SKEL [even]: 1 + FRONDS branches, every frond starting at the
 * trunk's tip, LEAVES leaflets on each, none on the trunk; with "even", a vertical trunk's
 * fronds 360 / FRONDS apart round it. */
int check_palm(int argc, char **argv)
{
	struct skel s;
	int fronds, amount, *nleaves;

	if (argc != 3 && argc != 4)
		return 2;
	fronds = atoi(argv[0]);
	amount = atoi(argv[1]);
	load_skel(argv[2], &s);
	if (s.nbranches != (size_t)fronds + 1) {
		bad("%zu branches, want a trunk and %d fronds", s.nbranches, fronds);
		return finish("palm");
	}
	nleaves = leaves_per_branch(&s);
	if (s.branches[0].parent != -1 || nleaves[0] != 0)
		bad("the trunk: parent %d, %d leaves; want a bare trunk", s.branches[0].parent, nleaves[0]);
	for (size_t i = 1; i < s.nbranches; i++) {
		const struct skel_branch *b = &s.branches[i];

		if (b->parent != 0 || !same_point(b->points[0], tip(&s.branches[0])))
			bad("frond %zu: parent %d, starts at (%g, %g, %g), not at the trunk's top", i,
			    b->parent, b->points[0][0], b->points[0][1], b->points[0][2]);
		if (nleaves[i] != amount)
			bad("frond %zu: %d leaflets, want %d", i, nleaves[i], amount);
		if (argc == 4 && !strcmp(argv[3], "even") && i + 1 < s.nbranches) {
			const struct skel_branch *c = &s.branches[i + 1];
			double up[3] = { 0, 1, 0 }, d0[3], d1[3], step;

			for (int k = 0; k < 3; k++) {
				d0[k] = b->points[1][k] - b->points[0][k];
				d1[k] = c->points[1][k] - c->points[0][k];
			}
			step = azimuth_deg(d0, d1, up);
			if (fabs(step - 360.0 / fronds) > 0.1)
				bad("fronds %zu and %zu: %.3f degrees apart round the trunk, want %.3f", i, i + 1,
				    step, 360.0 / fronds);
		}
	}
	printf("palm: %d fronds at the trunk's top, %zu leaflets\n", fronds, s.nleaves);
	free(nleaves);
	skel_free(&s);
	return finish("palm");
}
