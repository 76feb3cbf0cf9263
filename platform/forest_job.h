/* SPDX-License-Identifier: MIT */
#pragma once

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "error.h"
#include "forest.h"
#include "forest_plant.h"

/*
 * The kiosk's forest brought up to date (docs/forest.md, "On the kiosk"), on the planting
 * thread: the day file read and the day begun anew when its reset moment has passed, the
 * archive listed, the day's newest max drawings planted (those already standing reused,
 * never changed), each tree's part made again only when its share of the triangles
 * changed, the layout, and the scene the screen draws. Touches nothing the main loop
 * writes: what it reuses is read only, what it makes is its own until handed back.
 */

/* A standing tree; planted and part are never changed once made, only replaced. */
struct forest_tree {
	uint64_t archive; /* its file's number: archive/drawing-NNNNNN.edaha */
	uint64_t number;  /* in the day */
	struct forest_planted *planted;
	struct forest_part *part;
	size_t share;     /* the triangles part was made for */
};

struct forest_job {
	/* in */
	const char *state_dir;
	size_t max;                  /* forest.max_trees */
	int reset_hour, reset_minute;
	int64_t now;                 /* seconds since 1970 */
	double strength;             /* the wind's, 0..1 */
	const struct forest_tree *had; /* standing until now, oldest first: reused */
	size_t nhad;
	const uint64_t *bad;         /* archive numbers that could not be planted: not again */
	size_t nbad;
	/* out */
	struct forest_day day;
	bool new_day;                /* a day began (the file written) */
	uint64_t next;               /* the number the next archived drawing gets */
	bool changed;                /* trees differs from had: the scene was built */
	struct forest_tree *trees;   /* standing now, oldest first (malloc'ed) */
	size_t ntrees;
	uint64_t *failed;            /* archive numbers newly found bad (malloc'ed) */
	size_t nfailed;
	size_t planted;              /* drawings planted by this job */
	struct forest_scene *scene;  /* the caller's, built when changed */
};

/* 0 (what the job found is in its out fields, even when a drawing could not be planted:
 * a journal line names it), or -ENOMEM / -errno with err (nothing changed: out fields
 * empty). */
int forest_job_run(struct forest_job *j, struct error *err);
/* Frees what the job made and the caller did not take: trees' planted and parts not in
 * had, the arrays. */
void forest_job_finish(struct forest_job *j);
