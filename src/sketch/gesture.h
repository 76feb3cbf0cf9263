/* SPDX-License-Identifier: MIT */
#pragma once

#include <stdbool.h>
#include <stddef.h>

#include "tree.h"

/*
 * Cut and erase gestures (seed 000, section 3.2). A stroke that crosses a branch once cuts
 * it there; two or more crossings erase the branch from its base. The pen's eraser end
 * erases what it touches. What is a gesture and what is a new branch is decided in
 * sketch.c (see docs/sketching.md).
 */

/* Within this distance (metres, 2.5% of the screen height) a stroke starts "on" a branch. */
#define GESTURE_SNAP_M 0.25
/* Half the width of the eraser's trail, metres (about 12 px on an 800 px screen). */
#define GESTURE_ERASER_RADIUS_M 0.15

struct gesture_crossing {
	int branch;
	int count;      /* how many times the stroke crosses it */
	size_t segment; /* where it first does, on the branch */
	double seg_t;
	double along;   /* ...and how far along the stroke that is, metres */
};

/* Crossings of the stroke polyline with every branch, in the sketch plane. *out is
 * malloc'ed (one entry per crossed branch, by id). 0 or -ENOMEM. */
int gesture_crossings(const struct tree *t, const struct vec3 *p, size_t n,
		      struct gesture_crossing **out, size_t *nout);

/*
 * The edits below look for crossings and touches in `seen`, the tree as the screen shows
 * it (the same ids and segments: t itself for the front view, a sketch_seen of it on a
 * turned 3D tree), and edit t.
 */

/* Applies cuts and erasures of a stroke that crosses branches, each crossed branch once,
 * from the newest. Returns how many edits were made, or -ENOMEM. */
int gesture_cut_erase(struct tree *t, const struct tree *seen, const struct vec3 *p, size_t n);

/* Erases the branches (from their base, with all attached) and leaves the eraser trail
 * touches. Returns how many were touched, or -ENOMEM. */
int gesture_eraser(struct tree *t, const struct tree *seen, const struct vec3 *p, size_t n);
