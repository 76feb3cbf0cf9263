/* SPDX-License-Identifier: MIT */
/*
 * Functional trees on the kiosk (docs/functional-trees.md): the New strip and its
 * templates, the parameter buttons while the tree is as generated, the season button, each
 * an undoable op of the drawing; the pen taps the strip as the GPIO buttons press.
 */
#include <errno.h>
#include <string.h>

#include "app.h"
#include "app_mode.h"
#include "app_private.h"
#include "journal.h"
#include "pen.h"
#include "test.h"

static struct pen pen = { .now_us = 1000, .hold_us = 50000, .steps = 20, .pause_us = PEN_PAUSE_US };

static const struct gen_params *params_of(const struct app *app)
{
	const struct doc_op *op = app_generated(app);

	return op ? op->params : NULL;
}

/* Where on the screen a tap presses b (the bar or the side strip), found by looking: the
 * test does not know the layout. */
static bool spot_of(const struct app *app, enum button b, double *x, double *y)
{
	for (double py = 2; py < app->screen.height; py += 4) {
		for (double px = 2; px < app->screen.width; px += 4) {
			enum button hit;

			if (app_ui_hit(app, px, py, &hit) && hit == b) {
				*x = px;
				*y = py;
				return true;
			}
		}
	}
	return false;
}

static void tap(struct app *app, double x, double y)
{
	pen_event(&pen, app, EVENT_PROXIMITY_IN, EVENT_TOOL_PEN, x, y, 0);
	pen_event(&pen, app, EVENT_TIP_DOWN, EVENT_TOOL_PEN, x, y, 0.5);
	pen_event(&pen, app, EVENT_TIP_UP, EVENT_TOOL_PEN, x, y, 0);
	pen_event(&pen, app, EVENT_PROXIMITY_OUT, EVENT_TOOL_PEN, x, y, 0);
	pen.now_us += PEN_PAUSE_US;
}

static bool branches_equal(const struct tree *a, const struct tree *b)
{
	if (a->nbranches != b->nbranches || a->nleaves != b->nleaves)
		return false;
	for (size_t i = 0; i < a->nbranches; i++) {
		const struct branch *x = &a->branches[i], *y = &b->branches[i];

		if (x->npoints != y->npoints || x->parent != y->parent || x->level != y->level ||
		    memcmp(x->points, y->points, x->npoints * sizeof(*x->points)) ||
		    memcmp(x->radii, y->radii, x->npoints * sizeof(*x->radii)))
			return false;
	}
	for (size_t i = 0; i < a->nleaves; i++)
		if (a->leaves[i].npoints != b->leaves[i].npoints ||
		    memcmp(a->leaves[i].points, b->leaves[i].points,
			   a->leaves[i].npoints * sizeof(*a->leaves[i].points)))
			return false;
	return true;
}

/* New opens the strip; a tap on a template puts that tree on the canvas, as a 3D tree. */
static void test_new_strip(void)
{
	struct app *app = app_create(1280, 800, 7);
	struct app_side_item items[APP_SIDE_MAX];
	struct gen_params ball;
	struct error err;
	double x, y;
	size_t n;

	CHECK(app);
	/* nothing on the side strip of an empty canvas until New */
	CHECK_INT(app_side_items(app, items), 0);
	pen_button(&pen, app, BUTTON_NEW);
	CHECK_INT(app->mode, APP_MODE_NEW);
	CHECK_INT(app->doc.nops, 0); /* an empty canvas is not cleared again */
	n = app_side_items(app, items);
	CHECK_INT(n, 1 + GEN_PRESET_COUNT);
	CHECK(items[0].thumbnail && items[0].button == BUTTON_TPL_BLANK && !items[0].preview);
	for (size_t i = 1; i < n; i++) {
		CHECK(items[i].thumbnail && items[i].template);
		CHECK_INT(items[i].button, BUTTON_TPL_CHERRY + (int)i - 1);
		/* a rendered picture of the tree */
		CHECK(items[i].preview && items[i].preview->bark.nindices > 0);
	}
	CHECK(app->templates[GEN_PRESET_PALM].leaves.nindices > 0);

	/* the pen taps the topiary ball's card */
	CHECK(spot_of(app, BUTTON_TPL_BALL, &x, &y));
	tap(app, x, y);
	CHECK_INT(app->failed, 0);
	CHECK_INT(app->mode, APP_MODE_SKETCH);
	CHECK(app->tree.lifted);
	CHECK(app->turning); /* it swings, as after 3D */
	CHECK_INT(app->doc.nops, 1);
	CHECK_INT(app->doc.ops[0].kind, DOC_OP_GENERATE);
	CHECK_INT(gen_preset(GEN_PRESET_BALL, &ball, &err), 0);
	CHECK(params_of(app) && !memcmp(params_of(app), &ball, sizeof(ball)));
	CHECK(app->tree.nbranches > 100);
	for (size_t i = 0; i < app->tree.nbranches; i++)
		CHECK_INT(app->tree.branches[i].origin, ORIGIN_GENERATE);
	CHECK_INT(app->tree.sides, ball.precision);

	/* New on a tree: cleared (undoable) and the strip again */
	pen_button(&pen, app, BUTTON_NEW);
	CHECK_INT(app->mode, APP_MODE_NEW);
	CHECK_INT(app->tree.nbranches, 0);
	CHECK_INT(app->doc.nops, 2);
	/* the blank card: the visitor draws */
	pen_button(&pen, app, BUTTON_TPL_BLANK);
	CHECK_INT(app->mode, APP_MODE_SKETCH);
	CHECK_INT(app->doc.nops, 2);
	/* drawing while the strip is open closes it, and draws */
	pen_button(&pen, app, BUTTON_NEW);
	CHECK_INT(app->mode, APP_MODE_NEW);
	pen_line(&pen, app, 640, 700, 650, 300);
	CHECK_INT(app->mode, APP_MODE_SKETCH);
	CHECK_INT(app->tree.nbranches, 1);
	/* a template replaces a drawn tree, and undo brings it back */
	pen_button(&pen, app, BUTTON_TPL_CHERRY);
	CHECK(app->tree.nbranches > 100);
	pen_button(&pen, app, BUTTON_UNDO);
	CHECK_INT(app->tree.nbranches, 1);
	CHECK_INT(app->tree.branches[0].origin, ORIGIN_SKETCH);
	app_destroy(app);
}

/* The parameter buttons change the generated tree while nobody has edited it by hand. */
static void test_parameter_buttons(void)
{
	struct app *app = app_create(1280, 800, 3);
	struct app_side_item items[APP_SIDE_MAX];
	struct gen_params p;
	uint64_t seed;
	double x, y;
	size_t nops;

	CHECK(app);
	gen_params_default(&p, GEN_LSYSTEM);
	p.levels = 5;
	CHECK_INT(app_generate(app, &p, pen.now_us), 0);
	CHECK_INT(app->tree.nbranches, 31);
	seed = app->doc.ops[0].seed;
	/* in pairs on the side strip */
	CHECK_INT(app_side_items(app, items), 8);
	CHECK_INT(items[0].button, BUTTON_GEN_MORE);
	CHECK_INT(items[1].button, BUTTON_GEN_FEWER);
	CHECK_INT(items[6].button, BUTTON_GEN_LEAFIER);
	CHECK_INT(items[7].button, BUTTON_GEN_BARER);

	/* more: a level more, the same seed */
	CHECK(spot_of(app, BUTTON_GEN_MORE, &x, &y));
	tap(app, x, y);
	CHECK_INT(app->tree.nbranches, 63);
	CHECK_INT(params_of(app)->levels, 6);
	CHECK(app->doc.ops[app->doc.cursor - 1].seed == seed);
	pen_button(&pen, app, BUTTON_GEN_FEWER);
	pen_button(&pen, app, BUTTON_GEN_FEWER);
	CHECK_INT(app->tree.nbranches, 15);
	pen_button(&pen, app, BUTTON_UNDO);
	CHECK_INT(app->tree.nbranches, 31);
	pen_button(&pen, app, BUTTON_REDO);
	CHECK_INT(app->tree.nbranches, 15);
	/* each pair changes what docs/functional-trees.md says */
	pen_button(&pen, app, BUTTON_GEN_WIDER);
	CHECK(params_of(app)->angle_min == p.angle_min + 8 && params_of(app)->angle_max == p.angle_max + 8);
	pen_button(&pen, app, BUTTON_GEN_TALLER);
	CHECK(params_of(app)->ratios[0] > p.ratios[0] * 1.149 && params_of(app)->ratios[0] < p.ratios[0] * 1.151);
	pen_button(&pen, app, BUTTON_GEN_BARER);
	CHECK_INT(params_of(app)->leaf_amount, p.leaf_amount - 2);
	CHECK_INT(app->tree.nleaves, 8 * (size_t)(p.leaf_amount - 2));
	/* a season is no hand edit, and the buttons keep it */
	pen_button(&pen, app, BUTTON_SEASON);
	CHECK(params_of(app) != NULL);
	CHECK_INT(app_side_items(app, items), 8);
	CHECK_INT(app->tree.season, SEASON_AUTUMN);
	pen_button(&pen, app, BUTTON_GEN_LEAFIER);
	CHECK_INT(app->tree.season, SEASON_AUTUMN);
	CHECK_INT(params_of(app)->leaf_amount, p.leaf_amount);

	/* a stroke is: the buttons give way, and do nothing */
	nops = app->doc.nops;
	pen_line(&pen, app, 640, 650, 520, 560); /* from the trunk: on a 3D tree a drag from afar turns it */
	CHECK(app->doc.nops == nops + 1);
	CHECK(params_of(app) == NULL);
	CHECK_INT(app_side_items(app, items), 0);
	CHECK(!app_gen_possible(app, BUTTON_GEN_MORE));
	pen_button(&pen, app, BUTTON_GEN_MORE);
	CHECK(app->doc.nops == nops + 1);
	/* undo back past it and they return */
	pen_button(&pen, app, BUTTON_UNDO);
	CHECK(params_of(app) != NULL);
	CHECK_INT(app_side_items(app, items), 8);
	/* a press past a limit changes nothing and says so */
	while (app_gen_possible(app, BUTTON_GEN_BARER))
		pen_button(&pen, app, BUTTON_GEN_BARER);
	CHECK_INT(params_of(app)->leaf_amount, 0);
	CHECK_INT(app->tree.nleaves, 0);
	nops = app->doc.nops;
	pen_button(&pen, app, BUTTON_GEN_BARER);
	CHECK(app->doc.nops == nops);
	/* the editing modes work on it as on any 3D tree, and put the buttons away */
	pen_button(&pen, app, BUTTON_CLONE);
	CHECK_INT(app->mode, APP_MODE_CLONE);
	CHECK_INT(app_side_items(app, items), 0);
	app_destroy(app);
}

/* The season: an op on any tree, cycling; it never changes a branch. */
static void test_season(void)
{
	static const enum season cycle[] = { SEASON_AUTUMN, SEASON_WINTER, SEASON_SPRING, SEASON_SUMMER };
	struct app *app = app_create(1280, 800, 5);
	struct tree before;

	CHECK(app);
	pen_button(&pen, app, BUTTON_SEASON);
	CHECK_INT(app->doc.nops, 0); /* an empty canvas has no season to show */
	pen_line(&pen, app, 640, 730, 640, 300);
	pen_line(&pen, app, 640, 450, 800, 350);
	CHECK_INT(app->tree.season, SEASON_SUMMER);
	tree_init(&before);
	CHECK_INT(tree_copy(&before, &app->tree), 0);
	for (int i = 0; i < 4; i++) {
		pen_button(&pen, app, BUTTON_SEASON);
		CHECK_INT(app->tree.season, cycle[i]);
		CHECK_INT(app->doc.ops[app->doc.cursor - 1].kind, DOC_OP_SEASON);
		CHECK(branches_equal(&before, &app->tree));
	}
	pen_button(&pen, app, BUTTON_UNDO);
	CHECK_INT(app->tree.season, SEASON_SPRING);
	pen_button(&pen, app, BUTTON_UNDO);
	pen_button(&pen, app, BUTTON_UNDO);
	CHECK_INT(app->tree.season, SEASON_AUTUMN);
	/* a template starts in its file's season: the cherry in blossom */
	pen_button(&pen, app, BUTTON_TPL_CHERRY);
	CHECK_INT(app->tree.season, SEASON_SPRING);
	tree_finish(&before);
	app_destroy(app);
}

/* The drawing holds parameters: saved and loaded (and through the autosave journal), the
 * same tree. */
static void test_drawing(void)
{
	struct app *app = app_create(1280, 800, 11), *back = app_create(1280, 800, 0);
	struct journal_replay jr;
	struct error err;
	struct buf b, j;
	struct doc d;

	CHECK(app && back);
	pen_button(&pen, app, BUTTON_TPL_HEDGE);
	pen_button(&pen, app, BUTTON_GEN_TALLER);
	pen_button(&pen, app, BUTTON_SEASON);
	pen_button(&pen, app, BUTTON_CLONE);
	pen_button(&pen, app, BUTTON_CLONE);
	pen_line(&pen, app, 900, 600, 1000, 400);
	buf_init(&b);
	CHECK_INT(doc_serialize(&app->doc, &app->tree, &b), 0);
	CHECK_INT(doc_parse((const char *)b.data, b.len, "drawing.edaha", &d, &err), 0);
	CHECK_INT(d.nops, app->doc.nops);
	CHECK(!memcmp(d.ops[0].params, app->doc.ops[0].params, sizeof(*d.ops[0].params)));
	CHECK_INT(app_load_doc(back, &d), 0);
	CHECK(branches_equal(&app->tree, &back->tree));
	CHECK_INT(back->tree.season, app->tree.season);
	/* the tree is parameters: a few hundred bytes for over a thousand branches */
	CHECK(app->tree.nbranches > 1000 && b.len < 3000);

	buf_init(&j);
	CHECK_INT(journal_header(&j), 0);
	CHECK_INT(journal_record(&app->doc, 0, &j), 0);
	CHECK_INT(journal_replay((const char *)j.data, j.len, "drawing.journal", &d, &jr, &err), 0);
	CHECK(!jr.torn);
	CHECK_INT(app_load_doc(back, &d), 0);
	CHECK(branches_equal(&app->tree, &back->tree));
	buf_finish(&j);
	buf_finish(&b);
	app_destroy(app);
	app_destroy(back);
}

/* A drawing of hundreds of large trees is refused as one of millions of points is: it
 * would keep --load busy for minutes. */
static void test_weight(void)
{
	struct gen_params p;
	struct error err;
	struct buf b, line;
	struct doc d;
	size_t n = 300;

	gen_params_default(&p, GEN_LSYSTEM);
	p.levels = 12;
	buf_init(&line);
	CHECK_INT(gen_write(&p, &line), 0);
	buf_init(&b);
	buf_printf(&b, "edaha-drawing 5\nseed 1\nhistory %zu %zu\n", n, n);
	for (size_t i = 0; i < n; i++)
		buf_printf(&b, "generate %zu 1 %zu %.*s\n", i, i, (int)line.len, (const char *)line.data);
	buf_printf(&b, "end\n");
	CHECK(!b.failed);
	CHECK_INT(doc_parse((const char *)b.data, b.len, "many.edaha", &d, &err), -EINVAL);
	CHECK(strstr(err.msg, "points in all") != NULL);
	/* and as many as fit read */
	CHECK(gen_count_branches(&p) + gen_count_leaves(&p) == 4095 + 2048 * 6);
	buf_reset(&b);
	n = DOC_MAX_POINTS / (4095 + 2048 * 6);
	buf_printf(&b, "edaha-drawing 5\nseed 1\nhistory %zu %zu\n", n, n);
	for (size_t i = 0; i < n; i++)
		buf_printf(&b, "generate %zu 1 %zu %.*s\n", i, i, (int)line.len, (const char *)line.data);
	buf_printf(&b, "end\n");
	CHECK_INT(doc_parse((const char *)b.data, b.len, "fits.edaha", &d, &err), 0);
	CHECK_INT(d.nops, n);
	doc_finish(&d);
	buf_finish(&b);
	buf_finish(&line);
}

/* The extent of a tree's leaves: up (y) and across (x). */
static void leaf_extent(const struct tree *t, double *height, double *width)
{
	double lo[2] = { INFINITY, INFINITY }, hi[2] = { -INFINITY, -INFINITY };

	for (size_t i = 0; i < t->nleaves; i++)
		for (size_t k = 0; k < t->leaves[i].npoints; k++) {
			double v[2] = { t->leaves[i].points[k].y, t->leaves[i].points[k].x };

			for (int j = 0; j < 2; j++) {
				lo[j] = fmin(lo[j], v[j]);
				hi[j] = fmax(hi[j], v[j]);
			}
		}
	*height = hi[0] - lo[0];
	*width = hi[1] - lo[1];
}

/*
 * The parameter buttons on a shrub (issue 24): its shape decides its crown, so taller and
 * wider make the crown itself taller and wider by about their step (1.15), shorter and
 * narrower smaller, leafier and barer change its leaves; more and fewer change how many
 * tips it has, or are refused where its shape already decides that (then drawn faded).
 */
static void test_shrub_buttons(void)
{
	static const enum button templates[] = { BUTTON_TPL_HEDGE, BUTTON_TPL_BALL, BUTTON_TPL_CONE };
	static const struct {
		enum button b;
		double height, width, leaves; /* the least (> 1) or most (< 1) ratio to before */
	} effects[] = {
		{ BUTTON_GEN_TALLER, 1.1, 0, 0 },    { BUTTON_GEN_SHORTER, 1 / 1.1, 0, 0 },
		{ BUTTON_GEN_WIDER, 0, 1.1, 0 },     { BUTTON_GEN_NARROWER, 0, 1 / 1.1, 0 },
		{ BUTTON_GEN_LEAFIER, 0, 0, 1.25 },  { BUTTON_GEN_BARER, 0, 0, 1 / 1.25 },
	};

	for (size_t k = 0; k < sizeof(templates) / sizeof(*templates); k++) {
		struct app *app = app_create(1280, 800, 13);
		double h0, w0, h, w;
		size_t n0, nops;

		CHECK(app);
		pen_button(&pen, app, templates[k]);
		CHECK(params_of(app) && params_of(app)->type == GEN_SHRUB);
		leaf_extent(&app->tree, &h0, &w0);
		n0 = app->tree.nleaves;
		for (size_t e = 0; e < sizeof(effects) / sizeof(*effects); e++) {
			CHECK(app_gen_possible(app, effects[e].b));
			pen_button(&pen, app, effects[e].b);
			leaf_extent(&app->tree, &h, &w);
			printf("%s: %-12s height %.3f -> %.3f m, width %.3f -> %.3f m, leaves %zu -> %zu\n",
			       gen_preset_name((enum gen_preset)(templates[k] - BUTTON_TPL_CHERRY)),
			       button_name(effects[e].b), h0, h, w0, w, n0, app->tree.nleaves);
			if (effects[e].height)
				CHECK(effects[e].height > 1 ? h >= h0 * effects[e].height : h <= h0 * effects[e].height);
			if (effects[e].width)
				CHECK(effects[e].width > 1 ? w >= w0 * effects[e].width : w <= w0 * effects[e].width);
			if (effects[e].leaves)
				CHECK(effects[e].leaves > 1 ? app->tree.nleaves >= n0 * effects[e].leaves
							    : app->tree.nleaves <= n0 * effects[e].leaves);
			pen_button(&pen, app, BUTTON_UNDO);
			CHECK_INT(app->tree.nleaves, n0);
		}
		/* fewer, down to where the shape decides the tips: then refused, and nothing done */
		while (app_gen_possible(app, BUTTON_GEN_FEWER)) {
			size_t before = app->tree.nbranches;

			pen_button(&pen, app, BUTTON_GEN_FEWER);
			CHECK(app->tree.nbranches < before);
		}
		nops = app->doc.nops;
		pen_button(&pen, app, BUTTON_GEN_FEWER);
		CHECK(app->doc.nops == nops);
		CHECK(params_of(app)->levels > 1);
		CHECK(app_gen_possible(app, BUTTON_GEN_MORE));
		app_destroy(app);
	}
}

int main(void)
{
	test_weight();
	test_new_strip();
	test_parameter_buttons();
	test_season();
	test_drawing();
	test_shrub_buttons();
	return 0;
}
