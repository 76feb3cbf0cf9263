/* SPDX-License-Identifier: MIT */
#pragma once

#include <stdbool.h>

#include "tree.h"

/*
 * Leaf arrangement by example (seed 000, section 3.5): the leaves a visitor drew on a
 * branch suggest how to go on; each suggestion is a pattern applied to that branch.
 */
enum arrange_pattern {
	ARRANGE_WHORL_ADD = 0, /* leaves at one place: one more, evenly around the branch */
	ARRANGE_WHORL_EXTEND,  /* such a set and a leaf higher up: the set repeated to the tip */
	ARRANGE_SPIRAL_EXTEND, /* single leaves at different places: their spacing and
				* divergence continued to the tip */
	ARRANGE_COUNT
};

/* The thresholds (arrange.c explains how they are used). */
#define ARRANGE_SAME_PLACE_M 0.15     /* leaves this close along the branch are one set... */
#define ARRANGE_SAME_PLACE_REACH 0.3  /* ...or closer than this x their mean reach */
#define ARRANGE_WHORL_MAX 16          /* whorl-add stops at this many leaves in a set */
#define ARRANGE_TIP_EPS_M 1e-6        /* a leaf this far past the tip still counts as on it */
#define ARRANGE_MAX_NEW_POINTS 200000 /* one application adds at most this many points */

/* Names are a contract (drawing.edaha): whorl-add, whorl-extend, spiral-extend. */
const char *arrange_pattern_name(enum arrange_pattern p);
bool arrange_pattern_from_name(const char *name, enum arrange_pattern *p);

/* The patterns the leaves on branch b suggest, as bits (1u << pattern); 0 for none. */
unsigned arrange_suggest(const struct tree *t, int b);

/* Applies pattern p to branch b: new leaves (origin ORIGIN_ARRANGE) are copies of the
 * visitor's own leaf shape. Returns how many leaves it added, -ENOENT if b does not
 * suggest p, -ENOMEM. */
int arrange_apply(struct tree *t, int b, enum arrange_pattern p);

/* A small tree for the suggestion's thumbnail: branch b alone (as its trunk, where it is
 * in the world) with its leaves after applying p. out is initialised here; the caller
 * tree_finish()es it. 0, -ENOENT, -ENOMEM. */
int arrange_preview(const struct tree *t, int b, enum arrange_pattern p, struct tree *out);
