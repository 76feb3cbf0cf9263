/* SPDX-License-Identifier: MIT */
#include "leaf_colors.h"

static void paint(float *rgb, size_t from, size_t to, struct season_rgb c)
{
	for (size_t v = from; v < to; v++) {
		rgb[3 * v] = c.r;
		rgb[3 * v + 1] = c.g;
		rgb[3 * v + 2] = c.b;
	}
}

bool leaf_colors_vary(enum season s)
{
	const struct season_rgb *c;

	return season_palette(s, &c) > 1;
}

bool leaf_colors_fill(const struct tree *t, const struct tree_mesh_marks *mk, size_t nvertices,
		      float *rgb)
{
	const struct season_rgb *c;
	size_t n = season_palette(t->season, &c);

	if (n == 0)
		return false;
	paint(rgb, 0, nvertices, c[0]);
	if (n == 1 || !mk || mk->nleaves != t->nleaves + 1 ||
	    mk->leaves[t->nleaves].nvertices != nvertices)
		return true;
	for (size_t i = 0; i < t->nleaves; i++) {
		size_t from = mk->leaves[i].nvertices, to = mk->leaves[i + 1].nvertices;

		if (from <= to && to <= nvertices)
			paint(rgb, from, to, c[season_leaf_color(t->season, &t->leaves[i])]);
	}
	return true;
}
