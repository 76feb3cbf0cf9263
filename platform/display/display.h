/* SPDX-License-Identifier: MIT */
#pragma once

#include <poll.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "drm_display.h"
#include "error.h"
#include "event.h"
#include "window_display_config.h"

/*
 * What the kiosk loop (kiosk.c) draws on, behind one interface: the DRM/KMS screen of
 * the kiosk (drm_display.c) or a window on a desktop (window_display.c, SDL2). Every
 * operation means what drm_display.h says of its drm_display_* namesake; a display
 * without page flips (a window: its swap returns when the frame is taken) never has a
 * flip pending, and one without a seat is always active.
 *
 * A display may bring its own input (a window: its mouse, touch and keys). It feeds
 * those events, stamped with CLOCK_MONOTONIC, through the function set_input gave it,
 * from display_dispatch on the loop's thread.
 */
struct display;

typedef void (*display_feed_fn)(void *data, const struct event *ev);

struct display_ops {
	void (*destroy)(struct display *d);
	size_t (*pollfds)(const struct display *d, struct pollfd *out, size_t max);
	int (*dispatch)(struct display *d, const struct pollfd *fds, size_t n);
	void (*size)(const struct display *d, int *width, int *height);
	const char *(*describe)(const struct display *d);
	bool (*gles3)(const struct display *d);
	bool (*seat_active)(const struct display *d);
	bool (*can_draw)(const struct display *d);
	bool (*needs_frame)(const struct display *d);
	int (*read_rgba)(struct display *d, uint8_t *rgba);
	int (*present)(struct display *d);
	bool (*flip_pending)(const struct display *d);
	int (*flip_timeout)(struct display *d);
	/* NULL: the display has no input of its own */
	void (*set_input)(struct display *d, display_feed_fn feed, void *data);
};

/* The first member of every display implementation. */
struct display {
	const struct display_ops *ops;
};

enum display_kind {
	DISPLAY_DRM,    /* the kiosk: fullscreen on DRM/KMS */
	DISPLAY_WINDOW, /* a window on a Wayland or X11 desktop */
};

struct display_config {
	enum display_kind kind;
	struct drm_display_config drm;
	struct window_display_config window;
};

/* The most fds display_pollfds gives, whichever the display. */
#define DISPLAY_MAX_POLLFDS 3

/* Whether this build has that kind of display. */
bool display_available(enum display_kind kind);
/* NULL, err says why (also when the build lacks that kind). */
struct display *display_create(const struct display_config *cfg, struct error *err);

static inline void display_destroy(struct display *d)
{
	if (d)
		d->ops->destroy(d);
}

static inline size_t display_pollfds(const struct display *d, struct pollfd *out, size_t max)
{
	return d->ops->pollfds(d, out, max);
}

static inline int display_dispatch(struct display *d, const struct pollfd *fds, size_t n)
{
	return d->ops->dispatch(d, fds, n);
}

static inline void display_size(const struct display *d, int *width, int *height)
{
	d->ops->size(d, width, height);
}

static inline const char *display_describe(const struct display *d)
{
	return d->ops->describe(d);
}

static inline bool display_gles3(const struct display *d)
{
	return d->ops->gles3(d);
}

static inline bool display_seat_active(const struct display *d)
{
	return d->ops->seat_active(d);
}

static inline bool display_can_draw(const struct display *d)
{
	return d->ops->can_draw(d);
}

static inline bool display_needs_frame(const struct display *d)
{
	return d->ops->needs_frame(d);
}

static inline int display_read_rgba(struct display *d, uint8_t *rgba)
{
	return d->ops->read_rgba(d, rgba);
}

static inline int display_present(struct display *d)
{
	return d->ops->present(d);
}

static inline bool display_flip_pending(const struct display *d)
{
	return d->ops->flip_pending(d);
}

static inline int display_flip_timeout(struct display *d)
{
	return d->ops->flip_timeout(d);
}

static inline void display_set_input(struct display *d, display_feed_fn feed, void *data)
{
	if (d->ops->set_input)
		d->ops->set_input(d, feed, data);
}
