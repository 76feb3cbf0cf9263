/* SPDX-License-Identifier: MIT */
/*
 * The wood and the vines in a tree's part of the forest (src/forest/forest_lod.c,
 * forest_lod_wood.c, forest_lod_vine.c; docs/forest.md "The wood and the vines"), on 300
 * seeded random trees as visitors grow them (live_trees_random: 1 to 300 branches, 0 to 12
 * leaves a branch, 2 to 15 m; grown 1 to 3 presses, conifer or broadleaf, and/or 1 to 3 of
 * the kiosk's vines, morning glory scaled to the trunk as app_mode_vine.c scales it,
 * planted round the foot before or after the wood):
 *
 * - at two budgets from 500 to 300,000 (log-uniform), at the tree's own count and one
 *   less, and at a budget from 500 to its own count: never over the budget; at its own
 *   count the part's bark is the tree's own bark, the wood's bark and the vines' stems
 *   byte for byte as tree_mesh_build, t->wood->bark and vine_mesh_append make them, its
 *   leaves the tree's then the vines'; the wood's part of the bark (made coarser) only the
 *   wood's own vertices, as many triangles as the stats say; the box of the part at least
 *   0.985 of the full box's extent (wood and vines in it) along each axis; nothing not
 *   finite, no index out of range; the same bytes twice;
 * - the least (a budget of 0): the trunk's tube at the coarsest level (none when the wood
 *   holds it), the wood at its fewest, no stems, one card;
 * - the part (forest_part_build) at its own count: every vertex of the wood and the vines
 *   bound as the screen binds them (live_attrs_bind_nearest of the wood's bark, the stems
 *   and the vines' leaves: the same data), and every vertex bound at any budget;
 * - colours: a vine leaf as it is the palette's first colour (autumn), none in winter;
 * - the wood made coarser alone (forest_lod_decimate) at random counts: at most that many
 *   (or its fewest), a closed manifold still (each edge twice, once each way), its Euler
 *   characteristic kept, its box exactly the wood's, its vertices the wood's own, the same
 *   bytes twice.
 *
 * The worst margins are printed.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app.h"
#include "app_private.h"
#include "forest.h"
#include "live.h"
#include "live_trees.h"
#include "rng.h"
#include "season.h"
#include "same.h"
#include "test.h"
#include "vine.h"
#include "vine_presets.h"
#include "vine_support.h"
#include "wood.h"

static size_t tris(const struct mesh *m)
{
	return m->nindices / 3;
}

/* a ++ b ++ c as one mesh (b's and c's indices moved on) into out. */
static void concat(struct mesh *out, const struct mesh *const *parts, size_t n)
{
	mesh_clear(out);
	for (size_t k = 0; k < n; k++) {
		const struct mesh *p = parts[k];
		size_t v0 = out->nvertices;

		/* (an empty mesh may hold no arrays: memcpy is not given NULL) */
		if (!p || p->nvertices == 0)
			continue;
		CHECK_INT(mesh_reserve(out, p->nvertices, p->nindices), 0);
		memcpy(&out->positions[3 * v0], p->positions, 3 * p->nvertices * sizeof(float));
		memcpy(&out->normals[3 * v0], p->normals, 3 * p->nvertices * sizeof(float));
		for (size_t i = 0; i < p->nindices; i++)
			out->indices[out->nindices + i] = p->indices[i] + (uint32_t)v0;
		out->nvertices += p->nvertices;
		out->nindices += p->nindices;
	}
}

/* ---- trees as visitors grow them --------------------------------------------------- */

/* The kiosk's vine, scaled to the trunk as app_mode_vine.c's scaled_params does. */
static void kiosk_vine(const struct tree *t, uint64_t seed, struct vine_params *p)
{
	struct error err = { { 0 } };
	double k;

	CHECK_INT(vine_preset(APP_VINE_PRESET, p, &err), 0);
	k = 0.1 * t->branches[0].radii[0] / p->radius;
	k = k < 6.0 ? 6.0 : k > 16.0 ? 16.0 : k;
	p->internode = fmin(p->internode * k, VINE_INTERNODE_MAX);
	p->radius = fmin(p->radius * k, VINE_RADIUS_MAX);
	p->leaf_size = fmin(p->leaf_size * k, VINE_LEAF_SIZE_MAX);
	p->seed = seed + t->nvines;
	CHECK_INT(vine_params_check(p, NULL, &err), 0);
}

/* n vines planted round the foot (a stem's width clear of the trunk), grown on its bark as
 * the vine op grows them (app_vine_support: the tubes, not the wood). */
static void plant_vines(struct tree *t, struct rng *r, int n, uint64_t seed)
{
	struct vine_support *s = NULL;
	int ret = app_vine_support(t, &s);

	if (ret == -EINVAL)
		return; /* no bark to climb: the kiosk plants nothing */
	CHECK_INT(ret, 0);
	for (int i = 0; i < n; i++) {
		struct vine_params p;
		struct vine v;
		struct vec3 foot = t->branches[0].points[0];
		double a = rng_range(r, 0.0, 2.0 * VEC_PI), d;

		kiosk_vine(t, seed, &p);
		d = t->branches[0].radii[0] + 2.0 * p.radius;
		vine_init(&v, &p, vec3(foot.x + d * cos(a), foot.y, foot.z + d * sin(a)));
		CHECK_INT(vine_grow(&v, s, INFINITY), 0);
		CHECK_INT(vine_attach(t, &v), 0);
		vine_finish(&v);
	}
	vine_support_destroy(s);
}

struct made {
	size_t trees, grown, vined, both, vines, presses;
};

/* A random tree grown and/or vined (the header says how). */
static void grown_tree(struct tree *t, struct rng *r, uint64_t seed, struct made *m)
{
	int kind = (int)(rng_next(r) % 3), presses = 1 + (int)(rng_next(r) % 3);
	int nvines = 1 + (int)(rng_next(r) % 3);
	bool vines_first = rng_next(r) % 2;
	struct wood_params wp;

	live_trees_random(t, 1 + (int)(rng_next(r) % 300), (int)(rng_next(r) % 13), seed,
			  rng_range(r, 2.0, 15.0));
	t->season = (enum season)(rng_next(r) % 4);
	wood_params_default(&wp);
	wp.mode = rng_next(r) % 2 ? WOOD_BROADLEAF : WOOD_CONIFER;
	if (kind != 0 && vines_first)
		plant_vines(t, r, nvines, seed);
	for (int i = 0; kind != 1 && i < presses; i++)
		CHECK(wood_grow(t, &wp) >= 0);
	if (kind != 0 && !vines_first)
		plant_vines(t, r, nvines, seed);
	m->trees++;
	m->grown += t->wood != NULL;
	m->vined += t->nvines > 0;
	m->both += t->wood && t->nvines;
	m->vines += t->nvines;
	m->presses += t->wood ? (size_t)t->wood->presses : 0;
}

/* ---- the tree at full detail ------------------------------------------------------- */

struct whole {
	struct tree_mesh own;     /* tree_mesh_build's */
	struct tree_mesh vines;   /* vine_mesh_append's: stems, leaves */
	const struct mesh *wood;  /* t->wood->bark or NULL */
	struct mesh bark, leaves; /* own bark ++ wood ++ stems; own leaves ++ vine leaves */
	struct box box;
	size_t triangles;
};

static void whole_build(struct whole *w, const struct tree *t)
{
	tree_mesh_init(&w->own);
	tree_mesh_init(&w->vines);
	mesh_init(&w->bark);
	mesh_init(&w->leaves);
	CHECK_INT(tree_mesh_build(&w->own, t), 0);
	for (size_t i = 0; i < t->nvines; i++)
		CHECK_INT(vine_mesh_append(&t->vines[i], &w->vines.bark, &w->vines.leaves), 0);
	w->wood = t->wood && t->wood->bark.nindices ? &t->wood->bark : NULL;
	{
		const struct mesh *b[3] = { &w->own.bark, w->wood, &w->vines.bark };
		const struct mesh *l[2] = { &w->own.leaves, &w->vines.leaves };

		concat(&w->bark, b, 3);
		concat(&w->leaves, l, 2);
	}
	box_empty(&w->box);
	box_add(&w->box, &w->bark);
	box_add(&w->box, &w->leaves);
	w->triangles = tris(&w->bark) + tris(&w->leaves);
}

static void whole_finish(struct whole *w)
{
	tree_mesh_finish(&w->own);
	tree_mesh_finish(&w->vines);
	mesh_finish(&w->bark);
	mesh_finish(&w->leaves);
}

/* A vertex's position and normal, bitwise, for sorting and finding. */
struct key {
	float x[6];
};

static int key_cmp(const void *a, const void *b)
{
	return memcmp(a, b, sizeof(struct key));
}

static struct key key_of(const struct mesh *m, size_t v)
{
	struct key k;

	memcpy(k.x, &m->positions[3 * v], 3 * sizeof(float));
	memcpy(k.x + 3, &m->normals[3 * v], 3 * sizeof(float));
	return k;
}

static struct key *keys_sorted(const struct mesh *m)
{
	struct key *k = malloc((m->nvertices ? m->nvertices : 1) * sizeof(*k));

	CHECK(k);
	for (size_t v = 0; v < m->nvertices; v++)
		k[v] = key_of(m, v);
	qsort(k, m->nvertices, sizeof(*k), key_cmp);
	return k;
}

/* Every vertex that triangles [f0, f1) of m use is one of keys (n of them). */
static void check_own_vertices(const struct mesh *m, size_t f0, size_t f1, const struct key *keys,
			       size_t n)
{
	for (size_t i = 3 * f0; i < 3 * f1; i++) {
		struct key k = key_of(m, m->indices[i]);

		CHECK(bsearch(&k, keys, n, sizeof(k), key_cmp));
	}
}

/* Triangles [f0, f0 + those of part) of m are part's, byte for byte: its vertices after the
 * ones before (the first that they use), its indices moved on by as many. */
static void check_part_at(const struct mesh *m, size_t f0, const struct mesh *part)
{
	size_t v0;

	if (part->nindices == 0)
		return;
	CHECK(3 * f0 + part->nindices <= m->nindices);
	v0 = m->indices[3 * f0] - part->indices[0];
	CHECK(v0 + part->nvertices <= m->nvertices);
	CHECK(!memcmp(&m->positions[3 * v0], part->positions, 3 * part->nvertices * sizeof(float)));
	CHECK(!memcmp(&m->normals[3 * v0], part->normals, 3 * part->nvertices * sizeof(float)));
	for (size_t i = 0; i < part->nindices; i++)
		CHECK(m->indices[3 * f0 + i] == part->indices[i] + v0);
}

struct margins {
	double cover;
	size_t builds, full, coarser_wood, coarser_stems, shoots_left_out, carded;
	size_t least_wood_most; /* the most triangles the wood's fewest had */
	size_t least_stems_most; /* the most the stems had at the least */
};

/* t at budget against its whole w. */
static void check_one(const struct tree *t, const struct whole *w, const struct key *wood_keys,
		      size_t budget, bool again, struct margins *mg)
{
	struct tree_mesh out;
	struct forest_lod_stats st;
	struct box b;
	size_t tubes;

	tree_mesh_init(&out);
	CHECK_INT(forest_lod_build(t, budget, &out, &st), 0);
	check_mesh_sane(&out.bark);
	check_mesh_sane(&out.leaves);
	CHECK_INT(st.full_triangles, w->triangles);
	CHECK_INT(st.bark_triangles, tris(&out.bark));
	CHECK_INT(st.leaf_triangles, tris(&out.leaves));
	if (!(tris(&out.bark) + tris(&out.leaves) <= budget))
		fprintf(stderr, "%zu branches, wood %zu, %zu vines: %zu + %zu triangles at %zu\n",
			t->nbranches, w->wood ? tris(w->wood) : 0, t->nvines, tris(&out.bark),
			tris(&out.leaves), budget);
	CHECK(!st.over_budget);
	CHECK(tris(&out.bark) + tris(&out.leaves) <= budget);
	mg->builds++;
	if (w->triangles <= budget) {
		/* everything as it is, byte for byte */
		CHECK(mesh_bytes_equal(&out.bark, &w->bark));
		CHECK(mesh_bytes_equal(&out.leaves, &w->leaves));
		CHECK(st.level == 0 && st.stem_level == 0 && st.cards == 0);
		CHECK_INT(st.wood_triangles, w->wood ? tris(w->wood) : 0);
		CHECK_INT(st.stem_triangles, tris(&w->vines.bark));
		mg->full++;
	}
	/* the bark: the tubes, the wood's, the stems' */
	CHECK(st.wood_triangles + st.stem_triangles <= st.bark_triangles);
	tubes = st.bark_triangles - st.wood_triangles - st.stem_triangles;
	if (w->wood) {
		CHECK(st.wood_triangles > 0);
		check_own_vertices(&out.bark, tubes, tubes + st.wood_triangles, wood_keys,
				   w->wood->nvertices);
		mg->coarser_wood += st.wood_triangles < tris(w->wood);
	} else {
		CHECK_INT(st.wood_triangles, 0);
	}
	if (w->wood && st.wood_triangles == tris(w->wood))
		check_part_at(&out.bark, tubes, w->wood);
	if (st.stem_level == 0) {
		/* the vines' own stems, the last of the bark */
		CHECK_INT(st.stem_triangles, tris(&w->vines.bark));
		CHECK_INT(st.shoots_kept, st.shoots);
		check_part_at(&out.bark, st.bark_triangles - st.stem_triangles, &w->vines.bark);
	} else {
		mg->coarser_stems++;
		CHECK(st.stem_triangles < tris(&w->vines.bark));
	}
	/* the stems' vertices are the bark's last stem_vertices, theirs alone (the screen
	 * colours them as a vine's) */
	CHECK(st.stem_vertices <= out.bark.nvertices);
	CHECK(st.stem_level != 0 || st.stem_vertices == w->vines.bark.nvertices);
	for (size_t i = 0; i < out.bark.nindices; i++) {
		bool stem_tri = i / 3 >= st.bark_triangles - st.stem_triangles;

		CHECK(stem_tri == (out.bark.indices[i] >= out.bark.nvertices - st.stem_vertices));
	}
	mg->shoots_left_out += st.shoots_kept < st.shoots;
	mg->carded += st.cards > 0;
	/* the outline */
	box_empty(&b);
	box_add(&b, &out.bark);
	box_add(&b, &out.leaves);
	for (int k = 0; k < 3; k++) {
		double ext = w->box.hi[k] - w->box.lo[k];

		if (ext > 1e-3) {
			double cover = (b.hi[k] - b.lo[k]) / ext;

			if (!(cover >= 0.985))
				fprintf(stderr, "%zu branches, %zu leaves, wood %d, %zu vines, budget %zu: "
						"axis %d covered %.4f (level %d, %zu branches kept, wood "
						"%zu, stems %zu at level %d, %zu cards)\n", t->nbranches,
					t->nleaves, w->wood != NULL, t->nvines, budget, k, cover,
					st.level, st.branches_kept, st.wood_triangles,
					st.stem_triangles, st.stem_level, st.cards);
			CHECK(cover >= 0.985);
			mg->cover = fmin(mg->cover, cover);
		}
	}
	if (again) {
		struct tree_mesh out2;
		struct forest_lod_stats st2;

		tree_mesh_init(&out2);
		CHECK_INT(forest_lod_build(t, budget, &out2, &st2), 0);
		CHECK(mesh_bytes_equal(&out.bark, &out2.bark));
		CHECK(mesh_bytes_equal(&out.leaves, &out2.leaves));
		CHECK(!memcmp(&st, &st2, sizeof(st)));
		tree_mesh_finish(&out2);
	}
	tree_mesh_finish(&out);
}

/* The least of the stems, written out again: the shoots that reach farther along one of
 * +-x, +-y, +-z than all else (an axis point plus the stem's radius), and those they grew
 * from, each drawn with 3 sides through rings at its first and last points and at its
 * farthest along each axis. */
static size_t stems_least(const struct tree *t, const struct whole *w)
{
	double rest[6], far[6];
	size_t best[6], n = 0, at = 0, sum = 0;
	struct vec3 **axes;
	size_t *count, *vine_of, *shoot_of;
	bool *held;
	struct box b;

	for (size_t i = 0; i < t->nvines; i++)
		n += t->vines[i].nshoots;
	if (n == 0)
		return 0;
	axes = calloc(n, sizeof(*axes));
	count = calloc(n, sizeof(*count));
	vine_of = calloc(n, sizeof(*vine_of));
	shoot_of = calloc(n, sizeof(*shoot_of));
	held = calloc(n, sizeof(*held));
	CHECK(axes && count && vine_of && shoot_of && held);
	box_empty(&b);
	box_add(&b, &w->own.bark);
	box_add(&b, &w->own.leaves);
	box_add(&b, &w->vines.leaves);
	box_add(&b, w->wood);
	for (int d = 0; d < 6; d++) {
		rest[d] = d % 2 ? -b.lo[d / 2] : b.hi[d / 2];
		far[d] = -INFINITY;
		best[d] = SIZE_MAX;
	}
	for (size_t i = 0; i < t->nvines; i++) {
		for (size_t s = 0; s < t->vines[i].nshoots; s++, at++) {
			CHECK_INT(vine_smooth(&t->vines[i], s, &axes[at]), 0);
			count[at] = t->vines[i].shoots[s].n;
			vine_of[at] = i;
			shoot_of[at] = s;
			for (size_t k = 0; count[at] >= 2 && k < count[at]; k++) {
				for (int d = 0; d < 6; d++) {
					struct vec3 p = axes[at][k];
					double x = (d / 2 == 0 ? p.x : d / 2 == 1 ? p.y : p.z) *
						   (d % 2 ? -1.0 : 1.0) + t->vines[i].p.radius;

					if (x > far[d]) {
						far[d] = x;
						best[d] = at;
					}
				}
			}
		}
	}
	for (int d = 0; d < 6; d++) {
		size_t i = far[d] > rest[d] ? best[d] : SIZE_MAX;

		while (i != SIZE_MAX) {
			int p = t->vines[vine_of[i]].shoots[shoot_of[i]].parent;

			held[i] = true;
			i = p >= 0 && (size_t)p < shoot_of[i] ? i - shoot_of[i] + (size_t)p : SIZE_MAX;
		}
	}
	for (size_t i = 0; i < n; i++) {
		size_t rings = 0;

		if (!held[i] || count[i] < 2)
			continue;
		for (size_t k = 0; k < count[i]; k++) {
			bool ring = k == 0 || k + 1 == count[i];

			for (int d = 0; d < 6 && !ring; d++) {
				size_t first = 0;
				double bx = -INFINITY;

				for (size_t j = 0; j < count[i]; j++) {
					struct vec3 p = axes[i][j];
					double x = (d / 2 == 0 ? p.x : d / 2 == 1 ? p.y : p.z) *
						   (d % 2 ? -1.0 : 1.0);

					if (x > bx) {
						bx = x;
						first = j;
					}
				}
				ring = first == k;
			}
			rings += ring;
		}
		sum += 2 * 3 * (rings - 1) + 3;
	}
	for (size_t i = 0; i < n; i++)
		free(axes[i]);
	free(held);
	free(shoot_of);
	free(vine_of);
	free(count);
	free(axes);
	return sum;
}

/* A budget of 0: the trunk's tube at the coarsest level (none if the wood holds it), the
 * wood at its fewest, the stems that hold the outline through it alone, one card when
 * there are leaves. */
static void check_least(const struct tree *t, const struct whole *w, struct margins *mg)
{
	struct tree_mesh out, trunk;
	struct tree_mesh_marks mk;
	struct forest_lod_stats st;
	const size_t zero = 0;
	size_t fewest = 0;

	tree_mesh_init(&out);
	tree_mesh_init(&trunk);
	tree_mesh_marks_init(&mk);
	CHECK_INT(forest_lod_build(t, 0, &out, &st), 0);
	CHECK_INT(tree_mesh_build_parts_coarse(&trunk, &mk, t, &zero, 1, NULL, 0,
					       &forest_lod_levels[FOREST_LOD_LEVELS - 1]), 0);
	if (w->wood) {
		struct mesh m;

		mesh_init(&m);
		CHECK_INT(forest_lod_decimate(w->wood, 0, &m, &fewest), 0);
		CHECK_INT(tris(&m), fewest);
		mesh_finish(&m);
		mg->least_wood_most = fewest > mg->least_wood_most ? fewest : mg->least_wood_most;
	}
	CHECK_INT(st.wood_triangles, fewest);
	CHECK_INT(st.stem_triangles, stems_least(t, w));
	CHECK(st.stem_triangles == 0 || st.stem_level == FOREST_LOD_STEM_OUTLINE ||
	      st.stem_level == 0);
	mg->least_stems_most = st.stem_triangles > mg->least_stems_most ? st.stem_triangles
									 : mg->least_stems_most;
	CHECK_INT(st.bark_triangles, tris(&trunk.bark) + fewest + st.stem_triangles);
	CHECK_INT(st.leaf_triangles, tris(&w->leaves) ? 2 : 0);
	tree_mesh_marks_finish(&mk);
	tree_mesh_finish(&trunk);
	tree_mesh_finish(&out);
}

/* The part at budget: every vertex bound; at its own count the wood's and the vines'
 * vertices bound as the screen binds them. */
static void check_part(const struct tree *t, const struct whole *w, size_t budget,
		       size_t *bound)
{
	struct forest_part p;
	struct live_skeleton sk;
	struct live_attrs a;

	forest_part_init(&p);
	live_attrs_init(&a);
	CHECK_INT(forest_part_build(&p, t, 5, budget, 0.5), 0);
	CHECK_INT(p.bark.n, p.mesh.bark.nvertices);
	CHECK_INT(p.leaves.n, p.mesh.leaves.nvertices);
	for (size_t v = 0; v < p.bark.n; v++)
		CHECK(isfinite(p.bark.v[v].point[0]) && isfinite(p.bark.v[v].d) &&
		      isfinite(p.bark.v[v].w[0]));
	for (size_t v = 0; v < p.leaves.n; v++)
		CHECK(isfinite(p.leaves.v[v].point[1]) && isfinite(p.leaves.v[v].d));
	*bound += p.bark.n + p.leaves.n;
	if (w->triangles <= budget) {
		const struct mesh *m[3] = { w->wood, &w->vines.bark, &w->vines.leaves };
		const struct live_attrs *in[3] = { &p.bark, &p.bark, &p.leaves };
		size_t at[3] = { w->own.bark.nvertices,
				 w->own.bark.nvertices + (w->wood ? w->wood->nvertices : 0),
				 w->own.leaves.nvertices };

		CHECK_INT(live_skeleton_init(&sk, t, 5), 0);
		for (int k = 0; k < 3; k++) {
			if (!m[k] || m[k]->nvertices == 0)
				continue;
			CHECK_INT(live_attrs_bind_nearest(&a, &sk, t, m[k]), 0);
			CHECK(at[k] + a.n <= in[k]->n);
			CHECK(!memcmp(&in[k]->v[at[k]], a.v, a.n * sizeof(*a.v)));
		}
		live_skeleton_finish(&sk);
	}
	live_attrs_finish(&a);
	forest_part_finish(&p);
}

/* ---- the wood made coarser alone ------------------------------------------------------- */

struct edge {
	uint32_t lo, hi, from; /* its ends, and where it runs from */
};

static int edge_cmp(const void *pa, const void *pb)
{
	const struct edge *a = pa, *b = pb;

	if (a->lo != b->lo)
		return a->lo < b->lo ? -1 : 1;
	if (a->hi != b->hi)
		return a->hi < b->hi ? -1 : 1;
	return a->from < b->from ? -1 : a->from > b->from ? 1 : 0;
}

/* A closed, consistently oriented manifold: every edge in exactly two faces, once each
 * way; no face with a vertex twice. Returns V - E + F over the vertices used. */
static long check_closed(const struct mesh *m)
{
	size_t nf = tris(m), ne = 3 * nf, used = 0;
	struct edge *e = malloc((ne ? ne : 1) * sizeof(*e));
	bool *u = calloc(m->nvertices ? m->nvertices : 1, 1);

	CHECK(e && u);
	for (size_t f = 0; f < nf; f++) {
		const uint32_t *v = &m->indices[3 * f];

		CHECK(v[0] != v[1] && v[1] != v[2] && v[0] != v[2]);
		for (int k = 0; k < 3; k++) {
			uint32_t a = v[k], b = v[(k + 1) % 3];

			e[3 * f + (size_t)k] = (struct edge){ a < b ? a : b, a < b ? b : a, a };
			u[a] = true;
		}
	}
	qsort(e, ne, sizeof(*e), edge_cmp);
	for (size_t i = 0; i < ne;) {
		size_t j = i;

		while (j < ne && e[j].lo == e[i].lo && e[j].hi == e[i].hi)
			j++;
		/* two faces, one running each way */
		CHECK_INT(j - i, 2);
		CHECK(e[i].from != e[i + 1].from);
		i = j;
	}
	for (size_t v = 0; v < m->nvertices; v++)
		used += u[v];
	free(u);
	free(e);
	return (long)used - (long)(ne / 2) + (long)nf;
}

struct dec_margins {
	size_t cases, fewest_most, over;
};

static void check_decimate(const struct mesh *wood, const struct key *keys, struct rng *r,
			   struct dec_margins *dm)
{
	long chi = check_closed(wood);
	size_t n = tris(wood), fewest;
	struct box wb, db;

	box_empty(&wb);
	box_add(&wb, wood);
	for (int c = 0; c < 2; c++) {
		size_t max = c == 0 ? 0 : (size_t)exp(rng_range(r, log(4.0), log((double)n)));
		struct mesh m, m2;

		mesh_init(&m);
		mesh_init(&m2);
		CHECK_INT(forest_lod_decimate(wood, max, &m, &fewest), 0);
		CHECK(tris(&m) <= (max > fewest ? max : fewest));
		/* two triangles a collapse: at most one fewer than asked, unless at its fewest */
		CHECK(tris(&m) + 1 >= max || tris(&m) == fewest);
		dm->over += tris(&m) > max;
		CHECK_INT(check_closed(&m), chi);
		check_own_vertices(&m, 0, tris(&m), keys, wood->nvertices);
		box_empty(&db);
		box_add(&db, &m);
		CHECK(!memcmp(&db, &wb, sizeof(db)));
		if (c == 1) {
			CHECK_INT(forest_lod_decimate(wood, max, &m2, NULL), 0);
			CHECK(mesh_bytes_equal(&m, &m2));
		}
		dm->cases++;
		dm->fewest_most = fewest > dm->fewest_most ? fewest : dm->fewest_most;
		mesh_finish(&m2);
		mesh_finish(&m);
	}
}

/* ---- colours ----------------------------------------------------------------------------- */

/* A vined tree as it is in autumn: its vines' leaves the palette's first colour, after
 * the tree's own; in winter no colours. */
static void test_colors(void)
{
	struct tree t;
	struct rng r;
	struct whole w;
	struct tree_mesh out;
	struct forest_lod_colors col;
	struct forest_lod_stats st;
	const struct season_rgb *pal;
	size_t own;

	tree_init(&t);
	tree_mesh_init(&out);
	forest_lod_colors_init(&col);
	rng_seed(&r, 4);
	live_trees_random(&t, 40, 4, 9, 6.0);
	plant_vines(&t, &r, 2, 9);
	CHECK(t.nvines == 2);
	t.season = SEASON_AUTUMN;
	CHECK(season_palette(t.season, &pal) > 1);
	whole_build(&w, &t);
	own = w.own.leaves.nvertices;
	CHECK(w.vines.leaves.nvertices > 0);
	CHECK_INT(forest_lod_build_colors(&t, w.triangles, &out, &col, &st), 0);
	CHECK_INT(col.n, own + w.vines.leaves.nvertices);
	for (size_t v = own; v < col.n; v++)
		CHECK(col.rgb[3 * v] == pal[0].r && col.rgb[3 * v + 1] == pal[0].g &&
		      col.rgb[3 * v + 2] == pal[0].b);
	/* cards of the vines' leaves alone: the palette's first colour too */
	t.season = SEASON_WINTER;
	CHECK_INT(forest_lod_build_colors(&t, w.triangles, &out, &col, &st), 0);
	CHECK_INT(col.n, 0);
	whole_finish(&w);
	forest_lod_colors_finish(&col);
	tree_mesh_finish(&out);
	tree_finish(&t);
	printf("colours: a vine's leaves the palette's first colour in autumn, none in winter\n");
}

int main(void)
{
	struct rng r;
	int cases = test_cases(300);
	struct made made = { 0 };
	struct margins mg = { INFINITY, 0, 0, 0, 0, 0, 0, 0, 0 };
	struct dec_margins dm = { 0 };
	size_t bound = 0;

	test_colors();
	rng_seed(&r, 2717);
	for (int c = 0; c < cases; c++) {
		struct tree t;
		struct whole w;
		struct key *wood_keys = NULL;

		tree_init(&t);
		grown_tree(&t, &r, 1000 + (uint64_t)c, &made);
		whole_build(&w, &t);
		if (w.wood) {
			wood_keys = keys_sorted(w.wood);
			check_decimate(w.wood, wood_keys, &r, &dm);
		}
		for (int b = 0; b < 2; b++)
			check_one(&t, &w, wood_keys,
				  (size_t)exp(rng_range(&r, log(500.0), log(300000.0))), b == 0, &mg);
		check_one(&t, &w, wood_keys, w.triangles, false, &mg);
		if (w.triangles > 500) {
			check_one(&t, &w, wood_keys, w.triangles - 1, false, &mg);
			check_one(&t, &w, wood_keys,
				  (size_t)exp(rng_range(&r, log(500.0), log((double)w.triangles))),
				  false, &mg);
		}
		check_least(&t, &w, &mg);
		check_part(&t, &w, w.triangles, &bound);
		if (c % 4 == 0)
			check_part(&t, &w, 1 + rng_next(&r) % (w.triangles + 1), &bound);
		free(wood_keys);
		whole_finish(&w);
		tree_finish(&t);
	}
	printf("trees: %zu (%zu grown, %zu with vines, %zu both; %zu vines, %zu presses)\n",
	       made.trees, made.grown, made.vined, made.both, made.vines, made.presses);
	printf("builds: %zu within their budgets (%zu everything as it is, byte for byte; %zu "
	       "with the wood made coarser, %zu the stems, %zu with shoots left out, %zu with "
	       "cards)\n", mg.builds, mg.full, mg.coarser_wood, mg.coarser_stems,
	       mg.shoots_left_out, mg.carded);
	printf("  outline: least cover of the full extent (wood and vines in it) %.4f (at least "
	       "0.985)\n", mg.cover);
	printf("  the least: the wood at its fewest, at most %zu triangles; the stems that hold "
	       "the outline, at most %zu\n", mg.least_wood_most, mg.least_stems_most);
	printf("parts: %zu vertices bound; the wood's and the vines' as the screen binds them\n",
	       bound);
	printf("the wood made coarser: %zu meshes, closed manifolds with their Euler "
	       "characteristic and box, their own vertices; fewest at most %zu triangles, %zu "
	       "over what was asked (at their fewest)\n", dm.cases, dm.fewest_most, dm.over);
	return 0;
}
