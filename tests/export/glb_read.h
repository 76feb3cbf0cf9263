/* SPDX-License-Identifier: MIT */
#pragma once

/* Reading back a GLB the exporter wrote, for the export tests (header-only, static). */

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <json-c/json.h>

#include "buf.h"
#include "test.h"

static inline uint32_t u32(const unsigned char *p)
{
	return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

struct glb {
	struct json_object *json;
	const unsigned char *bin;
	size_t bin_len; /* 0: no BIN chunk */
};

/* Checks the container and returns the parsed JSON chunk and the BIN chunk. */
static inline void parse_glb(const struct buf *b, struct glb *g)
{
	uint32_t json_len;
	char *text;

	CHECK(b->len >= 20 && b->len % 4 == 0);
	CHECK_INT(u32(b->data), 0x46546c67);
	CHECK_INT(u32(b->data + 4), 2);
	CHECK_INT(u32(b->data + 8), b->len);
	json_len = u32(b->data + 12);
	CHECK_INT(u32(b->data + 16), 0x4e4f534a);
	CHECK(json_len % 4 == 0 && json_len > 0 && 20 + (size_t)json_len <= b->len);
	/* padding is spaces */
	text = calloc(json_len + 1, 1);
	CHECK(text);
	memcpy(text, b->data + 20, json_len);
	CHECK(strlen(text) == json_len);
	g->json = json_tokener_parse(text);
	CHECK(g->json);
	free(text);

	if (20 + (size_t)json_len == b->len) {
		g->bin = NULL;
		g->bin_len = 0;
		return;
	}
	CHECK(28 + (size_t)json_len <= b->len);
	g->bin_len = u32(b->data + 20 + json_len);
	CHECK_INT(u32(b->data + 24 + json_len), 0x004e4942);
	CHECK(g->bin_len % 4 == 0);
	CHECK_INT(28 + (size_t)json_len + g->bin_len, b->len);
	g->bin = b->data + 28 + json_len;
}

static inline struct json_object *get(struct json_object *o, const char *key)
{
	struct json_object *v = NULL;

	if (!json_object_object_get_ex(o, key, &v)) {
		fprintf(stderr, "missing key %s\n", key);
		CHECK(0);
	}
	return v;
}

static inline int64_t get_int(struct json_object *o, const char *key)
{
	struct json_object *v = get(o, key);

	CHECK(json_object_is_type(v, json_type_int));
	return json_object_get_int64(v);
}

static inline const char *get_str(struct json_object *o, const char *key)
{
	struct json_object *v = get(o, key);

	CHECK(json_object_is_type(v, json_type_string));
	return json_object_get_string(v);
}

static inline struct json_object *at(struct json_object *arr, size_t i)
{
	CHECK(json_object_is_type(arr, json_type_array));
	CHECK(i < json_object_array_length(arr));
	return json_object_array_get_idx(arr, i);
}

static inline size_t count(struct json_object *o, const char *key)
{
	struct json_object *v;

	if (!json_object_object_get_ex(o, key, &v))
		return 0;
	CHECK(json_object_is_type(v, json_type_array));
	return json_object_array_length(v);
}

/* Accessor i's bytes in the BIN chunk (its whole bufferView: the exporter packs them). */
static inline const unsigned char *glb_accessor_bytes(const struct glb *g, int64_t i, size_t *len)
{
	struct json_object *a = at(get(g->json, "accessors"), (size_t)i);
	struct json_object *v = at(get(g->json, "bufferViews"), (size_t)get_int(a, "bufferView"));
	int64_t off = get_int(v, "byteOffset"), n = get_int(v, "byteLength");

	CHECK(!json_object_object_get_ex(a, "byteOffset", NULL));
	CHECK(off >= 0 && n >= 0 && (size_t)(off + n) <= g->bin_len);
	*len = (size_t)n;
	return g->bin + off;
}

/* The primitive whose material's name is `name`, or NULL. */
static inline struct json_object *glb_prim_of(const struct glb *g, const char *name)
{
	struct json_object *meshes, *prims, *materials;

	if (!json_object_object_get_ex(g->json, "meshes", &meshes))
		return NULL;
	prims = get(at(meshes, 0), "primitives");
	materials = get(g->json, "materials");
	for (size_t i = 0; i < json_object_array_length(prims); i++) {
		struct json_object *p = at(prims, i);

		if (!strcmp(get_str(at(materials, (size_t)get_int(p, "material")), "name"), name))
			return p;
	}
	return NULL;
}

/* The model's primitives (its one mesh's). */
static inline struct json_object *glb_prims(const struct glb *g)
{
	return get(at(get(g->json, "meshes"), 0), "primitives");
}

/* The primitive whose POSITION accessor is named "NAME.POSITION", or NULL. */
static inline struct json_object *glb_prim_named(const struct glb *g, const char *name)
{
	struct json_object *ps = glb_prims(g), *accessors = get(g->json, "accessors");
	char want[64];

	snprintf(want, sizeof(want), "%s.POSITION", name);
	for (size_t i = 0; i < json_object_array_length(ps); i++) {
		int64_t pos = get_int(get(at(ps, i), "attributes"), "POSITION");

		if (!strcmp(get_str(at(accessors, (size_t)pos), "name"), want))
			return at(ps, i);
	}
	return NULL;
}

/* How many indices a primitive has. */
static inline int64_t glb_prim_indices(const struct glb *g, struct json_object *prim)
{
	return get_int(at(get(g->json, "accessors"), (size_t)get_int(prim, "indices")), "count");
}

/* How many indices all the primitives have. */
static inline int64_t glb_indices(const struct glb *g)
{
	int64_t n = 0;

	for (size_t i = 0; i < json_object_array_length(glb_prims(g)); i++)
		n += glb_prim_indices(g, at(glb_prims(g), i));
	return n;
}

/* A JSON number, integer or not. */
static inline double json_num(struct json_object *v)
{
	CHECK(json_object_is_type(v, json_type_double) || json_object_is_type(v, json_type_int));
	return json_object_get_double(v);
}

/* A JSON file the exporter wrote (one line end at its end), parsed; b's text is left
 * NUL-terminated. */
static inline struct json_object *json_text(struct buf *b)
{
	struct json_object *root;

	CHECK(b->len > 0 && b->data[b->len - 1] == '\n');
	CHECK_INT(buf_append(b, "", 1), 0);
	b->len--;
	root = json_tokener_parse((const char *)b->data);
	CHECK(root);
	return root;
}

/* Whether two accessors hold the same bytes and say the same of them (but their names). */
static inline int glb_same_accessor(const struct glb *a, int64_t ia, const struct glb *b,
				    int64_t ib)
{
	static const char *const keys[] = { "componentType", "count", "type", "min", "max" };
	struct json_object *ja = at(get(a->json, "accessors"), (size_t)ia);
	struct json_object *jb = at(get(b->json, "accessors"), (size_t)ib);
	size_t la, lb;
	const unsigned char *da = glb_accessor_bytes(a, ia, &la), *db = glb_accessor_bytes(b, ib, &lb);

	for (size_t k = 0; k < sizeof(keys) / sizeof(*keys); k++) {
		struct json_object *va = NULL, *vb = NULL;

		json_object_object_get_ex(ja, keys[k], &va);
		json_object_object_get_ex(jb, keys[k], &vb);
		if (!json_object_equal(va, vb))
			return 0;
	}
	return la == lb && !memcmp(da, db, la);
}

/* Float i of an accessor's data. */
static inline float glb_float(const unsigned char *data, size_t i)
{
	uint32_t bits = u32(data + 4 * i);
	float f;

	memcpy(&f, &bits, sizeof(f));
	return f;
}

/* The printed bounds of a VEC3 accessor read back as exactly its data's extremes: floats
 * (12 bytes a vertex) or, for normalised bytes (4 a vertex, glTF's bounds being the
 * stored integers whatever `normalized` says), -127..127 with the fourth byte 0. */
static inline void check_vec3_bounds(struct json_object *a, const unsigned char *data, int64_t n,
				     int bytes)
{
	for (int c = 0; c < 3; c++) {
		double lo = 0, hi = 0;

		for (int64_t k = 0; k < n; k++) {
			double f = bytes ? (double)(int8_t)data[4 * k + c]
					 : (double)glb_float(data, (size_t)(3 * k + c));

			if (bytes) {
				CHECK(f >= -127 && f <= 127);
				CHECK_INT(data[4 * k + 3], 0);
			}
			lo = k == 0 || f < lo ? f : lo;
			hi = k == 0 || f > hi ? f : hi;
		}
		double min = json_object_get_double(at(get(a, "min"), (size_t)c));
		double max = json_object_get_double(at(get(a, "max"), (size_t)c));

		CHECK(bytes ? min == lo : (float)min == (float)lo);
		CHECK(bytes ? max == hi : (float)max == (float)hi);
	}
}

/* A morph target zero at every vertex (export_gltf.c): no view, so zeros, and one sparse
 * element, vertex 0, set to zero too, from views without a target; bounds 0. */
static inline void check_zero_target(const struct glb *g, struct json_object *a)
{
	struct json_object *sparse = get(a, "sparse"), *views = get(g->json, "bufferViews");
	struct json_object *iv = at(views, (size_t)get_int(get(sparse, "indices"), "bufferView"));
	struct json_object *vv = at(views, (size_t)get_int(get(sparse, "values"), "bufferView"));
	int64_t comp = get_int(a, "componentType");

	CHECK(!strcmp(get_str(a, "type"), "VEC3"));
	CHECK(comp == 5126 || (comp == 5120 && json_object_get_boolean(get(a, "normalized"))));
	CHECK_INT(get_int(sparse, "count"), 1);
	CHECK_INT(get_int(get(sparse, "indices"), "componentType"), 5125);
	CHECK(!json_object_object_get_ex(iv, "target", NULL));
	CHECK(!json_object_object_get_ex(vv, "target", NULL));
	CHECK(get_int(iv, "byteLength") >= 4 && get_int(vv, "byteLength") >= 12);
	CHECK_INT(u32(g->bin + get_int(iv, "byteOffset")), 0);
	for (int k = 0; k < 12; k++)
		CHECK_INT(g->bin[get_int(vv, "byteOffset") + k], 0);
	for (int c = 0; c < 3; c++) {
		CHECK(json_num(at(get(a, "min"), (size_t)c)) == 0.0);
		CHECK(json_num(at(get(a, "max"), (size_t)c)) == 0.0);
	}
}

/*
 * Accessors agree with the BIN chunk: views in range, bounds exact, indices in range; the
 * wind's morph targets (VEC3 normalised BYTE, stride 4, or FLOAT; zero ones sparse, without
 * a view) and its animation's keys (SCALAR FLOAT in views without a target; times from 0
 * rising, as min and max say).
 */
static inline void check_accessors(const struct glb *g)
{
	struct json_object *accessors = get(g->json, "accessors");
	struct json_object *views = get(g->json, "bufferViews");
	struct json_object *buffer = at(get(g->json, "buffers"), 0);

	CHECK_INT(get_int(buffer, "byteLength"), g->bin_len);
	CHECK(!json_object_object_get_ex(buffer, "uri", NULL));
	for (size_t i = 0; i < json_object_array_length(views); i++) {
		struct json_object *v = at(views, i), *target;

		CHECK_INT(get_int(v, "buffer"), 0);
		CHECK(get_int(v, "byteOffset") % 4 == 0);
		CHECK(get_int(v, "byteOffset") + get_int(v, "byteLength") <= (int64_t)g->bin_len);
		if (json_object_object_get_ex(v, "target", &target))
			CHECK(json_object_get_int64(target) == 34962 ||
			      json_object_get_int64(target) == 34963);
	}
	for (size_t i = 0; i < json_object_array_length(accessors); i++) {
		struct json_object *a = at(accessors, i), *v;
		const unsigned char *data;
		int64_t n = get_int(a, "count");
		int64_t comp = get_int(a, "componentType");
		const char *type = get_str(a, "type");
		int has_target;

		CHECK(n > 0);
		if (!json_object_object_get_ex(a, "bufferView", NULL)) {
			check_zero_target(g, a);
			continue;
		}
		v = at(views, (size_t)get_int(a, "bufferView"));
		data = g->bin + get_int(v, "byteOffset");
		has_target = json_object_object_get_ex(v, "target", NULL);
		if (!strcmp(type, "VEC3") && comp == 5120) {
			/* a morph target's deltas, KHR_mesh_quantization */
			CHECK(json_object_get_boolean(get(a, "normalized")));
			CHECK_INT(get_int(v, "byteStride"), 4);
			CHECK_INT(get_int(v, "byteLength"), 4 * n);
			CHECK_INT(get_int(v, "target"), 34962);
			check_vec3_bounds(a, data, n, 1);
		} else if (!strcmp(type, "VEC3")) {
			CHECK_INT(comp, 5126);
			CHECK_INT(get_int(v, "byteLength"), 12 * n);
			CHECK(!json_object_object_get_ex(v, "byteStride", NULL));
			CHECK_INT(get_int(v, "target"), 34962);
			if (json_object_object_get_ex(a, "min", NULL))
				check_vec3_bounds(a, data, n, 0);
		} else if (!strcmp(type, "VEC4")) {
			/* COLOR_0: RGBA bytes, 0..255 meaning 0..1, opaque */
			CHECK_INT(comp, 5121);
			CHECK(json_object_get_boolean(get(a, "normalized")));
			CHECK_INT(get_int(v, "byteLength"), 4 * n);
			CHECK(has_target);
			for (int64_t k = 0; k < n; k++)
				CHECK_INT(data[4 * k + 3], 255);
		} else if (comp == 5126) {
			/* an animation's keys: no vertex data, so no target */
			CHECK(!strcmp(type, "SCALAR"));
			CHECK(!has_target);
			CHECK_INT(get_int(v, "byteLength"), 4 * n);
			for (int64_t k = 0; k < n; k++)
				CHECK(isfinite(glb_float(data, (size_t)k)));
			if (json_object_object_get_ex(a, "min", NULL)) {
				float last = glb_float(data, (size_t)(n - 1));

				CHECK(glb_float(data, 0) == 0.0f);
				for (size_t k = 1; k < (size_t)n; k++)
					CHECK(glb_float(data, k) > glb_float(data, k - 1));
				CHECK((float)json_num(at(get(a, "min"), 0)) == 0.0f);
				CHECK((float)json_num(at(get(a, "max"), 0)) == last);
			}
		} else {
			/* indices: in range of the primitive's vertex count (the accessor before) */
			int64_t nv = get_int(at(accessors, i - 1), "count");

			CHECK(!strcmp(type, "SCALAR"));
			CHECK_INT(comp, 5125);
			CHECK_INT(get_int(v, "byteLength"), 4 * n);
			CHECK_INT(get_int(v, "target"), 34963);
			CHECK(n % 3 == 0);
			for (int64_t k = 0; k < n; k++)
				CHECK(u32(data + 4 * k) < nv);
		}
	}
}
