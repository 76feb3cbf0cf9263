/* SPDX-License-Identifier: MIT */
/* Export to the stick and the local copy (usb_export.h): the writer opened with its fds in
 * the loop's poll, its messages on the screen, and the export started once a frame was read
 * back for its picture. */
#include "kiosk_private.h"

#include <errno.h>
#include <stdio.h>

#include "export_set.h"
#include "leaf_tint.h"
#include "render_shaders.h"

static void usb_status(void *data, enum app_status status, bool held)
{
	struct kiosk *k = data;

	if (held)
		app_hold_status(k->app, status, kiosk_now_us());
	else
		app_set_status(k->app, status, kiosk_now_us());
}

/* The export's writer (usb_export.c), its fds in the poll. 0 or -1 (said why). */
int kiosk_open_usb(struct kiosk *k)
{
	const struct usb_export_config uc = {
		.usb = k->cfg.usb,
		.helper_socket = k->cfg.usb_socket,
		.wind = k->cfg.wind > 0 ? k->cfg.wind : 0.0, /* 0: the file's breeze */
		.language = k->cfg.language == RENDER_LANG_JA ? CONFIG_LANG_JA : CONFIG_LANG_EN,
		.local_dir = k->cfg.export_dir && k->cfg.export_dir[0] ? k->cfg.export_dir : NULL,
		.monitor = true,
		.status = usb_status,
		.data = k,
	};
	struct page_look look = {
		.lang = k->cfg.language == RENDER_LANG_JA ? EXPORT_PAGE_JA : EXPORT_PAGE_EN,
		.paper = { render_paper[0], render_paper[1], render_paper[2] },
		.bark = { render_bark[0], render_bark[1], render_bark[2] },
		.leaves = { LEAF_TINT_SUMMER_RGB },
		.stem = { render_vine_stem[0], render_vine_stem[1], render_vine_stem[2] },
	};
	struct kiosk_source src[2];
	struct error err = { { 0 } };
	size_t n;

	/* the take-home page's viewer, read once; without it a save is the rest, said once */
	if (page_viewer_load(&k->page_viewer, NULL, &err) < 0)
		fprintf(stderr, "edaha: export: saves carry no page (tree-NNNN.html): %s (the "
			"viewer's scripts are Debian's libjs-three)\n", err.msg);
	else
		look.viewer = &k->page_viewer;
	export_set_page_default(&look);
	k->usb = usb_export_create(&uc, &err);
	if (!k->usb) {
		fprintf(stderr, "edaha: %s\n", err.msg);
		return -1;
	}
	n = usb_export_sources(k->usb, src, 2);
	for (size_t i = 0; i < n; i++) {
		if (kiosk_add_source(k, &src[i]) < 0) {
			fputs("edaha: too many sources to poll\n", stderr);
			return -1;
		}
	}
	return 0;
}

/* Hands the export the last frame was read back for to usb_export.c, which tells the
 * visitor how it went. */
void kiosk_run_export(struct kiosk *k)
{
	struct buf forest;
	char date[11] = "";
	int ret = -ENODATA;

	k->export_ready = false;
	buf_init(&forest);
	if (k->export_forest && !usb_export_busy(k->usb)) {
		double t0 = (double)kiosk_now_us();

		ret = kiosk_forest_glb(k, &forest, date);
		if (ret == -ENOMEM)
			fputs("edaha: forest: out of memory building forest.glb: the tree alone is saved\n",
			      stderr);
		else if (ret == 0)
			fprintf(stderr, "edaha: forest: forest-%s.glb built (%zu bytes) in %.2f s\n",
				date, forest.len, ((double)kiosk_now_us() - t0) / 1e6);
	}
	k->export_forest = false;
	usb_export_start(k->usb, k->app, k->pixels, ret == 0 ? &forest : NULL, date);
	buf_finish(&forest);
}
