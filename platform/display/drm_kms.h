/* SPDX-License-Identifier: MIT */
#pragma once

/*
 * KMS for the kiosk's one output: which connector, mode, CRTC and primary plane to use,
 * and putting a framebuffer on them. Atomic commits where the driver takes them (a
 * modeset tried with TEST_ONLY first, then one non-blocking flip a frame with a
 * page-flip event); the legacy SetCrtc/PageFlip calls where the driver refuses the
 * atomic capability or its test commit, or when the caller asks for them. No fences:
 * GL has finished a frame when eglSwapBuffers returns (Mesa's llvmpipe has no
 * eglDupNativeFenceFDANDROID).
 */
#include <stdbool.h>
#include <stdint.h>
#include <xf86drmMode.h>

#include "error.h"

struct drm_kms;

/* What to look for: NULL / 0 fields are chosen automatically. */
struct drm_kms_want {
	const char *connector; /* "HDMI-A-1"; NULL: the first connected one */
	int width, height;     /* a mode; 0: the preferred one */
	int refresh;           /* Hz, with width/height; 0: any */
	bool fallback;         /* the preferred mode when width x height is not offered */
};

/* The output in use. */
struct drm_kms_output {
	uint32_t connector_id, crtc_id, plane_id; /* plane_id 0 on the legacy path */
	drmModeModeInfo mode;
	char connector[32]; /* its name as modetest prints it: "Virtual-1" */
};

/*
 * Uses the card open in fd (not closed by destroy). With atomic, asks for the universal
 * planes and atomic capabilities; refused, the legacy calls are used. NULL: no memory.
 */
struct drm_kms *drm_kms_create(int fd, bool atomic);
/* Frees the mode blob; does not touch the screen (see drm_kms_restore). */
void drm_kms_destroy(struct drm_kms *k);

/*
 * Finds a connected connector, a mode of it, a CRTC that can drive it and (atomic) the
 * CRTC's primary plane with the property ids commits need. The first successful pick
 * also saves what the CRTC showed, for drm_kms_restore. 0; -ENODEV with why in err
 * (card names the card in it); another negative errno.
 */
int drm_kms_pick(struct drm_kms *k, const struct drm_kms_want *want, const char *card,
		 struct error *err);
const struct drm_kms_output *drm_kms_output(const struct drm_kms *k);
/* Whether commits go the atomic way (false after a failed test commit). */
bool drm_kms_atomic(const struct drm_kms *k);

/*
 * Shows fb (of the output's mode size) with a full modeset; the frame is on screen when
 * this returns and no flip event comes. An atomic test commit that the driver refuses
 * switches to the legacy calls for good (said on stderr). 0 or a negative errno.
 */
int drm_kms_modeset(struct drm_kms *k, uint32_t fb);
/* Queues fb for the next vblank; drmHandleEvent's page-flip handler gets data when it
 * is on screen. 0 or a negative errno (-EBUSY: a flip is still queued). */
int drm_kms_flip(struct drm_kms *k, uint32_t fb, void *data);
/* Puts back what the CRTC showed before the first pick (a console, another program). */
int drm_kms_restore(struct drm_kms *k);

/*
 * The mode to use out of a connector's list: width x height (at refresh Hz when
 * refresh > 0) when width > 0; else, or when that is not there and fallback is set, the
 * preferred mode (or the first listed one: drivers list the best first). NULL when
 * nothing fits.
 */
const drmModeModeInfo *drm_kms_pick_mode(const drmModeModeInfo *modes, int n, int width,
					 int height, int refresh, bool fallback);
