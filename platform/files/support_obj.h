/* SPDX-License-Identifier: MIT */
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "error.h"

/* More triangles than this and a support is refused: a kiosk's vine climbs a pole, a
 * trellis or a tree, not a scanned city (2 M triangles are 48 MB of floats and indices). */
#define SUPPORT_OBJ_MAX_TRIANGLES 2000000u

/* A support's triangles, ready for vine_support_create: 3 floats a vertex (metres, y up),
 * 3 indices a triangle. */
struct support_obj {
	float *positions;
	size_t nvertices;
	uint32_t *indices;
	size_t ntriangles;
};

/*
 * Reads a Wavefront OBJ through assimp: every mesh's triangles (polygons triangulated,
 * points and lines left out), each placed by its nodes' transforms. 0; -EINVAL with err
 * "PATH: what is wrong" (assimp's message where it gives one) for a file that is missing,
 * no OBJ assimp reads, has no triangles, a non-finite coordinate or too many triangles;
 * -ENOMEM. Nothing to free on failure.
 */
int support_obj_read(const char *path, struct support_obj *s, struct error *err);
void support_obj_finish(struct support_obj *s);
