/* SPDX-License-Identifier: MIT */
/*
 * Autosave: what one committed stroke costs the loop (find what changed, build the
 * record, append, fsync), what the restart costs (read and replay the journal, write it
 * afresh as one record), and the archive at the idle reset, for drawings of 62..500
 * strokes. The journal lives in $TMPDIR (default /tmp): fsync's cost is that disk's.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "app.h"
#include "autosave.h"
#include "bench_draw.h"
#include "bench_util.h"

#define REPS 9

struct restart {
	const char *dir;
};

static void restart(void *arg)
{
	struct restart *r = arg;
	struct error err, warn;
	struct autosave *a = autosave_create(r->dir, &err);
	struct doc d;

	doc_init(&d, 0);
	if (!a || autosave_restore(a, &d, &warn, &err) != 1 || autosave_start(a, &d, &err) < 0) {
		fprintf(stderr, "bench_autosave: restart failed: %s\n", err.msg);
		exit(1);
	}
	doc_finish(&d);
	autosave_destroy(a);
}

int main(int argc, char **argv)
{
	const char *tmp = getenv("TMPDIR");
	char dir[512], cmd[600], name[64];
	double cs = 0, ct = 0, rs = 0, rt = 0, as = 0, at = 0;
	int reps, last;

	if (bench_init(&argc, argv, NULL))
		return 1;
	reps = bench_reps(REPS);
	last = bench_quick ? 124 : 500;
	snprintf(dir, sizeof(dir), "%s/edaha-bench-autosave-XXXXXX", tmp ? tmp : "/tmp");
	if (!mkdtemp(dir)) {
		perror("mkdtemp");
		return 1;
	}
	printf("commit = one stroke appended and fsync'ed; restart = read, replay, rewrite the journal\n");
	for (int n = 62; n <= last; n *= 2) {
		struct bench_pen pen = { .pen.now_us = 1000 };
		struct app *app = bench_draw_tree(&pen, n);
		struct error err;
		struct autosave *a = autosave_create(dir, &err);
		struct restart r = { dir };
		double commit[REPS], arch[REPS];

		if (!app || !a || autosave_start(a, &app->doc, &err) < 0) {
			fprintf(stderr, "bench_autosave: %s\n", err.msg);
			return 1;
		}
		for (int i = 0; i < reps; i++) {
			double t0;

			bench_draw_stroke(app, &pen, 560, 400 + 20 * i, 700, 300, 32, NULL);
			t0 = bench_now();
			if (autosave_sync(a, &app->doc, &err) < 0) {
				fprintf(stderr, "bench_autosave: %s\n", err.msg);
				return 1;
			}
			commit[i] = bench_now() - t0;
			t0 = bench_now();
			if (autosave_archive(a, &app->doc, &app->tree, 3, name, sizeof(name), &err) < 0) {
				fprintf(stderr, "bench_autosave: %s\n", err.msg);
				return 1;
			}
			arch[i] = bench_now() - t0;
		}
		autosave_destroy(a);
		snprintf(name, sizeof(name), "commit 1 stroke (%zu ops)", app->doc.nops);
		bench_row(name, n, bench_median(commit, (size_t)reps), &cs, &ct);
		snprintf(name, sizeof(name), "restart (%zu ops)", app->doc.nops);
		bench_row(name, n, bench_run(restart, &r, reps), &rs, &rt);
		snprintf(name, sizeof(name), "archive (%zu ops)", app->doc.nops);
		bench_row(name, n, bench_median(arch, (size_t)reps), &as, &at);
		app_destroy(app);
	}
	snprintf(cmd, sizeof(cmd), "rm -rf '%s'", dir);
	return system(cmd) == 0 ? 0 : 1;
}
