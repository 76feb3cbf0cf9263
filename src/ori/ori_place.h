/* SPDX-License-Identifier: MIT */
#pragma once

#include <stddef.h>

#include "ori_kinds.h"
#include "vec.h"

/*
 * Where an origami leaf goes in place of an outline (a drawn leaf copied by arrangement or
 * propagation, a generated leaf): its base O at the outline's point nearest `attach` (the
 * branch point it hangs from), the design's +y from there to the outline's farthest
 * point, whose distance is the leaf's length (the midrib is scaled to it), and +z along
 * the outline's Newell normal (made square to the axis). 0 and xf (ori_kinds.h), or
 * -EINVAL when the outline has no such frame (fewer than 3 points, not finite, no
 * length, no area, or a normal along the axis).
 */
int ori_place(const struct ori_kind *k, const struct vec3 *outline, size_t n,
	      struct vec3 attach, double xf[12]);

/*
 * The new outline of a leaf of kind `kind` placed in place of `outline`: *out (allocated,
 * the caller frees) holds *nout points. 0, -EINVAL (no frame, or no such kind: *out
 * NULL, the caller keeps the outline), or -ENOMEM.
 */
int ori_place_outline(int kind, const struct vec3 *outline, size_t n, struct vec3 attach,
		      struct vec3 **out, size_t *nout);

struct tree;
/*
 * Makes leaf i of t an origami leaf of `kind` in place of its outline (attached where its
 * branch point is), its `local` recorded again (tree_leaf_attach). A leaf already of that
 * kind, a kind < 0, or an outline with no frame stay as they are. 0 or -ENOMEM (the leaf
 * unchanged).
 */
int ori_place_leaf(struct tree *t, size_t i, int kind);
