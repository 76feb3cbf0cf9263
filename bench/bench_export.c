/* SPDX-License-Identifier: MIT */
/*
 * Mesh building and the three exporters on synthetic trees of 100..1,000 branches with 10
 * leaves each: median of REPS runs per stage and in total, growth with size, and what
 * came out (triangles, bytes). Then the mesh alone for drawings made through pen events
 * (bench_draw: 5 cm samples, the kiosk's real input), whose tubes have many more rings.
 * Last, the wind in model.glb (issue 26): export_glb against export_glb_wind (byte
 * targets, the default; float targets) and export_skeleton against export_skeleton_wind,
 * median times and sizes, on the demo (its trace replayed through the app, as drawn and
 * in 3D), cherry and a 1,000-branch tree with 20 leaves a branch. Then today's forest
 * (issue 27): export_glb_forest of 10, 20 and 40 trees of the demo's size (the demo in
 * 3D) and of cherry's, each its own seed and place, with the wind over the 8 s loop,
 * against as many model.glb. Last, a Save with the take-home page (issue 28) of the demo
 * in 3D and of cherry, each drawn by the kiosk's renderer into llvmpipe at 1280x800 for its
 * picture: the page's size and the time to make it (export_page_html with Debian's
 * libjs-three) and to write it (temporary, fsync, rename), every file's size, and the
 * Save's two halves: export_set_build on the main thread, export_set_save (the page made,
 * the six files written, fsynced and renamed) into a fresh directory on this disk.
 */
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "app.h"
#include "bench_draw.h"
#include "bench_util.h"
#include "buf.h"
#include "egl_headless.h"
#include "export.h"
#include "export_set.h"
#include "fileio.h"
#include "font_file.h"
#include "live_trees.h"
#include "mesh.h"
#include "page_viewer.h"
#include "render.h"
#include "render_shaders.h"
#include "synth_tree.h"
#include "trace.h"
#include "tree.h"

#define REPS 7
#define LEAVES_PER_BRANCH 10
#define NSIZES 4
#define NDRAWN 3
#define SEED 2024

enum stage { MESH, GLB, OBJ, SKELETON, TOTAL, NSTAGES };

static const char *const stage_names[NSTAGES] = {
	"tree_mesh_build", "export_glb", "export_obj", "export_skeleton", "total",
};

struct result {
	double median[NSTAGES];
	size_t branches, points, bark_tris, bark_verts, leaf_tris, glb_bytes, obj_bytes, mtl_bytes,
		skel_bytes;
};

static size_t tree_points(const struct tree *t)
{
	size_t n = 0;

	for (size_t i = 0; i < t->nbranches; i++)
		n += t->branches[i].npoints;
	return n;
}

static int run_size(int nbranches, struct result *res)
{
	double times[NSTAGES][REPS];
	struct tree t;
	struct tree_mesh tm;
	struct buf glb, obj, mtl, skel;
	int r, reps = bench_reps(REPS);

	tree_init(&t);
	tree_mesh_init(&tm);
	buf_init(&glb);
	buf_init(&obj);
	buf_init(&mtl);
	buf_init(&skel);
	r = synth_tree(&t, nbranches, LEAVES_PER_BRANCH, SEED);
	for (int rep = 0; rep < reps && r >= 0; rep++) {
		double t0, t1, t2, t3, t4;

		/* Fresh buffers each time, as for one visitor's export. */
		buf_finish(&glb);
		buf_finish(&obj);
		buf_finish(&mtl);
		buf_finish(&skel);
		tree_mesh_finish(&tm);

		t0 = bench_now();
		r = tree_mesh_build(&tm, &t);
		t1 = bench_now();
		if (r >= 0)
			r = export_glb(&t, &tm, NULL, &glb);
		t2 = bench_now();
		if (r >= 0)
			r = export_obj(&t, &tm, NULL, "tree.mtl", &obj, &mtl);
		t3 = bench_now();
		if (r >= 0)
			r = export_skeleton(&t, &skel);
		t4 = bench_now();
		times[MESH][rep] = t1 - t0;
		times[GLB][rep] = t2 - t1;
		times[OBJ][rep] = t3 - t2;
		times[SKELETON][rep] = t4 - t3;
		times[TOTAL][rep] = t4 - t0;
	}
	if (r >= 0) {
		for (int s = 0; s < NSTAGES; s++)
			res->median[s] = bench_median(times[s], (size_t)reps);
		res->points = tree_points(&t);
		res->bark_tris = tm.bark.nindices / 3;
		res->bark_verts = tm.bark.nvertices;
		res->leaf_tris = tm.leaves.nindices / 3;
		res->glb_bytes = glb.len;
		res->obj_bytes = obj.len;
		res->mtl_bytes = mtl.len;
		res->skel_bytes = skel.len;
	}
	buf_finish(&glb);
	buf_finish(&obj);
	buf_finish(&mtl);
	buf_finish(&skel);
	tree_mesh_finish(&tm);
	tree_finish(&t);
	return r;
}

/* The mesh of a drawn tree: median build time, its size. */
static int run_drawn(int nbranches, struct result *res)
{
	struct bench_pen pen = { .pen.now_us = 1000 };
	struct app *app = bench_draw_tree(&pen, nbranches);
	struct tree_mesh tm;
	double times[REPS];
	int r = 0, reps = bench_reps(REPS);

	if (!app)
		return -1;
	tree_mesh_init(&tm);
	for (int rep = 0; rep < reps && r >= 0; rep++) {
		double t0 = bench_now();

		r = tree_mesh_build(&tm, &app->tree);
		times[rep] = bench_now() - t0;
	}
	if (r >= 0) {
		res->median[MESH] = bench_median(times, (size_t)reps);
		res->points = tree_points(&app->tree);
		res->bark_tris = tm.bark.nindices / 3;
		res->bark_verts = tm.bark.nvertices;
		res->leaf_tris = tm.leaves.nindices / 3;
		/* the drawing may refuse a stroke; report what it holds */
		res->branches = app->tree.nbranches;
	}
	tree_mesh_finish(&tm);
	app_destroy(app);
	return r;
}

/* One export of the wind bench: export_glb, export_glb_wind (bytes, floats), skeletons. */
enum wind_op { STILL, WIND, FLOATS, SKEL_STILL, SKEL_WIND, NWIND_OPS };

struct wind_job {
	const struct tree *t;
	struct tree_mesh tm;
	struct tree_mesh_marks mk;
	enum wind_op op;
	size_t bytes;
};

static void wind_export(void *arg)
{
	struct wind_job *j = arg;
	struct export_wind ew = { .strength = 0.0, .angle = EXPORT_WIND_ANGLE, .seed = 1,
				  .floats = j->op == FLOATS };
	struct buf b;
	int r;

	buf_init(&b);
	if (j->op == STILL)
		r = export_glb(j->t, &j->tm, &j->mk, &b);
	else if (j->op == SKEL_STILL)
		r = export_skeleton(j->t, &b);
	else if (j->op == SKEL_WIND)
		r = export_skeleton_wind(j->t, &ew, &b);
	else
		r = export_glb_wind(j->t, &j->tm, &j->mk, &ew, &b);
	if (r < 0) {
		fprintf(stderr, "bench_export: the wind's export failed: %d\n", r);
		exit(1);
	}
	j->bytes = b.len;
	buf_finish(&b);
}

static void wind_row(const char *name, const struct tree *t)
{
	struct wind_job j = { .t = t };
	double ms[NWIND_OPS];
	size_t bytes[NWIND_OPS];
	int reps = bench_reps(REPS);

	tree_mesh_init(&j.tm);
	tree_mesh_marks_init(&j.mk);
	if (tree_mesh_build_marked(&j.tm, t, &j.mk) < 0) {
		fprintf(stderr, "bench_export: no memory\n");
		exit(1);
	}
	for (int op = 0; op < NWIND_OPS; op++) {
		j.op = (enum wind_op)op;
		ms[op] = bench_run(wind_export, &j, reps) * 1e3;
		bytes[op] = j.bytes;
	}
	printf("%-15s %7zu %9.2f %9.1f %9.2f %9.1f %5.0f%% %9.2f %9.1f %5.0f%% %7.2f %7.2f %6.1f\n",
	       name, j.tm.bark.nvertices + j.tm.leaves.nvertices, ms[STILL], bytes[STILL] / 1e3,
	       ms[WIND], bytes[WIND] / 1e3, 100.0 * (bytes[WIND] - bytes[STILL]) / bytes[STILL],
	       ms[FLOATS], bytes[FLOATS] / 1e3,
	       100.0 * (bytes[FLOATS] - bytes[STILL]) / bytes[STILL], ms[SKEL_STILL],
	       ms[SKEL_WIND], (double)(bytes[SKEL_WIND] - bytes[SKEL_STILL]));
	tree_mesh_marks_finish(&j.mk);
	tree_mesh_finish(&j.tm);
}

static void run_wind(void)
{
	struct tree t;

	printf("\nbench_export: the wind in model.glb, median of %d runs (ms, KB; + the wind's "
	       "share of the still file)\n\n", bench_reps(REPS));
	printf("%-15s %7s %9s %9s %9s %9s %6s %9s %9s %6s %7s %7s %6s\n", "tree", "verts",
	       "still ms", "still KB", "wind ms", "wind KB", "+", "float ms", "float KB", "+",
	       "skel ms", "+wind", "+bytes");
	tree_init(&t);
	live_trees_demo(&t, BENCH_DATA_DIR, false);
	wind_row("demo (2D)", &t);
	tree_clear(&t);
	live_trees_demo(&t, BENCH_DATA_DIR, true);
	wind_row("demo (3D)", &t);
	tree_clear(&t);
	live_trees_preset(&t, GEN_PRESET_CHERRY);
	wind_row("cherry", &t);
	if (!bench_quick) {
		tree_clear(&t);
		live_trees_random(&t, 1000, 20, SEED, 12.0);
		wind_row("1,000 branches", &t);
	}
	tree_finish(&t);
}

/* forest.glb of n copies of a tree, each its own seed and place on a sunflower spiral. */
#define FOREST_MAX 40

struct forest_job {
	struct export_forest_tree trees[FOREST_MAX];
	size_t n;
	size_t bytes;
};

static void forest_export(void *arg)
{
	struct forest_job *j = arg;
	const struct export_wind ew = { .strength = 0.0, .angle = EXPORT_WIND_ANGLE };
	struct buf b;

	buf_init(&b);
	if (export_glb_forest(j->trees, j->n, &ew, LIVE_WIND_COMMON_LOOP_S, &b) < 0) {
		fprintf(stderr, "bench_export: export_glb_forest failed\n");
		exit(1);
	}
	j->bytes = b.len;
	buf_finish(&b);
}

static void forest_rows(const char *name, const struct tree *t)
{
	static const size_t sizes[] = { 10, 20, 40 };
	struct forest_job *j = calloc(1, sizeof(*j));
	struct wind_job one = { .t = t, .op = WIND }; /* the meshes, and one model.glb */
	int reps = bench_reps(REPS);

	tree_mesh_init(&one.tm);
	tree_mesh_marks_init(&one.mk);
	if (!j || tree_mesh_build_marked(&one.tm, t, &one.mk) < 0) {
		fprintf(stderr, "bench_export: no memory\n");
		exit(1);
	}
	wind_export(&one);
	for (size_t k = 0; k < FOREST_MAX; k++) {
		double rad = 4.0 * sqrt((double)k + 0.5), a = 2.399963229728653 * (double)k;

		j->trees[k] = (struct export_forest_tree){
			.tree = t, .mesh = &one.tm, .marks = &one.mk, .seed = 1 + k, .number = 1 + k,
			.position = { rad * cos(a), 0.0, rad * sin(a) },
		};
	}
	for (size_t i = 0; i < BENCH_COUNT(sizes); i++) {
		double ms;

		j->n = sizes[i];
		ms = bench_run(forest_export, j, reps) * 1e3;
		printf("%-12s %5zu %9.1f %9.2f %10.1f %9.1f %11.1f\n", name, j->n, ms,
		       ms / (double)j->n, j->bytes / 1e3, j->bytes / 1e3 / (double)j->n,
		       one.bytes / 1e3);
	}
	tree_mesh_marks_finish(&one.mk);
	tree_mesh_finish(&one.tm);
	free(j);
}

static void run_forest(void)
{
	struct tree t;

	printf("\nbench_export: forest.glb (export_glb_forest, the wind over 8 s), median of %d "
	       "runs; each tree its own seed and place\n\n", bench_reps(REPS));
	printf("%-12s %5s %9s %9s %10s %9s %11s\n", "trees of", "trees", "ms", "ms/tree", "KB",
	       "KB/tree", "model.glb KB");
	tree_init(&t);
	live_trees_demo(&t, BENCH_DATA_DIR, true);
	forest_rows("demo (3D)", &t);
	if (!bench_quick) {
		tree_clear(&t);
		live_trees_preset(&t, GEN_PRESET_CHERRY);
		forest_rows("cherry", &t);
	}
	tree_finish(&t);
}

/* ---- a Save with the page (issue 28) ---------------------------------------------- */

#define SAVE_W 1280
#define SAVE_H 800

/* The app as the kiosk holds it at Save: the demo drawn and lifted, or cherry's template. */
static struct app *save_app(bool cherry)
{
	struct app *app = app_create(SAVE_W, SAVE_H, 1);
	struct event e = { .type = EVENT_BUTTON, .pressed = true };
	struct error err = { { 0 } };
	char path[4096];
	struct trace tr;

	if (!app)
		return NULL;
	trace_init(&tr);
	if (!cherry) {
		snprintf(path, sizeof(path), "%s/demo.edaha-trace", BENCH_DATA_DIR);
		if (trace_load(path, SAVE_W, SAVE_H, &tr, &err) < 0) {
			fprintf(stderr, "bench_export: %s\n", err.msg);
			app_destroy(app);
			return NULL;
		}
		for (size_t i = 0; i < tr.nevents; i++)
			app_handle_event(app, &tr.events[i]);
		trace_finish(&tr);
	}
	e.button = cherry ? BUTTON_TPL_CHERRY : BUTTON_3D;
	e.time_us = app->last_time_us + 100000;
	app_handle_event(app, &e);
	e.pressed = false;
	e.time_us += 100000;
	app_handle_event(app, &e);
	(void)app_take_requests(app);
	if (app->failed || app->tree.nbranches == 0) {
		fprintf(stderr, "bench_export: the %s did not come out\n", cherry ? "cherry" : "demo");
		app_destroy(app);
		return NULL;
	}
	return app;
}

/* The screen as the kiosk shows it at Save, read back: the picture's pixels. */
static int save_picture(struct app *app, uint8_t *rgba)
{
	struct error err = { { 0 } };
	struct egl_headless *egl = egl_headless_create(SAVE_W, SAVE_H, &err);
	struct render *render = egl ? render_create() : NULL;
	const char *used;
	char *font = NULL;
	size_t len;
	int r = -EIO;

	if (render && font_file_read(NULL, &font, &len, &used, &err) == 0)
		(void)render_set_text(render, font, len, RENDER_LANG_EN);
	(void)app_vines_advance(app, UINT64_MAX);
	if (render && render_frame(render, app) == 0 && egl_headless_read_rgba(egl, rgba) == 0)
		r = 0;
	else
		fprintf(stderr, "bench_export: no picture: %s\n", err.msg[0] ? err.msg : "rendering failed");
	free(font);
	render_destroy(render);
	egl_headless_destroy(egl);
	return r;
}

static void remove_set(const char *dir)
{
	char cmd[4200];

	snprintf(cmd, sizeof(cmd), "rm -rf '%s'", dir);
	if (system(cmd) != 0)
		fprintf(stderr, "bench_export: cannot remove %s\n", dir);
}

static void save_row(const char *name, bool cherry, const struct page_look *look)
{
	int reps = bench_reps(REPS);
	double build[REPS], write[REPS], page[REPS], page_write[REPS];
	size_t sizes[EXPORT_NAMES_NSUFFIXES] = { 0 }, all = 0;
	struct app *app = save_app(cherry);
	uint8_t *rgba = malloc((size_t)SAVE_W * SAVE_H * 4);
	char dir[] = "/tmp/edaha-bench-save-XXXXXX", sub[64], base[32];
	struct error err = { { 0 } };
	struct export_set s;
	struct buf html;

	if (!app || !rgba || save_picture(app, rgba) < 0 || !mkdtemp(dir)) {
		fprintf(stderr, "bench_export: cannot set up the save of the %s\n", name);
		exit(1);
	}
	buf_init(&html);
	for (int rep = 0; rep < reps; rep++) {
		double t0, t1, t2;
		int fd;

		export_set_init(&s);
		s.page = *look;
		t0 = bench_now();
		if (export_set_build(&s, app, rgba, &err) < 0) {
			fprintf(stderr, "bench_export: %s\n", err.msg);
			exit(1);
		}
		t1 = bench_now();
		snprintf(sub, sizeof(sub), "%s/%d", dir, rep);
		if (mkdir(sub, 0755) < 0 || (fd = open(sub, O_RDONLY | O_DIRECTORY | O_CLOEXEC)) < 0 ||
		    export_set_save(fd, &s, base, sizeof(base), &err) < 0) {
			fprintf(stderr, "bench_export: saving: %s\n", err.msg);
			exit(1);
		}
		t2 = bench_now();
		close(fd);
		build[rep] = t1 - t0;
		write[rep] = t2 - t1;
		/* the page alone: made, then written as fileio writes a file (fsync, rename) */
		buf_reset(&html);
		t0 = bench_now();
		if (look->viewer &&
		    page_viewer_html(look, s.files[EXPORT_SET_GLB].data, s.files[EXPORT_SET_GLB].len,
				     1, s.page_date, &html) < 0) {
			fprintf(stderr, "bench_export: the page: out of memory\n");
			exit(1);
		}
		t1 = bench_now();
		if (look->viewer && fileio_write_atomic(sub, "page.html", html.data, html.len, &err) < 0) {
			fprintf(stderr, "bench_export: %s\n", err.msg);
			exit(1);
		}
		t2 = bench_now();
		page[rep] = t1 - t0;
		page_write[rep] = t2 - t1;
		for (size_t i = 0; i < EXPORT_NAMES_NSUFFIXES; i++)
			sizes[i] = s.files[i].len;
		export_set_finish(&s);
		remove_set(sub);
	}
	for (size_t i = 0; i < EXPORT_NAMES_NSUFFIXES; i++)
		all += sizes[i];
	printf("%-15s %8.1f %8.1f %7.1f %7.1f %9.1f %8.2f %12.2f %8.1f %9.1f %8.1f %8.1f %8.1f\n",
	       name, sizes[EXPORT_SET_GLB] / 1e3, sizes[EXPORT_SET_HTML] / 1e3,
	       sizes[EXPORT_SET_PNG] / 1e3, sizes[EXPORT_SET_EDAHA] / 1e3,
	       (sizes[EXPORT_SET_OBJ] + sizes[EXPORT_SET_MTL]) / 1e3, all / 1e6,
	       (sizes[EXPORT_SET_GLB] + sizes[EXPORT_SET_HTML] + sizes[EXPORT_SET_PNG] +
		sizes[EXPORT_SET_EDAHA]) / 1e6,
	       bench_median(page, (size_t)reps) * 1e3, bench_median(page_write, (size_t)reps) * 1e3,
	       bench_median(build, (size_t)reps) * 1e3, bench_median(write, (size_t)reps) * 1e3,
	       (bench_median(build, (size_t)reps) + bench_median(write, (size_t)reps)) * 1e3);
	remove_set(dir);
	buf_finish(&html);
	free(rgba);
	app_destroy(app);
}

static void run_save(void)
{
	struct page_look look = { .lang = EXPORT_PAGE_EN,
				  .paper = { render_paper[0], render_paper[1], render_paper[2] } };
	struct page_viewer viewer;
	struct error err = { { 0 } };

	page_viewer_init(&viewer);
	if (page_viewer_load(&viewer, NULL, &err) < 0) {
		printf("\nbench_export: no Save with the page: %s (Debian's libjs-three)\n", err.msg);
		return;
	}
	look.viewer = &viewer;
	printf("\nbench_export: a Save with the page (tree-NNNN.*, issue 28), median of %d runs "
	       "(KB, MB, ms); the viewer's scripts %zu KB\n\n", bench_reps(REPS),
	       (viewer.scripts[0].len + viewer.scripts[1].len + viewer.scripts[2].len) / 1000);
	printf("%-15s %8s %8s %7s %7s %9s %8s %12s %8s %9s %8s %8s %8s\n", "tree", "glb KB",
	       "html KB", "png KB", "edaha", "obj+mtl", "set MB", "glb+html+png", "page ms",
	       "page wr ms", "build ms", "write ms", "Save ms");
	printf("%-15s %8s %8s %7s %7s %9s %8s %12s\n", "", "", "", "", "KB", "KB", "", "+edaha MB");
	save_row("demo (3D)", false, &look);
	if (!bench_quick)
		save_row("cherry", true, &look);
	/* as before the page: the same Save without it */
	look.viewer = NULL;
	save_row("demo, no page", false, &look);
	if (!bench_quick)
		save_row("cherry, no page", true, &look);
	page_viewer_finish(&viewer);
}

int main(int argc, char **argv)
{
	static const int sizes[NSIZES] = { 100, 250, 500, 1000 };
	static const int drawn_sizes[NDRAWN] = { 250, 500, 1000 };
	struct result res[NSIZES], drawn[NDRAWN];
	double prev_size = 0, prev_s = 0;
	int nsizes, ndrawn;

	if (bench_init(&argc, argv, NULL))
		return 1;
	nsizes = (int)BENCH_COUNT(sizes);
	ndrawn = (int)BENCH_COUNT(drawn_sizes);

	for (int i = 0; i < nsizes; i++) {
		int r = run_size(sizes[i], &res[i]);

		if (r < 0) {
			fprintf(stderr, "bench_export: %d branches failed: %d\n", sizes[i], r);
			return 1;
		}
	}

	printf("bench_export: synth_tree(n branches, %d leaves each), median of %d runs;"
	       " size = branches\n\n",
	       LEAVES_PER_BRANCH, bench_reps(REPS));
	for (int s = 0; s < NSTAGES; s++) {
		prev_size = 0;
		prev_s = 0;
		for (int i = 0; i < nsizes; i++)
			bench_row(stage_names[s], sizes[i], res[i].median[s], &prev_size, &prev_s);
		printf("\n");
	}

	printf("%8s %8s %8s %10s %10s %9s %10s %11s %11s %10s\n", "branches", "points", "leaves",
	       "bark tris", "bark verts", "tris/br.", "leaf tris", "glb bytes", "obj bytes",
	       "skel bytes");
	for (int i = 0; i < nsizes; i++)
		printf("%8d %8zu %8d %10zu %10zu %9.1f %10zu %11zu %11zu %10zu\n", sizes[i],
		       res[i].points, sizes[i] * LEAVES_PER_BRANCH, res[i].bark_tris,
		       res[i].bark_verts, (double)res[i].bark_tris / sizes[i], res[i].leaf_tris,
		       res[i].glb_bytes, res[i].obj_bytes + res[i].mtl_bytes, res[i].skel_bytes);

	for (int i = 0; i < ndrawn; i++) {
		int r = run_drawn(drawn_sizes[i], &drawn[i]);

		if (r < 0) {
			fprintf(stderr, "bench_export: drawing %d branches failed: %d\n",
				drawn_sizes[i], r);
			return 1;
		}
	}
	printf("\nbench_export: drawn trees (bench_draw: 1 + n strokes through pen events),"
	       " median of %d runs\n\n",
	       bench_reps(REPS));
	prev_size = 0;
	prev_s = 0;
	for (int i = 0; i < ndrawn; i++)
		bench_row("tree_mesh_build (drawn)", drawn_sizes[i], drawn[i].median[MESH],
			  &prev_size, &prev_s);
	printf("\n%8s %8s %10s %10s %9s %10s\n", "branches", "points", "bark tris", "bark verts",
	       "tris/br.", "leaf tris");
	for (int i = 0; i < ndrawn; i++)
		printf("%8zu %8zu %10zu %10zu %9.1f %10zu\n", drawn[i].branches, drawn[i].points,
		       drawn[i].bark_tris, drawn[i].bark_verts,
		       (double)drawn[i].bark_tris / (double)drawn[i].branches, drawn[i].leaf_tris);
	run_wind();
	run_forest();
	run_save();
	return 0;
}
