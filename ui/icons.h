/* SPDX-License-Identifier: MIT */
#pragma once

#include "batch.h"
#include "event.h"
#include "season.h"

/*
 * The pictures on the on-screen buttons, made of triangles (the words under them are text.c's):
 * 3d a cube, clone a branch with a plus, leaf a leaf, propagate a fan of arrows,
 * undo/redo curved arrows, new a blank sheet, export an arrow into a USB stick, view a
 * tree on a turntable, fixed-count/fixed-size twigs with leaves, season the sun (see
 * icon_draw_season); the parameter pairs: branches with a plus or minus badge, a tree
 * with arrows out or in (wider, narrower), up or down (taller, shorter), a leaf with a
 * badge. The New strip's cards as their template's row says (app_templates[]): the blank
 * one a sheet and a pencil, a preset's none (its picture is the tree).
 * `ink` draws the picture; `bg` is the button behind it, used for cut-outs.
 */
void icon_draw(struct batch *b, enum button button, struct pt centre, double size,
	       struct rgba ink, struct rgba bg);
/* The season button's picture for the tree's season: a cherry blossom, the sun, a maple
 * leaf, a snowflake. */
void icon_draw_season(struct batch *b, enum season season, struct pt centre, double size,
		      struct rgba ink, struct rgba bg);
