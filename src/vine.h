/* SPDX-License-Identifier: MIT */
#pragma once

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "error.h"
#include "vec.h"

/*
 * Twining vines (seed 004, Kasakura): a climbing plant grown by simulating circumnutation
 * (the apex's free rod sweeping about the vertical) and apical dominance around any
 * support, a triangle mesh. docs/vines.md says how; docs/vine-format.md is the parameter
 * file (`edaha-vine: 1`), read by vine_read(). Pure and deterministic: the same
 * parameters, support, planting point and seed give the same vine, bit for bit.
 */

/* The parameter file's version (`edaha-vine: N`) this edaha reads. */
#define VINE_PARAMS_VERSION 1

enum vine_twining {
	VINE_LEFT = 0, /* the mirror of right: hop */
	VINE_RIGHT,    /* the thesis's right (clockwise seen from below): a right-handed helix,
			* counter-clockwise seen from above (morning glory) */
};

/* Table 3.1 (defaults Table 4.1, one thesis unit = 1 mm) and edaha's own. */
struct vine_params {
	double internode;  /* l, metres */
	double radius;     /* r, the stem's, metres */
	double step_time;  /* t: a new axis point every t units of simulated time */
	double angle;      /* theta_p, degrees: the free rod's lean from the vertical */
	int free_nodes;    /* U: nodes from the root before the apex starts circling */
	enum vine_twining twining;
	int leaves_per_node; /* 0, 1 (alternate) or 2 (opposite) */
	int cotyledons;      /* 0, 1 or 2 */
	double leaf_size;    /* gamma, metres: half the diagonal of the square leaf */
	int points_per_internode; /* d */
	int ring_sides;      /* M */
	double sweep;        /* omega, degrees per unit of time */
	int internodes;      /* the growth budget: growth stops when the vine has made this many */
	uint64_t seed;
};

/* Table 4.1's defaults and edaha's (docs/vine-format.md). */
void vine_params_default(struct vine_params *p);

/*
 * Reads a vine parameter file (docs/vine-format.md) from memory; name is the file's name
 * for messages. 0, or -EINVAL/-ENOMEM with err "NAME:LINE: what is wrong" (*p unchanged).
 */
int vine_read(const char *data, size_t len, const char *name, struct vine_params *p,
	      struct error *err);
#define VINE_READ_MAX_BYTES 65536
#define VINE_READ_MAX_DEPTH 4

/* Within every limit (docs/vine-format.md): 0, or -EINVAL with err naming the key. */
int vine_params_check(const struct vine_params *p, const char **key, struct error *err);
