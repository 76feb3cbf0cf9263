/* SPDX-License-Identifier: MIT */
#pragma once

#include "mesh.h"
#include "tree.h"

/*
 * A tree's vines as the glTF and OBJ exporters write them. The app's tree_mesh holds none
 * of them (it draws them apart), so each export meshes them anew (vine_mesh_append): every
 * vine's stems in one mesh, every vine's leaves in another, vine after vine in the tree's
 * order. Without vines both stay empty and nothing is allocated, so a tree without vines
 * costs nothing and its files keep their bytes.
 */
struct export_vines {
	struct mesh stems;
	struct mesh leaves;
};

/* 0, or -ENOMEM (both meshes empty then; export_vines_finish frees them either way). */
int export_vines_build(struct export_vines *ev, const struct tree *t);
void export_vines_finish(struct export_vines *ev);
