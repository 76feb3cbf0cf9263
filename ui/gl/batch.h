/* SPDX-License-Identifier: MIT */
#pragma once

#include <stdbool.h>
#include <stddef.h>

#include "vec.h"

/*
 * Flat-coloured triangles in screen pixels (origin top left, y down), collected on the
 * CPU and drawn with one call: the ground, the stroke, the cursor, the buttons and their
 * labels. Curves become polygons fine enough that no facet is visible (chords within a
 * quarter pixel of the arc). Every vertex also samples the text atlas (atlas.h): flat
 * shapes its solid texel, glyphs their bitmaps, so text needs no call of its own. No GL
 * here.
 */

/* M_PI is POSIX, not C11. */

struct rgba {
	float r, g, b, a;
};

struct pt {
	double x, y;
};

/* x, y, u, v (atlas texels), r, g, b, a per vertex; three vertices per triangle */
#define BATCH_FLOATS_PER_VERTEX 8
/* The atlas texel, in both coordinates, that flat shapes sample: solid coverage. */
#define BATCH_SOLID_UV 2

struct batch {
	float *v;
	size_t nvertices, cap;
	bool failed; /* an allocation failed; later calls add nothing */
};

void batch_init(struct batch *b);
void batch_finish(struct batch *b);
void batch_reset(struct batch *b);

void batch_triangle(struct batch *b, struct pt p0, struct pt p1, struct pt p2, struct rgba c);
/* p0..p3 in order around the quad */
void batch_quad(struct batch *b, struct pt p0, struct pt p1, struct pt p2, struct pt p3,
		struct rgba c);
void batch_rect(struct batch *b, double x, double y, double w, double h, struct rgba c);
/* Colour `top` along the top edge fading to `bottom` along the bottom edge. */
void batch_rect_gradient(struct batch *b, double x, double y, double w, double h,
			 struct rgba top, struct rgba bottom);
/* Colour `left` along the left edge fading to `right` along the right edge. */
void batch_rect_hgradient(struct batch *b, double x, double y, double w, double h,
			  struct rgba left, struct rgba right);
/* A convex polygon, filled as a fan. */
void batch_convex(struct batch *b, const struct pt *p, size_t n, struct rgba c);
void batch_disc(struct batch *b, struct pt centre, double r, struct rgba c);
void batch_ring(struct batch *b, struct pt centre, double r_in, double r_out, struct rgba c);
/*
 * The band between two discs along their outer tangents, without the discs: with discs
 * at both ends it is a stroke segment whose width changes along it.
 */
void batch_taper(struct batch *b, struct pt p0, double r0, struct pt p1, double r1,
		 struct rgba c);
/* A line of constant width through n points, with round joins and caps. */
void batch_polyline(struct batch *b, const struct pt *p, size_t n, double width, struct rgba c);
void batch_rounded_rect(struct batch *b, double x, double y, double w, double h, double radius,
			struct rgba c);
/* The outline of a rounded rectangle, `width` wide, inside its edge. */
void batch_rounded_frame(struct batch *b, double x, double y, double w, double h, double radius,
			 double width, struct rgba c);
/* A w x h rectangle at (x, y) showing the atlas's w x h texels at (u, v) as coverage of
 * colour c: a glyph. */
void batch_image(struct batch *b, double x, double y, double w, double h, double u, double v,
		 struct rgba c);

