/* SPDX-License-Identifier: MIT */
/* offscreen_geometry: where the app's picture lands on a turned or other-sized display. */
#include "input_map.h"
#include "offscreen.h"
#include "test.h"

#define EPS 1e-6

/* Where the picture's texture point (u, v) (v up) lands, in the screen's clip space:
 * the quad is a parallelogram, so (u, v) maps affinely from its corners. */
static void clip_of(const struct offscreen_geometry *g, double u, double v, double *x, double *y)
{
	*x = g->quad[0][0] + u * (g->quad[1][0] - g->quad[0][0]) + v * (g->quad[2][0] - g->quad[0][0]);
	*y = g->quad[0][1] + u * (g->quad[1][1] - g->quad[0][1]) + v * (g->quad[2][1] - g->quad[0][1]);
}

static void check_corner(const struct offscreen_geometry *g, int i, double x, double y)
{
	CHECK_NEAR(g->quad[i][0], x, EPS);
	CHECK_NEAR(g->quad[i][1], y, EPS);
}

static void test_straight(void)
{
	struct offscreen_geometry g;

	offscreen_geometry(0, 1280, 800, 1280, 800, &g);
	check_corner(&g, 0, -1, -1);
	check_corner(&g, 1, 1, -1);
	check_corner(&g, 2, -1, 1);
	check_corner(&g, 3, 1, 1);
	/* texture corners in strip order: bottom-left, bottom-right, top-left, top-right */
	CHECK(g.quad[0][2] == 0 && g.quad[0][3] == 0 && g.quad[3][2] == 1 && g.quad[3][3] == 1);
	CHECK(g.quad[1][2] == 1 && g.quad[1][3] == 0 && g.quad[2][2] == 0 && g.quad[2][3] == 1);
	CHECK(g.one_to_one);
	CHECK_INT(g.w, 1280);
	CHECK_INT(g.h, 800);
}

static void test_turned(void)
{
	struct offscreen_geometry g;
	int w, h;

	/* a 1280x800 panel turned a quarter clockwise: the viewer sees 800x1280 */
	offscreen_turned_size(90, 1280, 800, &w, &h);
	CHECK_INT(w, 800);
	CHECK_INT(h, 1280);
	offscreen_turned_size(180, 1280, 800, &w, &h);
	CHECK_INT(w, 1280);
	CHECK_INT(h, 800);
	offscreen_geometry(90, 800, 1280, 1280, 800, &g);
	CHECK(g.one_to_one);
	/* the panel's top edge is on the viewer's right: the picture's top-left corner is
	 * the panel's bottom-left, its top-right the panel's top-left */
	check_corner(&g, 2, -1, -1);
	check_corner(&g, 3, -1, 1);
	check_corner(&g, 0, 1, -1);
	check_corner(&g, 1, 1, 1);
	offscreen_geometry(180, 1280, 800, 1280, 800, &g);
	check_corner(&g, 0, 1, 1); /* upside down */
	check_corner(&g, 3, -1, -1);
	offscreen_geometry(270, 800, 1280, 1280, 800, &g);
	check_corner(&g, 2, 1, 1); /* the top edge on the viewer's left */
	check_corner(&g, 0, -1, 1);
}

static void test_fit(void)
{
	struct offscreen_geometry g;

	/* 16:10 onto 16:9: bars left and right, 96 pixels each */
	offscreen_geometry(0, 1280, 800, 1920, 1080, &g);
	CHECK(!g.one_to_one);
	CHECK_INT(g.w, 1728);
	CHECK_INT(g.h, 1080);
	check_corner(&g, 0, -0.9, -1);
	check_corner(&g, 3, 0.9, 1);
	/* the same turned: the viewer sees 1080x1920, bars above and below */
	offscreen_geometry(90, 800, 1280, 1920, 1080, &g);
	CHECK_INT(g.w, 1080);
	CHECK_INT(g.h, 1728);
	check_corner(&g, 2, -0.9, -1);
	check_corner(&g, 1, 0.9, 1);
	/* the same width and more height: not scaled, centred on whole pixels */
	offscreen_geometry(0, 1280, 800, 1280, 1024, &g);
	CHECK(g.one_to_one);
	CHECK_NEAR(g.quad[2][1], 1.0 - 2.0 * 112 / 1024, EPS);
	/* an odd leftover keeps the picture on whole pixels: 1 pixel of 3 on the left */
	offscreen_geometry(0, 100, 100, 103, 100, &g);
	CHECK(g.one_to_one);
	CHECK_NEAR(g.quad[0][0], 2.0 * 1 / 103 - 1.0, EPS);
	/* smaller: scaled down, aspect kept */
	offscreen_geometry(0, 1280, 800, 1024, 768, &g);
	CHECK_INT(g.w, 1024);
	CHECK_INT(g.h, 640);
}

/*
 * display.rotation and input.rotation mean the same turn: a touchscreen glued to a
 * display turned by r, configured with input.rotation r, touches the picture where it
 * shows. The picture's pixel goes to the panel through the quad, the panel's point comes
 * back through input_map.
 */
static void test_agrees_with_input(void)
{
	static const int rotations[] = { 0, 90, 180, 270 };
	static const double points[][2] = { { 0, 0 }, { 100, 30 }, { 799, 1279 }, { 400, 640 } };

	for (size_t r = 0; r < 4; r++) {
		int rot = rotations[r], lw, lh;
		struct offscreen_geometry g;
		struct input_map m;

		offscreen_turned_size(rot, 1280, 800, &lw, &lh);
		offscreen_geometry(rot, lw, lh, 1280, 800, &g);
		input_map_init(&m, rot, CONFIG_AREA_STRETCH, NULL, 0, 0, lw, lh);
		for (size_t i = 0; i < sizeof(points) / sizeof(points[0]); i++) {
			double lx = points[i][0] * lw / 800.0, ly = points[i][1] * lh / 1280.0;
			double cx, cy, x, y;

			clip_of(&g, lx / lw, 1.0 - ly / lh, &cx, &cy);
			input_map_point(&m, (cx + 1.0) / 2.0, (1.0 - cy) / 2.0, &x, &y);
			CHECK_NEAR(x, lx, 1e-6 * lw);
			CHECK_NEAR(y, ly, 1e-6 * lh);
		}
	}
}

int main(void)
{
	test_straight();
	test_turned();
	test_fit();
	test_agrees_with_input();
	puts("offscreen: OK");
	return 0;
}
