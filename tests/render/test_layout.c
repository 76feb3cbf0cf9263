/* SPDX-License-Identifier: MIT */
/* The on-screen button bar: sizes, order, no overlaps, hit-testing, canvas. */
#include <stdbool.h>

#include "layout.h"
#include "test.h"
#include "view.h"

static const enum button expected_order[LAYOUT_NBUTTONS] = {
	BUTTON_3D,   BUTTON_CLONE, BUTTON_LEAF, BUTTON_PROPAGATE,
	BUTTON_UNDO, BUTTON_REDO,  BUTTON_NEW,  BUTTON_EXPORT,
};

static bool inside(const struct layout_button *b, double x, double y)
{
	return x >= b->x && x < b->x + b->w && y >= b->y && y < b->y + b->h;
}

static void check_screen(int width, int height)
{
	struct view v;
	struct layout_button b[LAYOUT_NBUTTONS];
	struct layout_rect canvas, bar;
	enum button hit;

	view_init(&v, width, height);
	CHECK_INT(layout_buttons(&v, b, LAYOUT_NBUTTONS), LAYOUT_NBUTTONS);
	canvas = layout_canvas(&v);
	bar = layout_bar(&v);

	CHECK_NEAR(canvas.x, 0, 0);
	CHECK_NEAR(canvas.y, 0, 0);
	CHECK_NEAR(canvas.h, height, 0);
	CHECK_NEAR(canvas.w + bar.w, width, 1e-9);
	CHECK_NEAR(bar.x, canvas.w, 1e-9);
	/* the canvas keeps most of a landscape screen */
	CHECK(canvas.w >= 0.8 * width);

	for (int i = 0; i < LAYOUT_NBUTTONS; i++) {
		const struct layout_button *p = &b[i];

		CHECK_INT(p->button, expected_order[i]);
		/* big enough for a child's pen: at least 9% of the height; wider, for the label */
		CHECK(p->h >= 0.09 * height);
		CHECK(p->w >= 1.5 * p->h && p->w <= 1.6 * p->h);
		/* whole pixels, inside the bar, on screen */
		CHECK_NEAR(p->x, (double)(long)p->x, 0);
		CHECK_NEAR(p->y, (double)(long)p->y, 0);
		CHECK(p->x >= bar.x && p->x + p->w <= width);
		CHECK(p->y >= 0 && p->y + p->h <= height);
		/* top to bottom, apart */
		if (i > 0)
			CHECK(p->y >= b[i - 1].y + b[i - 1].h + 1);

		/* centre, corners and the gap just outside hit this button */
		CHECK(layout_hit(&v, p->x + p->w / 2, p->y + p->h / 2, &hit));
		CHECK_INT(hit, p->button);
		CHECK(layout_hit(&v, p->x, p->y, &hit));
		CHECK_INT(hit, p->button);
		CHECK(layout_hit(&v, p->x + p->w - 0.01, p->y + p->h - 0.01, &hit));
		CHECK_INT(hit, p->button);
		CHECK(layout_hit(&v, width - 0.5, p->y + p->h / 2, &hit));
		CHECK_INT(hit, p->button);
	}
	/* modes and actions are grouped apart */
	CHECK(b[4].y - (b[3].y + b[3].h) > 1.5 * (b[1].y - (b[0].y + b[0].h)));

	/* the canvas and the middle of the group gap hit nothing */
	CHECK(!layout_hit(&v, canvas.w / 2, height / 2.0, &hit));
	CHECK(!layout_hit(&v, bar.x - 0.5, b[0].y + 1, &hit));
	CHECK(!layout_hit(&v, b[3].x + 1, 0.5 * (b[3].y + b[3].h + b[4].y), &hit));
	CHECK(!layout_hit(&v, width + 1.0, b[0].y + 1, &hit));
	CHECK(!layout_hit(&v, b[0].x + 1, -1.0, &hit));

	/* every point of every button hits that button and no other */
	for (int y = 0; y < height; y += 3) {
		for (int x = (int)bar.x; x < width; x += 3) {
			for (int i = 0; i < LAYOUT_NBUTTONS; i++) {
				if (inside(&b[i], x, y)) {
					CHECK(layout_hit(&v, x, y, &hit));
					CHECK_INT(hit, b[i].button);
				}
			}
		}
	}
}

int main(void)
{
	struct view v;
	struct layout_button few[3];

	check_screen(640, 400);
	check_screen(1280, 800);
	check_screen(1920, 1080);
	check_screen(1024, 768);

	/* like snprintf: the count is the full one even when out is short */
	view_init(&v, 1280, 800);
	CHECK_INT(layout_buttons(&v, few, 3), LAYOUT_NBUTTONS);
	CHECK_INT(few[2].button, BUTTON_LEAF);
	CHECK_INT(layout_buttons(&v, NULL, 0), LAYOUT_NBUTTONS);

	/* a tall narrow screen still leaves a canvas */
	view_init(&v, 300, 1000);
	CHECK(layout_canvas(&v).w >= 0.7 * 300);

	/* the buttons outside the bar have the bar's buttons' size; thumbnails are square */
	view_init(&v, 1280, 800);
	layout_buttons(&v, few, 1);
	{
		struct layout_button vb = layout_view_button(&v);
		struct layout_rect pat = layout_side_slot(&v, 1, false), th = layout_side_slot(&v, 0, true);
		size_t slot = 9;

		CHECK_NEAR(vb.w, few[0].w, 0);
		CHECK_NEAR(vb.h, few[0].h, 0);
		CHECK_NEAR(pat.w, few[0].w, 0);
		CHECK_NEAR(pat.h, few[0].h, 0);
		CHECK_NEAR(th.w, th.h, 0);
		CHECK(th.h > few[0].h);
		/* all of a wide button hits, to its right edge */
		CHECK(layout_hit_view_button(&v, vb.x + vb.w - 0.5, vb.y + vb.h / 2));
		CHECK(!layout_hit_view_button(&v, vb.x + vb.w + vb.h, vb.y + vb.h / 2));
		CHECK(layout_side_hit(&v, pat.x + pat.w - 0.5, pat.y + 1, 2, false, &slot));
		CHECK_INT(slot, 1);
		/* the pattern buttons stay clear of each other */
		CHECK(layout_side_slot(&v, 0, false).y + pat.h < pat.y);
	}
	return 0;
}
