/* SPDX-License-Identifier: MIT */
/* The wind's morph targets and keyframes for model.glb, its numbers for skeleton.json
 * (export_wind.h). */
#include "export_wind.h"

#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* The keys' spline may cost what the targets' rounding to bytes may (1 / 254 of a
 * target's scale a component): this is 1 / that budget over the Hermite bound's 384. */
#define KEYS_BUDGET (254.0 / 384.0)
#define KEYS_MIN_PER_CYCLE 4

double export_wind_strength(const struct export_wind *w)
{
	return w->strength == 0.0 ? LIVE_WIND_DEFAULT_STRENGTH : w->strength;
}

bool export_wind_valid(const struct export_wind *p, double loop)
{
	return p->strength >= 0.0 && p->strength <= 1.0 && isfinite(p->angle) &&
	       (loop == 0.0 ||
		(loop >= LIVE_WIND_COMMON_LOOP_MIN_S && loop <= LIVE_WIND_COMMON_LOOP_MAX_S));
}

int export_wind_tree_init(struct export_wind_tree *wt, const struct tree *t,
			  const struct export_wind *p, double loop)
{
	struct live_wind_params wp = { .strength = export_wind_strength(p), .angle = p->angle,
				       .loop = loop };
	int r;

	memset(wt, 0, sizeof(*wt));
	if (!export_wind_valid(p, loop))
		return -EINVAL;
	if (t->nbranches == 0)
		return -ENODATA;
	r = live_skeleton_init(&wt->sk, t, p->seed);
	if (r == 0)
		r = live_wind_setup(&wt->w, &wt->sk, &wp);
	return r;
}

void export_wind_tree_finish(struct export_wind_tree *wt)
{
	live_skeleton_finish(&wt->sk);
}

int export_wind_harmonic(const struct live_wind *w, int j)
{
	if (j == LIVE_TARGET_ALONG)
		return w->harmonic[0];
	if (j == LIVE_TARGET_ACROSS)
		return 2 * w->harmonic[0];
	if (j >= LIVE_TARGET_LEAF)
		return w->harmonic[LIVE_BANDS];
	return w->harmonic[1 + (j - LIVE_TARGET_BAND1) / 2];
}

size_t export_wind_keys(const struct live_wind *w, const double scale[LIVE_WIND_TARGETS])
{
	double num = 0.0, den = 0.0, n;
	int fastest = 0;

	for (int j = 0; j < LIVE_WIND_TARGETS; j++) {
		int h = export_wind_harmonic(w, j);
		double m = h;

		if (!(scale[j] > 0.0))
			continue;
		num += scale[j] * m * m * m * m;
		den += scale[j];
		fastest = h > fastest ? h : fastest;
	}
	if (den == 0.0)
		return 1;
	n = ceil(2.0 * VEC_PI * pow(KEYS_BUDGET * num / den, 0.25));
	fastest *= KEYS_MIN_PER_CYCLE;
	return n > fastest ? (size_t)n : (size_t)fastest;
}

/* The bark and leaves by their marks, found again where mk does not describe them, any
 * mesh by the nearest skeleton point where that fails too (it is not t's). */
static int bind_mesh(struct live_attrs *a, const struct export_wind_tree *wt, const struct tree *t,
		     const struct tree_mesh_marks *mk, const struct mesh *m,
		     enum export_wind_bind how)
{
	int r = -EINVAL;

	if (how == EXPORT_WIND_BARK) {
		r = live_attrs_bind_bark(a, &wt->sk, t, m, mk);
		if (r == -EINVAL && mk)
			r = live_attrs_bind_bark(a, &wt->sk, t, m, NULL);
	} else if (how == EXPORT_WIND_LEAVES) {
		r = live_attrs_bind_leaves(a, &wt->sk, t, m, mk);
		if (r == -EINVAL && mk)
			r = live_attrs_bind_leaves(a, &wt->sk, t, m, NULL);
	}
	if (r == -EINVAL)
		r = live_attrs_bind_nearest(a, &wt->sk, t, m);
	return r;
}

static double component(struct vec3 v, int c)
{
	return c == 0 ? v.x : c == 1 ? v.y : v.z;
}

/* scale[j] = max(scale[j], the largest |component| of target j over a's vertices). */
static void widen_scale(const struct live_wind *w, const struct live_attrs *a,
			double scale[LIVE_WIND_TARGETS])
{
	for (size_t i = 0; i < a->n; i++) {
		struct vec3 tg[LIVE_WIND_TARGETS];

		live_wind_targets(w, &a->v[i], tg);
		for (int j = 0; j < LIVE_WIND_TARGETS; j++)
			for (int c = 0; c < 3; c++)
				scale[j] = fmax(scale[j], fabs(component(tg[j], c)));
	}
}

/* A delta as a normalised signed byte of scale s: glTF's c = round(f * 127), f = d / s. */
static int8_t snorm8(double d, double s)
{
	long c = s > 0.0 ? lround(127.0 * d / s) : 0;

	return (int8_t)(c > 127 ? 127 : c < -127 ? -127 : c);
}

/* Target j of vertex i, stored at dst (target j's data): its three values, and p's bounds
 * widened to them. */
static void store(struct export_wind_prim *p, unsigned char *dst, bool floats, int j, size_t i,
		  struct vec3 d, double s)
{
	for (int c = 0; c < 3; c++) {
		double v;

		if (floats) {
			float f = (float)component(d, c);

			memcpy(dst + 12 * i + 4 * (size_t)c, &f, sizeof(f));
			v = f;
		} else {
			int8_t b = snorm8(component(d, c), s);

			dst[4 * i + (size_t)c] = (unsigned char)b;
			v = b;
		}
		p->lo[j][c] = i == 0 || v < p->lo[j][c] ? v : p->lo[j][c];
		p->hi[j][c] = i == 0 || v > p->hi[j][c] ? v : p->hi[j][c];
	}
	if (!floats)
		dst[4 * i + 3] = 0;
}

/* One primitive's targets from its vertices' data; a target zero at every vertex (as
 * stored) gets no data. 0 or -ENOMEM. */
static int prim_targets(struct export_wind_prim *p, const struct live_wind *w,
			const struct live_attrs *a, const double scale[LIVE_WIND_TARGETS],
			bool floats)
{
	size_t per = floats ? 3 * sizeof(float) : 4, n = a->n;
	unsigned char *block;

	p->nvertices = n;
	if (n > SIZE_MAX / per / LIVE_WIND_TARGETS)
		return -ENOMEM;
	block = malloc(n * per * LIVE_WIND_TARGETS);
	if (!block)
		return -ENOMEM;
	p->block = block;
	for (size_t i = 0; i < n; i++) {
		struct vec3 tg[LIVE_WIND_TARGETS];

		live_wind_targets(w, &a->v[i], tg);
		for (int j = 0; j < LIVE_WIND_TARGETS; j++)
			store(p, block + (size_t)j * n * per, floats, j, i, tg[j], scale[j]);
	}
	for (int j = 0; j < LIVE_WIND_TARGETS; j++) {
		bool zero = true;

		for (int c = 0; c < 3; c++)
			zero = zero && p->lo[j][c] == 0.0 && p->hi[j][c] == 0.0;
		p->data[j] = zero ? NULL : block + (size_t)j * n * per;
	}
	return 0;
}

/* The keys at t_k = T_loop k / N, k = 0..N: the weights and their rates, each times f_j
 * (the targets' scale with bytes, 1 with floats). The last key is the first, exactly. */
static int keyframes(struct export_wind_anim *a, const struct live_wind *w, size_t intervals)
{
	const size_t stride = 3 * LIVE_WIND_TARGETS;

	a->nkeys = intervals + 1;
	a->times = malloc(a->nkeys * sizeof(*a->times));
	a->values = malloc(a->nkeys * stride * sizeof(*a->values));
	if (!a->times || !a->values)
		return -ENOMEM;
	for (size_t k = 0; k < a->nkeys; k++) {
		double u = k == intervals ? 1.0 : (double)k / (double)intervals;
		double g[LIVE_WIND_TARGETS], rate[LIVE_WIND_TARGETS];
		float *v = &a->values[k * stride];

		live_wind_weights_at(w, u, g);
		live_wind_rates_at(w, u, rate);
		a->times[k] = (float)(u * w->loop);
		for (int j = 0; j < LIVE_WIND_TARGETS; j++) {
			double f = a->floats ? 1.0 : a->scale[j];

			v[j] = (float)(rate[j] * f);
			v[LIVE_WIND_TARGETS + j] = (float)(g[j] * f);
			v[2 * LIVE_WIND_TARGETS + j] = (float)(rate[j] * f);
		}
	}
	return 0;
}

int export_wind_anim_build(struct export_wind_anim *a, const struct export_wind_tree *wt,
			   const struct tree *t, const struct tree_mesh_marks *mk,
			   const struct mesh *const *meshes, const enum export_wind_bind *bind,
			   size_t n, bool floats)
{
	struct live_attrs *attrs;
	int r = 0;

	memset(a, 0, sizeof(*a));
	a->floats = floats;
	a->loop = wt->w.loop;
	attrs = calloc(n ? n : 1, sizeof(*attrs));
	a->prims = calloc(n ? n : 1, sizeof(*a->prims));
	if (!attrs || !a->prims) {
		free(attrs);
		return -ENOMEM;
	}
	a->nprims = n;
	/* the scales first: a weight's factor is the same for every primitive of the mesh */
	for (size_t i = 0; i < n && r == 0; i++) {
		live_attrs_init(&attrs[i]);
		r = bind_mesh(&attrs[i], wt, t, mk, meshes[i], bind[i]);
		if (r == 0)
			widen_scale(&wt->w, &attrs[i], a->scale);
	}
	for (size_t i = 0; i < n && r == 0; i++)
		r = prim_targets(&a->prims[i], &wt->w, &attrs[i], a->scale, floats);
	if (r == 0)
		r = keyframes(a, &wt->w, export_wind_keys(&wt->w, a->scale));
	for (size_t i = 0; i < n; i++)
		live_attrs_finish(&attrs[i]);
	free(attrs);
	return r;
}

void export_wind_anim_finish(struct export_wind_anim *a)
{
	for (size_t i = 0; a->prims && i < a->nprims; i++)
		free(a->prims[i].block);
	free(a->prims);
	free(a->times);
	free(a->values);
	memset(a, 0, sizeof(*a));
}
