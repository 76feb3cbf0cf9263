/* SPDX-License-Identifier: MIT */
/*
 * src/vine/ (floor 5 of src/FLOORS, beside sketch, gen and wood, which it never
 * includes): twining vines (seed 004): parameters, the support's index, growth, shapes
 * and meshes, and their place on a tree. Includes mesh, core and fmt.
 */
#pragma once

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "error.h"
#include "vec.h"

/*
 * Twining vines (seed 004, Kasakura): a climbing plant grown by simulating circumnutation
 * (the apex's free rod sweeping about the vertical) and apical dominance around any
 * support, a triangle mesh. docs/vines.md says how; docs/vine-format.md is the parameter
 * file (`edaha-vine: 1`), read by vine_read(). Pure and deterministic: the same
 * parameters, support, planting point and seed give the same vine, bit for bit.
 */

/* The parameter file's version (`edaha-vine: N`) this edaha reads. */
#define VINE_PARAMS_VERSION 1

enum vine_twining {
	VINE_LEFT = 0, /* the mirror of right: hop */
	VINE_RIGHT,    /* the thesis's right (clockwise seen from below): a right-handed helix,
			* counter-clockwise seen from above (morning glory) */
};

/* Table 3.1 (defaults Table 4.1, one thesis unit = 1 mm) and edaha's own. */
struct vine_params {
	double internode;  /* l, metres */
	double radius;     /* r, the stem's, metres */
	double step_time;  /* t: a new axis point every t units of simulated time */
	double angle;      /* theta_p, degrees: the free rod's lean from the vertical */
	int free_nodes;    /* U: nodes from the root before the apex starts circling */
	enum vine_twining twining;
	int leaves_per_node; /* 0, 1 (alternate) or 2 (opposite) */
	int cotyledons;      /* 0, 1 or 2 */
	double leaf_size;    /* gamma, metres: half the diagonal of the square leaf */
	int points_per_internode; /* d */
	int ring_sides;      /* M */
	double sweep;        /* omega, degrees per unit of time */
	int internodes;      /* the growth budget: growth stops when the vine has made this many */
	uint64_t seed;
};

/* The longest lengths a vine file may give (docs/vine-format.md), metres: what a scaled
 * vine (the kiosk's) keeps within. */
#define VINE_INTERNODE_MAX 1.0
#define VINE_RADIUS_MAX 0.05
#define VINE_LEAF_SIZE_MAX 0.2

/* Table 4.1's defaults and edaha's (docs/vine-format.md). */
void vine_params_default(struct vine_params *p);

/*
 * Reads a vine parameter file (docs/vine-format.md) from memory; name is the file's name
 * for messages. 0, or -EINVAL/-ENOMEM with err "NAME:LINE: what is wrong" (*p unchanged).
 */
int vine_read(const char *data, size_t len, const char *name, struct vine_params *p,
	      struct error *err);
/* The same for text that begins after line_offset lines of its file (a drawing's vine
 * line, in flow style): the lines told count from the file's start. */
int vine_read_at(const char *data, size_t len, const char *name, unsigned long line_offset,
		 struct vine_params *p, struct error *err);
struct buf;
/* The parameters as one line of YAML in flow style, every key, that vine_read reads back
 * bit for bit (how a drawing stores a vine). 0 or -ENOMEM (out as it was). */
int vine_write(const struct vine_params *p, struct buf *out);
#define VINE_READ_MAX_BYTES 65536
#define VINE_READ_MAX_DEPTH 4

/* Within every limit (docs/vine-format.md): 0, or -EINVAL with err naming the key. */
int vine_params_check(const struct vine_params *p, const char **key, struct error *err);

struct vine_support;

/* A shoot: the main axis (parent -1) or a lateral grown from one of its nodes. */
struct vine_shoot {
	int parent;         /* -1: the main axis; else the shoot it grew from */
	int node;           /* the parent's node it grew from (point node x d); 0 for the main */
	struct vec3 *axis;  /* the raw points, from the root */
	uint8_t *contact;   /* per point: it touched the support */
	size_t n, cap;
	size_t free_until;  /* points before this grew straight up (the non-twining part) */
	size_t pivot;       /* the free rod's pivot: the rod is axis[pivot .. n - 1] */
	double azimuth;     /* the rod's, radians, about +y: increasing counter-clockwise seen
			     * from above */
	size_t since_touch; /* points added since the rod last touched the support */
	int leaves_lost;    /* a leaf less at node `node` of the parent: this shoot's bud */
	bool stopped;
	/* The drawn axis kept clear of the support (vine_grow; docs/vines.md "Clear of the
	 * support"): point i is drawn at axis[i] + pull[i] (S_i - axis[i]), S_i its smoothed
	 * point, which smooth[i] holds as it was when pull[i] was found; pull 1 draws it
	 * smoothed, less pulls it back towards its raw point to stay r clear. Points from
	 * `cleared` on (all of them on a shoot made by hand: NULL arrays) are drawn smoothed. */
	struct vec3 *smooth;
	double *pull;
	size_t cleared;
	bool cleared_stopped; /* `stopped` when they were cleared */
};

/* A vine grown from a planting point around a support (vine_grow.c). */
struct vine {
	struct vine_params p;
	struct vec3 plant;
	struct vine_shoot *shoots;
	size_t nshoots, cap;
	int active;       /* the growing shoot; -1 when growth has ended */
	int next_bud;     /* the main axis's next node to sprout a lateral: U + 1, U + 2, ... */
	size_t points;    /* axis points grown, every shoot's, the roots not counted */
	uint64_t steps;   /* whole steps of step_time simulated */
};

/* A vine about to grow from plant (its root point). */
void vine_init(struct vine *v, const struct vine_params *p, struct vec3 plant);
void vine_finish(struct vine *v);
/* dst (not initialised) becomes an exact copy of src. 0, or -ENOMEM (dst then holds
 * nothing: vine_finish'ed). */
int vine_copy(struct vine *dst, const struct vine *src);
/* Bytes v's arrays take. */
size_t vine_bytes(const struct vine *v);

struct tree;
/* Takes v (grown) into tree t (its `vines`); v is left empty. 0, -ENOSPC (TREE_MAX_VINES)
 * or -ENOMEM (v unchanged then). vine_tree.c. */
int vine_attach(struct tree *t, struct vine *v);
/* How a tree frees, copies and counts its vines (tree.h's hooks): vine_attach sets it on
 * the tree, and so does an undo that brings vines back (tree_delta_swap). */
struct tree_vine_ops;
extern const struct tree_vine_ops vine_tree_ops;
/*
 * Grows v to simulated time `until` (units of step_time): every whole step not yet taken,
 * in order, so growing to 3.5 steps then to 7 gives what growing to 7 at once does. s may
 * be NULL (nothing to climb). Then keeps the drawn axes clear of s (vine_clear). 0 or
 * -ENOMEM (v as it was after the last whole step; points not yet cleared are drawn
 * smoothed until a later call clears them).
 */
int vine_grow(struct vine *v, const struct vine_support *s, double until);
/* Whether growth has ended: the budget spent, or no apex nor bud left. */
bool vine_done(const struct vine *v);
/* The number of nodes on a shoot (points node x d, from 1). */
size_t vine_shoot_nodes(const struct vine *v, size_t shoot);

/*
 * The shapes drawn from the raw axis (3.3; vine_shape.c): a shoot's smoothed axis (a
 * cubic spline where the direction's azimuth jumps by 45 degrees or more, over +-d/2
 * points; the free parts bent by seeded cubic Bezier offsets within +-5 l/d,
 * horizontally: the cotyledon node, the non-twining internodes, a stopped apex's last 2d
 * points), kept clear of the support it grew on (each point pulled back towards its raw
 * one as the shoot's `pull` says), as many points as the raw axis. *out allocated (the
 * caller frees). 0 or -ENOMEM. The raw axis never depends on the seed; only these do.
 */
int vine_smooth(const struct vine *v, size_t shoot, struct vec3 **out);
/*
 * Keeps the drawn axes clear of s (vine_grow does, after growing): every smoothed point
 * that changed since the last call, but a shoot's root, is drawn where it is if it lies r
 * or more from s and the way to it from its raw point crosses no triangle of s; else it
 * is pulled back along that way to the farthest point found so (bisected to 0.01 r): at
 * worst its raw point, which the growth kept r clear. Sets the shoots' smooth, pull and
 * cleared. s NULL: nothing to do. 0 or -ENOMEM (what was not cleared stays smoothed).
 */
int vine_clear(struct vine *v, const struct vine_support *s);

/* A leaf (or cotyledon): a square of half-diagonal leaf_size, a corner at its node. */
struct vine_leaf {
	size_t shoot;
	size_t node;    /* points node x d of its shoot */
	bool cotyledon;
	struct vec3 p[4]; /* counter-clockwise seen from its front */
};
/* Every leaf of v in shoot and node order. *out allocated (the caller frees), *n. 0 or
 * -ENOMEM. */
int vine_leaves(const struct vine *v, struct vine_leaf **out, size_t *n);

struct mesh;
/* The stems (rings of ring_sides along the smoothed axes, closed tips) appended to stem,
 * the leaves (double-sided quads) to leaves. 0 or -ENOMEM. */
int vine_mesh_append(const struct vine *v, struct mesh *stem, struct mesh *leaves);
/*
 * One shoot's stem through its axis points a[0..n) (n >= 2): rings of `sides` sides of
 * radius r, rotation-minimising (they do not twist), closed at the tip by a cone one
 * radius long; t and nr are scratch for n each; room made in m for sides (n + 1) + 1
 * vertices and 2 sides (n - 1) + sides triangles. vine_mesh_append's stems, and the
 * forest's coarser ones (src/forest/forest_lod_vine.c), are these.
 */
void vine_stem_tube(const struct vec3 *a, size_t n, size_t sides, double r, struct vec3 *t,
		    struct vec3 *nr, struct mesh *m);
