/* SPDX-License-Identifier: MIT */
#include "drm_display.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GLES2/gl2.h>
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <gbm.h>
#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <xf86drm.h>
#include <xf86drmMode.h>

/* Strokes are antialiased by multisampling, as in the headless framebuffer. */
#define MSAA_SAMPLES 4

struct drm_display {
	int fd;
	char name[128];
	uint32_t connector_id, crtc_id;
	drmModeModeInfo mode;
	drmModeCrtc *saved_crtc; /* what the CRTC showed before us, put back on destroy */
	struct gbm_device *gbm;
	struct gbm_surface *surface;
	EGLDisplay dpy;
	EGLContext ctx;
	EGLSurface egl_surface;
	bool gles3;
	bool mode_set;     /* the first present did the modeset */
	bool flip_pending; /* a flip is queued; `next` becomes the front at its event */
	struct gbm_bo *front, *next;
	uint8_t *row;      /* scratch for flipping rows on read-back */
};

/* ---- KMS: card, connector, mode, CRTC ---- */

static void connector_name(const drmModeConnector *c, char *out, size_t n)
{
	const char *type = drmModeGetConnectorTypeName(c->connector_type);

	snprintf(out, n, "%s-%u", type ? type : "Unknown", c->connector_type_id);
}

static const drmModeModeInfo *pick_mode(const drmModeConnector *c, const struct drm_display_config *cfg)
{
	const drmModeModeInfo *preferred = NULL;

	for (int i = 0; i < c->count_modes; i++) {
		const drmModeModeInfo *m = &c->modes[i];

		if (cfg->width > 0) {
			if (m->hdisplay == cfg->width && m->vdisplay == cfg->height &&
			    (cfg->refresh <= 0 || (int)m->vrefresh == cfg->refresh))
				return m;
		} else if (!preferred || (m->type & DRM_MODE_TYPE_PREFERRED)) {
			if (!preferred || !(preferred->type & DRM_MODE_TYPE_PREFERRED))
				preferred = m;
		}
	}
	/* with no preferred mode, the first listed one (drivers list the best first) */
	return preferred;
}

/* A CRTC the connector can use: the one its encoder drives now, else any free one. */
static uint32_t pick_crtc(int fd, const drmModeRes *res, const drmModeConnector *c)
{
	if (c->encoder_id) {
		drmModeEncoder *e = drmModeGetEncoder(fd, c->encoder_id);
		uint32_t crtc = e ? e->crtc_id : 0;

		drmModeFreeEncoder(e);
		if (crtc)
			return crtc;
	}
	for (int i = 0; i < c->count_encoders; i++) {
		drmModeEncoder *e = drmModeGetEncoder(fd, c->encoders[i]);

		if (!e)
			continue;
		for (int j = 0; j < res->count_crtcs && j < 32; j++) {
			if (e->possible_crtcs & (1u << j)) {
				drmModeFreeEncoder(e);
				return res->crtcs[j];
			}
		}
		drmModeFreeEncoder(e);
	}
	return 0;
}

/* Fills connector, mode and CRTC from the card open in d->fd. 0, or -ENODEV with why. */
static int pick_output(struct drm_display *d, const struct drm_display_config *cfg,
		       const char *card, struct error *err)
{
	drmModeRes *res = drmModeGetResources(d->fd);
	int ret = -ENODEV;

	/* render-only nodes (a Raspberry Pi's v3d) have no resources or no CRTCs */
	if (!res || res->count_crtcs <= 0 || res->count_connectors <= 0) {
		drmModeFreeResources(res);
		return error_set(err, -ENODEV, "%s cannot modeset", card);
	}
	error_set(err, -ENODEV, "%s: no connected %s%s", card,
		  cfg->connector ? "connector " : "connector", cfg->connector ? cfg->connector : "");
	for (int i = 0; i < res->count_connectors && ret < 0; i++) {
		drmModeConnector *c = drmModeGetConnector(d->fd, res->connectors[i]);
		const drmModeModeInfo *m;
		char name[32];

		if (!c)
			continue;
		connector_name(c, name, sizeof(name));
		if (c->connection != DRM_MODE_CONNECTED || c->count_modes <= 0 ||
		    (cfg->connector && strcmp(cfg->connector, name) != 0)) {
			drmModeFreeConnector(c);
			continue;
		}
		m = pick_mode(c, cfg);
		if (!m) {
			error_set(err, -ENODEV, "%s %s has no mode %dx%d@%d", card, name, cfg->width,
				  cfg->height, cfg->refresh);
		} else if (!(d->crtc_id = pick_crtc(d->fd, res, c))) {
			error_set(err, -ENODEV, "%s %s: no CRTC can drive it", card, name);
		} else {
			d->connector_id = c->connector_id;
			d->mode = *m;
			snprintf(d->name, sizeof(d->name), "%s %s %dx%d@%u", card, name, m->hdisplay,
				 m->vdisplay, m->vrefresh);
			ret = 0;
		}
		drmModeFreeConnector(c);
	}
	drmModeFreeResources(res);
	return ret;
}

static int try_card(struct drm_display *d, const struct drm_display_config *cfg, const char *path,
		    struct error *err)
{
	/* direct open: the kiosk runs as root or in the video group (libseat comes later) */
	d->fd = open(path, O_RDWR | O_CLOEXEC);
	if (d->fd < 0)
		return error_set(err, -errno, "%s: %s", path, strerror(errno));
	if (pick_output(d, cfg, path, err) == 0)
		return 0;
	close(d->fd);
	d->fd = -1;
	return -ENODEV;
}

static int cmp_names(const void *a, const void *b)
{
	return strcmp(*(const char *const *)a, *(const char *const *)b);
}

/* Boards have several DRM nodes in no fixed order: try every card, in name order. */
static int open_card(struct drm_display *d, const struct drm_display_config *cfg, struct error *err)
{
	char *names[64], path[300];
	size_t n = 0;
	struct dirent *de;
	DIR *dir;
	int ret = -ENODEV;

	if (cfg->card)
		return try_card(d, cfg, cfg->card, err);
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
			ret = try_card(d, cfg, path, err);
		free(names[i]);
	}
	return ret;
}

/* ---- EGL on GBM ---- */

static bool has_word(const char *list, const char *word)
{
	size_t n = strlen(word);

	for (const char *p = list; p && (p = strstr(p, word)); p += n) {
		if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0'))
			return true;
	}
	return false;
}

/* A config whose native visual is the surface's format; multisampled if there is one. */
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

static int create_egl(struct drm_display *d, struct error *err)
{
	static const int versions[] = { 3, 2 };
	const char *client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
	PFNEGLGETPLATFORMDISPLAYEXTPROC get_display;
	EGLint major, minor;

	if (!client ||
	    (!has_word(client, "EGL_KHR_platform_gbm") && !has_word(client, "EGL_MESA_platform_gbm")))
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
		EGLConfig config;

		if (!choose_config(d->dpy, bit, MSAA_SAMPLES, &config) &&
		    !choose_config(d->dpy, bit, 0, &config))
			continue;
		d->ctx = eglCreateContext(d->dpy, config, EGL_NO_CONTEXT, ctx_attribs);
		if (d->ctx == EGL_NO_CONTEXT)
			continue;
		d->gles3 = versions[i] == 3;
		d->egl_surface = eglCreateWindowSurface(d->dpy, config,
							(EGLNativeWindowType)d->surface, NULL);
		if (d->egl_surface == EGL_NO_SURFACE)
			return error_set(err, -ENODEV, "EGL: cannot make a window surface (error 0x%x)",
					 eglGetError());
		if (!eglMakeCurrent(d->dpy, d->egl_surface, d->egl_surface, d->ctx))
			return error_set(err, -ENODEV, "EGL: cannot make the context current (error 0x%x)",
					 eglGetError());
		glViewport(0, 0, d->mode.hdisplay, d->mode.vdisplay);
		return 0;
	}
	return error_set(err, -ENODEV, "EGL: no GLES 3 or GLES 2 context for XRGB8888 (error 0x%x)",
			 eglGetError());
}

struct drm_display *drm_display_create(const struct drm_display_config *cfg, struct error *err)
{
	static const struct drm_display_config automatic = { 0 };
	struct drm_display *d = calloc(1, sizeof(*d));

	if (!d) {
		error_set(err, -ENOMEM, "display: out of memory");
		return NULL;
	}
	d->fd = -1;
	d->dpy = EGL_NO_DISPLAY;
	d->ctx = EGL_NO_CONTEXT;
	d->egl_surface = EGL_NO_SURFACE;
	if (open_card(d, cfg ? cfg : &automatic, err) < 0)
		goto fail;
	d->row = malloc((size_t)d->mode.hdisplay * 4);
	if (!d->row) {
		error_set(err, -ENOMEM, "display: out of memory");
		goto fail;
	}
	d->saved_crtc = drmModeGetCrtc(d->fd, d->crtc_id);
	d->gbm = gbm_create_device(d->fd);
	if (!d->gbm) {
		error_set(err, -ENODEV, "%s: no GBM device", d->name);
		goto fail;
	}
	d->surface = gbm_surface_create(d->gbm, d->mode.hdisplay, d->mode.vdisplay,
					GBM_FORMAT_XRGB8888, GBM_BO_USE_SCANOUT | GBM_BO_USE_RENDERING);
	if (!d->surface) {
		error_set(err, -ENODEV, "%s: cannot create a GBM surface", d->name);
		goto fail;
	}
	if (create_egl(d, err) < 0)
		goto fail;
	return d;

fail:
	drm_display_destroy(d);
	return NULL;
}

void drm_display_destroy(struct drm_display *d)
{
	if (!d)
		return;
	/* a flip still queued would land on a framebuffer we are about to remove */
	while (d->flip_pending) {
		struct pollfd p = { .fd = d->fd, .events = POLLIN };

		/* bounded: a display unplugged mid-flip never sends its event */
		if (poll(&p, 1, 500) <= 0 || drm_display_dispatch(d) < 0)
			break;
	}
	if (d->mode_set && d->saved_crtc) {
		drmModeCrtc *s = d->saved_crtc;

		if (drmModeSetCrtc(d->fd, s->crtc_id, s->buffer_id, s->x, s->y, &d->connector_id, 1,
				   s->mode_valid ? &s->mode : NULL) < 0)
			fprintf(stderr, "edaha: cannot restore the previous display mode: %s\n",
				strerror(errno));
	}
	drmModeFreeCrtc(d->saved_crtc);
	/* buffers go back to the surface while EGL's side of it still exists: Mesa's release
	 * looks the buffer up in the EGL surface, which eglDestroySurface frees (and with it
	 * every buffer, whose framebuffers destroy_fb removes) */
	if (d->front)
		gbm_surface_release_buffer(d->surface, d->front);
	if (d->next && d->next != d->front)
		gbm_surface_release_buffer(d->surface, d->next);
	d->front = d->next = NULL;
	if (d->dpy != EGL_NO_DISPLAY) {
		eglMakeCurrent(d->dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
		if (d->egl_surface != EGL_NO_SURFACE)
			eglDestroySurface(d->dpy, d->egl_surface);
		if (d->ctx != EGL_NO_CONTEXT)
			eglDestroyContext(d->dpy, d->ctx);
		eglTerminate(d->dpy);
		/* frees EGL's per-thread state, which would otherwise outlive us */
		eglReleaseThread();
	}
	if (d->surface)
		gbm_surface_destroy(d->surface);
	if (d->gbm)
		gbm_device_destroy(d->gbm);
	if (d->fd >= 0)
		close(d->fd);
	free(d->row);
	free(d);
}

int drm_display_fd(const struct drm_display *d)
{
	return d->fd;
}

void drm_display_size(const struct drm_display *d, int *width, int *height)
{
	*width = d->mode.hdisplay;
	*height = d->mode.vdisplay;
}

const char *drm_display_describe(const struct drm_display *d)
{
	return d->name;
}

bool drm_display_gles3(const struct drm_display *d)
{
	return d->gles3;
}

bool drm_display_flip_pending(const struct drm_display *d)
{
	return d->flip_pending;
}

int drm_display_read_rgba(struct drm_display *d, uint8_t *rgba)
{
	int w = d->mode.hdisplay, h = d->mode.vdisplay;
	size_t stride = (size_t)w * 4;

	/* the back buffer, before the swap; a multisampled one is resolved by the read */
	glPixelStorei(GL_PACK_ALIGNMENT, 1);
	glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
	if (glGetError() != GL_NO_ERROR)
		return -EIO;
	/* GL's first row is the bottom one */
	for (int y = 0; y < h / 2; y++) {
		uint8_t *top = rgba + (size_t)y * stride;
		uint8_t *bottom = rgba + (size_t)(h - 1 - y) * stride;

		memcpy(d->row, top, stride);
		memcpy(top, bottom, stride);
		memcpy(bottom, d->row, stride);
	}
	return 0;
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
	struct gbm_bo *bo;
	uint32_t fb = 0;
	int ret;

	if (d->flip_pending)
		return -EBUSY;
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
		/* the first frame: no flip event comes, the buffer is the front at once */
		if (drmModeSetCrtc(d->fd, d->crtc_id, fb, 0, 0, &d->connector_id, 1, &d->mode) < 0) {
			ret = -errno;
			gbm_surface_release_buffer(d->surface, bo);
			return ret;
		}
		d->mode_set = true;
		d->front = bo;
		return 0;
	}
	if (drmModePageFlip(d->fd, d->crtc_id, fb, DRM_MODE_PAGE_FLIP_EVENT, d) < 0) {
		ret = -errno;
		gbm_surface_release_buffer(d->surface, bo);
		return ret;
	}
	d->next = bo;
	d->flip_pending = true;
	return 0;
}

static void flip_done(int fd, unsigned seq, unsigned sec, unsigned usec, void *data)
{
	struct drm_display *d = data;

	(void)fd, (void)seq, (void)sec, (void)usec;
	/* the old front is off the screen now: the surface may draw into it again */
	if (d->front)
		gbm_surface_release_buffer(d->surface, d->front);
	d->front = d->next;
	d->next = NULL;
	d->flip_pending = false;
}

int drm_display_dispatch(struct drm_display *d)
{
	drmEventContext ev = {
		.version = 2,
		.page_flip_handler = flip_done,
	};

	if (drmHandleEvent(d->fd, &ev) < 0)
		return errno ? -errno : -EIO;
	return 0;
}
