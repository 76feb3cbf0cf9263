/* SPDX-License-Identifier: MIT */
/*
 * The palm (seed 001, 3.2's "special trees"): a bare trunk built apart, straight or
 * leaning a little (trunk.end - trunk.start gives its direction, `height` its length),
 * and at its top a crown of `fronds` fronds, evenly round the trunk. A frond leaves the
 * trunk at gen_angle() from its axis and bends down by `droop` degrees over its length:
 * a midrib (a branch of FROND_POINTS points) with `leaves.amount` leaflets in pairs
 * along it, longest in the middle.
 */
#include <errno.h>
#include <math.h>

#include "gen_private.h"

#define DEG (VEC_PI / 180.0)
#define FROND_POINTS 10
/* The midrib: this fraction of the trunk's top radius at its base, at most this fraction of
 * the frond's length, tapering to MIDRIB_TIP of that. */
#define MIDRIB_OF_TRUNK 0.3
#define MIDRIB_OF_LENGTH 0.015
#define MIDRIB_TIP 0.3
/* Leaflets from here to there along the midrib, at this angle from it (forward) and
 * hanging down a little. */
#define LEAFLET_FROM 0.12
#define LEAFLET_TO 0.97
#define LEAFLET_ANGLE_DEG 60.0
#define LEAFLET_HANG 0.25

static int leaflets(struct gen_ctx *g, int frond, const struct vec3 *pts)
{
	const struct gen_params *p = g->p;
	int pairs = (p->leaf_amount + 1) / 2;
	struct vec3 out[GEN_LEAF_MAX_POINTS];

	for (int k = 0; k < p->leaf_amount; k++) {
		double t = LEAFLET_FROM + (LEAFLET_TO - LEAFLET_FROM) * (k / 2 + 0.5) / pairs;
		double x = t * (FROND_POINTS - 1);
		size_t j = (size_t)x < FROND_POINTS - 2 ? (size_t)x : FROND_POINTS - 2, n;
		struct vec3 at = vec3_lerp(pts[j], pts[j + 1], x - (double)j);
		struct vec3 tan = vec3_norm_or(vec3_sub(pts[j + 1], pts[j]), vec3(1, 0, 0));
		struct vec3 side = vec3_norm_or(vec3_cross(vec3(0, 1, 0), tan), vec3(0, 0, 1));
		double sign = k % 2 ? 1.0 : -1.0;
		struct vec3 axis = vec3_add(vec3_add(vec3_scale(tan, cos(LEAFLET_ANGLE_DEG * DEG)),
						     vec3_scale(side, sign * sin(LEAFLET_ANGLE_DEG * DEG))),
					    vec3(0, -LEAFLET_HANG, 0));
		double size = p->leaf_size * (0.55 + 0.45 * sin(VEC_PI * t));
		int ret;

		gen_leaf_points(g, at, axis, vec3(0, 1, 0), size, out, &n);
		/* the midrib's points are evenly spaced: t is its arc-length parameter */
		if ((ret = gen_add_leaf(g, frond, t, out, n)) < 0)
			return ret;
	}
	return 0;
}

int gen_palm(struct gen_ctx *g)
{
	const struct gen_params *p = g->p;
	struct vec3 up = vec3(0, 1, 0);
	struct vec3 dir = vec3_norm_or(vec3_sub(p->trunk_end, p->trunk_start), up);
	struct vec3 top = vec3_add(p->trunk_start, vec3_scale(dir, p->height));
	struct vec3 e = gen_reference(dir);
	double r_top = p->thickness * p->thickness_ratio;
	double r_mid = fmin(MIDRIB_OF_TRUNK * r_top, MIDRIB_OF_LENGTH * p->frond_length);
	int trunk = gen_add_branch(g, -1, p->trunk_start, top, p->thickness, r_top, 2);

	if (trunk < 0)
		return trunk;
	for (int i = 0; i < p->fronds; i++) {
		double alpha = gen_angle(g), phi = 2.0 * VEC_PI * i / p->fronds;
		struct vec3 v = vec3_add(vec3_scale(e, cos(phi)), vec3_scale(vec3_cross(dir, e), sin(phi)));
		struct vec3 b0 = vec3_add(vec3_scale(dir, cos(alpha)), vec3_scale(v, sin(alpha)));
		struct vec3 k = vec3_norm_or(vec3_cross(up, b0), vec3_norm_or(vec3_cross(up, v), e));
		struct vec3 pts[FROND_POINTS];
		double radii[FROND_POINTS], step = p->frond_length / (FROND_POINTS - 1);
		int id, ret;

		pts[0] = top;
		for (int j = 0; j < FROND_POINTS; j++) {
			double s = (double)j / (FROND_POINTS - 1);

			radii[j] = r_mid * (1.0 - (1.0 - MIDRIB_TIP) * s);
			if (j + 1 < FROND_POINTS) {
				struct vec3 d = gen_rotate(b0, k, p->droop * DEG * (j + 0.5) / (FROND_POINTS - 1));

				pts[j + 1] = vec3_add(pts[j], vec3_scale(d, step));
			}
		}
		id = tree_add_branch(g->t, trunk, 1.0, ORIGIN_GENERATE, pts, radii, FROND_POINTS);
		if (id < 0)
			return id;
		g->t->branches[id].level = 1;
		if ((ret = leaflets(g, id, pts)) < 0)
			return ret;
	}
	return 0;
}
