/* SPDX-License-Identifier: MIT */
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "error.h"
#include "mesh.h"
#include "tree.h"

/*
 * A drawing planted for today's forest (docs/forest.md, "What a tree in the forest is"):
 * the file read like any drawing, its history rebuilt by an app of its own, a 2D sketch
 * lifted as the 3D button would; what the forest keeps is the tree, its meshes at full
 * detail and their marks (what model.glb is made of), and the drawing's seed (the wind's
 * phases). Runs on the planting thread: it touches nothing shared.
 */
struct forest_planted {
	struct tree tree;
	struct tree_mesh mesh;
	struct tree_mesh_marks marks;
	uint64_t seed;
};

void forest_planted_init(struct forest_planted *p);
void forest_planted_finish(struct forest_planted *p);
/*
 * Plants path into p (emptied first). 0; -ENODATA (the drawing holds no tree: nothing to
 * plant, err says so); -EINVAL (not a drawing, err names the file and line); -ENOMEM or
 * another negative errno (err says why). p is empty on failure.
 */
int forest_plant(const char *path, struct forest_planted *p, struct error *err);
