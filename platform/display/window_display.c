/* SPDX-License-Identifier: MIT */
#include "window_display.h"

#include <SDL.h>
#include <SDL_syswm.h>
#include <GLES2/gl2.h>
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/eventfd.h>
#include <sys/timerfd.h>
#include <unistd.h>

#include "config.h"
#include "offscreen.h"
#include "window_input.h"
#if HAVE_WINDOW_X11
#include <X11/Xlib.h>
#endif
#if HAVE_WINDOW_WAYLAND
#include <wayland-client.h>
#endif

#define WINDOW_DEFAULT_W 1280
#define WINDOW_DEFAULT_H 800
/* Without the window system's fd, how often the loop looks for SDL events. */
#define WINDOW_TICK_NS 10000000L

struct window_display {
	struct display base; /* first: the kiosk loop sees a struct display */
	SDL_Window *win;
	SDL_GLContext ctx;
	bool sdl_up;
	int width, height; /* the app's size, fixed */
	bool gles3;
	struct offscreen *off; /* the picture at the app's size, shown scaled */
	int conn_fd;           /* X11 or Wayland connection; -1: none, tick_fd instead */
	int wake_fd;           /* eventfd: SDL holds events the connection fd will not announce */
	int tick_fd;           /* timerfd, without conn_fd */
	bool visible;          /* not minimised: worth drawing */
	bool needs_frame;
	bool vsync;
	struct window_input input;
	bool has_input;
	char name[160];
};

#define WIN(d) ((struct window_display *)(d))
#define CWIN(d) ((const struct window_display *)(d))

static void map_of(const struct window_display *w, struct window_map *m)
{
	m->app_w = w->width;
	m->app_h = w->height;
	SDL_GetWindowSize(w->win, &m->win_w, &m->win_h);
	SDL_GL_GetDrawableSize(w->win, &m->draw_w, &m->draw_h);
}

static void on_window_event(struct window_display *w, const SDL_WindowEvent *e)
{
	switch (e->event) {
	case SDL_WINDOWEVENT_MINIMIZED:
	case SDL_WINDOWEVENT_HIDDEN:
		w->visible = false;
		break;
	case SDL_WINDOWEVENT_RESTORED:
	case SDL_WINDOWEVENT_SHOWN:
	case SDL_WINDOWEVENT_MAXIMIZED:
		w->visible = true;
		w->needs_frame = true;
		break;
	case SDL_WINDOWEVENT_EXPOSED:
	case SDL_WINDOWEVENT_SIZE_CHANGED:
		/* the same picture, scaled to the new size */
		w->needs_frame = true;
		break;
	case SDL_WINDOWEVENT_CLOSE:
		break; /* SDL_QUIT follows */
	default:
		break;
	}
}

/* After a swap or a pump: events SDL read into its queue are not on the fd any more. */
static void wake_if_queued(struct window_display *w)
{
	uint64_t one = 1;

	SDL_PumpEvents();
	if (SDL_PeepEvents(NULL, 0, SDL_PEEKEVENT, SDL_FIRSTEVENT, SDL_LASTEVENT) > 0 &&
	    write(w->wake_fd, &one, sizeof(one)) < 0 && errno != EAGAIN)
		fprintf(stderr, "edaha: window: cannot wake the loop: %s\n", strerror(errno));
}

static int op_dispatch(struct display *d, const struct pollfd *fds, size_t n)
{
	struct window_display *w = WIN(d);
	struct window_map m;
	uint64_t count;
	SDL_Event ev;

	for (size_t i = 0; i < n; i++) {
		if (!(fds[i].revents & POLLIN))
			continue;
		/* a read that finds nothing (EAGAIN) is no failure */
		if ((fds[i].fd == w->wake_fd || fds[i].fd == w->tick_fd) &&
		    read(fds[i].fd, &count, sizeof(count)) < 0 && errno != EAGAIN)
			return -errno;
	}
	/* every turn of the loop: cheap when nothing is there, and nothing waits */
	map_of(w, &m);
	while (SDL_PollEvent(&ev)) {
		if (ev.type == SDL_QUIT) {
			/* closing the window stops the kiosk as SIGTERM does: the loop's
			 * signalfd sees it, and the recording and screenshot are written */
			fputs("edaha: the window was closed\n", stderr);
			if (kill(getpid(), SIGTERM) < 0)
				return -errno;
		} else if (ev.type == SDL_WINDOWEVENT) {
			on_window_event(w, &ev.window);
			map_of(w, &m);
		}
		if (w->has_input)
			window_input_handle(&w->input, &ev, &m);
	}
	return 0;
}

static size_t op_pollfds(const struct display *d, struct pollfd *out, size_t max)
{
	const struct window_display *w = CWIN(d);
	int fds[] = { w->conn_fd >= 0 ? w->conn_fd : w->tick_fd, w->wake_fd };
	size_t n = 0;

	for (size_t i = 0; i < 2 && n < max; i++)
		out[n++] = (struct pollfd){ .fd = fds[i], .events = POLLIN };
	return n;
}

static void op_size(const struct display *d, int *width, int *height)
{
	*width = CWIN(d)->width;
	*height = CWIN(d)->height;
}

static const char *op_describe(const struct display *d)
{
	return CWIN(d)->name;
}

static bool op_gles3(const struct display *d)
{
	return CWIN(d)->gles3;
}

static bool op_seat_active(const struct display *d)
{
	(void)d;
	return true; /* the desktop sends input only to the window it shows */
}

static bool op_can_draw(const struct display *d)
{
	return CWIN(d)->visible;
}

static bool op_needs_frame(const struct display *d)
{
	return CWIN(d)->needs_frame;
}

static int op_read_rgba(struct display *d, uint8_t *rgba)
{
	return offscreen_read_rgba(WIN(d)->off, rgba);
}

static int op_present(struct display *d)
{
	struct window_display *w = WIN(d);
	int dw, dh;

	SDL_GL_GetDrawableSize(w->win, &dw, &dh);
	if (offscreen_show(w->off, 0, dw, dh) < 0)
		return -EIO;
	SDL_GL_SwapWindow(w->win);
	w->needs_frame = false;
	wake_if_queued(w);
	return 0;
}

static bool op_flip_pending(const struct display *d)
{
	(void)d;
	return false; /* the swap returns once the frame is the window's */
}

static int op_flip_timeout(struct display *d)
{
	(void)d;
	return 0;
}

static void op_set_input(struct display *d, display_feed_fn feed, void *data)
{
	struct window_display *w = WIN(d);

	window_input_init(&w->input, feed, data);
	w->has_input = true;
}

static void op_destroy(struct display *d)
{
	struct window_display *w = WIN(d);

	if (w->ctx) {
		/* the offscreen's GL objects go while the context is current */
		SDL_GL_MakeCurrent(w->win, w->ctx);
		offscreen_destroy(w->off);
		SDL_GL_DeleteContext(w->ctx);
	}
	if (w->win)
		SDL_DestroyWindow(w->win);
	if (w->sdl_up)
		SDL_Quit();
	if (w->wake_fd >= 0)
		close(w->wake_fd);
	if (w->tick_fd >= 0)
		close(w->tick_fd);
	free(w);
}

static const struct display_ops window_ops = {
	.destroy = op_destroy,
	.pollfds = op_pollfds,
	.dispatch = op_dispatch,
	.size = op_size,
	.describe = op_describe,
	.gles3 = op_gles3,
	.seat_active = op_seat_active,
	.can_draw = op_can_draw,
	.needs_frame = op_needs_frame,
	.read_rgba = op_read_rgba,
	.present = op_present,
	.flip_pending = op_flip_pending,
	.flip_timeout = op_flip_timeout,
	.set_input = op_set_input,
};

/* The window system's connection, for poll(); -1 when this build cannot reach it. */
static int connection_fd(SDL_Window *win, const char **system)
{
	SDL_SysWMinfo info;

	SDL_VERSION(&info.version);
	*system = SDL_GetCurrentVideoDriver();
	if (!SDL_GetWindowWMInfo(win, &info))
		return -1;
	switch (info.subsystem) {
#if HAVE_WINDOW_X11
	case SDL_SYSWM_X11:
		return ConnectionNumber(info.info.x11.display);
#endif
#if HAVE_WINDOW_WAYLAND
	case SDL_SYSWM_WAYLAND:
		return wl_display_get_fd(info.info.wl.display);
#endif
	default:
		return -1;
	}
}

/* SDL fell back on a driver that shows nothing (offscreen, dummy) where the desktop
 * cannot be reached: not a window, unless SDL_VIDEODRIVER asked for it. */
static bool desktop_driver(void)
{
	const char *driver = SDL_GetCurrentVideoDriver(), *asked = SDL_getenv("SDL_VIDEODRIVER");

	if (!driver)
		return false;
	return strcmp(driver, "x11") == 0 || strcmp(driver, "wayland") == 0 ||
	       (asked && asked[0] && strstr(asked, driver));
}

/* A GLES context, 3.0 if there is one (multisampled offscreen, as headless), else 2.0. */
static int make_context(struct window_display *w, struct error *err)
{
	static const int majors[] = { 3, 2 };

	for (size_t i = 0; i < 2 && !w->ctx; i++) {
		SDL_GL_SetAttribute(SDL_GL_CONTEXT_PROFILE_MASK, SDL_GL_CONTEXT_PROFILE_ES);
		SDL_GL_SetAttribute(SDL_GL_CONTEXT_MAJOR_VERSION, majors[i]);
		SDL_GL_SetAttribute(SDL_GL_CONTEXT_MINOR_VERSION, 0);
		w->ctx = SDL_GL_CreateContext(w->win);
		w->gles3 = w->ctx && majors[i] == 3;
	}
	if (!w->ctx)
		return error_set(err, -ENODEV, "no GLES context for the window: %s", SDL_GetError());
	if (SDL_GL_MakeCurrent(w->win, w->ctx) < 0)
		return error_set(err, -ENODEV, "cannot use the window's GLES context: %s",
				 SDL_GetError());
	/* a frame a refresh, as the kiosk's page flips; late swap tearing rather than
	 * stalling a frame if the driver has it */
	w->vsync = SDL_GL_SetSwapInterval(-1) == 0 || SDL_GL_SetSwapInterval(1) == 0;
	return 0;
}

struct display *window_display_create(const struct window_display_config *cfg,
				      struct error *err)
{
	struct window_display *w = calloc(1, sizeof(*w));
	struct itimerspec tick = { { 0, WINDOW_TICK_NS }, { 0, WINDOW_TICK_NS } };
	const char *system = "";
	int dw, dh;

	if (!w) {
		(void)error_set(err, -ENOMEM, "out of memory");
		return NULL;
	}
	w->base.ops = &window_ops;
	w->conn_fd = w->tick_fd = -1;
	w->width = cfg->width > 0 ? cfg->width : WINDOW_DEFAULT_W;
	w->height = cfg->height > 0 ? cfg->height : WINDOW_DEFAULT_H;
	w->visible = w->needs_frame = true;
	w->wake_fd = eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC);
	if (w->wake_fd < 0) {
		(void)error_set(err, -errno, "no eventfd: %s", strerror(errno));
		goto fail;
	}
	/* the loop's signalfd has SIGINT and SIGTERM; GLES through EGL, as on the kiosk */
	SDL_SetHint(SDL_HINT_NO_SIGNAL_HANDLERS, "1");
	SDL_SetHint(SDL_HINT_VIDEO_X11_FORCE_EGL, "1");
	SDL_SetHint(SDL_HINT_OPENGL_ES_DRIVER, "1");
	/* SDL holds the screensaver off by default; a desk's lock must still work */
	SDL_SetHint(SDL_HINT_VIDEO_ALLOW_SCREENSAVER, "1");
	if (SDL_Init(SDL_INIT_VIDEO) < 0) {
		(void)error_set(err, -ENODEV, "no desktop session for a window (%s); --kiosk for the DRM screen",
				SDL_GetError());
		goto fail;
	}
	w->sdl_up = true;
	if (!desktop_driver()) {
		(void)error_set(err, -ENODEV,
				"no desktop session for a window (SDL found only its \"%s\" video driver); --kiosk for the DRM screen",
				SDL_GetCurrentVideoDriver());
		goto fail;
	}
	/* strokes are antialiased offscreen; the window's own framebuffer needs none */
	SDL_GL_SetAttribute(SDL_GL_RED_SIZE, 8);
	SDL_GL_SetAttribute(SDL_GL_GREEN_SIZE, 8);
	SDL_GL_SetAttribute(SDL_GL_BLUE_SIZE, 8);
	SDL_GL_SetAttribute(SDL_GL_DOUBLEBUFFER, 1);
	w->win = SDL_CreateWindow("edaha", SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED,
				  w->width, w->height,
				  SDL_WINDOW_OPENGL | SDL_WINDOW_RESIZABLE | SDL_WINDOW_ALLOW_HIGHDPI);
	if (!w->win) {
		(void)error_set(err, -ENODEV, "cannot open a window: %s", SDL_GetError());
		goto fail;
	}
	if (make_context(w, err) < 0)
		goto fail;
	w->off = offscreen_create(w->width, w->height, w->gles3, err);
	if (!w->off)
		goto fail;
	w->conn_fd = connection_fd(w->win, &system);
	if (w->conn_fd < 0) {
		w->tick_fd = timerfd_create(CLOCK_MONOTONIC, TFD_NONBLOCK | TFD_CLOEXEC);
		if (w->tick_fd < 0 || timerfd_settime(w->tick_fd, 0, &tick, NULL) < 0) {
			(void)error_set(err, -errno, "no timerfd: %s", strerror(errno));
			goto fail;
		}
	}
	SDL_GL_GetDrawableSize(w->win, &dw, &dh);
	snprintf(w->name, sizeof(w->name), "an SDL %s window %dx%d (app %dx%d, %s%s)", system, dw,
		 dh, w->width, w->height, w->vsync ? "vsync" : "no vsync",
		 w->conn_fd < 0 ? ", polled every 10 ms" : "");
	return &w->base;

fail:
	op_destroy(&w->base);
	return NULL;
}
