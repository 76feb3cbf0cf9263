/* SPDX-License-Identifier: MIT */
#pragma once

#include <stdbool.h>
#include <stdint.h>

#include "doc.h"
#include "display.h"
#include "event.h"
#include "kiosk_source.h"
#include "render.h"

/*
 * The kiosk's main loop: one poll() over the display's fds (DRM, seat, hotplug; or a
 * desktop window's connection: display.h), the
 * input sources, a timerfd and a signalfd (SIGINT, SIGTERM). A frame is drawn only when
 * what the app shows changed (or the 3D turn animates, or the display came back from a
 * VT switch or a replug) and only when the display can take one: at most one frame a
 * vblank, none while nothing happens, none while the display is away.
 */
struct kiosk;

/* The most frames a second the kiosk draws while the tree moves by itself (kiosk.max_fps). */
#define KIOSK_MAX_FPS_DEFAULT 30u

struct kiosk_config {
	struct display_config display; /* which display, and its settings */
	uint64_t seed;          /* of a new drawing */
	struct doc *doc;        /* a drawing to continue, taken (even on failure); NULL: new */
	const char *record;     /* write every event fed as an edaha trace; NULL: no */
	const char *export_dir; /* a copy of every export (usb_export.h); NULL or "": none */
	bool usb;               /* export to USB sticks through edaha-usb-helper */
	const char *usb_socket; /* the helper's socket */
	uint64_t attract_after_us; /* idle time before the attract screen; 0: never */
	/* Autosave (autosave.h): the journal and archive's directory, NULL: none. A drawing
	 * in the journal comes back unless doc is given. */
	const char *state_dir;
	uint64_t reset_after_us; /* idle time before the drawing is archived and cleared; 0: never */
	unsigned archive_keep;   /* archived drawings kept; 0: all */
	bool stats;             /* print the responsiveness figures on stdout at the end */
	/* Test runs: draw a frame every vblank as if the app changed each time, and stop
	 * after this many frames are on screen (0: run until a signal). */
	unsigned long frames;
	/* The last frame as a PNG: with frames, after them; otherwise the screen as it was
	 * when the kiosk stopped (a signal). */
	const char *screenshot;
	/* The living tree (docs/living-trees.md): the wind's strength, 0..1 (0 still; below
	 * 0: LIVE_WIND_DEFAULT_STRENGTH, a breeze); whether trees grow in when they become 3D
	 * (grow_in_off: not); while the tree moves the kiosk draws at the display's rate, at
	 * most max_fps frames a second (0: KIOSK_MAX_FPS_DEFAULT). */
	double wind;
	bool grow_in_off;
	unsigned max_fps;
	/* Today's forest on the attract screen (docs/forest.md; needs state_dir): at most
	 * forest_max trees (0: FOREST_MAX_TREES_DEFAULT), a new day at the local time
	 * forest_reset_hour:forest_reset_minute. */
	bool forest;
	unsigned forest_max;
	int forest_reset_hour, forest_reset_minute;
	enum render_lang language; /* of the words on the screen */
	const void *font;       /* the labels' font file's bytes, NULL: icons alone; */
	size_t font_len;        /* the renderer keeps a copy */
};

/* Opens the display and makes the app at the display's size. NULL (message printed). */
struct kiosk *kiosk_create(const struct kiosk_config *cfg);
void kiosk_destroy(struct kiosk *k);
/* Polls src->fd from now on (copied). 0 or -ENOMEM. */
int kiosk_add_source(struct kiosk *k, const struct kiosk_source *src);
/* Told at the start and whenever the mode shown changes (the GPIO LEDs follow it):
 * BUTTON_3D for a 3D tree being sketched on, BUTTON_CLONE/LEAF/PROPAGATE, BUTTON_COUNT
 * for a 2D sketch. */
void kiosk_set_mode_listener(struct kiosk *k, void (*fn)(void *data, enum button mode),
			     void *data);
/* Screen size (as the viewer sees it, turned), so that input can map a tablet onto it. */
void kiosk_size(const struct kiosk *k, int *width, int *height);
/* For sources' dispatch: one event into the app (and the recording). */
void kiosk_feed(struct kiosk *k, const struct event *ev);
/* Runs until SIGINT/SIGTERM, the frame count, or a failure. Exit status: 0 or 1. */
int kiosk_run(struct kiosk *k);
