/* SPDX-License-Identifier: MIT */
/*
 * The kiosk's loop (kiosk.h): create and destroy, the poll set and the handler each fd's
 * wake-up goes to, and the decisions to draw (frame_due) and to wake (the UI timer). What
 * the handlers do is in kiosk_*.c, sharing struct kiosk (kiosk_private.h): a frame and its
 * figures (kiosk_frame.c); what a frame shows (kiosk_look.c); events into the app
 * (kiosk_feed.c); the grow press (kiosk_grow.c); export (kiosk_export.c); the journal and
 * the idle reset (kiosk_autosave.c); signals and the watchdog (kiosk_service.c).
 */
#include "kiosk_private.h"

#include <errno.h>
#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/timerfd.h>
#include <time.h>
#include <unistd.h>

#include "export_set.h"
#include "notify.h"

uint64_t kiosk_now_us(void)
{
	struct timespec ts;

	/* the clock libinput stamps events with, so that app times compare */
	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (uint64_t)ts.tv_sec * 1000000u + (uint64_t)ts.tv_nsec / 1000u;
}

/*
 * Whether the next vblank should show a new frame. A tree that moves by itself (the wind,
 * growing in) and nothing else new: at the display's rate, but no sooner than 1 /
 * max_fps after the last frame began; *timeout_ms (poll's, -1: none) is lowered to when
 * that is.
 */
static bool frame_due(const struct kiosk *k, int *timeout_ms)
{
	struct kiosk_look now;
	uint64_t t = kiosk_now_us(), next;

	/* the display asks for one when it came back (VT switch, replug) */
	if (k->cfg.frames || !k->drawn_valid || k->animating || k->export_asked ||
	    display_needs_frame(k->display))
		return true;
	kiosk_look_of(k->app, t, &now);
	if (!kiosk_look_equal(&now, &k->drawn))
		return true;
	if (!k->living)
		return false;
	next = kiosk_living_next_us(k);
	if (t >= next)
		return true;
	if (timeout_ms) {
		int ms = (int)((next - t + 999) / 1000);

		*timeout_ms = *timeout_ms < 0 || ms < *timeout_ms ? ms : *timeout_ms;
	}
	return false;
}

static void feed_from_display(void *data, const struct event *ev)
{
	kiosk_feed(data, ev);
}

struct kiosk *kiosk_create(const struct kiosk_config *cfg)
{
	struct kiosk *k = calloc(1, sizeof(*k));
	struct error err = { { 0 } };
	int w, h;

	if (!k) {
		fputs("edaha: out of memory\n", stderr);
		if (cfg->doc)
			doc_finish(cfg->doc);
		return NULL;
	}
	k->cfg = *cfg;
	k->signal_fd = k->timer_fd = k->ui_timer_fd = k->watchdog_fd = -1;
	k->ui_deadline_us = UINT64_MAX;
	k->mode_lit = (enum button)-1; /* tells the LEDs the first mode, whatever it is */
	k->start_us = kiosk_now_us();
	if (kiosk_open_signals(k) < 0) {
		fprintf(stderr, "edaha: cannot watch for signals: %s\n", strerror(errno));
		goto fail;
	}
	k->timer_fd = timerfd_create(CLOCK_MONOTONIC, TFD_NONBLOCK | TFD_CLOEXEC);
	k->ui_timer_fd = timerfd_create(CLOCK_MONOTONIC, TFD_NONBLOCK | TFD_CLOEXEC);
	if (k->timer_fd < 0 || k->ui_timer_fd < 0) {
		fprintf(stderr, "edaha: no timerfd: %s\n", strerror(errno));
		goto fail;
	}
	if (kiosk_open_watchdog(k) < 0) {
		fprintf(stderr, "edaha: no timerfd for the watchdog: %s\n", strerror(errno));
		goto fail;
	}
	k->display = display_create(&cfg->display, &err);
	if (!k->display) {
		fprintf(stderr, "edaha: no display: %s\n", err.msg);
		goto fail;
	}
	display_size(k->display, &w, &h);
	fprintf(stderr, "edaha: %s on %s, GLES %d\n",
		cfg->display.kind == DISPLAY_WINDOW ? "window" : "kiosk",
		display_describe(k->display), display_gles3(k->display) ? 3 : 2);
	/* a window's mouse and keys are the pen and the buttons */
	display_set_input(k->display, feed_from_display, k);
	k->render = render_create();
	if (k->render && render_set_text(k->render, cfg->font, cfg->font_len, cfg->language) < 0)
		fputs("edaha: warning: the labels' font cannot be used: icons only\n", stderr);
	k->cfg.font = NULL; /* the renderer's copy is the one that lasts */
	k->app = app_create(w, h, cfg->doc ? cfg->doc->seed : cfg->seed);
	if (k->app && kiosk_live_setup(k) < 0)
		goto fail;
	k->lat = calloc(1, sizeof(*k->lat));
	k->frame_time = calloc(1, sizeof(*k->frame_time));
	k->pending = calloc(KIOSK_MAX_PENDING, sizeof(*k->pending));
	k->inflight = calloc(KIOSK_MAX_PENDING, sizeof(*k->inflight));
	if (!k->render || !k->app || !k->lat || !k->frame_time || !k->pending || !k->inflight) {
		fputs("edaha: cannot set up the renderer\n", stderr);
		goto fail;
	}
	latency_init(k->lat);
	latency_init(k->frame_time);
	/* a drawing brought back grows in from the start, by the app's clock */
	k->app->last_time_us = k->start_us;
	if (cfg->doc) {
		if (app_load_doc(k->app, cfg->doc) < 0) {
			fputs("edaha: out of memory loading the drawing\n", stderr);
			goto fail;
		}
		k->cfg.doc = NULL; /* the app has it now */
	}
	if (cfg->state_dir && kiosk_start_autosave(k) < 0)
		goto fail;
	if (kiosk_forest_create(k) < 0) {
		fputs("edaha: out of memory starting today's forest\n", stderr);
		goto fail;
	}
	/* idle time counts from the start: a kiosk nobody uses shows its attract screen */
	k->app->attract_after_us = cfg->attract_after_us;
	k->app->last_time_us = k->start_us;
	if (cfg->screenshot && !(k->shot = malloc((size_t)w * (size_t)h * 4))) {
		fputs("edaha: out of memory\n", stderr);
		goto fail;
	}
	if (cfg->record && !(k->rec = trace_writer_create(cfg->record, w, h, &err))) {
		fprintf(stderr, "edaha: %s\n", err.msg);
		goto fail;
	}
	if (kiosk_open_usb(k) < 0)
		goto fail;
	k->grow = grow_worker_create(&err);
	if (!k->grow) {
		fprintf(stderr, "edaha: %s\n", err.msg);
		goto fail;
	}
	k->app->grow_async = true;
	return k;

fail:
	kiosk_destroy(k);
	return NULL;
}

void kiosk_destroy(struct kiosk *k)
{
	if (!k)
		return;
	if (k->rec && trace_writer_destroy(k->rec) < 0)
		fprintf(stderr, "edaha: %s: cannot write the recording\n", k->cfg.record);
	/* waits for a save under way: its files reach the stick whole or not at all */
	usb_export_destroy(k->usb);
	/* no set is being written any more: the page's scripts can go */
	export_set_page_default(NULL);
	page_viewer_finish(&k->page_viewer);
	grow_worker_destroy(k->grow); /* and for a press under way */
	kiosk_forest_destroy(k);       /* and for a planting */
	/* GL objects go while the display's context is still current */
	render_destroy(k->render);
	display_destroy(k->display);
	app_destroy(k->app);
	autosave_destroy(k->autosave);
	if (k->cfg.doc)
		doc_finish(k->cfg.doc);
	free(k->shot);
	free(k->pixels);
	free(k->lat);
	free(k->frame_time);
	free(k->pending);
	free(k->inflight);
	if (k->timer_fd >= 0)
		close(k->timer_fd);
	if (k->ui_timer_fd >= 0)
		close(k->ui_timer_fd);
	if (k->watchdog_fd >= 0)
		close(k->watchdog_fd);
	if (k->signal_fd >= 0)
		close(k->signal_fd);
	if (k->mask_set)
		sigprocmask(SIG_SETMASK, &k->old_mask, NULL);
	free(k);
}

int kiosk_add_source(struct kiosk *k, const struct kiosk_source *src)
{
	if (k->nsources >= KIOSK_MAX_SOURCES)
		return -ENOMEM;
	k->sources[k->nsources++] = *src;
	return 0;
}

void kiosk_set_mode_listener(struct kiosk *k, void (*fn)(void *data, enum button mode),
			     void *data)
{
	k->mode_changed = fn;
	k->mode_data = data;
}

void kiosk_size(const struct kiosk *k, int *width, int *height)
{
	display_size(k->display, width, height);
}

void kiosk_fail(struct kiosk *k, const char *what, int err)
{
	fprintf(stderr, "edaha: %s: %s\n", what, strerror(-err));
	k->status = 1;
	k->quit = true;
}

static void on_source(struct kiosk *k, size_t i)
{
	int ret = k->sources[i].dispatch(k->sources[i].data);

	if (ret < 0) {
		/* the others still work: drop this one and carry on */
		fprintf(stderr, "edaha: input source %zu failed (%s); ignoring it from now on\n", i,
			strerror(-ret));
		k->sources[i] = k->sources[--k->nsources];
	}
}

/* Things the app asks of the platform between frames. */
static void take_requests(struct kiosk *k)
{
	uint32_t req = app_take_requests(k->app);
	enum button mode = app_lit_button(k->app); /* the button whose LED says the mode */

	if (req & APP_REQUEST_EXPORT) {
		k->export_asked = true;
		k->export_forest = (req & APP_REQUEST_FOREST) != 0;
	}
	if ((req & APP_REQUEST_GROW) && !grow_worker_busy(k->grow))
		kiosk_start_grow(k);
	if (mode != k->mode_lit) {
		k->mode_lit = mode;
		if (k->mode_changed)
			k->mode_changed(k->mode_data, mode);
	}
	if (k->app->failed) {
		kiosk_fail(k, "the app failed", k->app->failed);
	}
	kiosk_archive_replaced(k);
	kiosk_save_edits(k);
}

/* Sets the UI timer for the next change nobody causes (a message fading, the attract
 * screen): the loop sleeps in poll() until then. */
static void arm_ui_timer(struct kiosk *k)
{
	uint64_t next = kiosk_next_change(k->app, kiosk_now_us(), k->cfg.reset_after_us);
	struct itimerspec it = { { 0, 0 }, { 0, 0 } };

	if (next == k->ui_deadline_us)
		return;
	k->ui_deadline_us = next;
	if (next != UINT64_MAX)
		it.it_value = (struct timespec){ (time_t)(next / 1000000u),
						 (long)(next % 1000000u) * 1000 };
	if (timerfd_settime(k->ui_timer_fd, TFD_TIMER_ABSTIME, &it, NULL) < 0)
		kiosk_fail(k, "timer", -errno);
}

static void on_ui_timer(struct kiosk *k)
{
	uint64_t expirations;

	/* frame_due() sees what else changed */
	if (read(k->ui_timer_fd, &expirations, sizeof(expirations)) == (ssize_t)sizeof(expirations))
		k->ui_deadline_us = UINT64_MAX;
	kiosk_idle_reset(k, kiosk_now_us());
}

int kiosk_run(struct kiosk *k)
{
	struct pollfd fds[DISPLAY_MAX_POLLFDS + 5 + KIOSK_MAX_SOURCES];

	take_requests(k); /* the LEDs show the first mode */
	while (!k->quit) {
		size_t n, nd, nsrc = k->nsources;
		int timeout = -1;

		/* nothing is drawn while a flip is in flight, the seat is away or the
		 * display unplugged */
		if (display_can_draw(k->display)) {
			if (k->cfg.frames && k->frames >= k->cfg.frames)
				break;
			if (frame_due(k, &timeout))
				kiosk_draw_frame(k);
			else
				k->npending = 0; /* pen events that changed nothing on the screen */
			if (k->export_ready)
				kiosk_run_export(k);
			if (k->quit)
				break;
			/* a modeset or a window's swap shows its frame at once: the next one is
			 * due now, but what came meanwhile is read first (poll without waiting),
			 * or an animation that lasts until an event (a grow press waiting for its
			 * worker) would never see it */
			if (display_can_draw(k->display) && (k->cfg.frames || frame_due(k, &timeout)))
				timeout = 0;
		}
		/* an export while the display is away goes without its picture */
		if (k->export_asked && !display_can_draw(k->display) &&
		    !display_flip_pending(k->display)) {
			k->export_asked = false;
			free(k->pixels);
			k->pixels = NULL;
			kiosk_run_export(k);
		}
		arm_ui_timer(k);
		n = nd = display_pollfds(k->display, fds, DISPLAY_MAX_POLLFDS);
		fds[n++] = (struct pollfd){ .fd = k->signal_fd, .events = POLLIN };
		fds[n++] = (struct pollfd){ .fd = k->timer_fd, .events = POLLIN };
		fds[n++] = (struct pollfd){ .fd = k->ui_timer_fd, .events = POLLIN };
		/* -1 without a watchdog: poll() skips it */
		fds[n++] = (struct pollfd){ .fd = k->watchdog_fd, .events = POLLIN };
		fds[n++] = (struct pollfd){ .fd = grow_worker_fd(k->grow), .events = POLLIN };
		for (size_t i = 0; i < nsrc; i++)
			fds[n++] = (struct pollfd){ .fd = k->sources[i].fd, .events = POLLIN };
		if (poll(fds, n, timeout) < 0) {
			if (errno != EINTR)
				kiosk_fail(k, "poll", -errno);
			continue;
		}
		if (fds[nd].revents)
			kiosk_on_signal(k);
		kiosk_on_display(k, fds, nd);
		if (fds[nd + 1].revents)
			kiosk_on_timer(k);
		if (fds[nd + 2].revents)
			on_ui_timer(k);
		if (fds[nd + 3].revents)
			kiosk_on_watchdog(k);
		if (fds[nd + 4].revents)
			kiosk_on_grow(k);
		/* backwards, so that dropping a failed source leaves the rest in place */
		for (size_t i = nsrc; i-- > 0;) {
			if (fds[nd + 5 + i].revents)
				on_source(k, i);
		}
		take_requests(k);
	}
	notify_stopping();
	kiosk_print_stats(k, stderr);
	if (k->cfg.stats)
		kiosk_print_stats(k, stdout);
	if (k->status == 0 && k->shot && !k->cfg.frames && k->frames && kiosk_take_final_shot(k) < 0)
		k->status = 1;
	if (k->status == 0 && k->shot && k->frames >= k->cfg.frames && k->frames &&
	    kiosk_write_screenshot(k) < 0)
		k->status = 1;
	return k->status;
}
