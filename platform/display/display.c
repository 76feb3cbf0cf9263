/* SPDX-License-Identifier: MIT */
#include "display.h"

#include <errno.h>

#include "config.h"
#if HAVE_DRM
#include "drm_display.h"
#endif
#if HAVE_WINDOW
#include "window_display.h"
#endif

bool display_available(enum display_kind kind)
{
	switch (kind) {
	case DISPLAY_DRM:
		return HAVE_DRM;
	case DISPLAY_WINDOW:
		return HAVE_WINDOW;
	}
	return false;
}

struct display *display_create(const struct display_config *cfg, struct error *err)
{
	switch (cfg->kind) {
	case DISPLAY_DRM:
#if HAVE_DRM
		return drm_display_open(&cfg->drm, err);
#else
		(void)error_set(err, -ENOTSUP, "this build has no DRM/KMS display (libdrm, gbm)");
		return NULL;
#endif
	case DISPLAY_WINDOW:
#if HAVE_WINDOW
		return window_display_create(&cfg->window, err);
#else
		(void)error_set(err, -ENOTSUP, "this build has no window (SDL2)");
		return NULL;
#endif
	}
	(void)error_set(err, -ENOTSUP, "no such display");
	return NULL;
}
