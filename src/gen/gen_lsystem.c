/* SPDX-License-Identifier: MIT */
/*
 * The L-system type (seed 001, 3.1): the MakeTree recursion, read as the paper's prose
 * says (children are made while their level is above 1; the pseudo-code's IF is
 * inverted). docs/functional-trees.md has the geometry:
 *
 *   child i of a branch with direction d, at the branch's tip:
 *     direction  cos(theta_i) d + sin(theta_i) v(phi_i),  theta_i = gen_angle()
 *     azimuth    phi_i = (i - (children - 1) / 2) * spread, measured about d from the
 *                branch's reference e: v(phi) = cos(phi) e + sin(phi) (d x e)
 *     length     ratios[i] * the parent's length
 *     radius     the parent's tip radius, tapering to thickness_ratio of it
 *     reference  e turned by twist about d, then carried onto the child's direction by
 *                the rotation that takes d to it (so the branching plane turns by twist
 *                from one generation to the next)
 *
 * The generator draws every child's angle before it grows any child, depth first, so the
 * same seed gives the same tree.
 */
#include <errno.h>
#include <math.h>

#include "gen_private.h"

#define DEG (VEC_PI / 180.0)
/* A leaf leaves its branch at this angle, and the leaves of a tip follow each other round
 * it by the golden angle. */
#define LEAF_ANGLE_DEG 40.0
#define GOLDEN_DEG 137.50776405

struct vec3 gen_azimuth(struct vec3 d, struct vec3 e, double phi)
{
	return vec3_add(vec3_scale(e, cos(phi)), vec3_scale(vec3_cross(d, e), sin(phi)));
}

struct vec3 gen_transport(struct vec3 e, struct vec3 d, struct vec3 d2)
{
	struct vec3 k = vec3_cross(d, d2);
	double s = vec3_len(k), c = vec3_dot(d, d2);

	if (s > 1e-12)
		e = gen_rotate(e, vec3_scale(k, 1.0 / s), atan2(s, c));
	return vec3_norm_or(vec3_sub(e, vec3_scale(d2, vec3_dot(e, d2))), gen_reference(d2));
}

int gen_tip_leaves(struct gen_ctx *g, int b, struct vec3 e, double reach, struct vec3 face,
		   const struct gen_clip_shape *clip)
{
	const struct gen_params *p = g->p;
	const struct branch *br = &g->t->branches[b];
	struct vec3 a = br->points[0], z = br->points[br->npoints - 1];
	struct vec3 d = vec3_norm_or(vec3_sub(z, a), vec3(0, 1, 0));
	struct vec3 pts[GEN_LEAF_MAX_POINTS];

	for (int k = 0; k < p->leaf_amount; k++) {
		double t = 1.0 - reach * k / p->leaf_amount;
		struct vec3 v = gen_azimuth(d, e, k * GOLDEN_DEG * DEG);
		struct vec3 axis = vec3_add(vec3_scale(d, cos(LEAF_ANGLE_DEG * DEG)),
					    vec3_scale(v, sin(LEAF_ANGLE_DEG * DEG)));
		size_t n;
		int ret;

		gen_leaf_points(g, vec3_lerp(a, z, t), axis, face, p->leaf_size, pts, &n);
		if (clip && !gen_clip_leaf(clip, pts, n))
			continue;
		if ((ret = gen_add_leaf(g, b, t, pts, n)) < 0)
			return ret;
	}
	return 0;
}

/* The children of branch b, theirs, ... down to level 1; `length` is b's own. */
static int grow(struct gen_ctx *g, int b, struct vec3 e, double length)
{
	const struct gen_params *p = g->p;
	const struct branch *br = &g->t->branches[b];
	struct vec3 a = br->points[0], z = br->points[br->npoints - 1];
	struct vec3 d = vec3_norm_or(vec3_sub(z, a), vec3(0, 1, 0)), turned;
	double r0 = br->radii[br->npoints - 1], theta[GEN_MAX_CHILDREN];
	int level = br->level, ids[GEN_MAX_CHILDREN];
	struct vec3 refs[GEN_MAX_CHILDREN];
	double lengths[GEN_MAX_CHILDREN];
	int ret;

	if (level <= 1)
		return gen_tip_leaves(g, b, e, GEN_LEAF_REACH, vec3(0, 1, 0), NULL);
	for (int i = 0; i < p->children; i++)
		theta[i] = gen_angle(g);
	turned = gen_rotate(e, d, p->twist * DEG);
	for (int i = 0; i < p->children; i++) {
		double phi = (i - 0.5 * (p->children - 1)) * p->spread * DEG;
		struct vec3 di = vec3_add(vec3_scale(d, cos(theta[i])),
					  vec3_scale(gen_azimuth(d, e, phi), sin(theta[i])));
		double len = p->ratios[i] * length;
		int id = gen_add_branch(g, b, z, vec3_add(z, vec3_scale(di, len)), r0,
					r0 * p->thickness_ratio, level - 1);

		if (id < 0)
			return id;
		ids[i] = id;
		refs[i] = gen_transport(turned, d, di);
		lengths[i] = len;
	}
	for (int i = 0; i < p->children; i++)
		if ((ret = grow(g, ids[i], refs[i], lengths[i])) < 0)
			return ret;
	return 0;
}

int gen_lsystem(struct gen_ctx *g)
{
	const struct gen_params *p = g->p;
	struct vec3 d = vec3_norm_or(vec3_sub(p->trunk_end, p->trunk_start), vec3(0, 1, 0));
	int trunk = gen_add_branch(g, -1, p->trunk_start, p->trunk_end, p->thickness,
				   p->thickness * p->thickness_ratio, p->levels);

	if (trunk < 0)
		return trunk;
	return grow(g, trunk, gen_reference(d), vec3_dist(p->trunk_start, p->trunk_end));
}
