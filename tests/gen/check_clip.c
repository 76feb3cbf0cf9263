/* SPDX-License-Identifier: MIT */
/*
 * A shrub against its clipping shape (docs/functional-trees.md, "Shrub and palm"):
 *
 * - inside: every crown branch (all but the trunk) with its radius round each point, and
 *   every leaf, is inside the shape; so are model.glb's crown vertices, within 1 mm. The
 *   trunk's vertices are the first of the bark's: a branch's mesh depends on it and its
 *   ancestors only (mesh.h), so the same trunk grown alone (an L-system tree of one level:
 *   gen.sh's trunk_alone) gives them, and the test checks they are the same bytes.
 * - filled: what a gardener looks at is the clipped surface, and it is filled when leaves
 *   come up to it everywhere, without holes. FILL_SAMPLES points spread evenly by area over
 *   the surface; one is covered when a leaf's centre lies within DELTA of it; at least
 *   FRACTION of them must be. The bottom of a box and the base of a cone face the ground,
 *   where the trunk comes in and nobody looks: they are reported but not counted.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gen_check.h"
#include "glb.h"
#include "shape.h"

/* skeleton.json's micrometres */
#define SKEL_TOL 1.5e-6
#define GLB_TOL 0.001
#define FILL_SAMPLES 4000

static void check_skeleton(const struct skel *s, const struct shape *sh)
{
	double worst = -INFINITY;

	for (size_t i = 1; i < s->nbranches; i++) {
		const struct skel_branch *b = &s->branches[i];

		for (size_t k = 0; k < b->npoints; k++) {
			double d = shape_distance(sh, b->points[k]) + b->radii[k];

			worst = fmax(worst, d);
			if (d > SKEL_TOL)
				bad("branch %zu point %zu: its bark reaches %.3g m outside the shape", i, k, d);
		}
	}
	for (size_t i = 0; i < s->nleaves; i++)
		for (size_t k = 0; k < s->leaves[i].npoints; k++) {
			double d = shape_distance(sh, s->leaves[i].points[k]);

			worst = fmax(worst, d);
			if (d > SKEL_TOL)
				bad("leaf %zu point %zu: %.3g m outside the shape", i, k, d);
		}
	printf("clip: %zu crown branches and %zu leaves; the outermost %.4f m from the surface\n",
	       s->nbranches ? s->nbranches - 1 : 0, s->nleaves, worst);
}

static double prim_outside(const struct glb_prim *p, size_t from, const struct shape *sh,
			   const char *what)
{
	double worst = -INFINITY;

	for (size_t v = from; p && v < p->nvertices; v++) {
		double x[3] = { p->positions[3 * v], p->positions[3 * v + 1], p->positions[3 * v + 2] };
		double d = shape_distance(sh, x);

		worst = fmax(worst, d);
		if (d > GLB_TOL)
			bad("model.glb: %s vertex %zu at (%.4f, %.4f, %.4f) is %.4f m outside the shape", what,
			    v, x[0], x[1], x[2], d);
	}
	return worst;
}

static void check_glb(const char *full_path, const char *trunk_path, const struct shape *sh)
{
	struct glb full, trunk;
	const struct glb_prim *fb, *tb;
	double bark, leaves;

	if (glb_load(full_path, &full) < 0 || glb_load(trunk_path, &trunk) < 0)
		exit(2);
	fb = glb_prim(&full, "bark");
	tb = glb_prim(&trunk, "bark");
	if (!fb || !tb || tb->nvertices >= fb->nvertices ||
	    memcmp(fb->positions, tb->positions, tb->nvertices * 3 * sizeof(float))) {
		bad("model.glb: the trunk alone is not the first vertices of the shrub's bark");
	} else {
		bark = prim_outside(fb, tb->nvertices, sh, "bark");
		leaves = prim_outside(glb_prim(&full, "leaves"), 0, sh, "leaf");
		printf("clip: model.glb: %zu crown bark vertices (the trunk's %zu apart) and %zu leaf "
		       "vertices; the outermost %.4f and %.4f m from the surface\n",
		       fb->nvertices - tb->nvertices, tb->nvertices,
		       glb_prim(&full, "leaves") ? glb_prim(&full, "leaves")->nvertices : 0, bark, leaves);
	}
	glb_free(&full);
	glb_free(&trunk);
}

static int by_value(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;

	return (x > y) - (x < y);
}

/* The squared distance from p to the nearest of n points. */
static double nearest2(const double (*pts)[3], size_t n, const double p[3])
{
	double best = INFINITY;

	for (size_t i = 0; i < n; i++) {
		double dx = pts[i][0] - p[0], dy = pts[i][1] - p[1], dz = pts[i][2] - p[2];

		best = fmin(best, dx * dx + dy * dy + dz * dz);
	}
	return best;
}

static void check_fill(const struct skel *s, const struct shape *sh, double delta, double fraction)
{
	double (*centre)[3] = calloc(s->nleaves + 1, sizeof(*centre));
	double *near = calloc(FILL_SAMPLES, sizeof(double)), f;
	size_t counted = 0, covered = 0, below = 0, below_covered = 0;

	if (!centre || !near)
		exit(2);
	for (size_t i = 0; i < s->nleaves; i++)
		for (size_t k = 0; k < s->leaves[i].npoints; k++)
			for (int c = 0; c < 3; c++)
				centre[i][c] += s->leaves[i].points[k][c] / (double)s->leaves[i].npoints;
	for (unsigned j = 0; j < FILL_SAMPLES; j++) {
		double p[3], n[3], d;
		bool hit;

		shape_sample(sh, j, FILL_SAMPLES, p, n);
		d = sqrt(nearest2((const double (*)[3])centre, s->nleaves, p));
		hit = d <= delta;
		/* a box's bottom, a cone's base (a sphere's underside is in view) */
		if (sh->kind != SHAPE_SPHERE && n[1] < -0.99) {
			below++;
			below_covered += hit;
			continue;
		}
		near[counted++] = d;
		covered += hit;
	}
	f = counted ? (double)covered / counted : 0;
	qsort(near, counted, sizeof(double), by_value);
	printf("fill: %.1f%% of the surface has a leaf within %g m (want %.0f%%); the nearest leaf is "
	       "%.3f m away at the median, %.3f m at 90%%, %.3f m at worst", 100 * f, delta, 100 * fraction,
	       counted ? near[counted / 2] : 0, counted ? near[counted * 9 / 10] : 0,
	       counted ? near[counted - 1] : 0);
	if (below)
		printf("; the face to the ground %.1f%%, not counted", 100.0 * below_covered / below);
	printf("\n");
	if (f < fraction)
		bad("the crown does not fill its shape: %.1f%% of the surface covered, want %.0f%%", 100 * f,
		    100 * fraction);
	free(near);
	free(centre);
}

/* gen_check clip SKEL SHAPE... [glb FULL TRUNK] [fill DELTA FRACTION] */
int check_clip(int argc, char **argv)
{
	struct shape sh;
	struct skel s;
	int n, i;

	if (argc < 2 || !(n = shape_parse(argv + 1, argc - 1, &sh)))
		return 2;
	load_skel(argv[0], &s);
	if (s.nbranches < 2)
		bad("no crown: %zu branches", s.nbranches);
	check_skeleton(&s, &sh);
	for (i = 1 + n; i < argc; i++) {
		if (!strcmp(argv[i], "glb") && i + 2 < argc) {
			check_glb(argv[i + 1], argv[i + 2], &sh);
			i += 2;
		} else if (!strcmp(argv[i], "fill") && i + 2 < argc) {
			check_fill(&s, &sh, atof(argv[i + 1]), atof(argv[i + 2]));
			i += 2;
		} else {
			skel_free(&s);
			return 2;
		}
	}
	skel_free(&s);
	return finish("clip");
}
