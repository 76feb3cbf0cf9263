/* SPDX-License-Identifier: MIT */
/*
 * Headless frame time at the kiosk's 1280x800: synthetic trees of 62..500 branches with
 * 10 leaves each, drawn by the renderer into llvmpipe, the buttons labelled (the font
 * platform/files/font_file.c finds; the glyphs go into the UI's one draw call). For each tree:
 * a frame that uploads the meshes (what follows a finished stroke), a steady frame with
 * nothing to upload (what the pen's hover costs), and reading the frame back (what
 * --headless and the golden tests pay). Medians of FRAMES_MAX frames; glFinish() so the time
 * is the work done, not the work queued.
 * Then the tree propagation makes: 20 leaves on one branch propagated (fixed count) onto
 * every branch of 250..1,000-branch trees, up to 20,000 leaves: the propagation's time,
 * and, with the leaves drawn instanced (GLES 3: a call a leaf shape, leaf_instances.c) and
 * merged (one mesh of every leaf, as on GLES 2): the frame's time and draw calls, the
 * upload alone (what follows an edit: grouping the leaves included) and the bytes it
 * sends to the GPU. Then the main thread's CPU time a frame by leaf count, and on the
 * smallest tree what the labels cost: frames with and without them, interleaved. Then the
 * functional trees' presets in summer and in autumn; and 20,000 origami leaves of each
 * preset, at rest and unfolding. Last, the living tree (issue 26): still, growing in and in
 * the wind, edaha's own CPU time a frame apart from the whole frame.
 */
#include <GLES2/gl2.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "app.h"
#include "app_private.h"
#include "bench_util.h"
#include "egl_headless.h"
#include "font_file.h"
#include "gen.h"
#include "mesh.h"
#include "ori_kinds.h"
#include "ori_place.h"
#include "propagate.h"
#include "render.h"
#include "render_private.h"
#include "synth_tree.h"

#define WIDTH 1280
#define HEIGHT 800
#define FRAMES_MAX 7
#define LEAVES_PER_BRANCH 10
#define SEED 7

static int frames = FRAMES_MAX; /* bench_reps(FRAMES_MAX) */

static const int sizes[] = { 62, 125, 250, 500 };
#define NSIZES (sizeof(sizes) / sizeof(sizes[0]))

struct result {
	double upload_s, steady_s, readback_s, upload_only_s;
	size_t triangles, tree_triangles, upload_bytes, leaf_bytes;
	unsigned draw_calls;
};

struct bench {
	struct egl_headless *egl;
	struct render *render;
	struct app *app;
	uint8_t *rgba;
	int failed;
	const char *font; /* the labels' font file */
	uint64_t now_us;  /* the frames' time (UINT64_MAX: settled) */
	size_t font_len;
};

static void frame(struct bench *b)
{
	int r = render_frame_at(b->render, b->app, b->now_us);

	if (r < 0 && !b->failed) {
		fprintf(stderr, "bench_frame: render_frame: %s\n", strerror(-r));
		b->failed = r;
	}
	glFinish();
}

static void upload_frame(void *arg)
{
	struct bench *b = arg;

	b->app->mesh_serial++;
	frame(b);
}

static void steady_frame(void *arg)
{
	frame(arg);
}

/* The tree's upload alone, as after an edit. */
static void upload_only(void *arg)
{
	struct bench *b = arg;
	int r;

	b->app->mesh_serial++;
	r = render_upload_tree(b->render, b->app);
	if (r < 0 && !b->failed) {
		fprintf(stderr, "bench_frame: upload: %s\n", strerror(-r));
		b->failed = r;
	}
	glFinish();
}

/* Shows t (taking its contents) with its meshes. */
static int set_tree(struct bench *b, struct tree *t)
{
	return app_show_tree(b->app, t);
}

static void readback(void *arg)
{
	struct bench *b = arg;
	int r = egl_headless_read_rgba(b->egl, b->rgba);

	if (r < 0 && !b->failed) {
		fprintf(stderr, "bench_frame: read back: %s\n", strerror(-r));
		b->failed = r;
	}
}

static int measure(struct bench *b, int nbranches, struct result *res)
{
	struct tree t;
	struct render_stats st;
	int r;

	tree_init(&t);
	r = synth_tree(&t, nbranches, LEAVES_PER_BRANCH, SEED);
	if (r == 0)
		r = set_tree(b, &t);
	tree_finish(&t);
	if (r < 0) {
		fprintf(stderr, "bench_frame: building a %d-branch tree: %s\n", nbranches,
			strerror(-r));
		return r;
	}
	res->upload_s = bench_run(upload_frame, b, frames);
	res->steady_s = bench_run(steady_frame, b, frames);
	render_get_stats(b->render, &st);
	res->triangles = st.triangles;
	res->tree_triangles = st.tree_triangles;
	res->draw_calls = st.draw_calls;
	res->readback_s = bench_run(readback, b, frames);
	return b->failed;
}

/*
 * The kiosk's CPU cost a frame by leaf count: the main thread's CPU time in render_frame
 * (building the UI, submitting draws; llvmpipe rasterises on its own threads, a real GPU
 * on the GPU), with an upload and steady, and the draw calls. Trees of 100, 1,000 and
 * 20,000 leaves (10 x 10, 100 x 10, 1,000 x 20 synthetic leaves, all drawn leaves).
 */
static const int leaf_trees[][2] = { { 10, 10 }, { 100, 10 }, { 1000, 20 } };
#define NLEAF_TREES (sizeof(leaf_trees) / sizeof(leaf_trees[0]))

static double thread_cpu_s(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
	return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* What the labels cost a frame: steady frames of the app's tree with and without them,
 * interleaved so that the machine's load falls on both alike. */
static int labels_cost(struct bench *b)
{
	double cpu[2][FRAMES_MAX], wall[2][FRAMES_MAX];
	struct render_stats st[2];

	for (int k = 0; k < frames; k++) {
		for (int labelled = 1; labelled >= 0; labelled--) {
			double t0, w0;

			if (render_set_text(b->render, labelled ? b->font : NULL, b->font_len,
					    RENDER_LANG_EN) < 0 ||
			    render_frame(b->render, b->app) < 0) /* the glyphs rasterised again */
				return -EIO;
			glFinish();
			w0 = bench_now();
			t0 = thread_cpu_s();
			if (render_frame(b->render, b->app) < 0)
				return -EIO;
			cpu[labelled][k] = thread_cpu_s() - t0;
			glFinish();
			wall[labelled][k] = bench_now() - w0;
			render_get_stats(b->render, &st[labelled]);
		}
	}
	printf("  labels on/off: %u/%u draw calls, %zu/%zu triangles; steady frame CPU %.3f/%.3f ms,"
	       " with the rasteriser %.3f/%.3f ms\n",
	       st[1].draw_calls, st[0].draw_calls, st[1].triangles, st[0].triangles,
	       1e3 * bench_median(cpu[1], frames), 1e3 * bench_median(cpu[0], frames),
	       1e3 * bench_median(wall[1], frames), 1e3 * bench_median(wall[0], frames));
	return render_set_text(b->render, b->font, b->font_len, RENDER_LANG_EN);
}

static int frame_cpu(struct bench *b)
{
	double up[FRAMES_MAX], steady[FRAMES_MAX], prev_n = 0, prev_s = 0, prev_n2 = 0, prev_s2 = 0;

	printf("\nframe CPU time (main thread, render_frame before glFinish) by leaf count\n");
	for (size_t i = 0; i < BENCH_COUNT(leaf_trees); i++) {
		struct render_stats st;
		struct tree t;
		int n = leaf_trees[i][0] * leaf_trees[i][1];
		int r;

		tree_init(&t);
		r = synth_tree(&t, leaf_trees[i][0], leaf_trees[i][1], SEED);
		if (r == 0)
			r = set_tree(b, &t);
		tree_finish(&t);
		if (r < 0)
			return r;
		for (int k = 0; k < frames; k++) {
			double t0;

			b->app->mesh_serial++;
			t0 = thread_cpu_s();
			if (render_frame(b->render, b->app) < 0)
				return -EIO;
			up[k] = thread_cpu_s() - t0;
			glFinish();
			t0 = thread_cpu_s();
			if (render_frame(b->render, b->app) < 0)
				return -EIO;
			steady[k] = thread_cpu_s() - t0;
			glFinish();
		}
		render_get_stats(b->render, &st);
		printf("  %6d leaves on %4d branches: %u draw calls a frame, %zu tree triangles\n", n,
		       leaf_trees[i][0], st.draw_calls, st.tree_triangles);
		bench_row("frame CPU, with upload", n, bench_median(up, frames), &prev_n, &prev_s);
		bench_row("frame CPU, steady", n, bench_median(steady, frames), &prev_n2, &prev_s2);
		/* on the smallest tree, where the labels are the largest share */
		if (i == 0 && labels_cost(b) < 0)
			return -EIO;
	}
	return 0;
}

static const int prop_sizes[] = { 250, 500, 1000 };
#define NPROP (sizeof(prop_sizes) / sizeof(prop_sizes[0]))
#define PROP_LEAVES 20

/* Frames, upload and stats of the app's tree, leaves instanced or merged. */
static int measure_mode(struct bench *b, bool instanced, struct result *res)
{
	bool could = b->render->instanced;
	struct render_stats st;

	b->render->instanced = could && instanced;
	res->upload_s = bench_run(upload_frame, b, frames);
	res->upload_bytes = b->render->upload_bytes;
	res->leaf_bytes = res->upload_bytes - b->render->bark.bytes;
	res->steady_s = bench_run(steady_frame, b, frames);
	render_get_stats(b->render, &st);
	res->triangles = st.triangles;
	res->tree_triangles = st.tree_triangles;
	res->draw_calls = st.draw_calls;
	res->upload_only_s = bench_run(upload_only, b, frames);
	b->render->instanced = could;
	return b->failed;
}

/* A tree of n branches whose last twig (no children: only leaves are copied) carries 20
 * leaves, then propagated everywhere. res[0] instanced, res[1] merged. */
static int measure_propagated(struct bench *b, int n, struct result res[2], double *prop_s,
			      size_t *nleaves, size_t *nshapes)
{
	struct tree t;
	struct leaf_instances li;
	bool *drop = NULL;
	double t0;
	int r;

	tree_init(&t);
	r = synth_tree(&t, n, PROP_LEAVES, SEED);
	if (r == 0 && !(drop = calloc(t.nleaves + 1, sizeof(*drop))))
		r = -ENOMEM;
	if (r == 0) {
		int src = (int)t.nbranches - 1;

		for (size_t i = 0; i < t.nleaves; i++)
			drop[i] = t.leaves[i].branch != src;
		tree_remove_leaves(&t, drop);
		t0 = bench_now();
		r = propagate_apply(&t, src, PROPAGATE_FIXED_COUNT);
		*prop_s = bench_now() - t0;
		*nleaves = t.nleaves;
	}
	if (r >= 0)
		r = set_tree(b, &t);
	free(drop);
	tree_finish(&t);
	leaf_instances_init(&li);
	if (r >= 0)
		r = leaf_instances_build(&li, &b->app->tree);
	*nshapes = li.ninstanced_shapes;
	leaf_instances_finish(&li);
	if (r < 0) {
		fprintf(stderr, "bench_frame: propagating on %d branches: %s\n", n, strerror(-r));
		return r;
	}
	if (measure_mode(b, true, &res[0]) < 0 || measure_mode(b, false, &res[1]) < 0)
		return -1;
	return 0;
}

static void rows(const char *name, const struct result res[][2], int mode,
		 double (*get)(const struct result *))
{
	double prev_size = 0, prev_s = 0;

	for (size_t i = 0; i < BENCH_COUNT(prop_sizes); i++)
		bench_row(name, prop_sizes[i], get(&res[i][mode]), &prev_size, &prev_s);
}

static double get_upload(const struct result *r)
{
	return r->upload_s;
}

static double get_steady(const struct result *r)
{
	return r->steady_s;
}

static double get_upload_only(const struct result *r)
{
	return r->upload_only_s;
}

static int propagated(struct bench *b)
{
	struct result res[NPROP][2];
	double prop_s[NPROP], prev_size = 0, prev_s = 0;
	size_t nleaves[NPROP], nshapes[NPROP];

	for (size_t i = 0; i < BENCH_COUNT(prop_sizes); i++)
		if (measure_propagated(b, prop_sizes[i], res[i], &prop_s[i], &nleaves[i],
				       &nshapes[i]) < 0)
			return -1;
	printf("\npropagated: %d leaves on one branch copied onto every branch (fixed count); "
	       "leaves instanced (%s) and merged\n",
	       PROP_LEAVES, b->render->instanced ? "GLES 3" : "not on this GLES 2 context");
	for (size_t i = 0; i < BENCH_COUNT(prop_sizes); i++) {
		printf("  %4d branches: %6zu leaves, %8zu tree triangles\n", prop_sizes[i],
		       nleaves[i], res[i][0].tree_triangles);
		printf("      instanced: %2zu leaf shapes, %3u draw calls a frame, %9zu bytes "
		       "uploaded (leaves %9zu)\n",
		       nshapes[i], res[i][0].draw_calls, res[i][0].upload_bytes,
		       res[i][0].leaf_bytes);
		printf("      merged:                 %3u draw calls a frame, %9zu bytes "
		       "uploaded (leaves %9zu)\n",
		       res[i][1].draw_calls, res[i][1].upload_bytes, res[i][1].leaf_bytes);
	}
	for (size_t i = 0; i < BENCH_COUNT(prop_sizes); i++)
		bench_row("propagate (one run)", prop_sizes[i], prop_s[i], &prev_size, &prev_s);
	rows("upload, instanced", res, 0, get_upload_only);
	rows("upload, merged", res, 1, get_upload_only);
	rows("frame with upload, instanced", res, 0, get_upload);
	rows("frame with upload, merged", res, 1, get_upload);
	rows("frame, steady, instanced", res, 0, get_steady);
	rows("frame, steady, merged", res, 1, get_steady);
	return 0;
}

/*
 * The functional trees (issue 14): each preset as a template tap puts it on the canvas
 * (its marks made, as the app's), in summer (one leaf colour, the plain programs) and in
 * autumn (a colour a leaf, the tinted ones): the frame that uploads it, a steady frame and
 * its CPU time, the draw calls.
 */
static int presets(struct bench *b)
{
	static const enum season seasons[] = { SEASON_SUMMER, SEASON_AUTUMN };

	printf("the presets (the New strip's trees), median of %d frames: upload frame, steady "
	       "frame, its main-thread CPU; draw calls\n", frames);
	for (int i = 0; i < (int)bench_count(GEN_PRESET_COUNT); i++) {
		struct gen_params p;
		struct error err;
		struct render_stats st;
		struct tree t;
		int r;

		tree_init(&t);
		r = gen_preset((enum gen_preset)i, &p, &err);
		if (r == 0)
			r = gen_build(&t, &p, SEED);
		if (r < 0) {
			fprintf(stderr, "bench_frame: preset %s: %s\n", gen_preset_name((enum gen_preset)i),
				r == -EINVAL ? err.msg : strerror(-r));
			tree_finish(&t);
			return r;
		}
		r = set_tree(b, &t);
		if (r < 0)
			return r;
		for (size_t k = 0; k < sizeof(seasons) / sizeof(*seasons); k++) {
			double up, steady, cpu[FRAMES_MAX];

			b->app->tree.season = seasons[k];
			up = bench_run(upload_frame, b, frames);
			steady = bench_run(steady_frame, b, frames);
			for (int f = 0; f < frames; f++) {
				double t0 = thread_cpu_s();

				frame(b);
				cpu[f] = thread_cpu_s() - t0;
			}
			render_get_stats(b->render, &st);
			printf("  %-8s %-6s %7zu triangles: %7.3f ms, %7.3f ms, CPU %6.3f ms; %u draw calls\n",
			       gen_preset_name((enum gen_preset)i), season_name(seasons[k]),
			       st.tree_triangles, 1e3 * up, 1e3 * steady, 1e3 * bench_median(cpu, frames),
			       st.draw_calls);
		}
		if (b->failed)
			return b->failed;
	}
	tree_clear(&b->app->tree);
	return 0;
}

/*
 * Issue 15: a tree of 20,000 origami leaves (1,000 synthetic branches x 20 leaves, each
 * made a preset in place of its outline), per preset: the frame with its upload, steady,
 * its main-thread CPU, triangles and draw calls; then the same with every leaf unfolding
 * (keyframe meshes, as just after a propagation).
 */
static int origami(struct bench *b)
{
	int nbranches = bench_quick ? 50 : 1000;

	printf("%d origami leaves (%d branches x 20), median of %d frames: upload frame, "
	       "steady frame, its main-thread CPU; triangles; draw calls\n", 20 * nbranches,
	       nbranches, frames);
	for (int k = 0; k < ORI_KIND_COUNT; k++) {
		struct render_stats st;
		struct tree t;
		int r;

		tree_init(&t);
		r = synth_tree(&t, nbranches, 20, SEED);
		for (size_t i = 0; r == 0 && i < t.nleaves; i++)
			r = ori_place_leaf(&t, i, k);
		if (r == 0)
			r = set_tree(b, &t);
		tree_finish(&t);
		if (r < 0) {
			fprintf(stderr, "bench_frame: origami %s: %s\n", ori_kind_name(k), strerror(-r));
			return r;
		}
		for (int unfolding = 0; unfolding < 2; unfolding++) {
			double up, steady, cpu[FRAMES_MAX];

			/* every leaf half way through its second, as after a propagation */
			b->app->nunfold = (size_t)unfolding;
			b->app->unfold[0] = (struct app_unfold){ .first = 0, .start_us = 0 };
			b->now_us = unfolding ? APP_UNFOLD_US / 2 : UINT64_MAX;
			up = bench_run(upload_frame, b, frames);
			steady = bench_run(steady_frame, b, frames);
			for (int f = 0; f < frames; f++) {
				double t0 = thread_cpu_s();

				frame(b);
				cpu[f] = thread_cpu_s() - t0;
			}
			render_get_stats(b->render, &st);
			printf("  %-7s %-9s %8zu triangles: %7.3f ms, %7.3f ms, CPU %6.3f ms; %u draw "
			       "calls\n", ori_kind_name(k), unfolding ? "unfolding" : "at rest",
			       st.tree_triangles, 1e3 * up, 1e3 * steady, 1e3 * bench_median(cpu, frames),
			       st.draw_calls);
		}
		b->app->nunfold = 0;
		b->now_us = UINT64_MAX;
		if (b->failed)
			return b->failed;
	}
	tree_clear(&b->app->tree);
	return 0;
}

/*
 * Issue 26, the living tree: trees of 62 and 1,000 branches with 20,000 leaves (synthetic,
 * made 3D), still, growing in and in the wind at the default breeze, frames a 60th of a
 * second apart. edaha's own work a frame: app_live_at (the front, the wind's frame) and
 * the living program's uniforms (render_live_uniforms, the GL calls included), timed
 * over 10,000 frames, the bytes a frame uploads and its draw calls; apart, the main
 * thread's CPU in render_frame_at, which holds llvmpipe's vertex shading (Mesa's draw
 * module runs the vertex shader on the calling thread; a board's GPU does it on the GPU),
 * and the whole frame's wall time to glFinish. And what a change of the meshes costs once
 * with the wind on: the upload with the vertices' data bound and packed, against the
 * still upload.
 */
static const int live_trees[][2] = { { 62, 323 }, { 1000, 20 } };

enum live_mode { LIVE_STILL, LIVE_GROWING, LIVE_WIND, LIVE_MODES };
static const char *const live_names[] = { "still", "growing", "wind" };

#define OWN_FRAMES 10000

/* edaha's own per-frame work for the living tree, the frame's program in use: seconds a
 * frame, and the bytes the last frame uploaded. */
static double live_own(struct bench *b, uint64_t from, uint64_t dur)
{
	struct render *r = b->render;
	int n = bench_quick ? 100 : OWN_FRAMES;
	double t0;

	if (!r->live.on)
		return 0.0;
	glUseProgram(r->live.merged.tree.program);
	t0 = thread_cpu_s();
	for (int k = 0; k < n; k++) {
		(void)app_live_at(b->app, from + dur * (uint64_t)k / (uint64_t)n, &r->live.frame);
		render_live_uniforms(r, &r->live.merged);
	}
	t0 = (thread_cpu_s() - t0) / n;
	glUseProgram(0);
	return t0;
}

static int live_frames(struct bench *b, enum live_mode m, double *cpu_s, double *wall_s,
		       double *own_s, size_t *bytes)
{
	double cpu[FRAMES_MAX], wall[FRAMES_MAX];
	uint64_t start = 1000000, dur;
	int ret = app_set_wind(b->app, m == LIVE_WIND ? LIVE_WIND_DEFAULT_STRENGTH : 0.0);

	if (ret == 0 && m == LIVE_GROWING)
		ret = app_live_grow_start(b->app, start);
	else
		b->app->live.growing = false;
	if (ret < 0)
		return ret;
	dur = m == LIVE_GROWING ? app_live_grow_end(b->app) - start : 6000000;
	frame(b); /* the data bound and uploaded, as on the first frame after a change */
	for (int k = 0; k < frames; k++) {
		uint64_t now = start + dur * (uint64_t)(k + 1) / (uint64_t)(frames + 2);
		struct app_live_frame f;
		double t0 = thread_cpu_s(), w0 = bench_now();

		/* the kiosk asks whether to keep drawing; the renderer asks again inside */
		(void)app_live_at(b->app, now, &f);
		if (render_frame_at(b->render, b->app, now) < 0)
			return -EIO;
		cpu[k] = thread_cpu_s() - t0;
		glFinish();
		wall[k] = bench_now() - w0;
		if ((m != LIVE_STILL) != b->render->live.on)
			return -EINVAL; /* not drawn as it should be */
	}
	*bytes = b->render->live.bytes + (b->render->stats.uploads ? b->render->upload_bytes : 0);
	*cpu_s = bench_median(cpu, frames);
	*wall_s = bench_median(wall, frames);
	*own_s = live_own(b, start, dur);
	return 0;
}

/* One change of the meshes with the wind on or off: its frame's main-thread CPU. */
static int live_edit(struct bench *b, bool wind, double *cpu_s)
{
	double cpu[FRAMES_MAX];
	int ret = app_set_wind(b->app, wind ? LIVE_WIND_DEFAULT_STRENGTH : 0.0);

	b->app->live.growing = false;
	for (int k = 0; k < frames && ret == 0; k++) {
		double t0 = thread_cpu_s();

		b->app->mesh_serial++;
		ret = app_live_sync(b->app); /* the skeleton, as app.c makes it after an edit */
		if (ret == 0 && render_frame_at(b->render, b->app, 2000000 + 16667 * (uint64_t)k) < 0)
			ret = -EIO;
		cpu[k] = thread_cpu_s() - t0;
		glFinish();
	}
	*cpu_s = bench_median(cpu, frames);
	return ret;
}

static int living(struct bench *b)
{
	printf("\nthe living tree (issue 26), median of %d frames: edaha's own work a frame "
	       "(app_live_at and the uniforms, over %d frames; bytes uploaded), apart the main "
	       "thread's CPU in render_frame_at and the whole frame with llvmpipe; leaves %s\n",
	       frames, OWN_FRAMES,
	       b->render->instanced ? "instanced (GLES 3)" : "merged (GLES 2)");
	for (size_t i = 0; i < BENCH_COUNT(live_trees); i++) {
		int nb = bench_quick ? 10 * (int)(i + 1) : live_trees[i][0];
		int nl = bench_quick ? 5 : live_trees[i][1];
		double cpu[LIVE_MODES], wall[LIVE_MODES], own[LIVE_MODES], edit[2];
		size_t bytes[LIVE_MODES];
		struct render_stats st;
		struct tree t;
		int r;

		tree_init(&t);
		r = synth_tree(&t, nb, nl, SEED);
		t.lifted = true;
		if (r == 0)
			r = set_tree(b, &t);
		tree_finish(&t);
		for (int m = 0; m < LIVE_MODES && r == 0; m++)
			r = live_frames(b, (enum live_mode)m, &cpu[m], &wall[m], &own[m], &bytes[m]);
		render_get_stats(b->render, &st);
		if (r == 0)
			r = live_edit(b, false, &edit[0]);
		if (r == 0)
			r = live_edit(b, true, &edit[1]);
		if (r < 0) {
			fprintf(stderr, "bench_frame: the living tree on %d branches: %s\n", nb,
				strerror(-r));
			return r;
		}
		printf("  %4d branches, %6zu leaves, %7zu + %7zu vertices, %u draw calls:\n", nb,
		       b->app->tree.nleaves, b->app->mesh.bark.nvertices,
		       b->app->mesh.leaves.nvertices, st.draw_calls);
		for (int m = 0; m < LIVE_MODES; m++)
			printf("      %-8s edaha's own %6.3f us a frame, %zu bytes uploaded; main "
			       "thread (with llvmpipe's vertex shading) %7.3f ms; whole frame %8.3f ms\n",
			       live_names[m], 1e6 * own[m], bytes[m], 1e3 * cpu[m], 1e3 * wall[m]);
		printf("      after a change of the meshes: frame CPU %.3f ms still, %.3f ms with "
		       "the wind (the data bound, %.1f MB uploaded)\n", 1e3 * edit[0], 1e3 * edit[1],
		       (double)b->render->live.bytes / 1e6);
	}
	(void)app_set_wind(b->app, 0.0);
	tree_clear(&b->app->tree);
	return 0;
}

int main(int argc, char **argv)
{
	struct bench b = { .now_us = UINT64_MAX };
	struct result res[NSIZES];
	struct error err;
	double t0, first_s, prev_size, prev_s;
	const char *font_name;
	char *font = NULL;
	size_t font_len;
	int status = 1;

	if (bench_init(&argc, argv, NULL))
		return 1;
	frames = bench_reps(FRAMES_MAX);
	b.egl = egl_headless_create(WIDTH, HEIGHT, &err);
	if (!b.egl) {
		fprintf(stderr, "bench_frame: %s\n", err.msg);
		return 1;
	}
	b.rgba = malloc((size_t)WIDTH * HEIGHT * 4);
	if (!b.rgba)
		goto out;
	/* what the kiosk shows while a child hovers: the tree, the buttons, the pen's ring */
	b.app = app_create(WIDTH, HEIGHT, SEED);
	if (!b.app)
		goto out;
	app_handle_event(b.app, &(struct event){ .type = EVENT_PROXIMITY_IN, .time_us = 1000,
						 .tool = EVENT_TOOL_PEN, .x = 400, .y = 300 });
	if (!b.app->pen.in_proximity) {
		fprintf(stderr, "bench_frame: the pen's proximity was not taken\n");
		goto out;
	}

	if (font_file_read(NULL, &font, &font_len, &font_name, &err) < 0) {
		fprintf(stderr, "bench_frame: %s\n", err.msg);
		goto out;
	}
	/* the first frame compiles the shaders (and llvmpipe its pipelines) and rasterises
	 * the labels' glyphs */
	t0 = bench_now();
	b.render = render_create();
	if (!b.render) {
		fprintf(stderr, "bench_frame: render_create failed\n");
		goto out;
	}
	b.font = font;
	b.font_len = font_len;
	if (render_set_text(b.render, font, font_len, RENDER_LANG_EN) < 0) {
		fprintf(stderr, "bench_frame: %s: render_set_text failed\n", font_name);
		goto out;
	}
	frame(&b);
	first_s = bench_now() - t0;

	for (size_t i = 0; i < BENCH_COUNT(sizes); i++) {
		if (measure(&b, sizes[i], &res[i]) < 0)
			goto out;
	}

	printf("bench_frame: %dx%d, llvmpipe, median of %d frames; size = branches "
	       "(%d leaves each, every one its own shape)\n",
	       WIDTH, HEIGHT, frames, LEAVES_PER_BRANCH);
	printf("first frame (render_create, shader compile, labels' glyphs, empty tree): %.3f ms\n",
	       first_s * 1e3);
	for (size_t i = 0; i < BENCH_COUNT(sizes); i++)
		printf("  %4d branches: %8zu tree triangles, %8zu triangles, %u draw calls a frame\n",
		       sizes[i], res[i].tree_triangles, res[i].triangles, res[i].draw_calls);

	prev_size = prev_s = 0;
	for (size_t i = 0; i < BENCH_COUNT(sizes); i++)
		bench_row("frame with upload", sizes[i], res[i].upload_s, &prev_size, &prev_s);
	prev_size = prev_s = 0;
	for (size_t i = 0; i < BENCH_COUNT(sizes); i++)
		bench_row("frame, steady", sizes[i], res[i].steady_s, &prev_size, &prev_s);
	prev_size = prev_s = 0;
	for (size_t i = 0; i < BENCH_COUNT(sizes); i++)
		bench_row("read back (resolve + read)", sizes[i], res[i].readback_s, &prev_size,
			  &prev_s);
	if (propagated(&b) < 0)
		goto out;
	if (frame_cpu(&b) < 0)
		goto out;
	if (presets(&b) < 0)
		goto out;
	if (origami(&b) < 0)
		goto out;
	if (living(&b) < 0)
		goto out;
	status = 0;
out:
	render_destroy(b.render);
	if (b.app)
		app_destroy(b.app);
	free(b.rgba);
	free(font);
	egl_headless_destroy(b.egl);
	return status;
}
