/* SPDX-License-Identifier: MIT */
#pragma once

#include <stdint.h>

#include "drm_display.h"
#include "event.h"
#include "kiosk_source.h"

/*
 * The kiosk's main loop: one poll() over the display's fds (DRM, seat, hotplug), the
 * input sources, a timerfd and a signalfd (SIGINT, SIGTERM). A frame is drawn only when
 * what the app shows changed (or the 3D turn animates, or the display came back from a
 * VT switch or a replug) and only when the display can take one: at most one frame a
 * vblank, none while nothing happens, none while the display is away.
 */
struct kiosk;

struct kiosk_config {
	struct drm_display_config display;
	uint64_t seed;          /* of a new drawing */
	const char *record;     /* write every event fed as an edaha trace; NULL: no */
	/* Test runs: draw a frame every vblank as if the app changed each time, and stop
	 * after this many frames are on screen (0: run until a signal). */
	unsigned long frames;
	const char *screenshot; /* with frames: the last frame as a PNG */
};

/* Opens the display and makes the app at the display's size. NULL (message printed). */
struct kiosk *kiosk_create(const struct kiosk_config *cfg);
void kiosk_destroy(struct kiosk *k);
/* Polls src->fd from now on (copied). 0 or -ENOMEM. */
int kiosk_add_source(struct kiosk *k, const struct kiosk_source *src);
/* Screen size (as the viewer sees it, turned), so that input can map a tablet onto it. */
void kiosk_size(const struct kiosk *k, int *width, int *height);
/* For sources' dispatch: one event into the app (and the recording). */
void kiosk_feed(struct kiosk *k, const struct event *ev);
/* Runs until SIGINT/SIGTERM, the frame count, or a failure. Exit status: 0 or 1. */
int kiosk_run(struct kiosk *k);
