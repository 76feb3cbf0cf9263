/* SPDX-License-Identifier: MIT */
#pragma once

#include <stdbool.h>

#include "mesh_buffer.h"
#include "tree.h"

/* Two results compared for tests (test.h's CHECKs). */
/* The same vertices, normals and indices, bit for bit. */
void same_mesh(const struct mesh *a, const struct mesh *b);
/* The same, as a question (an empty mesh may hold no arrays at all). */
bool mesh_bytes_equal(const struct mesh *a, const struct mesh *b);
/* A mesh's bounding box, for tests of extents. */
struct box {
	double lo[3], hi[3];
};
void box_empty(struct box *b);
/* Grows b to m's vertices (m may be NULL: nothing). */
void box_add(struct box *b, const struct mesh *m);
/* Finite positions and normals, indices in range, whole triangles. */
void check_mesh_sane(const struct mesh *m);
/* The same tree: every field of its branches and leaves, its wood and its vines. */
void same_tree(const struct tree *a, const struct tree *b);
