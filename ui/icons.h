/* SPDX-License-Identifier: MIT */
#pragma once

#include "batch.h"
#include "event.h"

/*
 * The pictures on the on-screen buttons, made of triangles (the words under them are text.c's):
 * 3d a cube, clone a branch with a plus, leaf a leaf, propagate a fan of arrows,
 * undo/redo curved arrows, new a blank sheet, export an arrow into a USB stick, view a
 * tree on a turntable, fixed-count/fixed-size twigs with leaves.
 * `ink` draws the picture; `bg` is the button behind it, used for cut-outs.
 */
void icon_draw(struct batch *b, enum button button, struct pt centre, double size,
	       struct rgba ink, struct rgba bg);
