/* SPDX-License-Identifier: MIT */
/*
 * One branch or two (docs/sketching.md, "Thickness: one stroke or two"), replayed as edaha
 * traces through the trace parser and the pen path, asserting on skeleton.json:
 * - fans of 3 to 7 branches from one point, 10 to 45 degrees apart, drawn 0.2 to 1.5 s
 *   apart, with two twigs on each: every branch is kept;
 * - real two-outline trunks and branches, the second outline drawn either way: one thick
 *   branch each;
 * - a property test over seeded random sketches (strokes, fans, outline pairs, undo);
 * and everywhere: no branch's radius grows toward its tip, and no root radius is over a
 * quarter of its branch's length.
 */
#include <json-c/json.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app.h"
#include "buf.h"
#include "layout.h"
#include "replay_util.h"
#include "rng.h"
#include "test.h"
#include "trace.h"

#define W 1280
#define H 800
/* the pen samples every 8 ms, at a child's pace of about 500 px/s */
#define SAMPLE_US 8000
#define PX_PER_SAMPLE 4.0

/* docs/skeleton-format.md: x = (px - W/2) * 10/H, y = (0.92 H - py) * 10/H */
static double px_of_m(double m) { return m * H / 10.0; }
static double to_px_x(double x) { return x * H / 10.0 + W / 2.0; }
static double to_px_y(double y) { return 0.92 * H - y * H / 10.0; }

/* An edaha trace being written, as --record would write it. */
struct pen_trace {
	struct buf text;
	uint64_t t;
	struct rng jitter; /* a hand's wobble, in tenths of a pixel */
};

static void trace_begin(struct pen_trace *p, uint64_t seed)
{
	static const char head[] = "edaha-trace 1\nscreen 1280 800\n";

	buf_init(&p->text);
	CHECK_INT(buf_append(&p->text, head, strlen(head)), 0);
	p->t = 100000;
	rng_seed(&p->jitter, seed);
}

static void trace_event(struct pen_trace *p, enum event_type type, double x, double y, double pressure)
{
	struct event e = { .type = type, .time_us = p->t, .tool = EVENT_TOOL_PEN, .x = x, .y = y,
			   .pressure = pressure };
	char line[TRACE_LINE_MAX];
	int n = trace_format_event(&e, line, sizeof(line));

	CHECK(n > 0);
	CHECK_INT(buf_append(&p->text, line, (size_t)n), 0);
	p->t += SAMPLE_US;
}

/* A stroke along (x0,y0)-(x1,y1), then `pause_s` before the next. The ends are where the
 * pen went down and up; in between the hand wobbles by up to `wobble` px. */
static void trace_line(struct pen_trace *p, double x0, double y0, double x1, double y1,
		       double wobble, double pause_s)
{
	int n = (int)ceil(hypot(x1 - x0, y1 - y0) / PX_PER_SAMPLE);

	n = n < 2 ? 2 : n;
	trace_event(p, EVENT_PROXIMITY_IN, x0, y0, 0);
	trace_event(p, EVENT_TIP_DOWN, x0, y0, 0.5);
	for (int i = 1; i <= n; i++) {
		double f = (double)i / n, w = i < n ? wobble : 0.0;

		trace_event(p, EVENT_MOTION, x0 + (x1 - x0) * f + w * rng_range(&p->jitter, -1, 1),
			    y0 + (y1 - y0) * f + w * rng_range(&p->jitter, -1, 1), 0.6);
	}
	trace_event(p, EVENT_TIP_UP, x1, y1, 0);
	trace_event(p, EVENT_PROXIMITY_OUT, x1, y1, 0);
	p->t += (uint64_t)(pause_s * 1e6);
}

static void trace_press(struct pen_trace *p, enum button b, double pause_s)
{
	char line[TRACE_LINE_MAX];
	struct event e = { .type = EVENT_BUTTON, .time_us = p->t, .button = (int)b, .pressed = true };
	int n = trace_format_event(&e, line, sizeof(line));

	CHECK(n > 0);
	CHECK_INT(buf_append(&p->text, line, (size_t)n), 0);
	e.pressed = false;
	e.time_us += 50000;
	n = trace_format_event(&e, line, sizeof(line));
	CHECK(n > 0);
	CHECK_INT(buf_append(&p->text, line, (size_t)n), 0);
	p->t += 50000 + (uint64_t)(pause_s * 1e6);
}

/* The trace so far parsed, and its events from the `fed`th on given to app. */
static void trace_feed(struct pen_trace *p, const char *name, struct app *app, size_t *fed)
{
	struct trace t;
	struct error err = { { 0 } };

	trace_init(&t);
	if (trace_parse_edaha((const char *)p->text.data, p->text.len, name, W, H, &t, &err) < 0) {
		fprintf(stderr, "%s\n", err.msg);
		exit(1);
	}
	for (size_t i = *fed; i < t.nevents; i++)
		app_handle_event(app, &t.events[i]);
	*fed = t.nevents;
	trace_finish(&t);
	CHECK_INT(app->failed, 0);
}

/* The trace replayed into a new app. */
static struct app *trace_replay(struct pen_trace *p, const char *name)
{
	struct app *app = app_create(W, H, 1);
	size_t fed = 0;

	CHECK(app);
	trace_feed(p, name, app, &fed);
	return app;
}

static json_object *branch(json_object *s, size_t i)
{
	return json_object_array_get_idx(replay_get(s, "branches"), i);
}

static size_t nbranches(json_object *s)
{
	return json_object_array_length(replay_get(s, "branches"));
}

static double coord(json_object *pts, size_t k, size_t axis)
{
	return json_object_get_double(json_object_array_get_idx(json_object_array_get_idx(pts, k), axis));
}

static double radius(json_object *s, size_t i, size_t k)
{
	return json_object_get_double(json_object_array_get_idx(replay_get(branch(s, i), "radii"), k));
}

static double length(json_object *s, size_t i)
{
	json_object *pts = replay_get(branch(s, i), "points");
	double len = 0.0;

	for (size_t k = 1; k < json_object_array_length(pts); k++)
		len += sqrt(pow(coord(pts, k, 0) - coord(pts, k - 1, 0), 2) +
			    pow(coord(pts, k, 1) - coord(pts, k - 1, 1), 2) +
			    pow(coord(pts, k, 2) - coord(pts, k - 1, 2), 2));
	return len;
}

/* The two invariants, on skeleton.json; `what` names the drawing in a failure. The
 * file's numbers are rounded, hence the tolerances. */
static void check_invariants(const struct app *app, const char *what)
{
	json_object *s = replay_skeleton_json(&app->tree);

	for (size_t i = 0; i < nbranches(s); i++) {
		size_t n = json_object_array_length(replay_get(branch(s, i), "radii"));
		double len = length(s, i);

		for (size_t k = 1; k < n; k++) {
			if (radius(s, i, k) > radius(s, i, k - 1) * (1 + 1e-5) + 1e-7) {
				fprintf(stderr, "%s: branch %zu widens at point %zu: %g -> %g\n", what, i, k,
					radius(s, i, k - 1), radius(s, i, k));
				exit(1);
			}
		}
		if (radius(s, i, 0) > 0.25 * len * (1 + 1e-5) + 1e-7) {
			fprintf(stderr, "%s: branch %zu: root radius %g over a quarter of its length %g\n",
				what, i, radius(s, i, 0), len);
			exit(1);
		}
	}
	json_object_put(s);
}

/* The drawing of issue 13: a trunk, `n` mains fanned from its top `deg` apart, then two
 * twigs on each main; strokes `pause_s` apart. */
static void draw_fan(struct pen_trace *p, int n, double deg, double pause_s, double wobble)
{
	const double tx = 640, ty = 430, len = 170;

	trace_line(p, 640, 736, tx, ty, wobble, pause_s);
	for (int k = 0; k < n; k++) {
		double a = (k - (n - 1) / 2.0) * deg * VEC_PI / 180.0;

		trace_line(p, tx, ty, tx + len * sin(a), ty - len * cos(a), wobble, pause_s);
	}
	for (int k = 0; k < n; k++) {
		double a = (k - (n - 1) / 2.0) * deg * VEC_PI / 180.0;

		for (int j = 0; j < 2; j++) {
			double f = j ? 0.75 : 0.45, b = a + (j ? -0.6 : 0.6);
			double x = tx + f * len * sin(a), y = ty - f * len * cos(a);

			trace_line(p, x, y, x + 55 * sin(b), y - 55 * cos(b), wobble, pause_s);
		}
	}
}

static void test_fans(void)
{
	static const double degs[] = { 10, 20, 30, 45 }, pauses[] = { 0.2, 0.33, 0.7, 1.5 };

	for (int n = 3; n <= 7; n++) {
		for (size_t d = 0; d < sizeof(degs) / sizeof(degs[0]); d++) {
			for (size_t q = 0; q < sizeof(pauses) / sizeof(pauses[0]); q++) {
				struct pen_trace p;
				struct app *app;
				json_object *s;
				char what[96];

				snprintf(what, sizeof(what), "fan of %d, %g deg, %g s", n, degs[d], pauses[q]);
				trace_begin(&p, (uint64_t)(n * 100 + d * 10 + q));
				draw_fan(&p, n, degs[d], pauses[q], 0.6);
				app = trace_replay(&p, what);
				s = replay_skeleton_json(&app->tree);
				if (nbranches(s) != (size_t)(1 + 3 * n))
					fprintf(stderr, "%s: %zu branches\n", what, nbranches(s));
				CHECK_INT(nbranches(s), 1 + 3 * n);
				/* every main on the trunk, every twig on a main */
				for (int k = 0; k < 3 * n; k++) {
					int parent = json_object_get_int(replay_get(branch(s, (size_t)k + 1), "parent"));

					CHECK_INT(parent, k < n ? 0 : 1 + (k - n) / 2);
				}
				CHECK(!app->tree.has_profile);
				check_invariants(app, what);
				json_object_put(s);
				buf_finish(&p.text);
				app_destroy(app);
			}
		}
	}
}

/* A trunk drawn as its two outlines `gap` px apart, the second up or down, then a branch
 * to the right drawn as its outlines 14 px apart, the second either way. */
static void test_real_outlines(void)
{
	for (int trunk_down = 0; trunk_down <= 1; trunk_down++) {
		for (int branch_back = 0; branch_back <= 1; branch_back++) {
			struct pen_trace p;
			struct app *app;
			json_object *s;
			char what[64];
			double x, y, r;

			snprintf(what, sizeof(what), "outlines (%s, %s)", trunk_down ? "up-down" : "up-up",
				 branch_back ? "out-back" : "out-out");
			trace_begin(&p, 7 + (uint64_t)(2 * trunk_down + branch_back));
			trace_line(&p, 610, 736, 612, 316, 0.8, 0.4);
			if (trunk_down)
				trace_line(&p, 668, 316, 670, 736, 0.8, 0.8);
			else
				trace_line(&p, 670, 736, 668, 316, 0.8, 0.8);
			/* outlines of a branch on the trunk's right edge, 14 px apart */
			trace_line(&p, 640, 493, 900, 413, 0.6, 0.3);
			if (branch_back)
				trace_line(&p, 900, 427, 640, 507, 0.6, 1.0);
			else
				trace_line(&p, 640, 507, 900, 427, 0.6, 1.0);
			/* and a single stroke, which tapers like the trunk */
			trace_line(&p, 640, 620, 480, 540, 0.6, 1.0);
			app = trace_replay(&p, what);
			s = replay_skeleton_json(&app->tree);
			CHECK_INT(nbranches(s), 3);
			CHECK(app->tree.has_profile);
			/* the trunk: 58 px apart at the ground, so 29 px radius, axis at x = 640 */
			CHECK_NEAR(px_of_m(radius(s, 0, 0)), 29, 1.5);
			x = to_px_x(coord(replay_get(branch(s, 0), "points"), 0, 0));
			y = to_px_y(coord(replay_get(branch(s, 0), "points"), 0, 1));
			CHECK_NEAR(x, 640, 1);
			CHECK_NEAR(y, 736, 1);
			/* the branch: 7 px radius at its root, on the trunk */
			CHECK_INT(json_object_get_int(replay_get(branch(s, 1), "parent")), 0);
			r = px_of_m(radius(s, 1, 0));
			CHECK_NEAR(r, 7, 1);
			CHECK_INT(json_object_get_int(replay_get(branch(s, 2), "parent")), 0);
			check_invariants(app, what);
			json_object_put(s);
			buf_finish(&p.text);
			app_destroy(app);
		}
	}
}

static uint32_t below(struct rng *r, uint32_t n)
{
	return (uint32_t)(rng_next(r) % n);
}

/* A random point of a random branch, in screen pixels. */
static bool random_wood(const struct app *app, struct rng *r, double *x, double *y)
{
	const struct branch *b;
	size_t k;

	if (app->tree.nbranches == 0)
		return false;
	b = &app->tree.branches[below(r, (uint32_t)app->tree.nbranches)];
	k = below(r, (uint32_t)b->npoints);
	*x = to_px_x(b->points[k].x);
	*y = to_px_y(b->points[k].y);
	return true;
}

static double clampd(double v, double lo, double hi)
{
	return v < lo ? lo : v > hi ? hi : v;
}

/* A random sketch being drawn: its trace, and the app it has been fed to so far. */
struct sketch {
	struct pen_trace p;
	struct app *app;
	size_t fed;
	int cuts; /* strokes that turned out to be gestures, and were undone */
};

/* Whether branches [0, keep) are as they were (n points, tip): no cut or erase. */
static bool untouched(const struct app *app, const size_t *npoints, const struct vec3 *tips, size_t keep)
{
	if (app->tree.nbranches < keep)
		return false;
	for (size_t i = 0; i < keep; i++) {
		const struct branch *b = &app->tree.branches[i];

		if (b->npoints != npoints[i] || memcmp(&b->points[b->npoints - 1], &tips[i], sizeof(tips[i])) != 0)
			return false;
	}
	return true;
}

/*
 * One stroke of a random sketch, fed at once. A stroke that begins off the wood and
 * crosses it is a cut or an erase (docs/sketching.md): those shorten branches whatever
 * their radius, so they are not what this test is about; it is undone at once (which
 * tests undo as well).
 */
static void sketch_line(struct sketch *k, double x0, double y0, double x1, double y1, double wobble,
			double pause_s)
{
	size_t nb = k->app->tree.nbranches, *npoints = calloc(nb + 1, sizeof(*npoints));
	struct vec3 *tips = calloc(nb + 1, sizeof(*tips));

	CHECK(npoints && tips);
	for (size_t i = 0; i < nb; i++) {
		npoints[i] = k->app->tree.branches[i].npoints;
		tips[i] = k->app->tree.branches[i].points[npoints[i] - 1];
	}
	trace_line(&k->p, x0, y0, x1, y1, wobble, pause_s);
	trace_feed(&k->p, "property", k->app, &k->fed);
	/* an outline pair replaces the last branch */
	if (!untouched(k->app, npoints, tips, nb ? nb - 1 : 0)) {
		trace_press(&k->p, BUTTON_UNDO, 0.2);
		trace_feed(&k->p, "property", k->app, &k->fed);
		CHECK(untouched(k->app, npoints, tips, nb));
		k->cuts++;
	}
	free(npoints);
	free(tips);
}

/*
 * Seeded random sketches: strokes from the wood, fans, outline pairs (some as a child
 * would draw them, some too wide, opening or closing in), undo and redo; the invariants
 * hold after every action, and the whole trace replayed at once gives the same tree.
 */
static void test_property(void)
{
	enum { SKETCHES = 300, ACTIONS = 14 };
	struct layout_button bar[LAYOUT_NBUTTONS];
	struct screen v;
	double right;
	int merged = 0, cuts = 0, actions = 0, sketches = test_cases(SKETCHES);

	screen_init(&v, W, H);
	layout_buttons(&v, bar, LAYOUT_NBUTTONS);
	right = bar[0].x - 30; /* strokes stay clear of the button bar */
	for (uint64_t seed = 1; seed <= (uint64_t)sketches; seed++) {
		struct sketch k = { .app = app_create(W, H, 1) };
		struct rng r;
		struct app *again;
		char what[64];

		CHECK(k.app);
		rng_seed(&r, seed);
		trace_begin(&k.p, seed);
		sketch_line(&k, rng_range(&r, 500, 700), 736, rng_range(&r, 500, 700), rng_range(&r, 250, 450), 0.5,
			    rng_range(&r, 0.1, 2));
		for (int a = 0; a < ACTIONS; a++) {
			double x, y, dir = rng_range(&r, -VEC_PI, VEC_PI), len = rng_range(&r, 20, 260);
			double pause = rng_range(&r, 0.1, 2.0);
			uint32_t kind = below(&r, 10);
			size_t nb = k.app->tree.nbranches;

			if (!random_wood(k.app, &r, &x, &y)) {
				x = 600;
				y = 736;
			}
			if (kind < 4) { /* a stroke */
				sketch_line(&k, x, y, clampd(x + len * cos(dir), 5, right), clampd(y + len * sin(dir), 5, H - 5),
					    rng_range(&r, 0, 1.5), pause);
			} else if (kind < 6) { /* a fan from one point */
				int n = 2 + (int)below(&r, 4);
				double spread = rng_range(&r, 5, 50) * VEC_PI / 180.0;

				for (int f = 0; f < n; f++) {
					double d = dir + (f - (n - 1) / 2.0) * spread;

					sketch_line(&k, x, y, clampd(x + len * cos(d), 5, right), clampd(y + len * sin(d), 5, H - 5),
						    rng_range(&r, 0, 1.5), rng_range(&r, 0.1, 1.5));
				}
			} else if (kind < 9) { /* an outline pair: its gaps at the root and tip */
				double g0 = rng_range(&r, 0, 80), g1 = g0 * rng_range(&r, 0, 2.0);
				double nx = -sin(dir), ny = cos(dir);
				double x1 = clampd(x + len * cos(dir), 45, right - 45), y1 = clampd(y + len * sin(dir), 45, H - 45);

				sketch_line(&k, x - nx * g0 / 2, y - ny * g0 / 2, x1 - nx * g1 / 2, y1 - ny * g1 / 2,
					    rng_range(&r, 0, 1.5), rng_range(&r, 0.1, 1.0));
				nb = k.app->tree.nbranches;
				if (below(&r, 2))
					sketch_line(&k, x1 + nx * g1 / 2, y1 + ny * g1 / 2, x + nx * g0 / 2, y + ny * g0 / 2,
						    rng_range(&r, 0, 1.5), pause);
				else
					sketch_line(&k, x + nx * g0 / 2, y + ny * g0 / 2, x1 + nx * g1 / 2, y1 + ny * g1 / 2,
						    rng_range(&r, 0, 1.5), pause);
				merged += k.app->tree.nbranches == nb && k.app->tree.has_profile;
			} else { /* undo, and sometimes redo */
				trace_press(&k.p, BUTTON_UNDO, 0.3);
				if (below(&r, 3) == 0)
					trace_press(&k.p, BUTTON_REDO, 0.3);
				trace_feed(&k.p, "property", k.app, &k.fed);
			}
			snprintf(what, sizeof(what), "random sketch %llu, action %d", (unsigned long long)seed, a);
			check_invariants(k.app, what);
			actions++;
		}
		/* the whole trace replayed at once gives the same drawing */
		again = trace_replay(&k.p, "property");
		CHECK_INT(again->tree.nbranches, k.app->tree.nbranches);
		snprintf(what, sizeof(what), "random sketch %llu replayed", (unsigned long long)seed);
		check_invariants(again, what);
		cuts += k.cuts;
		app_destroy(again);
		app_destroy(k.app);
		buf_finish(&k.p.text);
	}
	printf("%d random sketches, %d actions: %d outline pairs became one branch, %d strokes were gestures (undone)\n",
	       sketches, actions, merged, cuts);
	/* the generator makes real outline pairs too, and not only them */
	CHECK(merged > sketches / 10);
}

/* With an argument, only that test: outlines, fans or property. */
int main(int argc, char **argv)
{
	const char *only = argc > 1 ? argv[1] : NULL;

	if (!only || strcmp(only, "outlines") == 0)
		test_real_outlines();
	if (!only || strcmp(only, "fans") == 0)
		test_fans();
	if (!only || strcmp(only, "property") == 0)
		test_property();
	return 0;
}
