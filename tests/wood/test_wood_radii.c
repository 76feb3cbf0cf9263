/* SPDX-License-Identifier: MIT */
/*
 * Step 1 of growing wood: the power law d^a = d1^a + d2^a (a = 2.5) at every fork, to
 * 1e-9 relative, on a hand-made tree and on the generated presets; tips keep their drawn
 * radius, the drawn taper stays between forks, and a second application changes nothing.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "gen.h"
#include "test.h"
#include "wood.h"

#define A WOOD_POWER_LAW_A

static double *params_of(const struct branch *b)
{
	double *t = malloc(b->npoints * sizeof(*t)), len = tree_branch_length(b), s = 0;

	CHECK(t);
	t[0] = 0;
	for (size_t k = 1; k < b->npoints; k++) {
		s += vec3_dist(b->points[k - 1], b->points[k]);
		t[k] = len > 0 ? s / len : 1;
	}
	return t;
}

/* The law at every point of every branch: below^a = above^a + the children joining
 * between them; elsewhere the drawn ratio (before) kept. Returns the forks checked. */
static size_t check_law(const struct tree *t, const struct tree *before)
{
	size_t forks = 0;

	for (size_t i = 0; i < t->nbranches; i++) {
		const struct branch *b = &t->branches[i], *d = &before->branches[i];
		double *tp = params_of(b);
		size_t n = b->npoints;

		CHECK_NEAR(b->radii[n - 1], d->radii[n - 1], 0); /* the tip kept */
		for (size_t k = 0; k + 1 < n; k++) {
			double kids = 0;
			bool any = false;

			for (size_t c = i + 1; c < t->nbranches; c++) {
				const struct branch *ch = &t->branches[c];
				bool here = ch->parent == (int)i &&
					    (k == 0 ? ch->parent_t <= tp[1] :
						      ch->parent_t > tp[k] && (ch->parent_t <= tp[k + 1] ||
									      k + 2 == n));

				if (here) {
					kids += pow(ch->radii[0], A);
					any = true;
				}
			}
			if (any) {
				double want = pow(b->radii[k + 1], A) + kids;

				CHECK(fabs(pow(b->radii[k], A) - want) <= 1e-9 * want);
				forks++;
			} else if (d->radii[k + 1] > 0) {
				CHECK(fabs(b->radii[k] / b->radii[k + 1] - d->radii[k] / d->radii[k + 1]) <=
				      1e-12 * (d->radii[k] / d->radii[k + 1]));
			}
		}
		free(tp);
	}
	return forks;
}

static void line(struct vec3 *p, double *r, size_t n, struct vec3 a, struct vec3 b, double r0,
		 double r1)
{
	for (size_t k = 0; k < n; k++) {
		double s = (double)k / (double)(n - 1);

		p[k] = vec3_lerp(a, b, s);
		r[k] = r0 + (r1 - r0) * s;
	}
}

/* A trunk with two forks on it (one of two children at the same point), a child with a
 * grandchild, and a child at the trunk's tip. */
static void test_hand(void)
{
	struct tree t, before;
	struct vec3 p[9];
	double r[9];

	tree_init(&t);
	tree_init(&before);
	line(p, r, 9, vec3(0, 0, 0), vec3(0, 4, 0), 0.1, 0.05);
	CHECK_INT(tree_add_branch(&t, -1, 0, ORIGIN_SKETCH, p, r, 9), 0);
	line(p, r, 5, vec3(0, 2, 0), vec3(1.5, 3, 0), 0.04, 0.01);
	CHECK_INT(tree_add_branch(&t, 0, 0.5, ORIGIN_SKETCH, p, r, 5), 1);
	line(p, r, 5, vec3(0, 2, 0), vec3(-1.5, 3, 0), 0.03, 0.01);
	CHECK_INT(tree_add_branch(&t, 0, 0.5, ORIGIN_SKETCH, p, r, 5), 2);
	line(p, r, 4, vec3(0.75, 2.5, 0), vec3(1, 3.5, 0.3), 0.02, 0.005);
	CHECK_INT(tree_add_branch(&t, 1, 0.5, ORIGIN_SKETCH, p, r, 4), 3);
	line(p, r, 4, vec3(0, 4, 0), vec3(0.5, 5, 0), 0.03, 0.01);
	CHECK_INT(tree_add_branch(&t, 0, 1.0, ORIGIN_SKETCH, p, r, 4), 4);
	CHECK_INT(tree_copy(&before, &t), 0);
	CHECK_INT(wood_power_law(&t, A), 0);
	CHECK_INT(check_law(&t, &before), 3);
	/* the trunk's foot carries it all: thicker than drawn */
	CHECK(t.branches[0].radii[0] > before.branches[0].radii[0]);
	/* twigs without children are as drawn */
	CHECK(memcmp(t.branches[3].radii, before.branches[3].radii, 4 * sizeof(double)) == 0);
	/* again: nothing changes */
	CHECK_INT(tree_copy(&before, &t), 0);
	CHECK_INT(wood_power_law(&t, A), 0);
	for (size_t i = 0; i < t.nbranches; i++)
		CHECK(memcmp(t.branches[i].radii, before.branches[i].radii,
			     t.branches[i].npoints * sizeof(double)) == 0);
	tree_finish(&t);
	tree_finish(&before);
}

/* Every generated preset: the law at its every fork. */
static void test_presets(void)
{
	for (int k = 0; k < GEN_PRESET_COUNT; k++) {
		struct gen_params gp;
		struct error err = { { 0 } };
		struct tree t, before;
		size_t forks;

		tree_init(&t);
		tree_init(&before);
		CHECK_INT(gen_preset((enum gen_preset)k, &gp, &err), 0);
		CHECK_INT(gen_build(&t, &gp, 7), 0);
		CHECK_INT(tree_copy(&before, &t), 0);
		CHECK_INT(wood_power_law(&t, A), 0);
		forks = check_law(&t, &before);
		CHECK(t.nbranches < 2 || forks > 0);
		tree_finish(&t);
		tree_finish(&before);
	}
}

int main(void)
{
	test_hand();
	test_presets();
	return 0;
}
