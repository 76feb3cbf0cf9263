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
/* The outline of a leaf of `size` from `base` along `axis`, its front turned up as far as
 * it goes: g->noutline points into out (GEN_LEAF_MAX_POINTS of room). */
void gen_leaf_points(const struct gen_ctx *g, struct vec3 base, struct vec3 axis, double size,
		     struct vec3 *out, size_t *n);
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

/*
 * The recursion of the L-system type (3.1) from a branch already in the tree: its
 * children, theirs, ... down to level 1. `e` is the unit vector perpendicular to the
 * branch that its children's azimuths are measured from; `length` the length the
 * children's ratios apply to (the branch's own, but for a shrub's trunk). A clip (shrub)
 * cuts every branch short where it would leave the shape (NULL: none). Leaves go on every
 * branch left without children.
 */
struct gen_clip_shape;
int gen_lsystem_grow(struct gen_ctx *g, int branch, struct vec3 e, double length,
		     const struct gen_clip_shape *clip);

int gen_lsystem(struct gen_ctx *g);
int gen_shrub(struct gen_ctx *g);
int gen_palm(struct gen_ctx *g);

/* A shrub's clipping shape (gen_shrub.c). */
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
/* The outward unit normal of the shape's surface nearest x (the distance's gradient). */
struct vec3 gen_clip_normal(const struct gen_clip_shape *s, struct vec3 x);
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
