/* SPDX-License-Identifier: MIT */
#include "season.h"

#include <stdint.h>
#include <string.h>

#include "numfmt.h"
#include "tree.h"

static const char *const names[SEASON_COUNT] = {
	[SEASON_SUMMER] = "summer",
	[SEASON_AUTUMN] = "autumn",
	[SEASON_WINTER] = "winter",
	[SEASON_SPRING] = "spring",
};

/*
 * Linear RGB, as glTF's colours are (the exporters write them as they are; the renderer
 * shows them through its own curve, ui/leaf_tint.c). Summer's green is the one every
 * exporter used before seasons (numfmt.h); the others are picked in sRGB, as the comments
 * give them, and converted.
 */
static const struct season_rgb summer[] = { { MATERIAL_LEAVES_RGB } };
/* cherry blossom, sRGB: (0.96, 0.72, 0.80), (0.93, 0.60, 0.72), (0.98, 0.90, 0.92) */
static const struct season_rgb spring[] = {
	{ 0.911f, 0.477f, 0.604f },
	{ 0.848f, 0.319f, 0.477f },
	{ 0.955f, 0.787f, 0.828f },
};
/* yellow, gold, orange, scarlet, red, crimson, sRGB: (0.90, 0.74, 0.16), (0.88, 0.58, 0.12),
 * (0.86, 0.42, 0.10), (0.80, 0.26, 0.08), (0.70, 0.16, 0.08), (0.55, 0.10, 0.10) */
static const struct season_rgb autumn[] = {
	{ 0.787f, 0.507f, 0.022f }, { 0.748f, 0.296f, 0.013f }, { 0.711f, 0.147f, 0.010f },
	{ 0.604f, 0.055f, 0.007f }, { 0.448f, 0.022f, 0.007f }, { 0.263f, 0.010f, 0.010f },
};

const char *season_name(enum season s)
{
	return (unsigned)s < SEASON_COUNT ? names[s] : names[SEASON_SUMMER];
}

bool season_from_name(const char *name, enum season *s)
{
	for (int i = 0; i < SEASON_COUNT; i++) {
		if (!strcmp(name, names[i])) {
			*s = (enum season)i;
			return true;
		}
	}
	return false;
}

enum season season_next(enum season s)
{
	switch (s) {
	case SEASON_SPRING:
		return SEASON_SUMMER;
	case SEASON_SUMMER:
		return SEASON_AUTUMN;
	case SEASON_AUTUMN:
		return SEASON_WINTER;
	case SEASON_WINTER:
	case SEASON_COUNT:
		break;
	}
	return SEASON_SPRING;
}

bool season_shows_leaves(enum season s)
{
	return s != SEASON_WINTER;
}

size_t season_palette(enum season s, const struct season_rgb **colors)
{
	switch (s) {
	case SEASON_SPRING:
		*colors = spring;
		return sizeof(spring) / sizeof(*spring);
	case SEASON_AUTUMN:
		*colors = autumn;
		return sizeof(autumn) / sizeof(*autumn);
	case SEASON_WINTER:
		*colors = NULL;
		return 0;
	case SEASON_SUMMER:
	case SEASON_COUNT:
		break;
	}
	*colors = summer;
	return 1;
}

static uint64_t mix(uint64_t h, double v)
{
	uint64_t bits;

	v = v == 0.0 ? 0.0 : v; /* -0 and 0 alike */
	memcpy(&bits, &v, sizeof(bits));
	h ^= bits;
	h *= 0x100000001b3ULL;
	return h ^ (h >> 29);
}

size_t season_leaf_color(enum season s, const struct leaf *l)
{
	const struct season_rgb *c;
	size_t n = season_palette(s, &c);
	uint64_t h = 0xcbf29ce484222325ULL;

	if (n <= 1 || l->npoints == 0)
		return 0;
	h = mix(mix(mix(h, l->points[0].x), l->points[0].y), l->points[0].z);
	h ^= h >> 33;
	h *= 0xff51afd7ed558ccdULL;
	h ^= h >> 33;
	return (size_t)(h % n);
}
