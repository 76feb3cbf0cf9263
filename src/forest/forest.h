/* SPDX-License-Identifier: MIT */
/*
 * src/forest/ (floor 8 of src/FLOORS: includes export and every floor below): today's
 * forest on the attract screen (issue 27, docs/forest.md), as pure functions: which
 * archived drawings form the day's forest and their numbers in it (forest_day.c), where
 * the trees stand (forest_layout.c), and forest.json (forest_json.c). The clock, the
 * archive's files and the trees' building are the caller's (platform/).
 */
#pragma once

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "buf.h"
#include "error.h"

#define FOREST_MAX_TREES_DEFAULT 40
#define FOREST_MAX_TREES_LIMIT 200

/* ---- the day ------------------------------------------------------------------- */

/*
 * What the forest keeps across restarts (STATE_DIR/forest-day): when the day began and
 * the archive number of its first tree. Everything else is rebuilt from the archive.
 */
struct forest_day {
	int64_t start;  /* seconds since 1970 (UTC); 0: no day yet */
	uint64_t first; /* the archive number of the day's first tree */
};

/*
 * A new day begins when the last reset moment at or before now (`reset`, the caller's
 * clock and time zone) is later than the day's start: day becomes {reset, next}, the next
 * archive number, and the function returns true. A clock set back never begins a day.
 */
bool forest_day_update(struct forest_day *day, int64_t reset, uint64_t next);
/* A new day now, whatever the hour (edaha --forest-reset). */
void forest_day_restart(struct forest_day *day, int64_t now, uint64_t next);
/*
 * The trees standing among archive numbers[0..n) (any order; duplicates count once):
 * those numbered day->first or more, the newest max of them. Writes their indexes into
 * numbers to out (at most max), oldest first, and returns how many.
 */
size_t forest_day_standing(const struct forest_day *day, const uint64_t *numbers, size_t n,
			   size_t max, size_t *out);
/* A tree's number in the day (1 for the day's first), 0 for one before the day. */
uint64_t forest_day_number(const struct forest_day *day, uint64_t archive_number);

/* The file (docs/forest.md), a flat YAML mapping: `edaha-forest-day: 1`, `start: S`,
 * `first: N`. read: 0, or -EINVAL / -ENOMEM with err "NAME:LINE: what is wrong" (day
 * unchanged). write: 0 or -ENOMEM. */
#define FOREST_DAY_VERSION 1
int forest_day_read(const char *data, size_t len, const char *name, struct forest_day *day,
		    struct error *err);
int forest_day_write(const struct forest_day *day, struct buf *out);

/* ---- the layout ------------------------------------------------------------------ */

/*
 * Where the trees stand on the ground (x, z, metres; y up): the tree numbered n at slot
 * (n - 1) mod max of a sunflower spiral, radius c sqrt(k + 1/2) at k golden angles, so a
 * tree keeps its place while it stands. c is the least scale at which every two trunks
 * are FOREST_GAP times the sum of their crown widths apart (and at least FOREST_MIN_C).
 * numbers[i] (1..; distinct modulo max) and widths[i] (metres, >= 0) of n trees; writes
 * xz[2i], xz[2i + 1]. Returns c, or -1 when two trees share a slot or an input is bad.
 */
#define FOREST_GAP 0.45
#define FOREST_MIN_C 1.0
double forest_layout(const uint64_t *numbers, const double *widths, size_t n, size_t max,
		     double *xz);

/* ---- forest.json ----------------------------------------------------------------- */

struct forest_json_tree {
	uint64_t number;
	const char *file;
	double position[3];
	double height, crown_width;
	size_t branches, leaves;
};
struct forest_json_skip {
	const char *file;
	const char *why;
};
/* {"format": "edaha-forest", "version": 1, "trees": [...], "skipped": [...]}. 0 or
 * -ENOMEM. */
int forest_json(const struct forest_json_tree *trees, size_t ntrees,
		const struct forest_json_skip *skipped, size_t nskipped, struct buf *out);
