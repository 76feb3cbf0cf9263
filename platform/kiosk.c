/* SPDX-License-Identifier: MIT */
#include "kiosk.h"

#include <errno.h>
#include <poll.h>
#include <signal.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/signalfd.h>
#include <sys/timerfd.h>
#include <time.h>
#include <unistd.h>

#include "app.h"
#include "buf.h"
#include "fileio.h"
#include "pngio.h"
#include "render.h"
#include "trace.h"

/* A flip that has not completed in this long will not: the display is gone (it is
 * probed again, and the kiosk goes on). */
#define KIOSK_FLIP_TIMEOUT_MS 1000
#define KIOSK_MAX_SOURCES 16

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
};

struct kiosk {
	struct kiosk_config cfg;
	struct drm_display *display;
	struct render *render;
	struct app *app;
	struct trace_writer *rec;
	struct kiosk_source sources[KIOSK_MAX_SOURCES];
	size_t nsources;
	int signal_fd, timer_fd;
	sigset_t old_mask;
	bool mask_set;
	struct kiosk_look drawn; /* what the screen shows */
	bool drawn_valid;        /* false until the first frame */
	bool animating;          /* the last frame was a step of the 3D turn */
	bool quit;
	int status;
	/* counts and times for the log line at the end */
	unsigned long frames;
	uint64_t start_us, first_frame_us, last_frame_us;
	uint8_t *shot; /* the last frame's pixels, with --screenshot */
};

static uint64_t now_us(void)
{
	struct timespec ts;

	/* the clock libinput stamps events with, so that app times compare */
	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (uint64_t)ts.tv_sec * 1000000u + (uint64_t)ts.tv_nsec / 1000u;
}

static void look_of(const struct app *app, struct kiosk_look *l)
{
	memset(l, 0, sizeof(*l)); /* padding too, though only fields are compared */
	l->mesh_serial = app->mesh_serial;
	l->previews_serial = app->previews_serial;
	l->stroke_points = app->stroke.npoints;
	l->stroke_active = app->stroke.active;
	l->pen_in = app->pen.in_proximity;
	l->pen_tool = app->pen.tool;
	l->pen_x = app->pen.x;
	l->pen_y = app->pen.y;
	l->orbiting = app->orbiting;
	l->turning = app->turning;
	l->ui_held = app->ui_button_held;
	l->ui_button = app->ui_button;
	l->side_held = app->side_held;
	l->mode = app->mode;
	l->pattern = app->pattern;
	memcpy(l->buttons, app->buttons_down, sizeof(l->buttons));
	l->camera = app->camera;
	l->selected = app->selected;
	l->suggestions = app->suggestions;
}

static bool look_equal(const struct kiosk_look *a, const struct kiosk_look *b)
{
	return a->mesh_serial == b->mesh_serial && a->previews_serial == b->previews_serial &&
	       a->stroke_points == b->stroke_points && a->stroke_active == b->stroke_active &&
	       a->pen_in == b->pen_in && a->pen_tool == b->pen_tool && a->pen_x == b->pen_x &&
	       a->pen_y == b->pen_y && a->orbiting == b->orbiting && a->turning == b->turning &&
	       a->ui_held == b->ui_held && a->ui_button == b->ui_button &&
	       a->side_held == b->side_held && a->mode == b->mode && a->pattern == b->pattern &&
	       memcmp(a->buttons, b->buttons, sizeof(a->buttons)) == 0 &&
	       a->camera.yaw == b->camera.yaw && a->camera.pitch == b->camera.pitch &&
	       a->selected == b->selected && a->suggestions == b->suggestions;
}

/* Whether the next vblank should show a new frame. */
static bool frame_due(const struct kiosk *k)
{
	struct kiosk_look now;

	/* the display asks for one when it came back (VT switch, replug) */
	if (k->cfg.frames || !k->drawn_valid || k->animating || drm_display_needs_frame(k->display))
		return true;
	look_of(k->app, &now);
	return !look_equal(&now, &k->drawn);
}

static int open_signals(struct kiosk *k)
{
	sigset_t mask;

	/* blocked before the display opens: GL driver threads inherit the mask, so the
	 * signals wait for our signalfd instead of landing in a random thread */
	sigemptyset(&mask);
	sigaddset(&mask, SIGINT);
	sigaddset(&mask, SIGTERM);
	if (sigprocmask(SIG_BLOCK, &mask, &k->old_mask) < 0)
		return -errno;
	k->mask_set = true;
	k->signal_fd = signalfd(-1, &mask, SFD_NONBLOCK | SFD_CLOEXEC);
	return k->signal_fd < 0 ? -errno : 0;
}

static int set_timer(struct kiosk *k, int ms)
{
	struct itimerspec it = { .it_value = { ms / 1000, (long)(ms % 1000) * 1000000 } };

	return timerfd_settime(k->timer_fd, 0, &it, NULL) < 0 ? -errno : 0;
}

struct kiosk *kiosk_create(const struct kiosk_config *cfg)
{
	struct kiosk *k = calloc(1, sizeof(*k));
	struct error err = { { 0 } };
	int w, h;

	if (!k) {
		fputs("edaha: out of memory\n", stderr);
		return NULL;
	}
	k->cfg = *cfg;
	k->signal_fd = k->timer_fd = -1;
	k->start_us = now_us();
	if (open_signals(k) < 0) {
		fprintf(stderr, "edaha: cannot watch for signals: %s\n", strerror(errno));
		goto fail;
	}
	k->timer_fd = timerfd_create(CLOCK_MONOTONIC, TFD_NONBLOCK | TFD_CLOEXEC);
	if (k->timer_fd < 0) {
		fprintf(stderr, "edaha: no timerfd: %s\n", strerror(errno));
		goto fail;
	}
	k->display = drm_display_create(&cfg->display, &err);
	if (!k->display) {
		fprintf(stderr, "edaha: no display: %s\n", err.msg);
		goto fail;
	}
	drm_display_size(k->display, &w, &h);
	fprintf(stderr, "edaha: kiosk on %s, GLES %d\n", drm_display_describe(k->display),
		drm_display_gles3(k->display) ? 3 : 2);
	k->render = render_create();
	k->app = app_create(w, h, cfg->seed);
	if (!k->render || !k->app) {
		fputs("edaha: cannot set up the renderer\n", stderr);
		goto fail;
	}
	if (cfg->screenshot && !(k->shot = malloc((size_t)w * (size_t)h * 4))) {
		fputs("edaha: out of memory\n", stderr);
		goto fail;
	}
	if (cfg->record && !(k->rec = trace_writer_create(cfg->record, w, h, &err))) {
		fprintf(stderr, "edaha: %s\n", err.msg);
		goto fail;
	}
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
	/* GL objects go while the display's context is still current */
	render_destroy(k->render);
	drm_display_destroy(k->display);
	app_destroy(k->app);
	free(k->shot);
	if (k->timer_fd >= 0)
		close(k->timer_fd);
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

void kiosk_size(const struct kiosk *k, int *width, int *height)
{
	drm_display_size(k->display, width, height);
}

void kiosk_feed(struct kiosk *k, const struct event *ev)
{
	if (k->rec && trace_writer_write(k->rec, ev) < 0) {
		fprintf(stderr, "edaha: %s: cannot write the recording; recording stops\n",
			k->cfg.record);
		if (trace_writer_destroy(k->rec) < 0)
			fprintf(stderr, "edaha: %s: cannot write the recording\n", k->cfg.record);
		k->rec = NULL;
	}
	app_handle_event(k->app, ev);
}

static void fail(struct kiosk *k, const char *what, int err)
{
	fprintf(stderr, "edaha: %s: %s\n", what, strerror(-err));
	k->status = 1;
	k->quit = true;
}

static void draw_frame(struct kiosk *k)
{
	uint64_t t = now_us();
	struct camera cam;
	bool last = k->cfg.frames && k->frames + 1 == k->cfg.frames;
	int ret;

	k->animating = app_camera_at(k->app, t, &cam);
	look_of(k->app, &k->drawn);
	k->drawn_valid = true;
	ret = render_frame_at(k->render, k->app, t);
	if (ret == 0 && last && k->shot)
		ret = drm_display_read_rgba(k->display, k->shot);
	if (ret == 0)
		ret = drm_display_present(k->display);
	if (ret == -ENODEV)
		return; /* not shown: the display said why; it asks for a frame when back */
	if (ret == 0 && drm_display_flip_pending(k->display))
		ret = set_timer(k, KIOSK_FLIP_TIMEOUT_MS);
	if (ret < 0) {
		fail(k, "cannot show a frame", ret);
		return;
	}
	k->frames++;
	if (k->frames == 1) {
		k->first_frame_us = now_us();
		/* the kiosk is up: a line for the journal (and for tests to wait on) */
		fprintf(stderr, "edaha: first frame on screen %.1f ms after start\n",
			(double)(k->first_frame_us - k->start_us) / 1000.0);
	}
}

/* Page flips, seat switches and hotplug events on the display's fds. */
static void on_display(struct kiosk *k, const struct pollfd *fds, size_t n)
{
	bool pending = drm_display_flip_pending(k->display);
	int ret = drm_display_dispatch(k->display, fds, n);

	if (ret < 0) {
		fail(k, "display", ret);
		return;
	}
	if (pending && !drm_display_flip_pending(k->display)) {
		k->last_frame_us = now_us();
		ret = set_timer(k, 0); /* disarms the flip watchdog */
		if (ret < 0)
			fail(k, "timer", ret);
	}
}

static void on_signal(struct kiosk *k)
{
	struct signalfd_siginfo si;

	if (read(k->signal_fd, &si, sizeof(si)) == (ssize_t)sizeof(si))
		fprintf(stderr, "edaha: %s, stopping\n", strsignal((int)si.ssi_signo));
	k->quit = true;
}

static void on_timer(struct kiosk *k)
{
	uint64_t expirations;

	if (read(k->timer_fd, &expirations, sizeof(expirations)) < 0)
		return; /* spurious wake-up (EAGAIN): nothing expired */
	if (drm_display_flip_pending(k->display)) {
		int ret = drm_display_flip_timeout(k->display);

		if (ret < 0)
			fail(k, "display", ret);
	}
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

	if (req & APP_REQUEST_EXPORT)
		fputs("edaha: export asked for; saving to USB is not in the kiosk yet\n", stderr);
	if (k->app->failed) {
		fail(k, "the app failed", k->app->failed);
	}
}

static int write_screenshot(struct kiosk *k)
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

static void print_stats(const struct kiosk *k)
{
	double first_ms = (double)(k->first_frame_us - k->start_us) / 1000.0;

	if (!k->frames)
		return;
	fprintf(stderr, "edaha: %lu frame%s; first on screen %.1f ms after start", k->frames,
		k->frames == 1 ? "" : "s", first_ms);
	if (k->frames > 1 && k->last_frame_us > k->first_frame_us)
		fprintf(stderr, "; %.1f frames/s after it",
			(double)(k->frames - 1) * 1e6 / (double)(k->last_frame_us - k->first_frame_us));
	fputc('\n', stderr);
}

int kiosk_run(struct kiosk *k)
{
	struct pollfd fds[DRM_DISPLAY_MAX_POLLFDS + 2 + KIOSK_MAX_SOURCES];

	while (!k->quit) {
		size_t n, nd, nsrc = k->nsources;

		/* nothing is drawn while a flip is in flight, the seat is away or the
		 * display unplugged */
		if (drm_display_can_draw(k->display)) {
			if (k->cfg.frames && k->frames >= k->cfg.frames)
				break;
			if (frame_due(k))
				draw_frame(k);
			if (k->quit)
				break;
			/* a modeset shows its frame at once: go round for the next one */
			if (drm_display_can_draw(k->display) && k->cfg.frames)
				continue;
		}
		n = nd = drm_display_pollfds(k->display, fds, DRM_DISPLAY_MAX_POLLFDS);
		fds[n++] = (struct pollfd){ .fd = k->signal_fd, .events = POLLIN };
		fds[n++] = (struct pollfd){ .fd = k->timer_fd, .events = POLLIN };
		for (size_t i = 0; i < nsrc; i++)
			fds[n++] = (struct pollfd){ .fd = k->sources[i].fd, .events = POLLIN };
		if (poll(fds, n, -1) < 0) {
			if (errno != EINTR)
				fail(k, "poll", -errno);
			continue;
		}
		if (fds[nd].revents)
			on_signal(k);
		on_display(k, fds, nd);
		if (fds[nd + 1].revents)
			on_timer(k);
		/* backwards, so that dropping a failed source leaves the rest in place */
		for (size_t i = nsrc; i-- > 0;) {
			if (fds[nd + 2 + i].revents)
				on_source(k, i);
		}
		take_requests(k);
	}
	print_stats(k);
	if (k->status == 0 && k->shot && k->frames >= k->cfg.frames && write_screenshot(k) < 0)
		k->status = 1;
	return k->status;
}
