/* SPDX-License-Identifier: MIT */
#pragma once

#include "mesh_buffer.h"
#include "tree.h"

/* Two results compared for tests (test.h's CHECKs). */
/* The same vertices, normals and indices, bit for bit. */
void same_mesh(const struct mesh *a, const struct mesh *b);
/* The same tree: every field of its branches and leaves, its wood and its vines. */
void same_tree(const struct tree *a, const struct tree *b);
