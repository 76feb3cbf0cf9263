/* SPDX-License-Identifier: MIT */
#pragma once

/*
 * What the app's files share: app.c (events, the document, the sketch), app_ops.c (each
 * op kind's row, the hooks that follow the ops), app_modes.c (the modes' table) and
 * app_camera.c (the orbit camera, on-screen hits). Not for the app's users.
 */
#include "app.h"

/* The pen can report positions off the screen (and traces any finite number): what is
 * drawn is what lands on the screen. */
static inline double app_clamp(double v, double lo, double hi)
{
	return v < lo ? lo : v > hi ? hi : v;
}

/* app_ops.c: one row a kind of op (doc.h's enum doc_op_kind). */
struct app_op_kind {
	/* Applies the op to app->tree and app->rng: SKETCH_GREW (it only appended, or
	 * changed no element), SKETCH_CHANGED, or < 0 (half of it may have been made). */
	int (*apply)(struct app *app, const struct doc_op *op);
	/* The tree keeps its wood after it whatever it did (its branches stay as they
	 * were); otherwise only when it only appended. */
	bool keeps_wood;
	/* It changes elements in place outside tree.c and tree_edit.c: its delta is taken by
	 * comparing with a copy of the tree before, not from the journal (app_history.c). */
	bool edits_in_place;
	/* Little or nothing of the tree before is left: a replay keeps the meshes before it
	 * in its delta, so that undoing it needs no meshing (app_history.c). */
	bool replaces_tree;
	/* It changes a setting, no element (the season, the next leaf's kind): a generated
	 * tree stays the generated one (app_generated). */
	bool setting_only;
	/* Every leaf after it is new (a generated tree): all of them unfold. */
	bool new_leaves;
	/* Its bark swells on screen (a grow press). */
	bool swells;
	/* The tree becomes 3D by it: it grows in on screen (app_live.c). */
	bool grows_in;
};
/* The row of kind; a kind without one applies as nothing (apply NULL). */
const struct app_op_kind *app_op_kind(enum doc_op_kind kind);

/* The tree before an op, for the hooks. */
struct app_op_before {
	size_t nbranches, nleaves, nvines;
};
/* A system that follows the ops on screen (each in its own file). */
struct app_op_hook {
	const char *name;
	/* After op (the document's copy) was applied and its meshes made (meshed: 0 or the
	 * meshing's negative errno). 0 or a negative errno. */
	int (*after_op)(struct app *app, const struct doc_op *op,
			const struct app_op_before *before, int meshed);
	/* The tree changed otherwise (undo, redo, a load, a tree shown): what it showed of
	 * the last ops goes. */
	void (*clear)(struct app *app);
};
extern const struct app_op_hook app_unfold_hook;
extern const struct app_op_hook app_wood_hook;
extern const struct app_op_hook app_vine_hook;
extern const struct app_op_hook app_live_hook;
/* The hooks, in the order they run: how many, and the list in *out. */
size_t app_op_hooks(const struct app_op_hook *const **out);
/* Every hook's after_op: meshed, or the first hook's failure. */
int app_op_hooks_after(struct app *app, const struct doc_op *op,
		       const struct app_op_before *before, int meshed);
/* Every hook's clear. */
void app_op_hooks_clear(struct app *app);

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
int app_undo(struct app *app);
int app_redo(struct app *app);

/* app_live.c: set up (grow_in on) and freed with the app; the skeleton and wind brought
 * in step with the meshes while anything lives (0 or -ENOMEM: then nothing moves); a
 * growth of the tree as it is from time_us (none unless 3D and grow_in); a loaded
 * drawing's growth (its last vine to climb after it); an input that finishes a growth (a
 * pen tip or a button put down), taken before the app handles it. */
void app_live_init(struct app *app);
void app_live_finish(struct app *app);
int app_live_sync(struct app *app);
int app_live_grow_start(struct app *app, uint64_t time_us);
int app_live_loaded(struct app *app);
/* The loaded drawing's last vine starts climbing once its growth ended by now_us (the
 * settled view, UINT64_MAX, or a growth finished early: it shows grown); called before the
 * vines advance. 0 or -ENOMEM. */
int app_live_vines(struct app *app, uint64_t now_us);
void app_live_input(struct app *app, const struct event *ev);

/* app_unfold.c: new origami leaves unfolding, noted by app_unfold_hook; clear: the tree
 * changed otherwise (undo, redo, load). */
void app_unfold_clear(struct app *app);

/* Each op kind's apply (app_op_kind's), in its system's file. */
/* app_mode_sketch.c */
int app_stroke_apply(struct app *app, const struct doc_op *op);
int app_lift_apply(struct app *app, const struct doc_op *op);
/* app_mode_new.c */
int app_new_apply(struct app *app, const struct doc_op *op);
/* app_mode_clone.c */
int app_clone_add_apply(struct app *app, const struct doc_op *op);
int app_clone_remove_apply(struct app *app, const struct doc_op *op);
/* app_mode_leaf.c */
int app_arrange_apply(struct app *app, const struct doc_op *op);
int app_leaftype_apply(struct app *app, const struct doc_op *op);
/* app_mode_propagate.c */
int app_propagate_apply(struct app *app, const struct doc_op *op);
/* app_generate.c */
int app_generate_apply(struct app *app, const struct doc_op *op);
int app_season_apply(struct app *app, const struct doc_op *op);

/* app_modes.c */
int app_push_edit(struct app *app, enum doc_op_kind kind, int branch, int pattern,
		  uint64_t time_us);
int app_refresh_mode_state(struct app *app);
int app_mode_stroke(struct app *app, double len, bool *taken);
int app_set_mode(struct app *app, enum app_mode mode, uint64_t time_us);
int app_mode_press(struct app *app, enum app_mode mode, uint64_t time_us);
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

/* app_generate.c: a template's tap, and the season and parameter buttons. */
struct app_template;
int app_press_template(struct app *app, const struct app_template *tpl, uint64_t time_us);
int app_press_functional(struct app *app, enum button b, uint64_t time_us);

/* app_vine.c: the vine op applied to the app's tree (SKETCH_GREW when it grew nothing,
 * CHANGED, or < 0; on the tap's index of the bark when the op is the tap's), and the index
 * of t's bark a vine climbs (0, -EINVAL: no bark, -ENOMEM). */
int app_vine_apply(struct app *app, const struct doc_op *op);
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
int app_import_apply(struct app *app, const struct doc_op *op);
bool app_op_keeps_wood(enum doc_op_kind kind, int result);
/* The grow button. 0 or a negative errno. */
int app_grow(struct app *app, uint64_t time_us);

/* app_camera.c */
void app_camera_store(struct app *app, struct camera c);
void app_camera_follow_tree(struct app *app);
bool app_ui_hit(const struct app *app, double x, double y, enum button *button);
void app_orbit_to(struct app *app, const struct event *ev);
