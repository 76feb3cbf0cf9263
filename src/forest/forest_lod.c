/* SPDX-License-Identifier: MIT */
/*
 * A tree's meshes at the level of detail the forest draws it (docs/forest.md, "Drawing it
 * fast enough"; the rules are forest.h's): its own meshes when they fit the budget; else
 * coarser bark, then fewer branches, and the leaves as cards. Everything follows from the
 * tree and the budget: the grid is searched, never guessed, and cards are numbered in the
 * order of their first leaf, so the same tree and budget give the same bytes.
 */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "forest_lod_private.h"
#include "leaf_colors.h"
#include "season.h"
#include "tube_frame.h"
#include "vine.h"
#include "wood.h"

/* Steps small enough that a budget between two is not much wasted (cherry: 24,512 bark
 * triangles at full detail, then 24,512 14,544 11,480 8,672 6,216 6,144 6,132; a
 * 1,000-branch synthetic tree: 90,882, then 84,414 74,098 63,678 47,850 28,560 17,958
 * 14,418). */
const struct mesh_coarse forest_lod_levels[FOREST_LOD_LEVELS] = {
	{ 8, 2.0 }, { 6, 3.0 }, { 5, 4.0 }, { 4, 6.0 }, { 3, 12.0 }, { 3, 32.0 }, { 3, 64.0 },
};

/* The finest grid the cards are looked for in: cells along the leaves' longest extent. */
#define LOD_GRID_MAX 65536u

static size_t triangles(const struct mesh *m)
{
	return m->nindices / 3;
}

static struct vec3 vertex(const struct mesh *m, size_t v)
{
	const float *p = &m->positions[3 * v];

	return vec3(p[0], p[1], p[2]);
}

static void mesh_swap(struct mesh *a, struct mesh *b)
{
	struct mesh x = *a;

	*a = *b;
	*b = x;
}

int lod_mesh_append(struct mesh *to, const struct mesh *from)
{
	size_t v0 = to->nvertices;
	int r;

	if (from->nvertices == 0 && from->nindices == 0)
		return 0;
	if (from->nvertices > UINT32_MAX - v0)
		return -EINVAL;
	r = mesh_reserve(to, from->nvertices, from->nindices);
	if (r < 0)
		return r;
	memcpy(&to->positions[3 * v0], from->positions, 3 * from->nvertices * sizeof(float));
	memcpy(&to->normals[3 * v0], from->normals, 3 * from->nvertices * sizeof(float));
	for (size_t i = 0; i < from->nindices; i++)
		to->indices[to->nindices + i] = from->indices[i] + (uint32_t)v0;
	to->nvertices += from->nvertices;
	to->nindices += from->nindices;
	return 0;
}

/* The most sides a ring has at a level (0: the tree's own). */
static int level_sides(const struct tree *t, int level)
{
	int s = t->sides <= 0 ? MESH_MAX_SIDES : t->sides < MESH_MIN_SIDES ? MESH_MIN_SIDES
					: t->sides > MESH_MAX_SIDES ? MESH_MAX_SIDES : t->sides;

	if (level > 0 && forest_lod_levels[level - 1].max_sides < s)
		s = forest_lod_levels[level - 1].max_sides;
	return s;
}

/* ---- bark ------------------------------------------------------------------------- */

/* The trunk: the first branch without a parent (SIZE_MAX: none). */
static size_t lod_trunk(const struct tree *t)
{
	for (size_t i = 0; i < t->nbranches; i++)
		if (t->branches[i].parent < 0)
			return i;
	return SIZE_MAX;
}

/* What a branch is worth on screen: its length times its root radius (its outline's area). */
static double branch_worth(const struct branch *b)
{
	double len = tree_branch_length(b), r = b->npoints && b->radii ? b->radii[0] : 0.0;
	double w = len * r;

	return isfinite(w) && w > 0.0 ? w : 0.0;
}

/*
 * Marks the branches that hold the tree's outline: along each of x, -x, y, -y, z and -z,
 * the branch with the farthest point (the first such) unless a vertex of the leaves (mesh
 * lm, or none) reaches as far (the cards keep that), and the branches it hangs on, down
 * to the trunk.
 */
#define OUTLINE_DIRS 6
static void outline_far(struct vec3 p, double x[OUTLINE_DIRS])
{
	x[0] = p.x;
	x[1] = -p.x;
	x[2] = p.y;
	x[3] = -p.y;
	x[4] = p.z;
	x[5] = -p.z;
}

static void outline_mark(const struct tree *t, const struct mesh *lm, bool *held)
{
	size_t best[OUTLINE_DIRS];
	double far[OUTLINE_DIRS], leaf[OUTLINE_DIRS], x[OUTLINE_DIRS];

	for (int d = 0; d < OUTLINE_DIRS; d++) {
		best[d] = SIZE_MAX;
		far[d] = leaf[d] = -INFINITY;
	}
	for (size_t v = 0; lm && v < lm->nvertices; v++) {
		outline_far(vertex(lm, v), x);
		for (int d = 0; d < OUTLINE_DIRS; d++)
			if (x[d] > leaf[d])
				leaf[d] = x[d];
	}
	for (size_t i = 0; i < t->nbranches; i++) {
		const struct branch *b = &t->branches[i];

		for (size_t k = 0; k < b->npoints; k++) {
			outline_far(b->points[k], x);
			for (int d = 0; d < OUTLINE_DIRS; d++) {
				if (x[d] > far[d] && isfinite(x[d])) {
					far[d] = x[d];
					best[d] = i;
				}
			}
		}
	}
	for (int d = 0; d < OUTLINE_DIRS; d++) {
		size_t i = far[d] > leaf[d] ? best[d] : SIZE_MAX;

		/* parents come first (tree.h): each step goes down, so this ends */
		while (i != SIZE_MAX && !held[i]) {
			int p = t->branches[i].parent;

			held[i] = true;
			i = p >= 0 && (size_t)p < i ? (size_t)p : SIZE_MAX;
		}
	}
}

struct prune_key {
	double worth; /* the most any branch of its subtree is worth */
	size_t index;
};

/* Least worth first; on a tie the later branch first (a child comes after its parent). */
static int prune_cmp(const void *pa, const void *pb)
{
	const struct prune_key *a = pa, *b = pb;

	if (a->worth != b->worth)
		return a->worth < b->worth ? -1 : 1;
	return a->index < b->index ? 1 : a->index > b->index ? -1 : 0;
}

int lod_keep(size_t n, const int *parent, const double *worth, const bool *held,
	     const size_t *tris, size_t cap, size_t root, bool *keep, size_t *kept)
{
	struct prune_key *key = malloc((n ? n : 1) * sizeof(*key));
	size_t total = 0;

	if (!key)
		return -ENOMEM;
	for (size_t i = 0; i < n; i++) {
		key[i] = (struct prune_key){ worth[i], i };
		keep[i] = true;
		total += tris[i];
	}
	/* a subtree's worth: its most worthy item's, so an item goes after those on it */
	for (size_t i = n; i-- > 1;) {
		int p = parent[i];

		/* children come after their parents; any other parent is no parent */
		if (p >= 0 && (size_t)p < i && key[p].worth < key[i].worth)
			key[p].worth = key[i].worth;
	}
	qsort(key, n, sizeof(*key), prune_cmp);
	/* First the items nothing holds, then (if need be) those that hold the outline:
	 * a held item's parent is held, so each pass leaves none without its parent. */
	for (int pass = 0; pass < 2; pass++) {
		for (size_t k = 0; k < n && total > cap; k++) {
			size_t i = key[k].index;

			if (i == root || !keep[i] || (pass == 0 && held[i]))
				continue;
			keep[i] = false;
			total -= tris[i];
		}
	}
	*kept = 0;
	for (size_t i = 0; i < n; i++)
		*kept += keep[i];
	free(key);
	return 0;
}

int forest_lod_keep(const struct tree *t, const struct mesh *leaves, const size_t *tris,
		    size_t cap, bool *keep, size_t *kept)
{
	size_t n = t->nbranches;
	double *worth = malloc((n ? n : 1) * sizeof(*worth));
	int *parent = malloc((n ? n : 1) * sizeof(*parent));
	bool *held = calloc(n ? n : 1, sizeof(*held));
	int r = -ENOMEM;

	if (!worth || !parent || !held)
		goto out;
	for (size_t i = 0; i < n; i++) {
		worth[i] = branch_worth(&t->branches[i]);
		parent[i] = t->branches[i].parent;
	}
	outline_mark(t, leaves, held);
	r = lod_keep(n, parent, worth, held, tris, cap, lod_trunk(t), keep, kept);
out:
	free(held);
	free(parent);
	free(worth);
	return r;
}

/* The branches of cm (t's bark at one level, every branch a part marked in cmk) that
 * forest_lod_keep keeps within cap, into out. 0 or -ENOMEM. */
static int bark_prune(const struct tree *t, const struct tree_mesh *cm,
		      const struct tree_mesh_marks *cmk, const struct mesh *lm, size_t cap,
		      struct tree_mesh *out, struct tree_mesh_marks *out_mk, size_t *kept)
{
	size_t n = t->nbranches, nk = 0;
	size_t *tris = malloc(n * sizeof(*tris)), *which = malloc(n * sizeof(*which));
	bool *keep = malloc(n * sizeof(*keep));
	int r = -ENOMEM;

	if (!tris || !which || !keep)
		goto out;
	for (size_t i = 0; i < n; i++)
		tris[i] = (cmk->bark[i + 1].nindices - cmk->bark[i].nindices) / 3;
	r = forest_lod_keep(t, lm, tris, cap, keep, kept);
	if (r < 0)
		goto out;
	for (size_t i = 0; i < n; i++)
		if (keep[i])
			which[nk++] = i;
	r = tree_mesh_copy_parts(out, out_mk, cm, cmk, which, nk, NULL, 0);
out:
	free(keep);
	free(which);
	free(tris);
	return r;
}

/*
 * The tubes within cap into out: the tree's own (full) if they fit, else the first level
 * that fits, else the coarsest pruned. known[l - 1]: level l's triangles
 * if built before (0: not yet), so a second call builds no level it knows too large.
 * 0 or -ENOMEM.
 */
static int lod_bark(const struct tree *t, const struct mesh *full, const struct mesh *leaves,
		    size_t cap, struct mesh *out, struct forest_lod_stats *st,
		    size_t known[FOREST_LOD_LEVELS])
{
	struct tree_mesh cm, pm;
	struct tree_mesh_marks cmk, pmk;
	size_t n = t->nbranches, *all;
	int r = 0, level;

	st->level = 0;
	st->branches_kept = n;
	mesh_clear(out);
	if (triangles(full) <= cap || n == 0)
		return lod_mesh_append(out, full);
	all = malloc(n * sizeof(*all));
	if (!all)
		return -ENOMEM;
	for (size_t i = 0; i < n; i++)
		all[i] = i;
	tree_mesh_init(&cm);
	tree_mesh_init(&pm);
	tree_mesh_marks_init(&cmk);
	tree_mesh_marks_init(&pmk);
	for (level = 1; level <= FOREST_LOD_LEVELS; level++) {
		if (known[level - 1] > cap && level < FOREST_LOD_LEVELS)
			continue;
		r = tree_mesh_build_parts_coarse(&cm, &cmk, t, all, n, NULL, 0,
						 &forest_lod_levels[level - 1]);
		if (r == 0)
			known[level - 1] = triangles(&cm.bark);
		if (r < 0 || triangles(&cm.bark) <= cap)
			break;
	}
	if (r == 0) {
		st->level = level > FOREST_LOD_LEVELS ? FOREST_LOD_LEVELS : level;
		if (triangles(&cm.bark) > cap) {
			r = bark_prune(t, &cm, &cmk, leaves, cap, &pm, &pmk, &st->branches_kept);
			if (r == 0)
				mesh_swap(&cm.bark, &pm.bark);
		}
		if (r == 0)
			mesh_swap(out, &cm.bark);
	}
	tree_mesh_marks_finish(&pmk);
	tree_mesh_marks_finish(&cmk);
	tree_mesh_finish(&pm);
	tree_mesh_finish(&cm);
	free(all);
	return r;
}

/* ---- leaves as cards ---------------------------------------------------------------- */

/* A leaf of the tree's own leaves mesh, as the cards see it. */
struct lod_leaf {
	size_t leaf;          /* in t->leaves */
	size_t v0, v1;        /* its vertices in the leaves mesh */
	struct vec3 c;        /* centroid (by area; its vertices' mean without area) */
	struct vec3 a;        /* area vector: its triangles' (a one-sided leaf's normal) */
	double area;          /* its triangles' areas summed */
	uint32_t card;
};

struct lod_card {
	double area, count;
	struct vec3 ca, cm, asum; /* sums of area * c, of c, of area vectors */
	double m[6];              /* sum of a a^T / |a| over area vectors a (xx xy xz yy yz zz) */
	double rgb[3];            /* sum of area * colour (or of colour, without area) */
	double rgb_plain[3];
	struct vec3 c, n, u, v;
	double umin, umax, vmin, vmax, nmin, nmax; /* its leaves' vertices from c */
};

static bool finite3(struct vec3 p)
{
	return isfinite(p.x) && isfinite(p.y) && isfinite(p.z);
}

/* The leaves of lm (leaf i between marks[i] and marks[i + 1]) that have triangles,
 * measured. Returns how many. */
static size_t leaves_measure(const struct mesh *lm, const struct tree_mesh_mark *marks, size_t nl,
			     struct lod_leaf *out)
{
	size_t n = 0;

	for (size_t i = 0; i < nl; i++) {
		struct lod_leaf *l = &out[n];
		size_t x0 = marks[i].nindices, x1 = marks[i + 1].nindices;
		struct vec3 ca = vec3(0, 0, 0), cm = vec3(0, 0, 0);
		bool ok = x1 > x0;

		l->leaf = i;
		l->v0 = marks[i].nvertices;
		l->v1 = marks[i + 1].nvertices;
		l->a = vec3(0, 0, 0);
		l->area = 0.0;
		for (size_t v = l->v0; v < l->v1 && ok; v++) {
			struct vec3 p = vertex(lm, v);

			ok = finite3(p);
			cm = vec3_add(cm, p);
		}
		if (!ok)
			continue; /* nothing drawn, or nothing to place */
		for (size_t x = x0; x < x1; x += 3) {
			struct vec3 p = vertex(lm, lm->indices[x]);
			struct vec3 q = vertex(lm, lm->indices[x + 1]);
			struct vec3 s = vertex(lm, lm->indices[x + 2]);
			struct vec3 cr = vec3_cross(vec3_sub(q, p), vec3_sub(s, p));
			double ar = 0.5 * vec3_len(cr);

			l->a = vec3_add(l->a, vec3_scale(cr, 0.5));
			l->area += ar;
			ca = vec3_add(ca, vec3_scale(vec3_add(p, vec3_add(q, s)), ar / 3.0));
		}
		l->c = l->area > 0.0 ? vec3_scale(ca, 1.0 / l->area)
				     : vec3_scale(cm, 1.0 / (double)(l->v1 - l->v0));
		n++;
	}
	return n;
}

/* Cells of a grid of cubes over [lo, hi], keyed ix + dx (iy + dy iz). */
struct grid {
	struct vec3 lo;
	double h;
	uint64_t dx, dy, dz;
};

/* Cells along an extent: enough to cover it, never more than n (the longest's). */
static uint64_t grid_dim(double extent, double h, uint32_t n)
{
	double d = ceil(extent / h);

	return !(d > 1.0) ? 1 : d >= (double)n ? n : (uint64_t)d;
}

/* n cells along the longest extent of [lo, hi] (the farthest side's points in the last). */
static void grid_set(struct grid *g, struct vec3 lo, struct vec3 hi, uint32_t n)
{
	struct vec3 e = vec3_sub(hi, lo);
	double m = fmax(e.x, fmax(e.y, e.z));

	g->lo = lo;
	g->h = m > 0.0 ? m / n : 1.0;
	g->dx = grid_dim(e.x, g->h, n);
	g->dy = grid_dim(e.y, g->h, n);
	g->dz = grid_dim(e.z, g->h, n);
}

static uint64_t grid_index(double x, double lo, double h, uint64_t d)
{
	double f = floor((x - lo) / h);

	return !(f > 0.0) ? 0 : f >= (double)d ? d - 1 : (uint64_t)f;
}

static uint64_t grid_key(const struct grid *g, struct vec3 p)
{
	return grid_index(p.x, g->lo.x, g->h, g->dx) +
	       g->dx * (grid_index(p.y, g->lo.y, g->h, g->dy) +
			g->dy * grid_index(p.z, g->lo.z, g->h, g->dz));
}

/* An open-addressing map of cell keys to card numbers (key + 1 stored; 0: empty). */
struct cell_map {
	uint64_t *key;
	uint32_t *card;
	size_t mask;
};

static int cell_map_init(struct cell_map *m, size_t n)
{
	size_t cap = 16;

	while (cap < 2 * n)
		cap *= 2;
	m->key = malloc(cap * sizeof(*m->key));
	m->card = malloc(cap * sizeof(*m->card));
	m->mask = cap - 1;
	return m->key && m->card ? 0 : -ENOMEM;
}

static void cell_map_finish(struct cell_map *m)
{
	free(m->key);
	free(m->card);
}

static void cell_map_clear(struct cell_map *m)
{
	memset(m->key, 0, (m->mask + 1) * sizeof(*m->key));
}

/* The card of cell `key`, numbered *n (and *n counted) if it is new. */
static uint32_t cell_map_get(struct cell_map *m, uint64_t key, uint32_t *n)
{
	uint64_t h = key + 0x9e3779b97f4a7c15ULL;
	size_t i;

	h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ULL;
	h = (h ^ (h >> 27)) * 0x94d049bb133111ebULL;
	h ^= h >> 31;
	for (i = (size_t)h & m->mask; m->key[i]; i = (i + 1) & m->mask)
		if (m->key[i] == key + 1)
			return m->card[i];
	m->key[i] = key + 1;
	m->card[i] = (*n)++;
	return m->card[i];
}

/* Cards the leaves take on a grid of n cells along their longest extent: leaf by leaf,
 * new cells numbered as met; stops past max. */
static uint32_t grid_cards(const struct lod_leaf *leaves, size_t nl, struct vec3 lo,
			   struct vec3 hi, uint32_t n, struct cell_map *m, size_t max,
			   struct grid *g)
{
	uint32_t cards = 0;

	grid_set(g, lo, hi, n);
	cell_map_clear(m);
	for (size_t i = 0; i < nl && cards <= max; i++)
		(void)cell_map_get(m, grid_key(g, leaves[i].c), &cards);
	return cards;
}

/* The palette colour of leaf i (past the tree's own, a vine's leaf: the palette's first,
 * as the screen tints vine leaves), or NULL in winter. */
static const struct season_rgb *leaf_rgb(const struct tree *t, size_t i)
{
	const struct season_rgb *c;

	if (season_palette(t->season, &c) == 0)
		return NULL;
	return i < t->nleaves ? &c[season_leaf_color(t->season, &t->leaves[i])] : &c[0];
}

/* Adds a leaf's area vector a to its card's orientation sums. */
static void card_orient(struct lod_card *cd, struct vec3 a)
{
	double len = vec3_len(a);

	cd->asum = vec3_add(cd->asum, a);
	if (!(len > 0.0))
		return;
	cd->m[0] += a.x * a.x / len;
	cd->m[1] += a.x * a.y / len;
	cd->m[2] += a.x * a.z / len;
	cd->m[3] += a.y * a.y / len;
	cd->m[4] += a.y * a.z / len;
	cd->m[5] += a.z * a.z / len;
}

/*
 * The unit eigenvector of the largest eigenvalue of the symmetric m (xx, xy, xz, yy, yz,
 * zz) by cyclic Jacobi rotations (a fixed sequence of them: deterministic); fallback
 * when m is 0.
 */
static struct vec3 principal_axis(const double m[6], struct vec3 fallback)
{
	double a[3][3] = { { m[0], m[1], m[2] }, { m[1], m[3], m[4] }, { m[2], m[4], m[5] } };
	double v[3][3] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
	double scale = fabs(m[0]) + fabs(m[3]) + fabs(m[5]);
	int best = 0;

	if (!(scale > 0.0) || !isfinite(scale))
		return fallback;
	for (int sweep = 0; sweep < 16; sweep++) {
		static const int pq[3][2] = { { 0, 1 }, { 0, 2 }, { 1, 2 } };

		if (fabs(a[0][1]) + fabs(a[0][2]) + fabs(a[1][2]) <= 1e-15 * scale)
			break;
		for (int r = 0; r < 3; r++) {
			int p = pq[r][0], q = pq[r][1];
			double th, t, c, s;

			if (a[p][q] == 0.0)
				continue;
			th = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
			t = (th >= 0.0 ? 1.0 : -1.0) / (fabs(th) + sqrt(th * th + 1.0));
			c = 1.0 / sqrt(t * t + 1.0);
			s = t * c;
			for (int k = 0; k < 3; k++) { /* a P, v P */
				double akp = a[k][p], akq = a[k][q], vkp = v[k][p], vkq = v[k][q];

				a[k][p] = c * akp - s * akq;
				a[k][q] = s * akp + c * akq;
				v[k][p] = c * vkp - s * vkq;
				v[k][q] = s * vkp + c * vkq;
			}
			for (int k = 0; k < 3; k++) { /* P^T (a P) */
				double apk = a[p][k], aqk = a[q][k];

				a[p][k] = c * apk - s * aqk;
				a[q][k] = s * apk + c * aqk;
			}
		}
	}
	for (int i = 1; i < 3; i++)
		if (a[i][i] > a[best][best])
			best = i;
	return vec3_norm_or(vec3(v[0][best], v[1][best], v[2][best]), fallback);
}

/*
 * A card's normal and plane axes. The normal is the axis its leaves' normals gather
 * round, whichever side each faces (a leaf drawn double-sided has no back): the principal
 * axis of the sum of a a^T / |a| over their area vectors a, turned to the side most of
 * their area faces (the sum of a). Its extent starts empty.
 */
static void card_shape(struct lod_card *cd)
{
	cd->n = principal_axis(cd->m, vec3(0, 0, 1));
	if (vec3_dot(cd->n, cd->asum) < 0.0)
		cd->n = vec3_scale(cd->n, -1.0);
	cd->u = tube_frame_perpendicular(cd->n);
	cd->v = vec3_cross(cd->n, cd->u);
	cd->umin = cd->vmin = cd->nmin = INFINITY;
	cd->umax = cd->vmax = cd->nmax = -INFINITY;
}

/*
 * Moves a card along its normal to the outer face of its leaves (their farthest vertex
 * on the side away from the crown's centre): a crown is seen from outside, and a card
 * through its leaves' middle would pull the outline in by half a cell where it faces out.
 */
static void card_outer(struct lod_card *cd, struct vec3 centre)
{
	double side = vec3_dot(vec3_sub(cd->c, centre), cd->n);

	cd->c = vec3_add(cd->c, vec3_scale(cd->n, side >= 0.0 ? cd->nmax : cd->nmin));
}

/* Widens [*lo, *hi] (around 0) to at least FOREST_LOD_CARD_MIN_M. */
static void card_min(double *lo, double *hi)
{
	double w = *hi - *lo;

	if (!(w >= FOREST_LOD_CARD_MIN_M)) {
		double mid = isfinite(w) ? 0.5 * (*lo + *hi) : 0.0;

		*lo = mid - 0.5 * FOREST_LOD_CARD_MIN_M;
		*hi = mid + 0.5 * FOREST_LOD_CARD_MIN_M;
	}
}

/* How far card cd reaches along unit d: its farthest corner. */
static double card_far(const struct lod_card *cd, struct vec3 d)
{
	double cu = vec3_dot(cd->u, d), cv = vec3_dot(cd->v, d);

	return vec3_dot(cd->c, d) + fmax(cd->umin * cu, cd->umax * cu) +
	       fmax(cd->vmin * cv, cd->vmax * cv);
}

/*
 * The leaves' outline kept: along each of +-x, +-y, +-z, the card of the leaf whose vertex
 * reaches farthest (the first such) is stretched in its plane, on the side of u or v that
 * points most along that way, until it reaches as far. A card on its leaves' outer face
 * misses their far vertex by as much as their depth along its normal where that normal
 * leans away from the axis.
 */
static void cards_outline(struct lod_card *cards, const struct lod_leaf *leaves, size_t n,
			  const struct mesh *lm)
{
	for (int d = 0; d < OUTLINE_DIRS; d++) {
		struct vec3 dir = vec3(d / 2 == 0, d / 2 == 1, d / 2 == 2);
		double far = -INFINITY, short_by, cu, cv;
		struct lod_card *cd = NULL;

		if (d % 2)
			dir = vec3_scale(dir, -1.0);
		for (size_t i = 0; i < n; i++) {
			for (size_t v = leaves[i].v0; v < leaves[i].v1; v++) {
				double x = vec3_dot(vertex(lm, v), dir);

				if (x > far) {
					far = x;
					cd = &cards[leaves[i].card];
				}
			}
		}
		if (!cd)
			return;
		short_by = far - card_far(cd, dir);
		cu = vec3_dot(cd->u, dir);
		cv = vec3_dot(cd->v, dir);
		if (!(short_by > 0.0) || !(fmax(fabs(cu), fabs(cv)) > 1e-9))
			continue;
		if (fabs(cu) >= fabs(cv)) {
			if (cu > 0.0)
				cd->umax += short_by / cu;
			else
				cd->umin += short_by / cu;
		} else {
			if (cv > 0.0)
				cd->vmax += short_by / cv;
			else
				cd->vmin += short_by / cv;
		}
	}
}

static void card_emit(struct mesh *m, const struct lod_card *cd)
{
	const double su[4] = { cd->umin, cd->umax, cd->umax, cd->umin };
	const double sv[4] = { cd->vmin, cd->vmin, cd->vmax, cd->vmax };
	uint32_t base = (uint32_t)m->nvertices;

	/* u x v = n: counter-clockwise seen from the normal's side */
	for (int k = 0; k < 4; k++) {
		struct vec3 p = vec3_add(cd->c, vec3_add(vec3_scale(cd->u, su[k]),
							 vec3_scale(cd->v, sv[k])));
		float *pos = &m->positions[3 * m->nvertices], *nor = &m->normals[3 * m->nvertices];

		pos[0] = (float)p.x;
		pos[1] = (float)p.y;
		pos[2] = (float)p.z;
		nor[0] = (float)cd->n.x;
		nor[1] = (float)cd->n.y;
		nor[2] = (float)cd->n.z;
		m->nvertices++;
	}
	m->indices[m->nindices++] = base;
	m->indices[m->nindices++] = base + 1;
	m->indices[m->nindices++] = base + 2;
	m->indices[m->nindices++] = base;
	m->indices[m->nindices++] = base + 2;
	m->indices[m->nindices++] = base + 3;
}

/*
 * The cards' colours into colors (4 vertices a card), or none in winter. 0 or -ENOMEM.
 */
static int cards_colors(const struct lod_card *cards, size_t n, bool winter,
			struct forest_lod_colors *colors)
{
	colors->n = 0;
	if (winter || n == 0)
		return 0;
	if (colors->cap < 4 * n) {
		float *p = realloc(colors->rgb, 4 * n * 3 * sizeof(*p));

		if (!p)
			return -ENOMEM;
		colors->rgb = p;
		colors->cap = 4 * n;
	}
	for (size_t k = 0; k < n; k++) {
		const struct lod_card *cd = &cards[k];

		for (int v = 0; v < 4; v++)
			for (int ch = 0; ch < 3; ch++)
				colors->rgb[3 * (4 * k + (size_t)v) + (size_t)ch] =
					(float)(cd->area > 0.0 ? cd->rgb[ch] / cd->area
							       : cd->rgb_plain[ch] / cd->count);
	}
	colors->n = 4 * n;
	return 0;
}

/*
 * The nl leaves of lm (t's own, then its vines', leaf i between marks i and i + 1) as at
 * most max cards (at least 1) into out. 0 or -ENOMEM.
 */
static int lod_cards(const struct tree *t, const struct mesh *lm,
		     const struct tree_mesh_mark *marks, size_t nl, size_t max, struct mesh *out,
		     struct forest_lod_colors *colors, struct forest_lod_stats *st)
{
	size_t n;
	struct lod_leaf *leaves = malloc((nl ? nl : 1) * sizeof(*leaves));
	struct lod_card *cards = NULL;
	struct cell_map map = { NULL, NULL, 0 };
	struct vec3 lo = vec3(INFINITY, INFINITY, INFINITY);
	struct vec3 hi = vec3(-INFINITY, -INFINITY, -INFINITY);
	uint32_t lo_n = 1, hi_n = LOD_GRID_MAX, ncards = 0;
	const struct season_rgb *palette;
	struct grid g;
	int r = -ENOMEM;

	mesh_clear(out);
	if (colors)
		colors->n = 0;
	if (!leaves)
		return -ENOMEM;
	n = leaves_measure(lm, marks, nl, leaves);
	if (n == 0) {
		r = 0;
		goto out;
	}
	if (cell_map_init(&map, n) < 0)
		goto out;
	for (size_t i = 0; i < n; i++) {
		struct vec3 c = leaves[i].c;

		lo = vec3(fmin(lo.x, c.x), fmin(lo.y, c.y), fmin(lo.z, c.z));
		hi = vec3(fmax(hi.x, c.x), fmax(hi.y, c.y), fmax(hi.z, c.z));
	}
	if (max < 1)
		max = 1;

	/* The finest grid whose cards fit: cells grow with n, by and large; a grid is taken
	 * only once counted, so a dip in that does not matter. */
	while (lo_n < hi_n) {
		uint32_t mid = lo_n + (hi_n - lo_n + 1) / 2;

		if (grid_cards(leaves, n, lo, hi, mid, &map, max, &g) <= max)
			lo_n = mid;
		else
			hi_n = mid - 1;
	}
	grid_set(&g, lo, hi, lo_n);
	cell_map_clear(&map);
	for (size_t i = 0; i < n; i++)
		leaves[i].card = cell_map_get(&map, grid_key(&g, leaves[i].c), &ncards);

	cards = calloc(ncards, sizeof(*cards));
	if (!cards || mesh_reserve(out, 4 * (size_t)ncards, 6 * (size_t)ncards) < 0)
		goto out;
	for (size_t i = 0; i < n; i++) {
		struct lod_card *cd = &cards[leaves[i].card];
		const struct season_rgb *rgb = leaf_rgb(t, leaves[i].leaf);

		cd->area += leaves[i].area;
		cd->count += 1.0;
		card_orient(cd, leaves[i].a);
		cd->ca = vec3_add(cd->ca, vec3_scale(leaves[i].c, leaves[i].area));
		cd->cm = vec3_add(cd->cm, leaves[i].c);
		if (rgb) {
			double c3[3] = { rgb->r, rgb->g, rgb->b };

			for (int ch = 0; ch < 3; ch++) {
				cd->rgb[ch] += leaves[i].area * c3[ch];
				cd->rgb_plain[ch] += c3[ch];
			}
		}
	}
	for (size_t k = 0; k < ncards; k++) {
		struct lod_card *cd = &cards[k];

		cd->c = cd->area > 0.0 ? vec3_scale(cd->ca, 1.0 / cd->area)
				       : vec3_scale(cd->cm, 1.0 / cd->count);
		card_shape(cd);
	}
	for (size_t i = 0; i < n; i++) {
		struct lod_card *cd = &cards[leaves[i].card];

		for (size_t v = leaves[i].v0; v < leaves[i].v1; v++) {
			struct vec3 d = vec3_sub(vertex(lm, v), cd->c);
			double pu = vec3_dot(d, cd->u), pv = vec3_dot(d, cd->v);

			double pn = vec3_dot(d, cd->n);

			cd->nmin = fmin(cd->nmin, pn);
			cd->nmax = fmax(cd->nmax, pn);
			cd->umin = fmin(cd->umin, pu);
			cd->umax = fmax(cd->umax, pu);
			cd->vmin = fmin(cd->vmin, pv);
			cd->vmax = fmax(cd->vmax, pv);
		}
	}
	for (size_t k = 0; k < ncards; k++) {
		card_outer(&cards[k], vec3_scale(vec3_add(lo, hi), 0.5));
		card_min(&cards[k].umin, &cards[k].umax);
		card_min(&cards[k].vmin, &cards[k].vmax);
	}
	cards_outline(cards, leaves, n, lm);
	for (size_t k = 0; k < ncards; k++)
		card_emit(out, &cards[k]);
	st->leaves_as_cards = n;
	st->cards = ncards;
	st->cell = g.h;
	r = colors ? cards_colors(cards, ncards, season_palette(t->season, &palette) == 0, colors)
		   : 0;
out:
	if (r < 0)
		mesh_clear(out);
	free(cards);
	cell_map_finish(&map);
	free(leaves);
	return r;
}

/* ---- the whole tree ----------------------------------------------------------------- */

void forest_lod_colors_init(struct forest_lod_colors *c)
{
	memset(c, 0, sizeof(*c));
}

void forest_lod_colors_finish(struct forest_lod_colors *c)
{
	free(c->rgb);
	forest_lod_colors_init(c);
}

/*
 * Everything a tree draws, at full detail: its own meshes (tree_mesh_build: the tubes,
 * the wood's branches left out, and its leaves), the wood's bark (t->wood->bark) and its
 * vines (vine_mesh_append: the stems and their leaves), and what the coarser levels of
 * the wood and the stems need, made when first needed.
 */
struct lod_tree {
	const struct tree *t;
	struct tree_mesh full;
	struct tree_mesh_marks mk;
	const struct mesh *wood;         /* NULL: no wood (or one without triangles) */
	struct tree_mesh vines;          /* every vine's stems (bark) and leaves, in order */
	/* the leaves as they are: the tree's own, then the vines' (each a quad); lm is
	 * full.leaves and marks mk.leaves for a tree without vines */
	struct mesh all_leaves;
	struct tree_mesh_mark *all_marks;
	const struct mesh *lm;
	const struct tree_mesh_mark *marks;
	size_t nleaves;                  /* leaves in all: marks[0..nleaves] */
	struct lod_decimate dec;
	bool planned;
	size_t tubes_outline;            /* the tubes lod_bark keeps last (SIZE_MAX: not known) */
	struct lod_stems stems;
	bool *held, *keep;               /* a shoot each: holds the outline; stays */
	size_t *tris;
	bool read;
	size_t known[FOREST_LOD_LEVELS];
};

static void lod_tree_finish(struct lod_tree *lt)
{
	tree_mesh_finish(&lt->full);
	tree_mesh_marks_finish(&lt->mk);
	tree_mesh_finish(&lt->vines);
	mesh_finish(&lt->all_leaves);
	free(lt->all_marks);
	lod_decimate_finish(&lt->dec);
	lod_stems_finish(&lt->stems);
	free(lt->held);
	free(lt->keep);
	free(lt->tris);
}

/* The leaves as they are, the vines' after the tree's, and where each begins. */
static int all_leaves(struct lod_tree *lt)
{
	const struct mesh *fl = &lt->full.leaves, *vl = &lt->vines.leaves;
	size_t nt = lt->t->nleaves, nv = vl->nvertices / 4, n = nt + nv;
	int r;

	lt->lm = fl;
	lt->marks = lt->mk.leaves;
	lt->nleaves = nt;
	if (vl->nvertices == 0)
		return 0;
	if (vl->nvertices != 4 * nv || vl->nindices != 6 * nv)
		return -EINVAL; /* not vine_mesh_append's quads */
	lt->all_marks = malloc((n + 1) * sizeof(*lt->all_marks));
	if (!lt->all_marks)
		return -ENOMEM;
	memcpy(lt->all_marks, lt->mk.leaves, (nt + 1) * sizeof(*lt->all_marks));
	/* vine_mesh_append's leaves: a quad each, 4 vertices and 6 indices */
	for (size_t i = 0; i < nv; i++) {
		lt->all_marks[nt + i + 1].nvertices = fl->nvertices + 4 * (i + 1);
		lt->all_marks[nt + i + 1].nindices = fl->nindices + 6 * (i + 1);
	}
	r = lod_mesh_append(&lt->all_leaves, fl);
	if (r == 0)
		r = lod_mesh_append(&lt->all_leaves, vl);
	if (r < 0)
		return r;
	lt->lm = &lt->all_leaves;
	lt->marks = lt->all_marks;
	lt->nleaves = n;
	return 0;
}

static int lod_tree_init(struct lod_tree *lt, const struct tree *t)
{
	int r;

	memset(lt, 0, sizeof(*lt));
	lt->t = t;
	lt->tubes_outline = SIZE_MAX;
	tree_mesh_init(&lt->full);
	tree_mesh_marks_init(&lt->mk);
	tree_mesh_init(&lt->vines);
	mesh_init(&lt->all_leaves);
	lod_decimate_init(&lt->dec);
	lod_stems_init(&lt->stems);
	r = tree_mesh_build_marked(&lt->full, t, &lt->mk);
	/* the leaves' parts must be known: cards are made from them */
	if (r == 0 && lt->mk.nleaves != t->nleaves + 1)
		r = -ENOMEM;
	for (size_t i = 0; i < t->nvines && r == 0; i++)
		r = vine_mesh_append(&t->vines[i], &lt->vines.bark, &lt->vines.leaves);
	if (r == 0 && t->wood && t->wood->bark.nindices >= 3)
		lt->wood = &t->wood->bark;
	if (r == 0)
		r = all_leaves(lt);
	return r;
}

/* ---- the wood and the vines' stems within their shares ------------------------------ */

static void far_add(const struct mesh *m, double far[OUTLINE_DIRS])
{
	double x[OUTLINE_DIRS];

	for (size_t v = 0; m && v < m->nvertices; v++) {
		outline_far(vertex(m, v), x);
		for (int d = 0; d < OUTLINE_DIRS; d++)
			if (x[d] > far[d])
				far[d] = x[d];
	}
}

/*
 * The shoots that hold the outline: along each of x, -x, y, -y, z and -z, the shoot whose
 * stem reaches farthest (an axis point plus its radius; the first such) unless the rest
 * of the tree (its own meshes, the wood, the vines' leaves) reaches as far, and the
 * shoots it grew from.
 */
static void stems_outline(struct lod_tree *lt)
{
	const struct lod_stems *ls = &lt->stems;
	double rest[OUTLINE_DIRS], far[OUTLINE_DIRS], x[OUTLINE_DIRS];
	size_t best[OUTLINE_DIRS];

	for (int d = 0; d < OUTLINE_DIRS; d++) {
		rest[d] = far[d] = -INFINITY;
		best[d] = SIZE_MAX;
	}
	far_add(&lt->full.bark, rest);
	far_add(lt->lm, rest);
	far_add(lt->wood, rest);
	for (size_t i = 0; i < ls->n; i++) {
		for (size_t k = 0; k < ls->s[i].n && ls->s[i].n >= 2; k++) {
			outline_far(ls->s[i].axis[k], x);
			for (int d = 0; d < OUTLINE_DIRS; d++) {
				if (x[d] + ls->s[i].radius > far[d] && isfinite(x[d])) {
					far[d] = x[d] + ls->s[i].radius;
					best[d] = i;
				}
			}
		}
	}
	for (int d = 0; d < OUTLINE_DIRS; d++) {
		size_t i = far[d] > rest[d] ? best[d] : SIZE_MAX;

		while (i != SIZE_MAX && !lt->held[i]) {
			int p = ls->s[i].parent;

			lt->held[i] = true;
			i = p >= 0 && (size_t)p < i ? (size_t)p : SIZE_MAX;
		}
	}
}

static int stems_read(struct lod_tree *lt)
{
	size_t n;
	int r;

	if (lt->read)
		return 0;
	r = lod_stems_read(&lt->stems, lt->t);
	n = lt->stems.n;
	if (r == 0) {
		lt->held = calloc(n ? n : 1, sizeof(*lt->held));
		lt->keep = malloc((n ? n : 1) * sizeof(*lt->keep));
		lt->tris = malloc((n ? n : 1) * sizeof(*lt->tris));
		if (!lt->held || !lt->keep || !lt->tris)
			r = -ENOMEM;
	}
	if (r == 0)
		stems_outline(lt);
	lt->read = r == 0;
	return r;
}

/*
 * The vines' stems within cap, appended to out: their own (vine_mesh_append's) if they
 * fit, else the first coarser level that fits, else the coarsest with shoots left out
 * (lod_keep: least worth first, never one before those that grew from it), but never
 * those that hold the outline: when they alone do not fit, they are drawn through their
 * outline alone (FOREST_LOD_STEM_OUTLINE), whatever cap. 0 or -ENOMEM.
 */
static int stems_fit(struct lod_tree *lt, size_t cap, struct mesh *out,
		     struct forest_lod_stats *st)
{
	const struct lod_stems *ls = &lt->stems;
	int level, *parent;
	double *worth;
	int r;

	st->stem_level = 0;
	if (triangles(&lt->vines.bark) <= cap) {
		st->shoots_kept = st->shoots;
		return lod_mesh_append(out, &lt->vines.bark);
	}
	r = stems_read(lt);
	if (r < 0)
		return r;
	for (level = 1; level <= FOREST_LOD_LEVELS; level++) {
		size_t sum = 0;

		for (size_t i = 0; i < ls->n; i++)
			sum += lt->tris[i] = lod_stems_triangles(ls, i, level);
		if (sum <= cap || level == FOREST_LOD_LEVELS)
			break;
	}
	st->stem_level = level > FOREST_LOD_LEVELS ? FOREST_LOD_LEVELS : level;
	parent = malloc((ls->n ? ls->n : 1) * sizeof(*parent));
	worth = malloc((ls->n ? ls->n : 1) * sizeof(*worth));
	r = parent && worth ? 0 : -ENOMEM;
	for (size_t i = 0; i < ls->n && r == 0; i++) {
		parent[i] = ls->s[i].parent;
		worth[i] = ls->s[i].worth;
	}
	if (r == 0)
		r = lod_keep(ls->n, parent, worth, lt->held, lt->tris, cap, SIZE_MAX, lt->keep,
			     &st->shoots_kept);
	/* what holds the outline stays: alone, through its outline, if it had to go */
	for (size_t i = 0; i < ls->n && r == 0; i++) {
		if (lt->held[i] && !lt->keep[i]) {
			st->stem_level = FOREST_LOD_STEM_OUTLINE;
			break;
		}
	}
	if (r == 0 && st->stem_level == FOREST_LOD_STEM_OUTLINE) {
		st->shoots_kept = 0;
		for (size_t i = 0; i < ls->n; i++)
			st->shoots_kept += lt->keep[i] = lt->held[i];
	}
	if (r == 0)
		r = lod_stems_build(ls, st->stem_level, lt->keep, out);
	free(worth);
	free(parent);
	return r;
}

/* The wood's bark within cap, appended to out: its own if it fits, else made coarser
 * (forest_lod_wood.c) to cap or as far as it goes. 0, -EINVAL or -ENOMEM. */
static int wood_fit(struct lod_tree *lt, size_t cap, struct mesh *out)
{
	int r;

	if (!lt->wood || triangles(lt->wood) <= cap)
		return lt->wood ? lod_mesh_append(out, lt->wood) : 0;
	if (!lt->planned) {
		r = lod_decimate_plan(&lt->dec, lt->wood);
		if (r < 0)
			return r;
		lt->planned = true;
	}
	return lod_decimate_apply(&lt->dec, cap, out);
}

/* The triangles of the tubes lod_bark keeps last: the trunk's and those of the branches
 * that hold the outline (outline_mark), at the coarsest level. 0 or -ENOMEM. */
static int tubes_outline(struct lod_tree *lt, size_t *out)
{
	const struct tree *t = lt->t;
	size_t n = t->nbranches, trunk = lod_trunk(t), sum = 0, *all;
	struct tree_mesh cm;
	struct tree_mesh_marks cmk;
	bool *held;
	int r;

	if (lt->tubes_outline != SIZE_MAX) {
		*out = lt->tubes_outline;
		return 0;
	}
	all = malloc((n ? n : 1) * sizeof(*all));
	held = calloc(n ? n : 1, sizeof(*held));
	tree_mesh_init(&cm);
	tree_mesh_marks_init(&cmk);
	r = all && held ? 0 : -ENOMEM;
	for (size_t i = 0; i < n && r == 0; i++)
		all[i] = i;
	if (r == 0)
		r = tree_mesh_build_parts_coarse(&cm, &cmk, t, all, n, NULL, 0,
						 &forest_lod_levels[FOREST_LOD_LEVELS - 1]);
	if (r == 0) {
		lt->known[FOREST_LOD_LEVELS - 1] = triangles(&cm.bark);
		outline_mark(t, lt->lm, held);
		for (size_t i = 0; i < n; i++)
			if (held[i] || i == trunk)
				sum += (cmk.bark[i + 1].nindices - cmk.bark[i].nindices) / 3;
		lt->tubes_outline = *out = sum;
	}
	tree_mesh_marks_finish(&cmk);
	tree_mesh_finish(&cm);
	free(held);
	free(all);
	return r;
}

/* The wood's triangles within cap (its own, or made coarser to cap or its fewest).
 * 0 or -ENOMEM. */
static int wood_triangles(struct lod_tree *lt, size_t cap, size_t *n)
{
	int r;

	*n = lt->wood ? triangles(lt->wood) : 0;
	if (*n <= cap)
		return 0;
	if (!lt->planned) {
		r = lod_decimate_plan(&lt->dec, lt->wood);
		if (r < 0)
			return r;
		lt->planned = true;
	}
	*n = lod_decimate_triangles(&lt->dec, cap);
	return 0;
}

/*
 * All the bark within cap into out: the tubes (the tree's own bark), then the wood's
 * bark, then the vines' stems. All of them as they are when they fit; else the wood and
 * the stems each take a share of cap in proportion to their own triangles, but together
 * no more than the tubes' outline (the trunk and the branches that hold the outline, at
 * the coarsest level) leaves of cap; the stems at their level (those that hold the
 * outline may take more), the tubes what those two leave (lod_bark); of what the tubes
 * leave, the stems again their part (if more than before), the wood all the rest.
 * *coarser: whether any of them was made coarser. 0, -EINVAL or -ENOMEM.
 */
static int lod_bark_all(struct lod_tree *lt, size_t cap, struct mesh *out,
			struct forest_lod_stats *st, bool *coarser)
{
	size_t tt = triangles(&lt->full.bark), w = lt->wood ? triangles(lt->wood) : 0;
	size_t v = triangles(&lt->vines.bark), total = tt + w + v, share_w, share_v, taken, wt;
	size_t rest, vcap;
	struct mesh stems;
	int r;

	st->shoots = 0;
	for (size_t i = 0; i < lt->t->nvines; i++)
		st->shoots += lt->t->vines[i].nshoots;
	st->stem_level = 0;
	st->shoots_kept = st->shoots;
	st->wood_triangles = w;
	st->stem_triangles = v;
	st->stem_vertices = 0;
	*coarser = total > cap;
	if (!*coarser) {
		st->level = 0;
		st->branches_kept = lt->t->nbranches;
		mesh_clear(out);
		r = lod_mesh_append(out, &lt->full.bark);
		if (r == 0)
			r = wood_fit(lt, cap, out);
		if (r == 0)
			r = lod_mesh_append(out, &lt->vines.bark);
		st->stem_vertices = lt->vines.bark.nvertices;
		return r;
	}
	share_w = (size_t)((double)cap * ((double)w / (double)total));
	share_v = (size_t)((double)cap * ((double)v / (double)total));
	if (share_w + share_v > 0) {
		size_t outline = 0, room;

		r = tubes_outline(lt, &outline);
		if (r < 0)
			return r;
		room = cap > outline ? cap - outline : 0;
		if (share_w + share_v > room) {
			share_w = (size_t)((double)room * ((double)w / (double)(w + v)));
			share_v = (size_t)((double)room * ((double)v / (double)(w + v)));
		}
	}
	mesh_init(&stems);
	r = stems_fit(lt, share_v, &stems, st);
	if (r == 0)
		r = wood_triangles(lt, share_w, &wt);
	taken = triangles(&stems) + wt;
	if (r == 0)
		r = lod_bark(lt->t, &lt->full.bark, lt->lm, cap > taken ? cap - taken : 0, out, st,
			     lt->known);
	/* what the tubes leave: the stems' part of it in proportion (never less than they
	 * had), then the wood all the rest */
	rest = cap > triangles(out) ? cap - triangles(out) : 0;
	vcap = v ? (size_t)((double)rest * ((double)v / (double)(w + v))) : 0;
	if (r == 0 && st->stem_level > 0 && vcap > share_v) {
		mesh_clear(&stems);
		r = stems_fit(lt, vcap, &stems, st);
	}
	taken = triangles(&stems) + triangles(out);
	wt = triangles(out);
	if (r == 0)
		r = wood_fit(lt, cap > taken ? cap - taken : 0, out);
	st->wood_triangles = triangles(out) - wt;
	st->stem_triangles = triangles(&stems);
	st->stem_vertices = stems.nvertices;
	if (r == 0)
		r = lod_mesh_append(out, &stems);
	mesh_finish(&stems);
	return r;
}

/* ---- the whole tree ----------------------------------------------------------------- */

/* The colours of the leaves as they are (lt->lm): the tree's own (leaf_colors_fill, by
 * mk), the vines' the palette's first. 0 or -ENOMEM. */
static int own_colors(const struct lod_tree *lt, struct forest_lod_colors *colors)
{
	const struct tree *t = lt->t;
	size_t nv = lt->lm->nvertices, own = lt->full.leaves.nvertices;
	const struct season_rgb *c;

	colors->n = 0;
	if (nv == 0)
		return 0;
	if (colors->cap < nv) {
		float *p = realloc(colors->rgb, nv * 3 * sizeof(*p));

		if (!p)
			return -ENOMEM;
		colors->rgb = p;
		colors->cap = nv;
	}
	if (!leaf_colors_fill(t, &lt->mk, own, colors->rgb) || season_palette(t->season, &c) == 0)
		return 0;
	for (size_t v = own; v < nv; v++) {
		colors->rgb[3 * v] = c[0].r;
		colors->rgb[3 * v + 1] = c[0].g;
		colors->rgb[3 * v + 2] = c[0].b;
	}
	colors->n = nv;
	return 0;
}

int forest_lod_build_colors(const struct tree *t, size_t max_triangles, struct tree_mesh *out,
			    struct forest_lod_colors *colors, struct forest_lod_stats *st)
{
	struct forest_lod_stats s;
	struct lod_tree lt;
	size_t leaves, cap, left;
	bool coarser = false;
	int r;

	memset(&s, 0, sizeof(s));
	mesh_clear(&out->bark);
	mesh_clear(&out->leaves);
	if (colors)
		colors->n = 0;
	r = lod_tree_init(&lt, t);
	if (r < 0)
		goto out;
	leaves = triangles(lt.lm);
	s.full_triangles = triangles(&lt.full.bark) + (lt.wood ? triangles(lt.wood) : 0) +
			   triangles(&lt.vines.bark) + leaves;
	s.branches_kept = t->nbranches;
	s.sides = level_sides(t, 0);

	/* The bark: all of it when everything fits; else at least its share, all the leaves
	 * leave if more. */
	cap = (size_t)((double)max_triangles * FOREST_LOD_BARK_SHARE);
	if (leaves < max_triangles && max_triangles - leaves > cap)
		cap = max_triangles - leaves;
	if (s.full_triangles <= max_triangles)
		cap = max_triangles;
	r = lod_bark_all(&lt, cap, &out->bark, &s, &coarser);
	if (r < 0)
		goto out;
	s.sides = level_sides(t, s.level);

	left = max_triangles > triangles(&out->bark) ? max_triangles - triangles(&out->bark) : 0;
	if (leaves <= left) {
		r = lod_mesh_append(&out->leaves, lt.lm);
		if (r == 0 && colors)
			r = own_colors(&lt, colors);
	} else {
		r = lod_cards(t, lt.lm, lt.marks, lt.nleaves, left / 2, &out->leaves, colors, &s);
		/* cards a leaf each may leave room: the bark takes it (they do not depend on it) */
		if (r == 0 && coarser && max_triangles > triangles(&out->leaves) &&
		    max_triangles - triangles(&out->leaves) > cap) {
			cap = max_triangles - triangles(&out->leaves);
			r = lod_bark_all(&lt, cap, &out->bark, &s, &coarser);
			s.sides = level_sides(t, s.level);
		}
	}
out:
	if (r < 0) {
		mesh_clear(&out->bark);
		mesh_clear(&out->leaves);
		if (colors)
			colors->n = 0;
		memset(&s, 0, sizeof(s));
	}
	s.bark_triangles = triangles(&out->bark);
	s.leaf_triangles = triangles(&out->leaves);
	s.over_budget = s.bark_triangles + s.leaf_triangles > max_triangles;
	if (st)
		*st = s;
	lod_tree_finish(&lt);
	return r;
}

int forest_lod_build(const struct tree *t, size_t max_triangles, struct tree_mesh *out,
		     struct forest_lod_stats *st)
{
	return forest_lod_build_colors(t, max_triangles, out, NULL, st);
}

/* ---- the forest's shares ----------------------------------------------------------- */

static double width_weight(double w)
{
	return isfinite(w) && w > 0.0 ? w : 0.0;
}

void forest_lod_shares(const double *widths, const size_t *need, size_t n, size_t total,
		       size_t *share)
{
	bool done_any = true;
	size_t left = total;

	for (size_t i = 0; i < n; i++)
		share[i] = SIZE_MAX; /* not settled */
	/* Each round settles every tree that needs no more than its share, or ends. */
	while (done_any) {
		double sum = 0.0;
		size_t open = 0, given = 0;

		done_any = false;
		for (size_t i = 0; i < n; i++) {
			if (share[i] != SIZE_MAX)
				continue;
			sum += width_weight(widths[i]);
			open++;
		}
		if (open == 0)
			return;
		for (size_t i = 0; i < n; i++) {
			double w = width_weight(widths[i]), part;
			size_t s;

			if (share[i] != SIZE_MAX)
				continue;
			part = sum > 0.0 ? (double)left * (w / sum) : (double)left / (double)open;
			s = part >= (double)left ? left : (size_t)part;
			if (need && need[i] <= s) {
				share[i] = need[i];
				left -= need[i];
				done_any = true;
				break; /* the others' shares grow: shared again */
			}
		}
		if (done_any)
			continue;
		for (size_t i = 0; i < n; i++) {
			double w = width_weight(widths[i]), part;

			if (share[i] != SIZE_MAX)
				continue;
			part = sum > 0.0 ? (double)left * (w / sum) : (double)left / (double)open;
			share[i] = part >= (double)(left - given) ? left - given : (size_t)part;
			given += share[i];
		}
	}
}
