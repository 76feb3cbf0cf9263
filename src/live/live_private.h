/* SPDX-License-Identifier: MIT */
#pragma once

/* What src/live/'s files share and nobody else needs. */
#include <stdbool.h>
#include <stddef.h>

#include "live.h"

/* Branch b's point at arc length s from its base (clamped to it), by sk's arc lengths. */
struct vec3 live_branch_point(const struct live_skeleton *sk, const struct branch *b, size_t id,
			      double s);

/* A direction as a vertex's snorm bytes, unit length first ([3] = 0; all 0 for none). */
void live_snorm(struct vec3 n, int8_t out[4]);

/*
 * A grid of every branch's segments in space (live_nearest.c), for binding any mesh to its
 * nearest skeleton point. Each segment is listed in every cell its box, grown by its
 * larger radius, touches.
 */
struct live_segment {
	struct vec3 a, e; /* start, end - start */
	double r0, r1;    /* radius at a and at a + e */
	double s0, len;   /* arc length of a on its branch; |e| */
	size_t branch;
};

struct live_grid {
	struct live_segment *segs;
	size_t nsegs;
	struct vec3 lo;   /* the grid's corner */
	double cell;      /* a cell's edge, m */
	size_t dim[3];
	size_t *start;    /* cell c's segments: items[start[c] .. start[c + 1]) */
	size_t *items;
};

/* 0, -EINVAL (no segment: no branch with a point) or -ENOMEM (g then finish-able). */
int live_grid_build(struct live_grid *g, const struct live_skeleton *sk, const struct tree *t);
void live_grid_finish(struct live_grid *g);
/* The skeleton point nearest p (least |p - q| - r(q)): its branch and arc length. */
void live_grid_nearest(const struct live_grid *g, struct vec3 p, size_t *branch, double *s);
