/* SPDX-License-Identifier: MIT */
#pragma once

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "rng.h"
#include "tree.h"

struct tree_delta;

/*
 * What the app knows of the states along its document's history (state k: ops[0..k)
 * applied to an empty canvas), so that undo and redo reach the next state without
 * replaying the document (docs/editing.md, "Undo and redo"):
 *
 * - A mark for each state it has been through: its element counts, its sketching state,
 *   the generator's state, and whether the op into it only appended elements.
 * - A delta for each op that did more than append (tree_delta.h): the elements it took
 *   out or changed, kept while the op is done; once it is undone, those it put in. An op
 *   that only appended has one once undone. Undo and redo move elements between the
 *   tree and the delta, and the meshes of those elements with them (the delta's stash).
 * - Checkpoints: exact copies of the tree and generator, taken only while replaying
 *   (--load, or an undo whose delta memory did not allow): at every HISTORY_SPACING-th
 *   state less than HISTORY_NEAR below the cursor and two at each doubling of that
 *   distance. Undoing an op whose delta is gone replays from the nearest one below.
 *
 * Memory: marks take sizeof(struct history_mark) (about 200 bytes) a state, at most
 * DOC_MAX_OPS + 1 of them. Deltas and checkpoints together take at most `budget`
 * (HISTORY_BUDGET_BYTES, counted by tree_delta_bytes and tree_bytes), except that the
 * deltas of the ops next to the cursor (the next undo's and the next redo's) and the two
 * checkpoints nearest it are always kept. Over it, checkpoints go first (thinned out away
 * from the cursor), then the deltas' stashed meshes (they can be built again: small ones
 * first, then large, farthest from the cursor first), then deltas farthest from the
 * cursor (their ops then undo and redo by replaying).
 */
#define HISTORY_SPACING 16
#define HISTORY_NEAR (8 * HISTORY_SPACING)
#define HISTORY_BUDGET_BYTES (96u << 20)
/* A stash of at most this many parts is built again within a few milliseconds (about
 * 5 us a part here): such stashes go before larger ones. */
#define HISTORY_CHEAP_PARTS 256

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

/* What the latest undo or redo cost, in work that does not depend on the machine (tests
 * bound it; bench_rebuild prints times). */
struct history_work {
	size_t replayed; /* ops applied */
	size_t meshed;   /* parts of the meshes built (branches and leaves) */
	size_t moved;    /* elements moved between the tree and a delta */
	bool full_mesh;  /* the meshes were built whole */
};

struct history {
	struct history_mark *marks; /* marks[k] for state k < nmarks */
	size_t nmarks, cap_marks;
	struct history_checkpoint *cps; /* by state */
	size_t ncps, cap_cps;
	struct tree_delta **deltas; /* deltas[k]: op k's (into state k), or NULL */
	size_t *delta_bytes;        /* what each takes (tree_delta_bytes) */
	size_t cap_deltas;
	size_t bytes;  /* of the checkpoints and deltas */
	size_t budget; /* HISTORY_BUDGET_BYTES (tests make it small) */
	struct history_work work;
};

void history_init(struct history *h);
void history_finish(struct history *h);
/* Forgets the states after k: the document changed from op k on. */
void history_forget_after(struct history *h, size_t k);
/* Forgets everything (another document). */
void history_clear(struct history *h);
/* State k is t with rng; the op into it only appended elements if grew. Records its
 * mark, and while replaying a checkpoint if one is due. cursor is the document's: what
 * is farthest from it goes first. Without memory it remembers less, which only makes
 * undo slower. */
void history_record(struct history *h, size_t k, const struct tree *t, const struct rng *rng,
		    bool grew, bool replaying, size_t cursor);
/* Op k's delta, or NULL. */
struct tree_delta *history_delta(const struct history *h, size_t k);
/* Keeps *d (moved in; *d is left empty) as op k's delta, dropping the one it had. 0, or
 * -ENOMEM (d dropped: op k undoes by replaying). */
int history_delta_put(struct history *h, size_t k, struct tree_delta *d, size_t cursor);
/* Op k's delta changed (it was swapped, or stashed meshes): its memory is counted again. */
void history_delta_changed(struct history *h, size_t k, size_t cursor);
void history_delta_drop(struct history *h, size_t k);
/* Drops the deltas that do not fit the tree being at state cursor (a quick path failed
 * half-way and the tree was rebuilt): op k's must hold its before side if k <= cursor,
 * its after side if not. */
void history_deltas_fit(struct history *h, size_t cursor);
/* State k's mark, or NULL if not known. */
const struct history_mark *history_mark(const struct history *h, size_t k);
/* Gives t (state k + 1, cut back by tree_truncate to m's counts) and rng mark m's state. */
void history_mark_restore(const struct history_mark *m, struct tree *t, struct rng *rng);
/* The checkpoint at the highest state <= k, or NULL. */
const struct history_checkpoint *history_checkpoint_below(const struct history *h, size_t k);
