/* SPDX-License-Identifier: MIT */
#include "synth_tree.h"

#include <math.h>

#include "rng.h"

#define SYNTH_PI 3.14159265358979323846
#define SYNTH_MAX_POINTS 16
#define SYNTH_MAX_LEAF_POINTS 10
#define TRUNK_HEIGHT 6.0
#define TRUNK_POINTS 12
#define TRUNK_RADIUS 0.25

/* Position, direction and radius at arc-length fraction t of a branch. */
static void branch_at(const struct branch *b, double t, struct vec3 *pos, struct vec3 *dir,
		      double *radius)
{
	double total = 0.0, want, acc = 0.0;

	for (size_t i = 0; i + 1 < b->npoints; i++)
		total += vec3_dist(b->points[i], b->points[i + 1]);
	want = t * total;
	for (size_t i = 0; i + 1 < b->npoints; i++) {
		double seg = vec3_dist(b->points[i], b->points[i + 1]);

		if (acc + seg >= want || i + 2 == b->npoints) {
			double f = seg > 0 ? (want - acc) / seg : 0.0;

			f = f < 0 ? 0 : f > 1 ? 1 : f;
			*pos = vec3_lerp(b->points[i], b->points[i + 1], f);
			*dir = vec3_norm_or(vec3_sub(b->points[i + 1], b->points[i]), vec3(0, 1, 0));
			*radius = b->radii[i] + (b->radii[i + 1] - b->radii[i]) * f;
			return;
		}
		acc += seg;
	}
	*pos = b->points[0];
	*dir = vec3(0, 1, 0);
	*radius = b->radii[0];
}

static double branch_length(const struct branch *b)
{
	double len = 0.0;

	for (size_t i = 0; i + 1 < b->npoints; i++)
		len += vec3_dist(b->points[i], b->points[i + 1]);
	return len;
}

/* Two unit vectors perpendicular to unit d and to each other. */
static void basis(struct vec3 d, struct vec3 *a, struct vec3 *b)
{
	struct vec3 ref = fabs(d.y) < 0.9 ? vec3(0, 1, 0) : vec3(1, 0, 0);

	*a = vec3_norm_or(vec3_cross(d, ref), vec3(0, 0, 1));
	*b = vec3_cross(d, *a);
}

/* A random unit vector perpendicular to unit d. */
static struct vec3 random_side(struct rng *r, struct vec3 d)
{
	struct vec3 a, b;
	double phi = rng_range(r, 0.0, 2.0 * SYNTH_PI);

	basis(d, &a, &b);
	return vec3_add(vec3_scale(a, cos(phi)), vec3_scale(b, sin(phi)));
}

static int add_trunk(struct tree *t, struct rng *r)
{
	struct vec3 p[TRUNK_POINTS];
	double radii[TRUNK_POINTS];
	double phase = rng_range(r, 0.0, 2.0 * SYNTH_PI);

	for (int i = 0; i < TRUNK_POINTS; i++) {
		double s = (double)i / (TRUNK_POINTS - 1);

		/* A gentle S-shaped lean; radius tapering to a fifth. */
		p[i] = vec3(0.35 * s * sin(phase + 3.0 * s), TRUNK_HEIGHT * s,
			    0.2 * s * cos(phase + 2.0 * s));
		radii[i] = TRUNK_RADIUS * (1.0 - 0.8 * s);
	}
	return tree_add_branch(t, -1, 0.0, ORIGIN_SKETCH, p, radii, TRUNK_POINTS);
}

static int add_branch(struct tree *t, struct rng *r, int index)
{
	struct vec3 p[SYNTH_MAX_POINTS];
	double radii[SYNTH_MAX_POINTS];
	/* u^2 favours early (thick, low-generation) parents: a tree, not a chain. */
	double u = rng_uniform(r);
	int parent = (int)(u * u * index);
	const struct branch *pb = &t->branches[parent];
	double pt = rng_range(r, 0.25, 0.95);
	double angle = rng_range(r, 35.0, 65.0) * SYNTH_PI / 180.0;
	double len, step, prad, r0;
	int npoints = 8 + (int)(rng_next(r) % 9);
	struct vec3 pos, pdir, dir;
	enum origin origin = ORIGIN_SKETCH;

	branch_at(pb, pt, &pos, &pdir, &prad);
	len = fmax(0.3, branch_length(pb) * rng_range(r, 0.35, 0.6));
	r0 = fmax(0.004, prad * rng_range(r, 0.55, 0.8));
	dir = vec3_add(vec3_scale(pdir, cos(angle)), vec3_scale(random_side(r, pdir), sin(angle)));
	dir = vec3_norm_or(vec3_add(dir, vec3(0, 0.25, 0)), pdir);
	step = len / (npoints - 1);

	/* Starts on the parent's axis, like a sketched branch joined to its parent. */
	p[0] = pos;
	radii[0] = r0;
	for (int i = 1; i < npoints; i++) {
		struct vec3 wobble = vec3(rng_range(r, -0.3, 0.3), rng_range(r, -0.3, 0.3),
					  rng_range(r, -0.3, 0.3));

		dir = vec3_norm_or(vec3_add(dir, vec3_add(wobble, vec3(0, 0.05, 0))), dir);
		p[i] = vec3_add(p[i - 1], vec3_scale(dir, step));
		radii[i] = fmax(0.002, r0 * (1.0 - 0.75 * i / (npoints - 1)));
	}
	if (index > 8) {
		double o = rng_uniform(r);

		origin = o < 0.6 ? ORIGIN_SKETCH : o < 0.8 ? ORIGIN_CLONE : o < 0.95 ? ORIGIN_PROPAGATE
										      : ORIGIN_MERGE;
	}
	return tree_add_branch(t, parent, pt, origin, p, radii, (size_t)npoints);
}

/* A small leaf next to the branch: 6-10 points, every third one lobed (concave). */
static int add_leaf(struct tree *t, struct rng *r, int branch, int k)
{
	struct vec3 p[SYNTH_MAX_LEAF_POINTS];
	const struct branch *b = &t->branches[branch];
	int npoints = 6 + (int)(rng_next(r) % 5);
	double size = rng_range(r, 0.08, 0.2);
	struct vec3 pos, dir, out, normal, e1, e2;
	double radius;

	branch_at(b, rng_range(r, 0.3, 1.0), &pos, &dir, &radius);
	out = random_side(r, dir);
	/* The blade points away from the branch and tilts at random about that direction. */
	basis(out, &e1, &e2);
	normal = vec3_norm_or(vec3_add(e1, vec3_scale(e2, rng_range(r, -0.7, 0.7))), e1);
	e1 = out;
	e2 = vec3_cross(normal, e1);
	pos = vec3_add(pos, vec3_scale(out, radius + 0.6 * size));

	for (int i = 0; i < npoints; i++) {
		double a = 2.0 * SYNTH_PI * i / npoints;
		double lobe = (k % 3 == 0 && i % 2) ? 0.5 : 1.0;
		/* A little off-plane noise: real strokes are never flat. */
		double bend = 0.02 * size * rng_range(r, -1.0, 1.0);

		p[i] = vec3_add(pos, vec3_add(vec3_scale(e1, 0.6 * size * lobe * cos(a)),
					      vec3_add(vec3_scale(e2, 0.3 * size * lobe * sin(a)),
						       vec3_scale(normal, bend))));
	}
	return tree_add_leaf(t, branch, b->origin, p, (size_t)npoints);
}

int synth_tree(struct tree *t, int nbranches, int leaves_per_branch, uint64_t seed)
{
	struct rng r;
	int ret;

	tree_clear(t);
	rng_seed(&r, seed);
	if (nbranches <= 0)
		return 0;
	ret = add_trunk(t, &r);
	for (int i = 1; i < nbranches && ret >= 0; i++)
		ret = add_branch(t, &r, i);
	for (int b = 0; b < nbranches && ret >= 0; b++)
		for (int k = 0; k < leaves_per_branch && ret >= 0; k++)
			ret = add_leaf(t, &r, b, k);
	return ret < 0 ? ret : 0;
}
