/* SPDX-License-Identifier: MIT */
/*
 * The app's tables are complete and agree with each other (issue 25): every op kind of
 * doc.h has a row (app_ops.c) that applies it; every mode a row (app_modes.c) whose
 * button maps back to it, and every bar button that enters a mode is that mode's; every
 * template of the New strip (app_mode_new.c) is the button of its name, has a picture,
 * and is on the strip in its order; the hooks that follow the ops each have both halves.
 * Then seeded random button presses: the mode a press leaves on is the pressed button's,
 * and the lit button (the screen's and the LEDs') is the mode's.
 */
#include <string.h>

#include "app.h"
#include "app_mode.h"
#include "app_private.h"
#include "batch.h"
#include "icons.h"
#include "layout.h"
#include "pen.h"
#include "rng.h"
#include "test.h"

static struct pen pen = { .now_us = 1000, .steps = 10, .pause_us = PEN_PAUSE_US };

/* doc.h's kinds. doc.h has no count: -Wswitch (an error in this build) names a kind added
 * there and not here, and then the row check below wants its row. */
static bool op_kind_listed(enum doc_op_kind k)
{
	switch (k) {
	case DOC_OP_STROKE:
	case DOC_OP_NEW:
	case DOC_OP_LIFT:
	case DOC_OP_CLONE_ADD:
	case DOC_OP_CLONE_REMOVE:
	case DOC_OP_ARRANGE:
	case DOC_OP_PROPAGATE:
	case DOC_OP_GENERATE:
	case DOC_OP_SEASON:
	case DOC_OP_LEAFTYPE:
	case DOC_OP_VINE:
	case DOC_OP_GROW:
	case DOC_OP_IMPORT:
		return true;
	}
	return false;
}

static void test_op_rows(void)
{
	int n = 0;

	/* the kinds are 0, 1, ...: the first not listed is past the last */
	while (op_kind_listed((enum doc_op_kind)n))
		n++;
	CHECK(n > DOC_OP_STROKE);
	for (int k = 0; k < n; k++) {
		const struct app_op_kind *row = app_op_kind((enum doc_op_kind)k);

		if (!row->apply)
			fprintf(stderr, "op kind %d has no row in app_ops.c\n", k);
		CHECK(row->apply);
		/* a setting or a press changes no branch: the wood stays */
		CHECK(!row->setting_only || row->keeps_wood);
		CHECK(!row->swells || row->keeps_wood);
		/* every leaf new: little of the tree before is left */
		CHECK(!row->new_leaves || row->replaces_tree);
	}
	/* past the last kind: applied as nothing */
	CHECK(!app_op_kind((enum doc_op_kind)n)->apply);
	printf("op kinds: %d, each with a row\n", n);
}

static void test_hooks(void)
{
	const struct app_op_hook *const *hooks;
	size_t n = app_op_hooks(&hooks);

	CHECK(n >= 3); /* unfolding, wood, vines */
	for (size_t i = 0; i < n; i++) {
		CHECK(hooks[i] && hooks[i]->name && hooks[i]->after_op && hooks[i]->clear);
		for (size_t j = 0; j < i; j++)
			CHECK(strcmp(hooks[i]->name, hooks[j]->name) != 0);
	}
	printf("after-op hooks: %zu\n", n);
}

static void test_mode_rows(void)
{
	enum app_mode back;

	for (int m = 0; m < APP_MODE_COUNT; m++) {
		const struct app_mode_ops *ops = app_mode_ops((enum app_mode)m);

		if (!ops)
			fprintf(stderr, "mode %d has no row in app_modes.c\n", m);
		CHECK(ops);
		CHECK_INT(ops->mode, m);
		CHECK_INT(app_mode_button((enum app_mode)m), ops->button);
		/* a lit mode has a button to light */
		CHECK(!ops->lit || ops->button != BUTTON_COUNT);
		if (ops->button == BUTTON_COUNT)
			continue;
		CHECK(app_mode_for_button(ops->button, &back));
		CHECK_INT(back, m); /* no two modes share a button */
	}
	/* sketching is where the others leave to: no button enters it */
	CHECK_INT(app_mode_button(APP_MODE_SKETCH), BUTTON_COUNT);
	for (int b = 0; b <= BUTTON_COUNT; b++) {
		if (!app_mode_for_button((enum button)b, &back))
			continue;
		CHECK(b != BUTTON_COUNT);
		CHECK_INT(app_mode_button(back), b);
	}
}

/* A 3D tree of a trunk and two limbs, a little different for each seed. */
static struct app *drawn_tree(uint64_t seed)
{
	struct app *app = app_create(1280, 800, seed);
	struct rng r;
	double dx;

	CHECK(app);
	rng_seed(&r, seed);
	dx = (double)(rng_next(&r) % 81) - 40.0;
	pen_line(&pen, app, 640, 736, 640 + dx, 236);
	pen_line(&pen, app, 640 + 0.4 * dx, 536, 880, 400 + dx);
	pen_line(&pen, app, 640 + 0.5 * dx, 480, 410, 350 - dx);
	pen_button(&pen, app, BUTTON_3D);
	CHECK(app->tree.lifted);
	CHECK_INT(app->failed, 0);
	return app;
}

/* The lit button as the renderer and the kiosk worked it out before the mode table. */
static enum button lit_before(const struct app *app)
{
	switch (app->mode) {
	case APP_MODE_CLONE:
		return BUTTON_CLONE;
	case APP_MODE_LEAF:
		return BUTTON_LEAF;
	case APP_MODE_PROPAGATE:
		return BUTTON_PROPAGATE;
	case APP_MODE_VINE:
		return BUTTON_VINE;
	default:
		return app->tree.lifted ? BUTTON_3D : BUTTON_COUNT;
	}
}

/* Every bar button that enters a mode, on a 3D tree, is that mode's; every mode with a
 * button is entered by it; the lit button is then the mode's. */
static void test_bar_buttons(void)
{
	struct app *probe = app_create(1280, 800, 1);
	struct layout_button bar[LAYOUT_NBUTTONS];
	size_t n;
	int entered = 0;
	bool seen[APP_MODE_COUNT] = { false };

	CHECK(probe);
	n = layout_buttons(&probe->screen, bar, LAYOUT_NBUTTONS);
	CHECK(n > 0);
	for (size_t i = 0; i < n; i++) {
		struct app *app = drawn_tree(7);
		enum app_mode m;

		pen_button(&pen, app, bar[i].button);
		CHECK_INT(app->failed, 0);
		CHECK_INT(app_lit_button(app), lit_before(app));
		if (app->mode == APP_MODE_SKETCH) {
			/* a button that enters a mode when pressed on a 3D tree did */
			CHECK(!app_mode_for_button(bar[i].button, &m));
			app_destroy(app);
			continue;
		}
		if (!app_mode_for_button(bar[i].button, &m))
			fprintf(stderr, "bar button %s entered mode %d and is no mode's\n",
				button_name(bar[i].button), (int)app->mode);
		CHECK(app_mode_for_button(bar[i].button, &m));
		CHECK_INT(m, app->mode);
		seen[m] = true;
		entered++;
		app_destroy(app);
	}
	/* every mode but sketching is entered from the bar */
	for (int m = 0; m < APP_MODE_COUNT; m++)
		CHECK(seen[m] == (m != APP_MODE_SKETCH));
	app_destroy(probe);
	printf("bar buttons: %zu, %d entering a mode\n", n, entered);
}

static bool starts_with(const char *s, const char *prefix)
{
	return strncmp(s, prefix, strlen(prefix)) == 0;
}

static void test_templates(void)
{
	struct app *app = drawn_tree(3);
	struct app_side_item items[APP_SIDE_MAX];
	int presets[GEN_PRESET_COUNT] = { 0 };
	struct batch b;
	size_t n;

	batch_init(&b);
	CHECK_INT(app_templates_build(app), 0);
	for (size_t i = 0; i < APP_TEMPLATE_COUNT; i++) {
		const struct app_template *tpl = &app_templates[i];
		char name[64];

		CHECK(app_template_of(tpl->button) == tpl);
		/* its button is the one named after it (traces and --press say tpl-NAME) */
		CHECK(tpl->name);
		snprintf(name, sizeof(name), "tpl-%s", tpl->name);
		if (strcmp(button_name(tpl->button), name) != 0)
			fprintf(stderr, "template %zu: %s is button %s\n", i, name,
				button_name(tpl->button));
		CHECK(strcmp(button_name(tpl->button), name) == 0);
		CHECK(tpl->preset >= -1 && tpl->preset < GEN_PRESET_COUNT);
		if (tpl->preset >= 0) {
			CHECK(strcmp(tpl->name, gen_preset_name((enum gen_preset)tpl->preset)) == 0);
			presets[tpl->preset]++;
		}
		/* its picture: the drawn icon, or its preset's tree */
		batch_reset(&b);
		icon_draw(&b, tpl->button, (struct pt){ 50.0, 50.0 }, 40.0,
			  (struct rgba){ 0.0f, 0.0f, 0.0f, 1.0f }, (struct rgba){ 1.0f, 1.0f, 1.0f, 1.0f });
		CHECK(!b.failed);
		switch (tpl->picture) {
		case APP_TEMPLATE_SHEET:
			CHECK(b.nvertices > 0);
			break;
		case APP_TEMPLATE_TREE:
			CHECK(tpl->preset >= 0);
			CHECK(b.nvertices == 0); /* no icon over the tree */
			CHECK(app->templates[tpl->preset].bark.nvertices > 0);
			break;
		}
	}
	/* every preset is a template, once */
	for (int p = 0; p < GEN_PRESET_COUNT; p++)
		CHECK_INT(presets[p], 1);
	/* every button named as a template is one */
	for (int k = 0; k < BUTTON_COUNT; k++)
		if (starts_with(button_name((enum button)k), "tpl-"))
			CHECK(app_template_of((enum button)k));
	/* the New strip shows them, in order, each tree with its picture */
	pen_button(&pen, app, BUTTON_NEW);
	CHECK_INT(app->mode, APP_MODE_NEW);
	n = app_side_items(app, items);
	CHECK_INT(n, APP_TEMPLATE_COUNT);
	for (size_t i = 0; i < n; i++) {
		const struct app_template *tpl = &app_templates[i];

		CHECK_INT(items[i].button, tpl->button);
		CHECK(items[i].template == (tpl->picture == APP_TEMPLATE_TREE));
		CHECK(!items[i].preview == (tpl->picture != APP_TEMPLATE_TREE));
	}
	batch_finish(&b);
	app_destroy(app);
	printf("templates: %d, every preset once\n", APP_TEMPLATE_COUNT);
}

/*
 * Seeded random presses of the bar's buttons and the blank template: after each, the
 * mode is sketching, the one the pressed button enters, or the one it was in (a press
 * that leaves the mode alone); the lit button is the mode's, as it was worked out before
 * the mode table.
 */
static void test_random_presses(void)
{
	static const enum button pool[] = {
		BUTTON_3D,   BUTTON_CLONE, BUTTON_LEAF, BUTTON_PROPAGATE, BUTTON_SEASON,
		BUTTON_VINE, BUTTON_UNDO,  BUTTON_REDO, BUTTON_NEW,       BUTTON_TPL_BLANK,
	};
	int cases = test_cases(200), presses = 0, entered = 0;

	for (int c = 0; c < cases; c++) {
		struct app *app = drawn_tree(1000 + (uint64_t)c);
		struct rng r;

		rng_seed(&r, 0x7ab1e5 + (uint64_t)c);
		for (int i = 0; i < 12; i++) {
			enum button b = pool[rng_next(&r) % (sizeof(pool) / sizeof(*pool))];
			enum app_mode was = app->mode, m;

			pen_button(&pen, app, b);
			CHECK_INT(app->failed, 0);
			presses++;
			if (app_mode_for_button(b, &m) && app->mode == m && m != was)
				entered++;
			CHECK(app->mode == APP_MODE_SKETCH || app->mode == was ||
			      (app_mode_for_button(b, &m) && app->mode == m));
			CHECK_INT(app_lit_button(app), lit_before(app));
		}
		app_destroy(app);
	}
	printf("random presses: %d cases, %d presses, %d entering a mode, lit button as before "
	       "after every one\n", cases, presses, entered);
}

int main(void)
{
	test_op_rows();
	test_hooks();
	test_mode_rows();
	test_bar_buttons();
	test_templates();
	test_random_presses();
	return 0;
}
