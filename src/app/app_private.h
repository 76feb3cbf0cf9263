/* SPDX-License-Identifier: MIT */
#pragma once

/*
 * What the app's files share: app.c (events, the document, the sketch), app_modes.c
 * (clone, leaf and propagate modes) and app_view.c (the orbit camera, on-screen hits).
 * Not for the app's users.
 */
#include "app.h"

/* The pen can report positions off the screen (and traces any finite number): what is
 * drawn is what lands on the screen. */
static inline double app_clamp(double v, double lo, double hi)
{
	return v < lo ? lo : v > hi ? hi : v;
}

/* app.c */
/* Records an edit and applies it on top of the current tree. 0, -ENOMEM, -ENOSPC. */
int app_push_op(struct app *app, struct doc_op *op);
/* Applies one op to the tree and generator: SKETCH_GREW, SKETCH_CHANGED or < 0. */
int app_apply_op(struct app *app, const struct doc_op *op);
int app_press_button(struct app *app, enum button button, uint64_t time_us);

/* app_history.c */
/* app_apply_op of ops[k - 1], the result recorded as state k (history.h), with its
 * delta. */
int app_apply_recorded(struct app *app, size_t k);
/* The meshes after the op at the cursor was applied (applied: its SKETCH_GREW/CHANGED) on
 * a tree of nb branches and nl leaves: only what it changed is meshed. 0 or -ENOMEM. */
int app_mesh_after_op(struct app *app, size_t nb, size_t nl, int applied);
/* After doc_undo / doc_redo: the tree, generator and meshes of the cursor's state. 0 or
 * -ENOMEM. */
/* New origami leaves unfolding (app_unfold.c): an edit added leaves [first, ...) at
 * time_us; clear: the tree changed otherwise (undo, redo, load). */
void app_unfold_note(struct app *app, size_t first, uint64_t time_us);
void app_unfold_clear(struct app *app);
int app_undo(struct app *app);
int app_redo(struct app *app);

/* app_modes.c */
int app_push_edit(struct app *app, enum doc_op_kind kind, int branch, int pattern,
		  uint64_t time_us);
int app_refresh_mode_state(struct app *app);
int app_mode_stroke(struct app *app, double len, bool *taken);
int app_set_mode(struct app *app, enum app_mode mode, uint64_t time_us);
struct app_side_item;
int app_side_tap(struct app *app, const struct app_side_item *item, uint64_t time_us);
bool app_has_child_branch(const struct tree *t, int b);
bool app_has_leaf(const struct tree *t, int b);
/* The branch shown within `within` metres of view-space point p, or -1. */
int app_branch_near(const struct app *app, struct vec3 p, double within);
/* Point i of the stroke under the pen, in view space. */
struct vec3 app_stroke_point(const struct app *app, size_t i);

/* app_mode_leaf.c */
void app_clear_suggestions(struct app *app);
int app_update_suggestions(struct app *app, int b);

/* app_mode_new.c: the templates' thumbnails, made once. 0 or -ENOMEM. */
int app_templates_build(struct app *app);

/* app_generate.c: the season, template and parameter buttons. */
int app_press_functional(struct app *app, enum button b, uint64_t time_us);

/* app_vine.c: the vine op applied to t (SKETCH_GREW when it grew nothing, CHANGED, or
 * < 0) on bark, the index of t's bark (NULL: made here), and the index of t's bark a vine
 * climbs (0, -EINVAL: no bark, -ENOMEM). */
int app_vine_apply(struct tree *t, const struct doc_op *op, const struct vine_support *bark);
struct vine_support;
int app_vine_support(const struct tree *t, struct vine_support **out);
/* The vine op just applied (the tree's last vine) starts growing on screen; the one
 * growing before shows grown. 0 or -ENOMEM. */
int app_vine_growth_start(struct app *app, const struct doc_op *op);
/* No vine grows on screen any more (undo, redo, a new drawing). */
void app_vine_growth_clear(struct app *app);
/* The vines' meshes in step with the tree's (mesh_serial) and the growth. 0 or -ENOMEM. */
int app_vines_refresh(struct app *app);
/* app_mode_vine.c: where a tap at view-space point p plants a vine, with its parameters
 * scaled to the tree: 1 and *op filled (kind, plant, vine allocated) and *bark the index of
 * the tree's bark it built (the caller's; may be NULL), 0 when the tap is too far from the
 * tree's foot, or -ENOMEM. */
int app_vine_plan(const struct app *app, struct vec3 p, uint64_t time_us, struct doc_op *op,
		  struct vine_support **bark);

/* app_wood.c: a grow op (a press; one grown off the loop, lent, is swapped in) and an
 * import op applied to the app's tree (SKETCH_* or < 0); and
 * whether the tree keeps its wood after an op of this kind gave this result. */
int app_wood_apply(struct app *app, const struct doc_op *op);
int app_import_apply(struct tree *t, const struct doc_op *op);
bool app_op_keeps_wood(enum doc_op_kind kind, int result);
/* The grow button. 0 or a negative errno. */
int app_grow(struct app *app, uint64_t time_us);

/* app_view.c */
void app_camera_store(struct app *app, struct camera c);
void app_camera_follow_tree(struct app *app);
bool app_ui_hit(const struct app *app, double x, double y, enum button *button);
void app_orbit_to(struct app *app, const struct event *ev);
