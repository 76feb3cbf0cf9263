/* SPDX-License-Identifier: MIT */
#include "offscreen.h"
#include "gl_util.h"

#include <GLES3/gl3.h>
#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Strokes are antialiased by multisampling, as in the window's and the headless
 * framebuffers. */
#define MSAA_SAMPLES 4

enum { ATTR_POS = 0, ATTR_UV = 1 };

struct offscreen {
	int width, height;
	int samples;             /* 0: drawn straight into the texture */
	GLuint fbo, color_rb, depth_rb;
	GLuint resolve_fbo;      /* with samples: the single-sampled copy (the texture's) */
	GLuint texture;          /* the picture, sampled by the pass that shows it */
	bool resolved;           /* the texture has what was drawn since the last show */
	GLuint program;
	GLint tex_uniform;
	uint8_t *row;            /* scratch for flipping rows */
};

/* GLSL ES 1.00: the pass is the same on GLES 2 and 3. */
static const char vertex_src[] =
	"attribute vec2 pos;\n"
	"attribute vec2 uv;\n"
	"varying vec2 v_uv;\n"
	"void main() {\n"
	"	v_uv = uv;\n"
	"	gl_Position = vec4(pos, 0.0, 1.0);\n"
	"}\n";
/* highp where there is one: mediump's 10 bits cannot address texels past 1024 */
static const char fragment_src[] =
	"#ifdef GL_FRAGMENT_PRECISION_HIGH\n"
	"precision highp float;\n"
	"#else\n"
	"precision mediump float;\n"
	"#endif\n"
	"uniform sampler2D tex;\n"
	"varying vec2 v_uv;\n"
	"void main() {\n"
	"	gl_FragColor = vec4(texture2D(tex, v_uv).rgb, 1.0);\n"
	"}\n";

/* ---- geometry ---- */

void offscreen_turned_size(int rotation, int screen_w, int screen_h, int *w, int *h)
{
	bool turned = rotation == 90 || rotation == 270;

	*w = turned ? screen_h : screen_w;
	*h = turned ? screen_w : screen_h;
}

/* From the viewer's clip space to the screen's, for a screen turned clockwise: the
 * picture turns the other way. */
static void turn(int rotation, float vx, float vy, float *x, float *y)
{
	switch (rotation) {
	case 90:
		*x = -vy, *y = vx;
		break;
	case 180:
		*x = -vx, *y = -vy;
		break;
	case 270:
		*x = vy, *y = -vx;
		break;
	default:
		*x = vx, *y = vy;
		break;
	}
}

void offscreen_geometry(int rotation, int width, int height, int screen_w, int screen_h,
			struct offscreen_geometry *g)
{
	static const float corners[4][2] = { { 0, 0 }, { 1, 0 }, { 0, 1 }, { 1, 1 } };
	int64_t vw, vh, w, h;
	int tw, th;
	float left, right, top, bottom;

	offscreen_turned_size(rotation, screen_w, screen_h, &tw, &th);
	vw = tw, vh = th;
	/* the side that runs out first sets the scale; the other is rounded */
	if (vw * height <= vh * width) {
		w = vw;
		h = (2 * height * vw + width) / (2 * (int64_t)width);
	} else {
		h = vh;
		w = (2 * width * vh + height) / (2 * (int64_t)height);
	}
	if (w < 1)
		w = 1;
	if (h < 1)
		h = 1;
	/* whole pixels from the top left, so that an unscaled picture maps texel to pixel */
	left = 2.0f * (float)((vw - w) / 2) / (float)vw - 1.0f;
	right = left + 2.0f * (float)w / (float)vw;
	top = 1.0f - 2.0f * (float)((vh - h) / 2) / (float)vh;
	bottom = top - 2.0f * (float)h / (float)vh;
	for (int i = 0; i < 4; i++) {
		float vx = corners[i][0] ? right : left, vy = corners[i][1] ? top : bottom;

		turn(rotation, vx, vy, &g->quad[i][0], &g->quad[i][1]);
		g->quad[i][2] = corners[i][0];
		g->quad[i][3] = corners[i][1];
	}
	g->w = (int)w;
	g->h = (int)h;
	g->one_to_one = w == width && h == height;
}

/* ---- GL ---- */

static GLuint compile(GLenum type, const char *src, struct error *err)
{
	GLuint s = glCreateShader(type);
	GLint ok = 0;
	char log[256] = "";

	glShaderSource(s, 1, &src, NULL);
	glCompileShader(s);
	glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
	if (!ok) {
		glGetShaderInfoLog(s, sizeof(log), NULL, log);
		error_set(err, -EIO, "GL: the screen-turning shader does not compile: %s", log);
		glDeleteShader(s);
		return 0;
	}
	return s;
}

static int make_program(struct offscreen *o, struct error *err)
{
	GLuint vs = compile(GL_VERTEX_SHADER, vertex_src, err), fs = 0;
	GLint ok = 0;

	if (vs)
		fs = compile(GL_FRAGMENT_SHADER, fragment_src, err);
	if (!fs) {
		glDeleteShader(vs);
		return -EIO;
	}
	o->program = glCreateProgram();
	glAttachShader(o->program, vs);
	glAttachShader(o->program, fs);
	glBindAttribLocation(o->program, ATTR_POS, "pos");
	glBindAttribLocation(o->program, ATTR_UV, "uv");
	glLinkProgram(o->program);
	/* the program keeps them until it goes */
	glDeleteShader(vs);
	glDeleteShader(fs);
	glGetProgramiv(o->program, GL_LINK_STATUS, &ok);
	if (!ok)
		return error_set(err, -EIO, "GL: the screen-turning shader does not link");
	o->tex_uniform = glGetUniformLocation(o->program, "tex");
	return 0;
}

static int make_texture(struct offscreen *o, bool gles3)
{
	glGenTextures(1, &o->texture);
	glBindTexture(GL_TEXTURE_2D, o->texture);
	/* sized storage on GLES 3: a blit from the multisampled RGBA8 needs the same format */
	if (gles3)
		glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA8, o->width, o->height);
	else
		glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, o->width, o->height, 0, GL_RGBA,
			     GL_UNSIGNED_BYTE, NULL);
	/* GLES 2 samples sizes that are no power of two only clamped, without mipmaps */
	glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
	glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
	glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
	glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
	glBindTexture(GL_TEXTURE_2D, 0);
	return glGetError() == GL_NO_ERROR ? 0 : -EIO;
}

static int make_framebuffers(struct offscreen *o, bool gles3, struct error *err)
{
	const char *exts = (const char *)glGetString(GL_EXTENSIONS);
	GLenum depth = gles3 || gl_has_extension(exts, "GL_OES_depth24") ? GL_DEPTH_COMPONENT24
								   : GL_DEPTH_COMPONENT16;
	GLenum status;

	if (gles3) {
		GLint max_samples = 0;

		glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
		o->samples = max_samples < MSAA_SAMPLES ? max_samples : MSAA_SAMPLES;
	}
	if (make_texture(o, gles3) < 0)
		return error_set(err, -EIO, "GL: cannot make a %dx%d texture", o->width, o->height);
	glGenFramebuffers(1, &o->fbo);
	glBindFramebuffer(GL_FRAMEBUFFER, o->fbo);
	if (o->samples > 0) {
		o->color_rb = gl_make_renderbuffer(GL_RGBA8, o->samples, o->width, o->height);
		glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
					  o->color_rb);
	} else {
		glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D,
				       o->texture, 0);
	}
	o->depth_rb = gl_make_renderbuffer(depth, o->samples, o->width, o->height);
	glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, o->depth_rb);
	status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
	if (status != GL_FRAMEBUFFER_COMPLETE)
		return error_set(err, -EIO, "GL: offscreen framebuffer incomplete (0x%x)", status);
	if (o->samples > 0) {
		glGenFramebuffers(1, &o->resolve_fbo);
		glBindFramebuffer(GL_FRAMEBUFFER, o->resolve_fbo);
		glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D,
				       o->texture, 0);
		status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
		if (status != GL_FRAMEBUFFER_COMPLETE)
			return error_set(err, -EIO, "GL: resolve framebuffer incomplete (0x%x)",
					 status);
	} else {
		o->resolve_fbo = o->fbo;
	}
	offscreen_bind(o);
	if (glGetError() != GL_NO_ERROR)
		return error_set(err, -EIO, "GL: cannot make a %dx%d offscreen framebuffer",
				 o->width, o->height);
	return 0;
}

struct offscreen *offscreen_create(int width, int height, bool gles3, struct error *err)
{
	struct offscreen *o = calloc(1, sizeof(*o));

	if (!o || !(o->row = malloc((size_t)width * 4))) {
		free(o);
		error_set(err, -ENOMEM, "offscreen: out of memory");
		return NULL;
	}
	o->width = width;
	o->height = height;
	/* errors left by others are not ours */
	while (glGetError() != GL_NO_ERROR)
		;
	if (make_program(o, err) < 0 || make_framebuffers(o, gles3, err) < 0) {
		offscreen_destroy(o);
		return NULL;
	}
	return o;
}

void offscreen_destroy(struct offscreen *o)
{
	if (!o)
		return;
	glBindFramebuffer(GL_FRAMEBUFFER, 0);
	if (o->resolve_fbo != o->fbo)
		glDeleteFramebuffers(1, &o->resolve_fbo);
	glDeleteFramebuffers(1, &o->fbo);
	glDeleteRenderbuffers(1, &o->color_rb);
	glDeleteRenderbuffers(1, &o->depth_rb);
	glDeleteTextures(1, &o->texture);
	glDeleteProgram(o->program);
	free(o->row);
	free(o);
}

void offscreen_bind(struct offscreen *o)
{
	glBindFramebuffer(GL_FRAMEBUFFER, o->fbo);
	glViewport(0, 0, o->width, o->height);
}

/* Samples cannot be read or sampled: average them into the texture, once a frame. */
static void resolve(struct offscreen *o)
{
	if (o->samples == 0 || o->resolved)
		return;
	glBindFramebuffer(GL_READ_FRAMEBUFFER, o->fbo);
	glBindFramebuffer(GL_DRAW_FRAMEBUFFER, o->resolve_fbo);
	glBlitFramebuffer(0, 0, o->width, o->height, 0, 0, o->width, o->height,
			  GL_COLOR_BUFFER_BIT, GL_NEAREST);
	o->resolved = true;
}

int offscreen_read_rgba(struct offscreen *o, uint8_t *rgba)
{
	int ret;

	resolve(o);
	glBindFramebuffer(GL_FRAMEBUFFER, o->resolve_fbo);
	ret = gl_read_rgba(o->width, o->height, rgba, o->row);
	offscreen_bind(o);
	return ret;
}

int offscreen_show(struct offscreen *o, int rotation, int screen_w, int screen_h)
{
	struct offscreen_geometry g;
	GLint filter;

	offscreen_geometry(rotation, o->width, o->height, screen_w, screen_h, &g);
	filter = g.one_to_one ? GL_NEAREST : GL_LINEAR;
	/* the app's renderer reports its own errors */
	while (glGetError() != GL_NO_ERROR)
		;
	resolve(o);
	glBindFramebuffer(GL_FRAMEBUFFER, 0);
	glViewport(0, 0, screen_w, screen_h);
	/* the app's frame may have left any of these on */
	glDisable(GL_DEPTH_TEST);
	glDisable(GL_BLEND);
	glDisable(GL_SCISSOR_TEST);
	glDisable(GL_CULL_FACE);
	glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
	glDepthMask(GL_TRUE);
	/* black where a scaled picture leaves the screen uncovered */
	glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
	glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
	glUseProgram(o->program);
	glUniform1i(o->tex_uniform, 0);
	glActiveTexture(GL_TEXTURE0);
	glBindTexture(GL_TEXTURE_2D, o->texture);
	glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
	glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
	/* client-side arrays: the app's renderer draws them too, with no buffer bound */
	glBindBuffer(GL_ARRAY_BUFFER, 0);
	glEnableVertexAttribArray(ATTR_POS);
	glEnableVertexAttribArray(ATTR_UV);
	glVertexAttribPointer(ATTR_POS, 2, GL_FLOAT, GL_FALSE, sizeof(g.quad[0]), &g.quad[0][0]);
	glVertexAttribPointer(ATTR_UV, 2, GL_FLOAT, GL_FALSE, sizeof(g.quad[0]), &g.quad[0][2]);
	glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
	glBindTexture(GL_TEXTURE_2D, 0);
	glUseProgram(0);
	o->resolved = false;
	/* the swap takes what was drawn into the window's framebuffer, whatever is bound */
	offscreen_bind(o);
	return glGetError() == GL_NO_ERROR ? 0 : -EIO;
}
