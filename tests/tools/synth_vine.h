/* SPDX-License-Identifier: MIT */
#pragma once

#include <stddef.h>

#include "tree.h"
#include "vine.h"

/*
 * A tree with vines for the export tests and samples: a lifted vertical trunk of
 * SYNTH_VINE_HEIGHT metres and radius SYNTH_VINE_RADIUS from the origin, one leaf at its
 * top, and nvines (at most SYNTH_VINE_MAX) vines grown to their ends on its bark as the
 * kiosk grows them (app_vine.c): the first the default vine planted at +x, the second a
 * right-twining one with opposite leaves at +z. Clears t (initialised) first. Same
 * arguments, same tree. 0, -EINVAL (too many) or -ENOMEM.
 */
#define SYNTH_VINE_HEIGHT 3.0
#define SYNTH_VINE_RADIUS 0.2
#define SYNTH_VINE_MAX 2
int synth_vine_tree(struct tree *t, size_t nvines);
/* The parameters and planting point synth_vine_tree gives vine i. */
void synth_vine_params(size_t i, struct vine_params *p, struct vec3 *plant);
