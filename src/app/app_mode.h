/* SPDX-License-Identifier: MIT */
#pragma once

/*
 * A kiosk mode is a small handler behind this interface: the bar button that enters it,
 * what a finished pen stroke means in it, what its side strip (the column at the canvas's
 * left edge) offers, and what a tap there does. app.c and app_modes.c dispatch to the
 * active mode's handler; each mode is its own file (app_mode_*.c) and one row of
 * app_modes.c's table, which is the only place a mode and its button are linked: the
 * renderer lights, and the kiosk's LEDs show, app_lit_button(). Not for the app's users
 * but the renderer and the kiosk, which draw the side strip from app_side_items().
 */
#include "app.h"
#include "layout.h"

/* One place on the side strip: a button, or a card with a picture (a thumbnail). */
struct app_side_item {
	bool thumbnail;
	/* What a tap presses (GPIO and traces press the same); BUTTON_COUNT: the mode's own
	 * use of a tap, `tap` (a leaf arrangement: its pattern). */
	enum button button;
	int tap;
	/* A thumbnail's picture (NULL: an empty card, the blank canvas), seen through the
	 * app's camera, or through APP_TEMPLATE_CAMERA when `template`. */
	const struct tree_mesh *preview;
	bool template;
	bool lit; /* the choice in effect (a propagation pattern) */
};
#define APP_SIDE_MAX 16
/* Templates are shown turned a little, so that they read as 3D trees. */
#define APP_TEMPLATE_YAW_DEG 25.0
#define APP_TEMPLATE_PITCH_DEG 10.0

struct app_mode_ops {
	enum app_mode mode;
	/* The bar button that enters it (app_mode_for_button); BUTTON_COUNT: none (sketching,
	 * where the others leave to). */
	enum button button;
	/* Its button is lit (and its LED) while it is on: an editing mode. Otherwise the 3D
	 * button is, on a 3D tree, as while sketching (the New strip is on the way to a tree,
	 * not a way of working on one). */
	bool lit;
	/* What its button does. NULL: app_set_mode, the editing modes' way (on a 3D tree,
	 * made 3D first; pressed again, back to sketching). */
	int (*press)(struct app *app, uint64_t time_us);
	/* Entering it: 0 or a negative errno (the mode is on either way). NULL: nothing to do. */
	int (*enter)(struct app *app, uint64_t time_us);
	/* A finished pen stroke: *taken when it meant something in this mode (a tap, a
	 * circle); otherwise it is drawn as in sketching. NULL: always drawn. */
	int (*stroke)(struct app *app, double len, bool *taken);
	/* A tap on empty canvas, where a drag turns the camera, is the mode's too: a stroke of
	 * one point (the vine mode's ground). */
	bool taps_on_canvas;
	/* The side strip's items, top to bottom; at most max. NULL: an empty strip. */
	size_t (*side)(const struct app *app, struct app_side_item *out, size_t max);
	/* A tap on an item whose button is BUTTON_COUNT. */
	int (*side_tap)(struct app *app, const struct app_side_item *item, uint64_t time_us);
};

extern const struct app_mode_ops app_mode_sketch_ops;
extern const struct app_mode_ops app_mode_clone_ops;
extern const struct app_mode_ops app_mode_leaf_ops;
extern const struct app_mode_ops app_mode_propagate_ops;
extern const struct app_mode_ops app_mode_new_ops;
extern const struct app_mode_ops app_mode_vine_ops;

const struct app_mode_ops *app_mode_ops(enum app_mode mode);
/* The mode bar button b enters: true and *mode, or false (b is not a mode's). */
bool app_mode_for_button(enum button b, enum app_mode *mode);
/* The bar button that enters mode (BUTTON_COUNT: none). */
enum button app_mode_button(enum app_mode mode);
/* The bar button lit for what the screen shows (its LED on the kiosk): the editing mode's,
 * or while sketching on a 3D tree the 3D one; BUTTON_COUNT: none. */
enum button app_lit_button(const struct app *app);

/*
 * The New strip's templates (app_mode_new.c), top to bottom: the blank canvas, then the
 * presets. The only list of them: the strip, a tap (app_generate.c), the renderer's
 * colour and the icons read it. A new template is a row there (and its button in
 * event.h, its words in ui/labels.c).
 */
enum app_template_picture {
	APP_TEMPLATE_SHEET, /* drawn (ui/icons.c): a blank sheet and a pencil */
	APP_TEMPLATE_TREE,  /* the preset's tree, rendered (app->templates[preset]) */
};
struct app_template {
	enum button button;  /* what a tap presses (GPIO and traces press the same) */
	const char *name;    /* the preset's name (presets/NAME.yaml); the blank canvas's */
	int preset;          /* the enum gen_preset it puts on the canvas; -1: none, it clears */
	enum app_template_picture picture; /* its card's */
};
#define APP_TEMPLATE_COUNT (1 + GEN_PRESET_COUNT)
extern const struct app_template app_templates[APP_TEMPLATE_COUNT];
/* The template button b presses, or NULL. */
const struct app_template *app_template_of(enum button b);

/* What the side strip shows now: the active mode's items. */
size_t app_side_items(const struct app *app, struct app_side_item out[APP_SIDE_MAX]);
/* How the side strip lays out items of this kind (all of a strip's are of one kind). */
enum layout_side_kind app_side_kind(const struct app_side_item *item);
/* The side strip item under (x, y), if any. */
bool app_side_hit(const struct app *app, double x, double y, struct app_side_item *item);
