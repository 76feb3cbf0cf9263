/* SPDX-License-Identifier: MIT */
/*
 * src/sketch/ (floor 5 of src/FLOORS, beside gen, vine and wood, which it never
 * includes): freehand sketching (this header), gestures, the sketch as the camera shows
 * it, lifting to 3D, clone, leaf arrangement and propagation (seed 000). Includes ori,
 * core and fmt.
 */
#pragma once

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "camera.h"
#include "event.h"
#include "tree.h"

/* Resampling step along strokes, metres (about 4 px on an 800 px high screen). */
#define SKETCH_STEP_M 0.05
/* Strokes shorter than this are taps, not drawings. */
#define SKETCH_MIN_LENGTH_M 0.1
/* Two outlines of one branch (Fig. 4) are drawn within this pause of each other. */
#define SKETCH_OUTLINE_PAUSE_US 3000000u
/* ...and run beside each other as a branch's edges do (docs/sketching.md): their chords
 * within this angle; at the root at least this far apart (a thin branch's thickness);
 * never more than WIDEN x + WOBBLE apart than anywhere nearer the root; closing in by
 * at most MAX_TAPER from root to tip (as much as a single stroke tapers). */
#define SKETCH_OUTLINE_MAX_CHORD_DEG 30.0
#define SKETCH_OUTLINE_MIN_GAP_M 0.03
#define SKETCH_OUTLINE_WIDEN 1.15
#define SKETCH_OUTLINE_WOBBLE_M 0.05
#define SKETCH_OUTLINE_MAX_TAPER 5.0
/* A closed stroke's area / length^2 at least (a V returning to its start is no leaf). */
#define SKETCH_MIN_LEAF_ROUNDNESS 0.02
/* At most this many samples a stroke: a longer stroke is sampled more coarsely. */
#define SKETCH_MAX_SAMPLES 4096
/* A sketch stroke that would take the tree's sketched points past this makes nothing:
 * it bounds the meshes a damaged or hostile drawing can ask for. */
#define SKETCH_MAX_TREE_POINTS 200000

struct sketch_hit {
	int branch;      /* -1 if the tree has no branches */
	size_t segment;  /* segment index on that branch */
	double seg_t;    /* 0..1 along that segment */
	double param;    /* 0..1 arc length along the branch */
	struct vec3 point;
	double dist;
};

/* Nearest point on any branch to p (in the sketch plane's x/y); on equal distances the
 * first segment in the tree's order. Through t's grid if it keeps one (tree_index.h). */
struct sketch_hit sketch_nearest(const struct tree *t, struct vec3 p);
/* The same by looking at every segment: what the grid must agree with (tests). */
struct sketch_hit sketch_nearest_scan(const struct tree *t, struct vec3 p);

/* Resamples a polyline by arc length at `step` (or coarser, to stay within
 * SKETCH_MAX_SAMPLES); *out is malloc'ed. 0, -EINVAL (not finite) or -ENOMEM. */
int sketch_resample(const struct vec3 *in, size_t n, double step, struct vec3 **out, size_t *nout);

/* Light smoothing: SKETCH_SMOOTH_PASSES of a (1/4, 1/2, 1/4) filter that leaves the ends
 * (of an open stroke) and corners sharper than SKETCH_CORNER_DEG where they are. */
#define SKETCH_SMOOTH_PASSES 2
#define SKETCH_CORNER_DEG 60.0
void sketch_smooth(struct vec3 *p, size_t n, bool closed);

/* Whether a resampled stroke returns near its start: a leaf rather than a branch. */
bool sketch_is_closed(const struct vec3 *p, size_t n);

/* One pen stroke as the sketch takes it: what a drawing's stroke op holds (doc.h's
 * doc_apply_stroke makes one of it), in plain values. */
struct sketch_stroke {
	const struct vec3 *points; /* as drawn on the sketch plane, world metres, z 0 */
	size_t npoints;
	enum event_tool tool;
	struct camera camera; /* the view it was drawn in */
	uint64_t time_us;     /* when it began */
	uint64_t end_us;      /* when it ended */
};

/*
 * Applies one stroke: an open stroke becomes a branch (the first the trunk, later ones
 * attached to the nearest branch point), a closed one a leaf on the nearest branch, an
 * eraser's stroke erases. Returns SKETCH_GREW when the tree only gained elements at its
 * end (or nothing: taps, a leaf with no branch), SKETCH_CHANGED when existing elements
 * changed, or -ENOMEM.
 */
#define SKETCH_GREW 0
#define SKETCH_CHANGED 1
int sketch_stroke(struct tree *t, const struct sketch_stroke *s);
