/* SPDX-License-Identifier: MIT */
/*
 * Headless frame time at the kiosk's 1280x800: synthetic trees of 62..500 branches with
 * 10 leaves each, drawn by the renderer into llvmpipe. For each tree: a frame that
 * uploads the meshes (what follows a finished stroke), a steady frame with nothing to
 * upload (what the pen's hover costs), and reading the frame back (what --headless and
 * the golden tests pay). Medians of FRAMES frames; glFinish() so the time is the work
 * done, not the work queued.
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
	status = 0;
out:
	render_destroy(b.render);
	tree_mesh_finish(&b.app.mesh);
	free(b.rgba);
	egl_headless_destroy(b.egl);
	return status;
}
