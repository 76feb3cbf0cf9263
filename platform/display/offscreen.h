/* SPDX-License-Identifier: MIT */
#pragma once

/*
 * The picture drawn at the app's (logical) size away from the screen, then put onto the
 * screen turned (a display mounted on its side) and scaled to fit with its aspect kept
 * (a display that came back with another mode). GLES 3 draws into a multisampled
 * framebuffer resolved by a blit, as the window's own would be; GLES 2 draws into a
 * plain texture. Needs the GL context current in every call.
 */
#include <stdbool.h>
#include <stdint.h>

#include "error.h"

struct offscreen;

/* A framebuffer of width x height, bound for drawing. NULL with why in err. */
struct offscreen *offscreen_create(int width, int height, bool gles3, struct error *err);
void offscreen_destroy(struct offscreen *o);

/* Binds it for drawing (what create and offscreen_show leave bound). */
void offscreen_bind(struct offscreen *o);
/* The picture drawn so far as RGBA, top row first. 0 or -EIO. */
int offscreen_read_rgba(struct offscreen *o, uint8_t *rgba);
/*
 * Draws the picture into the window's framebuffer (0) of screen_w x screen_h, turned by
 * rotation degrees (see offscreen_geometry), black around it; then binds the offscreen
 * framebuffer again. 0 or -EIO.
 */
int offscreen_show(struct offscreen *o, int rotation, int screen_w, int screen_h);

/*
 * Where the picture goes, pure arithmetic (tests/platform/test_offscreen.c). rotation is
 * how the display is turned clockwise (0, 90, 180, 270): at 90 its top edge is on the
 * viewer's right, so the picture is drawn turned 90 degrees the other way to stand
 * upright. The picture (width x height, as the viewer sees it) is scaled to fit the
 * screen as the viewer sees it, aspect kept, centred on whole pixels.
 */
struct offscreen_geometry {
	/* a triangle strip of 4 vertices: x, y in the screen's clip space (y up) and u, v
	 * in the picture's texture (v up); the picture's bottom-left, bottom-right,
	 * top-left, top-right corners */
	float quad[4][4];
	int w, h;          /* the picture's size on the screen in pixels */
	bool one_to_one;   /* not scaled: sampled texel for pixel */
};
void offscreen_geometry(int rotation, int width, int height, int screen_w, int screen_h,
			struct offscreen_geometry *g);
/* The size the viewer sees of a screen_w x screen_h display turned by rotation. */
void offscreen_turned_size(int rotation, int screen_w, int screen_h, int *w, int *h);
