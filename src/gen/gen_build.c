/* SPDX-License-Identifier: MIT */
/* gen_build(): the generators' entry, and what they share. */
#include <errno.h>
#include <math.h>

#include "gen_private.h"

#define DEG (VEC_PI / 180.0)

struct vec3 gen_rotate(struct vec3 v, struct vec3 k, double a)
{
	double c = cos(a), s = sin(a);

	/* Rodrigues: v c + (k x v) s + k (k . v)(1 - c) */
	return vec3_add(vec3_add(vec3_scale(v, c), vec3_scale(vec3_cross(k, v), s)),
			vec3_scale(k, vec3_dot(k, v) * (1.0 - c)));
}

struct vec3 gen_reference(struct vec3 d)
{
	struct vec3 ref = fabs(d.x) < 0.9 ? vec3(1, 0, 0) : vec3(0, 0, 1);

	return vec3_norm_or(vec3_sub(ref, vec3_scale(d, vec3_dot(ref, d))), vec3(0, 0, 1));
}

double gen_angle(struct gen_ctx *g)
{
	const struct gen_params *p = g->p;
	double u = rng_range(&g->rng, -1.0, 1.0);
	double mid = 0.5 * (p->angle_min + p->angle_max);

	return (mid + p->randomness * u * 0.5 * (p->angle_max - p->angle_min)) * DEG;
}

/*
 * A child's root ring sits at its parent's tip, where the parent's tube closes: the mesh
 * shrinks it to stay inside (mesh.h). A second point a little way along keeps the shrinking
 * to the fork itself, so the branch is as thick as its radii say beyond it: still one
 * straight branch, its radius still linear in its length.
 */
#define GEN_FORK_RADII 1.5
#define GEN_FORK_MAX 0.3

int gen_add_branch(struct gen_ctx *g, int parent, struct vec3 a, struct vec3 b, double r0,
		   double r1, int level)
{
	double len = vec3_dist(a, b), f = len > 0 ? fmin(GEN_FORK_MAX, GEN_FORK_RADII * r0 / len) : 0;
	struct vec3 pts[3] = { a, vec3_lerp(a, b, f), b };
	double radii[3] = { r0, r0 + (r1 - r0) * f, r1 };
	int id;

	if (parent < 0 || !(f > 0)) {
		pts[1] = b;
		radii[1] = r1;
	}
	id = tree_add_branch(g->t, parent, parent < 0 ? 0.0 : 1.0, ORIGIN_GENERATE, pts, radii,
			     parent < 0 || !(f > 0) ? 2 : 3);

	if (id >= 0)
		g->t->branches[id].level = level;
	return id;
}

int gen_build(struct tree *t, const struct gen_params *p, uint64_t seed)
{
	struct gen_ctx g = { .t = t, .p = p };
	struct error err;
	const char *key;
	int ret;

	tree_clear(t);
	if (gen_params_check(p, &key, &err) < 0)
		return -EINVAL;
	rng_seed(&g.rng, seed);
	g.noutline = gen_leaf_outline(p->leaf_type, g.outline, GEN_LEAF_MAX_POINTS);
	switch (p->type) {
	case GEN_SHRUB:
		/* a drawing's older shrub grows as it did when drawn */
		ret = p->gen_version == 1 ? gen_shrub_v1(&g) : gen_shrub(&g);
		break;
	case GEN_PALM:
		ret = gen_palm(&g);
		break;
	case GEN_LSYSTEM:
	default:
		ret = gen_lsystem(&g);
		break;
	}
	if (ret < 0) {
		tree_clear(t);
		return ret;
	}
	t->lifted = true;
	t->sides = p->precision;
	t->season = p->season;
	/* its leaves are what the leaf mode offers next (tree.h) */
	t->leaf_kind = gen_leaf_kind(p->leaf_type);
	return 0;
}
