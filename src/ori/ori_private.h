/* SPDX-License-Identifier: MIT */
#pragma once
/*
 * What ori_build.c (the walk round the crease tree) and ori_check.c (what cannot fold)
 * share: the plane isometries of the folded state and the pattern as it is built.
 */
#include <stdbool.h>
#include <stddef.h>

#include "ori.h"

#define ORI_MAX_V 1024
#define ORI_MAX_C 1024
#define ORI_MAX_F 512
#define ORI_MAX_FI 4096
#define ORI_MAX_CUR 256

/* A plane isometry x -> m x + t. */
struct iso {
	double m[2][2], t[2];
};

static inline void iso_apply(const struct iso *a, const double x[2], double out[2])
{
	double y0 = a->m[0][0] * x[0] + a->m[0][1] * x[1] + a->t[0];
	double y1 = a->m[1][0] * x[0] + a->m[1][1] * x[1] + a->t[1];

	out[0] = y0;
	out[1] = y1;
}

static inline void iso_dir(const struct iso *a, const double x[2], double out[2])
{
	double y0 = a->m[0][0] * x[0] + a->m[0][1] * x[1];
	double y1 = a->m[1][0] * x[0] + a->m[1][1] * x[1];

	out[0] = y0;
	out[1] = y1;
}

/* a o b: b first. */
static inline struct iso iso_mul(const struct iso *a, const struct iso *b)
{
	struct iso r;

	for (int i = 0; i < 2; i++) {
		for (int j = 0; j < 2; j++)
			r.m[i][j] = a->m[i][0] * b->m[0][j] + a->m[i][1] * b->m[1][j];
		r.t[i] = a->m[i][0] * b->t[0] + a->m[i][1] * b->t[1] + a->t[i];
	}
	return r;
}

static inline struct iso iso_identity(void)
{
	return (struct iso){ { { 1, 0 }, { 0, 1 } }, { 0, 0 } };
}

/* The reflection across the line through p along the unit d. */
static inline struct iso iso_reflect(const double p[2], const double d[2])
{
	struct iso r;

	r.m[0][0] = d[0] * d[0] - d[1] * d[1];
	r.m[0][1] = 2 * d[0] * d[1];
	r.m[1][0] = r.m[0][1];
	r.m[1][1] = -r.m[0][0];
	r.t[0] = p[0] - (r.m[0][0] * p[0] + r.m[0][1] * p[1]);
	r.t[1] = p[1] - (r.m[1][0] * p[0] + r.m[1][1] * p[1]);
	return r;
}

/* The inverse of an isometry: m orthogonal. */
static inline struct iso iso_inverse(const struct iso *a)
{
	struct iso r;

	r.m[0][0] = a->m[0][0];
	r.m[0][1] = a->m[1][0];
	r.m[1][0] = a->m[0][1];
	r.m[1][1] = a->m[1][1];
	r.t[0] = -(r.m[0][0] * a->t[0] + r.m[0][1] * a->t[1]);
	r.t[1] = -(r.m[1][0] * a->t[0] + r.m[1][1] * a->t[1]);
	return r;
}

static inline double iso_diff(const struct iso *a, const struct iso *b)
{
	double e = 0;

	for (int i = 0; i < 2; i++) {
		for (int j = 0; j < 2; j++)
			e = fmax(e, fabs(a->m[i][j] - b->m[i][j]));
		e = fmax(e, fabs(a->t[i] - b->t[i]));
	}
	return e;
}

static inline double cross2(const double a[2], const double b[2])
{
	return a[0] * b[1] - a[1] * b[0];
}

struct ori_builder {
	const struct ori_design *d;
	const char *name;
	struct error *err;

	double v[ORI_MAX_V][2];
	int part_of[ORI_MAX_V]; /* margin vertices: their part (lobes) */
	size_t nv;
	struct ori_crease c[ORI_MAX_C];
	size_t nc;
	struct ori_node_geo nodes[ORI_MAX_LEAF_NODES];
	size_t nnodes;

	int fidx[ORI_MAX_FI];
	size_t nfi, fstart[ORI_MAX_F], flen[ORI_MAX_F];
	struct iso fmap[ORI_MAX_F];
	int from[ORI_MAX_F], across[ORI_MAX_F];
	size_t nf;
	int root_face;

	int cur[ORI_MAX_CUR]; /* the face being walked */
	size_t ncur;
	int cur_across;   /* the crease crossed into it (-1: the first) */
	struct iso M;     /* its folded map */

	int margin[ORI_MAX_V];
	size_t nmargin;

	/* the part being walked: its cut in folded coordinates, O's side of it */
	double cut_a[2], cut_b[2];
	double inside;
	/* a forked side part's cut tip, fitted on the right so its farthest tooth meets the
	 * spiral, and used again on the left (a mirror must not depend on rounding) */
	double fitted_r[ORI_MAX_SIDES];
	bool fitted[ORI_MAX_SIDES];
	int part;
	unsigned long part_line;
	const char *part_what;
	char what[64];
};

/* The parts' angles at O, from the middle out, of the first upto side parts. */
double ori_sides_angle(const struct ori_design *d, size_t upto);
/* What cannot fold, refused before the walk: an asymmetric middle or node, a node's psi
 * not below phi, a span of 360 degrees or more, a half fold with more than a midrib. */
int ori_check_design(const struct ori_design *d, const char *name, struct error *err);
/* What the walk made that cannot fold: crossing creases, overlapping lobes, faces not
 * convex (turned counter-clockwise here when the walk made them clockwise). */
int ori_check_pattern(struct ori_builder *b);
