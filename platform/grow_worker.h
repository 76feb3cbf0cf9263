/* SPDX-License-Identifier: MIT */
#pragma once

#include <stdbool.h>
#include <stdint.h>

#include "error.h"
#include "tree.h"
#include "wood.h"

/*
 * The kiosk's grow presses off its loop (issue 17): a press solves the tree's springs,
 * up to a second or more on the board, while frames and the watchdog must go on. A
 * thread grows a copy of the tree (wood_grow, pure) and makes the worker's fd readable
 * when it is done; the loop hands the grown copy to the app (app_grow_done).
 */
struct grow_worker;

struct grow_worker *grow_worker_create(struct error *err);
/* Waits for a press under way, and frees what it holds. */
void grow_worker_destroy(struct grow_worker *w);
/* Readable when a press is done. */
int grow_worker_fd(const struct grow_worker *w);
bool grow_worker_busy(const struct grow_worker *w);
/* Grows t (the worker's until taken back) with p on the thread. 0, -EBUSY or a negative
 * errno (t is the caller's again then). */
int grow_worker_start(struct grow_worker *w, struct tree *t, const struct wood_params *p,
		      uint64_t serial);
/* The press done: the tree back (the caller's), wood_grow's result and the serial given.
 * 0, or -EAGAIN when none is done. */
int grow_worker_take(struct grow_worker *w, struct tree **t, int *result, uint64_t *serial);
