/* SPDX-License-Identifier: MIT */
/*
 * The on-screen layout: the bar's buttons (order, groups, sizes, no overlaps, targets,
 * hit-testing, canvas), the vine button beside season and the grow button under it, the
 * side strip's places, every target at least 9 mm on a 10-inch 1280x800 and a 7-inch
 * 800x480 screen, and no stroke of the recorded traces (tests/data, given as argv[1]) on
 * the bar.
 */
#include <dirent.h>
#include <stdbool.h>
#include <string.h>

#include "layout.h"
#include "test.h"
#include "trace.h"
#include "screen.h"

static const enum button expected_order[LAYOUT_NBUTTONS] = {
	BUTTON_3D,   BUTTON_CLONE, BUTTON_LEAF, BUTTON_PROPAGATE, BUTTON_SEASON, BUTTON_VINE,
	BUTTON_GROW, BUTTON_UNDO,  BUTTON_REDO, BUTTON_NEW,       BUTTON_EXPORT,
};
/* where they are in it */
enum { SEASON = 4, VINE = 5, GROW = 6, UNDO = 7, REDO = 8, NEW = 9, SAVE = 10 };

/* A screen of this many inches across its diagonal. */
struct panel {
	int width, height;
	double inches;
};
static const struct panel tablet10 = { 1280, 800, 10.0 };
static const struct panel tablet7 = { 800, 480, 7.0 };

#define MIN_TARGET_MM 9.0

static double mm_per_px(const struct panel *s)
{
	return 25.4 * s->inches / hypot(s->width, s->height);
}

static bool inside(const struct layout_rect *r, double x, double y)
{
	return x >= r->x && x < r->x + r->w && y >= r->y && y < r->y + r->h;
}

static bool overlap(const struct layout_rect *a, const struct layout_rect *b)
{
	return a->x < b->x + b->w && b->x < a->x + a->w && a->y < b->y + b->h && b->y < a->y + a->h;
}

static struct layout_rect visible(const struct layout_button *b)
{
	return (struct layout_rect){ b->x, b->y, b->w, b->h };
}

/* A target's smaller side in mm is at least MIN_TARGET_MM; says what it is. */
static void check_mm(const struct panel *s, const char *what, size_t i, struct layout_rect t)
{
	double k = mm_per_px(s), w = t.w * k, h = t.h * k;

	printf("%4.0f\" %dx%d %-12s %2zu: target %5.1f x %5.1f mm\n", s->inches, s->width,
	       s->height, what, i, w, h);
	CHECK(w >= MIN_TARGET_MM && h >= MIN_TARGET_MM);
}

/* The buttons of a bar on a screen: inside it, apart, their targets around them, apart,
 * and hit where they are. */
static void check_bar(const struct screen *v, const struct layout_bar_list *list,
		      const struct layout_button *b, size_t n)
{
	struct layout_rect bar = layout_bar(v);
	size_t hit;

	for (size_t i = 0; i < n; i++) {
		const struct layout_button *p = &b[i];
		struct layout_rect vis = visible(p);

		CHECK_INT(p->button, list->buttons[i]);
		/* whole pixels, inside the bar, on screen */
		CHECK_NEAR(p->x, round(p->x), 0);
		CHECK_NEAR(p->y, round(p->y), 0);
		CHECK_NEAR(p->w, round(p->w), 0);
		CHECK(p->x >= bar.x && p->x + p->w <= v->width);
		CHECK(p->y >= 0 && p->y + p->h <= v->height);
		/* a target holds its button and stays in the bar */
		CHECK(p->target.x <= p->x && p->target.y <= p->y);
		CHECK(p->target.x + p->target.w >= p->x + p->w);
		CHECK(p->target.y + p->target.h >= p->y + p->h);
		CHECK(p->target.x >= bar.x && p->target.x + p->target.w <= v->width);
		for (size_t j = 0; j < i; j++) {
			struct layout_rect o = visible(&b[j]);

			CHECK(!overlap(&vis, &o));
			CHECK(!overlap(&p->target, &b[j].target));
		}
		/* centre, corners and the target's edges hit this one */
		CHECK(layout_bar_hit(v, list, p->x + p->w / 2, p->y + p->h / 2, &hit));
		CHECK_INT(hit, i);
		CHECK(layout_bar_hit(v, list, p->x + p->w - 0.01, p->y + p->h - 0.01, &hit));
		CHECK_INT(hit, i);
		CHECK(layout_bar_hit(v, list, p->target.x, p->target.y, &hit));
		CHECK_INT(hit, i);
		CHECK(layout_bar_hit(v, list, p->target.x + p->target.w - 0.01,
				     p->target.y + p->target.h - 0.01, &hit));
		CHECK_INT(hit, i);
	}
	/* the canvas and just left of the bar hit nothing, nor anything off the screen */
	CHECK(!layout_bar_hit(v, list, bar.x / 2, v->height / 2.0, &hit));
	CHECK(!layout_bar_hit(v, list, bar.x - 0.5, b[0].y + 1, &hit));
	CHECK(!layout_bar_hit(v, list, v->width + 1.0, b[0].y + 1, &hit));
	CHECK(!layout_bar_hit(v, list, b[0].x + 1, -1.0, &hit));
}

static void check_screen(int width, int height, double min_canvas)
{
	struct screen v;
	struct layout_button b[LAYOUT_NBUTTONS];
	struct layout_rect canvas, bar;
	enum button hit;
	double row_gap, group_gap;

	screen_init(&v, width, height);
	CHECK_INT(layout_buttons(&v, b, LAYOUT_NBUTTONS), LAYOUT_NBUTTONS);
	canvas = layout_canvas(&v);
	bar = layout_bar(&v);

	CHECK_NEAR(canvas.x, 0, 0);
	CHECK_NEAR(canvas.y, 0, 0);
	CHECK_NEAR(canvas.h, height, 0);
	CHECK_NEAR(canvas.w + bar.w, width, 1e-9);
	CHECK_NEAR(bar.x, canvas.w, 1e-9);
	/* the canvas keeps most of the screen */
	CHECK(canvas.w >= min_canvas * width);

	check_bar(&v, &layout_kiosk_bar, b, LAYOUT_NBUTTONS);
	for (size_t i = 0; i < LAYOUT_NBUTTONS; i++) {
		CHECK_INT(b[i].button, expected_order[i]);
		/* big enough for a child's pen: a tenth of the height; wider, for the label */
		CHECK(b[i].h >= 0.095 * height);
		CHECK(b[i].w >= 1.2 * b[i].h && b[i].w <= 1.3 * b[i].h);
		CHECK(layout_hit(&v, b[i].x + 1, b[i].y + 1, &hit));
		CHECK_INT(hit, b[i].button);
	}
	/* two columns: pairs side by side, the tools from the top, the actions at the bottom */
	CHECK_NEAR(b[0].y, b[1].y, 0);
	CHECK(b[1].x > b[0].x + b[0].w);
	CHECK_NEAR(b[SEASON].x, b[0].x, 0);
	CHECK_NEAR(b[VINE].x, b[1].x, 0);
	CHECK_NEAR(b[VINE].y, b[SEASON].y, 0); /* season | vine */
	CHECK_NEAR(b[GROW].x, b[SEASON].x, 0); /* grow under season */
	CHECK(b[GROW].y > b[SEASON].y + b[SEASON].h);
	CHECK_NEAR(b[UNDO].y, b[REDO].y, 0);
	CHECK_NEAR(b[NEW].y, b[SAVE].y, 0);
	CHECK(b[NEW].y > b[UNDO].y);
	CHECK_NEAR(b[SAVE].x + b[SAVE].w + (b[1].x - b[0].x - b[0].w), width, 1);
	/* the screen's edges belong to the buttons beside them */
	CHECK_NEAR(b[1].target.y, 0, 0);
	CHECK_NEAR(b[SAVE].target.x + b[SAVE].target.w, width, 0);
	CHECK_NEAR(b[SAVE].target.y + b[SAVE].target.h, height, 0);
	/* the tree tools and the actions read apart: a whole empty row at least between them */
	row_gap = b[2].y - (b[0].y + b[0].h);
	group_gap = b[UNDO].y - (b[GROW].y + b[GROW].h);
	CHECK(group_gap > 2.0 * row_gap + b[0].h);
	CHECK(!layout_hit(&v, b[GROW].x + 1, 0.5 * (b[GROW].y + b[GROW].h + b[UNDO].y), &hit));
	/* the place beside grow is empty */
	CHECK(!layout_hit(&v, b[VINE].x + b[VINE].w / 2, b[GROW].y + b[GROW].h / 2, &hit));

	/* every point of every button hits that button and no other */
	for (int y = 0; y < height; y += 3) {
		for (int x = (int)bar.x; x < width; x += 3) {
			for (int i = 0; i < LAYOUT_NBUTTONS; i++) {
				struct layout_rect r = visible(&b[i]);

				if (inside(&r, x, y)) {
					CHECK(layout_hit(&v, x, y, &hit));
					CHECK_INT(hit, b[i].button);
				}
			}
		}
	}
}

/* A tree tool on a kiosk's screen: in the bar once, its centre and its corners pressing
 * it, clear of every other button and target, above every action. Fills b and returns
 * the tool's place in it. */
static size_t check_tool(const struct panel *s, enum button tool,
			 struct layout_button b[LAYOUT_NBUTTONS])
{
	struct screen v;
	struct layout_rect bar, vis;
	size_t found = 0, at = 0;
	enum button hit = BUTTON_COUNT;

	screen_init(&v, s->width, s->height);
	CHECK_INT(layout_buttons(&v, b, LAYOUT_NBUTTONS), LAYOUT_NBUTTONS);
	bar = layout_bar(&v);
	for (size_t i = 0; i < LAYOUT_NBUTTONS; i++) {
		if (b[i].button == tool) {
			found++;
			at = i;
		}
	}
	CHECK_INT(found, 1);
	vis = visible(&b[at]);
	CHECK(vis.x >= bar.x && vis.x + vis.w <= s->width && vis.y >= 0 && vis.y + vis.h <= s->height);
	CHECK(layout_hit(&v, vis.x + vis.w / 2, vis.y + vis.h / 2, &hit));
	CHECK_INT(hit, tool);
	CHECK(layout_hit(&v, vis.x + 0.5, vis.y + 0.5, &hit));
	CHECK_INT(hit, tool);
	CHECK(layout_hit(&v, vis.x + vis.w - 0.5, vis.y + 0.5, &hit));
	CHECK_INT(hit, tool);
	CHECK(layout_hit(&v, vis.x + 0.5, vis.y + vis.h - 0.5, &hit));
	CHECK_INT(hit, tool);
	CHECK(layout_hit(&v, vis.x + vis.w - 0.5, vis.y + vis.h - 0.5, &hit));
	CHECK_INT(hit, tool);
	for (size_t i = 0; i < LAYOUT_NBUTTONS; i++) {
		struct layout_rect o = visible(&b[i]);

		if (i == at)
			continue;
		CHECK(!overlap(&vis, &o));
		CHECK(!overlap(&b[at].target, &b[i].target));
		if (b[i].button == BUTTON_UNDO)
			CHECK(vis.y + vis.h < b[i].y);
	}
	printf("%4.0f\" %dx%d %s at %.0f,%.0f %.0fx%.0f\n", s->inches, s->width, s->height,
	       button_name(tool), vis.x, vis.y, vis.w, vis.h);
	return at;
}

/* The vine button (issue 16): season's right-hand neighbour. */
static void check_vine(const struct panel *s)
{
	struct layout_button b[LAYOUT_NBUTTONS];
	size_t at = check_tool(s, BUTTON_VINE, b);

	CHECK(b[SEASON].y == b[at].y && b[SEASON].x + b[SEASON].w < b[at].x);
}

/* The grow button (issue 17): under season, in the left column, with an empty row at
 * least between it and the actions. */
static void check_grow(const struct panel *s)
{
	struct layout_button b[LAYOUT_NBUTTONS];
	size_t at = check_tool(s, BUTTON_GROW, b);
	double row = b[2].y - b[0].y;

	CHECK(b[SEASON].x == b[at].x && b[SEASON].y + b[SEASON].h < b[at].y);
	CHECK_NEAR(b[at].y - b[SEASON].y, row, 0);
	CHECK(b[at].y + row + b[at].h < b[UNDO].y);
}

/* Every target on the two screens a kiosk may have is at least 9 mm either way: the bar's,
 * the front view button, the side strip's places. */
static void check_targets(const struct panel *s)
{
	static const enum layout_side_kind kinds[] = { LAYOUT_SIDE_BUTTONS, LAYOUT_SIDE_CARDS,
						       LAYOUT_SIDE_NAMED_CARDS };
	static const char *const kind_names[] = { "side button", "card", "named card" };
	struct screen v;
	struct layout_button b[LAYOUT_NBUTTONS];
	size_t n;

	screen_init(&v, s->width, s->height);
	n = layout_buttons(&v, b, LAYOUT_NBUTTONS);
	CHECK_INT(n, LAYOUT_NBUTTONS);
	for (size_t i = 0; i < n; i++)
		check_mm(s, "bar", i, b[i].target);
	check_mm(s, "front view", 0, layout_view_button(&v).target);
	for (size_t k = 0; k < 3; k++) {
		/* the New strip's seven cards, the eight parameter buttons */
		for (size_t i = 0; i < 8; i++)
			check_mm(s, kind_names[k], i, layout_side_target(&v, i, kinds[k]));
	}
	printf("%4.0f\" %dx%d canvas %.0f px wide (%.1f%%)\n", s->inches, s->width, s->height,
	       layout_canvas(&v).w, 100.0 * layout_canvas(&v).w / s->width);
}

/* Side strip places of a kind on a screen: on the canvas, apart, targets around them and
 * apart, hit where they are; cards stay above the front view button. */
static void check_side(int width, int height, enum layout_side_kind kind, size_t n)
{
	struct screen v;
	struct layout_rect canvas, view_target;
	struct layout_button vb;

	screen_init(&v, width, height);
	canvas = layout_canvas(&v);
	vb = layout_view_button(&v);
	view_target = vb.target;
	for (size_t i = 0; i < n; i++) {
		struct layout_rect s = layout_side_slot(&v, i, kind);
		struct layout_rect t = layout_side_target(&v, i, kind);
		size_t slot = 99;

		CHECK(s.x >= 0 && s.y >= 0 && s.x + s.w < canvas.w && s.y + s.h <= height);
		CHECK(inside(&t, s.x, s.y) && inside(&t, s.x + s.w - 0.5, s.y + s.h - 0.5));
		CHECK(!overlap(&t, &view_target));
		for (size_t j = 0; j < i; j++) {
			struct layout_rect o = layout_side_slot(&v, j, kind);
			struct layout_rect ot = layout_side_target(&v, j, kind);

			CHECK(!overlap(&s, &o));
			CHECK(!overlap(&t, &ot));
		}
		CHECK(layout_side_hit(&v, s.x + s.w / 2, s.y + s.h / 2, n, kind, &slot));
		CHECK_INT(slot, i);
		CHECK(layout_side_hit(&v, t.x, t.y, n, kind, &slot));
		CHECK_INT(slot, i);
		/* a picture is square, a named card's with its word under it */
		if (kind != LAYOUT_SIDE_BUTTONS) {
			struct layout_rect p = layout_card_picture(s, kind);

			CHECK_NEAR(p.w, p.h, 0);
			CHECK(kind == LAYOUT_SIDE_NAMED_CARDS ? s.h > 1.2 * p.h : s.h == p.h);
		}
	}
	/* buttons in pairs side by side; cards down a column */
	if (kind == LAYOUT_SIDE_BUTTONS) {
		CHECK_NEAR(layout_side_slot(&v, 0, kind).y, layout_side_slot(&v, 1, kind).y, 0);
		CHECK(layout_side_slot(&v, 2, kind).y > layout_side_slot(&v, 0, kind).y);
	} else {
		CHECK_NEAR(layout_side_slot(&v, 0, kind).x, layout_side_slot(&v, 1, kind).x, 0);
	}
	CHECK(!layout_side_hit(&v, canvas.w / 2, height / 2.0, n, kind, &(size_t){ 0 }));
}

/*
 * The recorded traces keep meaning what they mean: no stroke (tip down to tip up) of any
 * of them, read at its screen size, reaches the bar's targets. The edaha traces are
 * recorded at 1280x800; the libinput recordings are replayed (cli.sh) at the default
 * 1280x800 too.
 */
static void check_traces(const char *dir)
{
	DIR *d = opendir(dir);
	struct dirent *e;
	size_t files = 0;
	double largest = 0.0;
	struct screen v;
	struct layout_rect bar;

	CHECK(d);
	screen_init(&v, 1280, 800);
	bar = layout_bar(&v);
	while ((e = readdir(d))) {
		size_t len = strlen(e->d_name);
		char path[4096];
		struct trace t;
		struct error err;
		bool down = false;

		if (!(len > 12 && !strcmp(e->d_name + len - 12, ".edaha-trace")) &&
		    !(len > 4 && !strcmp(e->d_name + len - 4, ".yml")))
			continue;
		CHECK(snprintf(path, sizeof(path), "%s/%s", dir, e->d_name) < (int)sizeof(path));
		trace_init(&t);
		if (trace_load(path, v.width, v.height, &t, &err) < 0) {
			fprintf(stderr, "%s: %s\n", path, err.msg);
			CHECK(0);
		}
		for (size_t i = 0; i < t.nevents; i++) {
			const struct event *ev = &t.events[i];

			if (ev->type == EVENT_TIP_DOWN)
				down = true;
			if (down && (ev->type == EVENT_TIP_DOWN || ev->type == EVENT_MOTION ||
				     ev->type == EVENT_TIP_UP)) {
				if (ev->x >= bar.x)
					fprintf(stderr, "%s: event %zu at x %.1f, on the bar (%.0f)\n",
						e->d_name, i, ev->x, bar.x);
				CHECK(ev->x < bar.x);
				largest = fmax(largest, ev->x);
			}
			if (ev->type == EVENT_TIP_UP)
				down = false;
		}
		trace_finish(&t);
		files++;
	}
	closedir(d);
	printf("%zu traces: strokes reach x = %.1f, the bar begins at %.0f\n", files, largest, bar.x);
	CHECK(files >= 20);
}

int main(int argc, char **argv)
{
	struct screen v;
	struct layout_button few[3];

	CHECK(argc == 2);
	check_screen(640, 400, 0.8);
	check_screen(800, 480, 0.8);
	check_screen(1280, 800, 0.8);
	check_screen(1920, 1080, 0.8);
	/* a 4:3 screen gives a little more of its width to the bar */
	check_screen(1024, 768, 0.75);

	check_targets(&tablet10);
	check_targets(&tablet7);
	check_vine(&tablet10);
	check_vine(&tablet7);
	check_grow(&tablet10);
	check_grow(&tablet7);
	for (size_t k = 0; k < 3; k++) {
		check_side(1280, 800, (enum layout_side_kind)k, 8);
		check_side(800, 480, (enum layout_side_kind)k, 8);
		check_side(640, 400, (enum layout_side_kind)k, 8);
	}

	/* like snprintf: the count is the full one even when out is short */
	screen_init(&v, 1280, 800);
	CHECK_INT(layout_buttons(&v, few, 3), LAYOUT_NBUTTONS);
	CHECK_INT(few[2].button, BUTTON_LEAF);
	CHECK_INT(layout_buttons(&v, NULL, 0), LAYOUT_NBUTTONS);
	/* a list too long for the rows has no buttons */
	{
		static const enum button nine_tools[9] = { BUTTON_3D };
		struct layout_bar_list too_many = { nine_tools, 9, 9 };
		size_t hit;

		CHECK_INT(layout_bar_buttons(&v, &too_many, few, 3), 0);
		CHECK(!layout_bar_hit(&v, &too_many, 1270, 10, &hit));
	}

	/* a tall narrow screen still leaves a canvas */
	screen_init(&v, 300, 1000);
	CHECK(layout_canvas(&v).w >= 0.7 * 300);

	/* where the traces tap the side strip at 1280x800 (tests/data/gen-edit-traces.py):
	 * the pattern buttons at (56, 56), the leaf suggestions down the left edge */
	screen_init(&v, 1280, 800);
	{
		struct layout_button vb = layout_view_button(&v);
		struct layout_rect pat = layout_side_slot(&v, 1, LAYOUT_SIDE_BUTTONS);
		size_t slot = 9;

		CHECK(layout_side_hit(&v, 56, 56, 2, LAYOUT_SIDE_BUTTONS, &slot));
		CHECK_INT(slot, 0);
		for (size_t i = 0; i < 3; i++) {
			CHECK(layout_side_hit(&v, 80, 80 + 140.0 * (double)i, 3, LAYOUT_SIDE_CARDS, &slot));
			CHECK_INT(slot, i);
		}
		/* the side buttons are as large as the front view button, which all hits */
		CHECK_NEAR(vb.w, pat.w, 0);
		CHECK_NEAR(vb.h, pat.h, 0);
		CHECK(layout_hit_view_button(&v, vb.x + vb.w - 0.5, vb.y + vb.h / 2));
		CHECK(!layout_hit_view_button(&v, vb.x + vb.w + vb.h, vb.y + vb.h / 2));
	}
	check_traces(argv[1]);
	return 0;
}
