/* SPDX-License-Identifier: MIT */
/*
 * render-scene [--twice] SCENE OUT.png: renders a hand-built scene (tests/render/scene.c)
 * headless, with the labels' font (platform/files/font_file.c's defaults), and writes it as
 * PNG. With --twice it renders again, with the same and with a fresh renderer, and fails
 * unless all frames are byte-identical.
 */
#include <errno.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "buf.h"
#include "egl_headless.h"
#include "font_file.h"
#include "pngio.h"
#include "render.h"
#include "scene.h"

static const char *font_data;
static size_t font_len;

static struct render *renderer(const char *scene)
{
	struct render *r = render_create();
	int ret;

	if (!r)
		return NULL;
	ret = render_set_text(r, font_data, font_len,
			      scene_japanese(scene) ? RENDER_LANG_JA : RENDER_LANG_EN);
	if (ret < 0) {
		fprintf(stderr, "render-scene: render_set_text: %s\n", strerror(-ret));
		render_destroy(r);
		return NULL;
	}
	return r;
}

static int render_once(struct render *r, struct egl_headless *egl, const struct app *app,
		       uint64_t now_us, uint8_t *rgba)
{
	int ret = render_frame_at(r, app, now_us);

	if (ret < 0) {
		fprintf(stderr, "render-scene: render_frame: %s\n", strerror(-ret));
		return ret;
	}
	ret = egl_headless_read_rgba(egl, rgba);
	if (ret < 0)
		fprintf(stderr, "render-scene: read back: %s\n", strerror(-ret));
	return ret;
}

static int write_png(const char *path, const uint8_t *rgba, int width, int height)
{
	struct buf b;
	struct error err;
	FILE *f;
	int ret;

	buf_init(&b);
	ret = pngio_encode_rgba(rgba, width, height, &b, &err);
	if (ret < 0) {
		fprintf(stderr, "render-scene: %s\n", err.msg);
		buf_finish(&b);
		return ret;
	}
	f = fopen(path, "wb");
	if (!f) {
		ret = -errno;
	} else {
		if (fwrite(b.data, 1, b.len, f) != b.len)
			ret = -EIO;
		if (fclose(f) != 0 && ret == 0)
			ret = -errno;
	}
	if (ret < 0)
		fprintf(stderr, "render-scene: %s: %s\n", path, strerror(-ret));
	buf_finish(&b);
	return ret;
}

int main(int argc, char **argv)
{
	struct app app;
	struct egl_headless *egl = NULL;
	struct render *r = NULL, *fresh = NULL;
	struct error err;
	uint8_t *rgba = NULL, *again = NULL;
	bool twice = argc == 4 && !strcmp(argv[1], "--twice");
	const char *scene, *out, *font_name;
	char *font = NULL;
	uint64_t now_us;
	size_t size;
	int ret, status = 1;

	if (argc != 3 && !twice) {
		fprintf(stderr, "usage: render-scene [--twice] SCENE OUT.png\nscenes:");
		for (size_t i = 0; scene_names[i]; i++)
			fprintf(stderr, " %s", scene_names[i]);
		fprintf(stderr, "\n");
		return 2;
	}
	scene = argv[argc - 2];
	out = argv[argc - 1];
	now_us = scene_time_us(scene);
	if (font_file_read(NULL, &font, &font_len, &font_name, &err) < 0) {
		fprintf(stderr, "render-scene: %s\n", err.msg);
		return 1;
	}
	font_data = font;
	ret = scene_build(&app, scene);
	if (ret < 0) {
		fprintf(stderr, "render-scene: scene '%s': %s\n", scene, strerror(-ret));
		free(font);
		return 2;
	}

	egl = egl_headless_create(app.screen.width, app.screen.height, &err);
	if (!egl) {
		fprintf(stderr, "render-scene: %s\n", err.msg);
		goto out;
	}
	r = renderer(scene);
	size = (size_t)app.screen.width * (size_t)app.screen.height * 4;
	rgba = malloc(size);
	again = malloc(size);
	if (!r || !rgba || !again) {
		fprintf(stderr, "render-scene: cannot set up the renderer\n");
		goto out;
	}
	if (render_once(r, egl, &app, now_us, rgba) < 0)
		goto out;

	if (twice) {
		/* the same renderer (no upload this time), then a new one (uploads again) */
		if (render_once(r, egl, &app, now_us, again) < 0)
			goto out;
		if (memcmp(rgba, again, size) != 0) {
			fprintf(stderr, "render-scene: %s: a second frame differs\n", scene);
			goto out;
		}
		fresh = renderer(scene);
		if (!fresh || render_once(fresh, egl, &app, now_us, again) < 0)
			goto out;
		if (memcmp(rgba, again, size) != 0) {
			fprintf(stderr, "render-scene: %s: a new renderer draws differently\n", scene);
			goto out;
		}
	}
	if (write_png(out, rgba, app.screen.width, app.screen.height) < 0)
		goto out;
	status = 0;
out:
	free(rgba);
	free(again);
	render_destroy(fresh);
	render_destroy(r);
	egl_headless_destroy(egl);
	scene_finish(&app);
	free(font);
	return status;
}
