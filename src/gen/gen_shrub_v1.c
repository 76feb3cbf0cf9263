/* SPDX-License-Identifier: MIT */
/*
 * The shrub of generator version 1 (gen.h, GEN_VERSION): this file exists so that drawings
 * made before version 2 (a visitor's .edaha, the kiosk's archive and journal) rebuild their
 * shrubs as they were, bit for bit. It is the shrub of edaha before issue 24 (commit
 * 4394a65: its gen_shrub.c and the clipped recursion of its gen_lsystem.c), kept as it was:
 * do not improve it, or old drawings change. gen_shrub.c grows today's shrubs.
 *
 * A vertical trunk built apart, and a crown grown by the L-system recursion into a clipping
 * shape (sphere, box or cone), as a gardener clips a hedge or a topiary: every branch that
 * would leave the shape is cut at its surface, its bark and tip inside, and grows no
 * further; leaves that would stick out are made smaller or left out.
 *
 * The crown's first branches are ratios x L0 long, L0 chosen so that a straight run
 * through every generation would reach 1.25 times as far as the farthest point of the
 * shape from the trunk's top.
 *
 * What it shares with today's generators is what did not change: the clipping shape and
 * its distance, gen_clip_segment, the leaf outlines (a face of +y is the old leaves' frame),
 * gen_add_branch, gen_add_leaf and the random angles. What changed is here, as it was: the
 * recursion, the leaves of a tip, the surface's normal (a step of 1e-5) and the fitting of
 * a leaf (24 halvings).
 */
#include <errno.h>
#include <math.h>

#include "gen_private.h"

#define DEG (VEC_PI / 180.0)
/* A leaf leaves its branch at this angle, and the leaves of a tip follow each other round
 * it by the golden angle. */
#define V1_LEAF_ANGLE_DEG 40.0
#define V1_GOLDEN_DEG 137.50776405
/* The leaves of a tip sit along its outer part: the first at the tip. */
#define V1_LEAF_REACH 0.75
/* A branch clipped shorter than this many of its radii, or 1 cm, is left out. */
#define V1_CLIP_MIN_RADII 2.0
#define V1_CLIP_MIN_M 0.01
/* A clipped branch is cut this many leaf lengths inside the surface, so that its shoots
 * have room and its leaves reach out to the surface. */
#define V1_CLIP_SETBACK_LEAVES 0.5
/* A shoot that keeps less than this of its length is turned back into the shape. */
#define V1_CLIP_TURN_BACK 0.5
#define V1_REACH_FACTOR 1.25
/* A leaf keeps this far inside the surface (metres). */
#define V1_LEAF_CLEARANCE 0.002
#define V1_LEAF_MIN_SCALE (1.0 / 3.0)
#define V1_LEAF_FIT_STEPS 24

/* The outward unit normal of the shape's surface nearest x (the distance's gradient). */
static struct vec3 v1_clip_normal(const struct gen_clip_shape *s, struct vec3 x)
{
	const double h = 1e-5;
	struct vec3 g = vec3(gen_clip_distance(s, vec3_add(x, vec3(h, 0, 0))) -
				     gen_clip_distance(s, vec3_sub(x, vec3(h, 0, 0))),
			     gen_clip_distance(s, vec3_add(x, vec3(0, h, 0))) -
				     gen_clip_distance(s, vec3_sub(x, vec3(0, h, 0))),
			     gen_clip_distance(s, vec3_add(x, vec3(0, 0, h))) -
				     gen_clip_distance(s, vec3_sub(x, vec3(0, 0, h))));

	return vec3_norm_or(g, vec3(0, 1, 0));
}

static bool v1_leaf_fits(const struct gen_clip_shape *s, const struct vec3 *p, size_t n, double k)
{
	for (size_t i = 0; i < n; i++)
		if (gen_clip_distance(s, vec3_lerp(p[0], p[i], k)) > -V1_LEAF_CLEARANCE)
			return false;
	return true;
}

/* Shrinks a leaf about its base until every point is inside the shape; false (left out)
 * when even a third of its size is not. */
static bool v1_clip_leaf(const struct gen_clip_shape *s, struct vec3 *p, size_t n)
{
	double lo = V1_LEAF_MIN_SCALE, hi = 1.0;

	if (v1_leaf_fits(s, p, n, 1.0))
		return true;
	if (!v1_leaf_fits(s, p, n, lo))
		return false;
	for (int i = 0; i < V1_LEAF_FIT_STEPS; i++) {
		double mid = 0.5 * (lo + hi);

		if (v1_leaf_fits(s, p, n, mid))
			lo = mid;
		else
			hi = mid;
	}
	for (size_t i = 1; i < n; i++)
		p[i] = vec3_lerp(p[0], p[i], lo);
	return true;
}

/* The leaves of a tip: its outer three quarters, turned up, each fitted to the shape. */
static int v1_tip_leaves(struct gen_ctx *g, int b, struct vec3 e, const struct gen_clip_shape *clip)
{
	const struct gen_params *p = g->p;
	const struct branch *br = &g->t->branches[b];
	struct vec3 a = br->points[0], z = br->points[br->npoints - 1];
	struct vec3 d = vec3_norm_or(vec3_sub(z, a), vec3(0, 1, 0));
	struct vec3 pts[GEN_LEAF_MAX_POINTS];

	for (int k = 0; k < p->leaf_amount; k++) {
		double t = 1.0 - V1_LEAF_REACH * k / p->leaf_amount;
		struct vec3 v = gen_azimuth(d, e, k * V1_GOLDEN_DEG * DEG);
		struct vec3 axis = vec3_add(vec3_scale(d, cos(V1_LEAF_ANGLE_DEG * DEG)),
					    vec3_scale(v, sin(V1_LEAF_ANGLE_DEG * DEG)));
		size_t n;
		int ret;

		gen_leaf_points(g, vec3_lerp(a, z, t), axis, vec3(0, 1, 0), p->leaf_size, pts, &n);
		if (!v1_clip_leaf(clip, pts, n))
			continue;
		if ((ret = gen_add_leaf(g, b, t, pts, n)) < 0)
			return ret;
	}
	return 0;
}

/*
 * The L-system recursion (gen_lsystem.c) from branch b, clipped: its children, theirs, ...
 * down to level 1, every branch cut short where it would leave the shape. `e` is the unit
 * vector across b its children's azimuths are measured from; `length` the length their
 * ratios apply to. Leaves go on every branch left without children, but the trunk.
 */
static int v1_grow(struct gen_ctx *g, int b, struct vec3 e, double length,
		   const struct gen_clip_shape *clip)
{
	const struct gen_params *p = g->p;
	const struct branch *br = &g->t->branches[b];
	struct vec3 a = br->points[0], z = br->points[br->npoints - 1];
	struct vec3 d = vec3_norm_or(vec3_sub(z, a), vec3(0, 1, 0)), turned;
	double r0 = br->radii[br->npoints - 1], theta[GEN_MAX_CHILDREN];
	int level = br->level, ids[GEN_MAX_CHILDREN], made = 0;
	struct vec3 refs[GEN_MAX_CHILDREN];
	double lengths[GEN_MAX_CHILDREN];
	bool br_is_trunk = br->parent < 0;
	int ret;

	if (level <= 1)
		return br_is_trunk ? 0 : v1_tip_leaves(g, b, e, clip);
	for (int i = 0; i < p->children; i++)
		theta[i] = gen_angle(g);
	turned = gen_rotate(e, d, p->twist * DEG);
	for (int i = 0; i < p->children; i++) {
		double phi = (i - 0.5 * (p->children - 1)) * p->spread * DEG;
		struct vec3 di = vec3_add(vec3_scale(d, cos(theta[i])),
					  vec3_scale(gen_azimuth(d, e, phi), sin(theta[i])));
		double len = p->ratios[i] * length, r1 = r0 * p->thickness_ratio;
		struct vec3 end = vec3_add(z, vec3_scale(di, len));
		double setback = p->leaf_amount ? V1_CLIP_SETBACK_LEAVES * p->leaf_size : 0.0;
		double f = gen_clip_segment(clip, z, end, r0, r1, setback);
		int id;

		/* a shoot that would leave at once is turned back along the surface, as clipping
		 * makes a hedge grow in on itself */
		if (f < V1_CLIP_TURN_BACK) {
			struct vec3 n = v1_clip_normal(clip, z);
			struct vec3 dr = vec3_sub(di, vec3_scale(n, 2.0 * vec3_dot(di, n)));
			struct vec3 end_r = vec3_add(z, vec3_scale(dr, len));
			double fr = gen_clip_segment(clip, z, end_r, r0, r1, setback);

			if (fr > f) {
				di = dr;
				end = end_r;
				f = fr;
			}
		}
		if (f < 1.0) {
			/* cut at the surface; as a clipped hedge does, it sprouts again just
			 * inside, where its shoots that run along the surface fill it */
			double kept = f * len;

			if (f < 0 || kept < V1_CLIP_MIN_M || kept < V1_CLIP_MIN_RADII * r0)
				continue;
			r1 = r0 + (r1 - r0) * f;
			end = vec3_add(z, vec3_scale(di, kept));
		}
		id = gen_add_branch(g, b, z, end, r0, r1, level - 1);
		if (id < 0)
			return id;
		ids[made] = id;
		refs[made] = gen_transport(turned, d, di);
		lengths[made] = len;
		made++;
	}
	for (int i = 0; i < made; i++) {
		if ((ret = v1_grow(g, ids[i], refs[i], lengths[i], clip)) < 0)
			return ret;
	}
	/* every child clipped away: this branch is a tip of the crown (the trunk is not one:
	 * it stays bare) */
	return made || br_is_trunk ? 0 : v1_tip_leaves(g, b, e, clip);
}

/* The farthest the shape reaches from x. */
static double v1_reach(const struct gen_clip_shape *s, struct vec3 x)
{
	double far = 0.0;

	switch (s->kind) {
	case GEN_CLIP_BOX:
		for (int i = 0; i < 8; i++) {
			struct vec3 c = vec3(s->center.x + (i & 1 ? s->half.x : -s->half.x),
					     s->center.y + (i & 2 ? s->half.y : -s->half.y),
					     s->center.z + (i & 4 ? s->half.z : -s->half.z));

			far = fmax(far, vec3_dist(x, c));
		}
		return far;
	case GEN_CLIP_CONE:
		far = vec3_dist(x, vec3_add(s->center, vec3(0, s->height, 0)));
		for (int i = 0; i < 32; i++) {
			double a = 2.0 * VEC_PI * i / 32;
			struct vec3 rim = vec3_add(s->center, vec3(s->radius * cos(a), 0, s->radius * sin(a)));

			far = fmax(far, vec3_dist(x, rim));
		}
		return far;
	case GEN_CLIP_SPHERE:
	case GEN_CLIP_COUNT:
		break;
	}
	return vec3_dist(x, s->center) + s->radius;
}

int gen_shrub_v1(struct gen_ctx *g)
{
	const struct gen_params *p = g->p;
	struct gen_clip_shape shape;
	struct vec3 top = vec3_add(p->trunk_start, vec3(0, p->trunk_height, 0));
	double mean = 0.0, run = 0.0, k = 1.0;
	int trunk;

	gen_clip_shape_of(p, &shape);
	for (int i = 0; i < p->children; i++)
		mean += p->ratios[i] / p->children;
	for (int l = 1; l < p->levels; l++) {
		k *= mean;
		run += k;
	}
	trunk = gen_add_branch(g, -1, p->trunk_start, top, p->thickness,
			       p->thickness * p->thickness_ratio, p->levels);
	if (trunk < 0)
		return trunk;
	return v1_grow(g, trunk, gen_reference(vec3(0, 1, 0)),
		       run > 0 ? V1_REACH_FACTOR * v1_reach(&shape, top) / run : 0.0, &shape);
}
