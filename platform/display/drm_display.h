/* SPDX-License-Identifier: MIT */
#pragma once

#include <poll.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "error.h"

/*
 * The kiosk's screen: one DRM/KMS output (drm_kms.c: atomic commits, or the legacy calls
 * where the driver refuses atomic or when EDAHA_DRM_LEGACY=1), a GBM surface and a GLES
 * context (3.0 when the driver has it, else 2.0) drawing into it through EGL's GBM
 * platform. The card is opened through the seat (seat.c: libseat when a seat daemon
 * runs, else directly) and a udev monitor watches for displays coming and going
 * (drm_hotplug.c).
 *
 * One frame: when drm_display_can_draw(), draw into the bound framebuffer at
 * drm_display_size(), then drm_display_present(). The frame is on screen when the
 * display's fds (drm_display_pollfds) have been dispatched and drm_display_flip_pending()
 * is false again. At most one flip is in flight.
 *
 * drm_display_size() is the app's (logical) size for the life of the display: turned
 * when the configuration says the display is, and kept when a display comes back with
 * another mode. Then the picture is drawn offscreen at that size and shown turned and
 * scaled to fit (offscreen.c). While the seat is away (a VT switch) or the connector is
 * unplugged nothing can be drawn and the kiosk keeps running; once it is back,
 * drm_display_needs_frame() asks for a frame although the app did not change.
 */
struct drm_display;
struct display;

/* What a configuration may force; NULL / 0 fields are chosen automatically. */
struct drm_display_config {
	const char *card;      /* "/dev/dri/card1"; default: the first card that can modeset */
	const char *connector; /* "HDMI-A-1", "Virtual-1"; default: the first connected one */
	int width, height;     /* a mode of the connector; default: its preferred mode */
	int refresh;           /* Hz, with width/height; 0: any */
	int rotation;          /* how the display is turned, clockwise: 0, 90, 180, 270 */
};

/* The most fds drm_display_pollfds gives: the card, the seat, the hotplug monitor. */
#define DRM_DISPLAY_MAX_POLLFDS 3

/* Sets nothing on screen yet (the first present does the modeset). NULL, err says why. */
struct drm_display *drm_display_create(const struct drm_display_config *cfg, struct error *err);
/* The same as the kiosk loop's display (display.h). */
struct display *drm_display_open(const struct drm_display_config *cfg, struct error *err);
/* Puts back the CRTC's previous framebuffer and mode (a console, another program). */
void drm_display_destroy(struct drm_display *d);

/* Fills out (up to max) with the fds to poll for reading; returns how many. */
size_t drm_display_pollfds(const struct drm_display *d, struct pollfd *out, size_t max);
/* Handles what poll() returned for those fds (fds may hold others too: they are
 * skipped): page flips, seat switches, hotplug. 0, or a negative errno when the display
 * is broken for good. */
int drm_display_dispatch(struct drm_display *d, const struct pollfd *fds, size_t n);

void drm_display_size(const struct drm_display *d, int *width, int *height);
/* Card, connector, mode, how commits are made, how the card was opened, and the
 * picture when it is turned or scaled: "/dev/dri/card0 Virtual-1 1280x800@75 (atomic,
 * direct)". */
const char *drm_display_describe(const struct drm_display *d);
bool drm_display_gles3(const struct drm_display *d);

/* The seat is ours: no other VT (a console, another program) is in front. */
bool drm_display_seat_active(const struct drm_display *d);
/* The seat is ours, the connector is there and no flip is in flight. */
bool drm_display_can_draw(const struct drm_display *d);
/* The screen does not show our last frame (first frame, after a VT switch or a replug):
 * draw one even if nothing changed. */
bool drm_display_needs_frame(const struct drm_display *d);

/* Reads the frame drawn so far (before present) as RGBA at drm_display_size, top row
 * first, unturned. 0 or -EIO. */
int drm_display_read_rgba(struct drm_display *d, uint8_t *rgba);
/*
 * Shows what was drawn: after a modeset at once, else by a page flip on vblank. 0;
 * -EBUSY while a flip is pending; -ENODEV when the frame could not be shown because the
 * display went away or the seat did (said on stderr; drawing resumes when
 * drm_display_can_draw() is true again); another negative errno when broken for good.
 */
int drm_display_present(struct drm_display *d);
bool drm_display_flip_pending(const struct drm_display *d);
/* The loop's word that the pending flip is overdue: the display is taken as gone and its
 * connector probed again; if it is there, the next frame sets the mode anew. 0, or a
 * negative errno when the display is broken for good. */
int drm_display_flip_timeout(struct drm_display *d);
