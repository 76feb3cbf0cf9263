/* SPDX-License-Identifier: MIT */
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "tree.h"

/* An indexed triangle list; positions in world metres (y up), unit normals. */
struct mesh {
	float *positions; /* 3 per vertex */
	float *normals;   /* 3 per vertex */
	size_t nvertices, cap_vertices;
	uint32_t *indices; /* 3 per triangle, counter-clockwise seen from outside */
	size_t nindices, cap_indices;
};

void mesh_init(struct mesh *m);
void mesh_finish(struct mesh *m);
void mesh_clear(struct mesh *m);

/* Bark (branches swept as tubes) and leaves (one-sided polygons, drawn double-sided). */
struct tree_mesh {
	struct mesh bark;
	struct mesh leaves;
};

void tree_mesh_init(struct tree_mesh *tm);
void tree_mesh_finish(struct tree_mesh *tm);
/* Rebuilds both meshes from the tree. Returns 0 or -ENOMEM (meshes then empty).
 * Deterministic: elements are laid out in the tree's order. */
int tree_mesh_build(struct tree_mesh *tm, const struct tree *t);
/* Adds branches [first_branch..) and leaves [first_leaf..) to meshes built for the
 * elements before them: the same bytes as a full rebuild, at the cost of the new ones. */
int tree_mesh_append(struct tree_mesh *tm, const struct tree *t, size_t first_branch,
		     size_t first_leaf);
