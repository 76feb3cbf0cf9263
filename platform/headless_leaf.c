/* SPDX-License-Identifier: MIT */
/*
 * edaha --headless --leaf NAME|FILE [--opening T]: an origami leaf alone (issue 15, seed
 * 003), written to --out as origami.json, leaf.glb and screen.png. Everything is built and
 * drawn before the folder is touched, so a design that will not fold writes nothing.
 */
#include "headless.h"

#include <errno.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "buf.h"
#include "egl_headless.h"
#include "export.h"
#include "fileio.h"
#include "mesh.h"
#include "ori.h"
#include "ori_json.h"
#include "pngio.h"
#include "render.h"

/* A design file is small (ORI_READ_MAX_BYTES, which ori_read tells at the file's first
 * line); anything past this is not read at all. */
#define LEAF_FILE_MAX (1u << 20)

/* Exit status for a failure to read input: the input's fault (2) or the machine's (1). */
static int input_status(int err)
{
	return err == -ENOMEM || err == -EIO ? 1 : 2;
}

static bool is_preset(const char *name)
{
	size_t n;
	const char *const *names = ori_preset_names(&n);

	for (size_t i = 0; i < n; i++)
		if (strcmp(names[i], name) == 0)
			return true;
	return false;
}

/* A name that is no preset and nothing on disk: most likely a preset misspelt. */
static int no_such_leaf(const char *arg)
{
	size_t n;
	const char *const *names = ori_preset_names(&n);

	fprintf(stderr, "edaha: --leaf \"%s\": no such leaf preset or file (presets:", arg);
	for (size_t i = 0; i < n; i++)
		fprintf(stderr, "%s %s", i ? "," : "", names[i]);
	fputs(")\n", stderr);
	return 2;
}

/* The design: a preset's, else a file's, read through fileio and named by its path. */
static int read_design(const char *arg, struct ori_design *d)
{
	struct error err = { { 0 } };
	struct stat st;
	size_t len;
	char *data;
	int ret;

	if (is_preset(arg)) {
		ret = ori_preset(arg, d, &err);
		if (ret < 0) /* compiled in and tested: not the visitor's fault */
			fprintf(stderr, "edaha: leaf preset %s: %s\n", arg, err.msg);
		return ret < 0 ? 1 : 0;
	}
	if (stat(arg, &st) < 0 && (errno == ENOENT || errno == ENOTDIR))
		return no_such_leaf(arg);
	ret = fileio_read_all(arg, LEAF_FILE_MAX, &data, &len, &err);
	if (ret == 0) {
		ret = ori_read(data, len, arg, d, &err);
		free(data);
	}
	if (ret < 0) {
		fprintf(stderr, "edaha: %s\n", err.msg);
		return input_status(ret);
	}
	return 0;
}

/* The leaf's picture, RGBA top row first (malloc'ed). 0, or 1 with stderr saying why. */
static int draw(const struct options *o, const struct mesh *m, uint8_t **rgba)
{
	struct error err = { { 0 } };
	struct egl_headless *egl;
	struct render *render;
	int status = 1;

	*rgba = NULL;
	egl = egl_headless_create(o->width, o->height, &err);
	if (!egl) {
		fprintf(stderr, "edaha: no headless GL: %s\n", err.msg);
		return 1;
	}
	render = render_create();
	*rgba = malloc((size_t)o->width * (size_t)o->height * 4);
	if (!render || !*rgba)
		fprintf(stderr, "edaha: cannot set up the renderer\n");
	else if (render_leaf(render, m, o->width, o->height) < 0 ||
		 egl_headless_read_rgba(egl, *rgba) < 0)
		fprintf(stderr, "edaha: rendering failed\n");
	else
		status = 0;
	render_destroy(render);
	egl_headless_destroy(egl);
	if (status) {
		free(*rgba);
		*rgba = NULL;
	}
	return status;
}

/* The three files, each atomically; 0 or 1 with stderr naming the file. */
static int write_files(const char *dir, const struct buf *json, const struct buf *glb,
		       const struct buf *png)
{
	struct error err = { { 0 } };
	int ret = fileio_mkdirs(dir, &err);

	if (ret == 0)
		ret = fileio_write_atomic(dir, "origami.json", json->data, json->len, &err);
	if (ret == 0)
		ret = fileio_write_atomic(dir, "leaf.glb", glb->data, glb->len, &err);
	if (ret == 0)
		ret = fileio_write_atomic(dir, "screen.png", png->data, png->len, &err);
	if (ret < 0) {
		fprintf(stderr, "edaha: %s\n", err.msg);
		return 1;
	}
	return 0;
}

int headless_leaf_run(const struct options *o)
{
	struct error err = { { 0 } };
	struct ori_design d;
	struct ori_leaf l;
	struct mesh m;
	struct buf json, glb, png;
	double (*opened)[3] = NULL;
	uint8_t *rgba = NULL;
	const char *name;
	double t;
	int ret, status;

	ori_leaf_init(&l);
	mesh_init(&m);
	buf_init(&json);
	buf_init(&glb);
	buf_init(&png);
	status = read_design(o->leaf, &d);
	if (status)
		goto out;
	name = d.name[0] ? d.name : o->leaf;
	t = o->opening_given ? o->opening : d.rest;
	ret = ori_build(&d, o->leaf, &l, &err);
	if (ret == 0) {
		opened = calloc(l.nvertices ? l.nvertices : 1, sizeof(*opened));
		ret = opened ? ori_open(&l, t, opened) : -ENOMEM;
		/* ori_build takes no design ori_open cannot place; said as the design's fault */
		if (ret == -EDOM)
			ret = error_at(&err, ret, o->leaf, d.line, "the leaf cannot open to %g: a "
				       "node of the midrib does not close", t);
	}
	if (ret < 0) {
		fprintf(stderr, "edaha: %s\n", ret == -ENOMEM ? "out of memory" : err.msg);
		status = input_status(ret);
		goto out;
	}
	if (ori_mesh_append(&l, (const double (*)[3])opened, NULL, &m) < 0 ||
	    ori_json(&l, name, t, (const double (*)[3])opened, &json) < 0 ||
	    export_glb_leaf(&m, name, &glb) < 0) {
		fprintf(stderr, "edaha: out of memory\n");
		status = 1;
		goto out;
	}
	status = draw(o, &m, &rgba);
	if (status)
		goto out;
	if (pngio_encode_rgba(rgba, o->width, o->height, &png, &err) < 0) {
		fprintf(stderr, "edaha: screen.png: %s\n", err.msg);
		status = 1;
		goto out;
	}
	status = write_files(o->out_dir, &json, &glb, &png);
	if (status == 0)
		printf("edaha: wrote origami.json, leaf.glb and screen.png to %s (%s at opening "
		       "%g)\n", o->out_dir, name, t);
out:
	free(rgba);
	free(opened);
	buf_finish(&json);
	buf_finish(&glb);
	buf_finish(&png);
	mesh_finish(&m);
	ori_leaf_finish(&l);
	return status;
}
