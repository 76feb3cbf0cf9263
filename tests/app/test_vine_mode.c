/* SPDX-License-Identifier: MIT */
/*
 * The vine mode (issue 16): the vine button and a tap at the foot of a drawn 3D tree plant
 * a vine scaled to it, which finds the trunk and winds up it; a tap out of reach plants at
 * the nearest point within reach, one far away says where to tap. The vine is an undoable
 * op of the drawing, saved and loaded bit for bit; on screen it grows by the events' time,
 * to the model's vine whatever the frame rate.
 */
#include <math.h>
#include <string.h>

#include "app.h"
#include "buf.h"
#include "doc.h"
#include "pen.h"
#include "test.h"
#include "vine.h"
#include "vine_presets.h"

static struct pen pen = { .now_us = 1000, .steps = 10, .pause_us = PEN_PAUSE_US };

/* A trunk and four limbs, made 3D. */
static struct app *drawn_tree(void)
{
	struct app *app = app_create(1280, 800, 7);

	CHECK(app);
	pen_line(&pen, app, 640, 736, 640, 236);
	pen_line(&pen, app, 640, 536, 880, 400);
	pen_line(&pen, app, 640, 480, 410, 350);
	pen_line(&pen, app, 640, 400, 780, 250);
	pen_line(&pen, app, 640, 360, 500, 220);
	pen_button(&pen, app, BUTTON_3D);
	CHECK(app->tree.lifted);
	return app;
}

static void tap(struct app *app, double x, double y)
{
	pen_line(&pen, app, x, y, x, y);
}

static size_t contacts(const struct vine *v)
{
	size_t n = 0;

	for (size_t s = 0; s < v->nshoots; s++)
		for (size_t i = 0; i < v->shoots[s].n; i++)
			n += v->shoots[s].contact[i] != 0;
	return n;
}

static bool same_vine(const struct vine *a, const struct vine *b)
{
	if (memcmp(&a->p, &b->p, sizeof(a->p)) || memcmp(&a->plant, &b->plant, sizeof(a->plant)) ||
	    a->nshoots != b->nshoots || a->points != b->points)
		return false;
	for (size_t s = 0; s < a->nshoots; s++) {
		const struct vine_shoot *x = &a->shoots[s], *y = &b->shoots[s];

		if (x->n != y->n || x->parent != y->parent || x->node != y->node ||
		    x->stopped != y->stopped || memcmp(x->axis, y->axis, x->n * sizeof(*x->axis)) ||
		    memcmp(x->contact, y->contact, x->n))
			return false;
	}
	return true;
}

static const struct doc_op *last_op(const struct app *app)
{
	return app->doc.cursor ? &app->doc.ops[app->doc.cursor - 1] : NULL;
}

/* A tap just beside the trunk's foot plants a vine that finds the trunk and climbs. */
static void test_plant(void)
{
	struct app *app = drawn_tree();
	const struct branch *trunk = &app->tree.branches[0];
	const struct vine *v;
	double top = 0.0, base = trunk->points[0].y;
	struct vine_params preset;
	struct error err = { { 0 } };
	double k;

	pen_button(&pen, app, BUTTON_VINE);
	CHECK_INT(app->mode, APP_MODE_VINE);
	CHECK_INT(app->status, APP_STATUS_VINE_TAP);
	tap(app, 680, 730);
	CHECK_INT(app->tree.nvines, 1);
	CHECK_INT(last_op(app)->kind, DOC_OP_VINE);
	CHECK_INT(app->mode, APP_MODE_VINE); /* more taps plant more */
	v = &app->tree.vines[0];
	CHECK(contacts(v) > 20);
	CHECK_NEAR(v->plant.y, base, 1e-12);
	for (size_t s = 0; s < v->nshoots; s++)
		for (size_t i = 0; i < v->shoots[s].n; i++)
			top = fmax(top, v->shoots[s].axis[i].y);
	/* it wound up the trunk, well above the foot */
	CHECK(top - base > 0.5 * (trunk->points[trunk->npoints - 1].y - base));
	/* one factor on every length of the preset, the stem a tenth of the trunk */
	CHECK_INT(vine_preset(APP_VINE_PRESET, &preset, &err), 0);
	k = v->p.internode / preset.internode;
	CHECK(k >= 6.0 - 1e-9 && k <= 16.0 + 1e-9);
	CHECK_NEAR(v->p.radius / preset.radius, k, 1e-9);
	CHECK_NEAR(v->p.radius, fmax(6.0 * preset.radius, fmin(0.1 * trunk->radii[0],
								   16.0 * preset.radius)), 1e-12);
	CHECK_INT(vine_params_check(&v->p, NULL, &err), 0);
	app_destroy(app);
}

/* A tap beyond the rod's reach plants at the nearest point that reaches; one far from the
 * tree plants nothing and says where to tap. */
static void test_reach(void)
{
	struct app *app = drawn_tree();
	double foot_x;

	pen_button(&pen, app, BUTTON_VINE);
	foot_x = app->tree.branches[0].points[0].x;
	/* 1.9 m right of the trunk (0.0125 m a pixel): under the crown, out of reach */
	tap(app, 640 + 152, 730);
	CHECK_INT(app->tree.nvines, 1);
	CHECK(app->tree.vines[0].plant.x - foot_x < 1.5);
	CHECK(app->tree.vines[0].plant.x - foot_x > app->tree.branches[0].radii[0]);
	CHECK(contacts(&app->tree.vines[0]) > 0);
	/* 6 m to the left, beyond the crown */
	tap(app, 640 - 480, 730);
	CHECK_INT(app->tree.nvines, 1);
	CHECK_INT(app->status, APP_STATUS_VINE_WHERE);
	CHECK_INT(last_op(app)->kind, DOC_OP_VINE);
	app_destroy(app);
}

/* Undo takes it away, redo gives the same vine; the drawing saved and loaded has it. */
static void test_undo_and_file(void)
{
	struct app *app = drawn_tree(), *back = app_create(1280, 800, 1);
	struct buf b;
	struct doc d;
	struct error err = { { 0 } };
	struct vine copy;

	CHECK(back);
	pen_button(&pen, app, BUTTON_VINE);
	tap(app, 680, 730);
	CHECK_INT(app->tree.nvines, 1);
	CHECK_INT(vine_copy(&copy, &app->tree.vines[0]), 0);
	CHECK(app->vines_mesh.bark.nvertices > 0 || app->growth.on);
	pen_button(&pen, app, BUTTON_UNDO);
	CHECK_INT(app->tree.nvines, 0);
	CHECK(!app->growth.on);
	(void)app_vines_advance(app, UINT64_MAX);
	CHECK_INT(app->vines_mesh.bark.nvertices, 0);
	pen_button(&pen, app, BUTTON_REDO);
	CHECK_INT(app->tree.nvines, 1);
	CHECK(same_vine(&app->tree.vines[0], &copy));
	(void)app_vines_advance(app, UINT64_MAX);
	CHECK(app->vines_mesh.bark.nvertices > 0);

	buf_init(&b);
	CHECK_INT(doc_serialize(&app->doc, &app->tree, &b), 0);
	CHECK(strstr((const char *)b.data, "\nvine "));
	CHECK_INT(doc_parse((const char *)b.data, b.len, "vine.edaha", &d, &err), 0);
	CHECK_INT(app_load_doc(back, &d), 0);
	CHECK_INT(back->tree.nvines, 1);
	CHECK(same_vine(&back->tree.vines[0], &copy));
	CHECK(!back->growth.on); /* a loaded vine is grown */
	CHECK_INT(back->vines_mesh.bark.nvertices, app->vines_mesh.bark.nvertices);
	CHECK(!memcmp(back->vines_mesh.bark.positions, app->vines_mesh.bark.positions,
		      3 * sizeof(float) * app->vines_mesh.bark.nvertices));
	buf_finish(&b);
	vine_finish(&copy);
	doc_finish(&d);
	app_destroy(back);
	app_destroy(app);
}

/* On screen the vine grows by the events' time, 48 points a second; watched at 30 or 60
 * frames a second it ends as the model's vine, and then shows with the others. */
static void test_growth(void)
{
	static const double fps[] = { 30.0, 60.0 };

	for (size_t f = 0; f < 2; f++) {
		struct app *app = drawn_tree();
		uint64_t t0;
		size_t frames = (size_t)(0.5 * fps[f]); /* from half a second on */
		bool growing = true;

		pen_button(&pen, app, BUTTON_VINE);
		tap(app, 680, 730);
		CHECK(app->growth.on);
		CHECK_INT(app->vines_mesh.bark.nvertices, 0); /* the growing one is left out */
		t0 = last_op(app)->time_us;
		CHECK(app_vines_advance(app, t0 + 500000));
		/* half a second: 24 points, the root's aside */
		CHECK_INT(app->growth.v.points, 24);
		CHECK(app->growth.mesh.bark.nvertices > 0);
		while (growing && frames < 100000) {
			growing = app_vines_advance(app, t0 + (uint64_t)llround(1e6 * (double)frames / fps[f]));
			if (growing) {
				const struct vine *g = &app->growth.v;

				/* what shows is never ahead of the clock */
				CHECK((double)g->points <= 48.0 * (double)frames / fps[f] + 1.0);
			}
			frames++;
		}
		CHECK(!growing);
		CHECK(!app->growth.on);
		CHECK(app->vines_mesh.bark.nvertices > 0);
		/* it took as long as its points at 48 a second */
		CHECK_NEAR((double)frames / fps[f], (double)app->tree.vines[0].points / 48.0,
			   2.0 / fps[f] + 0.05);
		app_destroy(app);
	}
}

/*
 * The frames' vine is the model's: at every frame (60 a second) what shows is the model's
 * vine as far as it has grown, bit for bit, but for the apex's free rod, still circling
 * about its pivot.
 */
static bool prefix_of(const struct vine *g, const struct vine *v)
{
	if (g->nshoots > v->nshoots)
		return false;
	for (size_t s = 0; s < g->nshoots; s++) {
		const struct vine_shoot *x = &g->shoots[s], *y = &v->shoots[s];
		/* the rod turns about its pivot: what is before it stays */
		size_t fixed = x->stopped ? x->n : x->pivot + 1 < x->n ? x->pivot + 1 : x->n;

		if (x->n > y->n || x->parent != y->parent || x->node != y->node ||
		    memcmp(x->axis, y->axis, fixed * sizeof(*x->axis)))
			return false;
	}
	return true;
}

static void test_frames_equal_model(void)
{
	struct app *app = drawn_tree();
	uint64_t t0;
	size_t frames = 0, checked = 0;

	pen_button(&pen, app, BUTTON_VINE);
	tap(app, 700, 730);
	t0 = last_op(app)->time_us;
	for (uint64_t t = t0; app_vines_advance(app, t); t += 16667, frames++) {
		checked += prefix_of(&app->growth.v, &app->tree.vines[0]);
		CHECK(prefix_of(&app->growth.v, &app->tree.vines[0]));
	}
	CHECK(frames > 60);
	CHECK_INT(checked, frames);
	app_destroy(app);
}

/* A tree takes TREE_MAX_VINES; the next tap says it is full. The mode's button again goes
 * back to drawing; on a sketch it makes the tree 3D first. */
static void test_full_and_toggle(void)
{
	struct app *app = app_create(1280, 800, 3);

	CHECK(app);
	pen_line(&pen, app, 640, 736, 640, 236);
	pen_line(&pen, app, 640, 500, 840, 380);
	pen_button(&pen, app, BUTTON_VINE);
	CHECK(app->tree.lifted);
	CHECK_INT(app->mode, APP_MODE_VINE);
	for (unsigned i = 0; i < TREE_MAX_VINES; i++)
		tap(app, 660 + 4 * i, 730);
	CHECK_INT(app->tree.nvines, TREE_MAX_VINES);
	tap(app, 700, 730);
	CHECK_INT(app->tree.nvines, TREE_MAX_VINES);
	CHECK_INT(app->status, APP_STATUS_VINE_FULL);
	/* each with its own seed: their bends differ */
	CHECK(app->tree.vines[0].p.seed != app->tree.vines[1].p.seed);
	pen_button(&pen, app, BUTTON_VINE);
	CHECK_INT(app->mode, APP_MODE_SKETCH);
	/* a New tree has none */
	pen_button(&pen, app, BUTTON_NEW);
	CHECK_INT(app->tree.nvines, 0);
	pen_button(&pen, app, BUTTON_UNDO);
	CHECK_INT(app->tree.nvines, TREE_MAX_VINES);
	app_destroy(app);
}

int main(void)
{
	test_plant();
	test_reach();
	test_undo_and_file();
	test_growth();
	test_frames_equal_model();
	test_full_and_toggle();
	return 0;
}
