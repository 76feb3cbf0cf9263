/* SPDX-License-Identifier: MIT */
#pragma once

#include <stdint.h>

#include "app.h"
#include "error.h"
#include "export.h"
#include "page_viewer.h"

/* The names of the files a drawing is saved as; NULL: that file is not written. */
struct output_names {
	const char *glb, *obj, *mtl, *skeleton, *drawing, *png, *html;
};

/*
 * Writes the drawing into dir (created when missing) under those names, each file
 * atomically; the picture only when rgba (app->screen's size) is given; model.glb with
 * the tree's sway and skeleton.json with its "wind" (export_glb_wind) at `wind`; the page
 * of that model.glb (docs/page.md: no number, no date: a headless run has neither a set
 * nor a clock) only when page has a viewer. Same state, same bytes. 0, or a negative
 * errno with a message naming the file.
 */
int output_write(const struct app *app, const char *dir, const struct output_names *names,
		 const uint8_t *rgba, const struct export_wind *wind,
		 const struct page_look *page, struct error *err);

/* A headless run's files: model.glb, model.obj + model.mtl, skeleton.json and
 * drawing.edaha, plus screen.png when a picture is given and model.html when page has a
 * viewer. */
int output_write_all(const struct app *app, const char *dir, const uint8_t *rgba,
		     const struct export_wind *wind, const struct page_look *page,
		     struct error *err);
