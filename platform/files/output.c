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

int output_write(const struct app *app, const char *dir, const struct output_names *n,
		 const uint8_t *rgba, const struct export_wind *wind,
		 const struct page_look *page, struct error *err)
{
	struct buf a, b;
	int ret;

	buf_init(&a);
	buf_init(&b);
	ret = fileio_mkdirs(dir, err);
	if (ret == 0 && (n->glb || n->html)) {
		int r = export_glb_wind(&app->tree, &app->mesh, &app->mesh_marks, wind, &a);

		if (r < 0)
			ret = write_buf(dir, n->glb ? n->glb : n->html, &a, r, err);
	}
	if (ret == 0 && n->glb)
		ret = write_buf(dir, n->glb, &a, 0, err);
	/* the page of the very bytes model.glb has */
	if (ret == 0 && n->html && page && page->viewer)
		ret = write_buf(dir, n->html, &b, page_viewer_html(page, a.data, a.len, 0, NULL, &b),
				err);
	if (ret == 0 && n->obj && n->mtl) {
		buf_reset(&a);
		buf_reset(&b);
		ret = export_obj(&app->tree, &app->mesh, &app->mesh_marks, n->mtl, &a, &b);
		ret = write_buf(dir, n->obj, &a, ret, err);
		if (ret == 0)
			ret = write_buf(dir, n->mtl, &b, 0, err);
	}
	if (ret == 0 && n->skeleton) {
		buf_reset(&a);
		ret = write_buf(dir, n->skeleton, &a, export_skeleton_wind(&app->tree, wind, &a),
				err);
	}
	if (ret == 0 && n->drawing) {
		buf_reset(&a);
		ret = write_buf(dir, n->drawing, &a, doc_serialize(&app->doc, &app->tree, &a), err);
	}
	if (ret == 0 && n->png && rgba) {
		buf_reset(&a);
		ret = pngio_encode_rgba(rgba, app->screen.width, app->screen.height, &a, err);
		if (ret == 0)
			ret = fileio_write_atomic(dir, n->png, a.data, a.len, err);
	}
	buf_finish(&a);
	buf_finish(&b);
	return ret;
}

int output_write_all(const struct app *app, const char *dir, const uint8_t *rgba,
		     const struct export_wind *wind, const struct page_look *page,
		     struct error *err)
{
	static const struct output_names headless = {
		.glb = "model.glb", .obj = "model.obj", .mtl = "model.mtl",
		.skeleton = "skeleton.json", .drawing = "drawing.edaha", .png = "screen.png",
		.html = "model.html",
	};

	return output_write(app, dir, &headless, rgba, wind, page, err);
}
