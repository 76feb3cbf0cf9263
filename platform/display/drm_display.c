/* SPDX-License-Identifier: MIT */
#include "drm_display.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GLES2/gl2.h>
#include <dirent.h>
#include <errno.h>
#include <gbm.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <xf86drm.h>

#include "display.h"
#include "drm_hotplug.h"
#include "drm_kms.h"
#include "offscreen.h"
#include "seat.h"
#include "gl_util.h"

/* Strokes are antialiased by multisampling, as in the headless framebuffer. */
#define MSAA_SAMPLES 4
/* How long destroy waits for a queued flip before it takes the framebuffers away. */
#define DRAIN_MS 500

struct drm_display {
	struct display base; /* first: the kiosk loop sees a struct display */
	struct seat *seat;
	struct drm_kms *kms;
	struct drm_hotplug *hotplug; /* NULL: no monitor (said at create) */
	int fd;
	char card[256];
	char name[320];
	int rotation;
	bool any_connector; /* the configuration named none: a replug may use another */
	int width, height;  /* the app's size, fixed */
	struct gbm_device *gbm;
	struct gbm_surface *surface;
	int surface_w, surface_h; /* the mode's size */
	EGLDisplay dpy;
	EGLConfig config;
	EGLContext ctx;
	EGLSurface egl_surface;
	bool gles3;
	struct offscreen *off; /* NULL: the app draws straight into the surface */
	bool connected;        /* the connector is there with a mode */
	bool mode_set;         /* the screen shows our frames: no modeset due */
	bool ever_set;         /* we changed the CRTC: destroy puts it back */
	bool probe_due;        /* a hotplug event or the seat's return, not probed yet */
	bool flip_pending;     /* a flip is queued; `next` becomes the front at its event */
	struct gbm_bo *front, *next;
	uint8_t *row;          /* scratch for flipping rows on read-back */
};

static int make_surface(struct drm_display *d, int w, int h, struct error *err);

/* The mode, as the viewer sees it, is not the app's size: the picture is scaled. */
static bool scaled(const struct drm_display *d, int mode_w, int mode_h)
{
	int w, h;

	offscreen_turned_size(d->rotation, mode_w, mode_h, &w, &h);
	return w != d->width || h != d->height;
}

/* The app's picture cannot go straight onto this mode: turned, or of another size. */
static bool needs_offscreen(const struct drm_display *d, int mode_w, int mode_h)
{
	return d->rotation != 0 || scaled(d, mode_w, mode_h);
}

static void describe(struct drm_display *d)
{
	const struct drm_kms_output *o = drm_kms_output(d->kms);
	char turned[16] = "";
	int n;

	n = snprintf(d->name, sizeof(d->name), "%s %s %dx%d@%u (%s, %s)", d->card, o->connector,
		     o->mode.hdisplay, o->mode.vdisplay, o->mode.vrefresh,
		     drm_kms_atomic(d->kms) ? "atomic" : "legacy", seat_describe(d->seat));
	if (!d->off || n < 0 || (size_t)n >= sizeof(d->name))
		return;
	if (d->rotation)
		snprintf(turned, sizeof(turned), " turned %d", d->rotation);
	snprintf(d->name + n, sizeof(d->name) - (size_t)n, ", picture %dx%d%s%s", d->width,
		 d->height, turned,
		 scaled(d, o->mode.hdisplay, o->mode.vdisplay) ? " scaled to fit" : "");
}

/* ---- the card ---- */

static int try_card(struct drm_display *d, const struct drm_display_config *cfg, const char *path,
		    bool atomic, struct error *err)
{
	const struct drm_kms_want want = {
		.connector = cfg->connector,
		.width = cfg->width,
		.height = cfg->height,
		.refresh = cfg->refresh,
	};
	int fd = seat_open(d->seat, path);

	if (fd < 0)
		return error_set(err, fd, "%s: %s", path, strerror(-fd));
	d->kms = drm_kms_create(fd, atomic);
	if (!d->kms) {
		seat_close(d->seat, fd);
		return error_set(err, -ENOMEM, "display: out of memory");
	}
	if (drm_kms_pick(d->kms, &want, path, err) == 0) {
		d->fd = fd;
		snprintf(d->card, sizeof(d->card), "%s", path);
		return 0;
	}
	drm_kms_destroy(d->kms);
	d->kms = NULL;
	seat_close(d->seat, fd);
	return -ENODEV;
}

static int cmp_names(const void *a, const void *b)
{
	return strcmp(*(const char *const *)a, *(const char *const *)b);
}

/* Boards have several DRM nodes in no fixed order: try every card, in name order. */
static int open_card(struct drm_display *d, const struct drm_display_config *cfg, bool atomic,
		     struct error *err)
{
	char *names[64], path[300];
	size_t n = 0;
	struct dirent *de;
	DIR *dir;
	int ret = -ENODEV;

	if (cfg->card)
		return try_card(d, cfg, cfg->card, atomic, err);
	dir = opendir("/dev/dri");
	if (!dir)
		return error_set(err, -ENODEV, "/dev/dri: %s (no DRM driver loaded?)", strerror(errno));
	while ((de = readdir(dir)) && n < sizeof(names) / sizeof(names[0])) {
		if (strncmp(de->d_name, "card", 4) == 0 && (names[n] = strdup(de->d_name)))
			n++;
	}
	closedir(dir);
	qsort(names, n, sizeof(names[0]), cmp_names);
	error_set(err, -ENODEV, "/dev/dri has no card");
	for (size_t i = 0; i < n; i++) {
		snprintf(path, sizeof(path), "/dev/dri/%s", names[i]);
		if (ret < 0)
			ret = try_card(d, cfg, path, atomic, err);
		free(names[i]);
	}
	return ret;
}

/* ---- EGL on GBM ---- */

/* A config whose native visual is the surface's format; multisampled if asked. */
static bool choose_config(EGLDisplay dpy, EGLint renderable, EGLint samples, EGLConfig *out)
{
	const EGLint attribs[] = {
		EGL_SURFACE_TYPE, EGL_WINDOW_BIT,
		EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8,
		EGL_DEPTH_SIZE, 16,
		EGL_RENDERABLE_TYPE, renderable,
		EGL_SAMPLE_BUFFERS, samples > 0, EGL_SAMPLES, samples,
		EGL_NONE,
	};
	EGLConfig configs[64];
	EGLint n = 0;

	if (!eglChooseConfig(dpy, attribs, configs, 64, &n))
		return false;
	for (EGLint i = 0; i < n; i++) {
		EGLint id = 0;

		/* the GBM surface is XRGB8888: the config must scan out as that */
		if (eglGetConfigAttrib(dpy, configs[i], EGL_NATIVE_VISUAL_ID, &id) &&
		    id == GBM_FORMAT_XRGB8888) {
			*out = configs[i];
			return true;
		}
	}
	return false;
}

/* The display and a context; the surface is make_surface's. samples: of the window. */
static int create_egl(struct drm_display *d, EGLint samples, struct error *err)
{
	static const int versions[] = { 3, 2 };
	const char *client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
	PFNEGLGETPLATFORMDISPLAYEXTPROC get_display;
	EGLint major, minor;

	if (!client ||
	    (!gl_has_extension(client, "EGL_KHR_platform_gbm") && !gl_has_extension(client, "EGL_MESA_platform_gbm")))
		return error_set(err, -ENODEV, "EGL: no GBM platform (is libegl-mesa0 installed?)");
	/* the EXT entry point takes the same arguments and exists on EGL 1.4 libraries too */
	get_display = (PFNEGLGETPLATFORMDISPLAYEXTPROC)eglGetProcAddress("eglGetPlatformDisplayEXT");
	if (!get_display)
		return error_set(err, -ENODEV, "EGL: no eglGetPlatformDisplayEXT");
	d->dpy = get_display(EGL_PLATFORM_GBM_KHR, d->gbm, NULL);
	if (d->dpy == EGL_NO_DISPLAY)
		return error_set(err, -ENODEV, "EGL: no GBM display (error 0x%x)", eglGetError());
	if (!eglInitialize(d->dpy, &major, &minor)) {
		d->dpy = EGL_NO_DISPLAY;
		return error_set(err, -ENODEV, "EGL: cannot initialise (error 0x%x)", eglGetError());
	}
	if (!eglBindAPI(EGL_OPENGL_ES_API))
		return error_set(err, -ENODEV, "EGL: no OpenGL ES (error 0x%x)", eglGetError());
	for (size_t i = 0; i < sizeof(versions) / sizeof(versions[0]); i++) {
		const EGLint ctx_attribs[] = { EGL_CONTEXT_CLIENT_VERSION, versions[i], EGL_NONE };
		EGLint bit = versions[i] == 3 ? EGL_OPENGL_ES3_BIT : EGL_OPENGL_ES2_BIT;

		if (!(samples > 0 && choose_config(d->dpy, bit, samples, &d->config)) &&
		    !choose_config(d->dpy, bit, 0, &d->config))
			continue;
		d->ctx = eglCreateContext(d->dpy, d->config, EGL_NO_CONTEXT, ctx_attribs);
		if (d->ctx == EGL_NO_CONTEXT)
			continue;
		d->gles3 = versions[i] == 3;
		return 0;
	}
	return error_set(err, -ENODEV, "EGL: no GLES 3 or GLES 2 context for XRGB8888 (error 0x%x)",
			 eglGetError());
}

/* Gives the locked buffers back to the surface. */
static void release_buffers(struct drm_display *d)
{
	/* while EGL's side of the surface still exists: Mesa's release looks the buffer up
	 * in the EGL surface, which eglDestroySurface frees (and with it every buffer,
	 * whose framebuffers destroy_fb removes) */
	if (d->front)
		gbm_surface_release_buffer(d->surface, d->front);
	if (d->next && d->next != d->front)
		gbm_surface_release_buffer(d->surface, d->next);
	d->front = d->next = NULL;
}

static void destroy_surface(struct drm_display *d)
{
	release_buffers(d);
	if (d->egl_surface != EGL_NO_SURFACE) {
		/* the context stays, with every GL object in it */
		eglMakeCurrent(d->dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
		eglDestroySurface(d->dpy, d->egl_surface);
		d->egl_surface = EGL_NO_SURFACE;
	}
	if (d->surface)
		gbm_surface_destroy(d->surface);
	d->surface = NULL;
}

/* A GBM surface of the mode's size and EGL's window on it, current. */
static int make_surface(struct drm_display *d, int w, int h, struct error *err)
{
	destroy_surface(d);
	d->surface = gbm_surface_create(d->gbm, (uint32_t)w, (uint32_t)h, GBM_FORMAT_XRGB8888,
					GBM_BO_USE_SCANOUT | GBM_BO_USE_RENDERING);
	if (!d->surface)
		return error_set(err, -ENODEV, "%s: cannot create a %dx%d GBM surface", d->card, w, h);
	d->egl_surface = eglCreateWindowSurface(d->dpy, d->config, (EGLNativeWindowType)d->surface,
						NULL);
	if (d->egl_surface == EGL_NO_SURFACE)
		return error_set(err, -ENODEV, "EGL: cannot make a window surface (error 0x%x)",
				 eglGetError());
	if (!eglMakeCurrent(d->dpy, d->egl_surface, d->egl_surface, d->ctx))
		return error_set(err, -ENODEV, "EGL: cannot make the context current (error 0x%x)",
				 eglGetError());
	d->surface_w = w;
	d->surface_h = h;
	if (d->off)
		offscreen_bind(d->off);
	else
		glViewport(0, 0, w, h);
	return 0;
}

/* ---- seat, hotplug, probing ---- */

static void seat_disabled(void *data)
{
	(void)data;
	/* a flip in flight still completes; nothing new is committed until enable */
	fputs("edaha: display: the seat was switched away (VT switch); not drawing\n", stderr);
}

static void seat_enabled(void *data)
{
	struct drm_display *d = data;

	/* whoever had the screen set their own mode: ours is set again with the next frame */
	fputs("edaha: display: the seat is back; drawing again\n", stderr);
	d->mode_set = false;
	d->probe_due = true;
}

static const struct seat_listener seat_listener = {
	.disable = seat_disabled,
	.enable = seat_enabled,
};

/* Gives up on the output until a hotplug event or the seat's return. */
static void lost(struct drm_display *d, const char *what, int err)
{
	fprintf(stderr, "edaha: display: %s: %s; not drawing until %s is back\n", what,
		strerror(-err), drm_kms_output(d->kms)->connector);
	d->connected = false;
	d->mode_set = false;
}

/*
 * Looks at the connector in use again: gone, there as before, or back (with the mode in
 * use if it still offers it, else its preferred one: the picture is then scaled to fit).
 * Gone, and the configuration named no connector: any connected one will do. A negative
 * errno only when the display cannot go on (no memory, no GL).
 */
static int probe(struct drm_display *d)
{
	const struct drm_kms_output before = *drm_kms_output(d->kms);
	struct drm_kms_want want = {
		.connector = before.connector,
		.width = before.mode.hdisplay,
		.height = before.mode.vdisplay,
		.refresh = (int)before.mode.vrefresh,
		.fallback = true,
	};
	const struct drm_kms_output *o;
	struct error err = { { 0 } };
	int ret;

	d->probe_due = false;
	ret = drm_kms_pick(d->kms, &want, d->card, &err);
	if (ret == -ENODEV && d->any_connector) {
		want.connector = NULL;
		ret = drm_kms_pick(d->kms, &want, d->card, &err);
	}
	if (ret < 0) {
		if (d->connected)
			fprintf(stderr, "edaha: display: %s disconnected; not drawing until it is "
				"back\n", before.connector);
		d->connected = false;
		return ret == -ENODEV ? 0 : ret;
	}
	o = drm_kms_output(d->kms);
	if (!d->connected || o->connector_id != before.connector_id ||
	    o->crtc_id != before.crtc_id || memcmp(&o->mode, &before.mode, sizeof(o->mode)) != 0) {
		fprintf(stderr, "edaha: display: %s connected, %dx%d@%u\n", o->connector,
			o->mode.hdisplay, o->mode.vdisplay, o->mode.vrefresh);
		d->mode_set = false;
	}
	d->connected = true;
	if (o->mode.hdisplay != d->surface_w || o->mode.vdisplay != d->surface_h) {
		ret = make_surface(d, o->mode.hdisplay, o->mode.vdisplay, &err);
		if (ret == 0 && !d->off &&
		    !(d->off = offscreen_create(d->width, d->height, d->gles3, &err)))
			ret = -EIO;
		if (ret < 0) {
			fprintf(stderr, "edaha: display: %s\n", err.msg);
			return ret;
		}
	}
	describe(d);
	return 0;
}

/* ---- create, destroy ---- */

struct drm_display *drm_display_create(const struct drm_display_config *cfg, struct error *err)
{
	static const struct drm_display_config automatic = { 0 };
	const char *legacy = getenv("EDAHA_DRM_LEGACY");
	struct drm_display *d = calloc(1, sizeof(*d));
	const drmModeModeInfo *mode;
	struct error hotplug_err = { { 0 } };
	struct stat st;

	if (!d) {
		error_set(err, -ENOMEM, "display: out of memory");
		return NULL;
	}
	cfg = cfg ? cfg : &automatic;
	d->fd = -1;
	d->dpy = EGL_NO_DISPLAY;
	d->ctx = EGL_NO_CONTEXT;
	d->egl_surface = EGL_NO_SURFACE;
	d->rotation = cfg->rotation;
	d->any_connector = !cfg->connector;
	d->seat = seat_create(&seat_listener, d, err);
	if (!d->seat)
		goto fail;
	if (open_card(d, cfg, !(legacy && strcmp(legacy, "1") == 0), err) < 0)
		goto fail;
	d->connected = true;
	mode = &drm_kms_output(d->kms)->mode;
	offscreen_turned_size(d->rotation, mode->hdisplay, mode->vdisplay, &d->width, &d->height);
	d->row = malloc((size_t)d->width * 4);
	if (!d->row) {
		error_set(err, -ENOMEM, "display: out of memory");
		goto fail;
	}
	d->gbm = gbm_create_device(d->fd);
	if (!d->gbm) {
		error_set(err, -ENODEV, "%s: no GBM device", d->card);
		goto fail;
	}
	/* a window that only shows the offscreen picture needs no samples of its own */
	if (create_egl(d, needs_offscreen(d, mode->hdisplay, mode->vdisplay) ? 0 : MSAA_SAMPLES,
		       err) < 0 ||
	    make_surface(d, mode->hdisplay, mode->vdisplay, err) < 0)
		goto fail;
	if (needs_offscreen(d, mode->hdisplay, mode->vdisplay) &&
	    !(d->off = offscreen_create(d->width, d->height, d->gles3, err)))
		goto fail;
	/* without it the kiosk still runs: a display replugged is then seen by a flip that
	 * does not complete, or not at all */
	if (fstat(d->fd, &st) < 0)
		error_set(&hotplug_err, -errno, "%s: %s", d->card, strerror(errno));
	else
		d->hotplug = drm_hotplug_create(st.st_rdev, &hotplug_err);
	if (!d->hotplug)
		fprintf(stderr, "edaha: warning: display hotplug is not watched: %s\n",
			hotplug_err.msg);
	describe(d);
	return d;

fail:
	drm_display_destroy(d);
	return NULL;
}

static void flip_done(int fd, unsigned seq, unsigned sec, unsigned usec, void *data)
{
	struct drm_display *d = data;

	(void)fd, (void)seq, (void)sec, (void)usec;
	/* late, for a flip drm_display_flip_timeout gave up on */
	if (!d->flip_pending)
		return;
	/* the old front is off the screen now: the surface may draw into it again */
	if (d->front)
		gbm_surface_release_buffer(d->surface, d->front);
	d->front = d->next;
	d->next = NULL;
	d->flip_pending = false;
}

static int handle_drm(struct drm_display *d)
{
	drmEventContext ev = {
		.version = 2,
		.page_flip_handler = flip_done,
	};

	if (drmHandleEvent(d->fd, &ev) < 0)
		return errno ? -errno : -EIO;
	return 0;
}

void drm_display_destroy(struct drm_display *d)
{
	int ret;

	if (!d)
		return;
	/* a flip still queued would land on a framebuffer we are about to remove */
	while (d->flip_pending) {
		struct pollfd p = { .fd = d->fd, .events = POLLIN };

		/* bounded: a display unplugged mid-flip may never send its event */
		if (poll(&p, 1, DRAIN_MS) <= 0 || handle_drm(d) < 0)
			break;
	}
	if (d->ever_set && seat_active(d->seat) && (ret = drm_kms_restore(d->kms)) < 0)
		fprintf(stderr, "edaha: cannot restore the previous display mode: %s\n",
			strerror(-ret));
	/* with the context current; where a failed make_surface left none, GL ignores the
	 * calls and the objects go with the context */
	offscreen_destroy(d->off);
	if (d->dpy != EGL_NO_DISPLAY) {
		destroy_surface(d);
		if (d->ctx != EGL_NO_CONTEXT)
			eglDestroyContext(d->dpy, d->ctx);
		eglTerminate(d->dpy);
		/* frees EGL's per-thread state, which would otherwise outlive us */
		eglReleaseThread();
	} else if (d->surface) {
		gbm_surface_destroy(d->surface);
	}
	if (d->gbm)
		gbm_device_destroy(d->gbm);
	drm_kms_destroy(d->kms);
	drm_hotplug_destroy(d->hotplug);
	if (d->fd >= 0)
		seat_close(d->seat, d->fd);
	seat_destroy(d->seat);
	free(d->row);
	free(d);
}

/* ---- the loop's view ---- */

size_t drm_display_pollfds(const struct drm_display *d, struct pollfd *out, size_t max)
{
	const int fds[DRM_DISPLAY_MAX_POLLFDS] = {
		d->fd,
		seat_fd(d->seat),
		d->hotplug ? drm_hotplug_fd(d->hotplug) : -1,
	};
	size_t n = 0;

	for (size_t i = 0; i < DRM_DISPLAY_MAX_POLLFDS && n < max; i++)
		if (fds[i] >= 0)
			out[n++] = (struct pollfd){ .fd = fds[i], .events = POLLIN };
	return n;
}

int drm_display_dispatch(struct drm_display *d, const struct pollfd *fds, size_t n)
{
	int seat = seat_fd(d->seat), hotplug = d->hotplug ? drm_hotplug_fd(d->hotplug) : -1;
	int ret = 0;

	for (size_t i = 0; i < n && ret == 0; i++) {
		if (!fds[i].revents || fds[i].fd < 0)
			continue;
		if (fds[i].fd == d->fd)
			ret = handle_drm(d);
		else if (fds[i].fd == seat)
			ret = seat_dispatch(d->seat);
		else if (fds[i].fd == hotplug && drm_hotplug_dispatch(d->hotplug) > 0)
			d->probe_due = true;
	}
	/* not under a queued flip: a new mode may mean new buffers */
	if (ret == 0 && d->probe_due && !d->flip_pending)
		ret = probe(d);
	return ret;
}

int drm_display_flip_timeout(struct drm_display *d)
{
	if (!d->flip_pending)
		return 0;
	fprintf(stderr, "edaha: display: a page flip did not complete; probing %s\n",
		drm_kms_output(d->kms)->connector);
	/* as if it had: the buffer may be on screen. A late event is ignored */
	flip_done(d->fd, 0, 0, 0, d);
	/* there or not, what the CRTC does is unknown: a full modeset */
	d->mode_set = false;
	return probe(d);
}

void drm_display_size(const struct drm_display *d, int *width, int *height)
{
	*width = d->width;
	*height = d->height;
}

const char *drm_display_describe(const struct drm_display *d)
{
	return d->name;
}

bool drm_display_gles3(const struct drm_display *d)
{
	return d->gles3;
}

bool drm_display_seat_active(const struct drm_display *d)
{
	return seat_active(d->seat);
}

bool drm_display_can_draw(const struct drm_display *d)
{
	return seat_active(d->seat) && d->connected && !d->flip_pending;
}

bool drm_display_needs_frame(const struct drm_display *d)
{
	return !d->mode_set;
}

bool drm_display_flip_pending(const struct drm_display *d)
{
	return d->flip_pending;
}

int drm_display_read_rgba(struct drm_display *d, uint8_t *rgba)
{
	if (d->off)
		return offscreen_read_rgba(d->off, rgba);
	/* the back buffer, before the swap; a multisampled one is resolved by the read */
	return gl_read_rgba(d->width, d->height, rgba, d->row);
}

/* ---- framebuffers and flips ---- */

struct drm_fb {
	int fd;
	uint32_t id;
};

static void destroy_fb(struct gbm_bo *bo, void *data)
{
	struct drm_fb *fb = data;

	(void)bo;
	if (drmModeRmFB(fb->fd, fb->id) < 0)
		fprintf(stderr, "edaha: cannot remove framebuffer %u: %s\n", fb->id, strerror(errno));
	free(fb);
}

/* The KMS framebuffer of a GBM buffer, made the first time the surface hands it out. */
static int bo_fb(struct drm_display *d, struct gbm_bo *bo, uint32_t *id)
{
	struct drm_fb *fb = gbm_bo_get_user_data(bo);
	uint32_t handles[4] = { gbm_bo_get_handle(bo).u32 };
	uint32_t pitches[4] = { gbm_bo_get_stride(bo) };
	uint32_t offsets[4] = { 0 };

	if (fb) {
		*id = fb->id;
		return 0;
	}
	fb = calloc(1, sizeof(*fb));
	if (!fb)
		return -ENOMEM;
	fb->fd = d->fd;
	if (drmModeAddFB2(d->fd, gbm_bo_get_width(bo), gbm_bo_get_height(bo), GBM_FORMAT_XRGB8888,
			  handles, pitches, offsets, &fb->id, 0) < 0 &&
	    /* older drivers only know the depth/bpp call */
	    drmModeAddFB(d->fd, gbm_bo_get_width(bo), gbm_bo_get_height(bo), 24, 32, pitches[0],
			 handles[0], &fb->id) < 0) {
		int ret = -errno;

		free(fb);
		return ret;
	}
	gbm_bo_set_user_data(bo, fb, destroy_fb);
	*id = fb->id;
	return 0;
}

int drm_display_present(struct drm_display *d)
{
	bool atomic = drm_kms_atomic(d->kms);
	struct gbm_bo *bo;
	uint32_t fb = 0;
	int ret;

	if (d->flip_pending)
		return -EBUSY;
	if (!drm_display_can_draw(d))
		return -ENODEV;
	if (d->off && offscreen_show(d->off, d->rotation, d->surface_w, d->surface_h) < 0)
		return -EIO;
	if (!eglSwapBuffers(d->dpy, d->egl_surface))
		return -EIO;
	bo = gbm_surface_lock_front_buffer(d->surface);
	if (!bo)
		return -EIO;
	ret = bo_fb(d, bo, &fb);
	if (ret < 0) {
		gbm_surface_release_buffer(d->surface, bo);
		return ret;
	}
	if (!d->mode_set) {
		/* the first frame, or the first since the display or the seat came back: no
		 * flip event comes, the buffer is the front at once */
		ret = drm_kms_modeset(d->kms, fb);
		if (atomic != drm_kms_atomic(d->kms))
			describe(d);
		if (ret < 0) {
			gbm_surface_release_buffer(d->surface, bo);
			lost(d, "cannot set the mode", ret);
			return -ENODEV;
		}
		if (d->front)
			gbm_surface_release_buffer(d->surface, d->front);
		d->front = bo;
		/* for the journal: the kiosk is back on the screen */
		if (d->ever_set)
			fprintf(stderr, "edaha: display: mode set again on %s\n",
				drm_kms_output(d->kms)->connector);
		d->mode_set = d->ever_set = true;
		return 0;
	}
	ret = drm_kms_flip(d->kms, fb, d);
	if (ret < 0) {
		gbm_surface_release_buffer(d->surface, bo);
		lost(d, "cannot flip", ret);
		return -ENODEV;
	}
	d->next = bo;
	d->flip_pending = true;
	return 0;
}

/* The kiosk loop's view of it (display.h). */
_Static_assert(DRM_DISPLAY_MAX_POLLFDS <= DISPLAY_MAX_POLLFDS, "the loop's room for the display's fds");
#define DRM(d) ((struct drm_display *)(d))
#define CDRM(d) ((const struct drm_display *)(d))

static void op_destroy(struct display *d) { drm_display_destroy(DRM(d)); }
static size_t op_pollfds(const struct display *d, struct pollfd *out, size_t max)
{
	return drm_display_pollfds(CDRM(d), out, max);
}
static int op_dispatch(struct display *d, const struct pollfd *fds, size_t n)
{
	return drm_display_dispatch(DRM(d), fds, n);
}
static void op_size(const struct display *d, int *w, int *h) { drm_display_size(CDRM(d), w, h); }
static const char *op_describe(const struct display *d) { return drm_display_describe(CDRM(d)); }
static bool op_gles3(const struct display *d) { return drm_display_gles3(CDRM(d)); }
static bool op_seat_active(const struct display *d) { return drm_display_seat_active(CDRM(d)); }
static bool op_can_draw(const struct display *d) { return drm_display_can_draw(CDRM(d)); }
static bool op_needs_frame(const struct display *d) { return drm_display_needs_frame(CDRM(d)); }
static int op_read_rgba(struct display *d, uint8_t *rgba) { return drm_display_read_rgba(DRM(d), rgba); }
static int op_present(struct display *d) { return drm_display_present(DRM(d)); }
static bool op_flip_pending(const struct display *d) { return drm_display_flip_pending(CDRM(d)); }
static int op_flip_timeout(struct display *d) { return drm_display_flip_timeout(DRM(d)); }

static const struct display_ops drm_ops = {
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
	.set_input = NULL, /* the pen and buttons come through libinput and the GPIO lines */
};

struct display *drm_display_open(const struct drm_display_config *cfg, struct error *err)
{
	struct drm_display *d = drm_display_create(cfg, err);

	if (!d)
		return NULL;
	d->base.ops = &drm_ops;
	return &d->base;
}
