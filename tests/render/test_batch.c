/* SPDX-License-Identifier: MIT */
/* The 2D triangle batch: shapes land where they should, with no GL involved. */
#include <math.h>
#include <string.h>

#include "batch.h"
#include "test.h"

static const struct rgba red = { 1.0f, 0.0f, 0.0f, 1.0f };

static struct pt vertex(const struct batch *b, size_t i)
{
	const float *v = b->v + i * BATCH_FLOATS_PER_VERTEX;

	return (struct pt){ v[0], v[1] };
}

/* Twice the signed area of triangle i; positive is clockwise on a y-down screen. */
static double area2(const struct batch *b, size_t tri)
{
	struct pt p = vertex(b, 3 * tri), q = vertex(b, 3 * tri + 1), r = vertex(b, 3 * tri + 2);

	return (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x);
}

static double total_area(const struct batch *b)
{
	double sum = 0.0;

	for (size_t i = 0; i < b->nvertices / 3; i++)
		sum += fabs(area2(b, i)) / 2.0;
	return sum;
}

int main(void)
{
	struct batch b;

	batch_init(&b);

	/* a rectangle: two triangles covering exactly its area, colour kept */
	batch_rect(&b, 10, 20, 30, 40, red);
	CHECK_INT(b.nvertices, 6);
	CHECK_NEAR(total_area(&b), 1200.0, 1e-6);
	CHECK(b.v[4] == 1.0f && b.v[5] == 0.0f && b.v[7] == 1.0f);
	/* flat shapes sample the atlas's solid texel */
	CHECK(b.v[2] == BATCH_SOLID_UV && b.v[3] == BATCH_SOLID_UV);

	/* a disc: every vertex on the circle or its centre, area close to pi r^2 */
	batch_reset(&b);
	batch_disc(&b, (struct pt){ 50, 50 }, 20, red);
	CHECK(b.nvertices >= 3 * 8);
	for (size_t i = 0; i < b.nvertices; i++) {
		struct pt p = vertex(&b, i);
		double d = hypot(p.x - 50, p.y - 50);

		CHECK(d < 1e-4 || fabs(d - 20) < 1e-4);
	}
	CHECK_NEAR(total_area(&b), VEC_PI * 400, VEC_PI * 400 * 0.02);

	/* a ring: the annulus's area */
	batch_reset(&b);
	batch_ring(&b, (struct pt){ 0, 0 }, 10, 12, red);
	/* chords within a quarter pixel: a few percent short on so small a ring */
	CHECK_NEAR(total_area(&b), VEC_PI * (144 - 100), VEC_PI * 44 * 0.04);

	/* a taper between discs of radii 10 and 4, 30 apart: touches both circles at tangents */
	batch_reset(&b);
	batch_taper(&b, (struct pt){ 0, 0 }, 10, (struct pt){ 30, 0 }, 4, red);
	CHECK_INT(b.nvertices, 6);
	for (size_t i = 0; i < b.nvertices; i++) {
		struct pt p = vertex(&b, i);
		double d0 = hypot(p.x, p.y), d1 = hypot(p.x - 30, p.y);

		CHECK(fabs(d0 - 10) < 1e-4 || fabs(d1 - 4) < 1e-4);
	}
	/* one disc inside the other: nothing between them to fill */
	batch_reset(&b);
	batch_taper(&b, (struct pt){ 0, 0 }, 10, (struct pt){ 3, 0 }, 4, red);
	CHECK_INT(b.nvertices, 0);

	/* a rounded rectangle: inside its box, a little less than the box's area */
	batch_reset(&b);
	batch_rounded_rect(&b, 100, 100, 80, 60, 12, red);
	for (size_t i = 0; i < b.nvertices; i++) {
		struct pt p = vertex(&b, i);

		CHECK(p.x >= 100 - 1e-4 && p.x <= 180 + 1e-4 && p.y >= 100 - 1e-4 && p.y <= 160 + 1e-4);
	}
	CHECK_NEAR(total_area(&b), 80 * 60 - (4 - VEC_PI) * 144, 16.0);

	/* its frame: the area between it and the rectangle inset by the width */
	batch_reset(&b);
	batch_rounded_frame(&b, 100, 100, 80, 60, 12, 3, red);
	CHECK_NEAR(total_area(&b),
		   (80 * 60 - (4 - VEC_PI) * 144) - (74 * 54 - (4 - VEC_PI) * 81), 10.0);

	/* a polyline: both segments' bodies and three round ends/joins */
	batch_reset(&b);
	batch_polyline(&b, (struct pt[]){ { 0, 0 }, { 100, 0 }, { 100, 100 } }, 3, 4, red);
	CHECK(total_area(&b) >= 2 * 100 * 4);

	/* an atlas image: its rectangle, each corner at the matching texel corner */
	batch_reset(&b);
	batch_image(&b, 10, 20, 7, 9, 100, 200, red);
	CHECK_INT(b.nvertices, 6);
	CHECK_NEAR(total_area(&b), 63.0, 1e-6);
	for (size_t i = 0; i < b.nvertices; i++) {
		const float *v = b.v + i * BATCH_FLOATS_PER_VERTEX;

		CHECK(v[2] - 100.0f == v[0] - 10.0f && v[3] - 200.0f == v[1] - 20.0f);
		CHECK(v[4] == 1.0f && v[7] == 1.0f);
	}

	batch_finish(&b);
	CHECK(b.v == NULL && b.nvertices == 0);
	return 0;
}
