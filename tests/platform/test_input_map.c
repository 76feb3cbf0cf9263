/* SPDX-License-Identifier: MIT */
/* input_map: rotations, the aspect-keeping area, explicit areas, clamping, tilt. */
#include "input_map.h"
#include "test.h"

#define EPS 1e-9

static void test_rotate(void)
{
	/* the tablet's top-left corner and a point right of it, turned clockwise */
	static const struct {
		int rot;
		double u, v, ru, rv;
	} cases[] = {
		{ 0, 0.0, 0.0, 0.0, 0.0 },   { 0, 0.25, 0.1, 0.25, 0.1 },
		{ 90, 0.0, 0.0, 1.0, 0.0 },  { 90, 0.25, 0.1, 0.9, 0.25 },
		{ 180, 0.0, 0.0, 1.0, 1.0 }, { 180, 0.25, 0.1, 0.75, 0.9 },
		{ 270, 0.0, 0.0, 0.0, 1.0 }, { 270, 0.25, 0.1, 0.1, 0.75 },
	};

	for (size_t i = 0; i < sizeof(cases) / sizeof(cases[0]); i++) {
		double ru, rv;

		input_map_rotate(cases[i].rot, cases[i].u, cases[i].v, &ru, &rv);
		CHECK_NEAR(ru, cases[i].ru, EPS);
		CHECK_NEAR(rv, cases[i].rv, EPS);
	}
	/* four quarter turns are no turn; 90 then 270 neither */
	for (double u = 0.0; u <= 1.0; u += 0.125) {
		for (double v = 0.0; v <= 1.0; v += 0.25) {
			double a = u, b = v, c, d;

			for (int k = 0; k < 4; k++) {
				input_map_rotate(90, a, b, &c, &d);
				a = c;
				b = d;
			}
			CHECK_NEAR(a, u, EPS);
			CHECK_NEAR(b, v, EPS);
			input_map_rotate(90, u, v, &a, &b);
			input_map_rotate(270, a, b, &c, &d);
			CHECK_NEAR(c, u, EPS);
			CHECK_NEAR(d, v, EPS);
			input_map_rotate(180, u, v, &a, &b);
			input_map_rotate(90, u, v, &c, &d);
			input_map_rotate(90, c, d, &c, &d);
			CHECK_NEAR(a, c, EPS);
			CHECK_NEAR(b, d, EPS);
		}
	}
}

static void test_stretch(void)
{
	struct input_map m;
	double x, y;

	input_map_init(&m, 0, CONFIG_AREA_STRETCH, NULL, 216, 135, 1280, 800);
	input_map_point(&m, 0.5, 0.5, &x, &y);
	CHECK_NEAR(x, 640, EPS);
	CHECK_NEAR(y, 400, EPS);
	input_map_point(&m, 1.0, 1.0, &x, &y);
	CHECK_NEAR(x, 1280, EPS);
	CHECK_NEAR(y, 800, EPS);
	/* outside the tablet: clamped */
	input_map_point(&m, -0.5, 1.5, &x, &y);
	CHECK_NEAR(x, 0, EPS);
	CHECK_NEAR(y, 800, EPS);
	/* fit with an unknown size is stretch */
	input_map_init(&m, 0, CONFIG_AREA_FIT, NULL, 0, 0, 1280, 800);
	input_map_point(&m, 0.25, 0.75, &x, &y);
	CHECK_NEAR(x, 320, EPS);
	CHECK_NEAR(y, 600, EPS);
}

/* Equal distances on the tablet are equal distances on the screen: circles stay round. */
static void check_aspect(const struct input_map *m, double tw, double th)
{
	double x0, y0, x1, y1, x2, y2;
	double du = 0.1, dv = 0.1 * tw / th; /* the same millimetres across and down */

	input_map_point(m, 0.5, 0.5, &x0, &y0);
	input_map_point(m, 0.5 + du, 0.5, &x1, &y1);
	input_map_point(m, 0.5, 0.5 + dv, &x2, &y2);
	CHECK_NEAR(hypot(x1 - x0, y1 - y0), hypot(x2 - x0, y2 - y0), 1e-6);
	/* the centre stays the centre */
	CHECK_NEAR(x0, m->screen_w / 2, 1e-9);
	CHECK_NEAR(y0, m->screen_h / 2, 1e-9);
}

static void test_fit(void)
{
	struct input_map m;
	double x, y;

	/* a 16:9 tablet (Intuos M: 216 x 135 mm is 16:10; this one 160 x 90) on 4:3 */
	input_map_init(&m, 0, CONFIG_AREA_FIT, NULL, 160, 90, 1024, 768);
	CHECK_NEAR(m.area[1], 0.0, EPS);
	CHECK_NEAR(m.area[3], 1.0, EPS);
	CHECK_NEAR(m.area[2] - m.area[0], (4.0 / 3.0) / (16.0 / 9.0), EPS);
	check_aspect(&m, 160, 90);
	/* the tablet's left strip is unused: its points sit on the screen's left edge */
	input_map_point(&m, 0.05, 0.5, &x, &y);
	CHECK_NEAR(x, 0, EPS);
	input_map_point(&m, m.area[0], 0.0, &x, &y);
	CHECK_NEAR(x, 0, EPS);
	CHECK_NEAR(y, 0, EPS);
	input_map_point(&m, m.area[2], 1.0, &x, &y);
	CHECK_NEAR(x, 1024, 1e-9);
	CHECK_NEAR(y, 768, 1e-9);

	/* a 4:3 tablet on 16:9: all its width, the middle of its height */
	input_map_init(&m, 0, CONFIG_AREA_FIT, NULL, 120, 90, 1920, 1080);
	CHECK_NEAR(m.area[0], 0.0, EPS);
	CHECK_NEAR(m.area[2], 1.0, EPS);
	CHECK_NEAR(m.area[3] - m.area[1], (4.0 / 3.0) / (16.0 / 9.0), EPS);
	check_aspect(&m, 120, 90);

	/* same aspect: the whole tablet */
	input_map_init(&m, 0, CONFIG_AREA_FIT, NULL, 216, 135, 1280, 800);
	CHECK_NEAR(m.area[0], 0.0, EPS);
	CHECK_NEAR(m.area[1], 0.0, EPS);
	CHECK_NEAR(m.area[2], 1.0, EPS);
	CHECK_NEAR(m.area[3], 1.0, EPS);

	/* turned a quarter: a 16:10 tablet stands 10:16, on a 16:10 screen: all its width,
	 * a band across its middle */
	for (int rot = 90; rot <= 270; rot += 180) {
		input_map_init(&m, rot, CONFIG_AREA_FIT, NULL, 216, 135, 1280, 800);
		CHECK_NEAR(m.area[0], 0.0, EPS);
		CHECK_NEAR(m.area[2], 1.0, EPS);
		CHECK_NEAR(m.area[3] - m.area[1], (135.0 / 216.0) * (135.0 / 216.0), EPS);
		/* equal millimetres along the tablet's x and y stay equal on screen */
		double x0, y0, x1, y1, x2, y2;

		input_map_point(&m, 0.5, 0.5, &x0, &y0);
		input_map_point(&m, 0.6, 0.5, &x1, &y1);
		input_map_point(&m, 0.5, 0.5 + 0.1 * 216.0 / 135.0, &x2, &y2);
		CHECK_NEAR(hypot(x1 - x0, y1 - y0), hypot(x2 - x0, y2 - y0), 1e-6);
		CHECK_NEAR(x0, 640, 1e-9);
		CHECK_NEAR(y0, 400, 1e-9);
		/* the tablet's x runs down the screen at 90, up at 270 */
		CHECK(rot == 90 ? y1 > y0 : y1 < y0);
		CHECK_NEAR(x1, x0, 1e-9);
	}
	/* 180: the corners swap */
	input_map_init(&m, 180, CONFIG_AREA_FIT, NULL, 216, 135, 1280, 800);
	input_map_point(&m, 0.0, 0.0, &x, &y);
	CHECK_NEAR(x, 1280, EPS);
	CHECK_NEAR(y, 800, EPS);
}

static void test_rect(void)
{
	static const double rect[4] = { 0.25, 0.5, 0.75, 1.0 };
	struct input_map m;
	double x, y;

	input_map_init(&m, 0, CONFIG_AREA_RECT, rect, 216, 135, 1000, 500);
	input_map_point(&m, 0.25, 0.5, &x, &y);
	CHECK_NEAR(x, 0, EPS);
	CHECK_NEAR(y, 0, EPS);
	input_map_point(&m, 0.5, 0.75, &x, &y);
	CHECK_NEAR(x, 500, EPS);
	CHECK_NEAR(y, 250, EPS);
	input_map_point(&m, 0.1, 0.1, &x, &y);
	CHECK_NEAR(x, 0, EPS);
	CHECK_NEAR(y, 0, EPS);
	/* the rectangle is in the turned tablet's terms */
	input_map_init(&m, 90, CONFIG_AREA_RECT, rect, 216, 135, 1000, 500);
	input_map_point(&m, 0.75, 0.25, &x, &y); /* turned: (0.75, 0.75) */
	CHECK_NEAR(x, 1000, EPS);
	CHECK_NEAR(y, 250, EPS);
}

static void test_tilt(void)
{
	struct input_map m;
	double x, y;

	input_map_init(&m, 0, CONFIG_AREA_STRETCH, NULL, 0, 0, 100, 100);
	input_map_tilt(&m, 10, -20, &x, &y);
	CHECK_NEAR(x, 10, EPS);
	CHECK_NEAR(y, -20, EPS);
	/* tilt turns like a direction: the tablet's +x is the screen's +y at 90 */
	input_map_init(&m, 90, CONFIG_AREA_STRETCH, NULL, 0, 0, 100, 100);
	input_map_tilt(&m, 10, 0, &x, &y);
	CHECK_NEAR(x, 0, EPS);
	CHECK_NEAR(y, 10, EPS);
	input_map_init(&m, 180, CONFIG_AREA_STRETCH, NULL, 0, 0, 100, 100);
	input_map_tilt(&m, 10, 20, &x, &y);
	CHECK_NEAR(x, -10, EPS);
	CHECK_NEAR(y, -20, EPS);
	input_map_init(&m, 270, CONFIG_AREA_STRETCH, NULL, 0, 0, 100, 100);
	input_map_tilt(&m, 10, 0, &x, &y);
	CHECK_NEAR(x, 0, EPS);
	CHECK_NEAR(y, -10, EPS);
	/* and matches how positions turn */
	for (int rot = 0; rot < 360; rot += 90) {
		double x0, y0, x1, y1, tx, ty;

		input_map_init(&m, rot, CONFIG_AREA_STRETCH, NULL, 0, 0, 100, 100);
		input_map_point(&m, 0.5, 0.5, &x0, &y0);
		input_map_point(&m, 0.6, 0.55, &x1, &y1);
		input_map_tilt(&m, 0.1, 0.05, &tx, &ty);
		CHECK_NEAR((x1 - x0) / 100, tx, 1e-9);
		CHECK_NEAR((y1 - y0) / 100, ty, 1e-9);
	}
}

int main(void)
{
	test_rotate();
	test_stretch();
	test_fit();
	test_rect();
	test_tilt();
	return 0;
}
