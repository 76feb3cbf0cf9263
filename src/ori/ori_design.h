/* SPDX-License-Identifier: MIT */
#pragma once

#include <stddef.h>

#include "error.h"
#include "ori.h"

/*
 * A design's limits (docs/leaf-format.md), kept apart from ori.h: ori_read checks what it
 * read with ori_design_check, which names the value at fault so that the refusal is told
 * at that value's line; the tests and the fuzzer check what was accepted with it.
 */

/* A fan's default side part (line 0); a file's side part must give its angle. */
void ori_side_default(struct ori_side *s);

/* The values ori_design_check may name. */
enum ori_value {
	ORI_VALUE_DESIGN = 0, /* the design as a whole: its fold, its counts */
	ORI_VALUE_NAME,
	ORI_VALUE_SIZE,
	ORI_VALUE_REST,
	ORI_VALUE_MIDDLE, /* middle.angle */
	ORI_VALUE_NODE_AT, /* these three: a node's, its index in nodes (a side part's: side) */
	ORI_VALUE_NODE_PHI,
	ORI_VALUE_NODE_PSI,
	ORI_VALUE_SIDE_ANGLE, /* these five: a side part's, its index in sides */
	ORI_VALUE_SIDE_FORKS,
	ORI_VALUE_FORK_AT,
	ORI_VALUE_FORK_A,
	ORI_VALUE_FORK_B,
	ORI_VALUE_SIDE_NODES, /* a side part's nodes as a whole */
	ORI_VALUE_JUNCTION,
	ORI_VALUE_THETA0,
	ORI_VALUE_WIDTH,
	ORI_VALUE_POWER,
	ORI_VALUE_COUNT
};

struct ori_fault {
	enum ori_value value;
	size_t index; /* the node or side part; 0 for the others */
	int side;     /* a side part's node: the part's index; else -1 */
};

/*
 * Whether every value of d is within its range (the table in docs/leaf-format.md), the
 * nodes' `at` increasing, each psi below its phi, a half fold without nodes or side parts.
 * 0, or -EINVAL with why "what: what is wrong" (no file name, no line) and *at the value.
 * What cannot fold (an asymmetric middle, a span of 360 degrees) is ori_build's to refuse.
 */
int ori_design_check(const struct ori_design *d, struct ori_fault *at, struct error *why);
