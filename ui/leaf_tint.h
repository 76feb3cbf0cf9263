/* SPDX-License-Identifier: MIT */
#pragma once

#include <stdbool.h>
#include <stddef.h>

#include "leaf_instances.h"
#include "mesh.h"
#include "season.h"
#include "tree.h"

/*
 * The colours the screen gives a season's leaves (season.h), for the renderer; no GL here.
 *
 * The screen has always drawn summer leaves in its own green, LEAF_TINT_SUMMER_RGB, lighter
 * than the exporters' (season.c's summer palette, numfmt.h): it shows a colour as it is,
 * lit by its own shader. Every palette colour is shown through the curve that takes the
 * one to the other, channel by channel: c^k with k = ln(screen) / ln(palette) of summer's
 * green (0.78, 0.73, 0.78). It keeps 0 and 1 where they are and shades in their order, so
 * blossom and autumn leaves are lightened as summer's always were, and nothing passes 1.
 * Summer itself is drawn with LEAF_TINT_SUMMER_RGB, the very floats it always was.
 */
#define LEAF_TINT_SUMMER_RGB 0.33f, 0.62f, 0.24f

/* A palette colour as the screen shows it. */
void leaf_tint_map(struct season_rgb c, float out[3]);
/*
 * One colour for all of a season's leaves: summer's green, exactly, or the first colour
 * of another season's palette; what pictures too small to tell leaves apart use. False in
 * winter (out untouched).
 */
bool leaf_tint_uniform(enum season s, float out[3]);
/*
 * The screen's colour of every vertex of t's merged leaves mesh (3 floats a vertex, as
 * leaf_colors_fill gives them from the marks mk, mapped). False in winter.
 */
bool leaf_tint_vertices(const struct tree *t, const struct tree_mesh_marks *mk, size_t nvertices,
			float *rgb);
/* The colour of each leaf drawn instanced (li's first li->ninstanced instances), 3 floats
 * each. */
void leaf_tint_instances(const struct tree *t, const struct leaf_instances *li, float *rgb);
/*
 * The colour of every vertex of li->loose (3 floats a vertex): the leaves no instanced
 * shape draws, in leaf order, each as many vertices as its part of t's merged mesh (the
 * marks mk). Where mk does not tell, every vertex takes the palette's first colour (as
 * leaf_colors_fill does). 0, or -ENOMEM.
 */
int leaf_tint_loose(const struct tree *t, const struct tree_mesh_marks *mk,
		    const struct leaf_instances *li, float *rgb);
