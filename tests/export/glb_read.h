/* SPDX-License-Identifier: MIT */
#pragma once

/* Reading back a GLB the exporter wrote, for the export tests (header-only, static). */

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

/* Accessors agree with the BIN chunk: views in range, bounds exact, indices in range. */
static inline void check_accessors(const struct glb *g)
{
	struct json_object *accessors = get(g->json, "accessors");
	struct json_object *views = get(g->json, "bufferViews");
	struct json_object *buffer = at(get(g->json, "buffers"), 0);

	CHECK_INT(get_int(buffer, "byteLength"), g->bin_len);
	CHECK(!json_object_object_get_ex(buffer, "uri", NULL));
	for (size_t i = 0; i < json_object_array_length(views); i++) {
		struct json_object *v = at(views, i);
		int64_t target = get_int(v, "target");

		CHECK_INT(get_int(v, "buffer"), 0);
		CHECK(get_int(v, "byteOffset") % 4 == 0);
		CHECK(get_int(v, "byteOffset") + get_int(v, "byteLength") <= (int64_t)g->bin_len);
		CHECK(target == 34962 || target == 34963);
	}
	for (size_t i = 0; i < json_object_array_length(accessors); i++) {
		struct json_object *a = at(accessors, i);
		struct json_object *v = at(views, (size_t)get_int(a, "bufferView"));
		const unsigned char *data = g->bin + get_int(v, "byteOffset");
		int64_t n = get_int(a, "count");
		int64_t comp = get_int(a, "componentType");
		const char *type = get_str(a, "type");

		CHECK(n > 0);
		if (!strcmp(type, "VEC3")) {
			CHECK_INT(comp, 5126);
			CHECK_INT(get_int(v, "byteLength"), 12 * n);
		} else if (!strcmp(type, "VEC4")) {
			/* COLOR_0: RGBA bytes, 0..255 meaning 0..1, opaque */
			CHECK_INT(comp, 5121);
			CHECK(json_object_get_boolean(get(a, "normalized")));
			CHECK_INT(get_int(v, "byteLength"), 4 * n);
			for (int64_t k = 0; k < n; k++)
				CHECK_INT(data[4 * k + 3], 255);
		} else {
			/* indices: in range of the primitive's vertex count (the accessor before) */
			int64_t nv = get_int(at(accessors, i - 1), "count");

			CHECK(!strcmp(type, "SCALAR"));
			CHECK_INT(comp, 5125);
			CHECK_INT(get_int(v, "byteLength"), 4 * n);
			CHECK(n % 3 == 0);
			for (int64_t k = 0; k < n; k++)
				CHECK(u32(data + 4 * k) < nv);
		}
		if (json_object_object_get_ex(a, "min", NULL)) {
			/* the printed bounds read back as exactly the float extremes */
			for (int c = 0; c < 3; c++) {
				float lo = 0, hi = 0;

				for (int64_t k = 0; k < n; k++) {
					uint32_t bits = u32(data + 12 * k + 4 * c);
					float f;

					memcpy(&f, &bits, sizeof(f));
					lo = k == 0 || f < lo ? f : lo;
					hi = k == 0 || f > hi ? f : hi;
				}
				CHECK((float)json_object_get_double(at(get(a, "min"), (size_t)c)) == lo);
				CHECK((float)json_object_get_double(at(get(a, "max"), (size_t)c)) == hi);
			}
		}
	}
}
