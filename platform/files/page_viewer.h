/* SPDX-License-Identifier: MIT */
#pragma once

/*
 * The viewer's scripts the take-home page inlines (export_page_html, docs/page.md):
 * three.min.js, examples/js/loaders/GLTFLoader.js and examples/js/controls/
 * OrbitControls.js of Debian's libjs-three (r111), read once: by the kiosk when it starts,
 * by a headless run when it writes model.html.
 */
#include <stddef.h>

#include "buf.h"
#include "error.h"
#include "export.h"

#define PAGE_VIEWER_NFILES 3
/* Each script's path under the directory, in the page's order. */
extern const char *const page_viewer_files[PAGE_VIEWER_NFILES];
/* None of them is near this; a larger one is not what we think it is. */
#define PAGE_VIEWER_MAX_BYTES (16u << 20)

struct page_viewer {
	char *data[PAGE_VIEWER_NFILES];
	struct export_page_script scripts[PAGE_VIEWER_NFILES];
};

void page_viewer_init(struct page_viewer *v);
void page_viewer_finish(struct page_viewer *v);
/* Where the scripts are: EDAHA_THREE_DIR from the environment when set (for tests), else
 * the build's THREE_DIR (meson option three_dir, /usr/share/javascript/three). */
const char *page_viewer_dir(void);
/* Reads the three scripts from dir (NULL: page_viewer_dir()). 0, or -errno with a message
 * naming the file (v empty then). */
int page_viewer_load(struct page_viewer *v, const char *dir, struct error *err);

/* What a tree's page needs besides the tree: the viewer (NULL: no page), the kiosk's
 * language, its paper (ui's render_paper) and the screen's colours of the bark, summer's
 * leaves and a vine's stems (render_bark, LEAF_TINT_SUMMER_RGB, render_vine_stem), so
 * the page colours the tree as the screen does (export_page). */
struct page_look {
	const struct page_viewer *viewer;
	enum export_page_lang lang;
	float paper[3], bark[3], leaves[3], stem[3];
};
/* The page of the model glb (export_page_html): number 0 and date NULL for none. 0,
 * -EINVAL (no viewer, a language we have no words for) or -ENOMEM; out as it was then. */
int page_viewer_html(const struct page_look *look, const void *glb, size_t glb_len,
		     unsigned number, const char *date, struct buf *out);
