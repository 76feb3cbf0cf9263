/* SPDX-License-Identifier: MIT */
#pragma once

/*
 * Access to the kiosk's devices. Where a seat daemon runs (seatd, or logind for a
 * kiosk in a login session), devices are opened through libseat: edaha needs neither
 * root nor the video group, and the daemon hands the display to another VT and back
 * (disable and enable). Without one, or in a build without libseat, devices are opened
 * directly (root or the video group) and the seat is always active.
 *
 * libseat's builtin backend (a seatd forked inside edaha) is not used unless
 * LIBSEAT_BACKEND asks for it: without a daemon the kiosk opens its card itself.
 */
#include <stdbool.h>

#include "error.h"

struct seat;

struct seat_listener {
	/* Stop using the devices (no commits, no flips); the seat acknowledges to the
	 * daemon when this returns. */
	void (*disable)(void *data);
	/* Back: the devices work again; a display needs a new modeset. */
	void (*enable)(void *data);
};

/*
 * Opens the seat, waiting a few seconds for the daemon to make it active. listener may
 * be NULL. NULL on failure with why in err: no memory, or a daemon that never let us in.
 */
struct seat *seat_create(const struct seat_listener *listener, void *data, struct error *err);
/* Devices still open are closed. */
void seat_destroy(struct seat *s);

/* "libseat (seatd)", "libseat (logind)" or "direct", for the log. */
const char *seat_describe(const struct seat *s);
/* The fd to poll for seat events; -1 when devices are opened directly. */
int seat_fd(const struct seat *s);
/* Reads the seat's events when its fd is readable; calls the listener. 0 or -errno. */
int seat_dispatch(struct seat *s);
bool seat_active(const struct seat *s);

/* Opens a device node read-write (close-on-exec). An fd, or a negative errno. */
int seat_open(struct seat *s, const char *path);
void seat_close(struct seat *s, int fd);
