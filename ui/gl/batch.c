/* SPDX-License-Identifier: MIT */
#include "batch.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* How far a chord may stray from its arc, in pixels: below what MSAA can show. */
#define ARC_TOLERANCE_PX 0.25
#define MIN_CIRCLE_SEGMENTS 8
#define MAX_CIRCLE_SEGMENTS 96
/* Points of one rounded corner at most: a quarter of the finest circle, plus its end. */
#define MAX_CORNER_POINTS (MAX_CIRCLE_SEGMENTS / 4 + 1)

void batch_init(struct batch *b)
{
	memset(b, 0, sizeof(*b));
}

void batch_finish(struct batch *b)
{
	free(b->v);
	batch_init(b);
}

void batch_reset(struct batch *b)
{
	b->nvertices = 0;
	b->failed = false;
}

static bool reserve(struct batch *b, size_t nvertices)
{
	size_t cap;
	float *v;

	if (b->failed)
		return false;
	if (nvertices <= b->cap - b->nvertices)
		return true;
	cap = b->cap ? b->cap : 1024;
	while (cap - b->nvertices < nvertices) {
		if (cap > SIZE_MAX / 2 / (BATCH_FLOATS_PER_VERTEX * sizeof(float)))
			goto fail;
		cap *= 2;
	}
	v = realloc(b->v, cap * BATCH_FLOATS_PER_VERTEX * sizeof(float));
	if (!v)
		goto fail;
	b->v = v;
	b->cap = cap;
	return true;
fail:
	b->failed = true;
	return false;
}

static void vertex_uv(struct batch *b, struct pt p, double u, double v, struct rgba c)
{
	float *f = b->v + b->nvertices * BATCH_FLOATS_PER_VERTEX;

	f[0] = (float)p.x;
	f[1] = (float)p.y;
	f[2] = (float)u;
	f[3] = (float)v;
	f[4] = c.r;
	f[5] = c.g;
	f[6] = c.b;
	f[7] = c.a;
	b->nvertices++;
}

static void vertex(struct batch *b, struct pt p, struct rgba c)
{
	vertex_uv(b, p, BATCH_SOLID_UV, BATCH_SOLID_UV, c);
}

void batch_triangle(struct batch *b, struct pt p0, struct pt p1, struct pt p2, struct rgba c)
{
	if (!reserve(b, 3))
		return;
	vertex(b, p0, c);
	vertex(b, p1, c);
	vertex(b, p2, c);
}

void batch_quad(struct batch *b, struct pt p0, struct pt p1, struct pt p2, struct pt p3,
		struct rgba c)
{
	batch_triangle(b, p0, p1, p2, c);
	batch_triangle(b, p0, p2, p3, c);
}

void batch_rect(struct batch *b, double x, double y, double w, double h, struct rgba c)
{
	batch_rect_gradient(b, x, y, w, h, c, c);
}

/* Corner colours clockwise from the top left. */
static void rect_colors(struct batch *b, double x, double y, double w, double h,
			const struct rgba c[4])
{
	struct pt tl = { x, y }, tr = { x + w, y }, br = { x + w, y + h }, bl = { x, y + h };

	if (!reserve(b, 6))
		return;
	vertex(b, tl, c[0]);
	vertex(b, tr, c[1]);
	vertex(b, br, c[2]);
	vertex(b, tl, c[0]);
	vertex(b, br, c[2]);
	vertex(b, bl, c[3]);
}

void batch_rect_gradient(struct batch *b, double x, double y, double w, double h,
			 struct rgba top, struct rgba bottom)
{
	const struct rgba c[4] = { top, top, bottom, bottom };

	rect_colors(b, x, y, w, h, c);
}

void batch_rect_hgradient(struct batch *b, double x, double y, double w, double h,
			  struct rgba left, struct rgba right)
{
	const struct rgba c[4] = { left, right, right, left };

	rect_colors(b, x, y, w, h, c);
}

void batch_convex(struct batch *b, const struct pt *p, size_t n, struct rgba c)
{
	for (size_t i = 1; i + 1 < n; i++)
		batch_triangle(b, p[0], p[i], p[i + 1], c);
}

/* Segments for a whole circle of radius r. */
static size_t circle_segments(double r)
{
	double step;
	size_t n;

	if (!(r > ARC_TOLERANCE_PX))
		return MIN_CIRCLE_SEGMENTS;
	step = 2.0 * acos(1.0 - ARC_TOLERANCE_PX / r);
	n = (size_t)ceil(2.0 * VEC_PI / step);
	/* a multiple of 4, so rounded corners get whole quarters */
	n = (n + 3) / 4 * 4;
	if (n < MIN_CIRCLE_SEGMENTS)
		n = MIN_CIRCLE_SEGMENTS;
	if (n > MAX_CIRCLE_SEGMENTS)
		n = MAX_CIRCLE_SEGMENTS;
	return n;
}

void batch_disc(struct batch *b, struct pt centre, double r, struct rgba c)
{
	size_t n = circle_segments(r);
	struct pt prev = { centre.x + r, centre.y };

	if (!(r > 0.0) || !reserve(b, 3 * n))
		return;
	for (size_t i = 1; i <= n; i++) {
		double a = 2.0 * VEC_PI * (double)i / (double)n;
		struct pt p = { centre.x + r * cos(a), centre.y + r * sin(a) };

		vertex(b, centre, c);
		vertex(b, prev, c);
		vertex(b, p, c);
		prev = p;
	}
}

void batch_ring(struct batch *b, struct pt centre, double r_in, double r_out, struct rgba c)
{
	size_t n = circle_segments(r_out);

	if (!(r_out > r_in) || r_in < 0.0 || !reserve(b, 6 * n))
		return;
	for (size_t i = 0; i < n; i++) {
		double a0 = 2.0 * VEC_PI * (double)i / (double)n;
		double a1 = 2.0 * VEC_PI * (double)(i + 1) / (double)n;
		struct pt i0 = { centre.x + r_in * cos(a0), centre.y + r_in * sin(a0) };
		struct pt o0 = { centre.x + r_out * cos(a0), centre.y + r_out * sin(a0) };
		struct pt i1 = { centre.x + r_in * cos(a1), centre.y + r_in * sin(a1) };
		struct pt o1 = { centre.x + r_out * cos(a1), centre.y + r_out * sin(a1) };

		batch_quad(b, i0, o0, o1, i1, c);
	}
}

/*
 * The part of the hull of two discs between them: the quad between their outer tangent
 * lines. With equal radii the tangent points are straight across from the centres;
 * otherwise they lean towards the smaller disc.
 */
void batch_taper(struct batch *b, struct pt p0, double r0, struct pt p1, double r1,
		 struct rgba c)
{
	double dx = p1.x - p0.x, dy = p1.y - p0.y;
	double d = hypot(dx, dy);
	double ux, uy, nx, ny, s, k;

	if (d <= fabs(r1 - r0) || d < 1e-9)
		return; /* one disc holds the other: the discs are the hull */
	ux = dx / d;
	uy = dy / d;
	nx = -uy;
	ny = ux;
	s = (r0 - r1) / d; /* sine of the tangent's lean */
	k = sqrt(1.0 - s * s);

	batch_quad(b,
		   (struct pt){ p0.x + r0 * (k * nx + s * ux), p0.y + r0 * (k * ny + s * uy) },
		   (struct pt){ p1.x + r1 * (k * nx + s * ux), p1.y + r1 * (k * ny + s * uy) },
		   (struct pt){ p1.x + r1 * (-k * nx + s * ux), p1.y + r1 * (-k * ny + s * uy) },
		   (struct pt){ p0.x + r0 * (-k * nx + s * ux), p0.y + r0 * (-k * ny + s * uy) }, c);
}

void batch_polyline(struct batch *b, const struct pt *p, size_t n, double width, struct rgba c)
{
	double r = 0.5 * width;

	/* round joins and caps: a disc at every point */
	for (size_t i = 0; i < n; i++) {
		batch_disc(b, p[i], r, c);
		if (i > 0)
			batch_taper(b, p[i - 1], r, p[i], r, c);
	}
}

/* Clockwise outline of a rounded rectangle, the same number of points for any radius. */
static size_t rounded_outline(double x, double y, double w, double h, double radius,
			      size_t per_corner, struct pt *out)
{
	const struct pt centres[4] = {
		{ x + radius, y + radius },
		{ x + w - radius, y + radius },
		{ x + w - radius, y + h - radius },
		{ x + radius, y + h - radius },
	};
	size_t n = 0;

	for (size_t corner = 0; corner < 4; corner++) {
		/* top left starts facing left (pi); each corner turns a quarter clockwise */
		double a0 = VEC_PI + (double)corner * 0.5 * VEC_PI;

		for (size_t i = 0; i < per_corner; i++) {
			double a = a0 + 0.5 * VEC_PI * (double)i / (double)(per_corner - 1);

			out[n++] = (struct pt){ centres[corner].x + radius * cos(a),
						centres[corner].y + radius * sin(a) };
		}
	}
	return n;
}

static size_t corner_points(double radius)
{
	return circle_segments(radius) / 4 + 1;
}

static double clamp_radius(double w, double h, double radius)
{
	return fmax(0.0, fmin(radius, 0.5 * fmin(w, h)));
}

void batch_rounded_rect(struct batch *b, double x, double y, double w, double h, double radius,
			struct rgba c)
{
	struct pt outline[4 * MAX_CORNER_POINTS];
	size_t n;

	radius = clamp_radius(w, h, radius);
	n = rounded_outline(x, y, w, h, radius, corner_points(radius), outline);
	batch_convex(b, outline, n, c);
}

void batch_rounded_frame(struct batch *b, double x, double y, double w, double h, double radius,
			 double width, struct rgba c)
{
	struct pt outer[4 * MAX_CORNER_POINTS], inner[4 * MAX_CORNER_POINTS];
	size_t per_corner, n;

	radius = clamp_radius(w, h, radius);
	width = fmin(width, 0.5 * fmin(w, h));
	per_corner = corner_points(radius);
	n = rounded_outline(x, y, w, h, radius, per_corner, outer);
	rounded_outline(x + width, y + width, w - 2.0 * width, h - 2.0 * width,
			fmax(0.0, radius - width), per_corner, inner);
	for (size_t i = 0; i < n; i++) {
		size_t j = (i + 1) % n;

		batch_quad(b, outer[i], outer[j], inner[j], inner[i], c);
	}
}

void batch_image(struct batch *b, double x, double y, double w, double h, double u, double v,
		 struct rgba c)
{
	struct pt tl = { x, y }, tr = { x + w, y }, br = { x + w, y + h }, bl = { x, y + h };

	if (!reserve(b, 6))
		return;
	vertex_uv(b, tl, u, v, c);
	vertex_uv(b, tr, u + w, v, c);
	vertex_uv(b, br, u + w, v + h, c);
	vertex_uv(b, tl, u, v, c);
	vertex_uv(b, br, u + w, v + h, c);
	vertex_uv(b, bl, u, v + h, c);
}
