/* SPDX-License-Identifier: MIT */
#pragma once

#include <stdbool.h>
#include <stddef.h>

#include "mesh.h"
#include "season.h"
#include "tree.h"

/* How the leaves go into the files, by season. */
enum export_look {
	EXPORT_LEAVES_GREEN,   /* summer: each exporter's one leaves material, as before seasons
				* (byte for byte: neither the leaves nor the marks are looked at) */
	EXPORT_LEAVES_COLORED, /* spring, autumn: each leaf its palette entry, by the parts below */
	EXPORT_LEAVES_NONE,    /* winter: no leaves, no leaves material */
};
enum export_look export_look(enum season s);

/*
 * The leaves mesh as the exporters colour it in spring and autumn: in parts, each the
 * mesh of one leaf (tree_mesh_marks) in one entry of the season's palette
 * (season_leaf_color), so the glTF's vertex colours and the OBJ's materials agree with
 * each other and with leaf_colors_fill. Where the marks do not describe the mesh (unknown
 * after an allocation failure, or of another tree), the whole mesh is one part in the
 * palette's first colour, as leaf_colors_fill paints it then: colours go, never a leaf.
 *
 * Parts are found from the marks on each call, nothing is allocated: an export cannot
 * fail for them, and a 30,000-leaf tree costs a hash a leaf per pass.
 */
struct export_leaves {
	const struct tree *tree;
	const struct mesh *mesh;
	const struct tree_mesh_marks *marks; /* NULL: unknown, one part */
	const struct season_rgb *palette;
	size_t ncolors; /* 0 in winter */
};

struct export_leaf_part {
	size_t first_vertex, end_vertex; /* [first, end) of the leaves mesh's vertices */
	size_t first_index, end_index;   /* [first, end) of its indices, whole triangles */
	size_t color;                    /* palette entry */
};

void export_leaves_init(struct export_leaves *el, const struct tree *t, const struct mesh *leaves,
			const struct tree_mesh_marks *mk);
size_t export_leaves_nparts(const struct export_leaves *el);
struct export_leaf_part export_leaves_part(const struct export_leaves *el, size_t i);
/* Bit k set when some part with triangles takes palette entry k. */
unsigned export_leaves_colors_used(const struct export_leaves *el);
