/* SPDX-License-Identifier: MIT */
#pragma once

/*
 * The export button on the kiosk: the drawing onto a USB stick (and a copy into
 * kiosk.export_dir), without ever blocking the main loop.
 *
 * Sticks come from the udev monitor (usb_monitor.c, in the kiosk's poll). Each one is
 * looked at when it comes (the helper mounts it, opens edaha/ and lets go of it again),
 * so the visitor hears at once whether it will do. On export the main thread builds the
 * files' bytes (export_set.c) and hands them to this module's thread, which asks
 * edaha-usb-helper to mount the stick, writes the set into the edaha/ fd it passes and
 * rewrites the gallery there (gallery.h: index.html), syncfs, closes, asks the helper to
 * eject, writes the local copy and its gallery, and reports back
 * through an eventfd in the kiosk's poll. A slow or dying stick blocks that thread only;
 * the stick is mounted only while a save is under way, so it may be pulled at any other
 * time.
 */
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "app.h"
#include "config_file.h"
#include "error.h"
#include "kiosk_source.h"
#include "usb_proto.h"

struct usb_export_config {
	bool usb;                  /* watch for sticks and save to them (usb.enabled) */
	const char *helper_socket; /* usb.helper_socket */
	const char *local_dir;     /* kiosk.export_dir, a copy of every export; NULL: none */
	double wind;               /* kiosk.wind: the .glb's sway; 0: the default breeze */
	enum config_language language; /* the words of the gallery, index.html */
	bool monitor;              /* false: no udev monitor, sticks come by usb_export_added */
	const char *sys_block;     /* NULL: /sys/class/block, where a stick is seen to be gone */
	/* tells the visitor (on the main thread): held until the next, while under way */
	void (*status)(void *data, enum app_status status, bool held);
	void *data;
};

struct usb_export;

/* NULL with a message when its thread cannot start; without udev it warns and runs
 * without sticks. */
struct usb_export *usb_export_create(const struct usb_export_config *cfg, struct error *err);
/* Waits for a save under way to end (its thread cannot be interrupted in a write). */
void usb_export_destroy(struct usb_export *ux);
/* What the kiosk polls: the udev monitor (with usb) and the thread's results. Up to 2. */
size_t usb_export_sources(struct usb_export *ux, struct kiosk_source *out, size_t max);
/* The export button: the drawing and its picture (rgba, app->screen's size; NULL: none)
 * are saved, and today's forest when forest holds its .glb (taken: left empty; NULL:
 * none) of the day forest_date ("YYYY-MM-DD"). Ignored (and said on stderr) while the
 * last one is being saved. */
void usb_export_start(struct usb_export *ux, const struct app *app, const uint8_t *rgba,
		      struct buf *forest, const char *forest_date);
/* A stick came (its kernel name) or went: what the monitor says; also for tests. */
void usb_export_added(struct usb_export *ux, const char *kname);
void usb_export_removed(struct usb_export *ux, const char *kname);
/* Whether a save is under way. */
bool usb_export_busy(const struct usb_export *ux);

/* The visitor's message for an outcome of saving to a stick. */
enum app_status usb_export_status_of(enum usb_outcome o);
