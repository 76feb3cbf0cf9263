/* SPDX-License-Identifier: MIT */
/*
 * src/core/ (floor 2 of src/FLOORS): the tree model (this header: branches, leaves,
 * the hooks through which vines, wood and the undo journal are reached), its index and
 * edits, the triangle buffer, tube frames, vectors, the seeded generator, camera, season,
 * the event model and the screen's layout. Includes fmt only.
 */
#pragma once

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "season.h"
#include "vec.h"

/* How an element came to be; written to skeleton.json as a string. */
enum origin {
	ORIGIN_SKETCH = 0,
	ORIGIN_CLONE,
	ORIGIN_PROPAGATE,
	ORIGIN_MERGE,
	ORIGIN_ARRANGE,
	ORIGIN_GENERATE, /* made by a tree generator from its parameters (seed 001, gen.h) */
};

const char *origin_name(enum origin origin);

struct branch {
	int id;          /* index in tree.branches */
	int parent;      /* -1 for the trunk */
	double parent_t; /* arc-length parameter 0..1 on the parent where it attaches */
	int generation;  /* 0 for the trunk */
	int level;       /* a generated branch's level (gen.h: the trunk's is `levels`, tips
			  * are 1); 0 for every other branch */
	enum origin origin;
	struct vec3 *points; /* root first, world metres */
	double *radii;       /* one per point, metres */
	size_t npoints;
};

struct leaf {
	int id;
	int branch;      /* the branch it is attached to */
	double branch_t; /* arc-length parameter 0..1 on that branch where it attaches */
	enum origin origin;
	struct vec3 *points; /* closed polygon, last point != first */
	/* The same points in the branch's frame at branch_t (tree_leaf_attach), so the leaf
	 * follows when the branch moves (tree_leaves_follow); NULL until attached. */
	struct vec3 *local;
	size_t npoints;
	/* An origami leaf's kind (ori_kinds.h: its points are the design's margin at rest in
	 * the leaf's frame), or ORI_KIND_DRAWN (-1) for an outline. */
	int kind;
};

#define TREE_PROFILE_N 16

/*
 * The most a tree grows to by example-based editing (propagation multiplies it: three
 * twigs propagated twice over 1,000 branches make 16,000). An edit that could pass these
 * is refused, so a kiosk (or a hostile drawing) cannot ask for a mesh its board cannot
 * draw, nor an export a USB stick cannot take: 30,000 leaves are about 1 M triangles
 * and an 80 MB OBJ. (20 leaves on each of 1,000 branches fit.)
 */
#define TREE_MAX_BRANCHES 10000u
#define TREE_MAX_LEAVES 30000u
/* Vines on one tree: a planting past it is refused (the kiosk says the tree is full). */
#define TREE_MAX_VINES 12u
/* The farthest a drawing's coordinates lie from the origin, metres (|x|, |y| on the
 * sketch plane: DOC_MAX_COORD_M); a generated tree's points keep within it too. */
#define TREE_MAX_COORD_M 1000.0f

struct tree;
struct vine;
struct wood;
struct tree_journal;

/*
 * What systems built on the tree keep in it: the vines (vine.h) and the wood (wood.h).
 * The tree frees, copies and counts them through these tables, which each system sets on
 * a tree when it puts its data there (vine_attach, wood_begin, and tree_delta_swap when
 * an undo brings some back); tree_clear keeps them, tree_copy copies them. So the tree
 * (core, a floor below them: src/FLOORS) never names their code.
 */
struct tree_vine_ops {
	/* Frees what each of t's nvines vines holds (the array and the count stay). */
	void (*clear)(struct tree *t);
	/* dst, without vines, gets exact copies of src's: 0, or -ENOMEM (dst->nvines then
	 * counts the copies made, for tree_clear to free). */
	int (*copy)(struct tree *dst, const struct tree *src);
	/* Bytes t's vines take: the array (cap_vines of them) and what each holds. */
	size_t (*bytes)(const struct tree *t);
	/* Calls f on each of the vines' points, with its stem's radius: a vine's planting
	 * point, then its shoots' raw axis points, in order; vine after vine. What another
	 * system moves when it moves what hangs on the tree (wood_move_out). */
	void (*each_point)(struct tree *t, void (*f)(struct vec3 *p, double radius, void *ctx),
			   void *ctx);
};

struct tree_wood_ops {
	/* Frees w and what it holds. */
	void (*destroy)(struct wood *w);
	/* An exact copy of w (allocated), or NULL without memory. */
	struct wood *(*copy)(const struct wood *w);
	/* Bytes w takes, itself and what it holds. */
	size_t (*bytes)(const struct wood *w);
	/* Whether branch i's bark is the wood's (voxelised), not its swept tube. */
	bool (*holds)(const struct wood *w, size_t i);
};

/* The hooks an undo journal (tree_delta.h, a floor above) sets on the tree it watches:
 * tree.c and tree_edit.c call them through tree_journal.h, never the journal's code. */
struct tree_journal_ops;

/* The model: what the skeleton, the meshes and the screen are made from. */
struct tree {
	struct branch *branches;
	size_t nbranches, cap_branches;
	struct leaf *leaves;
	size_t nleaves, cap_leaves;

	bool lifted; /* the 3D button made it a 3D tree (or a generator made it, in 3D) */
	/* What every element's look depends on, beside the elements (undone with them):
	 * the sides of every ring of bark (a generated tree's `precision`; 0: the mesh's
	 * level of detail picks them, mesh.h), and the season (season.h). */
	int sides;
	enum season season;
	/* The leaf kind the leaf mode chose (DOC_OP_LEAFTYPE, a generated tree's leaves.type):
	 * what arrangement and propagation place; -1 the drawn leaves. */
	int leaf_kind;
	/* Twining vines planted on the tree (issue 16, DOC_OP_VINE), each grown to its end
	 * on the bark as it stood when planted; later edits leave them as they are. */
	struct vine *vines;
	size_t nvines, cap_vines;
	const struct tree_vine_ops *vine_ops; /* vine.h's, once the tree has had vines */
	/* Growing wood (issue 17, DOC_OP_GROW): the field of its thick branches through its
	 * presses and the bark drawn from it (wood.h), or NULL: never grown, or an edit changed
	 * its branches since. Owned, copied with the tree. */
	struct wood *wood;
	const struct tree_wood_ops *wood_ops; /* wood.h's, once the tree has had wood */
	/* What sketching carries from stroke to stroke; rebuilt with the tree. */
	int last_sketched;             /* the branch the latest stroke drew, or -1 */
	uint64_t last_sketched_end_us; /* when that stroke ended */
	bool has_profile;              /* a two-stroke branch defined a radius profile: */
	double profile[TREE_PROFILE_N]; /* radius / root radius at s = i / (N - 1) */

	/* sketch_nearest's grid of the branch segments (tree_index.h), if this tree keeps one:
	 * a cache, not part of the model (tree_copy leaves it). The functions here keep it in
	 * step; code that moves a branch's points in place calls tree_index_drop(). */
	struct tree_index *index;
	/* While the app applies an op: what its edits take out or change, for undo and redo
	 * (tree_delta.h); NULL otherwise. Not part of the model either (tree_copy leaves it). */
	struct tree_journal *journal;
	const struct tree_journal_ops *journal_ops; /* the journal's hooks (tree_journal.h) */
};

void tree_init(struct tree *t);
void tree_finish(struct tree *t);
void tree_clear(struct tree *t);
/* Copies points/radii. Returns the new id, or -ENOMEM. */
int tree_add_branch(struct tree *t, int parent, double parent_t, enum origin origin,
		    const struct vec3 *points, const double *radii, size_t npoints);
int tree_add_leaf(struct tree *t, int branch, enum origin origin, const struct vec3 *points,
		  size_t npoints);
/* Drops t's wood (its branches show their swept bark again, their radii as the power law
 * left them). */
void tree_wood_drop(struct tree *t);
/* Whether branch i's bark is the wood's (voxelised), not its swept tube. */
bool tree_branch_in_wood(const struct tree *t, size_t i);
/* Makes dst (initialised) an exact copy of src: every field of every branch and leaf, the
 * sketching state, bit for bit. 0, or -ENOMEM (dst is then empty). */
int tree_copy(struct tree *dst, const struct tree *src);
/* Removes the branches from nb on and the leaves from nl on: the tree as it was before
 * they were appended (what stays must not refer to them). */
void tree_truncate(struct tree *t, size_t nb, size_t nl);
/* Bytes the tree's elements take (its arrays and what they point to). */
size_t tree_bytes(const struct tree *t);
/* Swaps two trees, their grids (tree_index.h) with them. */
void tree_swap(struct tree *a, struct tree *b);

/* Edits (tree_edit.c). Ids stay dense and in creation order, so a child always comes
 * after its parent. */

/* Removes every branch with remove[id] set, everything attached to it (recursively) and
 * their leaves; renumbers what stays. remove has nbranches entries and is updated to
 * say what was removed. 0 or -ENOMEM (tree unchanged). */
int tree_remove_branches(struct tree *t, bool *remove);
/* Removes leaves with remove[id] set; renumbers the rest. */
void tree_remove_leaves(struct tree *t, const bool *remove);
/* Cuts branch b at (segment, seg_t): its part beyond, and every branch and leaf attached
 * there, are removed; attachment parameters on b are rescaled to its new length.
 * 0 or -ENOMEM (tree unchanged). */
int tree_cut_branch(struct tree *t, int b, size_t segment, double seg_t);
/* Arc length of a branch's polyline. */
double tree_branch_length(const struct branch *b);
/* Where arc-length parameter t (0..1) falls on b: segment index and fraction along it;
 * and back. Points that move (lifting) keep their (segment, fraction), not their t. */
void tree_locate(const struct branch *b, double t, size_t *segment, double *seg_t);
double tree_param(const struct branch *b, size_t segment, double seg_t);

/* The frame of branch b at arc-length parameter t: position, unit tangent and two unit
 * normals: `normal` across the branch in the picture plane, `binormal` = tangent x normal.
 * Deterministic. */
struct tree_frame {
	struct vec3 origin, tangent, normal, binormal;
};
struct tree_frame tree_frame_at(const struct branch *b, double t);
/* Records leaf i's points in its branch's frame. 0 or -ENOMEM. */
int tree_leaf_attach(struct tree *t, size_t leaf);
/* Moves every attached leaf of branch b (all branches if b < 0) to where its branch's
 * frame now puts it: call after changing a branch's points. */
void tree_leaves_follow(struct tree *t, int b);
