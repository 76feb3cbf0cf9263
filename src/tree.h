/* SPDX-License-Identifier: MIT */
#pragma once

#include <stddef.h>

#include "vec.h"

/* How an element came to be; written to skeleton.json as a string. */
enum origin {
	ORIGIN_SKETCH = 0,
	ORIGIN_CLONE,
	ORIGIN_PROPAGATE,
	ORIGIN_MERGE,
};

const char *origin_name(enum origin origin);

struct branch {
	int id;          /* index in tree.branches */
	int parent;      /* -1 for the trunk */
	double parent_t; /* arc-length parameter 0..1 on the parent where it attaches */
	int generation;  /* 0 for the trunk */
	enum origin origin;
	struct vec3 *points; /* root first, world metres */
	double *radii;       /* one per point, metres */
	size_t npoints;
};

struct leaf {
	int id;
	int branch; /* the branch it is attached to */
	enum origin origin;
	struct vec3 *points; /* closed polygon, last point != first */
	size_t npoints;
};

/* The model: what the skeleton, the meshes and the screen are made from. */
struct tree {
	struct branch *branches;
	size_t nbranches, cap_branches;
	struct leaf *leaves;
	size_t nleaves, cap_leaves;
};

void tree_init(struct tree *t);
void tree_finish(struct tree *t);
void tree_clear(struct tree *t);
/* Copies points/radii. Returns the new id, or -ENOMEM. */
int tree_add_branch(struct tree *t, int parent, double parent_t, enum origin origin,
		    const struct vec3 *points, const double *radii, size_t npoints);
int tree_add_leaf(struct tree *t, int branch, enum origin origin, const struct vec3 *points,
		  size_t npoints);
