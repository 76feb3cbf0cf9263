/* SPDX-License-Identifier: MIT */
#include "atlas.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "batch.h"

/* Blank texels between images. */
#define PAD 1
#define SOLID 4

static void mark(struct atlas *a, int y0, int y1)
{
	if (a->dirty_y0 >= a->dirty_y1) {
		a->dirty_y0 = y0;
		a->dirty_y1 = y1;
		return;
	}
	if (y0 < a->dirty_y0)
		a->dirty_y0 = y0;
	if (y1 > a->dirty_y1)
		a->dirty_y1 = y1;
}

int atlas_init(struct atlas *a, int size, int max)
{
	memset(a, 0, sizeof(*a));
	if (size < 8 || size > max || (size & (size - 1)))
		return -EINVAL;
	a->pixels = calloc((size_t)size * (size_t)size, 1);
	if (!a->pixels)
		return -ENOMEM;
	a->w = a->h = size;
	a->max = max;
	/* the solid block: its centre is BATCH_SOLID_UV, two texels from every edge */
	for (int y = 0; y < SOLID; y++)
		memset(a->pixels + (size_t)y * (size_t)size, 0xff, SOLID);
	a->shelf_x = SOLID + PAD;
	a->shelf_h = SOLID;
	a->resized = true;
	_Static_assert(BATCH_SOLID_UV * 2 == SOLID, "the solid block is centred on BATCH_SOLID_UV");
	return 0;
}

void atlas_finish(struct atlas *a)
{
	free(a->pixels);
	memset(a, 0, sizeof(*a));
}

/* Doubles both sides, the old image in the top left. */
static int grow(struct atlas *a)
{
	int side = 2 * a->w;
	uint8_t *p;

	if (side > a->max)
		return -ENOSPC;
	p = calloc((size_t)side * (size_t)side, 1);
	if (!p)
		return -ENOMEM;
	for (int y = 0; y < a->h; y++)
		memcpy(p + (size_t)y * (size_t)side, a->pixels + (size_t)y * (size_t)a->w,
		       (size_t)a->w);
	free(a->pixels);
	a->pixels = p;
	a->w = a->h = side;
	a->resized = true;
	return 0;
}

int atlas_add(struct atlas *a, const uint8_t *src, int w, int h, int pitch, int *x, int *y)
{
	int ret;

	if (w < 0 || h < 0)
		return -EINVAL;
	for (;;) {
		/* on this shelf, else on a new one below it */
		if (a->shelf_x + w + PAD <= a->w && a->shelf_y + h + PAD <= a->h)
			break;
		if (a->shelf_x > 0 && w + PAD <= a->w &&
		    a->shelf_y + a->shelf_h + PAD + h + PAD <= a->h) {
			a->shelf_y += a->shelf_h + PAD;
			a->shelf_x = 0;
			a->shelf_h = 0;
			continue;
		}
		if ((ret = grow(a)) < 0)
			return ret;
	}
	*x = a->shelf_x;
	*y = a->shelf_y;
	for (int r = 0; r < h; r++)
		memcpy(a->pixels + (size_t)(*y + r) * (size_t)a->w + (size_t)*x,
		       src + (size_t)r * (size_t)pitch, (size_t)w);
	a->shelf_x += w + PAD;
	if (h > a->shelf_h)
		a->shelf_h = h;
	mark(a, *y, *y + h);
	return 0;
}

void atlas_clean(struct atlas *a)
{
	a->dirty_y0 = a->dirty_y1 = 0;
	a->resized = false;
}
