/* SPDX-License-Identifier: MIT */
/* Fig. 4: a branch drawn as its two outlines gets their radius profile, and later single
 * strokes taper the same way; what is not a pair of outlines stays two branches. */
#include <math.h>
#include <stdio.h>

#include "app.h"
#include "pen.h"
#include "test.h"

/* 40 motion events a line */
static struct pen pen = { .now_us = 1000, .steps = 40 };

static double px(const struct app *app, double m)
{
	return m / app->screen.m_per_px;
}

static void test_two_outlines(void)
{
	struct app *app = app_create(1280, 800, 1);
	const struct branch *b;
	double r0;

	/* the trunk's two outlines: 80 px apart at the ground, 20 px at the top; the second
	 * drawn the other way round */
	pen_line(&pen, app, 600, 736, 630, 300);
	pen_line(&pen, app, 650, 300, 680, 736);
	CHECK_INT(app->tree.nbranches, 1);
	CHECK(app->tree.has_profile);
	b = &app->tree.branches[0];
	CHECK_NEAR(px(app, b->radii[0]), 40, 1);
	CHECK_NEAR(px(app, b->radii[b->npoints - 1]), 10, 1);
	/* the axis runs between the outlines */
	CHECK_NEAR(px(app, b->points[0].x) + 640, 640, 1);

	/* a single stroke now tapers like the outlines did: 1 -> 0.25, 0.625 half way */
	pen_line(&pen, app, 640, 500, 900, 400);
	CHECK_INT(app->tree.nbranches, 2);
	b = &app->tree.branches[1];
	r0 = b->radii[0];
	CHECK_NEAR(b->radii[b->npoints - 1] / r0, 0.25, 0.02);
	CHECK_NEAR(b->radii[b->npoints / 2] / r0, 0.625, 0.03);

	/* undoing the second outline gives the first back as an ordinary trunk */
	{
		struct event u = { .type = EVENT_BUTTON, .time_us = pen.now_us, .button = BUTTON_UNDO, .pressed = true };

		app_handle_event(app, &u);
		app_handle_event(app, &u);
	}
	CHECK_INT(app->tree.nbranches, 1);
	CHECK(!app->tree.has_profile);
	app_destroy(app);
}

static void test_not_outlines(void)
{
	struct app *app = app_create(1280, 800, 1);

	pen_line(&pen, app, 640, 736, 640, 300);
	/* two twigs side by side but drawn 4 s apart */
	pen_line(&pen, app, 640, 500, 900, 420);
	pen.now_us += 4000000;
	pen_line(&pen, app, 640, 520, 900, 440);
	CHECK_INT(app->tree.nbranches, 3);
	/* two quick strokes from the same point in different directions */
	pen_line(&pen, app, 640, 400, 850, 300);
	pen_line(&pen, app, 640, 400, 430, 300);
	CHECK_INT(app->tree.nbranches, 5);
	/* a quick stroke much longer than the one before */
	pen_line(&pen, app, 640, 600, 700, 560);
	pen_line(&pen, app, 640, 620, 1000, 560);
	CHECK_INT(app->tree.nbranches, 7);
	CHECK(!app->tree.has_profile);
	app_destroy(app);
}

/* Radius never grows from root to tip, and the root is at most a quarter of the length. */
static void check_taper(const struct app *app)
{
	for (size_t i = 0; i < app->tree.nbranches; i++) {
		const struct branch *b = &app->tree.branches[i];

		for (size_t k = 1; k < b->npoints; k++)
			CHECK(b->radii[k] <= b->radii[k - 1] * (1 + 1e-9));
		CHECK(b->radii[0] <= 0.25 * vec3_polyline_length(b->points, b->npoints) * (1 + 1e-9));
	}
}

static void test_outlines_meeting_at_the_tip(void)
{
	struct app *app = app_create(1280, 800, 1);

	/* a second stroke that starts where the first ended: a V of two branches
	 * (docs/sketching.md: outlines do not close in to a point) */
	pen_line(&pen, app, 600, 736, 640, 300);
	pen_line(&pen, app, 640, 300, 680, 736);
	CHECK_INT(app->tree.nbranches, 2);
	CHECK(!app->tree.has_profile);
	/* later branches still taper the default way, to a twig */
	pen_line(&pen, app, 640, 500, 900, 400);
	CHECK(app->tree.branches[2].radii[app->tree.branches[2].npoints - 1] > 0);
	check_taper(app);
	app_destroy(app);
}

/* Two strokes from one point that open up are two branches, at any angle of a fan. */
static void test_fan_is_two_branches(void)
{
	for (int deg = 5; deg <= 45; deg += 5) {
		struct app *app = app_create(1280, 800, 1);
		double a = deg * VEC_PI / 180.0;

		pen_line(&pen, app, 640, 736, 640, 436);
		pen_line(&pen, app, 640, 436, 640 + 200 * sin(a / 2), 436 - 200 * cos(a / 2));
		pen_line(&pen, app, 640, 436, 640 - 200 * sin(a / 2), 436 - 200 * cos(a / 2));
		CHECK_INT(app->tree.nbranches, 3);
		CHECK(!app->tree.has_profile);
		/* and beside each other but 6 px apart at the root and opening up */
		pen_line(&pen, app, 640, 600, 640 + 200 * cos(a), 600 - 200 * sin(a));
		pen_line(&pen, app, 640, 594, 640 + 200 * cos(2 * a), 594 - 200 * sin(2 * a));
		CHECK_INT(app->tree.nbranches, 5);
		check_taper(app);
		app_destroy(app);
	}
}

/* Where each threshold of docs/sketching.md lies, both sides. */
static void test_outline_thresholds(void)
{
	struct {
		double gap_root, gap_tip; /* px, a vertical trunk 400 px long */
		int branches;
	} cases[] = {
		{ 40, 40, 1 },   /* parallel */
		{ 40, 9, 1 },    /* closes in 4.4x */
		{ 40, 7, 2 },    /* 5.7x: two branches */
		{ 40, 44, 1 },   /* widens within the wobble */
		{ 40, 60, 2 },   /* widens 1.5x */
		{ 1.6, 1.6, 2 }, /* on top of each other: no thickness at the root */
		{ 3, 3, 1 },     /* a thin branch's thickness apart */
		{ 190, 150, 1 }, /* root radius 95 px < 400 / 4 */
		{ 220, 190, 2 }, /* 110 px > 400 / 4 */
	};

	for (size_t c = 0; c < sizeof(cases) / sizeof(cases[0]); c++) {
		struct app *app = app_create(1280, 800, 1);

		pen_line(&pen, app, 640 - cases[c].gap_root / 2, 736, 640 - cases[c].gap_tip / 2, 336);
		pen_line(&pen, app, 640 + cases[c].gap_tip / 2, 336, 640 + cases[c].gap_root / 2, 736);
		if (app->tree.nbranches != (size_t)cases[c].branches)
			fprintf(stderr, "case %zu: %g -> %g px\n", c, cases[c].gap_root, cases[c].gap_tip);
		CHECK_INT(app->tree.nbranches, cases[c].branches);
		CHECK(app->tree.has_profile == (cases[c].branches == 1));
		check_taper(app);
		app_destroy(app);
	}
}

int main(void)
{
	test_outlines_meeting_at_the_tip();
	test_fan_is_two_branches();
	test_outline_thresholds();
	test_two_outlines();
	test_not_outlines();
	return 0;
}
