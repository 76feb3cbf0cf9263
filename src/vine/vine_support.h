/* SPDX-License-Identifier: MIT */
#pragma once

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "vec.h"

/*
 * What a vine climbs (seed 004): a triangle mesh (the tree's bark, or an OBJ file),
 * indexed for the growth's contact queries: the distance from a point to the mesh, and the
 * nearest point, fast enough that supports of 100k triangles stay cheap. Pure: built from
 * arrays, no I/O; deterministic.
 */
struct vine_support;

/*
 * Builds the index over ntriangles triangles (indices: 3 a triangle into positions, 3
 * floats a vertex, metres, y up). Degenerate triangles (no area) are kept as segments or
 * points for distances. 0 and *out, or -EINVAL (an index out of range, a non-finite
 * position) or -ENOMEM.
 */
int vine_support_create(const float *positions, size_t nvertices, const uint32_t *indices,
			size_t ntriangles, struct vine_support **out);
void vine_support_destroy(struct vine_support *s);

/* The number of triangles, and the bounding box of them all. */
size_t vine_support_triangles(const struct vine_support *s);
void vine_support_bounds(const struct vine_support *s, struct vec3 *lo, struct vec3 *hi);

/*
 * The distance from p to the nearest point of the mesh, if it is below max: returns it and
 * sets *nearest (may be NULL) and *triangle (may be NULL) to where; otherwise returns a
 * value >= max and leaves them. Exact (to double rounding) for every triangle it looks at;
 * the index only skips triangles that cannot be nearer than max or than the best found.
 */
double vine_support_distance(const struct vine_support *s, struct vec3 p, double max,
			     struct vec3 *nearest, size_t *triangle);

/*
 * Whether the segment from a to b meets a triangle of the mesh (one without area never
 * counts). Conservative: a segment through an edge or a vertex, or touching a triangle,
 * meets it, so a closed mesh has no gap for a segment to slip through; a segment lying in
 * a triangle's plane meets it when their boxes overlap. False for a point that is not
 * finite.
 */
bool vine_support_crosses(const struct vine_support *s, struct vec3 a, struct vec3 b);
