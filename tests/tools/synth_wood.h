/* SPDX-License-Identifier: MIT */
#pragma once

#include <stddef.h>

#include "tree.h"

/*
 * A tree with growing wood for the export tests and samples: a lifted vertical trunk of
 * 1 m and radius 0.08 m from the origin, a limb leaning out of it at 0.6 (radius 0.05 to
 * 0.04) and two thin twigs (radius 6 mm: too thin for the 64 grid), one on the limb, one
 * on the trunk, and a leaf at each twig's tip. With presses > 0 it is grown as the kiosk
 * grows it (app_wood_apply): the default settings in `mode` (0: conifer, 1: broadleaf,
 * enum wood_mode), the power law and then `presses` presses; the trunk and the limb are
 * then voxelised (t->wood), the twigs not. Clears t (initialised) first. Same arguments,
 * same tree. 0, -EINVAL (presses < 0) or -ENOMEM.
 */
#define SYNTH_WOOD_BRANCHES 4
int synth_wood_tree(struct tree *t, int presses, int mode);
