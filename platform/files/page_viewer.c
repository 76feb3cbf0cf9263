/* SPDX-License-Identifier: MIT */
#include "page_viewer.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>

#include "config.h"
#include "fileio.h"

const char *const page_viewer_files[PAGE_VIEWER_NFILES] = {
	"three.min.js",
	"examples/js/loaders/GLTFLoader.js",
	"examples/js/controls/OrbitControls.js",
};

void page_viewer_init(struct page_viewer *v)
{
	for (size_t i = 0; i < PAGE_VIEWER_NFILES; i++) {
		v->data[i] = NULL;
		v->scripts[i] = (struct export_page_script){ NULL, 0 };
	}
}

void page_viewer_finish(struct page_viewer *v)
{
	for (size_t i = 0; i < PAGE_VIEWER_NFILES; i++)
		free(v->data[i]);
	page_viewer_init(v);
}

const char *page_viewer_dir(void)
{
	const char *dir = getenv("EDAHA_THREE_DIR");

	return dir && dir[0] ? dir : THREE_DIR;
}

int page_viewer_load(struct page_viewer *v, const char *dir, struct error *err)
{
	char path[4096];

	page_viewer_finish(v);
	if (!dir)
		dir = page_viewer_dir();
	for (size_t i = 0; i < PAGE_VIEWER_NFILES; i++) {
		size_t len = 0;
		int r;

		if ((size_t)snprintf(path, sizeof(path), "%s/%s", dir, page_viewer_files[i]) >=
		    sizeof(path)) {
			page_viewer_finish(v);
			return error_set(err, -ENAMETOOLONG, "%s: path too long", dir);
		}
		r = fileio_read_all(path, PAGE_VIEWER_MAX_BYTES, &v->data[i], &len, err);
		if (r == 0 && len == 0)
			r = error_set(err, -ENODATA, "%s: empty", path);
		if (r < 0) {
			page_viewer_finish(v);
			return r;
		}
		v->scripts[i] = (struct export_page_script){ v->data[i], len };
	}
	return 0;
}

int page_viewer_html(const struct page_look *look, const void *glb, size_t glb_len,
		     unsigned number, const char *date, struct buf *out)
{
	const struct export_page page = {
		.glb = glb,
		.glb_len = glb_len,
		.scripts = look->viewer ? look->viewer->scripts : NULL,
		.nscripts = PAGE_VIEWER_NFILES,
		.number = number,
		.date = date,
		.words = export_page_words(look->lang),
		.paper = { look->paper[0], look->paper[1], look->paper[2] },
		.bark = { look->bark[0], look->bark[1], look->bark[2] },
		.leaves = { look->leaves[0], look->leaves[1], look->leaves[2] },
		.stem = { look->stem[0], look->stem[1], look->stem[2] },
	};

	if (!look->viewer)
		return -EINVAL;
	return export_page_html(&page, out);
}
