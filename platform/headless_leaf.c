/* SPDX-License-Identifier: MIT */
/*
 * edaha --headless --leaf NAME|FILE [--opening T]: an origami leaf alone (issue 15, seed
 * 003), written to --out as origami.json, leaf.glb and screen.png. Everything is built and
 * drawn before the folder is touched, so a design that will not fold writes nothing.
 */
#include "headless.h"
#include "headless_one.h"

#include <errno.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "buf.h"
#include "export.h"
#include "fileio.h"
#include "mesh.h"
#include "ori.h"
#include "ori_json.h"
#include "render.h"

/* A design file is small (ORI_READ_MAX_BYTES, which ori_read tells at the file's first
 * line); anything past this is not read at all. */
#define LEAF_FILE_MAX (1u << 20)

/* The design: a preset's, else a file's, read through fileio and named by its path. */
static int read_design(const char *arg, struct ori_design *d)
{
	size_t n;
	const char *const *names = ori_preset_names(&n);
	struct error err = { { 0 } };
	struct stat st;
	size_t len;
	char *data;
	int ret;

	if (headless_is_preset(names, n, arg)) {
		ret = ori_preset(arg, d, &err);
		if (ret < 0) /* compiled in and tested: not the visitor's fault */
			fprintf(stderr, "edaha: leaf preset %s: %s\n", arg, err.msg);
		return ret < 0 ? 1 : 0;
	}
	if (stat(arg, &st) < 0 && (errno == ENOENT || errno == ENOTDIR))
		return headless_no_such_preset("--leaf", "leaf", arg, names, n);
	ret = fileio_read_all(arg, LEAF_FILE_MAX, &data, &len, &err);
	if (ret == 0) {
		ret = ori_read(data, len, arg, d, &err);
		free(data);
	}
	if (ret < 0) {
		fprintf(stderr, "edaha: %s\n", err.msg);
		return headless_input_status(ret);
	}
	return 0;
}

static int draw(struct render *r, const void *m, int width, int height)
{
	return render_leaf(r, m, width, height);
}

int headless_leaf_run(const struct options *o)
{
	struct error err = { { 0 } };
	struct ori_design d;
	struct ori_leaf l;
	struct mesh m;
	static const char *const names[] = { "origami.json", "leaf.glb", "screen.png" };
	struct buf files[3];
	double (*opened)[3] = NULL;
	const char *name;
	double t;
	int ret, status;

	ori_leaf_init(&l);
	mesh_init(&m);
	for (int i = 0; i < 3; i++)
		buf_init(&files[i]);
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
		status = headless_input_status(ret);
		goto out;
	}
	if (ori_mesh_append(&l, (const double (*)[3])opened, NULL, &m) < 0 ||
	    ori_json(&l, name, t, (const double (*)[3])opened, &files[0]) < 0 ||
	    export_glb_leaf(&m, name, &files[1]) < 0) {
		fprintf(stderr, "edaha: out of memory\n");
		status = 1;
		goto out;
	}
	status = headless_one_picture(o, draw, &m, &files[2]);
	if (status)
		goto out;
	status = headless_one_write(o->out_dir, names, files, 3);
	if (status == 0)
		printf("edaha: wrote origami.json, leaf.glb and screen.png to %s (%s at opening "
		       "%g)\n", o->out_dir, name, t);
out:
	free(opened);
	for (int i = 0; i < 3; i++)
		buf_finish(&files[i]);
	mesh_finish(&m);
	ori_leaf_finish(&l);
	return status;
}
