/* SPDX-License-Identifier: MIT */
#pragma once

#include <stdbool.h>
#include <stddef.h>

#include "mesh.h"
#include "season.h"
#include "tree.h"

/*
 * The season's colour of every vertex of a tree's leaves mesh (the renderer's merged
 * leaves, the exporters): each leaf's part (mk, tree_mesh_marks) takes its leaf's palette
 * entry (season_leaf_color). rgb gets 3 floats a vertex, nvertices of them. Where mk does
 * not describe the mesh (a mark unknown), every vertex takes the palette's first colour.
 * Winter has no palette: false, rgb untouched (its leaves are not shown).
 */
bool leaf_colors_fill(const struct tree *t, const struct tree_mesh_marks *mk, size_t nvertices,
		      float *rgb);
/* Whether the season gives the leaves more than one colour (spring, autumn): then they
 * need colours of their own; in summer one material colour does. */
bool leaf_colors_vary(enum season s);
