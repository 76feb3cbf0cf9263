/* SPDX-License-Identifier: MIT */
#pragma once

#include <stdbool.h>
#include <stdint.h>
#include <string.h>

#include "app.h"
#include "pen.h"
#include "rng.h"
#include "same.h"
#include "test.h"

/*
 * What the undo tests (test_undo.c, test_undo_walk.c) share: a visitor's gestures on the
 * app's screen, on the test's pen clock, and an app compared field by field and byte by
 * byte with a fresh one that replayed its document. Every failure exits as test.h's CHECK
 * does.
 */

/* a and b hold the same bytes */
#define SAME(a, b) CHECK(memcmp(&(a), &(b), sizeof(a)) == 0)

/* d: a copy of src's ops, cursor and view, to load into another app. */
void session_copy_doc(struct doc *d, const struct doc *src);

/* A stroke of n pen events from (x0, y0) to (x1, y1), wavering a little; the clock then
 * moves on pause_us more. */
void session_stroke(struct pen *pen, struct app *app, double x0, double y0, double x1, double y1,
		    int n, enum event_tool tool, uint64_t pause_us);
/* A loop of radius r from (cx + r, cy) round (cx, cy): clockwise on the screen for dir 1,
 * the other way for -1. */
void session_loop(struct pen *pen, struct app *app, double cx, double cy, double r, double dir);
/* A tap at (x, y). */
void session_tap(struct pen *pen, struct app *app, double x, double y);
/* A point of a random branch (one with children if `parent`) where the screen shows it, off
 * the buttons; false when 40 tries found none. */
bool session_pick(const struct app *app, struct rng *r, bool parent, double *x, double *y);
