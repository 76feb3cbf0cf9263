/* SPDX-License-Identifier: MIT */
/*
 * The forest as the screen draws it (src/forest/forest_scene.c, docs/forest.md): 60
 * seeded random forests of 1 to 40 trees (random trees of 1 to 300 branches, 0 to 20
 * leaves each, 2 to 15 m, and the functional trees' presets), each tree a part at its
 * share of 300,000 triangles, placed by forest_layout:
 *
 * - the parts: within their budgets, their living data one a vertex, their wind over the
 *   common 8 s loop, their trunk harmonic its own;
 * - the scene: each tree's vertices and indices one range in the given order, together
 *   all of them; its indices within its own vertices; each vertex where its part has it
 *   moved by the tree's place (its foot onto its position), its skeleton point with it;
 *   w0 scaled by the tree's own sway against the frame's (so the frame's amplitude times
 *   the weight is the tree's own: checked), never above 1; each vertex's trunk harmonic
 *   and phase its tree's; at most 300,000 triangles; the same bytes when built again; an
 *   empty forest empty, the serial bumped at each build;
 * - each tree's growing in: live_grow_setup's rule from the farthest path length of its
 *   vertices, so that at its end every vertex of it is a swell behind the front (drawn
 *   whole) and at its start none but its foot's is drawn.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "forest.h"
#include "live_trees.h"
#include "rng.h"
#include "test.h"

#define TOTAL 300000
#define MAXN 40

static void check_range(const struct mesh *m, const size_t vr[2], const size_t ir[2])
{
	for (size_t i = ir[0]; i < ir[1]; i++)
		CHECK(m->indices[i] >= vr[0] && m->indices[i] < vr[1]);
}

int main(void)
{
	static struct tree trees[MAXN];
	static struct forest_part parts[MAXN];
	const struct forest_part *pp[MAXN];
	struct forest_scene s, again;
	struct rng r;
	int cases = test_cases(60);
	size_t checked = 0, most_tris = 0, grown = 0;
	double worst_amp = 0.0;

	rng_seed(&r, 2727);
	forest_scene_init(&s);
	forest_scene_init(&again);
	for (int c = 0; c < cases; c++) {
		size_t n = 1 + (size_t)(rng_next(&r) % (c % 5 == 0 ? MAXN : 8));
		uint64_t numbers[MAXN];
		double widths[MAXN], xz[2 * MAXN], pos[3 * MAXN];
		size_t share[MAXN], tris = 0;
		uint64_t serial = s.serial;

		for (size_t i = 0; i < n; i++) {
			tree_init(&trees[i]);
			if (rng_next(&r) % 4 == 0)
				live_trees_preset(&trees[i], (enum gen_preset)(rng_next(&r) % GEN_PRESET_COUNT));
			else
				live_trees_random(&trees[i], 1 + (int)(rng_next(&r) % 300),
						  (int)(rng_next(&r) % 21), 100 + (uint64_t)c * 64 + i,
						  rng_range(&r, 2.0, 15.0));
			numbers[i] = 1 + (uint64_t)c + i;
			widths[i] = forest_tree_crown_width(&trees[i]);
		}
		forest_lod_shares(widths, NULL, n, TOTAL, share);
		CHECK(forest_layout(numbers, widths, n, MAXN, xz) > 0);
		for (size_t i = 0; i < n; i++) {
			forest_part_init(&parts[i]);
			CHECK(forest_part_build(&parts[i], &trees[i], 7 + i, share[i], 0.35) == 0);
			CHECK(parts[i].mesh.bark.nindices / 3 + parts[i].mesh.leaves.nindices / 3 <=
			      (share[i] > 20 ? share[i] : 20));
			CHECK(parts[i].bark.n == parts[i].mesh.bark.nvertices);
			CHECK(parts[i].leaves.n == parts[i].mesh.leaves.nvertices);
			CHECK(parts[i].wind.loop == LIVE_WIND_COMMON_LOOP_S);
			CHECK(parts[i].harmonic0 == parts[i].wind.harmonic[0] && parts[i].harmonic0 >= 1);
			pp[i] = &parts[i];
			pos[3 * i] = xz[2 * i];
			pos[3 * i + 1] = 0.0;
			pos[3 * i + 2] = xz[2 * i + 1];
		}
		CHECK(forest_scene_build(&s, pp, numbers, pos, n) == 0);
		CHECK(s.serial == serial + 1 && s.ntrees == n);
		CHECK(s.bark.n == s.mesh.bark.nvertices && s.leaves.n == s.mesh.leaves.nvertices);
		for (size_t i = 0; i < n; i++) {
			const struct forest_scene_tree *t = &s.trees[i];
			const struct forest_part *p = &parts[i];
			double shift[3], scale = p->amp0 / s.wind.amp0;

			for (int k = 0; k < 3; k++)
				shift[k] = pos[3 * i + k] - p->foot[k];
			CHECK(t->number == numbers[i]);
			CHECK(t->bark_vertices[0] == (i ? s.trees[i - 1].bark_vertices[1] : 0));
			CHECK(t->leaves_indices[0] == (i ? s.trees[i - 1].leaves_indices[1] : 0));
			CHECK(t->bark_vertices[1] - t->bark_vertices[0] == p->mesh.bark.nvertices);
			CHECK(t->leaves_indices[1] - t->leaves_indices[0] == p->mesh.leaves.nindices);
			check_range(&s.mesh.bark, t->bark_vertices, t->bark_indices);
			check_range(&s.mesh.leaves, t->leaves_vertices, t->leaves_indices);
			CHECK(scale <= 1.0 + 1e-12);
			{
				struct live_skeleton sk = { .d_max = 0.0 };
				struct live_grow g;

				for (size_t v = 0; v < p->bark.n; v++)
					sk.d_max = fmax(sk.d_max, p->bark.v[v].d);
				for (size_t v = 0; v < p->leaves.n; v++)
					sk.d_max = fmax(sk.d_max, p->leaves.v[v].d);
				live_grow_setup(&g, &sk);
				CHECK(!memcmp(&g, &t->grow, sizeof(g)));
				CHECK(t->grow.duration >= LIVE_GROW_MIN_S &&
				      t->grow.duration <= LIVE_GROW_MAX_S);
				for (size_t v = t->bark_vertices[0]; v < t->bark_vertices[1]; v++) {
					float d = s.bark.v[v].d;

					CHECK(live_grow_pull(&t->grow, live_grow_front(&t->grow, 1e9), d) == 1.0);
					CHECK(live_grow_visible(live_grow_front(&t->grow, 0.0), d) == (d <= 0.0f));
					grown++;
				}
				for (size_t v = t->leaves_vertices[0]; v < t->leaves_vertices[1]; v++)
					CHECK(live_grow_pull(&t->grow, t->grow.d_end, s.leaves.v[v].d) == 1.0);
			}
			for (size_t v = 0; v < p->mesh.bark.nvertices; v++) {
				size_t w = t->bark_vertices[0] + v;
				const struct live_vertex *a = &p->bark.v[v], *b = &s.bark.v[w];

				for (int k = 0; k < 3; k++) {
					CHECK(s.mesh.bark.positions[3 * w + k] ==
					      (float)(p->mesh.bark.positions[3 * v + k] + shift[k]));
					CHECK(b->point[k] == (float)(a->point[k] + shift[k]));
				}
				CHECK(b->w[0] == (float)(a->w[0] * scale) && b->w[0] <= 1.0f);
				/* the frame's sway times the placed weight is the tree's own */
				worst_amp = fmax(worst_amp, fabs(s.wind.amp0 * b->w[0] - p->amp0 * a->w[0]));
				CHECK(s.bark_trunk[2 * w] == p->harmonic0 && s.bark_trunk[2 * w + 1] == p->phase0);
				checked++;
			}
			tris += p->mesh.bark.nindices / 3 + p->mesh.leaves.nindices / 3;
		}
		CHECK(tris == (s.mesh.bark.nindices + s.mesh.leaves.nindices) / 3);
		CHECK(tris <= TOTAL + 20 * n);
		most_tris = tris > most_tris ? tris : most_tris;
		/* again: the same bytes */
		CHECK(forest_scene_build(&again, pp, numbers, pos, n) == 0);
		CHECK(again.mesh.bark.nvertices == s.mesh.bark.nvertices);
		CHECK(!memcmp(again.mesh.bark.positions, s.mesh.bark.positions,
			      3 * sizeof(float) * s.mesh.bark.nvertices));
		CHECK(!memcmp(again.leaves.v, s.leaves.v, sizeof(*s.leaves.v) * s.leaves.n));
		for (size_t i = 0; i < n; i++) {
			forest_part_finish(&parts[i]);
			tree_finish(&trees[i]);
		}
	}
	CHECK(worst_amp < 1e-6);
	CHECK(forest_scene_build(&s, NULL, NULL, NULL, 0) == 0);
	CHECK(s.ntrees == 0 && s.mesh.bark.nvertices == 0);
	forest_scene_finish(&s);
	forest_scene_finish(&again);
	printf("forest scene: %d random forests, %zu bark vertices placed as their parts; the "
	       "largest %zu triangles; the shared frame's trunk sway the tree's own within %.1g m; "
	       "%zu bark vertices drawn whole at their tree's growth's end\n",
	       cases, checked, most_tris, worst_amp, grown);
	return 0;
}
