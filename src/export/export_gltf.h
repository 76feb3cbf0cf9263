/* SPDX-License-Identifier: MIT */
#pragma once

/*
 * A glTF binary of many trees, built one tree after another (export_gltf.c), for
 * forest.glb (export_forest.c). Each tree is a root node of the scene with its own mesh,
 * whose primitives are the tree's model.glb's (export.h: "bark", "wood", "leaves",
 * "vine", "vine-leaves", with the wind's targets), the materials shared (each in the
 * file once); with the wind, the one animation "wind" has a channel and a sampler a tree
 * with branches. The document keeps pointers to the trees' meshes (not copies) until it
 * is written.
 */
#include <stdbool.h>
#include <stddef.h>

#include "buf.h"
#include "export.h"
#include "mesh.h"
#include "tree.h"

struct export_gltf;

/* Where a tree goes: its node's name (its mesh's, its accessors' names' first part) and
 * translation (metres, y up; NULL: none). */
struct export_gltf_node {
	const char *name;
	const double *translation;
};

/* NULL without memory. */
struct export_gltf *export_gltf_create(void);
void export_gltf_destroy(struct export_gltf *d);
/*
 * Appends tree t (meshes m, marks mk as export_glb takes them) as a node, always (one
 * without triangles: a node without a mesh), with wind its targets and its channel, the
 * wind over `loop` seconds (export_wind_tree_init: 0 its own loop, else a common one) and
 * the phases from wind->seed. 0, -EINVAL (the wind's parameters) or -ENOMEM; after a
 * failure the document can only be destroyed.
 */
int export_gltf_add_tree(struct export_gltf *d, const struct tree *t, const struct tree_mesh *m,
			 const struct tree_mesh_marks *mk, const struct export_wind *wind,
			 double loop, const struct export_gltf_node *node);
/* The GLB appended to out, or nothing at all: 0, -ENOMEM or -EFBIG. No tree: an empty
 * scene. */
int export_gltf_write(struct export_gltf *d, struct buf *out);
