/* SPDX-License-Identifier: MIT */
#pragma once

#include "options.h"

/* Runs --headless: load, replay/press in order, render one frame, write the outputs.
 * Returns the process exit status (0, 1 runtime failure, 2 malformed input). */
int headless_run(const struct options *o);

/* Runs --headless --leaf: an origami leaf alone, built, opened, drawn and written to --out
 * (origami.json, leaf.glb, screen.png), or nothing written. Returns the exit status. */
int headless_leaf_run(const struct options *o);

/* Runs --headless --support: a twining vine grown to its end on an OBJ support alone,
 * drawn and written to --out (skeleton.json, model.glb, model.obj, model.mtl, screen.png),
 * or nothing written. Returns the exit status. */
int headless_vine_run(const struct options *o);

/* Runs --headless --forest DIR: today's forest of the drawings in DIR (docs/forest.md),
 * written to --out. Returns the exit status (2: DIR unreadable). */
int headless_forest_run(const struct options *o);
