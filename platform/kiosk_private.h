/* SPDX-License-Identifier: MIT */
/*
 * What the kiosk's loop (kiosk.c) shares with the files that do its work: struct kiosk,
 * and each file's functions the others call. Not for use outside the kiosk's files.
 */
#pragma once

#include <poll.h>
#include <signal.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "app.h"
#include "app_mode.h"
#include "autosave.h"
#include "grow_worker.h"
#include "kiosk.h"
#include "latency.h"
#include "page_viewer.h"
#include "trace.h"
#include "usb_export.h"

#define KIOSK_MAX_SOURCES 16
/* Pen events waiting for the frame that shows them; a slow frame under a fast pen
 * drops the excess from the figures, not from the drawing. */
#define KIOSK_MAX_PENDING 1024

/* A place of the side strip as the screen shows it (ui/render_ui.c draws a parameter
 * button that would change nothing disabled). */
struct kiosk_side_look {
	bool thumbnail, lit, enabled;
	enum button button;
	int tap;
	const struct tree_mesh *preview;
};

/*
 * What a frame shows, apart from the clock: when none of it changed since the last
 * frame, the screen is already right and nothing is drawn.
 */
struct kiosk_look {
	uint64_t mesh_serial, previews_serial;
	size_t stroke_points;
	bool stroke_active, pen_in, orbiting, turning, ui_held, side_held;
	enum event_tool pen_tool;
	double pen_x, pen_y;
	enum app_mode mode;
	enum app_pattern pattern;
	bool buttons[BUTTON_COUNT];
	enum button ui_button;
	struct camera camera;
	int selected;
	unsigned suggestions;
	enum app_status status; /* the message on screen */
	bool attract;           /* the attract screen */
	bool forest;            /* ...showing today's forest */
	uint64_t forest_serial; /* the forest's scene (swapped in by kiosk_forest.c) */
	uint64_t status_number, forest_number; /* numbers the messages say */
	enum season season;     /* the season button's picture, the leaves' colours */
	size_t nside;           /* the side strip: what it holds, and how each place shows */
	struct kiosk_side_look side[APP_SIDE_MAX];
};

/* A pen event on its way to the screen: its kernel time, and frames shown before it. */
struct kiosk_pending {
	uint64_t time_us, shown;
};

struct kiosk {
	struct kiosk_config cfg;
	struct display *display;
	struct render *render;
	struct app *app;
	struct trace_writer *rec;
	struct kiosk_source sources[KIOSK_MAX_SOURCES];
	size_t nsources;
	int signal_fd, timer_fd;
	int ui_timer_fd;         /* wakes the loop when a message or the attract screen changes */
	int watchdog_fd;         /* the service's watchdog: pinged from the loop, -1 without */
	uint64_t ui_deadline_us; /* what it is set to; UINT64_MAX: nothing to wait for */
	sigset_t old_mask;
	bool mask_set;
	struct kiosk_look drawn; /* what the screen shows */
	bool drawn_valid;        /* false until the first frame */
	bool animating;          /* the last frame was a step of the 3D turn */
	bool living;             /* ...or the tree moved by itself (the wind, growing in) */
	bool quit;
	int status;
	/* counts and times for the log line at the end */
	unsigned long frames;
	uint64_t start_us, first_frame_us, last_frame_us;
	uint8_t *shot; /* the last frame's pixels, with --screenshot */
	/* pen-to-screen latency: events not drawn yet, events in the frame being flipped */
	struct latency *lat;
	struct latency *frame_time; /* from starting to draw a frame to it being on screen */
	uint64_t frame_start_us;
	struct kiosk_pending *pending, *inflight;
	size_t npending, ninflight;
	uint64_t shown;          /* frames that reached the screen */
	uint64_t stats_logged_us, stats_logged_n;
	/* export: asked for; the next frame is read back for its picture, then written */
	bool export_asked, export_ready;
	bool export_forest; /* ...of today's forest too: Save pressed while it was on screen */
	uint8_t *pixels;
	struct usb_export *usb;  /* where the export goes: sticks, the local copy */
	struct page_viewer page_viewer; /* the take-home page's scripts, read at start */
	struct grow_worker *grow; /* grow presses, off the loop */
	/* the press's start, and frames drawn and shown by then */
	uint64_t grow_started_us, grow_frames, grow_shown;
	struct autosave *autosave; /* NULL: none */
	struct kiosk_forest *forest; /* today's forest (kiosk_forest.c); NULL: off */
	bool autosave_failing;     /* said once, not at every stroke */
	enum button mode_lit;    /* what mode_changed was last told */
	void (*mode_changed)(void *data, enum button mode);
	void *mode_data;
};

/* kiosk.c */
uint64_t kiosk_now_us(void);
void kiosk_fail(struct kiosk *k, const char *what, int err);

/* kiosk_look.c */
void kiosk_look_of(const struct app *app, uint64_t now_us, struct kiosk_look *l);
bool kiosk_look_equal(const struct kiosk_look *a, const struct kiosk_look *b);
bool kiosk_animating_at(const struct app *app, uint64_t now_us, bool turning);
uint64_t kiosk_reset_at(const struct app *app, uint64_t reset_after_us);
uint64_t kiosk_next_change(const struct app *app, uint64_t now_us, uint64_t reset_after_us);

/* kiosk_live.c: the wind and growing in from the configuration (0, or -ENOMEM: said);
 * when the next frame of a tree moving by itself is due (max_fps after the last began). */
int kiosk_live_setup(struct kiosk *k);
uint64_t kiosk_living_next_us(const struct kiosk *k);

/* kiosk_frame.c */
void kiosk_draw_frame(struct kiosk *k);
void kiosk_on_display(struct kiosk *k, const struct pollfd *fds, size_t n);
void kiosk_on_timer(struct kiosk *k);
int kiosk_write_screenshot(struct kiosk *k);
void kiosk_print_stats(struct kiosk *k, FILE *f);
int kiosk_take_final_shot(struct kiosk *k);

/* kiosk_grow.c */
void kiosk_start_grow(struct kiosk *k);
void kiosk_on_grow(struct kiosk *k);

/* kiosk_export.c */
int kiosk_open_usb(struct kiosk *k);
void kiosk_run_export(struct kiosk *k);

/* kiosk_autosave.c */
int kiosk_start_autosave(struct kiosk *k);
void kiosk_save_edits(struct kiosk *k);
/* New after something was drawn: that drawing, as it stood, goes to the archive. */
void kiosk_archive_replaced(struct kiosk *k);
void kiosk_idle_reset(struct kiosk *k, uint64_t now);

/* kiosk_forest.c: today's forest (docs/forest.md), with forest.enabled and autosave on:
 * planted at the start and after every archived drawing, on a thread of its own. */
int kiosk_forest_create(struct kiosk *k); /* 0 (off when it cannot run: said) or -ENOMEM */
void kiosk_forest_destroy(struct kiosk *k);
void kiosk_forest_refresh(struct kiosk *k);
/* The number the drawing on the canvas will have in today's forest when archived (0:
 * no forest, or not known yet). */
uint64_t kiosk_forest_number(const struct kiosk *k);
/* A drawing archived under name: planted; its number in the day (0: no forest, or not
 * known yet: with tell, said by kiosk_forest_tell once the forest's first job is done). */
uint64_t kiosk_forest_archived(struct kiosk *k, const char *name, bool tell);
/* "Your tree is No. number in today's forest", on the screen and in the journal. */
void kiosk_forest_tell(struct kiosk *k, uint64_t number);
/* Save on the forest: forest.glb's bytes (every standing tree at full detail, placed as
 * on screen, with its wind) into out, and the day's date "YYYY-MM-DD" (local time) into
 * date. 0, -ENODATA (no tree stands) or -ENOMEM. */
int kiosk_forest_glb(struct kiosk *k, struct buf *out, char date[11]);

/* kiosk_service.c */
int kiosk_open_signals(struct kiosk *k);
int kiosk_open_watchdog(struct kiosk *k);
void kiosk_on_signal(struct kiosk *k);
void kiosk_on_watchdog(struct kiosk *k);
