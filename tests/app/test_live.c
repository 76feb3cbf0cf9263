/* SPDX-License-Identifier: MIT */
/*
 * The living tree in the app (issue 26, docs/living-trees.md): a tree that becomes 3D (the
 * 3D press, a template, a loaded drawing) grows in from the trunk's foot by the events'
 * clock. Through the app's own state and functions (app_live_at, app_live_skeleton, the
 * meshes and marks it keeps) on seeded random sketches made 3D and on the presets: no
 * vertex of a branch is drawn before the growth's front has passed the point of its parent
 * where it is attached, no leaf's before the front passed its anchor (both path lengths
 * walked here along the branches, not taken from live/), the front never goes back, and
 * at the growth's end the tree is settled. Any pen tip or button put down finishes it;
 * hovering does not; the press's own release does not. The same events make the same
 * growth, bit for bit; a loaded 3D drawing grows in; grow_in off, none; the wind's
 * strength is taken in 0..1 only and moves a tree, not an empty canvas or the settled
 * view.
 */
#include <errno.h>
#include <math.h>
#include <string.h>

#include "app.h"
#include "app_private.h"
#include "buf.h"
#include "layout.h"
#include "gen.h"
#include "live.h"
#include "pen.h"
#include "rng.h"
#include "test.h"

static struct pen pen = { .now_us = 1000, .steps = 8, .pause_us = 300000, .hold_us = 50000 };

/* The worst margins seen, printed at the end. */
static double worst_branch = INFINITY, worst_leaf = INFINITY;
static size_t vertices_checked, trees_checked;

static double arc_length(const struct branch *b)
{
	double s = 0.0;

	for (size_t i = 1; i < b->npoints; i++)
		s += vec3_len(vec3_sub(b->points[i], b->points[i - 1]));
	return s;
}

/* Each branch's base's path length from the trunk's foot, walked along its parents. */
static double *base_paths(const struct tree *t)
{
	double *d = calloc(t->nbranches + 1, sizeof(*d));

	CHECK(d);
	for (size_t b = 0; b < t->nbranches; b++) {
		int p = t->branches[b].parent;

		d[b] = p >= 0 && (size_t)p < b ? d[p] + t->branches[b].parent_t *
							   arc_length(&t->branches[p])
					       : 0.0;
	}
	return d;
}

/* A visitor's sketch of a trunk and n branches off what is there, seeded. */
static struct app *sketched(uint64_t seed)
{
	struct app *app = app_create(1280, 800, seed);
	struct rng rng;
	double seg[16][4];
	int nseg = 0, n;

	CHECK(app);
	rng_seed(&rng, seed * 7919 + 11);
	seg[nseg][0] = seg[nseg][2] = rng_range(&rng, 500, 700);
	seg[nseg][1] = 740;
	seg[nseg][3] = 740 - rng_range(&rng, 250, 500);
	pen_line(&pen, app, seg[0][0], seg[0][1], seg[0][2], seg[0][3]);
	nseg++;
	n = 2 + (int)(rng_next(&rng) % 7);
	for (int i = 0; i < n && nseg < 16; i++) {
		const double *s = seg[rng_next(&rng) % (uint64_t)nseg];
		double u = rng_range(&rng, 0.3, 0.9);
		double x0 = s[0] + u * (s[2] - s[0]), y0 = s[1] + u * (s[3] - s[1]);
		double a = -VEC_PI * rng_range(&rng, 0.1, 0.9), len = rng_range(&rng, 80, 250);
		double x1 = fmin(fmax(x0 + len * cos(a), 60), 1000), y1 = fmin(fmax(y0 + len * sin(a), 40), 760);

		pen_line(&pen, app, x0, y0, x1, y1);
		seg[nseg][0] = x0;
		seg[nseg][1] = y0;
		seg[nseg][2] = x1;
		seg[nseg][3] = y1;
		nseg++;
	}
	return app;
}

/*
 * The growth's order on the app's tree, growing from start_us: at 60 moments through it,
 * every vertex the front has reached is on a branch whose attachment the front passed, or
 * on a leaf whose anchor it passed; the front never goes back; at the end all is settled.
 */
static void check_order(struct app *app, uint64_t start_us)
{
	const struct live_skeleton *sk = app_live_skeleton(app);
	const struct tree *t = &app->tree;
	const struct tree_mesh_marks *mk = &app->mesh_marks;
	struct live_attrs bark, leaves;
	struct app_live_frame f;
	double *dbase = base_paths(t), last = -1.0;
	uint64_t end = app_live_grow_end(app);

	CHECK(sk);
	CHECK(end > start_us);
	/* the duration follows the tree's size, within 2..6 s */
	CHECK(end - start_us >= 2000000 && end - start_us <= 6000000);
	CHECK(mk->nbark == t->nbranches + 1 && mk->nleaves == t->nleaves + 1);
	live_attrs_init(&bark);
	live_attrs_init(&leaves);
	CHECK(live_attrs_bind_bark(&bark, sk, t, &app->mesh.bark, mk) == 0);
	CHECK(live_attrs_bind_leaves(&leaves, sk, t, &app->mesh.leaves, mk) == 0);
	for (int k = 0; k <= 60; k++) {
		uint64_t now = start_us + (end - start_us) * (uint64_t)k / 60 - (k == 60);

		CHECK(app_live_at(app, now, &f));
		CHECK(f.growing);
		CHECK(f.front >= last);
		last = f.front;
		for (size_t b = 0; b < t->nbranches; b++) {
			for (size_t i = mk->bark[b].nvertices; i < mk->bark[b + 1].nvertices; i++) {
				if (!live_grow_visible(f.front, bark.v[i].d))
					continue;
				vertices_checked++;
				worst_branch = fmin(worst_branch, f.front - dbase[b]);
				CHECK(f.front >= dbase[b] - 1e-5);
			}
		}
		for (size_t l = 0; l < t->nleaves; l++) {
			const struct leaf *lf = &t->leaves[l];
			double anchor = dbase[lf->branch] + lf->branch_t * arc_length(&t->branches[lf->branch]);

			for (size_t i = mk->leaves[l].nvertices; i < mk->leaves[l + 1].nvertices; i++) {
				if (!live_grow_visible(f.front, leaves.v[i].d))
					continue;
				vertices_checked++;
				worst_leaf = fmin(worst_leaf, f.front - anchor);
				CHECK(f.front >= anchor - 1e-5);
			}
		}
	}
	/* at its start only the foot is there; at its end, the settled tree: not moving */
	CHECK(app_live_at(app, start_us, &f) && f.front == 0.0);
	CHECK(!app_live_growing_at(app, end));
	CHECK(!app_live_at(app, end, &f) && !f.moving);
	CHECK(!app_live_at(app, UINT64_MAX, NULL));
	live_attrs_finish(&bark);
	live_attrs_finish(&leaves);
	free(dbase);
	trees_checked++;
}

/* The 3D press on seeded random sketches: the tree grows in from the press. */
static void test_sketches(void)
{
	int n = test_cases(300);

	for (int i = 0; i < n; i++) {
		struct app *app = sketched((uint64_t)i + 1);
		uint64_t press;

		CHECK(app->tree.nbranches >= 1);
		CHECK(!app_live_growing_at(app, pen.now_us));
		press = pen.now_us;
		pen_button(&pen, app, BUTTON_3D);
		CHECK(app->tree.lifted);
		/* the press's own release did not finish it */
		CHECK(app_live_growing_at(app, press + 1));
		check_order(app, press);
		app_destroy(app);
	}
}

/* A template: each preset grows in from the op's time. */
static void test_presets(void)
{
	for (int p = 0; p < GEN_PRESET_COUNT; p++) {
		struct app *app = app_create(1280, 800, 3);
		struct gen_params params;
		struct error err;

		CHECK(app);
		CHECK(gen_preset((enum gen_preset)p, &params, &err) == 0);
		CHECK(app_generate(app, &params, 5000000) == 0);
		CHECK(app->tree.nleaves > 0);
		check_order(app, 5000000);
		app_destroy(app);
	}
}

/* Any pen tip or button put down finishes it at once; hovering does not. */
static void test_input(void)
{
	struct app *app = sketched(77);
	uint64_t press = pen.now_us;

	pen_button(&pen, app, BUTTON_3D);
	CHECK(app_live_growing_at(app, pen.now_us));
	/* the pen hovering over the tablet: still growing */
	pen_event(&pen, app, EVENT_PROXIMITY_IN, EVENT_TOOL_PEN, 300, 300, 0);
	pen_event(&pen, app, EVENT_MOTION, EVENT_TOOL_PEN, 310, 300, 0);
	CHECK(app_live_growing_at(app, pen.now_us));
	pen_event(&pen, app, EVENT_TIP_DOWN, EVENT_TOOL_PEN, 310, 300, 0.5);
	CHECK(!app_live_growing_at(app, pen.now_us));
	CHECK(!app_live_at(app, press + 100000, NULL)); /* finished: settled at any moment */
	pen_event(&pen, app, EVENT_TIP_UP, EVENT_TOOL_PEN, 310, 300, 0);
	app_destroy(app);

	/* a button: the view button, which changes nothing else on a tree seen from the front */
	app = sketched(78);
	pen_button(&pen, app, BUTTON_3D);
	CHECK(app_live_growing_at(app, pen.now_us));
	app_handle_event(app, &(struct event){ .type = EVENT_BUTTON, .button = BUTTON_VIEW,
					       .pressed = false, .time_us = pen.now_us });
	CHECK(app_live_growing_at(app, pen.now_us)); /* a release is no input */
	pen_button(&pen, app, BUTTON_VIEW);
	CHECK(!app_live_growing_at(app, pen.now_us));
	app_destroy(app);

	/* the 3D button tapped on the bar with the pen: its tip going up does not end it */
	app = sketched(79);
	{
		struct layout_button lb[LAYOUT_NBUTTONS];
		size_t n = layout_buttons(&app->screen, lb, LAYOUT_NBUTTONS), k = 0;
		double x, y;

		while (k < n && lb[k].button != BUTTON_3D)
			k++;
		CHECK(k < n);
		x = lb[k].x + lb[k].w / 2;
		y = lb[k].y + lb[k].h / 2;
		pen_event(&pen, app, EVENT_PROXIMITY_IN, EVENT_TOOL_PEN, x, y, 0);
		pen_event(&pen, app, EVENT_TIP_DOWN, EVENT_TOOL_PEN, x, y, 0.5);
		CHECK(app->tree.lifted);
		pen_event(&pen, app, EVENT_TIP_UP, EVENT_TOOL_PEN, x, y, 0);
		pen_event(&pen, app, EVENT_PROXIMITY_OUT, EVENT_TOOL_PEN, x, y, 0);
		CHECK(app_live_growing_at(app, pen.now_us));
	}
	app_destroy(app);
}

/* The same events, the same growth: two apps fed alike agree bit for bit. */
static void test_replay(void)
{
	struct pen a = pen, b = pen;
	struct app *x, *y;
	uint64_t press;

	pen = a;
	x = sketched(91);
	press = pen.now_us;
	pen_button(&pen, x, BUTTON_3D);
	pen = b;
	y = sketched(91);
	pen_button(&pen, y, BUTTON_3D);
	CHECK(app_live_grow_end(x) == app_live_grow_end(y));
	for (uint64_t t = press; t < app_live_grow_end(x); t += 37000) {
		struct app_live_frame fx, fy;

		CHECK(app_live_at(x, t, &fx) && app_live_at(y, t, &fy));
		CHECK(memcmp(&fx.front, &fy.front, sizeof(fx.front)) == 0);
	}
	CHECK(x->live.sk.nbranches == y->live.sk.nbranches);
	for (size_t i = 0; i < x->live.sk.nbranches; i++)
		CHECK(memcmp(&x->live.sk.branches[i], &y->live.sk.branches[i],
			     sizeof(x->live.sk.branches[i])) == 0);
	app_destroy(x);
	app_destroy(y);
}

/* The app's drawing as a file would bring it back. */
static void copy_doc(struct doc *copy, const struct app *app)
{
	struct error err;
	struct buf b;

	buf_init(&b);
	CHECK(doc_serialize(&app->doc, &app->tree, &b) == 0);
	CHECK(doc_parse((const char *)b.data, b.len, "drawing.edaha", copy, &err) == 0);
	buf_finish(&b);
}

/* A loaded 3D drawing grows in from the app's clock then; a 2D one does not; off: none. */
static void test_load(void)
{
	struct app *app = sketched(5), *other;
	struct doc copy;

	pen_button(&pen, app, BUTTON_3D);
	copy_doc(&copy, app);
	other = app_create(1280, 800, 1);
	CHECK(other);
	other->last_time_us = 123456789;
	CHECK(app_load_doc(other, &copy) == 0);
	CHECK(other->tree.lifted);
	CHECK(app_live_growing_at(other, 123456789 + 1));
	check_order(other, 123456789);
	/* no growth with grow_in off */
	app_set_grow_in(other, false);
	CHECK(!app_live_growing_at(other, 123456789 + 1));
	copy_doc(&copy, app);
	CHECK(app_load_doc(other, &copy) == 0);
	CHECK(!app_live_growing_at(other, 123456789 + 1));
	pen_button(&pen, other, BUTTON_UNDO);
	pen_button(&pen, other, BUTTON_3D);
	CHECK(other->tree.lifted && !app_live_growing_at(other, pen.now_us));
	app_destroy(other);
	app_destroy(app);
}

/* The wind: 0..1 only; it moves a tree at a moment, not the settled view nor an empty
 * canvas. */
static void test_wind(void)
{
	struct app *app = app_create(1280, 800, 9);
	struct app_live_frame f;

	CHECK(app);
	CHECK(app_set_wind(app, -0.1) == -EINVAL);
	CHECK(app_set_wind(app, 1.5) == -EINVAL);
	CHECK(app_set_wind(app, NAN) == -EINVAL);
	CHECK(app_set_wind(app, LIVE_WIND_DEFAULT_STRENGTH) == 0);
	CHECK(!app_live_at(app, 1000000, NULL)); /* nothing to sway */
	app_destroy(app);
	app = sketched(12);
	CHECK(app_set_wind(app, LIVE_WIND_DEFAULT_STRENGTH) == 0);
	CHECK(app_live_at(app, pen.now_us, &f) && f.moving && !f.growing);
	CHECK(f.wind.amp0 > 0.0);
	CHECK(!app_live_at(app, UINT64_MAX, NULL));
	CHECK(app_set_wind(app, 0.0) == 0);
	CHECK(!app_live_at(app, pen.now_us, NULL));
	app_destroy(app);
}

int main(void)
{
	test_input();
	test_replay();
	test_load();
	test_wind();
	test_presets();
	test_sketches();
	printf("growth order on %zu trees, %zu drawn vertices: the front past a branch's "
	       "attachment by at least %.3g m, past a leaf's anchor by at least %.3g m\n",
	       trees_checked, vertices_checked, worst_branch, worst_leaf);
	return 0;
}
