/* SPDX-License-Identifier: MIT */
/* Fig. 4: a branch drawn as its two outlines gets their radius profile, and later single
 * strokes taper the same way; what is not a pair of outlines stays two branches. */
#include "app.h"
#include "pen.h"
#include "test.h"

/* 40 motion events a line */
static struct pen pen = { .now_us = 1000, .steps = 40 };

static double px(const struct app *app, double m)
{
	return m / app->view.m_per_px;
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

static void test_outlines_meeting_at_the_tip(void)
{
	struct app *app = app_create(1280, 800, 1);

	/* the second outline starts where the first ended: radius 0 at the tip */
	pen_line(&pen, app, 600, 736, 640, 300);
	pen_line(&pen, app, 640, 300, 680, 736);
	CHECK_INT(app->tree.nbranches, 1);
	CHECK(app->tree.has_profile);
	/* later branches still end in a twig, not a needle of radius 0 */
	pen_line(&pen, app, 640, 500, 900, 400);
	CHECK(app->tree.branches[1].radii[app->tree.branches[1].npoints - 1] > 0);
	app_destroy(app);
}

int main(void)
{
	test_outlines_meeting_at_the_tip();
	test_two_outlines();
	test_not_outlines();
	return 0;
}
