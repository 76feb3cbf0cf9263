/* SPDX-License-Identifier: MIT */
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "error.h"
#include "forest.h"

/*
 * What today's forest keeps on disk (docs/forest.md, "Which trees"): nothing but the day
 * file STATE_DIR/forest-day; the trees are the archive's drawings (autosave.h), read back
 * at every start. And the clock's part: the last reset moment in local time.
 */
#define FOREST_STATE_FILE "forest-day"

/*
 * The archive's drawings (STATE_DIR/archive/drawing-NNNNNN.edaha): their numbers in
 * ascending order (*numbers malloc'ed, free it; NULL when none) and the number the next
 * one will get (as autosave_archive gives it). A missing archive is an empty one. 0 or
 * -errno with err.
 */
int forest_state_archive(const char *state_dir, uint64_t **numbers, size_t *n, uint64_t *next,
			 struct error *err);
/*
 * The day file: 0 with *day as saved, or a day not yet begun ({0, 0}) when the file is
 * missing; a damaged file is not an error: warn says why (naming its line) and the day
 * is not begun, so a new one starts. -errno with err only when it cannot be read (I/O).
 */
int forest_state_load(const char *state_dir, struct forest_day *day, struct error *warn,
		      struct error *err);
/* Writes it atomically (temporary name, fsync, rename). 0 or -errno with err. */
int forest_state_save(const char *state_dir, const struct forest_day *day, struct error *err);
/* The last moment at or before now (seconds since 1970) that is hour:minute local time
 * (the TZ environment's), whatever daylight saving does that day. */
int64_t forest_state_reset_moment(int64_t now, int hour, int minute);
/* The day's first tree when the day file is missing or damaged (a first start, a file
 * someone removed): the first of the archive's numbers (ascending) whose drawing was
 * written at or after `since`, the reset moment, so today's drawings still stand; next
 * when none was. */
uint64_t forest_state_first_since(const char *state_dir, const uint64_t *numbers, size_t n,
				  int64_t since, uint64_t next);
/* edaha --forest-reset: a new day begins now; the next archived drawing is its No. 1.
 * 0 or -errno with err. */
int forest_state_reset(const char *state_dir, int64_t now, struct error *err);
