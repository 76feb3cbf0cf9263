/* SPDX-License-Identifier: MIT */
#pragma once

#include <stdbool.h>
#include <stddef.h>

#include "ori.h"
#include "vec.h"

/*
 * The origami leaf kinds a tree's leaves can be (struct leaf's `kind`): the compiled-in
 * presets, each built once (ori_build) the first time it is asked for and kept, with its
 * rest positions (ori_rest). A leaf of a kind keeps its `points` as the design's margin at
 * rest moved into the leaf's frame, so its frame is found again from its points alone
 * (ori_kind_frame): every edit that moves a leaf rigidly or scales it (following,
 * copying, arranging, propagating) keeps it a leaf of its kind with no frame to update.
 */
#define ORI_KIND_DRAWN (-1) /* a visitor's outline, or a generated tree's own */
enum {
	ORI_KIND_ENTIRE = 0,
	ORI_KIND_HOP,
	ORI_KIND_MAPLE,
	ORI_KIND_COUNT
};

struct ori_kind {
	struct ori_leaf leaf;
	double (*rest)[3];  /* ori_rest: nvertices rows, the design's coordinates */
	/* ori_unfold_frames: ORI_UNFOLD_FRAMES x nvertices rows, a new leaf unfolding */
	double (*frames)[3];
	size_t ntriangles;  /* ori_mesh_triangles */
	/* margin indices whose rest positions (offsets from O's) give the frame back */
	size_t anchor_a, anchor_b;
	double frame[3][3]; /* orthonormal rows from the anchors, as ori_kind_frame makes */
	double anchor_len;  /* |rest[a] - rest[O]| */
};

/* "drawn" for ORI_KIND_DRAWN, the preset's name for a kind, NULL for anything else. */
const char *ori_kind_name(int kind);
/* drawn, entire, hop, maple. */
bool ori_kind_from_name(const char *name, int *kind);
/* The kind, built on first use; NULL for ORI_KIND_DRAWN, an unknown kind, or when it
 * could not be built (out of memory): callers keep the leaf a drawn outline then. */
const struct ori_kind *ori_kind_get(int kind);
/* Frees what ori_kind_get built (tests that count allocations). */
void ori_kinds_release(void);

/* Row-major 3x4 [M | o]: a design point p goes to M p + o (M a rotation times a scale). */
struct vec3 ori_xf_apply(const double xf[12], const double p[3]);
/* The margin at rest moved by xf: k->leaf.nmargin points into out. */
void ori_kind_outline(const struct ori_kind *k, const double xf[12], struct vec3 *out);
/* The frame a leaf of kind k with these points was placed in (its outline is
 * ori_kind_outline(k, xf)). False when the points cannot be one (count, degenerate). */
bool ori_kind_frame(const struct ori_kind *k, const struct vec3 *points, size_t n,
		    double xf[12]);
