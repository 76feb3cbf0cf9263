/* SPDX-License-Identifier: MIT */
#pragma once

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "rng.h"
#include "tree.h"

/*
 * What the app knows of the states along its document's history (state k: ops[0..k)
 * applied to an empty canvas), so that undo and redo reach the next state without
 * replaying the whole document (see "Undo" in docs/ARCHITECTURE.md):
 *
 * - A mark for each state it has been through: its element counts, its sketching state,
 *   the generator's state, and whether the op into it only appended elements. Undoing
 *   such an op is cutting the tree back to the previous mark's counts (tree_truncate) and
 *   putting back that mark's state.
 * - Checkpoints: exact copies of the tree and generator at some states, taken going
 *   forward: at every HISTORY_SPACING-th state less than HISTORY_NEAR below the cursor,
 *   two at each doubling of that distance (so a replay towards the cursor, --load,
 *   copies the tree O(log n) times), and after an op slow to apply (lift, propagate).
 *   Undoing any other op replays from the nearest checkpoint below, and leaves spacing
 *   checkpoints behind it for the next undo.
 *
 * Memory: marks take sizeof(struct history_mark) (about 200 bytes) a state, at most
 * DOC_MAX_OPS + 1 of them. Checkpoints take at most `budget` (HISTORY_BUDGET_BYTES, by
 * tree_bytes of their trees), except that the two nearest the cursor are always kept:
 * the bound is HISTORY_BUDGET_BYTES or two copies of the largest tree, whichever is
 * more. Over it, checkpoints thin out away from the cursor (evict() in history.c).
 */
#define HISTORY_SPACING 16
#define HISTORY_NEAR (8 * HISTORY_SPACING)
#define HISTORY_BUDGET_BYTES (64u << 20)

struct history_mark {
	bool known;
	bool grew; /* the op into this state only appended elements (the mesh did too) */
	size_t nbranches, nleaves;
	struct rng rng;
	/* the tree's sketching state (struct tree) */
	bool lifted;
	int sides;
	enum season season;
	int leaf_kind;
	int last_sketched;
	uint64_t last_sketched_end_us;
	bool has_profile;
	double profile[TREE_PROFILE_N];
};

struct history_checkpoint {
	size_t at; /* state */
	struct tree tree;
	struct rng rng;
	size_t bytes;
};

struct history {
	struct history_mark *marks; /* marks[k] for state k < nmarks */
	size_t nmarks, cap_marks;
	struct history_checkpoint *cps; /* by state */
	size_t ncps, cap_cps;
	size_t bytes;  /* of the checkpoints */
	size_t budget; /* HISTORY_BUDGET_BYTES (tests make it small) */
};

void history_init(struct history *h);
void history_finish(struct history *h);
/* Forgets the states after k: the document changed from op k on. */
void history_forget_after(struct history *h, size_t k);
/* Forgets everything (another document). */
void history_clear(struct history *h);
/* State k is t with rng; the op into it (slow: a lift or a propagation) only appended
 * elements if grew. Records its mark, and a checkpoint if one is due. cursor is the
 * document's: the checkpoints farthest from it go first. Without memory it remembers
 * less, which only makes undo slower. */
void history_record(struct history *h, size_t k, const struct tree *t, const struct rng *rng,
		    bool grew, bool slow, size_t cursor);
/* State k's mark, or NULL if not known. */
const struct history_mark *history_mark(const struct history *h, size_t k);
/* Gives t (state k + 1, cut back by tree_truncate to m's counts) and rng mark m's state. */
void history_mark_restore(const struct history_mark *m, struct tree *t, struct rng *rng);
/* The checkpoint at the highest state <= k, or NULL. */
const struct history_checkpoint *history_checkpoint_below(const struct history *h, size_t k);
