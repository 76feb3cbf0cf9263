/* SPDX-License-Identifier: MIT */
#pragma once

/* skeleton.json (docs/skeleton-format.md) as the gen tests read it: plain arrays, every
 * field the tests assert on. Reading checks the layout; a file that breaks it fails the
 * test that reads it. */
#include <stddef.h>

struct skel_branch {
	int id, parent, generation, level; /* level: -1 when absent */
	char origin[16];
	double parent_t;
	size_t npoints;
	double (*points)[3];
	double *radii;
};

struct skel_leaf {
	int id, branch;
	char origin[16];
	size_t npoints;
	double (*points)[3];
};

struct skel {
	char season[16];
	size_t nbranches, nleaves;
	struct skel_branch *branches;
	struct skel_leaf *leaves;
};

/* 0, or -1 with a message on stderr. */
int skel_load(const char *path, struct skel *s);
void skel_free(struct skel *s);

/* A branch's arc length, and the unit vector from its first point to its last. */
double skel_length(const struct skel_branch *b);
void skel_direction(const struct skel_branch *b, double d[3]);
