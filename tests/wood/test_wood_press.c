/* SPDX-License-Identifier: MIT */
/*
 * Growing wood's presses end to end (issue 17): a trunk leaning 45 degrees thickens on its
 * lower side as a conifer and on its upper side as a broadleaf tree; a Y stays mirror-
 * symmetric and its arms grow as the trunk does; without gravity nothing moves, bit for
 * bit, press after press; the same tree gives the same field. Each pressed tree's bark
 * (these and a 127-branch zelkova, argv[1], after three presses) is closed, oriented and a
 * manifold without degenerate triangles, its volume within 5% of the wood (sum of
 * density h^3), and the zelkova's twigs beside the wood start inside it.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "iso_check.h"
#include "skeleton_read.h"
#include "test.h"
#include "wood.h"

static const char *zelkova_path;

/* The bark of w's last press: watertight, and as much as the wood. */
static void check_bark(const struct wood *w, const char *what)
{
	struct iso_stats st;
	double wood = 0.0, err;

	CHECK(w->bark.nindices > 0);
	check_mesh(&w->bark, 0, 0, w->g.h, &st);
	for (size_t i = 0; i < wood_cells(&w->g); i++)
		wood += w->g.density[i];
	wood *= w->g.h * w->g.h * w->g.h;
	err = (st.volume - wood) / wood;
	printf("%s: bark of %zu triangles in %zu parts, closed; volume %+.2f%% of the wood\n",
	       what, st.faces, st.components, 100 * err);
	CHECK(fabs(err) <= 0.05);
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

/* A trunk of 1 m, radius 5 cm, leaning `lean` degrees towards +x from its foot at 0. */
static void leaning(struct tree *t, double lean)
{
	struct vec3 p[11];
	double r[11], a = lean * VEC_PI / 180.0;

	tree_init(t);
	line(p, r, 11, vec3(0, 0, 0), vec3(sin(a), cos(a), 0), 0.05, 0.05);
	CHECK_INT(tree_add_branch(t, -1, 0, ORIGIN_SKETCH, p, r, 11), 0);
	t->lifted = true;
}

/* Wood gained on each side of an axis from foot along dir, between fractions s0 and s1
 * of its length L: the side below (towards `down`, perpendicular to dir) and above. */
static void sides(const struct wood *w, struct vec3 foot, struct vec3 dir, struct vec3 down,
		  double L, double s0, double s1, double *below, double *above)
{
	const struct wood_grid *g = &w->g;

	*below = *above = 0.0;
	for (int z = 0; z < g->nz; z++)
		for (int y = 0; y < g->ny; y++)
			for (int x = 0; x < g->nx; x++) {
				size_t i = wood_index(g, x, y, z);
				struct vec3 c = vec3(g->origin.x + (x + 0.5) * g->h,
						     g->origin.y + (y + 0.5) * g->h,
						     g->origin.z + (z + 0.5) * g->h);
				struct vec3 v = vec3_sub(c, foot);
				double s = vec3_dot(v, dir) / L, gain = g->density[i] - w->density0[i];

				if (s < s0 || s > s1 || gain <= 0.0)
					continue;
				if (vec3_dot(v, down) > 0.0)
					*below += gain;
				else
					*above += gain;
			}
}

static void test_leaning(enum wood_mode mode)
{
	struct tree t;
	struct wood w;
	struct wood_params p;
	double below, above, a = 45 * VEC_PI / 180.0;

	leaning(&t, 45);
	wood_params_default(&p);
	p.mode = mode;
	p.grid = 64;
	p.beta = 1;
	CHECK_INT(wood_begin(&w, &t, &p), 0);
	CHECK_INT(wood_press(&w), 0);
	sides(&w, vec3(0, 0, 0), vec3(sin(a), cos(a), 0), vec3(cos(a), -sin(a), 0), 1.0, 0.15, 0.40,
	      &below, &above);
	printf("%s: lower side %.4g, upper side %.4g (ratio %.3g); added %.4g, lost %.3g; "
	       "%zu points, %zu springs, %d iterations, residual %.2g\n",
	       mode == WOOD_CONIFER ? "conifer" : "broadleaf", below, above,
	       mode == WOOD_CONIFER ? below / above : above / below, w.added, w.lost,
	       w.solve.points, w.solve.springs, w.solve.iterations, w.solve.residual);
	CHECK(below + above > 0.0);
	check_bark(&w, mode == WOOD_CONIFER ? "leaning conifer" : "leaning broadleaf");
	if (mode == WOOD_CONIFER)
		CHECK(below >= 2.0 * above);
	else
		CHECK(above >= 1.5 * below);
	wood_finish(&w);
	tree_finish(&t);
}

/* A Y: a trunk and two arms by the power law, 45 degrees out, mirror images in x = 0. */
static void y_tree(struct tree *t)
{
	struct vec3 p[9];
	double r[9], ra = 0.1 * pow(0.5, 1.0 / WOOD_POWER_LAW_A);

	tree_init(t);
	line(p, r, 9, vec3(0, 0, 0), vec3(0, 1, 0), 0.1, 0.1);
	CHECK_INT(tree_add_branch(t, -1, 0, ORIGIN_SKETCH, p, r, 9), 0);
	line(p, r, 9, vec3(0, 1, 0), vec3(0.5, 1.5, 0), ra, ra);
	CHECK_INT(tree_add_branch(t, 0, 1.0, ORIGIN_SKETCH, p, r, 9), 1);
	line(p, r, 9, vec3(0, 1, 0), vec3(-0.5, 1.5, 0), ra, ra);
	CHECK_INT(tree_add_branch(t, 0, 1.0, ORIGIN_SKETCH, p, r, 9), 2);
	t->lifted = true;
}

static void test_y(void)
{
	struct tree t;
	struct wood w;
	struct wood_params p;
	const struct wood_grid *g;
	double worst = 0.0, below[2], above[2], s = sqrt(0.5);

	y_tree(&t);
	wood_params_default(&p);
	p.mode = WOOD_CONIFER;
	CHECK_INT(wood_begin(&w, &t, &p), 0);
	CHECK_INT(wood_press(&w), 0);
	g = &w.g;
	/* each row along x that crosses both arms (or the trunk's two sides) solidly: the
	 * wood's centre on one side mirrors the other's within half a voxel */
	for (int z = 0; z < g->nz; z++)
		for (int y = 0; y < g->ny; y++) {
			double m[2] = { 0, 0 }, mx[2] = { 0, 0 };

			for (int x = 0; x < g->nx; x++) {
				double d = g->density[wood_index(g, x, y, z)];
				double cx = g->origin.x + (x + 0.5) * g->h;

				m[cx > 0] += d;
				mx[cx > 0] += d * cx;
			}
			if (m[0] >= 2.0 && m[1] >= 2.0)
				worst = fmax(worst, fabs(mx[0] / m[0] + mx[1] / m[1]) / g->h);
		}
	printf("Y: the two sides' rows mirror each other within %.3g voxels\n", worst);
	/* the issue asks half a voxel; the grid centred across the tree makes it exact but
	 * for the rays' tie-breaking nudge (docs/wood.md) */
	CHECK(worst <= 1e-3);
	/* the arms grow as a leaning trunk does: more below (conifer) */
	sides(&w, vec3(0, 1, 0), vec3(s, s, 0), vec3(s, -s, 0), sqrt(0.5), 0.15, 0.6, &below[0],
	      &above[0]);
	sides(&w, vec3(0, 1, 0), vec3(-s, s, 0), vec3(-s, -s, 0), sqrt(0.5), 0.15, 0.6, &below[1],
	      &above[1]);
	printf("Y arms: below %.4g / %.4g, above %.4g / %.4g\n", below[0], below[1], above[0],
	       above[1]);
	/* as the leaning trunk: at least twice below what grows above, on each arm; and the
	 * two arms the same (every overflow spread at once, the grid centred) */
	CHECK(below[0] >= 2.0 * above[0] && below[1] >= 2.0 * above[1]);
	CHECK(fabs(below[0] - below[1]) <= 1e-3 * below[0]);
	CHECK(fabs(above[0] - above[1]) <= 1e-3 * above[0]);
	check_bark(&w, "Y");
	wood_finish(&w);
	tree_finish(&t);
}

/* No gravity, no wind: no force, no growth; three presses leave the field as it was. */
static void test_no_gravity(void)
{
	struct tree t;
	struct wood w;
	struct wood_params p;

	leaning(&t, 30);
	wood_params_default(&p);
	p.gravity = 0;
	CHECK_INT(wood_begin(&w, &t, &p), 0);
	for (int i = 0; i < 3; i++)
		CHECK_INT(wood_press(&w), 0);
	CHECK(memcmp(w.g.density, w.density0, wood_cells(&w.g) * sizeof(double)) == 0);
	CHECK(w.added == 0.0);
	wood_finish(&w);
	tree_finish(&t);
}

/* The same tree and settings: the same field, bit for bit. */
static void test_determinism(void)
{
	struct tree t[2];
	struct wood w[2];
	struct wood_params p;

	wood_params_default(&p);
	for (int k = 0; k < 2; k++) {
		y_tree(&t[k]);
		CHECK_INT(wood_begin(&w[k], &t[k], &p), 0);
		CHECK_INT(wood_press(&w[k]), 0);
		CHECK_INT(wood_press(&w[k]), 0);
	}
	CHECK(memcmp(w[0].g.density, w[1].g.density, wood_cells(&w[0].g) * sizeof(double)) == 0);
	CHECK(memcmp(w[0].g.displacement, w[1].g.displacement,
		     3 * wood_cells(&w[0].g) * sizeof(double)) == 0);
	for (int k = 0; k < 2; k++) {
		wood_finish(&w[k]);
		tree_finish(&t[k]);
	}
}

/* A drawn-like tree: every branch from 1.5 voxels up voxelised, three presses. */
static void test_zelkova(void)
{
	struct tree t;
	struct wood w;
	struct wood_params p;
	struct error err;
	char *data;
	size_t len = 0, cap = 1 << 16;
	FILE *f = fopen(zelkova_path, "rb");

	CHECK(f);
	data = malloc(cap);
	CHECK(data);
	for (size_t n; (n = fread(data + len, 1, cap - len, f)) > 0;) {
		len += n;
		if (len == cap) {
			cap *= 2;
			data = realloc(data, cap);
			CHECK(data);
		}
	}
	CHECK(!ferror(f));
	fclose(f);
	tree_init(&t);
	CHECK_INT(skeleton_read(data, len, zelkova_path, &t, &err), 0);
	free(data);
	wood_params_default(&p);
	CHECK_INT(wood_begin(&w, &t, &p), 0);
	for (int i = 0; i < 3; i++)
		CHECK_INT(wood_press(&w), 0);
	check_bark(&w, "zelkova, 3 presses");
	/* every twig beside the wood starts inside it: its tube leaves the bark without a gap */
	{
		size_t twigs = 0;
		double least = 1.0;

		for (size_t i = 0; i < t.nbranches; i++) {
			const struct branch *b = &t.branches[i];

			if (w.voxelised[i] || b->parent < 0 || !w.voxelised[b->parent])
				continue;
			least = fmin(least, wood_density_at(&w.g, b->points[0]));
			twigs++;
		}
		printf("zelkova: %zu twigs on the wood, the least density at their roots %.3g\n",
		       twigs, least);
		CHECK(twigs >= 5);
		CHECK(least > 0.5);
	}
	wood_finish(&w);
	tree_finish(&t);
}

int main(int argc, char **argv)
{
	if (argc != 2) {
		fprintf(stderr, "usage: test_wood_press TREE100.json\n");
		return 2;
	}
	zelkova_path = argv[1];
	test_leaning(WOOD_CONIFER);
	test_leaning(WOOD_BROADLEAF);
	test_y();
	test_no_gravity();
	test_determinism();
	test_zelkova();
	return 0;
}
