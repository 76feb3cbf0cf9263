/* SPDX-License-Identifier: MIT */
#pragma once

#include <stdbool.h>
#include <stddef.h>

struct leaf;

/*
 * Seasons (edaha's design; seed 001 has only its four captions). A season is what the
 * leaves look like, never a branch: spring shows blossom, summer full green, autumn
 * yellow to red leaves (each leaf its own shade), winter bare branches. The season
 * button cycles spring -> summer -> autumn -> winter -> spring. It is part of the
 * drawing (docs/tree-params.md, docs/document-format.md): the renderer and the
 * exporters colour leaves by it; meshes and the skeleton never change with it.
 *
 * Summer is 0, so a tree that never saw the season button is green, as before.
 */
enum season {
	SEASON_SUMMER = 0,
	SEASON_AUTUMN,
	SEASON_WINTER,
	SEASON_SPRING,
	SEASON_COUNT
};

const char *season_name(enum season s);
bool season_from_name(const char *name, enum season *s);
/* The next season as the button cycles. */
enum season season_next(enum season s);
/* False in winter: the leaves are not shown (nor exported). */
bool season_shows_leaves(enum season s);

/*
 * A season's leaf colours: a small palette (linear RGB 0..1, as glTF's), each leaf taking
 * one entry.
 * Summer has one entry (every leaf the same green); spring a few blossom pinks and
 * whites; autumn a run from yellow to deep red. Winter has none.
 */
#define SEASON_MAX_COLORS 6
struct season_rgb {
	float r, g, b;
};
size_t season_palette(enum season s, const struct season_rgb **colors);
/*
 * Which palette entry leaf l takes: a hash of its first point's coordinates, so a leaf
 * keeps its shade when other leaves come and go (ids are renumbered), and the same
 * drawing gives the same colours everywhere. 0 when the palette has one entry or none.
 */
size_t season_leaf_color(enum season s, const struct leaf *l);
