/* SPDX-License-Identifier: MIT */
/*
 * page_write MODEL.glb OUT.html NUMBER en|ja DATE: the take-home page of a model as a Save
 * makes it (page_viewer_html, the viewer's scripts read as the kiosk reads them), with the
 * number and date given, for tests/export/page.sh to open: a tree-NNNN.html without a
 * kiosk. Exit 0, 1 (a file, the scripts) or 2 (usage).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "buf.h"
#include "error.h"
#include "fileio.h"
#include "leaf_tint.h"
#include "page_viewer.h"
#include "render_shaders.h"

int main(int argc, char **argv)
{
	/* the kiosk's look, as kiosk_export.c gives it */
	struct page_look look = {
		.paper = { render_paper[0], render_paper[1], render_paper[2] },
		.bark = { render_bark[0], render_bark[1], render_bark[2] },
		.leaves = { LEAF_TINT_SUMMER_RGB },
		.stem = { render_vine_stem[0], render_vine_stem[1], render_vine_stem[2] },
	};
	struct error err = { { 0 } };
	struct page_viewer viewer;
	struct buf html;
	char *glb = NULL;
	size_t len = 0;
	int r;

	if (argc != 6 || (strcmp(argv[4], "en") && strcmp(argv[4], "ja"))) {
		fputs("usage: page_write MODEL.glb OUT.html NUMBER en|ja DATE\n", stderr);
		return 2;
	}
	look.lang = strcmp(argv[4], "ja") ? EXPORT_PAGE_EN : EXPORT_PAGE_JA;
	page_viewer_init(&viewer);
	buf_init(&html);
	r = fileio_read_all(argv[1], 1u << 30, &glb, &len, &err);
	if (r == 0)
		r = page_viewer_load(&viewer, NULL, &err);
	if (r == 0) {
		look.viewer = &viewer;
		r = page_viewer_html(&look, glb, len, (unsigned)strtoul(argv[3], NULL, 10), argv[5],
				     &html);
		if (r < 0)
			error_set(&err, r, "cannot make the page");
	}
	if (r == 0) {
		FILE *f = fopen(argv[2], "wb");

		if (!f || fwrite(html.data, 1, html.len, f) != html.len || fclose(f) != 0)
			r = error_set(&err, -1, "%s: cannot write", argv[2]);
	}
	if (r < 0)
		fprintf(stderr, "page_write: %s\n", err.msg);
	free(glb);
	buf_finish(&html);
	page_viewer_finish(&viewer);
	return r < 0 ? 1 : 0;
}
