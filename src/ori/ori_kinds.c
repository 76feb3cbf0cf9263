/* SPDX-License-Identifier: MIT */
/* The origami leaf kinds, built once: see ori_kinds.h. */
#include "ori_kinds.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char *const kind_names[ORI_KIND_COUNT] = {
	[ORI_KIND_ENTIRE] = "entire",
	[ORI_KIND_HOP] = "hop",
	[ORI_KIND_MAPLE] = "maple",
};

/* Built on first use and kept: every leaf of a kind shares its pattern and rest. The
 * app runs on one thread (exports are built on it too), so no lock. */
static struct ori_kind kinds[ORI_KIND_COUNT];
static bool built[ORI_KIND_COUNT];

const char *ori_kind_name(int kind)
{
	if (kind == ORI_KIND_DRAWN)
		return "drawn";
	return kind >= 0 && kind < ORI_KIND_COUNT ? kind_names[kind] : NULL;
}

bool ori_kind_from_name(const char *name, int *kind)
{
	for (int i = ORI_KIND_DRAWN; i < ORI_KIND_COUNT; i++) {
		if (!strcmp(name, ori_kind_name(i))) {
			*kind = i;
			return true;
		}
	}
	return false;
}

static struct vec3 row(const double (*p)[3], int v)
{
	return vec3(p[v][0], p[v][1], p[v][2]);
}

/* Rows of a right-handed orthonormal frame from offsets a, b; false on a line. */
static bool frame_of(struct vec3 a, struct vec3 b, struct vec3 fr[3])
{
	struct vec3 x = vec3_cross(a, b);
	double la = vec3_len(a), lx = vec3_len(x);

	if (!(la > 0) || !(lx > 1e-9 * la * la) || !isfinite(lx))
		return false;
	fr[0] = vec3_scale(a, 1.0 / la);
	fr[2] = vec3_scale(x, 1.0 / lx);
	fr[1] = vec3_cross(fr[2], fr[0]);
	return true;
}

/* The anchors: the margin point farthest from O, and the one making the largest
 * parallelogram with it (a curled margin is still far from a line). */
static bool anchors(struct ori_kind *k)
{
	const struct ori_leaf *l = &k->leaf;
	struct vec3 o = row(k->rest, l->margin[0]), fr[3];
	double best = -1.0;

	for (size_t i = 0; i < l->nmargin; i++) {
		double d = vec3_dist(row(k->rest, l->margin[i]), o);

		if (d > best) {
			best = d;
			k->anchor_a = i;
		}
	}
	best = -1.0;
	for (size_t i = 0; i < l->nmargin; i++) {
		struct vec3 x = vec3_cross(vec3_sub(row(k->rest, l->margin[k->anchor_a]), o),
					   vec3_sub(row(k->rest, l->margin[i]), o));

		if (vec3_dot(x, x) > best) {
			best = vec3_dot(x, x);
			k->anchor_b = i;
		}
	}
	if (!frame_of(vec3_sub(row(k->rest, l->margin[k->anchor_a]), o),
		      vec3_sub(row(k->rest, l->margin[k->anchor_b]), o), fr))
		return false;
	for (int i = 0; i < 3; i++) {
		k->frame[i][0] = fr[i].x;
		k->frame[i][1] = fr[i].y;
		k->frame[i][2] = fr[i].z;
	}
	k->anchor_len = vec3_dist(row(k->rest, l->margin[k->anchor_a]), o);
	return true;
}

static bool build(int i)
{
	struct ori_kind *k = &kinds[i];
	struct ori_design d;
	struct error err = { 0 };

	ori_leaf_init(&k->leaf);
	if (ori_preset(kind_names[i], &d, &err) < 0 ||
	    ori_build(&d, kind_names[i], &k->leaf, &err) < 0)
		goto fail;
	k->rest = malloc((k->leaf.nvertices ? k->leaf.nvertices : 1) * sizeof(*k->rest));
	k->frames = calloc(ORI_UNFOLD_FRAMES * (k->leaf.nvertices ? k->leaf.nvertices : 1),
			   sizeof(*k->frames));
	if (!k->rest || ori_rest(&k->leaf, k->rest) < 0 || k->leaf.nmargin < 3 ||
	    !anchors(k) || !k->frames ||
	    ori_unfold_frames(&k->leaf, ORI_UNFOLD_FRAMES, k->frames) < 0)
		goto fail;
	k->ntriangles = ori_mesh_triangles(&k->leaf);
	return true;
fail:
	free(k->rest);
	k->rest = NULL;
	free(k->frames);
	k->frames = NULL;
	ori_leaf_finish(&k->leaf);
	return false;
}

const struct ori_kind *ori_kind_get(int kind)
{
	if (kind < 0 || kind >= ORI_KIND_COUNT)
		return NULL;
	if (!built[kind])
		built[kind] = build(kind); /* tried again next time if it failed */
	return built[kind] ? &kinds[kind] : NULL;
}

void ori_kinds_release(void)
{
	for (int i = 0; i < ORI_KIND_COUNT; i++) {
		if (!built[i])
			continue;
		free(kinds[i].rest);
		kinds[i].rest = NULL;
		free(kinds[i].frames);
		kinds[i].frames = NULL;
		ori_leaf_finish(&kinds[i].leaf);
		built[i] = false;
	}
}

struct vec3 ori_xf_apply(const double xf[12], const double p[3])
{
	return vec3(xf[0] * p[0] + xf[1] * p[1] + xf[2] * p[2] + xf[3],
		    xf[4] * p[0] + xf[5] * p[1] + xf[6] * p[2] + xf[7],
		    xf[8] * p[0] + xf[9] * p[1] + xf[10] * p[2] + xf[11]);
}

void ori_kind_outline(const struct ori_kind *k, const double xf[12], struct vec3 *out)
{
	for (size_t i = 0; i < k->leaf.nmargin; i++)
		out[i] = ori_xf_apply(xf, k->rest[k->leaf.margin[i]]);
}

bool ori_kind_frame(const struct ori_kind *k, const struct vec3 *points, size_t n,
		    double xf[12])
{
	struct vec3 g[3], o;
	double s;

	if (n != k->leaf.nmargin)
		return false;
	o = points[0];
	if (!frame_of(vec3_sub(points[k->anchor_a], o), vec3_sub(points[k->anchor_b], o), g))
		return false;
	s = vec3_dist(points[k->anchor_a], o) / k->anchor_len;
	/* M = s G^T F: the design's anchor frame onto the points' */
	for (int r = 0; r < 3; r++)
		for (int c = 0; c < 3; c++) {
			const double gr[3] = { g[0].x, g[0].y, g[0].z };
			const double g1[3] = { g[1].x, g[1].y, g[1].z };
			const double g2[3] = { g[2].x, g[2].y, g[2].z };

			xf[4 * r + c] = s * (gr[r] * k->frame[0][c] + g1[r] * k->frame[1][c] +
					     g2[r] * k->frame[2][c]);
		}
	/* the rest's O may be off the origin by rounding: put it on points[0] */
	{
		const double *p0 = k->rest[k->leaf.margin[0]];

		xf[3] = o.x - (xf[0] * p0[0] + xf[1] * p0[1] + xf[2] * p0[2]);
		xf[7] = o.y - (xf[4] * p0[0] + xf[5] * p0[1] + xf[6] * p0[2]);
		xf[11] = o.z - (xf[8] * p0[0] + xf[9] * p0[1] + xf[10] * p0[2]);
	}
	for (int i = 0; i < 12; i++)
		if (!isfinite(xf[i]))
			return false;
	return true;
}
