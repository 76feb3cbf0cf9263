/* SPDX-License-Identifier: MIT */
#include "live_trees.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "app.h"
#include "error.h"
#include "synth_tree.h"
#include "test.h"
#include "trace.h"

#define DEMO_W 1280
#define DEMO_H 800
#define DEMO_SEED 1

void live_trees_demo(struct tree *t, const char *data_dir, bool lift)
{
	char path[4096];
	struct trace tr;
	struct error err = { { 0 } };
	struct app *app = app_create(DEMO_W, DEMO_H, DEMO_SEED);

	CHECK(app);
	snprintf(path, sizeof(path), "%s/demo.edaha-trace", data_dir);
	trace_init(&tr);
	if (trace_load(path, DEMO_W, DEMO_H, &tr, &err) < 0) {
		fprintf(stderr, "%s\n", err.msg);
		exit(1);
	}
	for (size_t i = 0; i < tr.nevents; i++)
		app_handle_event(app, &tr.events[i]);
	trace_finish(&tr);
	if (lift) {
		struct event e = { .type = EVENT_BUTTON, .time_us = app->last_time_us + 100000,
				   .button = BUTTON_3D, .pressed = true };

		app_handle_event(app, &e);
		e.pressed = false;
		app_handle_event(app, &e);
		CHECK(app->tree.lifted);
	}
	CHECK_INT(app->failed, 0);
	CHECK_INT(tree_copy(t, &app->tree), 0);
	app_destroy(app);
}

void live_trees_preset(struct tree *t, enum gen_preset which)
{
	struct gen_params p;
	struct error err = { { 0 } };

	CHECK_INT(gen_preset(which, &p, &err), 0);
	CHECK_INT(gen_build(t, &p, 1), 0);
}

struct vec3 live_trees_point(const struct tree *t, size_t b, double u)
{
	return tree_frame_at(&t->branches[b], u).origin;
}

/* Arc-length parameter of the point of b nearest p. */
static double project(const struct branch *b, struct vec3 p)
{
	double best = INFINITY, at = 0.0, walked = 0.0, len = tree_branch_length(b);

	for (size_t i = 0; i + 1 < b->npoints; i++) {
		struct vec3 e = vec3_sub(b->points[i + 1], b->points[i]);
		double ee = vec3_dot(e, e), f = ee > 0 ? vec3_dot(vec3_sub(p, b->points[i]), e) / ee : 0;
		double d;

		f = f < 0 ? 0 : f > 1 ? 1 : f;
		d = vec3_dist(p, vec3_add(b->points[i], vec3_scale(e, f)));
		if (d < best) {
			best = d;
			at = walked + f * sqrt(ee);
		}
		walked += sqrt(ee);
	}
	return len > 0 ? at / len : 0.0;
}

void live_trees_scale(struct tree *t, double k)
{
	struct vec3 o = t->nbranches ? t->branches[0].points[0] : vec3(0, 0, 0);

	for (size_t i = 0; i < t->nbranches; i++) {
		struct branch *b = &t->branches[i];

		for (size_t j = 0; j < b->npoints; j++) {
			b->points[j] = vec3_add(o, vec3_scale(vec3_sub(b->points[j], o), k));
			b->radii[j] *= k;
		}
	}
	for (size_t i = 0; i < t->nleaves; i++)
		for (size_t j = 0; j < t->leaves[i].npoints; j++)
			t->leaves[i].points[j] =
				vec3_add(o, vec3_scale(vec3_sub(t->leaves[i].points[j], o), k));
}

void live_trees_random(struct tree *t, int nbranches, int leaves_per_branch, uint64_t seed,
		       double height)
{
	CHECK_INT(synth_tree(t, nbranches, leaves_per_branch, seed), 0);
	for (size_t i = 0; i < t->nleaves; i++) {
		struct leaf *l = &t->leaves[i];
		struct vec3 c = vec3(0, 0, 0);

		for (size_t j = 0; j < l->npoints; j++)
			c = vec3_add(c, l->points[j]);
		c = vec3_scale(c, 1.0 / (double)l->npoints);
		l->branch_t = project(&t->branches[l->branch], c);
	}
	{
		double top = 0.0;

		for (size_t i = 0; i < t->nbranches; i++)
			for (size_t j = 0; j < t->branches[i].npoints; j++)
				top = fmax(top, t->branches[i].points[j].y - t->branches[0].points[0].y);
		live_trees_scale(t, height / top);
	}
}

int live_trees_dominant(const struct vec3 *x, int n)
{
	static double *cs, *sn; /* cos, sin of 2 pi m i / n for the last n asked */
	static int table_n;
	int best = 1;
	double best_p = -1.0;

	if (table_n != n) {
		free(cs);
		free(sn);
		cs = malloc((size_t)n * (size_t)n * sizeof(*cs));
		sn = malloc((size_t)n * (size_t)n * sizeof(*sn));
		CHECK(cs && sn);
		for (int m = 0; m < n; m++)
			for (int i = 0; i < n; i++) {
				cs[m * n + i] = cos(2.0 * VEC_PI * (double)((long)m * i % n) / n);
				sn[m * n + i] = sin(2.0 * VEC_PI * (double)((long)m * i % n) / n);
			}
		table_n = n;
	}
	for (int m = 1; m <= n / 2; m++) {
		double re[3] = { 0 }, im[3] = { 0 }, p = 0.0;

		for (int i = 0; i < n; i++) {
			double c = cs[m * n + i], s = sn[m * n + i];

			re[0] += x[i].x * c;
			re[1] += x[i].y * c;
			re[2] += x[i].z * c;
			im[0] -= x[i].x * s;
			im[1] -= x[i].y * s;
			im[2] -= x[i].z * s;
		}
		for (int a = 0; a < 3; a++)
			p += re[a] * re[a] + im[a] * im[a];
		if (p > best_p) {
			best_p = p;
			best = m;
		}
	}
	return best;
}
