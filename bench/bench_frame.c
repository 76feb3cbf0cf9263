/* SPDX-License-Identifier: MIT */
/*
 * Headless frame time at the kiosk's 1280x800: synthetic trees of 62..500 branches with
 * 10 leaves each, drawn by the renderer into llvmpipe. For each tree: a frame that
 * uploads the meshes (what follows a finished stroke), a steady frame with nothing to
 * upload (what the pen's hover costs), and reading the frame back (what --headless and
 * the golden tests pay). Medians of FRAMES frames; glFinish() so the time is the work
 * done, not the work queued.
 * Then the tree propagation makes: 20 leaves on one branch propagated (fixed count) onto
 * every branch of 250..1,000-branch trees, up to 20,000 leaves: the propagation's time,
 * and the frame's time and draw calls.
 */
#include <GLES2/gl2.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app.h"
#include "bench_util.h"
#include "egl_headless.h"
#include "mesh.h"
#include "propagate.h"
#include "render.h"
#include "synth_tree.h"

#define WIDTH 1280
#define HEIGHT 800
#define FRAMES 7
#define LEAVES_PER_BRANCH 10
#define SEED 7

static const int sizes[] = { 62, 125, 250, 500 };
#define NSIZES (sizeof(sizes) / sizeof(sizes[0]))

struct result {
	double upload_s, steady_s, readback_s;
	size_t triangles, tree_triangles;
	unsigned draw_calls;
};

struct bench {
	struct egl_headless *egl;
	struct render *render;
	struct app app;
	uint8_t *rgba;
	int failed;
};

static void frame(struct bench *b)
{
	int r = render_frame(b->render, &b->app);

	if (r < 0 && !b->failed) {
		fprintf(stderr, "bench_frame: render_frame: %s\n", strerror(-r));
		b->failed = r;
	}
	glFinish();
}

static void upload_frame(void *arg)
{
	struct bench *b = arg;

	b->app.mesh_serial++;
	frame(b);
}

static void steady_frame(void *arg)
{
	frame(arg);
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
		r = tree_mesh_build(&b->app.mesh, &t);
	tree_finish(&t);
	if (r < 0) {
		fprintf(stderr, "bench_frame: building a %d-branch tree: %s\n", nbranches,
			strerror(-r));
		return r;
	}
	res->upload_s = bench_run(upload_frame, b, FRAMES);
	res->steady_s = bench_run(steady_frame, b, FRAMES);
	render_get_stats(b->render, &st);
	res->triangles = st.triangles;
	res->tree_triangles = st.tree_triangles;
	res->draw_calls = st.draw_calls;
	res->readback_s = bench_run(readback, b, FRAMES);
	return b->failed;
}

static const int prop_sizes[] = { 250, 500, 1000 };
#define NPROP (sizeof(prop_sizes) / sizeof(prop_sizes[0]))
#define PROP_LEAVES 20

/* A tree of n branches whose last twig (no children: only leaves are copied) carries 20
 * leaves, then propagated everywhere. */
static int measure_propagated(struct bench *b, int n, struct result *res, double *prop_s,
			      size_t *nleaves)
{
	struct tree t;
	struct render_stats st;
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
		r = tree_mesh_build(&b->app.mesh, &t);
	free(drop);
	tree_finish(&t);
	if (r < 0) {
		fprintf(stderr, "bench_frame: propagating on %d branches: %s\n", n, strerror(-r));
		return r;
	}
	res->upload_s = bench_run(upload_frame, b, FRAMES);
	res->steady_s = bench_run(steady_frame, b, FRAMES);
	render_get_stats(b->render, &st);
	res->triangles = st.triangles;
	res->tree_triangles = st.tree_triangles;
	res->draw_calls = st.draw_calls;
	return b->failed;
}

static int propagated(struct bench *b)
{
	struct result res[NPROP];
	double prop_s[NPROP], prev_size = 0, prev_s = 0;
	size_t nleaves[NPROP];

	for (size_t i = 0; i < NPROP; i++)
		if (measure_propagated(b, prop_sizes[i], &res[i], &prop_s[i], &nleaves[i]) < 0)
			return -1;
	printf("\npropagated: %d leaves on one branch copied onto every branch (fixed count)\n",
	       PROP_LEAVES);
	for (size_t i = 0; i < NPROP; i++)
		printf("  %4d branches: %6zu leaves, %8zu tree triangles, %u draw calls a frame\n",
		       prop_sizes[i], nleaves[i], res[i].tree_triangles, res[i].draw_calls);
	for (size_t i = 0; i < NPROP; i++)
		bench_row("propagate (one run)", prop_sizes[i], prop_s[i], &prev_size, &prev_s);
	prev_size = prev_s = 0;
	for (size_t i = 0; i < NPROP; i++)
		bench_row("frame with upload", prop_sizes[i], res[i].upload_s, &prev_size, &prev_s);
	prev_size = prev_s = 0;
	for (size_t i = 0; i < NPROP; i++)
		bench_row("frame, steady", prop_sizes[i], res[i].steady_s, &prev_size, &prev_s);
	return 0;
}

int main(void)
{
	struct bench b = { 0 };
	struct result res[NSIZES];
	struct error err;
	double t0, first_s, prev_size, prev_s;
	int status = 1;

	b.egl = egl_headless_create(WIDTH, HEIGHT, &err);
	if (!b.egl) {
		fprintf(stderr, "bench_frame: %s\n", err.msg);
		return 1;
	}
	b.rgba = malloc((size_t)WIDTH * HEIGHT * 4);
	if (!b.rgba)
		goto out;
	/* what the kiosk shows while a child hovers: the tree, the buttons, the pen's ring */
	view_init(&b.app.view, WIDTH, HEIGHT);
	tree_mesh_init(&b.app.mesh);
	b.app.pen.in_proximity = true;
	b.app.pen.x = 400;
	b.app.pen.y = 300;

	/* the first frame compiles the shaders (and llvmpipe its pipelines) */
	t0 = bench_now();
	b.render = render_create();
	if (!b.render) {
		fprintf(stderr, "bench_frame: render_create failed\n");
		goto out;
	}
	frame(&b);
	first_s = bench_now() - t0;

	for (size_t i = 0; i < NSIZES; i++) {
		if (measure(&b, sizes[i], &res[i]) < 0)
			goto out;
	}

	printf("bench_frame: %dx%d, llvmpipe, median of %d frames; size = branches "
	       "(%d leaves each)\n",
	       WIDTH, HEIGHT, FRAMES, LEAVES_PER_BRANCH);
	printf("first frame (render_create, shader compile, empty tree): %.3f ms\n", first_s * 1e3);
	for (size_t i = 0; i < NSIZES; i++)
		printf("  %4d branches: %8zu tree triangles, %8zu triangles, %u draw calls a frame\n",
		       sizes[i], res[i].tree_triangles, res[i].triangles, res[i].draw_calls);

	prev_size = prev_s = 0;
	for (size_t i = 0; i < NSIZES; i++)
		bench_row("frame with upload", sizes[i], res[i].upload_s, &prev_size, &prev_s);
	prev_size = prev_s = 0;
	for (size_t i = 0; i < NSIZES; i++)
		bench_row("frame, steady", sizes[i], res[i].steady_s, &prev_size, &prev_s);
	prev_size = prev_s = 0;
	for (size_t i = 0; i < NSIZES; i++)
		bench_row("read back (resolve + read)", sizes[i], res[i].readback_s, &prev_size,
			  &prev_s);
	if (propagated(&b) < 0)
		goto out;
	status = 0;
out:
	render_destroy(b.render);
	tree_mesh_finish(&b.app.mesh);
	free(b.rgba);
	egl_headless_destroy(b.egl);
	return status;
}
