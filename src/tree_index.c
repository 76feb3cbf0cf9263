/* SPDX-License-Identifier: MIT */
#include "tree_index.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define NONE UINT32_MAX
/* Cells this far from the origin (27,000 km) and segments whose bounding box covers more
 * cells than this go to the list scanned at every query: the grid stays small whatever a
 * file holds. */
#define MAX_CELL (1 << 28)
#define MAX_SPAN_CELLS 64
/* Rounding in cells and distances is far below this (metres). */
#define MARGIN_M 1e-6

struct entry {
	uint32_t slot; /* the branch, as the grid numbers it */
	uint32_t segment;
	uint32_t next; /* the next entry of the same cell, or NONE */
};

struct cell {
	int32_t x, y;
	uint32_t head; /* NONE: this place of the table is free */
};

struct tree_index {
	const struct tree *owner;
	bool stale;      /* rebuilt at the next query */
	size_t nindexed; /* the owner's branches [0..nindexed) are in it */
	/* The grid's numbers of branches (slots), so that a removal renumbers only these. */
	int *slot_id;    /* current branch id, -1 once removed */
	size_t *slot_n;  /* entries of each slot */
	size_t nslots, cap_slots;
	size_t nlive;    /* entries of slots not removed */
	struct entry *entries;
	size_t nentries, cap_entries;
	struct cell *cells; /* open addressing, linear probing, a power of 2 of them */
	size_t ncells, cap_cells;
	struct entry *wide; /* segments not in the grid, scanned at every query */
	size_t nwide, cap_wide;
	int32_t x0, y0, x1, y1; /* bounds of the cells in use, when ncells > 0 */
};

static int grow(void **array, size_t *cap, size_t n, size_t size)
{
	size_t ncap;
	void *p;

	if (n < *cap)
		return 0;
	ncap = *cap ? *cap * 2 : 64;
	p = realloc(*array, ncap * size);
	if (!p)
		return -1;
	*array = p;
	*cap = ncap;
	return 0;
}

static bool cell_of(double v, int32_t *c)
{
	double f = floor(v * (1.0 / TREE_INDEX_CELL_M));

	if (!(fabs(f) < MAX_CELL))
		return false; /* also NaN */
	*c = (int32_t)f;
	return true;
}

static size_t cell_hash(int32_t x, int32_t y, size_t cap)
{
	uint64_t k = ((uint64_t)(uint32_t)x << 32) | (uint32_t)y;

	k ^= k >> 33;
	k *= 0xff51afd7ed558ccdULL;
	k ^= k >> 33;
	return (size_t)k & (cap - 1);
}

static struct cell *cell_find(const struct tree_index *idx, int32_t x, int32_t y)
{
	size_t i;

	if (idx->ncells == 0)
		return NULL;
	for (i = cell_hash(x, y, idx->cap_cells);; i = (i + 1) & (idx->cap_cells - 1)) {
		struct cell *c = &idx->cells[i];

		if (c->head == NONE)
			return NULL;
		if (c->x == x && c->y == y)
			return c;
	}
}

static void cells_clear(struct cell *cells, size_t n)
{
	for (size_t i = 0; i < n; i++)
		cells[i].head = NONE;
}

/* The cell (x, y), added empty if new (head NONE but taken); NULL without memory. */
static struct cell *cell_get(struct tree_index *idx, int32_t x, int32_t y)
{
	struct cell *c = cell_find(idx, x, y);
	size_t i;

	if (c)
		return c;
	if ((idx->ncells + 1) * 2 > idx->cap_cells) {
		size_t cap = idx->cap_cells ? idx->cap_cells * 2 : 256;
		struct cell *n = malloc(cap * sizeof(*n));

		if (!n)
			return NULL;
		cells_clear(n, cap);
		for (size_t k = 0; k < idx->cap_cells; k++) {
			const struct cell *o = &idx->cells[k];

			if (o->head == NONE)
				continue;
			for (i = cell_hash(o->x, o->y, cap); n[i].head != NONE; i = (i + 1) & (cap - 1))
				;
			n[i] = *o;
		}
		free(idx->cells);
		idx->cells = n;
		idx->cap_cells = cap;
	}
	for (i = cell_hash(x, y, idx->cap_cells); idx->cells[i].head != NONE;
	     i = (i + 1) & (idx->cap_cells - 1))
		;
	c = &idx->cells[i];
	c->x = x;
	c->y = y;
	if (idx->ncells == 0) {
		idx->x0 = idx->x1 = x;
		idx->y0 = idx->y1 = y;
	}
	idx->x0 = x < idx->x0 ? x : idx->x0;
	idx->x1 = x > idx->x1 ? x : idx->x1;
	idx->y0 = y < idx->y0 ? y : idx->y0;
	idx->y1 = y > idx->y1 ? y : idx->y1;
	idx->ncells++;
	return c;
}

static int add_wide(struct tree_index *idx, uint32_t slot, uint32_t segment)
{
	if (grow((void **)&idx->wide, &idx->cap_wide, idx->nwide, sizeof(*idx->wide)) < 0)
		return -1;
	idx->wide[idx->nwide++] = (struct entry){ slot, segment, NONE };
	idx->slot_n[slot]++;
	return 0;
}

static int add_segment(struct tree_index *idx, uint32_t slot, uint32_t segment, struct vec3 a,
		       struct vec3 b)
{
	int32_t x0, y0, x1, y1;

	if (!cell_of(fmin(a.x, b.x), &x0) || !cell_of(fmax(a.x, b.x), &x1) ||
	    !cell_of(fmin(a.y, b.y), &y0) || !cell_of(fmax(a.y, b.y), &y1) ||
	    (int64_t)(x1 - x0 + 1) * (y1 - y0 + 1) > MAX_SPAN_CELLS)
		return add_wide(idx, slot, segment);
	for (int32_t y = y0; y <= y1; y++)
		for (int32_t x = x0; x <= x1; x++) {
			struct cell *c;

			if (idx->nentries >= NONE - 1 ||
			    grow((void **)&idx->entries, &idx->cap_entries, idx->nentries,
				 sizeof(*idx->entries)) < 0)
				return -1;
			c = cell_get(idx, x, y);
			if (!c)
				return -1;
			idx->entries[idx->nentries] = (struct entry){ slot, segment, c->head };
			c->head = (uint32_t)idx->nentries++;
			idx->slot_n[slot]++;
		}
	return 0;
}

static int add_branch(struct tree_index *idx, const struct tree *t, size_t id)
{
	const struct branch *b = &t->branches[id];
	uint32_t slot;

	if (idx->nslots >= NONE - 1)
		return -1;
	if (idx->nslots == idx->cap_slots) {
		size_t cap = idx->cap_slots ? idx->cap_slots * 2 : 64;
		int *id_of = realloc(idx->slot_id, cap * sizeof(*id_of));
		size_t *n;

		if (!id_of)
			return -1;
		idx->slot_id = id_of;
		n = realloc(idx->slot_n, cap * sizeof(*n));
		if (!n)
			return -1; /* slot_id is larger than needed: harmless */
		idx->slot_n = n;
		idx->cap_slots = cap;
	}
	slot = (uint32_t)idx->nslots++;
	idx->slot_id[slot] = (int)id;
	idx->slot_n[slot] = 0;
	for (size_t i = 0; i + 1 < b->npoints; i++)
		if (add_segment(idx, slot, (uint32_t)i, b->points[i], b->points[i + 1]) < 0)
			return -1;
	idx->nlive += idx->slot_n[slot];
	return 0;
}

static void reset(struct tree_index *idx)
{
	cells_clear(idx->cells, idx->cap_cells);
	idx->ncells = 0;
	idx->nentries = 0;
	idx->nwide = 0;
	idx->nslots = 0;
	idx->nlive = 0;
	idx->nindexed = 0;
	idx->stale = false;
}

/* Adds the branches appended since the last query, or starts again when much of what
 * it holds is gone. 0, or -1 without memory (then stale). */
static int update(struct tree_index *idx, const struct tree *t)
{
	if (idx->stale || idx->nentries + idx->nwide > 2 * idx->nlive + 1024 ||
	    idx->nslots > 2 * t->nbranches + 256 || idx->nindexed > t->nbranches)
		reset(idx);
	for (; idx->nindexed < t->nbranches; idx->nindexed++)
		if (add_branch(idx, t, idx->nindexed) < 0) {
			idx->stale = true;
			return -1;
		}
	return 0;
}

void tree_index_keep(struct tree *t)
{
	struct tree_index *idx;

	if (t->index && t->index->owner == t)
		return;
	idx = calloc(1, sizeof(*idx));
	t->index = idx; /* a copy's pointer is not ours to free */
	if (!idx)
		return;
	idx->owner = t;
	idx->stale = true;
}

void tree_index_destroy(struct tree *t)
{
	struct tree_index *idx = t->index;

	t->index = NULL;
	if (!idx || idx->owner != t)
		return;
	free(idx->slot_id);
	free(idx->slot_n);
	free(idx->entries);
	free(idx->cells);
	free(idx->wide);
	free(idx);
}

static struct tree_index *owned(const struct tree *t)
{
	return t->index && t->index->owner == t ? t->index : NULL;
}

void tree_index_drop(struct tree *t)
{
	if (owned(t))
		t->index->stale = true;
}

static void slot_gone(struct tree_index *idx, size_t s)
{
	idx->slot_id[s] = -1;
	idx->nlive -= idx->slot_n[s];
}

void tree_index_renumbered(struct tree *t, const int *map, size_t nold)
{
	struct tree_index *idx = owned(t);
	size_t kept = 0;

	if (!idx || idx->stale)
		return;
	for (size_t s = 0; s < idx->nslots; s++) {
		int id = idx->slot_id[s];

		if (id < 0)
			continue;
		if ((size_t)id >= nold || map[id] < 0)
			slot_gone(idx, s);
		else
			idx->slot_id[s] = map[id];
	}
	/* survivors keep their order: those indexed are the first ones */
	for (size_t i = 0; i < idx->nindexed && i < nold; i++)
		kept += map[i] >= 0;
	idx->nindexed = kept;
}

void tree_index_truncated(struct tree *t, size_t nb)
{
	struct tree_index *idx = owned(t);

	if (!idx || idx->stale)
		return;
	for (size_t s = 0; s < idx->nslots; s++)
		if (idx->slot_id[s] >= 0 && (size_t)idx->slot_id[s] >= nb)
			slot_gone(idx, s);
	if (idx->nindexed > nb)
		idx->nindexed = nb;
}

/* Takes entry e if it is nearer than the best so far, or as near and first in order. */
static void consider(const struct tree_index *idx, const struct tree *t, const struct entry *e,
		     struct vec3 p, struct tree_index_hit *best)
{
	int id = idx->slot_id[e->slot];
	const struct branch *b;
	double s, d2;

	if (id < 0 || (size_t)id >= t->nbranches)
		return;
	b = &t->branches[id];
	if ((size_t)e->segment + 1 >= b->npoints)
		return; /* a cut shortened the branch */
	d2 = tree_segment_d2(b->points[e->segment], b->points[e->segment + 1], p, &s);
	if (!(d2 < INFINITY))
		return; /* the scan never takes these either */
	if (d2 < best->d2 || (d2 == best->d2 && (id < best->branch ||
						 (id == best->branch && e->segment < best->segment)))) {
		best->branch = id;
		best->segment = e->segment;
		best->seg_t = s;
		best->d2 = d2;
	}
}

static void visit(const struct tree_index *idx, const struct tree *t, int32_t x, int32_t y,
		  struct vec3 p, struct tree_index_hit *best)
{
	const struct cell *c = cell_find(idx, x, y);

	for (uint32_t e = c ? c->head : NONE; e != NONE; e = idx->entries[e].next)
		consider(idx, t, &idx->entries[e], p, best);
}

/* Whether cells r rings out (Chebyshev distance from p's cell) may hold a segment as
 * near as the best: their points are at least (r - 1) cells away from p. */
static bool may_hold(int64_t r, const struct tree_index_hit *best)
{
	return r < 2 || !(best->d2 < INFINITY) ||
	       (double)(r - 1) * TREE_INDEX_CELL_M <= sqrt(best->d2) + MARGIN_M;
}

static int64_t max64(int64_t a, int64_t b)
{
	return a > b ? a : b;
}

static int64_t min64(int64_t a, int64_t b)
{
	return a < b ? a : b;
}

/* The cells of ring r around (cx, cy) inside the bounds: how many, and visits them. */
static int64_t ring(const struct tree_index *idx, const struct tree *t, int64_t cx, int64_t cy,
		    int64_t r, struct vec3 p, struct tree_index_hit *best, bool go)
{
	int64_t xa = max64(cx - r, idx->x0), xb = min64(cx + r, idx->x1);
	int64_t ya = max64(cy - r + 1, idx->y0), yb = min64(cy + r - 1, idx->y1);
	int64_t n = 0;

	if (r == 0) {
		if (go)
			visit(idx, t, (int32_t)cx, (int32_t)cy, p, best);
		return 1;
	}
	/* the rows at cy - r and cy + r, then the columns at cx - r and cx + r between */
	for (int64_t y = cy - r; y <= cy + r; y += 2 * r) {
		if (y < idx->y0 || y > idx->y1 || xa > xb)
			continue;
		n += xb - xa + 1;
		for (int64_t x = xa; go && x <= xb; x++)
			visit(idx, t, (int32_t)x, (int32_t)y, p, best);
	}
	for (int64_t x = cx - r; x <= cx + r; x += 2 * r) {
		if (x < idx->x0 || x > idx->x1 || ya > yb)
			continue;
		n += yb - ya + 1;
		for (int64_t y = ya; go && y <= yb; y++)
			visit(idx, t, (int32_t)x, (int32_t)y, p, best);
	}
	return n;
}

static void query(const struct tree_index *idx, const struct tree *t, int32_t cx32, int32_t cy32,
		  struct vec3 p, struct tree_index_hit *best)
{
	int64_t cx = cx32, cy = cy32, probes = 0;
	/* rings nearer than the cells in use are empty; past the farthest, nothing is left */
	int64_t r = max64(max64(idx->x0 - cx, cx - idx->x1), max64(idx->y0 - cy, cy - idx->y1));
	int64_t last = max64(max64(cx - idx->x0, idx->x1 - cx), max64(cy - idx->y0, idx->y1 - cy));

	for (r = max64(r, 0); r <= last && may_hold(r, best); r++) {
		int64_t n = ring(idx, t, cx, cy, r, p, best, false);

		if (probes + n > (int64_t)idx->cap_cells) {
			/* far out, looking cell by cell costs more than going through them all */
			for (size_t i = 0; i < idx->cap_cells; i++) {
				const struct cell *c = &idx->cells[i];
				int64_t d = max64(llabs(c->x - cx), llabs(c->y - cy));

				if (c->head == NONE || d < r || !may_hold(d, best))
					continue;
				for (uint32_t e = c->head; e != NONE; e = idx->entries[e].next)
					consider(idx, t, &idx->entries[e], p, best);
			}
			return;
		}
		probes += n;
		ring(idx, t, cx, cy, r, p, best, true);
	}
}

bool tree_index_nearest(const struct tree *t, struct vec3 p, struct tree_index_hit *hit)
{
	struct tree_index *idx = t->index;
	int32_t cx, cy;

	if (!idx || idx->owner != t || !cell_of(p.x, &cx) || !cell_of(p.y, &cy))
		return false;
	if (update(idx, t) < 0 || idx->nlive < TREE_INDEX_MIN_SEGMENTS)
		return false;
	*hit = (struct tree_index_hit){ .branch = -1, .d2 = INFINITY };
	for (size_t i = 0; i < idx->nwide; i++)
		consider(idx, t, &idx->wide[i], p, hit);
	if (idx->ncells > 0)
		query(idx, t, cx, cy, p, hit);
	return true;
}
