/* SPDX-License-Identifier: MIT */
/*
 * Today's forest on the kiosk (platform/forest_job.c, kiosk_forest.c): what its planting
 * thread costs, and whether the pen feels it.
 *
 *  - A start: a job from nothing over an archive of n drawings (the templates' trees,
 *    each with its own seed), for 10, 20 and 40: the day read, every drawing planted,
 *    each tree's part at its share, the layout and the scene. Per tree too.
 *  - A visitor's tree joining a forest of n - 1: one drawing planted, the parts whose
 *    share moved made again, the scene.
 *  - The pen while planting: the main thread's work for a pen event (the event into the
 *    app, a frame drawn to glFinish, llvmpipe's rendering included) with the planting
 *    thread idle and with it planting 40 drawings over and over at the kiosk's nice.
 *    Medians and 90th percentiles; the machine's cores are printed, as they decide it.
 */
#define _GNU_SOURCE
#include <errno.h>
#include <inttypes.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include <GLES2/gl2.h>

#include "app.h"
#include "autosave.h"
#include "bench_util.h"
#include "doc.h"
#include "egl_headless.h"
#include "fileio.h"
#include "forest_job.h"
#include "forest_state.h"
#include "render.h"

static char state[256];

static void must(int r, const char *what)
{
	if (r < 0) {
		fprintf(stderr, "bench_forest_job: %s: %s\n", what, strerror(-r));
		exit(1);
	}
}

static const enum button templates[] = { BUTTON_TPL_CHERRY, BUTTON_TPL_ZELKOVA, BUTTON_TPL_HEDGE,
					  BUTTON_TPL_BALL, BUTTON_TPL_CONE, BUTTON_TPL_PALM };
#define NTEMPLATES (sizeof(templates) / sizeof(templates[0]))

/* Archive drawing number a: template a mod 6's tree, seed a. */
static void archive(uint64_t a)
{
	struct app *app = app_create(1280, 800, 1000 + a);
	struct error err = { { 0 } };
	char dir[300], name[64];
	struct buf b;

	if (!app)
		must(-ENOMEM, "app_create");

	struct event ev = { .type = EVENT_BUTTON, .button = templates[a % NTEMPLATES],
			    .pressed = true, .time_us = 1000 };

	app_handle_event(app, &ev);
	ev.pressed = false;
	ev.time_us += 50000;
	app_handle_event(app, &ev);
	if (app->failed || !app->tree.nbranches)
		must(-EINVAL, "a template made no tree");
	buf_init(&b);
	must(doc_serialize(&app->doc, &app->tree, &b), "doc_serialize");
	snprintf(dir, sizeof(dir), "%s/%s", state, AUTOSAVE_ARCHIVE_DIR);
	snprintf(name, sizeof(name), "drawing-%06" PRIu64 ".edaha", a);
	must(fileio_mkdirs(dir, &err), err.msg);
	must(fileio_write_atomic(dir, name, b.data, b.len, &err), err.msg);
	buf_finish(&b);
	app_destroy(app);
}

static void clear(void)
{
	char cmd[300];

	snprintf(cmd, sizeof(cmd), "rm -rf '%s'", state);
	if (system(cmd) != 0)
		must(-EIO, "rm");
}

struct kiosk_side {
	struct forest_tree *trees;
	size_t ntrees;
	struct forest_scene scene;
};

static void free_trees(struct forest_tree *t, size_t n)
{
	for (size_t i = 0; i < n; i++) {
		forest_planted_finish(t[i].planted);
		free(t[i].planted);
		forest_part_finish(t[i].part);
		free(t[i].part);
	}
	free(t);
}

/* One job over the state directory, reusing k's trees; adopts its result. */
static void job(struct kiosk_side *k, size_t max)
{
	struct error err = { { 0 } };
	struct forest_job j = { .state_dir = state, .max = max, .reset_hour = 4, .now = 1796443200 + 3600,
				.strength = 0.35, .had = k->trees, .nhad = k->ntrees,
				.scene = &k->scene };

	must(forest_job_run(&j, &err), err.msg);
	/* the old trees the job kept are in j.trees; the others freed */
	for (size_t i = 0; i < k->ntrees; i++) {
		bool kept_planted = false, kept_part = false;

		for (size_t n = 0; n < j.ntrees; n++) {
			kept_planted |= j.trees[n].planted == k->trees[i].planted;
			kept_part |= j.trees[n].part == k->trees[i].part;
		}
		if (!kept_planted) {
			forest_planted_finish(k->trees[i].planted);
			free(k->trees[i].planted);
		}
		if (!kept_part) {
			forest_part_finish(k->trees[i].part);
			free(k->trees[i].part);
		}
	}
	free(k->trees);
	k->trees = j.trees;
	k->ntrees = j.ntrees;
	j.trees = NULL;
	j.ntrees = 0;
	forest_job_finish(&j);
}

static void day_file(void)
{
	struct error err = { { 0 } };
	struct forest_day d = { 1796443200, 1 }; /* 04:00 UTC; the jobs run at 05:00 */

	must(forest_state_save(state, &d, &err), err.msg);
}

static void starts(int reps)
{
	static const size_t counts[] = { 10, 20, 40 };

	puts("A start: a job from nothing over an archive of n drawings (templates, own seeds)");
	puts("    n   median_ms   ms_a_tree   triangles");
	for (size_t c = 0; c < BENCH_COUNT(counts); c++) {
		size_t n = counts[c], tris = 0;
		double t[8];

		clear();
		for (uint64_t a = 1; a <= n; a++)
			archive(a);
		day_file();
		for (int r = 0; r < reps; r++) {
			struct kiosk_side k = { 0 };
			double t0;

			forest_scene_init(&k.scene);
			t0 = bench_now();
			job(&k, n);
			t[r] = bench_now() - t0;
			if (k.ntrees != n)
				must(-EINVAL, "not every drawing stands");
			tris = (k.scene.mesh.bark.nindices + k.scene.mesh.leaves.nindices) / 3;
			free_trees(k.trees, k.ntrees);
			forest_scene_finish(&k.scene);
		}
		double m = bench_median(t, (size_t)reps);

		printf("%5zu %11.1f %11.1f %11zu\n", n, m * 1e3, m * 1e3 / (double)n, tris);
	}
}

static void joins(int reps)
{
	static const size_t counts[] = { 10, 20, 40 };

	puts("A tree joining a forest of n - 1 (max n): one planted, parts whose share moved redone");
	puts("    n   median_ms   parts_redone");
	for (size_t c = 0; c < BENCH_COUNT(counts); c++) {
		size_t n = counts[c], redone = 0;
		double t[8];

		for (int r = 0; r < reps; r++) {
			struct kiosk_side k = { 0 };
			struct forest_part **before = calloc(n, sizeof(*before));
			double t0;

			clear();
			for (uint64_t a = 1; a < n; a++)
				archive(a);
			day_file();
			forest_scene_init(&k.scene);
			job(&k, n);
			for (size_t i = 0; i < k.ntrees; i++)
				before[i] = k.trees[i].part;
			archive(n);
			t0 = bench_now();
			job(&k, n);
			t[r] = bench_now() - t0;
			redone = 0;
			for (size_t i = 0; i + 1 < k.ntrees; i++)
				redone += k.trees[i].part != before[i];
			free(before);
			free_trees(k.trees, k.ntrees);
			forest_scene_finish(&k.scene);
		}
		printf("%5zu %11.1f %14zu\n", n, bench_median(t, (size_t)reps) * 1e3, redone);
	}
}

/* ---- the pen while planting --------------------------------------------------- */

struct planter {
	pthread_t thread;
	volatile bool stop;
	size_t jobs;
};

static void *plant_loop(void *arg)
{
	struct planter *p = arg;

	(void)setpriority(PRIO_PROCESS, (id_t)gettid(), 10); /* as kiosk_forest.c */
	while (!p->stop) {
		struct kiosk_side k = { 0 };

		forest_scene_init(&k.scene);
		job(&k, 40);
		free_trees(k.trees, k.ntrees);
		forest_scene_finish(&k.scene);
		p->jobs++;
	}
	return NULL;
}

/* A pen stroke's events, each into the app and drawn: the main thread's time an event. */
static void pen(struct render *r, struct app *app, int events, double *out)
{
	struct event ev = { .type = EVENT_TIP_DOWN, .tool = EVENT_TOOL_PEN, .x = 400, .y = 700,
			    .pressure = 0.6, .time_us = 1000000 };

	app_handle_event(app, &ev);
	for (int i = 0; i < events; i++) {
		double t0 = bench_now();

		ev.type = EVENT_MOTION;
		ev.x = 400 + 2.0 * (i % 100);
		ev.y = 700 - 4.0 * (i % 100);
		ev.time_us += 8000;
		app_handle_event(app, &ev);
		must(render_frame_at(r, app, ev.time_us), "render_frame_at");
		glFinish();
		out[i] = bench_now() - t0;
		if (i % 100 == 99) {
			ev.type = EVENT_TIP_UP;
			app_handle_event(app, &ev);
			ev.type = EVENT_TIP_DOWN;
			app_handle_event(app, &ev);
		}
	}
	ev.type = EVENT_TIP_UP;
	app_handle_event(app, &ev);
}

static double p90(double *v, size_t n)
{
	bench_median(v, n); /* sorts */
	return v[(size_t)(0.9 * (double)(n - 1))];
}

static void pen_rows(int events)
{
	struct error err = { { 0 } };
	struct egl_headless *egl = egl_headless_create(1280, 800, &err);
	struct render *r;
	struct app *app;
	struct planter p = { 0 };
	double *idle = calloc((size_t)events, sizeof(double));
	double *busy = calloc((size_t)events, sizeof(double));

	if (!egl) {
		printf("The pen while planting: no headless EGL here (%s)\n", err.msg);
		free(idle);
		free(busy);
		return;
	}
	r = render_create();
	app = app_create(1280, 800, 1);
	if (!r || !app || !idle || !busy)
		must(-ENOMEM, "render_create");
	clear();
	for (uint64_t a = 1; a <= 40; a++)
		archive(a);
	day_file();
	pen(r, app, events, idle);
	if (pthread_create(&p.thread, NULL, plant_loop, &p) != 0)
		must(-EAGAIN, "pthread_create");
	usleep(100000);
	pen(r, app, events, busy);
	p.stop = true;
	pthread_join(p.thread, NULL);
	printf("The pen while planting (%ld cores; an event into the app and its frame drawn, %d events)\n",
	       sysconf(_SC_NPROCESSORS_ONLN), events);
	puts("                       median_ms   p90_ms");
	printf("  planting thread idle %9.2f %8.2f\n", bench_median(idle, (size_t)events) * 1e3,
	       p90(idle, (size_t)events) * 1e3);
	printf("  planting 40 drawings %9.2f %8.2f   (%zu forests planted meanwhile)\n",
	       bench_median(busy, (size_t)events) * 1e3, p90(busy, (size_t)events) * 1e3, p.jobs);
	app_destroy(app);
	render_destroy(r);
	egl_headless_destroy(egl);
	free(idle);
	free(busy);
}

int main(int argc, char **argv)
{
	const char *tmp = getenv("TMPDIR");

	if (bench_init(&argc, argv, NULL))
		return 1;
	/* the day's clock in UTC, whatever this machine's zone */
	setenv("TZ", "UTC", 1);
	tzset();
	snprintf(state, sizeof(state), "%s/edaha-bench-forest-job.%d", tmp ? tmp : "/tmp", (int)getpid());
	starts(bench_reps(3));
	joins(bench_reps(3));
	pen_rows(bench_quick ? 20 : 300);
	clear();
	return 0;
}
