/* SPDX-License-Identifier: MIT */
#pragma once

/*
 * Playing back a GLB's wind as glTF says, for the export tests (header-only, static): a
 * CUBICSPLINE sampler's keys and its Hermite spline (glTF 2.0, Appendix C), a primitive's
 * morph targets as read back (normalised bytes or floats), the harmonic of a target.
 */
#include <stdbool.h>
#include <string.h>

#include "glb_read.h"
#include "live.h"

/* A sampler's keys as read back (floats in the BIN chunk). */
struct keys {
	size_t n;
	const unsigned char *times, *values;
};

static inline float key_value(const struct keys *k, size_t key, int part, int j)
{
	return glb_float(k->values, key * 3 * LIVE_WIND_TARGETS + (size_t)part * LIVE_WIND_TARGETS +
					    (size_t)j);
}

/* A CUBICSPLINE sampler of a mesh's LIVE_WIND_TARGETS weights: its keys from 0, the last
 * the first (weights and tangents). */
static inline void read_sampler_keys(const struct glb *g, struct json_object *sampler,
				     struct keys *k)
{
	struct json_object *accessors = get(g->json, "accessors");
	size_t len;
	int64_t in, out;

	CHECK(!strcmp(get_str(sampler, "interpolation"), "CUBICSPLINE"));
	in = get_int(sampler, "input");
	out = get_int(sampler, "output");
	k->n = (size_t)get_int(at(accessors, (size_t)in), "count");
	CHECK(k->n >= 2);
	k->times = glb_accessor_bytes(g, in, &len);
	CHECK_INT(len, 4 * k->n);
	CHECK_INT(get_int(at(accessors, (size_t)out), "count"), 3 * LIVE_WIND_TARGETS * k->n);
	k->values = glb_accessor_bytes(g, out, &len);
	CHECK_INT(len, 4 * 3 * LIVE_WIND_TARGETS * k->n);
	CHECK(glb_float(k->times, 0) == 0.0f);
	CHECK(!memcmp(k->values, k->values + 4 * 3 * LIVE_WIND_TARGETS * (k->n - 1),
		      4 * 3 * LIVE_WIND_TARGETS));
}

/* The weights at t as glTF's cubic spline gives them (glTF 2.0, Appendix C). */
static inline void play(const struct keys *k, double t, double w[LIVE_WIND_TARGETS])
{
	size_t i = 0;
	double t0, t1, td, s, s2, s3;

	while (i + 2 < k->n && glb_float(k->times, i + 1) <= t)
		i++;
	t0 = glb_float(k->times, i);
	t1 = glb_float(k->times, i + 1);
	td = t1 - t0;
	s = (t - t0) / td;
	s2 = s * s;
	s3 = s2 * s;
	for (int j = 0; j < LIVE_WIND_TARGETS; j++)
		w[j] = (2 * s3 - 3 * s2 + 1) * key_value(k, i, 1, j) +
		       td * (s3 - 2 * s2 + s) * key_value(k, i, 2, j) +
		       (-2 * s3 + 3 * s2) * key_value(k, i + 1, 1, j) +
		       td * (s3 - s2) * key_value(k, i + 1, 0, j);
}

/* A primitive's targets as read back. */
struct targets {
	const unsigned char *data[LIVE_WIND_TARGETS]; /* NULL: zeros */
	bool bytes[LIVE_WIND_TARGETS];
};

static inline void read_targets(const struct glb *g, struct json_object *prim, size_t nv,
				struct targets *tg)
{
	struct json_object *arr = get(prim, "targets"), *accessors = get(g->json, "accessors");

	CHECK_INT(json_object_array_length(arr), LIVE_WIND_TARGETS);
	for (int j = 0; j < LIVE_WIND_TARGETS; j++) {
		int64_t i = get_int(at(arr, (size_t)j), "POSITION");
		struct json_object *a = at(accessors, (size_t)i);
		size_t len;

		CHECK_INT(json_object_object_length(at(arr, (size_t)j)), 1);
		CHECK_INT(get_int(a, "count"), nv);
		tg->bytes[j] = get_int(a, "componentType") == 5120;
		/* none: zeros (check_accessors saw its one sparse element is a zero too) */
		tg->data[j] = NULL;
		if (!json_object_object_get_ex(a, "bufferView", NULL))
			continue;
		tg->data[j] = glb_accessor_bytes(g, i, &len);
		CHECK_INT(len, (tg->bytes[j] ? 4 : 12) * nv);
	}
}

/* Target j of vertex v as glTF reads it: max(c / 127, -1) or the float. */
static inline struct vec3 target_delta(const struct targets *tg, int j, size_t v)
{
	if (!tg->data[j])
		return vec3(0, 0, 0);
	if (tg->bytes[j]) {
		const int8_t *c = (const int8_t *)(tg->data[j] + 4 * v);

		return vec3(fmax(c[0] / 127.0, -1.0), fmax(c[1] / 127.0, -1.0),
			    fmax(c[2] / 127.0, -1.0));
	}
	return vec3(glb_float(tg->data[j], 3 * v), glb_float(tg->data[j], 3 * v + 1),
		    glb_float(tg->data[j], 3 * v + 2));
}

/* The harmonic (whole cycles a loop) of target j's weight. */
static inline int harmonic(const struct live_wind *w, int j)
{
	if (j == LIVE_TARGET_ALONG)
		return w->harmonic[0];
	if (j == LIVE_TARGET_ACROSS)
		return 2 * w->harmonic[0];
	if (j >= LIVE_TARGET_LEAF)
		return w->harmonic[LIVE_BANDS];
	return w->harmonic[1 + (j - LIVE_TARGET_BAND1) / 2];
}
