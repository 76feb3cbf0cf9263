/* SPDX-License-Identifier: MIT */
/*
 * The living tree (src/live/, docs/living-trees.md): what binding a tree's meshes to its
 * skeleton costs, and what a frame of wind and growth costs.
 *
 * Synthetic trees (tests/tools/synth_tree.c) of 62 and 1,000 branches with 20,000 leaves
 * in all (323 and 20 a branch), then 62..1,000 branches with 20 leaves each for the
 * growth with size. For each: the skeleton (live_skeleton_init), binding the bark by its
 * marks and without them (meshing again to find them), the leaves, and the bark by the
 * nearest skeleton point (what the wood's iso-surface and vines take); the vertices and
 * the bytes their data takes. Per frame: live_wind_frame + live_wind_weights +
 * live_grow_front (what the app computes a frame: it must not grow with the tree), and
 * live_wind_frame_offset per vertex (the reference the shader mirrors, on the CPU).
 * Medians. Last, what the wind would add to model.glb as morph targets (cherry, the
 * trees above): the still model's bytes against LIVE_WIND_TARGETS targets as floats, and
 * quantised (KHR_mesh_quantization: normalised BYTE deltas padded to 4 bytes, each
 * target's scale in its weights; a primitive's all-zero targets, the bark's leaf flutter,
 * with no buffer view), plus the weights' keyframes (a cubic spline, 8 keys a cycle of
 * the fastest harmonic).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_util.h"
#include "buf.h"
#include "export.h"
#include "gen.h"
#include "live.h"
#include "mesh.h"
#include "synth_tree.h"

#define REPS 5
#define SEED 26
#define FRAME_CALLS 100000

struct fixture {
	struct tree t;
	struct tree_mesh tm;
	struct tree_mesh_marks mk;
	struct live_skeleton sk;
	struct live_attrs bark, leaves;
	struct live_wind w;
	struct live_grow g;
};

static void setup(struct fixture *f, int nbranches, int leaves_per_branch)
{
	struct live_wind_params p = { .strength = LIVE_WIND_DEFAULT_STRENGTH, .angle = 0.0 };

	tree_init(&f->t);
	tree_mesh_init(&f->tm);
	tree_mesh_marks_init(&f->mk);
	live_attrs_init(&f->bark);
	live_attrs_init(&f->leaves);
	if (synth_tree(&f->t, nbranches, leaves_per_branch, SEED) < 0 ||
	    tree_mesh_build_marked(&f->tm, &f->t, &f->mk) < 0 ||
	    live_skeleton_init(&f->sk, &f->t, SEED) < 0 || live_wind_setup(&f->w, &f->sk, &p) < 0) {
		fprintf(stderr, "bench_live: no memory\n");
		exit(1);
	}
	live_grow_setup(&f->g, &f->sk);
}

static void teardown(struct fixture *f)
{
	live_attrs_finish(&f->leaves);
	live_attrs_finish(&f->bark);
	live_skeleton_finish(&f->sk);
	tree_mesh_marks_finish(&f->mk);
	tree_mesh_finish(&f->tm);
	tree_finish(&f->t);
}

static void must(int r, const char *what)
{
	if (r < 0) {
		fprintf(stderr, "bench_live: %s failed (%d)\n", what, r);
		exit(1);
	}
}

static void skeleton(void *arg)
{
	struct fixture *f = arg;

	live_skeleton_finish(&f->sk);
	must(live_skeleton_init(&f->sk, &f->t, SEED), "live_skeleton_init");
}

static void bind_bark(void *arg)
{
	struct fixture *f = arg;

	must(live_attrs_bind_bark(&f->bark, &f->sk, &f->t, &f->tm.bark, &f->mk), "bind bark");
}

static void bind_bark_unmarked(void *arg)
{
	struct fixture *f = arg;

	must(live_attrs_bind_bark(&f->bark, &f->sk, &f->t, &f->tm.bark, NULL), "bind bark");
}

static void bind_leaves(void *arg)
{
	struct fixture *f = arg;

	must(live_attrs_bind_leaves(&f->leaves, &f->sk, &f->t, &f->tm.leaves, &f->mk), "bind leaves");
}

static void bind_nearest(void *arg)
{
	struct fixture *f = arg;

	must(live_attrs_bind_nearest(&f->bark, &f->sk, &f->t, &f->tm.bark), "bind nearest");
}

static volatile double sink;

/* What the app computes a frame: the wind's frame, the weights (an export's, here as a
 * stand-in for a morph-target player's), the growth's front. */
static void per_frame(void *arg)
{
	struct fixture *f = arg;
	struct live_wind_frame fr;
	double g[LIVE_WIND_TARGETS], acc = 0.0;

	for (int i = 0; i < FRAME_CALLS; i++) {
		double t = 0.0333 * i;

		live_wind_frame(&f->w, t, live_wind_angle(&f->w, t), &fr);
		live_wind_weights(&f->w, t, g);
		acc += fr.theta[1] + g[3] + live_grow_front(&f->g, t);
	}
	sink = acc;
}

static void offsets(void *arg)
{
	struct fixture *f = arg;
	struct live_wind_frame fr;
	double acc = 0.0;

	live_wind_frame(&f->w, 1.25, f->w.angle, &fr);
	for (size_t i = 0; i < f->leaves.n; i++)
		acc += live_wind_frame_offset(&fr, &f->leaves.v[i]).x;
	for (size_t i = 0; i < f->bark.n; i++)
		acc += live_wind_frame_offset(&fr, &f->bark.v[i]).x;
	sink = acc;
}

/* model.glb's bytes for t, and what the wind's morph targets would add to it. */
static void export_sizes(const char *name, const struct tree *t)
{
	struct tree_mesh tm;
	struct tree_mesh_marks mk;
	struct live_skeleton sk;
	struct live_wind w;
	struct live_wind_params p = { .strength = LIVE_WIND_DEFAULT_STRENGTH, .angle = 0.0 };
	struct buf glb;
	double nb, nl, floats, quant, keys, sampler;

	tree_mesh_init(&tm);
	tree_mesh_marks_init(&mk);
	buf_init(&glb);
	must(tree_mesh_build_marked(&tm, t, &mk), "tree_mesh_build_marked");
	must(export_glb(t, &tm, &mk, &glb), "export_glb");
	must(live_skeleton_init(&sk, t, SEED), "live_skeleton_init");
	must(live_wind_setup(&w, &sk, &p), "live_wind_setup");
	nb = (double)tm.bark.nvertices;
	nl = (double)tm.leaves.nvertices;
	floats = (nb + nl) * LIVE_WIND_TARGETS * 12.0;
	/* BYTE x 3 + 1 of padding a target; the bark's two flutter targets: no buffer view */
	quant = nb * (LIVE_WIND_TARGETS - 2) * 4.0 + nl * LIVE_WIND_TARGETS * 4.0;
	keys = 8.0 * w.harmonic[LIVE_BANDS] + 1;
	sampler = keys * 4.0 + keys * LIVE_WIND_TARGETS * 3 * 4.0;
	printf("%-14s model.glb %8.1f KB (%zu + %zu vertices); wind as float targets +%.1f KB, "
	       "quantised +%.1f KB (%.0f%% of the still model), keyframes %.1f KB\n",
	       name, glb.len / 1e3, tm.bark.nvertices, tm.leaves.nvertices, floats / 1e3,
	       (quant + sampler) / 1e3, 100.0 * (quant + sampler) / (double)glb.len,
	       sampler / 1e3);
	live_skeleton_finish(&sk);
	buf_finish(&glb);
	tree_mesh_marks_finish(&mk);
	tree_mesh_finish(&tm);
}

static void one_tree(int nbranches, int leaves_per_branch, int reps)
{
	struct fixture f;
	double s, nv;
	size_t bytes;

	setup(&f, nbranches, leaves_per_branch);
	printf("\n%d branches, %zu leaves: %zu bark + %zu leaf vertices\n", nbranches, f.t.nleaves,
	       f.tm.bark.nvertices, f.tm.leaves.nvertices);
	printf("  skeleton                    %10.3f ms\n", bench_run(skeleton, &f, reps) * 1e3);
	printf("  bind bark (marks)           %10.3f ms\n", bench_run(bind_bark, &f, reps) * 1e3);
	printf("  bind bark (no marks)        %10.3f ms\n", bench_run(bind_bark_unmarked, &f, reps) * 1e3);
	printf("  bind leaves (marks)         %10.3f ms\n", bench_run(bind_leaves, &f, reps) * 1e3);
	printf("  bind bark by nearest        %10.3f ms\n", bench_run(bind_nearest, &f, reps) * 1e3);
	bind_bark(&f);
	nv = (double)(f.bark.n + f.leaves.n);
	bytes = (f.bark.n + f.leaves.n) * sizeof(struct live_vertex);
	printf("  per-vertex data             %10zu B a vertex, %.1f MB in all (positions and "
	       "normals: %.1f MB)\n",
	       sizeof(struct live_vertex), bytes / 1e6, nv * 24 / 1e6);
	s = bench_run(per_frame, &f, reps);
	printf("  a frame's numbers           %10.1f ns (wind frame, weights, growth front)\n",
	       s / FRAME_CALLS * 1e9);
	s = bench_run(offsets, &f, reps);
	printf("  offset on the CPU           %10.1f ns a vertex (%.1f ms for all)\n", s / nv * 1e9,
	       s * 1e3);
	teardown(&f);
}

int main(int argc, char **argv)
{
	static const int sizes[] = { 62, 125, 250, 500, 1000 };
	double prev_size = 0.0, prev_s = 0.0, nprev = 0.0, nprev_s = 0.0;
	int reps;

	if (bench_init(&argc, argv, NULL))
		return 1;
	reps = bench_reps(REPS);
	printf("bench_live: binding meshes to the skeleton, a frame's wind and growth (medians of %d)\n",
	       reps);
	one_tree(62, 323, reps);
	if (!bench_quick)
		one_tree(1000, 20, reps);

	printf("\ngrowth with size (20 leaves a branch): bark and leaves bound by marks; by nearest\n");
	for (size_t i = 0; i < BENCH_COUNT(sizes); i++) {
		struct fixture f;
		double s;

		setup(&f, sizes[i], 20);
		s = bench_run(bind_bark, &f, reps) + bench_run(bind_leaves, &f, reps);
		bench_row("bind (marks)", sizes[i], s, &prev_size, &prev_s);
		s = bench_run(bind_nearest, &f, reps);
		bench_row("bind bark by nearest", sizes[i], s, &nprev, &nprev_s);
		teardown(&f);
	}

	printf("\nthe wind in model.glb (estimated from the meshes)\n");
	{
		struct tree t;
		struct gen_params gp;
		struct error err = { { 0 } };

		tree_init(&t);
		must(gen_preset(GEN_PRESET_CHERRY, &gp, &err), "gen_preset");
		must(gen_build(&t, &gp, 1), "gen_build");
		export_sizes("cherry", &t);
		must(synth_tree(&t, 62, 10, SEED), "synth_tree");
		export_sizes("62 branches", &t);
		if (!bench_quick) {
			must(synth_tree(&t, 1000, 20, SEED), "synth_tree");
			export_sizes("1,000 branches", &t);
		}
		tree_finish(&t);
	}
	return 0;
}
