/* SPDX-License-Identifier: MIT */
#pragma once

#include <stdbool.h>
#include <stddef.h>

#include "mesh.h"
#include "tree.h"
#include "tree_journal.h"

/*
 * How one op changed a tree, both ways, so that undo and redo move elements between the
 * tree and the delta instead of replaying the document (docs/editing.md, "Undo and redo").
 *
 * Side 0 is the tree before the op (state k - 1), side 1 after it (state k). Each side
 * lists, by index, its elements the other side does not share: those the op removed
 * (before) or added (after), and those it changed, listed on both sides. Every other
 * element is shared: the same arrays and fields but for its id and its parent's (or a
 * leaf's branch's) id, which removals renumber. Elements that are on both sides
 * (shared or changed: `kept`) correspond in order, the i-th to the i-th.
 *
 * The delta holds the listed elements of the side the tree is not at (`stored`): the
 * before side's while the op is done, the after side's once it is undone; the tree holds
 * the rest. tree_delta_swap moves the tree to the stored side and the delta to the other:
 * a copy of no point, a pass over the element structs (or only over the listed ones when
 * they are the last elements on both sides: appended, or the last branch redrawn).
 *
 * A side may also keep the meshes of its listed elements (PARTS, in list order) or of its
 * whole state (WHOLE), so that coming back meshes nothing: a cache, dropped first when
 * memory is short (history.c).
 *
 * What is not in a delta: the sketching state, the generator, sides, season, leaf kind,
 * lifted (the history's marks hold them, per state).
 */

enum tree_stash {
	TREE_STASH_NONE,
	TREE_STASH_PARTS, /* part s: the s-th listed branch / leaf of the side */
	TREE_STASH_WHOLE, /* the meshes of the side's whole tree */
};

struct tree_delta_side {
	size_t nbranches, nleaves, nvines; /* that state's counts */
	/* listed elements, by index ascending, and whether each is on the other side too */
	size_t *branch_at, *leaf_at;
	bool *branch_kept, *leaf_kept;
	size_t nb, nl;
	size_t vines_from; /* the side's vines from here on are its own (the rest shared) */
	/* held while the tree is at the other side: the listed elements as they are in this
	 * state (ids, parents and branches in its numbering), its own vines, its wood */
	struct branch *branches;
	struct leaf *leaves;
	struct vine *vines;
	struct wood *wood;
	/* meshes of this state (a cache) */
	enum tree_stash stash;
	struct tree_mesh mesh;
	struct tree_mesh_marks mk;
};

struct tree_delta {
	struct tree_delta_side side[2];
	bool wood; /* the two sides' woods differ (then each side has its own, or none) */
	int stored; /* the side whose listed elements the delta holds */
};

void tree_delta_init(struct tree_delta *d);
void tree_delta_finish(struct tree_delta *d);
/* Memory the delta holds: lists, stored elements, stashed meshes (the stash's alone in
 * *stash_bytes if given). */
size_t tree_delta_bytes(const struct tree_delta *d, size_t *stash_bytes);
void tree_delta_drop_stash(struct tree_delta_side *s);
/* Whether the op only appended elements (and vines): nothing before it is listed. */
bool tree_delta_appended_only(const struct tree_delta *d);

/*
 * Journals: while t has one, the editing functions of tree.c and tree_edit.c never free
 * or change in place what an element had when it began: an element removed is handed to
 * the journal, one about to change is kept there as it was (the tree goes on with
 * copies). Other code that changes elements in place (lifting, arrangement, growing
 * wood) must not run under a journal: tree_delta_diff records those.
 *
 * tree_journal_begin: 0 or -ENOMEM (then no journal). Out of memory later the journal
 * only gives up (the edit goes on as without one) and tree_journal_end says -ENOMEM.
 * A copy of the tree's struct (a view) does not share its journal.
 */
int tree_journal_begin(struct tree *t);
/* Ends t's journal: d (initialised) becomes the op's delta, the before side stored.
 * 0, or -ENOMEM (d left empty). */
int tree_journal_end(struct tree *t, struct tree_delta *d);
/* tree_journal_discard(t) (tree_journal.h) ends t's journal without a delta (the op
 * failed; the tree is rebuilt anyway). */

/* The hooks tree.c and tree_edit.c call (tree_journal.h; no-ops without a journal):
 * - branch, leaf (i, keep): branch or leaf i is about to be removed (its arrays are then
 *   NULL: nothing to free) or, if keep, changed (it gets copies of its arrays). 0, or
 *   -ENOMEM when keep and the copies could not be made (the tree is as it was).
 * - branches_moved, leaves_moved (map, nold): branches (leaves) were compacted: old index
 *   i < nold is now map[i], or gone if -1.
 * - clear: the tree is about to clear (every element, vine and the wood go); truncate
 *   (nb, nl): to be truncated to nb branches and nl leaves.
 * - keep_cut (b, cut_t): branch b is about to be cut at cut_t: it, and the leaves and
 *   children on it that stay (their parameters rescaled), are kept as they were. 0 or
 *   -ENOMEM (tree as it was).
 * - fail: something went without the journal seeing it (no memory): it gives up.
 * - take_wood (tree_journal_wood): whether the journal takes t's wood instead of freeing
 *   it (tree_wood_drop).
 */

/* An op that changed elements in place: before (a tree_copy of the state before it,
 * consumed: what t shares with it is freed) against t after it. Elements correspond by
 * index. d (initialised) becomes the op's delta, the before side stored. 0 or -ENOMEM
 * (d left empty; before freed). */
int tree_delta_diff(struct tree_delta *d, struct tree *before, const struct tree *t);

/* An op that appended t's branches from nb, leaves from nl (nothing else): d
 * (initialised) describes it with the after side stored, t cut back to before it.
 * (Undoing an append the history did not keep a delta of.) 0 or -ENOMEM (t unchanged). */
int tree_delta_take_appended(struct tree_delta *d, struct tree *t, size_t nb, size_t nl);

/*
 * Moves t (at the side not stored) to the stored side. branch_from and leaf_from (room for
 * the stored side's counts) get, for each element of t afterwards, the index it had
 * before if it is shared (unchanged), or -1. 0, -ENOMEM or -EINVAL (t is not at the
 * other side's counts); t and d unchanged on failure.
 */
int tree_delta_swap(struct tree_delta *d, struct tree *t, int *branch_from, int *leaf_from);
/* For the elements of side `to` (not stored: the tree's), the index on the other side of
 * each shared one, or -1, as tree_delta_swap gives them. */
void tree_delta_map(const struct tree_delta *d, int to, int *branch_from, int *leaf_from);
