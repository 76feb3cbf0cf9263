/* SPDX-License-Identifier: MIT */
#pragma once

/* What the generators (gen_lsystem.c, gen_shrub.c, gen_palm.c) share. Not for gen.h's
 * users. */
#include "gen.h"
#include "rng.h"

/* The most points of a leaf outline (gen_leaf.c). */
#define GEN_LEAF_MAX_POINTS 24

struct gen_ctx {
	struct tree *t;
	const struct gen_params *p;
	struct rng rng;
	/* the leaves' outline (gen_leaf_outline of p->leaf_type), made once a tree */
	double outline[GEN_LEAF_MAX_POINTS][2];
	size_t noutline;
};

/* A leaf of length 1 along +x from (0, 0), its width along y, counter-clockwise: how many
 * points it has (0 when max is too small). */
size_t gen_leaf_outline(enum gen_leaf type, double out[][2], size_t max);
/* The outline of a leaf of `size` from `base` along `axis`, its front turned towards `face`
 * (a unit vector: up, but on a clipped shrub) as far as it goes: g->noutline points into
 * out (GEN_LEAF_MAX_POINTS of room). */
void gen_leaf_points(const struct gen_ctx *g, struct vec3 base, struct vec3 axis, struct vec3 face,
		     double size, struct vec3 *out, size_t *n);
/* Adds a leaf with points p on `branch` at arc-length parameter t, attached (its `local`
 * recorded). Its id, or -ENOMEM. */
int gen_add_leaf(struct gen_ctx *g, int branch, double t, const struct vec3 *p, size_t n);

/* A straight branch from a to b, radius r0 tapering to r1, at its parent's tip (the trunk:
 * parent -1). Its id, or -ENOMEM. */
int gen_add_branch(struct gen_ctx *g, int parent, struct vec3 a, struct vec3 b, double r0,
		   double r1, int level);

/* The angle the MakeTree rule gives (radians): mid + randomness u (max - min) / 2 with u
 * uniform in [-1, 1], drawn from g's generator whatever the randomness. */
double gen_angle(struct gen_ctx *g);

/* Rotates v about the unit axis k by angle a (radians), right-handed. */
struct vec3 gen_rotate(struct vec3 v, struct vec3 k, double a);
/* A unit vector perpendicular to unit d: world +x made perpendicular (+z when d is
 * along x): where a trunk's azimuths are measured from. */
struct vec3 gen_reference(struct vec3 d);
/* v(phi) = cos(phi) e + sin(phi) (d x e): the direction at azimuth phi round unit d from e
 * (perpendicular to it). */
struct vec3 gen_azimuth(struct vec3 d, struct vec3 e, double phi);
/* e (perpendicular to d) carried onto direction d2 by the rotation taking d to d2. */
struct vec3 gen_transport(struct vec3 e, struct vec3 d, struct vec3 d2);

struct gen_clip_shape;

/* Leaves on a tip branch b: leaves.amount of them, the first at its tip and the others
 * evenly down the `reach` of it (a fraction of its length: an L-system tree's leaves go
 * GEN_LEAF_REACH down), round it by the golden angle from e (a unit vector across it),
 * their fronts towards `face` (gen_leaf_points); each cut to the shape (clip; NULL: none).
 * 0 or -ENOMEM. */
#define GEN_LEAF_REACH 0.75
int gen_tip_leaves(struct gen_ctx *g, int b, struct vec3 e, double reach, struct vec3 face,
		   const struct gen_clip_shape *clip);

int gen_lsystem(struct gen_ctx *g);
int gen_shrub(struct gen_ctx *g);
int gen_palm(struct gen_ctx *g);
/* A shrub as generator version 1 grew it (gen_shrub_v1.c): drawings made before version 2
 * rebuild as they were. */
int gen_shrub_v1(struct gen_ctx *g);

/* A shrub's crown (gen_shrub.c): how many tips it aims at its shape's surface, and the
 * most branches it has, its trunk's included (gen_count_branches). */
size_t gen_shrub_tips(const struct gen_params *p);
size_t gen_shrub_branches(const struct gen_params *p);

/* A shrub's clipping shape. */
struct gen_clip_shape {
	enum gen_clip kind;
	struct vec3 center; /* sphere, box: the centre; cone: the centre of its base */
	double radius, height;
	struct vec3 half;   /* box: half its edges */
};
void gen_clip_shape_of(const struct gen_params *p, struct gen_clip_shape *s);
/* The signed distance from x to the shape's surface (< 0 inside): exact inside, and
 * never more than the true distance outside. Convex in x. */
double gen_clip_distance(const struct gen_clip_shape *s, struct vec3 x);
/*
 * How much of the branch from a (radius r0) to b (radius r1) stays inside the shape with
 * its bark and its tip: the largest f in [0, 1] that keeps every point of a + f' (b - a),
 * f' <= f, deeper inside than GEN_CLIP_MARGIN times its radius plus `setback`. -1 when
 * a itself is not deeper than GEN_CLIP_MARGIN times r0.
 */
#define GEN_CLIP_MARGIN 2.2
double gen_clip_segment(const struct gen_clip_shape *s, struct vec3 a, struct vec3 b, double r0,
			double r1, double setback);
/* Shrinks a leaf about its first point (its base) until every point is inside the shape;
 * false (the leaf is left out) when even a third of its size is not. */
bool gen_clip_leaf(const struct gen_clip_shape *s, struct vec3 *p, size_t n);
