/* SPDX-License-Identifier: MIT */
#pragma once

/*
 * The wind in the exported files (export.h; docs/living-trees.md, "The wind in
 * model.glb"): a tree's skeleton and wind at an export's parameters, and for the glTF
 * exporter every primitive's morph targets and the weights' keyframes.
 */
#include <stdbool.h>
#include <stddef.h>

#include "export.h"
#include "live.h"

/* A tree's skeleton and its wind at an export's parameters. */
struct export_wind_tree {
	struct live_skeleton sk;
	struct live_wind w;
};

/*
 * The wind over `loop` seconds: 0 the tree's own loop (model.glb), else a common loop
 * (forest.glb: live_wind_params.loop). The parameters are checked first: -EINVAL
 * (strength outside 0..1, angle not finite, loop out of bounds). Then -ENODATA for a tree
 * without branches (nothing to sway), else 0 or -ENOMEM. wt can be finished whatever was
 * returned.
 */
int export_wind_tree_init(struct export_wind_tree *wt, const struct tree *t,
			  const struct export_wind *p, double loop);
/* Whether export_wind_tree_init takes p and loop (-EINVAL's test alone). */
bool export_wind_valid(const struct export_wind *p, double loop);
void export_wind_tree_finish(struct export_wind_tree *wt);

/* How a primitive's vertices are bound to the skeleton, as the renderer binds them. */
enum export_wind_bind {
	EXPORT_WIND_BARK,    /* tree_mesh_build's bark: each branch's rings, by the marks */
	EXPORT_WIND_LEAVES,  /* its leaves: each to its anchor, fluttering */
	EXPORT_WIND_NEAREST, /* any other mesh on the tree: the wood's bark, the vines */
};

/* The harmonic (whole cycles a loop) of target j's weight: live_wind_weights' order. */
int export_wind_harmonic(const struct live_wind *w, int j);

/*
 * The keyframes' intervals over the loop for targets whose largest component is scale[j]
 * metres: enough that a cubic Hermite spline through the sines, off by at most
 * (2 pi m / N)^4 / 384 of a target's scale (m its harmonic), is off by no more in all
 * than rounding the targets to bytes may cost (sum of scale[j] / 254); and at least 4 a
 * cycle of the fastest target. 1 when every target is zero.
 */
size_t export_wind_keys(const struct live_wind *w, const double scale[LIVE_WIND_TARGETS]);

/* One primitive's targets. */
struct export_wind_prim {
	/* target j's deltas, a vertex each: int8 x, y, z and a zero (normalised, 4-byte
	 * aligned) or float x, y, z; NULL where the target is zero at every vertex */
	const void *data[LIVE_WIND_TARGETS];
	double lo[LIVE_WIND_TARGETS][3], hi[LIVE_WIND_TARGETS][3]; /* the stored values' */
	size_t nvertices;
	void *block; /* owns the data */
};

/* The morph targets of a mesh's primitives and the weights' animation. */
struct export_wind_anim {
	bool floats;
	size_t nprims;
	struct export_wind_prim *prims;
	/* metres: the largest |component| of target j over every primitive; with bytes, what
	 * each weight is multiplied by (a byte c stands for scale c / 127) */
	double scale[LIVE_WIND_TARGETS];
	double loop;   /* T_loop, s */
	size_t nkeys;  /* intervals + 1: the last key is the first */
	float *times;  /* nkeys: t_k = T_loop k / (nkeys - 1) */
	/* nkeys x 3 x LIVE_WIND_TARGETS, glTF's CUBICSPLINE layout: each key's in-tangents,
	 * weights, out-tangents (per second) */
	float *values;
};

/*
 * The targets of meshes[0..n) (bound as bind[i] says; the bark's and leaves' by mk, or
 * found again when mk does not describe them, or by the nearest skeleton point when that
 * fails too) and the keyframes, at wt's wind. 0, -EINVAL (a mesh with vertices and no
 * segment of the skeleton to bind them to) or -ENOMEM; a is finish-able either way.
 */
int export_wind_anim_build(struct export_wind_anim *a, const struct export_wind_tree *wt,
			   const struct tree *t, const struct tree_mesh_marks *mk,
			   const struct mesh *const *meshes, const enum export_wind_bind *bind,
			   size_t n, bool floats);
void export_wind_anim_finish(struct export_wind_anim *a);
