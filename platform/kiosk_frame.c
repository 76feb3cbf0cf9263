/* SPDX-License-Identifier: MIT */
/* A frame: drawn, read back for an export or a screenshot, presented, and seen on the
 * screen at its flip (or its flip's timeout); the pen-to-screen and frame-time figures it
 * makes, and the screenshot and figures at the end of a run. */
#include "kiosk_private.h"

#include <errno.h>
#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/timerfd.h>
#include <unistd.h>

#include "buf.h"
#include "fileio.h"
#include "notify.h"
#include "pngio.h"

/* A flip that has not completed in this long will not: the display is gone (it is
 * probed again, and the kiosk goes on). */
#define KIOSK_FLIP_TIMEOUT_MS 1000
/* How often the journal gets the pen-to-screen figures while visitors draw. */
#define KIOSK_STATS_LOG_US (300u * 1000000u)

static int set_timer(struct kiosk *k, int ms)
{
	struct itimerspec it = { .it_value = { ms / 1000, (long)(ms % 1000) * 1000000 } };

	return timerfd_settime(k->timer_fd, 0, &it, NULL) < 0 ? -errno : 0;
}

static void log_latency(struct kiosk *k, FILE *f)
{
	char line[256];

	latency_format(k->lat, line, sizeof(line));
	fprintf(f, "edaha: %s\n", line);
	k->stats_logged_n = k->lat->n;
}

/* A frame reached the screen at now: the pen events it carried have their latency. */
static void frame_shown(struct kiosk *k, uint64_t now)
{
	k->shown++;
	k->last_frame_us = now;
	if (k->shown == 1)
		notify_ready(); /* the visitor sees the kiosk: the service is up */
	latency_add(k->frame_time, now - k->frame_start_us, 1);
	for (size_t i = 0; i < k->ninflight; i++) {
		const struct kiosk_pending *e = &k->inflight[i];

		/* a timestamp from the future (a clock mismatch) counts as no wait */
		latency_add(k->lat, now > e->time_us ? now - e->time_us : 0,
			    (unsigned)(k->shown - e->shown));
	}
	k->ninflight = 0;
	if (k->lat->n > k->stats_logged_n && now - k->stats_logged_us >= KIOSK_STATS_LOG_US) {
		k->stats_logged_us = now;
		log_latency(k, stderr);
	}
}

void kiosk_draw_frame(struct kiosk *k)
{
	uint64_t t = kiosk_now_us();
	struct camera cam;
	bool last = k->cfg.frames && k->frames + 1 == k->cfg.frames;
	size_t room, n;
	int ret;

	k->frame_start_us = t;
	/* a vine planted grows by the clock, as the turn into 3D turns */
	k->animating = app_vines_advance(k->app, t);
	k->animating = kiosk_animating_at(k->app, t, app_camera_at(k->app, t, &cam)) || k->animating;
	/* the wind or a growth: frames keep coming at the display's rate, up to max_fps */
	/* today's forest on the attract screen counts: its camera travels (app_live_at) */
	k->living = app_live_at(k->app, t, NULL);
	kiosk_look_of(k->app, t, &k->drawn);
	k->drawn_valid = true;
	ret = render_frame_at(k->render, k->app, t);
	if (ret == 0 && last && k->shot)
		ret = display_read_rgba(k->display, k->shot);
	if (ret == 0 && k->export_asked) {
		int w, h;

		/* the export's picture is the frame the visitor sees as the button is pressed */
		kiosk_size(k, &w, &h);
		if (!k->pixels)
			k->pixels = malloc((size_t)w * (size_t)h * 4);
		if (k->pixels && display_read_rgba(k->display, k->pixels) < 0) {
			fputs("edaha: export: cannot read the screen back; no picture\n", stderr);
			free(k->pixels);
			k->pixels = NULL;
		}
		k->export_asked = false;
		k->export_ready = true;
	}
	if (ret == 0)
		ret = display_present(k->display);
	if (ret == -ENODEV)
		return; /* not shown: the display said why; it asks for a frame when back */
	if (ret == 0 && display_flip_pending(k->display))
		ret = set_timer(k, KIOSK_FLIP_TIMEOUT_MS);
	if (ret < 0) {
		kiosk_fail(k, "cannot show a frame", ret);
		return;
	}
	/* the pen events so far are in this frame */
	room = KIOSK_MAX_PENDING - k->ninflight;
	n = k->npending < room ? k->npending : room;
	memcpy(k->inflight + k->ninflight, k->pending, n * sizeof(*k->pending));
	k->ninflight += n;
	k->npending = 0;
	k->frames++;
	/* a modeset shows its frame at once, with no flip event */
	if (!display_flip_pending(k->display))
		frame_shown(k, kiosk_now_us());
	if (k->frames == 1) {
		k->first_frame_us = kiosk_now_us();
		/* the kiosk is up: a line for the journal (and for tests to wait on) */
		fprintf(stderr, "edaha: first frame on screen %.1f ms after start\n",
			(double)(k->first_frame_us - k->start_us) / 1000.0);
	}
}

/* Page flips, seat switches and hotplug events on the display's fds. */
void kiosk_on_display(struct kiosk *k, const struct pollfd *fds, size_t n)
{
	bool pending = display_flip_pending(k->display);
	int ret = display_dispatch(k->display, fds, n);

	if (ret < 0) {
		kiosk_fail(k, "display", ret);
		return;
	}
	if (pending && !display_flip_pending(k->display)) {
		frame_shown(k, kiosk_now_us());
		ret = set_timer(k, 0); /* disarms the flip watchdog */
		if (ret < 0)
			kiosk_fail(k, "timer", ret);
	}
}

void kiosk_on_timer(struct kiosk *k)
{
	uint64_t expirations;

	if (read(k->timer_fd, &expirations, sizeof(expirations)) < 0)
		return; /* spurious wake-up (EAGAIN): nothing expired */
	if (display_flip_pending(k->display)) {
		int ret = display_flip_timeout(k->display);

		if (ret < 0)
			kiosk_fail(k, "display", ret);
	}
}

int kiosk_write_screenshot(struct kiosk *k)
{
	struct error err = { { 0 } };
	struct buf png;
	char *dir = strdup(k->cfg.screenshot), *slash;
	const char *name;
	int w, h, ret = -ENOMEM;

	if (!dir) {
		fputs("edaha: out of memory\n", stderr);
		return -ENOMEM;
	}
	/* fileio writes a name inside a directory, atomically */
	slash = strrchr(dir, '/');
	if (slash) {
		*slash = '\0';
		name = slash + 1;
	} else {
		name = dir;
	}
	buf_init(&png);
	kiosk_size(k, &w, &h);
	ret = pngio_encode_rgba(k->shot, w, h, &png, &err);
	if (ret == 0)
		ret = fileio_write_atomic(slash ? (dir[0] ? dir : "/") : ".", name, png.data, png.len,
					  &err);
	if (ret < 0)
		fprintf(stderr, "edaha: screenshot: %s\n", err.msg);
	buf_finish(&png);
	free(dir);
	return ret;
}

void kiosk_print_stats(struct kiosk *k, FILE *f)
{
	double first_ms = (double)(k->first_frame_us - k->start_us) / 1000.0;

	if (!k->frames)
		return;
	/* a still kiosk draws only on change: frames/s means something with --kiosk-frames
	 * or while the tree moves by itself (the wind) */
	fprintf(f, "edaha: %lu frame%s; first on screen %.1f ms after start", k->frames,
		k->frames == 1 ? "" : "s", first_ms);
	if ((k->cfg.frames || k->app->live.strength > 0.0) && k->frames > 1 &&
	    k->last_frame_us > k->first_frame_us)
		fprintf(f, "; %.1f frames/s after it",
			(double)(k->frames - 1) * 1e6 / (double)(k->last_frame_us - k->first_frame_us));
	fprintf(f, "; drawing to on screen: median %.1f ms, p90 %.1f ms, max %.1f ms\n",
		(double)latency_percentile(k->frame_time, 0.5) / 1000.0,
		(double)latency_percentile(k->frame_time, 0.9) / 1000.0,
		(double)k->frame_time->max_us / 1000.0);
	log_latency(k, f);
}

/* The screen as it is now, for --screenshot when the kiosk stops (not shown: read). */
int kiosk_take_final_shot(struct kiosk *k)
{
	int ret = render_frame_at(k->render, k->app, kiosk_now_us());

	if (ret == 0)
		ret = display_read_rgba(k->display, k->shot);
	if (ret < 0)
		fprintf(stderr, "edaha: screenshot: cannot read the screen: %s\n", strerror(-ret));
	return ret;
}
