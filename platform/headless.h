/* SPDX-License-Identifier: MIT */
#pragma once

#include "options.h"

/* Runs --headless: load, replay/press in order, render one frame, write the outputs.
 * Returns the process exit status (0, 1 runtime failure, 2 malformed input). */
int headless_run(const struct options *o);

/* Runs --headless --leaf: an origami leaf alone, built, opened, drawn and written to --out
 * (origami.json, leaf.glb, screen.png), or nothing written. Returns the exit status. */
int headless_leaf_run(const struct options *o);
