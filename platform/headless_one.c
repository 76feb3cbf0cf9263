/* SPDX-License-Identifier: MIT */
/* What the runs showing one object alone share (headless_one.h). */
#include "headless_one.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "egl_headless.h"
#include "fileio.h"
#include "font_file.h"
#include "pngio.h"
#include "render.h"

int headless_input_status(int err)
{
	return err == -ENOMEM || err == -EIO ? 1 : 2;
}

bool headless_is_preset(const char *const *names, size_t n, const char *arg)
{
	for (size_t i = 0; i < n; i++)
		if (strcmp(names[i], arg) == 0)
			return true;
	return false;
}

int headless_no_such_preset(const char *opt, const char *what, const char *arg,
			    const char *const *names, size_t n)
{
	fprintf(stderr, "edaha: %s \"%s\": no such %s preset or file (presets:", opt, arg, what);
	for (size_t i = 0; i < n; i++)
		fprintf(stderr, "%s %s", i ? "," : "", names[i]);
	fputs(")\n", stderr);
	return 2;
}

int headless_set_text(struct render *render, const struct options *o)
{
	struct error err = { { 0 } };
	enum render_lang lang = o->lang && !strcmp(o->lang, "ja") ? RENDER_LANG_JA : RENDER_LANG_EN;
	const char *used;
	char *font;
	size_t len;
	int ret = font_file_read(NULL, &font, &len, &used, &err);

	if (ret < 0) {
		fprintf(stderr, "edaha: %s\n", err.msg);
		return ret;
	}
	ret = render_set_text(render, font, len, lang);
	if (ret < 0)
		fprintf(stderr, "edaha: %s: cannot use this font for the labels\n", used);
	free(font);
	return ret;
}

int headless_one_picture(const struct options *o,
			 int (*draw)(struct render *r, const void *ctx, int width, int height),
			 const void *ctx, struct buf *png)
{
	struct error err = { { 0 } };
	struct egl_headless *egl;
	struct render *render;
	uint8_t *rgba;
	int status = 1;

	egl = egl_headless_create(o->width, o->height, &err);
	if (!egl) {
		fprintf(stderr, "edaha: no headless GL: %s\n", err.msg);
		return 1;
	}
	render = render_create();
	rgba = malloc((size_t)o->width * (size_t)o->height * 4);
	if (!render || !rgba)
		fprintf(stderr, "edaha: cannot set up the renderer\n");
	else if (draw(render, ctx, o->width, o->height) < 0 || egl_headless_read_rgba(egl, rgba) < 0)
		fprintf(stderr, "edaha: rendering failed\n");
	else if (pngio_encode_rgba(rgba, o->width, o->height, png, &err) < 0)
		fprintf(stderr, "edaha: screen.png: %s\n", err.msg);
	else
		status = 0;
	free(rgba);
	render_destroy(render);
	egl_headless_destroy(egl);
	return status;
}

int headless_one_write(const char *dir, const char *const *names, const struct buf *files,
		       size_t n)
{
	struct error err = { { 0 } };
	int ret = fileio_mkdirs(dir, &err);

	for (size_t i = 0; i < n && ret == 0; i++)
		ret = fileio_write_atomic(dir, names[i], files[i].data, files[i].len, &err);
	if (ret < 0) {
		fprintf(stderr, "edaha: %s\n", err.msg);
		return 1;
	}
	return 0;
}
