/* SPDX-License-Identifier: MIT */
/* The generated trees' leaf outlines and how a leaf is hung on its branch. */
#include <errno.h>
#include <math.h>

#include "gen_private.h"
#include "ori_place.h"

int gen_leaf_kind(enum gen_leaf type)
{
	switch (type) {
	case GEN_LEAF_ENTIRE:
		return ORI_KIND_ENTIRE;
	case GEN_LEAF_HOP:
		return ORI_KIND_HOP;
	case GEN_LEAF_MAPLE:
		return ORI_KIND_MAPLE;
	default:
		return ORI_KIND_DRAWN;
	}
}

/*
 * Half-widths along a leaf of length 1, from its base (x = 0) to its tip (x = 1): the
 * outline is the upper edge from base to tip and the lower edge back, counter-clockwise
 * seen from the leaf's front.
 */
static double half_width(enum gen_leaf type, double x, int i)
{
	switch (type) {
	case GEN_LEAF_OVAL:
		/* widest before the middle, a drawn-out tip */
		return 0.30 * pow(sin(VEC_PI * pow(x, 0.8)), 1.2);
	case GEN_LEAF_POINTED:
		/* narrower and longer-pointed, every other point a tooth */
		return (0.22 + (i % 2 ? 0.025 : 0.0)) * pow(sin(VEC_PI * pow(x, 0.7)), 1.1);
	case GEN_LEAF_ROUND:
		return 0.42 * sqrt(fmax(0.0, sin(VEC_PI * x)));
	case GEN_LEAF_NEEDLE:
		return 0.07 * sin(VEC_PI * x);
	case GEN_LEAF_LEAFLET:
		return 0.06 * pow(sin(VEC_PI * pow(x, 0.9)), 0.7);
	case GEN_LEAF_ENTIRE:
	case GEN_LEAF_HOP:
	case GEN_LEAF_MAPLE:
		/* an origami leaf takes the oval's place (gen_add_leaf) */
		return half_width(GEN_LEAF_OVAL, x, i);
	case GEN_LEAF_COUNT:
		break;
	}
	return 0.3 * sin(VEC_PI * x);
}

/* Points along each edge (between base and tip), by type: a tooth needs its points. */
static int edge_points(enum gen_leaf type)
{
	switch (type) {
	case GEN_LEAF_POINTED:
		return 9;
	case GEN_LEAF_NEEDLE:
		return 1;
	case GEN_LEAF_LEAFLET:
		return 3;
	case GEN_LEAF_OVAL:
	case GEN_LEAF_ROUND:
	case GEN_LEAF_ENTIRE:
	case GEN_LEAF_HOP:
	case GEN_LEAF_MAPLE:
	case GEN_LEAF_COUNT:
		break;
	}
	return 5;
}

size_t gen_leaf_outline(enum gen_leaf type, double out[][2], size_t max)
{
	int m = edge_points(type);
	size_t n = 0;

	if ((size_t)(2 * m + 2) > max)
		return 0;
	out[n][0] = 0.0;
	out[n++][1] = 0.0;
	for (int i = 1; i <= m; i++) {
		double x = (double)i / (m + 1);

		out[n][0] = x;
		out[n++][1] = -half_width(type, x, i);
	}
	out[n][0] = 1.0;
	out[n++][1] = 0.0;
	for (int i = m; i >= 1; i--) {
		double x = (double)i / (m + 1);

		out[n][0] = x;
		out[n++][1] = half_width(type, x, i);
	}
	return n;
}

/*
 * The leaf's frame: its axis a (unit) and its width w, chosen so that its front (a x w)
 * faces `face` as far as it can: up, as leaves turn to the sky; a clipped shrub's outwards,
 * to the light at its surface.
 */
static struct vec3 width_dir(struct vec3 a, struct vec3 face)
{
	struct vec3 w = vec3_cross(face, a);

	if (vec3_len(w) < 1e-9)
		w = vec3_cross(vec3(0, 0, 1), a);
	return vec3_norm_or(w, vec3(1, 0, 0));
}

void gen_leaf_points(const struct gen_ctx *g, struct vec3 base, struct vec3 axis, struct vec3 face,
		     double size, struct vec3 *out, size_t *n)
{
	struct vec3 a = vec3_norm_or(axis, vec3(0, 1, 0)), w = width_dir(a, face);

	*n = g->noutline;
	for (size_t k = 0; k < *n; k++)
		out[k] = vec3_add(base, vec3_add(vec3_scale(a, size * g->outline[k][0]),
						 vec3_scale(w, size * g->outline[k][1])));
}

int gen_add_leaf(struct gen_ctx *g, int branch, double t, const struct vec3 *p, size_t n)
{
	int id = tree_add_leaf(g->t, branch, ORIGIN_GENERATE, p, n), ret;

	if (id < 0)
		return id;
	g->t->leaves[id].branch_t = t;
	/* in the branch's frame, as a drawn leaf is: it follows when the branch moves */
	if ((ret = tree_leaf_attach(g->t, (size_t)id)) < 0)
		return ret;
	/* an origami leaf in the frame of the outline it replaces, as propagation places */
	return ori_place_leaf(g->t, (size_t)id, gen_leaf_kind(g->p->leaf_type));
}
