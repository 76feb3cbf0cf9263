/* SPDX-License-Identifier: MIT */
/* A grow press on its worker (grow_worker.h): started on a copy of the tree, its result
 * handed to the app when the worker's fd is readable, started again if the tree changed
 * meanwhile. */
#include "kiosk_private.h"

#include <errno.h>
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* A grow press the app waits for, on the worker: a copy of the tree as it is now. */
void kiosk_start_grow(struct kiosk *k)
{
	struct tree *t = malloc(sizeof(*t));
	struct wood_params p;
	uint64_t serial;
	int ret = t ? 0 : -ENOMEM;

	if (t) {
		tree_init(t);
		ret = app_grow_job(k->app, t, &p, &serial);
	}
	if (ret == 0)
		ret = grow_worker_start(k->grow, t, &p, serial);
	if (ret == 0 && !k->grow_started_us) {
		k->grow_started_us = kiosk_now_us();
		k->grow_frames = k->frames;
		k->grow_shown = k->shown;
	}
	if (ret < 0) {
		if (t) {
			tree_finish(t);
			free(t);
		}
		fprintf(stderr, "edaha: warning: a grow press could not start: %s\n", strerror(-ret));
		k->grow_started_us = 0;
		k->app->grow_waiting = false;
		app_set_status(k->app, APP_STATUS_NONE, kiosk_now_us());
	}
}

/* The worker's press done: to the app, or again if the tree changed meanwhile. */
void kiosk_on_grow(struct kiosk *k)
{
	struct tree *t;
	uint64_t serial;
	int result, ret;

	if (grow_worker_take(k->grow, &t, &result, &serial) < 0)
		return;
	ret = result < 0 ? result : app_grow_done(k->app, t, serial, kiosk_now_us());
	tree_finish(t);
	free(t);
	if (ret == 0) {
		/* the technician's proof that the loop went on while the worker grew: frames
		 * drawn count, as a frame's flip can land just after the worker's result */
		fprintf(stderr, "edaha: grew a year in %.2f s, %" PRIu64 " frames drawn and %" PRIu64
			" shown meanwhile\n", (double)(kiosk_now_us() - k->grow_started_us) / 1e6,
			k->frames - k->grow_frames, k->shown - k->grow_shown);
		k->grow_started_us = 0;
	}
	if (ret == -EAGAIN) {
		kiosk_start_grow(k);
	} else if (ret < 0) {
		k->grow_started_us = 0;
		fprintf(stderr, "edaha: warning: a grow press failed: %s\n", strerror(-ret));
		k->app->grow_waiting = false;
		app_set_status(k->app, APP_STATUS_NONE, kiosk_now_us());
	}
	kiosk_save_edits(k);
}
