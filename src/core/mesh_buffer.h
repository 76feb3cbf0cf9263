/* SPDX-License-Identifier: MIT */
#pragma once

#include <stddef.h>
#include <stdint.h>

/*
 * A triangle buffer (mesh_buffer.c): what the tree's meshes (mesh.h), an origami leaf's
 * (ori_mesh_append), a vine's and the wood's bark are all written into. Core: it names
 * nothing else, so every floor may fill one (src/FLOORS).
 */

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
/* Room for nv more vertices and ni more indices. 0 or -ENOMEM (m unchanged). */
int mesh_reserve(struct mesh *m, size_t nv, size_t ni);
