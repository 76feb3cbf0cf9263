/* SPDX-License-Identifier: MIT */
#include "leaf_tint.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "leaf_colors.h"

static const float screen_summer[3] = { LEAF_TINT_SUMMER_RGB };

void leaf_tint_map(struct season_rgb c, float out[3])
{
	const struct season_rgb *summer;
	const float in[3] = { c.r, c.g, c.b };
	float palette[3];

	(void)season_palette(SEASON_SUMMER, &summer);
	palette[0] = summer[0].r;
	palette[1] = summer[0].g;
	palette[2] = summer[0].b;
	for (int k = 0; k < 3; k++) {
		double x = in[k] > 0.0f ? (in[k] < 1.0f ? in[k] : 1.0) : 0.0;

		out[k] = (float)pow(x, log(screen_summer[k]) / log(palette[k]));
	}
}

/* The season's palette as the screen shows it: how many colours (0 in winter). */
static size_t screen_palette(enum season s, float out[SEASON_MAX_COLORS][3])
{
	const struct season_rgb *c;
	size_t n = season_palette(s, &c);

	for (size_t i = 0; i < n && i < SEASON_MAX_COLORS; i++)
		leaf_tint_map(c[i], out[i]);
	return n < SEASON_MAX_COLORS ? n : SEASON_MAX_COLORS;
}

bool leaf_tint_uniform(enum season s, float out[3])
{
	float p[SEASON_MAX_COLORS][3];

	if (s == SEASON_SUMMER) {
		memcpy(out, screen_summer, sizeof(screen_summer));
		return true;
	}
	if (screen_palette(s, p) == 0)
		return false;
	memcpy(out, p[0], sizeof(p[0]));
	return true;
}

static void paint(float *rgb, size_t from, size_t to, const float c[3])
{
	for (size_t v = from; v < to; v++)
		memcpy(rgb + 3 * v, c, 3 * sizeof(float));
}

bool leaf_tint_vertices(const struct tree *t, const struct tree_mesh_marks *mk, size_t nvertices,
			float *rgb)
{
	const struct season_rgb *c;
	float p[SEASON_MAX_COLORS][3];
	size_t n = season_palette(t->season, &c), last = 0;

	if (!leaf_colors_fill(t, mk, nvertices, rgb))
		return false;
	(void)screen_palette(t->season, p);
	/* every vertex holds one of the palette's colours, runs of them a leaf */
	for (size_t v = 0; v < nvertices; v++) {
		float *x = rgb + 3 * v;

		for (size_t k = 0; k < n; k++) {
			size_t e = (last + k) % n;

			if (x[0] == c[e].r && x[1] == c[e].g && x[2] == c[e].b) {
				memcpy(x, p[e], sizeof(p[e]));
				last = e;
				break;
			}
		}
	}
	return true;
}

void leaf_tint_instances(const struct tree *t, const struct leaf_instances *li, float *rgb)
{
	float p[SEASON_MAX_COLORS][3];

	if (screen_palette(t->season, p) == 0)
		return;
	for (size_t i = 0; i < li->ninstanced; i++) {
		const struct leaf *l = &t->leaves[li->instances[i].leaf];

		memcpy(rgb + 3 * i, p[season_leaf_color(t->season, l)], sizeof(p[0]));
	}
}

int leaf_tint_loose(const struct tree *t, const struct tree_mesh_marks *mk,
		    const struct leaf_instances *li, float *rgb)
{
	float p[SEASON_MAX_COLORS][3];
	size_t n = screen_palette(t->season, p), nv = li->loose.nvertices, at = 0;
	bool *instanced;

	if (n == 0)
		return 0;
	paint(rgb, 0, nv, p[0]);
	if (n == 1 || !mk || mk->nleaves != t->nleaves + 1)
		return 0;
	instanced = calloc(t->nleaves ? t->nleaves : 1, sizeof(*instanced));
	if (!instanced)
		return -ENOMEM;
	for (size_t i = 0; i < li->ninstanced; i++)
		instanced[li->instances[i].leaf] = true;
	for (size_t i = 0; i < t->nleaves && at <= nv; i++) {
		size_t from = mk->leaves[i].nvertices, to = mk->leaves[i + 1].nvertices;

		if (instanced[i])
			continue;
		if (to < from || to - from > nv - at) {
			at = nv + 1; /* the marks do not describe this mesh */
			break;
		}
		paint(rgb, at, at + (to - from), p[season_leaf_color(t->season, &t->leaves[i])]);
		at += to - from;
	}
	free(instanced);
	if (at != nv)
		paint(rgb, 0, nv, p[0]);
	return 0;
}
