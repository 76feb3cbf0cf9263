/* SPDX-License-Identifier: MIT */
#include "egl_headless.h"
#include "gl_util.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GLES3/gl3.h>
#include <errno.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

/* Strokes are antialiased by multisampling; 4x is what every GLES 3 driver must offer. */
#define MSAA_SAMPLES 4

struct egl_headless {
	EGLDisplay dpy;
	EGLContext ctx;
	int width, height;
	bool gles3;
	/* what is drawn into: multisampled when samples > 0 */
	GLuint fbo, color_rb, depth_rb;
	int samples;
	/* single-sampled copy read back from, when multisampling */
	GLuint resolve_fbo, resolve_rb;
	uint8_t *row; /* scratch for flipping rows */
};

/*
 * The surfaceless display is one per process and eglTerminate() ends it for every
 * context on it: only the last instance to go terminates it.
 */
static int display_users;

static EGLDisplay get_surfaceless_display(struct error *err)
{
	const char *client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
	PFNEGLGETPLATFORMDISPLAYPROC get_platform_display;
	PFNEGLGETPLATFORMDISPLAYEXTPROC get_platform_display_ext;
	EGLDisplay dpy;

	if (!client || !gl_has_extension(client, "EGL_MESA_platform_surfaceless")) {
		error_set(err, -ENODEV,
			  "EGL: no surfaceless platform (EGL_MESA_platform_surfaceless missing; "
			  "is Mesa's libEGL (libegl-mesa0) installed?)");
		return EGL_NO_DISPLAY;
	}
	/* EGL 1.5 core first; the EXT entry point for 1.4 libraries */
	get_platform_display = (PFNEGLGETPLATFORMDISPLAYPROC)eglGetProcAddress("eglGetPlatformDisplay");
	if (get_platform_display) {
		dpy = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
	} else {
		get_platform_display_ext = (PFNEGLGETPLATFORMDISPLAYEXTPROC)eglGetProcAddress(
			"eglGetPlatformDisplayEXT");
		if (!get_platform_display_ext) {
			error_set(err, -ENODEV, "EGL: no eglGetPlatformDisplay(EXT)");
			return EGL_NO_DISPLAY;
		}
		dpy = get_platform_display_ext(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY,
					       NULL);
	}
	if (dpy == EGL_NO_DISPLAY)
		error_set(err, -ENODEV, "EGL: no surfaceless display (error 0x%x)", eglGetError());
	return dpy;
}

/* A GLES 3 context if the driver has one, else GLES 2. */
static int create_context(struct egl_headless *e, struct error *err)
{
	static const int versions[] = { 3, 2 };
	const char *exts = eglQueryString(e->dpy, EGL_EXTENSIONS);

	if (!exts || !gl_has_extension(exts, "EGL_KHR_surfaceless_context"))
		return error_set(err, -ENODEV, "EGL: no EGL_KHR_surfaceless_context");
	if (!eglBindAPI(EGL_OPENGL_ES_API))
		return error_set(err, -ENODEV, "EGL: no OpenGL ES API (error 0x%x)", eglGetError());

	for (size_t i = 0; i < sizeof(versions) / sizeof(versions[0]); i++) {
		const EGLint config_attribs[] = {
			EGL_RENDERABLE_TYPE, versions[i] == 3 ? EGL_OPENGL_ES3_BIT : EGL_OPENGL_ES2_BIT,
			/* we never make a surface: any config type will do */
			EGL_SURFACE_TYPE, EGL_DONT_CARE,
			EGL_NONE,
		};
		/* EGL_CONTEXT_CLIENT_VERSION: the same token as EGL 1.5's MAJOR_VERSION */
		const EGLint context_attribs[] = { EGL_CONTEXT_CLIENT_VERSION, versions[i], EGL_NONE };
		EGLConfig config;
		EGLint n = 0;

		if (!eglChooseConfig(e->dpy, config_attribs, &config, 1, &n) || n < 1)
			continue;
		e->ctx = eglCreateContext(e->dpy, config, EGL_NO_CONTEXT, context_attribs);
		if (e->ctx != EGL_NO_CONTEXT) {
			e->gles3 = versions[i] >= 3;
			return 0;
		}
	}
	return error_set(err, -ENODEV, "EGL: cannot create a GLES 3 or GLES 2 context (error 0x%x)",
			 eglGetError());
}

static int create_framebuffers(struct egl_headless *e, struct error *err)
{
	const char *exts = (const char *)glGetString(GL_EXTENSIONS);
	GLenum color_format = GL_RGBA8, depth_format = GL_DEPTH_COMPONENT24;
	GLenum status;

	if (e->gles3) {
		GLint max_samples = 0;

		glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
		e->samples = max_samples < MSAA_SAMPLES ? max_samples : MSAA_SAMPLES;
	} else {
		/* GLES 2 core only has 16-bit formats; the extensions bring the usual ones */
		if (!gl_has_extension(exts, "GL_OES_rgb8_rgba8"))
			color_format = GL_RGBA4;
		if (!gl_has_extension(exts, "GL_OES_depth24"))
			depth_format = GL_DEPTH_COMPONENT16;
	}

	glGenFramebuffers(1, &e->fbo);
	glBindFramebuffer(GL_FRAMEBUFFER, e->fbo);
	e->color_rb = gl_make_renderbuffer(color_format, e->samples, e->width, e->height);
	glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, e->color_rb);
	e->depth_rb = gl_make_renderbuffer(depth_format, e->samples, e->width, e->height);
	glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, e->depth_rb);
	status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
	if (status != GL_FRAMEBUFFER_COMPLETE)
		return error_set(err, -EIO, "GL: framebuffer incomplete (0x%x)", status);

	if (e->samples > 0) {
		glGenFramebuffers(1, &e->resolve_fbo);
		glBindFramebuffer(GL_FRAMEBUFFER, e->resolve_fbo);
		e->resolve_rb = gl_make_renderbuffer(color_format, 0, e->width, e->height);
		glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
					  e->resolve_rb);
		status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
		if (status != GL_FRAMEBUFFER_COMPLETE)
			return error_set(err, -EIO, "GL: resolve framebuffer incomplete (0x%x)", status);
	}

	glBindFramebuffer(GL_FRAMEBUFFER, e->fbo);
	glViewport(0, 0, e->width, e->height);
	if (glGetError() != GL_NO_ERROR)
		return error_set(err, -EIO, "GL: cannot create a %dx%d framebuffer", e->width,
				 e->height);
	return 0;
}

struct egl_headless *egl_headless_create(int width, int height, struct error *err)
{
	struct egl_headless *e;
	EGLint major, minor;
	GLint max_size = 0;

	if (width <= 0 || height <= 0) {
		error_set(err, -EINVAL, "headless: bad framebuffer size %dx%d", width, height);
		return NULL;
	}
	e = calloc(1, sizeof(*e));
	if (!e) {
		error_set(err, -ENOMEM, "headless: out of memory");
		return NULL;
	}
	e->width = width;
	e->height = height;
	e->ctx = EGL_NO_CONTEXT;
	e->row = malloc((size_t)width * 4);
	if (!e->row) {
		error_set(err, -ENOMEM, "headless: out of memory");
		goto fail;
	}

	e->dpy = get_surfaceless_display(err);
	if (e->dpy == EGL_NO_DISPLAY)
		goto fail;
	if (!eglInitialize(e->dpy, &major, &minor)) {
		error_set(err, -ENODEV, "EGL: cannot initialise the surfaceless display (error 0x%x)",
			  eglGetError());
		e->dpy = EGL_NO_DISPLAY;
		goto fail;
	}
	display_users++;
	if (create_context(e, err) < 0)
		goto fail;
	if (!eglMakeCurrent(e->dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, e->ctx)) {
		error_set(err, -ENODEV, "EGL: cannot make the context current (error 0x%x)",
			  eglGetError());
		goto fail;
	}
	glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_size);
	if (width > max_size || height > max_size) {
		error_set(err, -EINVAL, "GL: %dx%d is larger than the driver's %d", width, height,
			  max_size);
		goto fail;
	}
	if (create_framebuffers(e, err) < 0)
		goto fail;
	return e;

fail:
	egl_headless_destroy(e);
	return NULL;
}

void egl_headless_destroy(struct egl_headless *e)
{
	if (!e)
		return;
	if (e->ctx != EGL_NO_CONTEXT) {
		/* GL names are only valid with our context current */
		if (eglGetCurrentContext() == e->ctx) {
			glBindFramebuffer(GL_FRAMEBUFFER, 0);
			glDeleteFramebuffers(1, &e->resolve_fbo);
			glDeleteRenderbuffers(1, &e->resolve_rb);
			glDeleteFramebuffers(1, &e->fbo);
			glDeleteRenderbuffers(1, &e->color_rb);
			glDeleteRenderbuffers(1, &e->depth_rb);
			eglMakeCurrent(e->dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
		}
		eglDestroyContext(e->dpy, e->ctx);
	}
	if (e->dpy != EGL_NO_DISPLAY && --display_users == 0) {
		eglTerminate(e->dpy);
		/* frees EGL's per-thread state, which would otherwise outlive us */
		eglReleaseThread();
	}
	free(e->row);
	free(e);
}

int egl_headless_read_rgba(struct egl_headless *e, uint8_t *rgba)
{
	int ret;

	if (e->samples > 0) {
		/* samples cannot be read directly: average them into the single-sampled copy */
		glBindFramebuffer(GL_READ_FRAMEBUFFER, e->fbo);
		glBindFramebuffer(GL_DRAW_FRAMEBUFFER, e->resolve_fbo);
		glBlitFramebuffer(0, 0, e->width, e->height, 0, 0, e->width, e->height,
				  GL_COLOR_BUFFER_BIT, GL_NEAREST);
		glBindFramebuffer(GL_READ_FRAMEBUFFER, e->resolve_fbo);
	}
	ret = gl_read_rgba(e->width, e->height, rgba, e->row);
	/* leave the drawing framebuffer bound, as create did */
	glBindFramebuffer(GL_FRAMEBUFFER, e->fbo);
	return ret;
}
