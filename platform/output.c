/* SPDX-License-Identifier: MIT */
#include "output.h"

#include <errno.h>

#include "buf.h"
#include "export.h"
#include "fileio.h"
#include "pngio.h"

static int write_buf(const char *dir, const char *name, struct buf *b, int ret, struct error *err)
{
	if (ret < 0)
		return error_set(err, ret, "cannot build %s: out of memory", name);
	return fileio_write_atomic(dir, name, b->data, b->len, err);
}

int output_write_all(const struct app *app, const char *dir, const uint8_t *rgba,
		     struct error *err)
{
	struct buf a, b;
	int ret;

	buf_init(&a);
	buf_init(&b);
	ret = fileio_mkdirs(dir, err);
	if (ret == 0)
		ret = write_buf(dir, "model.glb", &a, export_glb(&app->mesh, &a), err);
	if (ret == 0) {
		buf_reset(&a);
		ret = export_obj(&app->mesh, "model.mtl", &a, &b);
		ret = write_buf(dir, "model.obj", &a, ret, err);
		if (ret == 0)
			ret = write_buf(dir, "model.mtl", &b, 0, err);
	}
	if (ret == 0) {
		buf_reset(&a);
		ret = write_buf(dir, "skeleton.json", &a, export_skeleton(&app->tree, &a), err);
	}
	if (ret == 0) {
		buf_reset(&a);
		ret = write_buf(dir, "drawing.edaha", &a, doc_serialize(&app->doc, &app->tree, &a), err);
	}
	if (ret == 0 && rgba) {
		buf_reset(&a);
		ret = pngio_encode_rgba(rgba, app->view.width, app->view.height, &a, err);
		if (ret == 0)
			ret = fileio_write_atomic(dir, "screen.png", a.data, a.len, err);
	}
	buf_finish(&a);
	buf_finish(&b);
	return ret;
}
