/* SPDX-License-Identifier: MIT */
/*
 * src/mesh/ (floor 4 of src/FLOORS): the tree's meshes (this header: tubes, leaf
 * polygons, origami leaves), their reuse and updates, leaf instances and colours.
 * Includes ori, core and fmt.
 */
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "mesh_buffer.h"
#include "tree.h"

/*
 * The tree as triangles (mesh.c, mesh_reuse.c, mesh_update.c; leaf_instances.h and
 * leaf_colors.h beside it): on the floor above the origami leaves (src/FLOORS), whose
 * kinds it meshes, and below every system that draws on it.
 */

/*
 * Level of detail. The camera is orthographic at a fixed scale (the screen height always
 * spans SCREEN_HEIGHT_M, no zoom), so a branch's size on screen is its size in metres times
 * MESH_REF_SCREEN_PX / SCREEN_HEIGHT_M: pixels at a reference screen height of 1080 px, 108 px
 * a metre. Detail follows from that alone, so it is the same on every screen and in exports:
 *
 * - Sides. Each ring gets the fewest sides (MESH_MIN_SIDES..MESH_MAX_SIDES) whose polygon
 *   keeps within MESH_SIDE_ERROR_PX of the true circle, r (1 - cos(pi / sides)) in pixels:
 *   3 sides up to 1 px of radius (9 mm), 4 to 16 mm, 8 to 60 mm, 16 from 0.21 m (a trunk;
 *   past 0.24 m the error grows beyond half a pixel). Neighbouring rings with different
 *   counts are stitched by angle, so a tapering branch loses sides towards its tip.
 * - Rings. A point of a branch gets no ring when the straight tube between the rings kept
 *   on either side stays near it: its distance from that tube's axis plus its radius's
 *   difference from that tube's radius is at most mesh_drop_tolerance(r) =
 *   min(MESH_DROP_ERROR_PX in metres (2.3 mm), MESH_DROP_RADIUS_FRACTION * r); the branch
 *   turns by at most MESH_DROP_TURN_DEG there; the straight tube runs within
 *   MESH_DROP_TURN_DEG of every segment it replaces, at most MESH_DROP_MAX_SPAN of them;
 *   and the point would get the sides of the ring kept before it (counts change only at
 *   kept rings). The first and last points always keep their rings; rings that stay sit
 *   exactly on their points.
 */
#define MESH_REF_SCREEN_PX 1080.0
#define MESH_SIDE_ERROR_PX 0.5
#define MESH_MIN_SIDES 3
#define MESH_MAX_SIDES 16
#define MESH_DROP_ERROR_PX 0.25
#define MESH_DROP_RADIUS_FRACTION 0.25
#define MESH_DROP_TURN_DEG 4.0
#define MESH_DROP_MAX_SPAN 16

/* Sides of a ring of this radius (metres). */
int mesh_ring_sides(double radius);
/* How far (metres) a left-out point of radius r may be from the tube that replaces it. */
double mesh_drop_tolerance(double radius);

/*
 * Bark (branches swept as tubes along rotation-minimising frames) and leaves (one-sided
 * polygons, drawn double-sided). Each branch is a closed tube: a disc at the root, a cone
 * at the tip. A child's root lies on its parent's axis (at parent_t); its root ring shrinks
 * as far as needed to lie inside the parent's tube (or, near the parent's root, the
 * grandparent's), which has few sides when thin, so no root disc shows beside its parent
 * and the child leaves it without a gap. A child's mesh depends on it, its parent and
 * grandparent only.
 */
struct tree_mesh {
	struct mesh bark;
	struct mesh leaves;
};

void tree_mesh_init(struct tree_mesh *tm);
void tree_mesh_finish(struct tree_mesh *tm);
/* Rebuilds both meshes from the tree. Returns 0 or -ENOMEM (meshes then empty).
 * Deterministic: elements are laid out in the tree's order. */
int tree_mesh_build(struct tree_mesh *tm, const struct tree *t);
/* Adds branches [first_branch..) and leaves [first_leaf..) to meshes built for the
 * elements before them: the same bytes as a full rebuild, at the cost of the new ones. */
int tree_mesh_append(struct tree_mesh *tm, const struct tree *t, size_t first_branch,
		     size_t first_leaf);

/*
 * Where each element's part of a tree_mesh begins, and where the last one ends. Since an
 * element's mesh depends on elements before it only, the meshes of a tree cut back to
 * a prefix of its elements (tree_truncate) are these meshes cut back
 * (tree_mesh_truncate): how undo takes back a stroke without meshing the tree again.
 */
struct tree_mesh_mark {
	size_t nvertices, nindices;
};
struct tree_mesh_marks {
	struct tree_mesh_mark *bark, *leaves; /* [i]: before element i; [n]: after all */
	size_t nbark, nleaves;                /* marks held: elements + 1, or 0 if unknown */
	size_t cap_bark, cap_leaves;
};
void tree_mesh_marks_init(struct tree_mesh_marks *mk);
void tree_mesh_marks_finish(struct tree_mesh_marks *mk);
/* tree_mesh_build and tree_mesh_append that keep mk too (unknown without memory for it,
 * or when mk did not describe tm). Same results. */
int tree_mesh_build_marked(struct tree_mesh *tm, const struct tree *t, struct tree_mesh_marks *mk);
int tree_mesh_append_marked(struct tree_mesh *tm, const struct tree *t, size_t first_branch,
			    size_t first_leaf, struct tree_mesh_marks *mk);
/* Cuts tm back to the first nb branches' and nl leaves' parts. False (nothing changed)
 * when mk does not know where they end. */
bool tree_mesh_truncate(struct tree_mesh *tm, struct tree_mesh_marks *mk, size_t nb, size_t nl);
/*
 * tree_mesh_build_marked of t into tm (not from), except that branch i's part is copied
 * from from's part of its branch reuse_branch[i] when that is >= 0 (its indices moved
 * with it), and leaf i's from leaf reuse_leaf[i]: the caller vouches they would come out
 * the same (mesh_reuse.c). from_mk must know from's parts. Same results otherwise.
 */
int tree_mesh_build_reusing(struct tree_mesh *tm, struct tree_mesh_marks *mk, const struct tree *t,
			    const struct tree_mesh *from, const struct tree_mesh_marks *from_mk,
			    const int *reuse_branch, const int *reuse_leaf);
/*
 * The parts of t's branches `branches[0..nb)` and leaves `leaves[0..nl)` alone, one after
 * the other, into out (cleared first): part k between marks k and k + 1 of out_mk, its
 * indices counted from its own first vertex's place in out. Each is the part a full
 * build makes of that element, but for where its vertices are. 0, -EINVAL (no such
 * element) or -ENOMEM (out then empty).
 */
int tree_mesh_build_parts(struct tree_mesh *out, struct tree_mesh_marks *out_mk,
			  const struct tree *t, const size_t *branches, size_t nb, const size_t *leaves,
			  size_t nl);
/*
 * Coarser bark for a tree seen small (the forest's levels of detail, docs/forest.md):
 * every ring at most max_sides sides (at least MESH_MIN_SIDES; 0: no cap, a tree's fixed
 * `sides` capped too), and rings left out drop_scale times as readily: the tolerance
 * mesh_drop_tolerance and the turn MESH_DROP_TURN_DEG both times drop_scale (at most
 * MESH_COARSE_MAX_SCALE, the turn at most MESH_COARSE_MAX_TURN_DEG; <= 1: as they are).
 * A child's root ring is sized by the joint rule above with the capped sides but the
 * tree's own tolerance and turn: it lies inside its parent's tube as the tree's own mesh
 * would have it, which the coarser tube strays from by at most the coarser tolerance
 * (a root may show by that much, where a stricter joint would pinch every thick child
 * to a point). Leaves are never coarsened: they come out as a full build makes them.
 */
#define MESH_COARSE_MAX_SCALE 64.0
#define MESH_COARSE_MAX_TURN_DEG 45.0
struct mesh_coarse {
	int max_sides;
	double drop_scale;
};
/* tree_mesh_build_parts with bark made coarser by c (NULL or {0, 1}: the same bytes). */
int tree_mesh_build_parts_coarse(struct tree_mesh *out, struct tree_mesh_marks *out_mk,
				 const struct tree *t, const size_t *branches, size_t nb,
				 const size_t *leaves, size_t nl, const struct mesh_coarse *c);
/*
 * Meshes t from the meshes tm holds (those of another tree, marked in mk), in place: part
 * i of t's bark is the old part branch[i] when that is >= 0 (such parts must come in the
 * old order), part -2 - branch[i] of `stash` (marked in stash_mk) when that is <= -2, or
 * built (-1); leaves alike. The caller vouches that the parts taken are what a build
 * would make. Memory moves only where parts come and go: the parts kept shift in place.
 * 0, -EINVAL (a part that is not there, or out of order) or -ENOMEM; tm and mk are as
 * they were on failure. parts_built, if given, gets how many parts were built.
 */
#define TREE_MESH_BUILD (-1)
struct tree_mesh_plan {
	const int *branch, *leaf;
	const struct tree_mesh *stash;
	const struct tree_mesh_marks *stash_mk;
};
int tree_mesh_update(struct tree_mesh *tm, struct tree_mesh_marks *mk, const struct tree *t,
		     const struct tree_mesh_plan *plan, size_t *parts_built);
/* Gives back the room tm's meshes hold beyond a quarter more than they use (meshes
 * kept aside, to be the tree's again). */
void tree_mesh_shrink(struct tree_mesh *tm);
/* Copies the parts of tm's branches `branches[0..nb)` and leaves `leaves[0..nl)` into out
 * (cleared first), as tree_mesh_build_parts lays them out. 0, -EINVAL or -ENOMEM. */
int tree_mesh_copy_parts(struct tree_mesh *out, struct tree_mesh_marks *out_mk,
			 const struct tree_mesh *tm, const struct tree_mesh_marks *mk,
			 const size_t *branches, size_t nb, const size_t *leaves, size_t nl);
