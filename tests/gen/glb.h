/* SPDX-License-Identifier: MIT */
#pragma once

/* model.glb as the gen tests read it: the container (a JSON chunk and a BIN chunk), and
 * each primitive's positions and triangle count, found by its material's name ("bark",
 * "leaves"). Read without the exporter's code, so its mistakes are not the test's. */
#include <stddef.h>

struct glb_prim {
	char material[32];
	size_t nvertices, ntriangles;
	float *positions; /* 3 per vertex */
};

struct glb {
	size_t nprims;
	struct glb_prim prims[8];
};

/* 0, or -1 with a message on stderr. */
int glb_load(const char *path, struct glb *g);
void glb_free(struct glb *g);
/* The primitive drawn with that material, or NULL (none: nothing of it in the model). */
const struct glb_prim *glb_prim(const struct glb *g, const char *material);
