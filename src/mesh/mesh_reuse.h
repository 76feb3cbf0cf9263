/* SPDX-License-Identifier: MIT */
#pragma once

#include "mesh.h"
#include "tree.h"

/*
 * Meshing a tree again after an edit that changed a few of its elements (undo or redo of
 * a cut, an erasure, a clone removed): what the edit left alone keeps its meshes. A
 * branch's part of the bark depends on its points, radii and attachment and on its parent
 * and grandparent alone (mesh.h), a leaf's on its points: such an element of t that `old`
 * has too, with the same parent and grandparent, gets old's part copied instead of built.
 * The same bytes as tree_mesh_build (tested against it).
 */

/* tm and mk hold old's meshes; afterwards t's. 0, or -ENOMEM (meshes then empty). */
int tree_mesh_rebuild_from(struct tree_mesh *tm, struct tree_mesh_marks *mk, const struct tree *t,
			   const struct tree *old);
