/* SPDX-License-Identifier: MIT */
/*
 * Today's forest (issue 27, docs/forest.md "Drawing it fast enough"): what its levels of
 * detail cost and give.
 *
 * Per tree: the demo (its trace replayed through the app and lifted to 3D), cherry (a
 * functional tree's preset) and synthetic trees (tests/tools/synth_tree.c) of 62 and
 * 1,000 branches with 20,000 leaves in all (323 and 20 a branch); then cherry grown twice
 * (wood_grow, the default settings) and cherry with three of the kiosk's vines (morning
 * glory scaled to its trunk as app_mode_vine.c scales it, planted round its foot): its own
 * meshes (tree_mesh_build: time, triangles; the wood's bark and the vines' meshes
 * counted in), its height and crown width, and forest_lod_build at 7,500 (300,000 / 40),
 * 15,000 and 30,000 triangles: median time, triangles (bark + leaves), the bark's level
 * and sides, branches kept, cards; for the last two the wood's triangles and the stems'
 * (and their level). Then the growth of forest_lod_build's time with the tree (62..1,000
 * branches, 20 leaves each, at 7,500).
 *
 * The forest: 10, 20 and 40 trees, the four above in turn, each with its share of 300,000
 * triangles by crown width (forest_lod_shares, water-filled by what each tree's own meshes
 * need): the shares, the triangles drawn in all against the trees' own, the meshes'
 * building in all (the planting thread's, never a frame's). The rendering figures (draw
 * calls and frame times under llvmpipe) are the renderer's: render_rows().
 *
 * The layout (forest_layout: every pair of trunks, when a tree joins or leaves): median
 * time for 10, 20, 40 and 200 trees, and how it grows (n^2 pairs).
 */
#include <GLES2/gl2.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <math.h>

#include "app.h"
#include "app_private.h"
#include "bench_util.h"
#include "egl_headless.h"
#include "font_file.h"
#include "forest.h"
#include "render.h"
#include "render_private.h"
#include "live_trees.h"
#include "mesh.h"
#include "synth_tree.h"
#include "tree.h"
#include "vine.h"
#include "vine_presets.h"
#include "vine_support.h"
#include "wood.h"

#define REPS 7
#define SEED 26
#define FOREST_TRIANGLES 300000
#define NKINDS 4 /* the forest's rows' trees */
#define NGROWN 2 /* and the per-tree rows' grown and vined trees */

static const size_t budgets[] = { 7500, 15000, 30000 };

static void must(int r, const char *what)
{
	if (r < 0) {
		fprintf(stderr, "bench_forest: %s failed (%d)\n", what, r);
		exit(1);
	}
}

struct job {
	const struct tree *t;
	size_t budget;
	struct tree_mesh tm;
	struct forest_lod_stats st;
};

static void job_init(struct job *j, const struct tree *t, size_t budget)
{
	memset(j, 0, sizeof(*j));
	j->t = t;
	j->budget = budget;
	tree_mesh_init(&j->tm);
}

static void own_meshes(void *arg)
{
	struct job *j = arg;

	must(tree_mesh_build(&j->tm, j->t), "tree_mesh_build");
}

static void lod(void *arg)
{
	struct job *j = arg;

	must(forest_lod_build(j->t, j->budget, &j->tm, &j->st), "forest_lod_build");
}

static size_t triangles(const struct tree_mesh *tm)
{
	return (tm->bark.nindices + tm->leaves.nindices) / 3;
}

struct kind {
	const char *name;
	struct tree t;
	double width;
	size_t own;       /* its own meshes' triangles (its wood's and vines' too) */
	size_t in_wood, stems, vine_leaves;
};

/* n of the kiosk's vines round t's foot, grown on its bark as the vine op grows them. */
static void vines(struct tree *t, int n)
{
	struct vine_support *s = NULL;
	struct error err = { { 0 } };

	must(app_vine_support(t, &s), "app_vine_support");
	for (int i = 0; i < n; i++) {
		const struct branch *trunk = &t->branches[0];
		double a = 2.0 * VEC_PI * i / n, k, d;
		struct vine_params p;
		struct vine v;

		must(vine_preset(APP_VINE_PRESET, &p, &err), "vine_preset");
		/* app_mode_vine.c's scale: the stem a tenth of the trunk, 6 to 16 times */
		k = fmin(fmax(0.1 * trunk->radii[0] / p.radius, 6.0), 16.0);
		p.internode = fmin(p.internode * k, VINE_INTERNODE_MAX);
		p.radius = fmin(p.radius * k, VINE_RADIUS_MAX);
		p.leaf_size = fmin(p.leaf_size * k, VINE_LEAF_SIZE_MAX);
		p.seed = SEED + (uint64_t)i;
		d = trunk->radii[0] + 2.0 * p.radius;
		vine_init(&v, &p, vec3_add(trunk->points[0], vec3(d * cos(a), 0.0, d * sin(a))));
		must(vine_grow(&v, s, INFINITY), "vine_grow");
		must(vine_attach(t, &v), "vine_attach");
		vine_finish(&v);
	}
	vine_support_destroy(s);
}

/* Its own meshes' triangles: the tree's, the wood's bark and the vines' (the stems' and the
 * leaves' into *stems, *leaves). */
static size_t own_triangles(const struct tree *t, const struct tree_mesh *tm, size_t *stems,
			    size_t *leaves)
{
	struct mesh s, l;
	size_t n = triangles(tm) + (t->wood ? t->wood->bark.nindices / 3 : 0);

	mesh_init(&s);
	mesh_init(&l);
	for (size_t i = 0; i < t->nvines; i++)
		must(vine_mesh_append(&t->vines[i], &s, &l), "vine_mesh_append");
	*stems = s.nindices / 3;
	*leaves = l.nindices / 3;
	n += *stems + *leaves;
	mesh_finish(&s);
	mesh_finish(&l);
	return n;
}

static void kinds_init(struct kind *k)
{
	static const char *const names[NKINDS + NGROWN] = {
		"demo (3D)", "cherry", "62 branches", "1,000 branches", "cherry, grown twice",
		"cherry with 3 vines"
	};
	struct wood_params wp;

	for (int i = 0; i < NKINDS + NGROWN; i++) {
		k[i].name = names[i];
		tree_init(&k[i].t);
	}
	live_trees_demo(&k[0].t, BENCH_DATA_DIR, true);
	live_trees_preset(&k[1].t, GEN_PRESET_CHERRY);
	must(synth_tree(&k[2].t, 62, 323, SEED), "synth_tree");
	must(synth_tree(&k[3].t, 1000, 20, SEED), "synth_tree");
	live_trees_preset(&k[4].t, GEN_PRESET_CHERRY);
	wood_params_default(&wp);
	for (int i = 0; i < 2; i++)
		if (wood_grow(&k[4].t, &wp) != 0)
			must(-22, "wood_grow");
	live_trees_preset(&k[5].t, GEN_PRESET_CHERRY);
	vines(&k[5].t, 3);
	for (int i = 0; i < NKINDS + NGROWN; i++) {
		struct job j;

		k[i].width = forest_tree_crown_width(&k[i].t);
		job_init(&j, &k[i].t, 0);
		own_meshes(&j);
		k[i].own = own_triangles(&k[i].t, &j.tm, &k[i].stems, &k[i].vine_leaves);
		k[i].in_wood = 0;
		for (size_t b = 0; b < k[i].t.nbranches; b++)
			k[i].in_wood += tree_branch_in_wood(&k[i].t, b);
		tree_mesh_finish(&j.tm);
	}
}

static void per_tree(struct kind *k, int reps)
{
	struct job j;
	double s;

	job_init(&j, &k->t, 0);
	s = bench_run(own_meshes, &j, reps);
	printf("\n%s: %zu branches, %zu leaves, %.2f m high, crown %.2f m wide\n", k->name,
	       k->t.nbranches, k->t.nleaves, forest_tree_height(&k->t), k->width);
	if (k->t.wood || k->t.nvines)
		printf("  its wood's bark %zu triangles (%zu branches in it), %zu vines' stems %zu "
		       "and leaves %zu\n", k->t.wood ? k->t.wood->bark.nindices / 3 : 0, k->in_wood,
		       k->t.nvines, k->stems, k->vine_leaves);
	printf("  its own meshes %29zu triangles %9.2f ms (tree_mesh_build)\n", k->own, s * 1e3);
	for (size_t b = 0; b < sizeof(budgets) / sizeof(budgets[0]); b++) {
		j.budget = budgets[b];
		s = bench_run(lod, &j, reps);
		printf("  at %6zu: %6zu bark + %6zu leaves = %6zu triangles %9.2f ms  level %d "
		       "(%2d sides), %4zu of %4zu branches, %5zu cards\n",
		       budgets[b], j.st.bark_triangles, j.st.leaf_triangles, triangles(&j.tm),
		       s * 1e3, j.st.level, j.st.sides, j.st.branches_kept, k->t.nbranches,
		       j.st.cards);
		if (k->t.wood || k->t.nvines)
			printf("            of the bark: the wood's %6zu of %6zu, the stems' %5zu of "
			       "%5zu (level %d, %zu of %zu shoots)\n", j.st.wood_triangles,
			       k->t.wood ? k->t.wood->bark.nindices / 3 : 0, j.st.stem_triangles,
			       k->stems, j.st.stem_level, j.st.shoots_kept, j.st.shoots);
	}
	tree_mesh_finish(&j.tm);
}

static void growth(int reps)
{
	static const int sizes[] = { 62, 125, 250, 500, 1000 };
	double prev_size = 0.0, prev_s = 0.0;

	printf("\nforest_lod_build at 7,500 triangles with the tree (20 leaves a branch; its own "
	       "meshes built within)\n");
	for (size_t i = 0; i < BENCH_COUNT(sizes); i++) {
		struct tree t;
		struct job j;

		tree_init(&t);
		must(synth_tree(&t, sizes[i], 20, SEED), "synth_tree");
		job_init(&j, &t, 7500);
		bench_row("forest_lod_build", sizes[i], bench_run(lod, &j, reps), &prev_size,
			  &prev_s);
		tree_mesh_finish(&j.tm);
		tree_finish(&t);
	}
}

static void forest(struct kind *k, size_t n)
{
	double *widths = malloc(n * sizeof(*widths)), ms = 0.0;
	size_t *need = malloc(n * sizeof(*need)), *share = malloc(n * sizeof(*share));
	size_t drawn = 0, own = 0, lo = SIZE_MAX, hi = 0, over = 0;
	struct job j;

	if (!widths || !need || !share)
		must(-12, "malloc");
	for (size_t i = 0; i < n; i++) {
		widths[i] = k[i % NKINDS].width;
		need[i] = k[i % NKINDS].own;
	}
	forest_lod_shares(widths, need, n, FOREST_TRIANGLES, share);
	job_init(&j, NULL, 0);
	for (size_t i = 0; i < n; i++) {
		double t0 = bench_now();

		j.t = &k[i % NKINDS].t;
		j.budget = share[i];
		lod(&j);
		ms += (bench_now() - t0) * 1e3;
		drawn += triangles(&j.tm);
		own += need[i];
		over += j.st.over_budget;
		lo = share[i] < lo ? share[i] : lo;
		hi = share[i] > hi ? share[i] : hi;
	}
	printf("%5zu %9zu %9zu %12zu %12zu %11.1f %7zu\n", n, lo, hi, drawn, own, ms, over);
	tree_mesh_finish(&j.tm);
	free(share);
	free(need);
	free(widths);
}

struct layout_job {
	size_t n;
	uint64_t numbers[FOREST_MAX_TREES_LIMIT];
	double widths[FOREST_MAX_TREES_LIMIT], xz[2 * FOREST_MAX_TREES_LIMIT];
};

static void layout(void *arg)
{
	struct layout_job *j = arg;

	if (forest_layout(j->numbers, j->widths, j->n, j->n, j->xz) < 0)
		must(-22, "forest_layout");
}

static void layouts(int reps)
{
	static const size_t sizes[] = { 10, 20, 40, 200 };
	static struct layout_job j;
	double prev_size = 0.0, prev_s = 0.0;

	printf("\nforest_layout (a sunflower spiral scaled over every pair of trunks)\n");
	for (size_t i = 0; i < BENCH_COUNT(sizes); i++) {
		j.n = sizes[i];
		for (size_t t = 0; t < j.n; t++) {
			j.numbers[t] = 100 + t;
			j.widths[t] = 2.0 + (double)((t * 7) % 11);
		}
		bench_row("forest_layout", (double)j.n, bench_run(layout, &j, reps), &prev_size,
			  &prev_s);
	}
}

static double thread_cpu_s(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
	return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

#define RENDER_W 1280
#define RENDER_H 800
#define OWN_FRAMES 2000

/*
 * The forest on the attract screen (ui/render_forest.c) for n trees (the four above in
 * turn, each at its share): draw calls and triangles a frame, settled and while the
 * newest tree grows in; edaha's own CPU work a frame (render_forest_frame_at: the
 * camera's fit, the wind's numbers, the growth's front; render_forest_labels_current: the
 * numbers' quads still the scene's), the GL calls it then makes aside; the main
 * thread's CPU in render_frame_at (llvmpipe's vertex work included) and the whole frame
 * to glFinish; the first frame, which uploads the scene and builds the numbers.
 */
static void render_row(struct render *r, struct kind *k, size_t n, int reps,
		       struct forest_scene *scene)
{
	struct forest_part *parts = calloc(n, sizeof(*parts));
	const struct forest_part **pp = calloc(n, sizeof(*pp));
	uint64_t *numbers = calloc(n, sizeof(*numbers));
	double *widths = calloc(n, sizeof(*widths)), *xz = calloc(2 * n, sizeof(*xz));
	double *pos = calloc(3 * n, sizeof(*pos)), cpu = 0.0, wall = 0.0, first, t0, own, own_labels;
	size_t *share = calloc(n, sizeof(*share));
	struct render_stats st, grown;
	struct render_forest_frame ff;
	struct app *app = app_create(RENDER_W, RENDER_H, 1);
	unsigned current = 0;

	if (!parts || !pp || !numbers || !widths || !xz || !pos || !share || !app)
		must(-12, "malloc");
	for (size_t i = 0; i < n; i++) {
		numbers[i] = 1 + i;
		widths[i] = k[i % NKINDS].width;
	}
	forest_lod_shares(widths, NULL, n, FOREST_TRIANGLES, share);
	if (forest_layout(numbers, widths, n, n, xz) < 0)
		must(-22, "forest_layout");
	for (size_t i = 0; i < n; i++) {
		forest_part_init(&parts[i]);
		must(forest_part_build(&parts[i], &k[i % NKINDS].t, 7 + i, share[i], 0.35),
		     "forest_part_build");
		pp[i] = &parts[i];
		pos[3 * i] = xz[2 * i];
		pos[3 * i + 2] = xz[2 * i + 1];
	}
	/* one scene built again, as the kiosk's: the renderer knows it by its serial */
	must(forest_scene_build(scene, pp, numbers, pos, n), "forest_scene_build");
	app->forest = scene;
	app->attract_after_us = 1;
	t0 = bench_now();
	must(render_frame_at(r, app, 1000000), "render_frame_at");
	glFinish();
	first = bench_now() - t0;
	for (int f = 0; f < reps; f++) {
		double w0 = bench_now(), c0 = thread_cpu_s();

		must(render_frame_at(r, app, 1000000 + 33333 * (uint64_t)(f + 1)), "render_frame_at");
		cpu += thread_cpu_s() - c0;
		glFinish();
		wall += bench_now() - w0;
	}
	render_get_stats(r, &st);
	/* the newest tree a second into its growth (of 2 to 6 s) */
	app->forest_joined_us = 1000000 + 33333 * (uint64_t)reps;
	must(render_frame_at(r, app, app->forest_joined_us + 1000000), "render_frame_at");
	glFinish();
	render_get_stats(r, &grown);
	/* edaha's own a frame, the camera travelling, the newest growing in: the frame's
	 * numbers, then the labels' check */
	t0 = thread_cpu_s();
	for (int f = 0; f < OWN_FRAMES; f++)
		render_forest_frame_at(app, app->forest_joined_us + 33333 * (uint64_t)f, &ff);
	own = (thread_cpu_s() - t0) / OWN_FRAMES;
	t0 = thread_cpu_s();
	for (int f = 0; f < OWN_FRAMES; f++)
		current += render_forest_labels_current(r, app);
	own_labels = (thread_cpu_s() - t0) / OWN_FRAMES;
	if (current != OWN_FRAMES)
		must(-22, "render_forest_labels_current");
	app->forest_joined_us = 0;
	printf("%5zu %9zu %6u %8u %10.2f %10.2f %10.1f %10.1f %10.1f\n", n, st.tree_triangles,
	       st.draw_calls, grown.draw_calls, own * 1e6, own_labels * 1e6, cpu / reps * 1e3,
	       wall / reps * 1e3, first * 1e3);
	app_destroy(app);
	for (size_t i = 0; i < n; i++)
		forest_part_finish(&parts[i]);
	free(parts);
	free(pp);
	free(numbers);
	free(widths);
	free(xz);
	free(pos);
	free(share);
}

static void render_rows(struct kind *k, int reps)
{
	static const size_t counts[] = { 10, 20, 40 };
	struct error err = { { 0 } };
	struct egl_headless *egl = egl_headless_create(RENDER_W, RENDER_H, &err);
	struct forest_scene scene;
	struct render *r;
	const char *used;
	char *font = NULL;
	size_t len;

	printf("\nthe forest on screen (render_frame_at, %dx%d, the attract screen; means of "
	       "%d frames)\n", RENDER_W, RENDER_H, reps);
	if (!egl) {
		printf("  no headless GL here (%s): not measured\n", err.msg);
		return;
	}
	r = render_create();
	if (!r)
		must(-12, "render_create");
	if (font_file_read(NULL, &font, &len, &used, &err) == 0)
		(void)render_set_text(r, font, len, RENDER_LANG_EN);
	free(font);
	printf("%5s %9s %6s %8s %10s %10s %10s %10s %10s\n", "trees", "triangles", "draws",
	       "growing", "frame us", "labels us", "main ms", "frame ms", "first ms");
	forest_scene_init(&scene);
	for (size_t i = 0; i < BENCH_COUNT(counts); i++)
		if (!bench_quick || counts[i] <= 10)
			render_row(r, k, counts[i], reps, &scene);
	forest_scene_finish(&scene);
	render_destroy(r);
	egl_headless_destroy(egl);
}

int main(int argc, char **argv)
{
	static const size_t trees[] = { 10, 20, 40 };
	struct kind k[NKINDS + NGROWN];
	int reps;

	if (bench_init(&argc, argv, NULL))
		return 1;
	reps = bench_reps(REPS);
	printf("bench_forest: the forest's levels of detail (medians of %d)\n", reps);
	kinds_init(k);
	for (int i = 0; i < NKINDS + NGROWN; i++)
		if (!bench_quick || i < 3 || i >= NKINDS)
			per_tree(&k[i], reps);
	growth(reps);

	printf("\nthe forest: each tree's share of %d triangles by crown width, water-filled "
	       "(the four trees above in turn)\n", FOREST_TRIANGLES);
	printf("%5s %9s %9s %12s %12s %11s %7s\n", "trees", "least", "most", "triangles",
	       "own meshes", "build ms", "over");
	for (size_t i = 0; i < BENCH_COUNT(trees); i++)
		forest(k, trees[i]);
	layouts(reps);
	render_rows(k, reps);
	for (int i = 0; i < NKINDS + NGROWN; i++)
		tree_finish(&k[i].t);
	return 0;
}
