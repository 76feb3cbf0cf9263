/* SPDX-License-Identifier: MIT */
#pragma once

#include <stdbool.h>
#include <stdint.h>

#include "error.h"

/*
 * The kiosk's screen: a DRM/KMS output driven by legacy modesetting, a GBM surface and
 * a GLES context (3.0 when the driver has it, else 2.0) drawing into it through EGL's
 * GBM platform. One frame: draw into the bound default framebuffer, then
 * drm_display_present(); the frame is on screen when the DRM fd has been dispatched
 * and drm_display_flip_pending() is false again. At most one flip is in flight.
 */
struct drm_display;

/* What a configuration may force; NULL / 0 fields are chosen automatically. */
struct drm_display_config {
	const char *card;      /* "/dev/dri/card1"; default: the first card that can modeset */
	const char *connector; /* "HDMI-A-1", "Virtual-1"; default: the first connected one */
	int width, height;     /* a mode of the connector; default: its preferred mode */
	int refresh;           /* Hz, with width/height; 0: any */
};

/* Sets nothing on screen yet (the first present does the modeset). NULL, err says why. */
struct drm_display *drm_display_create(const struct drm_display_config *cfg, struct error *err);
/* Puts back the CRTC's previous framebuffer and mode (a console, another program). */
void drm_display_destroy(struct drm_display *d);

/* The fd to poll for page-flip events. */
int drm_display_fd(const struct drm_display *d);
void drm_display_size(const struct drm_display *d, int *width, int *height);
/* Card, connector and mode, for the log: "card0 Virtual-1 1280x800@75". */
const char *drm_display_describe(const struct drm_display *d);
bool drm_display_gles3(const struct drm_display *d);

/* Reads the frame drawn so far (before present) as RGBA, top row first. 0 or -EIO. */
int drm_display_read_rgba(struct drm_display *d, uint8_t *rgba);
/* Shows what was drawn: the first time by a modeset, then by a page flip on vblank.
 * -EBUSY while a flip is pending; 0; or a negative errno. */
int drm_display_present(struct drm_display *d);
bool drm_display_flip_pending(const struct drm_display *d);
/* Reads the DRM fd's events when it is readable. 0 or a negative errno. */
int drm_display_dispatch(struct drm_display *d);
