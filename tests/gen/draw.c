/* SPDX-License-Identifier: MIT */
#include "draw.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "test.h"

uint64_t draw_mix(uint64_t *s)
{
	uint64_t z = (*s += 0x9e3779b97f4a7c15ULL);

	z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
	z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
	return z ^ (z >> 31);
}

double draw_uni(uint64_t *s)
{
	return (double)(draw_mix(s) >> 11) * 0x1.0p-53;
}

double draw_span(uint64_t *s, double lo, double hi)
{
	return lo + (hi - lo) * draw_uni(s);
}

double draw_logspan(uint64_t *s, double lo, double hi)
{
	return exp(draw_span(s, log(lo), log(hi)));
}

void draw_put(char *yaml, size_t size, const char *fmt, ...)
{
	size_t len = strlen(yaml);
	va_list ap;
	int n;

	va_start(ap, fmt);
	n = vsnprintf(yaml + len, size - len, fmt, ap);
	va_end(ap);
	CHECK(n > 0 && (size_t)n < size - len);
}

void draw_put_clip(char *yaml, size_t size, const struct shape *sh)
{
	switch (sh->kind) {
	case SHAPE_SPHERE:
		draw_put(yaml, size, "clip: {shape: sphere, center: [%.17g, %.17g, %.17g], radius: %.17g}\n",
			 sh->c[0], sh->c[1], sh->c[2], sh->r);
		break;
	case SHAPE_BOX:
		draw_put(yaml, size,
			 "clip: {shape: box, center: [%.17g, %.17g, %.17g], size: [%.17g, %.17g, %.17g]}\n",
			 sh->c[0], sh->c[1], sh->c[2], 2 * sh->half[0], 2 * sh->half[1], 2 * sh->half[2]);
		break;
	case SHAPE_CONE:
		draw_put(yaml, size,
			 "clip: {shape: cone, center: [%.17g, %.17g, %.17g], radius: %.17g, height: %.17g}\n",
			 sh->c[0], sh->c[1], sh->c[2], sh->r, sh->h);
		break;
	}
}
