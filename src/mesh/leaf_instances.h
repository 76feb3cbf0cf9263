/* SPDX-License-Identifier: MIT */
#pragma once

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "mesh.h"
#include "tree.h"

/*
 * Leaves grouped by shape, for drawing them instanced (one draw call a shape).
 *
 * Propagation copies a leaf scaled, arrangement turned about its branch, lifting and
 * tree_leaves_follow() move it rigidly: the copies' outlines are similar to their
 * source's. A leaf whose world outline is o + M * (b_k - c) for every point k, where b
 * are the points of an earlier leaf with as many points (the shape's base), c their
 * centroid and M a rotation times a uniform scale (determinant > 0), is an instance of
 * that leaf's shape; otherwise it starts a shape of its own.
 *
 * Finding M: the base's point farthest from its centroid (a) and the point making the
 * largest parallelogram with it (b) give an orthonormal frame; the same two points of
 * the leaf give another; the rotation takes one to the other and the scale is the ratio
 * of the outlines' root-mean-square sizes. It is accepted when every point lands within
 * LEAF_INSTANCES_TOLERANCE x the leaf's size (its largest distance from its centroid).
 * Candidates are found by a key, the point count and the squared edge lengths as
 * fractions of their sum quantised to 1/LEAF_INSTANCES_KEY_STEPS, hashed: grouping costs
 * about the same for every leaf. Leaves with a non-finite point, fewer than 3 points or
 * all on a line (no frame) are shapes of their own and never matched.
 *
 * Which shapes are drawn instanced: those with at least LEAF_INSTANCES_MIN_COPIES
 * instances, at most LEAF_INSTANCES_MAX_SHAPES of them (the ones with the most instances;
 * ties: the earlier). Every other leaf (a drawn leaf nothing was copied from, and any
 * beyond that number of shapes) goes into one merged mesh, `loose`, built by
 * tree_mesh_build's code in world coordinates: a frame never costs more than
 * LEAF_INSTANCES_MAX_SHAPES + 1 draw calls for leaves, whatever a drawing holds. When no
 * shape is instanced, loose is left empty: it would be tree_mesh_build's leaves mesh, which
 * the caller has (ninstanced_shapes == 0 says so).
 *
 * An instanced shape's mesh is its base outline about the centroid (b_k - c)
 * triangulated by mesh.c (tree_mesh_append on a one-leaf tree): the triangles a merged
 * mesh has for each of its leaves, the same vertices moved by the leaf's matrix, the
 * normals turned by it. Only leaves of one kind (struct leaf's) match: an origami leaf's
 * shape is its faces about the centroid (mesh.c meshes a one-leaf tree of that kind so),
 * never its outline triangulated. Deterministic: same tree, same groups, same bytes.
 */
#define LEAF_INSTANCES_TOLERANCE 1e-6
#define LEAF_INSTANCES_KEY_STEPS 4096.0
#define LEAF_INSTANCES_MIN_COPIES 2
#define LEAF_INSTANCES_MAX_SHAPES 64

struct leaf_shape {
	size_t base;          /* the leaf whose outline it is: its first */
	struct vec3 centroid; /* of the base's points (world); the origin of the shape's frame */
	size_t npoints;       /* of the base (and of every instance) */
	size_t first, count;  /* its instances: instances[first .. first + count) */
	bool instanced;       /* drawn instanced (mesh + matrices); else its leaves are in loose */
	struct mesh mesh;     /* instanced only: b_k - c triangulated as mesh.c does a leaf */
	/* An instanced origami shape's unfolding (ori_unfold_frames): ORI_UNFOLD_FRAMES
	 * meshes in the same frame as `mesh`, for the leaves still opening; else NULL. */
	struct mesh *frames;

	/* How leaves are matched against it (leaf_instances.c). */
	uint64_t key;
	size_t next_same_key; /* another shape with this key, or SIZE_MAX */
	size_t anchor_a, anchor_b;
	struct vec3 frame[3]; /* orthonormal, from the anchors; frame[0] along b_a - c */
	double norm2;         /* sum of |b_k - c|^2 */
	bool matchable;
};

struct leaf_instance {
	size_t leaf;  /* its id in the tree */
	size_t shape; /* index in shapes */
	/* Row-major 3x4 [M | o]: leaf point k = M * (base point k - base centroid) + o. For
	 * the base itself M = I and o = the centroid. */
	double xf[12];
};

struct leaf_instances {
	struct leaf_shape *shapes; /* in the order of their base leaves */
	size_t nshapes, cap_shapes;
	/* Every leaf once: the instanced shapes' (shape by shape in shapes' order, each in
	 * leaf order) in [0, ninstanced), then the others' (likewise). */
	struct leaf_instance *instances;
	size_t ninstances, ninstanced, cap_instances;
	float *matrices;       /* xf as float, 12 an instance, in the order of instances */
	size_t cap_matrices;   /* in instances */
	size_t ninstanced_shapes;
	struct mesh loose;     /* the leaves of shapes not instanced, in leaf order, world;
				* empty when no shape is instanced (see above) */
	size_t ntriangles;     /* drawn instanced: each instanced shape's triangles x its count */

	/* scratch, kept between builds */
	size_t *table; /* key hash -> shape + 1 (0: empty) */
	size_t table_cap;
	struct leaf_instance *by_leaf;
	size_t cap_by_leaf;
};

void leaf_instances_init(struct leaf_instances *li);
void leaf_instances_finish(struct leaf_instances *li);
/* Groups t's leaves (see above). 0 or -ENOMEM (li then empty). */
int leaf_instances_build(struct leaf_instances *li, const struct tree *t);
/* Point k of instance i as its shape and matrix give it (within the tolerance of the
 * leaf's own point k). */
struct vec3 leaf_instances_point(const struct leaf_instances *li, const struct tree *t,
				 size_t i, size_t k);
