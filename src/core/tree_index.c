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
/* Cells are TREE_INDEX_CELL_M wide and high, TREE_INDEX_DEPTH_M deep: a lifted tree is
 * as deep as it is wide, and the front view's line crosses every depth. */
static const double H[3] = { TREE_INDEX_CELL_M, TREE_INDEX_CELL_M, TREE_INDEX_DEPTH_M };

struct entry {
	uint32_t slot; /* the branch, as the grid numbers it */
	uint32_t segment;
	uint32_t next; /* the next entry of the same cell, or NONE */
};

struct cell {
	int32_t c[3];
	uint32_t head; /* NONE: this place of the table is free */
};

struct tree_index {
	const struct tree *owner;
	/* A view's copy (tree_index_keep_view) has no grid of its own: */
	const struct tree *world;
	const struct camera_xf *xf;
	void (*show)(void *ctx, int branch);
	void *ctx;

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
	int32_t lo[3], hi[3]; /* bounds of the cells in use, when ncells > 0 */
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

static bool cell_of(double v, int axis, int32_t *c)
{
	double f = floor(v / H[axis]);

	if (!(fabs(f) < MAX_CELL))
		return false; /* also NaN */
	*c = (int32_t)f;
	return true;
}

static double coord(struct vec3 v, int axis)
{
	return axis == 0 ? v.x : axis == 1 ? v.y : v.z;
}

static size_t cell_hash(const int32_t c[3], size_t cap)
{
	uint64_t k = (uint64_t)(uint32_t)c[0] * 0x9e3779b97f4a7c15ULL ^
		     (uint64_t)(uint32_t)c[1] * 0xc2b2ae3d27d4eb4fULL ^
		     (uint64_t)(uint32_t)c[2] * 0x165667b19e3779f9ULL;

	k ^= k >> 33;
	k *= 0xff51afd7ed558ccdULL;
	k ^= k >> 33;
	return (size_t)k & (cap - 1);
}

static bool same_cell(const int32_t a[3], const int32_t b[3])
{
	return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
}

static const struct cell *cell_find(const struct tree_index *idx, const int32_t c[3])
{
	if (idx->ncells == 0)
		return NULL;
	for (size_t i = cell_hash(c, idx->cap_cells);; i = (i + 1) & (idx->cap_cells - 1)) {
		const struct cell *e = &idx->cells[i];

		if (e->head == NONE)
			return NULL;
		if (same_cell(e->c, c))
			return e;
	}
}

static void cells_clear(struct cell *cells, size_t n)
{
	for (size_t i = 0; i < n; i++)
		cells[i].head = NONE;
}

static size_t free_place(const struct cell *cells, size_t cap, const int32_t c[3])
{
	size_t i;

	for (i = cell_hash(c, cap); cells[i].head != NONE; i = (i + 1) & (cap - 1))
		;
	return i;
}

/* Cell c's entry list (*head), the cell added if new; NULL without memory. */
static uint32_t *cell_get(struct tree_index *idx, const int32_t c[3])
{
	const struct cell *found = cell_find(idx, c);
	struct cell *e;

	if (found)
		return &idx->cells[found - idx->cells].head;
	if ((idx->ncells + 1) * 2 > idx->cap_cells) {
		size_t cap = idx->cap_cells ? idx->cap_cells * 2 : 256;
		struct cell *n = malloc(cap * sizeof(*n));

		if (!n)
			return NULL;
		cells_clear(n, cap);
		for (size_t k = 0; k < idx->cap_cells; k++)
			if (idx->cells[k].head != NONE)
				n[free_place(n, cap, idx->cells[k].c)] = idx->cells[k];
		free(idx->cells);
		idx->cells = n;
		idx->cap_cells = cap;
	}
	e = &idx->cells[free_place(idx->cells, idx->cap_cells, c)];
	memcpy(e->c, c, sizeof(e->c));
	for (int a = 0; a < 3; a++) {
		idx->lo[a] = idx->ncells == 0 || c[a] < idx->lo[a] ? c[a] : idx->lo[a];
		idx->hi[a] = idx->ncells == 0 || c[a] > idx->hi[a] ? c[a] : idx->hi[a];
	}
	idx->ncells++;
	return &e->head; /* NONE until the caller adds an entry */
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
	int32_t lo[3], hi[3], c[3];
	int64_t span = 1;

	for (int k = 0; k < 3; k++) {
		double u = coord(a, k), v = coord(b, k);

		if (!cell_of(fmin(u, v), k, &lo[k]) || !cell_of(fmax(u, v), k, &hi[k]))
			return add_wide(idx, slot, segment);
		span *= (int64_t)hi[k] - lo[k] + 1;
	}
	if (span > MAX_SPAN_CELLS)
		return add_wide(idx, slot, segment);
	for (c[2] = lo[2]; c[2] <= hi[2]; c[2]++)
		for (c[1] = lo[1]; c[1] <= hi[1]; c[1]++)
			for (c[0] = lo[0]; c[0] <= hi[0]; c[0]++) {
				uint32_t *head;

				if (idx->nentries >= NONE - 1 ||
				    grow((void **)&idx->entries, &idx->cap_entries, idx->nentries,
					 sizeof(*idx->entries)) < 0)
					return -1;
				head = cell_get(idx, c);
				if (!head)
					return -1;
				idx->entries[idx->nentries] = (struct entry){ slot, segment, *head };
				*head = (uint32_t)idx->nentries++;
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

	if (t->index && t->index->owner == t && !t->index->world)
		return;
	tree_index_destroy(t);
	idx = calloc(1, sizeof(*idx));
	t->index = idx;
	if (!idx)
		return;
	idx->owner = t;
	idx->stale = true;
}

bool tree_index_keep_view(struct tree *view, const struct tree *world, const struct camera_xf *xf,
			  void (*show)(void *ctx, int branch), void *ctx)
{
	struct tree_index *idx;

	tree_index_destroy(view);
	if (!world->index || world->index->owner != world || world->index->world)
		return false;
	idx = calloc(1, sizeof(*idx));
	view->index = idx;
	if (!idx)
		return false;
	idx->owner = view;
	idx->world = world;
	idx->xf = xf;
	idx->show = show;
	idx->ctx = ctx;
	return true;
}

static struct tree_index *owned(const struct tree *t)
{
	return t->index && t->index->owner == t ? t->index : NULL;
}

void tree_index_destroy(struct tree *t)
{
	struct tree_index *idx = owned(t);

	t->index = NULL; /* a copy's pointer is not ours to free */
	if (!idx)
		return;
	free(idx->slot_id);
	free(idx->slot_n);
	free(idx->entries);
	free(idx->cells);
	free(idx->wide);
	free(idx);
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

void tree_index_swapped(struct tree *a, struct tree *b)
{
	/* a grid is owned by the tree struct it belongs to: a copy's pointer is not ours */
	struct tree_index *ia = a->index && a->index->owner == b ? a->index : NULL;
	struct tree_index *ib = b->index && b->index->owner == a ? b->index : NULL;

	if (ia)
		ia->owner = a;
	if (ib)
		ib->owner = b;
}

void tree_index_replaced(struct tree *t, const int *map, size_t nold)
{
	struct tree_index *idx = owned(t);
	bool *have;
	size_t kept = 0;

	if (!idx || idx->stale)
		return;
	for (size_t i = 0; i < nold; i++)
		kept += map[i] >= 0;
	/* mostly new branches: a new grid at the next query costs no more */
	have = 2 * kept >= t->nbranches ? calloc(t->nbranches + 1, sizeof(*have)) : NULL;
	if (!have) {
		idx->stale = true;
		return;
	}
	for (size_t s = 0; s < idx->nslots; s++) {
		int id = idx->slot_id[s];

		if (id < 0)
			continue;
		if ((size_t)id >= nold || map[id] < 0) {
			slot_gone(idx, s);
			continue;
		}
		idx->slot_id[s] = map[id];
		have[map[id]] = true;
	}
	for (size_t j = 0; j < t->nbranches && !idx->stale; j++)
		if (!have[j] && add_branch(idx, t, j) < 0)
			idx->stale = true;
	idx->nindexed = t->nbranches;
	free(have);
}

static uint64_t points_key(const struct branch *b)
{
	uint64_t k = b->npoints * 0x9e3779b97f4a7c15ULL;

	if (b->npoints) {
		const struct vec3 *e[2] = { &b->points[0], &b->points[b->npoints - 1] };

		for (int i = 0; i < 2; i++) {
			uint64_t u[3];

			memcpy(u, e[i], sizeof(u));
			for (int j = 0; j < 3; j++) {
				k ^= u[j] + 0x9e3779b97f4a7c15ULL + (k << 6) + (k >> 2);
				k *= 0xff51afd7ed558ccdULL;
			}
		}
	}
	return k ^ (k >> 31);
}

/* For each of src's branches, dst's with the same points (each taken once), or -1. */
static int match_points(const struct tree *dst, const struct tree *src, int *map)
{
	size_t cap = 16;
	uint64_t *key;
	int *first, *next;

	while (cap < 2 * dst->nbranches)
		cap *= 2;
	key = malloc(cap * sizeof(*key));
	first = malloc(cap * sizeof(*first));
	next = malloc((dst->nbranches + 1) * sizeof(*next));
	if (!key || !first || !next) {
		free(key);
		free(first);
		free(next);
		return -1;
	}
	for (size_t i = 0; i < cap; i++)
		first[i] = -1;
	for (size_t j = dst->nbranches; j-- > 0;) {
		uint64_t k = points_key(&dst->branches[j]);
		size_t i = (size_t)k & (cap - 1);

		while (first[i] >= 0 && key[i] != k)
			i = (i + 1) & (cap - 1);
		key[i] = k;
		next[j] = first[i];
		first[i] = (int)j;
	}
	for (size_t s = 0; s < src->nbranches; s++) {
		const struct branch *b = &src->branches[s];
		uint64_t k = points_key(b);
		size_t i = (size_t)k & (cap - 1);

		map[s] = -1;
		while (first[i] >= 0 && key[i] != k)
			i = (i + 1) & (cap - 1);
		/* the first unused one with these points: the chain is in id order */
		for (int *j = &first[i]; *j >= 0; j = &next[*j]) {
			const struct branch *c = &dst->branches[*j];

			if (c->npoints == b->npoints &&
			    (b->npoints == 0 || memcmp(c->points, b->points, b->npoints * sizeof(*b->points)) == 0)) {
				map[s] = *j;
				*j = next[*j]; /* taken */
				break;
			}
		}
	}
	free(key);
	free(first);
	free(next);
	return 0;
}

void tree_index_move(struct tree *dst, struct tree *src)
{
	struct tree_index *idx = owned(src);
	bool *have;
	int *map;

	tree_index_destroy(dst);
	if (!idx || idx->world) {
		tree_index_keep(dst);
		return;
	}
	src->index = NULL;
	dst->index = idx;
	idx->owner = dst;
	if (idx->stale)
		return;
	map = malloc((src->nbranches + 1) * sizeof(*map));
	have = calloc(dst->nbranches + 1, sizeof(*have));
	if (!map || !have || match_points(dst, src, map) < 0) {
		idx->stale = true;
		free(map);
		free(have);
		return;
	}
	/* what the grid holds of src (its first nindexed branches) under dst's numbers */
	for (size_t s = 0; s < idx->nslots; s++) {
		int id = idx->slot_id[s];

		if (id < 0)
			continue;
		if ((size_t)id >= src->nbranches || map[id] < 0) {
			slot_gone(idx, s);
			continue;
		}
		idx->slot_id[s] = map[id];
		have[map[id]] = true;
	}
	for (size_t j = 0; j < dst->nbranches && !idx->stale; j++)
		if (!have[j] && add_branch(idx, dst, j) < 0)
			idx->stale = true;
	idx->nindexed = dst->nbranches;
	free(map);
	free(have);
}

/* A query: the screen point p, the line of world points shown there (through p0 along
 * dir), and what the tree looks like on the screen (xf, NULL for the front view). */
struct query {
	const struct tree_index *idx;
	const struct tree *t;
	const struct camera_xf *xf;
	/* a view's copy, whose points are shown on demand: what candidates are measured in */
	const struct tree *view;
	void (*show)(void *ctx, int branch);
	void *ctx;
	struct vec3 p, p0, dir;
	struct tree_index_hit best;
	size_t probes, budget;
};

/* Takes entry e if it is nearer than the best so far, or as near and first in order. */
static void consider(struct query *q, const struct entry *e)
{
	int id = q->idx->slot_id[e->slot];
	const struct branch *b;
	struct vec3 a, c;
	double s, d2;

	if (id < 0 || (size_t)id >= q->t->nbranches)
		return;
	b = &(q->view ? q->view : q->t)->branches[id];
	if ((size_t)e->segment + 1 >= b->npoints)
		return; /* a cut shortened the branch */
	if (!b->points)
		q->show(q->ctx, id); /* turned once, then read as the copy holds it */
	a = b->points[e->segment];
	c = b->points[e->segment + 1];
	d2 = tree_segment_d2(a, c, q->p, &s);
	if (!(d2 < INFINITY))
		return; /* the scan never takes these either */
	if (d2 < q->best.d2 || (d2 == q->best.d2 && (id < q->best.branch ||
						     (id == q->best.branch && e->segment < q->best.segment)))) {
		q->best.branch = id;
		q->best.segment = e->segment;
		q->best.seg_t = s;
		q->best.d2 = d2;
	}
}

static void visit(struct query *q, const int32_t c[3])
{
	const struct cell *cell = cell_find(q->idx, c);

	q->probes++;
	for (uint32_t e = cell ? cell->head : NONE; e != NONE; e = q->idx->entries[e].next)
		consider(q, &q->idx->entries[e]);
}

/* How far q's line passes from world point w. */
static double line_distance(const struct query *q, struct vec3 w)
{
	struct vec3 d = vec3_sub(w, q->p0);

	return vec3_len(vec3_sub(d, vec3_scale(q->dir, vec3_dot(d, q->dir))));
}

static double found(const struct query *q)
{
	return q->best.d2 < INFINITY ? sqrt(q->best.d2) : INFINITY;
}

/* Every cell in use that may hold a segment as near as the best: the way to go when
 * looking cell by cell would cost more. */
static void visit_all(struct query *q)
{
	const double half_diagonal = 0.5 * sqrt(H[0] * H[0] + H[1] * H[1] + H[2] * H[2]);

	for (size_t i = 0; i < q->idx->cap_cells; i++) {
		const struct cell *cell = &q->idx->cells[i];
		struct vec3 centre;

		if (cell->head == NONE)
			continue;
		centre = vec3((cell->c[0] + 0.5) * H[0], (cell->c[1] + 0.5) * H[1], (cell->c[2] + 0.5) * H[2]);
		if (line_distance(q, centre) - half_diagonal > found(q) + MARGIN_M)
			continue;
		for (uint32_t e = cell->head; e != NONE; e = q->idx->entries[e].next)
			consider(q, &q->idx->entries[e]);
	}
}

static int32_t clamp_cell(double v, int axis, int32_t lo, int32_t hi)
{
	double f = floor(v / H[axis]);

	return f < lo ? lo : f > hi ? hi : (int32_t)f;
}

/*
 * The cells of slab s (along axis a, where the line runs most steeply) that may hold a
 * point within r of the line: such a point has its a, and so the line's parameter, in a
 * known range there, and its other two coordinates within r of the line's over that
 * range. False when the line passes the slab outside the cells in use; clears *all
 * when the cells are not all those of the slab in use.
 */
static bool slab_cells(const struct query *q, double r, int a, int32_t s, int32_t from[3],
		       int32_t to[3], bool *all)
{
	const struct tree_index *idx = q->idx;
	double reach = r + MARGIN_M, da = coord(q->dir, a), pa = coord(q->p0, a);
	double t0 = ((double)s * H[a] - reach - pa) / da;
	double t1 = ((double)(s + 1) * H[a] + reach - pa) / da;
	bool inside = true;

	for (int k = 0; k < 3; k++) {
		double u = coord(q->p0, k) + coord(q->dir, k) * t0;
		double v = coord(q->p0, k) + coord(q->dir, k) * t1;
		double lo = fmin(u, v) - reach, hi = fmax(u, v) + reach;

		from[k] = clamp_cell(lo, k, idx->lo[k], idx->hi[k]);
		to[k] = clamp_cell(hi, k, idx->lo[k], idx->hi[k]);
		if (k == a)
			continue;
		if (lo > idx->lo[k] * H[k] || hi < (idx->hi[k] + 1) * H[k])
			*all = false;
		if (hi < idx->lo[k] * H[k] || lo > (idx->hi[k] + 1) * H[k])
			inside = false;
	}
	from[a] = to[a] = s;
	return inside;
}

/* Visits every cell that may hold a point within r of the line, slab by slab along a.
 * Returns false, visiting nothing, when that would run over the budget; sets *all when
 * the cells visited were all those in use. */
static bool visit_near(struct query *q, double r, int a, bool *all)
{
	int32_t from[3], to[3], cell[3];
	size_t probes = q->probes;

	/* counted first: a pass that would run over the budget is not begun */
	*all = true;
	for (int32_t s = q->idx->lo[a]; s <= q->idx->hi[a]; s++)
		if (slab_cells(q, r, a, s, from, to, all))
			probes += (size_t)(to[0] - from[0] + 1) * (size_t)(to[1] - from[1] + 1) *
				  (size_t)(to[2] - from[2] + 1);
	if (probes > q->budget)
		return false;
	for (int32_t s = q->idx->lo[a]; s <= q->idx->hi[a]; s++) {
		if (!slab_cells(q, r, a, s, from, to, all))
			continue;
		for (cell[2] = from[2]; cell[2] <= to[2]; cell[2]++)
			for (cell[1] = from[1]; cell[1] <= to[1]; cell[1]++)
				for (cell[0] = from[0]; cell[0] <= to[0]; cell[0]++)
					visit(q, cell);
	}
	return true;
}

/* The axis the query's line runs closest to: its slabs. */
static int slab_axis(struct vec3 dir)
{
	int a = 0;

	for (int k = 1; k < 3; k++)
		if (fabs(coord(dir, k)) > fabs(coord(dir, a)))
			a = k;
	return a;
}

/* A little wider than the best so far, if there is one. */
static double next_radius(const struct query *q)
{
	return q->best.d2 < INFINITY ? found(q) + 2 * MARGIN_M : 0.0;
}

static void query(struct query *q)
{
	int a = slab_axis(q->dir);
	bool all;

	/* wider each time, and at once as wide as the best found so far */
	for (double r = TREE_INDEX_CELL_M;; r = fmax(2 * r, next_radius(q))) {
		if (!visit_near(q, r, a, &all)) {
			visit_all(q);
			return;
		}
		/* every segment nearer than r has been looked at, ties too */
		if (all || found(q) + MARGIN_M <= r)
			return;
	}
}

/* Answers q from idx, the grid of t. */
static bool answer(struct query *q, struct tree_index *idx, const struct tree *t)
{
	if (update(idx, t) < 0 || idx->nlive < TREE_INDEX_MIN_SEGMENTS)
		return false;
	if (q->xf) {
		q->p0 = camera_from_view(q->xf, vec3(q->p.x, q->p.y, 0.0));
		q->dir = q->xf->back; /* view space looks along -z */
	} else {
		q->p0 = vec3(q->p.x, q->p.y, 0.0);
		q->dir = vec3(0, 0, 1);
	}
	for (int k = 0; k < 3; k++) {
		int32_t c;

		if (!cell_of(coord(q->p0, k), k, &c))
			return false;
	}
	/* A line through a deep tree passes many slabs: below this many segments a slab's
	 * few cells each cost more than scanning them all. */
	if (idx->ncells > 0) {
		int a = slab_axis(q->dir);

		if (idx->nlive < 8 * 9 * (size_t)((int64_t)idx->hi[a] - idx->lo[a] + 1))
			return false;
	}
	q->idx = idx;
	q->t = t;
	q->best = (struct tree_index_hit){ .branch = -1, .d2 = INFINITY };
	q->budget = idx->cap_cells / 4; /* a probe costs a few steps of visit_all */
	for (size_t i = 0; i < idx->nwide; i++)
		consider(q, &idx->wide[i]);
	if (idx->ncells > 0)
		query(q);
	return true;
}

bool tree_index_nearest(const struct tree *t, struct vec3 p, struct tree_index_hit *hit)
{
	struct tree_index *idx = t->index;
	struct query q = { .p = p };

	if (!idx || idx->owner != t || !isfinite(p.x) || !isfinite(p.y))
		goto scan;
	if (!idx->world) {
		if (!answer(&q, idx, t))
			return false;
		*hit = q.best;
		return true;
	}
	/* a view of idx->world: its grid, its points turned (the copy was made of it as it
	 * is now, unless the stroke since changed it: then the copy's own points) */
	q.xf = idx->xf->identity ? NULL : idx->xf;
	q.view = t;
	q.show = idx->show;
	q.ctx = idx->ctx;
	if (idx->world->nbranches != t->nbranches || !owned(idx->world) ||
	    !answer(&q, idx->world->index, idx->world))
		goto scan;
	*hit = q.best; /* shown: it was measured */
	return true;
scan:
	if (idx && idx->owner == t && idx->world)
		idx->show(idx->ctx, -1);
	return false;
}
