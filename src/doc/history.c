/* SPDX-License-Identifier: MIT */
#include "history.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "tree_delta.h"

void history_init(struct history *h)
{
	memset(h, 0, sizeof(*h));
	h->budget = HISTORY_BUDGET_BYTES;
}

static void checkpoint_drop(struct history *h, size_t i)
{
	h->bytes -= h->cps[i].bytes;
	tree_finish(&h->cps[i].tree);
	memmove(&h->cps[i], &h->cps[i + 1], (h->ncps - i - 1) * sizeof(*h->cps));
	h->ncps--;
}

void history_delta_drop(struct history *h, size_t k)
{
	if (k >= h->cap_deltas || !h->deltas[k])
		return;
	h->bytes -= h->delta_bytes[k];
	tree_delta_finish(h->deltas[k]);
	free(h->deltas[k]);
	h->deltas[k] = NULL;
	h->delta_bytes[k] = 0;
}

void history_forget_after(struct history *h, size_t k)
{
	if (h->nmarks > k + 1)
		h->nmarks = k + 1;
	while (h->ncps > 0 && h->cps[h->ncps - 1].at > k)
		checkpoint_drop(h, h->ncps - 1);
	for (size_t i = k + 1; i < h->cap_deltas; i++)
		history_delta_drop(h, i);
}

void history_clear(struct history *h)
{
	history_forget_after(h, 0);
	h->nmarks = 0;
	while (h->ncps > 0)
		checkpoint_drop(h, h->ncps - 1);
	history_delta_drop(h, 0);
}

void history_finish(struct history *h)
{
	history_clear(h);
	free(h->marks);
	free(h->cps);
	free(h->deltas);
	free(h->delta_bytes);
	history_init(h);
}

static void record_mark(struct history *h, size_t k, const struct tree *t, const struct rng *rng,
			bool grew)
{
	struct history_mark *m;

	if (k >= h->cap_marks) {
		size_t cap = h->cap_marks ? h->cap_marks : 64;
		struct history_mark *p;

		while (cap <= k)
			cap *= 2;
		p = realloc(h->marks, cap * sizeof(*p));
		if (!p)
			return;
		h->marks = p;
		h->cap_marks = cap;
	}
	for (; h->nmarks <= k; h->nmarks++)
		h->marks[h->nmarks].known = false;
	m = &h->marks[k];
	*m = (struct history_mark){
		.known = true,
		.grew = grew,
		.nbranches = t->nbranches,
		.nleaves = t->nleaves,
		.rng = *rng,
		.lifted = t->lifted,
		.sides = t->sides,
		.season = t->season,
		.leaf_kind = t->leaf_kind,
		.last_sketched = t->last_sketched,
		.last_sketched_end_us = t->last_sketched_end_us,
		.has_profile = t->has_profile,
	};
	memcpy(m->profile, t->profile, sizeof(m->profile));
}

static size_t distance(size_t a, size_t b)
{
	return a > b ? a - b : b - a;
}

/* The checkpoint whose going leaves the smallest gap for how far it is from the
 * cursor: far from it they thin out, so that a long walk back replays about as many ops
 * as it has come (logarithmic spacing). The two nearest the cursor stay: -1 then. */
static long checkpoint_victim(const struct history *h, size_t cursor)
{
	size_t near[2] = { 0, 1 }, victim = SIZE_MAX;
	double best = 0.0;

	if (h->ncps <= 2)
		return -1;
	for (size_t i = 0; i < h->ncps; i++) {
		size_t d = distance(h->cps[i].at, cursor);

		if (i < 2)
			continue;
		if (d < distance(h->cps[near[0]].at, cursor)) {
			near[1] = near[0];
			near[0] = i;
		} else if (d < distance(h->cps[near[1]].at, cursor)) {
			near[1] = i;
		}
	}
	if (distance(h->cps[near[1]].at, cursor) < distance(h->cps[near[0]].at, cursor)) {
		size_t x = near[0];

		near[0] = near[1];
		near[1] = x;
	}
	for (size_t i = 0; i < h->ncps; i++) {
		size_t prev = i > 0 ? h->cps[i - 1].at : 0;
		size_t next = i + 1 < h->ncps ? h->cps[i + 1].at : h->cps[i].at;
		double score = (double)(next - prev) / (double)(distance(h->cps[i].at, cursor) + 1);

		if (i == near[0] || i == near[1])
			continue;
		if (victim == SIZE_MAX || score < best) {
			victim = i;
			best = score;
		}
	}
	return (long)victim;
}

/* Parts a delta's stash holds: what a press would build without it. */
static size_t stashed_parts(const struct tree_delta *d)
{
	size_t n = 0;

	for (int s = 0; s < 2; s++) {
		const struct tree_delta_side *side = &d->side[s];

		if (side->stash == TREE_STASH_WHOLE)
			n += side->nbranches + side->nleaves;
		else if (side->stash == TREE_STASH_PARTS)
			n += side->nb + side->nl;
	}
	return n;
}

/* The delta farthest from the cursor, but for those of the next undo and the next redo:
 * with a stash of at most `parts` parts if stashed (0: any), or any. -1 if none. */
static long delta_victim(const struct history *h, size_t cursor, bool stashed, size_t parts)
{
	long victim = -1;
	size_t far = 0;

	for (size_t k = 0; k < h->cap_deltas; k++) {
		const struct tree_delta *d = h->deltas[k];
		size_t dist = distance(k, cursor), n;

		if (!d || k == cursor || k == cursor + 1 || dist < far)
			continue;
		n = stashed ? stashed_parts(d) : 0;
		if (stashed && (n == 0 || (parts && n > parts)))
			continue;
		victim = (long)k;
		far = dist;
	}
	return victim;
}

static void delta_count(struct history *h, size_t k)
{
	h->bytes -= h->delta_bytes[k];
	h->delta_bytes[k] = tree_delta_bytes(h->deltas[k], NULL);
	h->bytes += h->delta_bytes[k];
}

/* Over the budget: checkpoints go first (only an op without a delta needs one), then
 * meshes stashed far from the cursor (they can be built again), then deltas. */
static void evict(struct history *h, size_t cursor)
{
	while (h->bytes > h->budget) {
		long k = checkpoint_victim(h, cursor);

		if (k >= 0) {
			checkpoint_drop(h, (size_t)k);
			continue;
		}
		/* stashes a press builds again quickly first, then any */
		k = delta_victim(h, cursor, true, HISTORY_CHEAP_PARTS);
		if (k < 0)
			k = delta_victim(h, cursor, true, 0);
		if (k >= 0) {
			tree_delta_drop_stash(&h->deltas[k]->side[0]);
			tree_delta_drop_stash(&h->deltas[k]->side[1]);
			delta_count(h, (size_t)k);
			continue;
		}
		k = delta_victim(h, cursor, false, 0);
		if (k < 0)
			return;
		history_delta_drop(h, (size_t)k);
	}
}

static void record_checkpoint(struct history *h, size_t k, const struct tree *t,
			      const struct rng *rng, size_t cursor)
{
	size_t i = h->ncps;
	struct history_checkpoint *cp;

	while (i > 0 && h->cps[i - 1].at >= k) {
		if (h->cps[i - 1].at == k)
			return; /* the same state, bit for bit */
		i--;
	}
	if (h->ncps == h->cap_cps) {
		size_t cap = h->cap_cps ? h->cap_cps * 2 : 16;
		struct history_checkpoint *p = realloc(h->cps, cap * sizeof(*p));

		if (!p)
			return;
		h->cps = p;
		h->cap_cps = cap;
	}
	memmove(&h->cps[i + 1], &h->cps[i], (h->ncps - i) * sizeof(*h->cps));
	cp = &h->cps[i];
	cp->at = k;
	cp->rng = *rng;
	tree_init(&cp->tree);
	h->ncps++;
	if (tree_copy(&cp->tree, t) < 0) {
		checkpoint_drop(h, i);
		return;
	}
	cp->bytes = tree_bytes(&cp->tree);
	h->bytes += cp->bytes;
	evict(h, cursor);
}

/* Which half doubling of HISTORY_NEAR distance d is in (-1 below it). */
static int band(size_t d)
{
	return d < HISTORY_NEAR ? -1 : (int)floor(2.0 * log2((double)d / HISTORY_NEAR));
}

/* Spacing checkpoints near the cursor, and two a doubling of the distance farther out:
 * a replay towards the cursor copies the tree O(log n) times. (Where checkpoints are
 * changes no result: each is an exact copy.) */
static bool due(size_t k, size_t cursor)
{
	size_t d = cursor > k ? cursor - k : 0;

	if (k == 0 || k % HISTORY_SPACING != 0)
		return false;
	return d < HISTORY_NEAR || band(d) != band(d - HISTORY_SPACING);
}

void history_record(struct history *h, size_t k, const struct tree *t, const struct rng *rng,
		    bool grew, bool replaying, size_t cursor)
{
	record_mark(h, k, t, rng, grew);
	if (replaying && due(k, cursor))
		record_checkpoint(h, k, t, rng, cursor);
}

struct tree_delta *history_delta(const struct history *h, size_t k)
{
	return k < h->cap_deltas ? h->deltas[k] : NULL;
}

int history_delta_put(struct history *h, size_t k, struct tree_delta *d, size_t cursor)
{
	struct tree_delta *p;

	history_delta_drop(h, k);
	if (k >= h->cap_deltas) {
		size_t cap = h->cap_deltas ? h->cap_deltas : 64;
		struct tree_delta **nd;
		size_t *nb;

		while (cap <= k)
			cap *= 2;
		nd = realloc(h->deltas, cap * sizeof(*nd));
		if (nd)
			h->deltas = nd;
		nb = nd ? realloc(h->delta_bytes, cap * sizeof(*nb)) : NULL;
		if (!nb) {
			tree_delta_finish(d);
			return -ENOMEM;
		}
		h->delta_bytes = nb;
		for (size_t i = h->cap_deltas; i < cap; i++) {
			h->deltas[i] = NULL;
			h->delta_bytes[i] = 0;
		}
		h->cap_deltas = cap;
	}
	p = malloc(sizeof(*p));
	if (!p) {
		tree_delta_finish(d);
		return -ENOMEM;
	}
	*p = *d;
	tree_delta_init(d);
	h->deltas[k] = p;
	h->delta_bytes[k] = 0;
	delta_count(h, k);
	evict(h, cursor);
	return 0;
}

void history_delta_changed(struct history *h, size_t k, size_t cursor)
{
	if (k >= h->cap_deltas || !h->deltas[k])
		return;
	delta_count(h, k);
	evict(h, cursor);
}

void history_deltas_fit(struct history *h, size_t cursor)
{
	for (size_t k = 1; k < h->cap_deltas; k++)
		if (h->deltas[k] && h->deltas[k]->stored != (k <= cursor ? 0 : 1))
			history_delta_drop(h, k);
}

const struct history_mark *history_mark(const struct history *h, size_t k)
{
	return k < h->nmarks && h->marks[k].known ? &h->marks[k] : NULL;
}

void history_mark_restore(const struct history_mark *m, struct tree *t, struct rng *rng)
{
	t->lifted = m->lifted;
	t->sides = m->sides;
	t->season = m->season;
	t->leaf_kind = m->leaf_kind;
	t->last_sketched = m->last_sketched;
	t->last_sketched_end_us = m->last_sketched_end_us;
	t->has_profile = m->has_profile;
	memcpy(t->profile, m->profile, sizeof(t->profile));
	*rng = m->rng;
}

const struct history_checkpoint *history_checkpoint_below(const struct history *h, size_t k)
{
	for (size_t i = h->ncps; i-- > 0;)
		if (h->cps[i].at <= k)
			return &h->cps[i];
	return NULL;
}
