/* SPDX-License-Identifier: MIT */
/* export_glb: container layout, JSON contents, bounds, determinism. */
#include <stdint.h>
#include <string.h>

#include <json-c/json.h>

#include "buf.h"
#include "export.h"
#include "mesh.h"
#include "synth_tree.h"
#include "test.h"
#include "tree.h"

static uint32_t u32(const unsigned char *p)
{
	return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

struct glb {
	struct json_object *json;
	const unsigned char *bin;
	size_t bin_len; /* 0: no BIN chunk */
};

/* Checks the container and returns the parsed JSON chunk and the BIN chunk. */
static void parse_glb(const struct buf *b, struct glb *g)
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

static struct json_object *get(struct json_object *o, const char *key)
{
	struct json_object *v = NULL;

	CHECK(json_object_object_get_ex(o, key, &v));
	return v;
}

static int64_t get_int(struct json_object *o, const char *key)
{
	struct json_object *v = get(o, key);

	CHECK(json_object_is_type(v, json_type_int));
	return json_object_get_int64(v);
}

static const char *get_str(struct json_object *o, const char *key)
{
	struct json_object *v = get(o, key);

	CHECK(json_object_is_type(v, json_type_string));
	return json_object_get_string(v);
}

static struct json_object *at(struct json_object *arr, size_t i)
{
	CHECK(json_object_is_type(arr, json_type_array));
	CHECK(i < json_object_array_length(arr));
	return json_object_array_get_idx(arr, i);
}

static size_t count(struct json_object *o, const char *key)
{
	struct json_object *v;

	if (!json_object_object_get_ex(o, key, &v))
		return 0;
	CHECK(json_object_is_type(v, json_type_array));
	return json_object_array_length(v);
}

static void export_tree(const struct tree *t, struct buf *out)
{
	struct tree_mesh tm;

	tree_mesh_init(&tm);
	CHECK_INT(tree_mesh_build(&tm, t), 0);
	CHECK_INT(export_glb(t, &tm, NULL, out), 0);
	tree_mesh_finish(&tm);
}

static void test_empty(void)
{
	struct tree t;
	struct buf b;
	struct glb g;
	const char *want = "{\"asset\":{\"version\":\"2.0\",\"generator\":\"edaha\"},\"scene\":0,"
			   "\"scenes\":[{}]}";

	tree_init(&t);
	buf_init(&b);
	export_tree(&t, &b);
	parse_glb(&b, &g);
	CHECK_INT(g.bin_len, 0);
	CHECK(!memcmp(b.data + 20, want, strlen(want)));
	CHECK_INT(count(g.json, "scenes"), 1);
	CHECK_INT(count(g.json, "meshes"), 0);
	CHECK_INT(count(g.json, "nodes"), 0);
	CHECK_INT(count(g.json, "buffers"), 0);
	json_object_put(g.json);
	buf_finish(&b);
	tree_finish(&t);
}

/* Accessors agree with the BIN chunk: views in range, bounds exact, indices in range. */
static void check_accessors(const struct glb *g)
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

static void test_tree(void)
{
	const struct vec3 p[] = { { 0, 0, 0 }, { 0.1, 2, 0 }, { 0.3, 4, 0.1 } };
	const double r[] = { 0.2, 0.15, 0.05 };
	const struct vec3 leaf[] = { { 0.3, 4, 0.1 }, { 0.5, 4.2, 0.1 }, { 0.4, 4.25, 0.1 },
				     { 0.42, 4.4, 0.1 }, { 0.3, 4.3, 0.1 } };
	const char *head = "{\"asset\":{\"version\":\"2.0\",\"generator\":\"edaha\"},\"scene\":0,"
			   "\"scenes\":[{\"nodes\":[0]}],\"nodes\":[{\"name\":\"tree\",\"mesh\":0}],"
			   "\"meshes\":[{\"name\":\"tree\",\"primitives\":[";
	struct json_object *mesh, *prims, *materials;
	struct tree t;
	struct buf b;
	struct glb g;

	tree_init(&t);
	buf_init(&b);
	CHECK_INT(tree_add_branch(&t, -1, 0, ORIGIN_SKETCH, p, r, 3), 0);

	/* bark only: one primitive, one material */
	export_tree(&t, &b);
	parse_glb(&b, &g);
	CHECK(!memcmp(b.data + 20, head, strlen(head)));
	prims = get(at(get(g.json, "meshes"), 0), "primitives");
	CHECK_INT(json_object_array_length(prims), 1);
	CHECK_INT(count(g.json, "materials"), 1);
	CHECK(!strcmp(get_str(at(get(g.json, "materials"), 0), "name"), "bark"));
	check_accessors(&g);
	json_object_put(g.json);

	/* bark and leaves */
	CHECK_INT(tree_add_leaf(&t, 0, ORIGIN_SKETCH, leaf, 5), 0);
	buf_reset(&b);
	export_tree(&t, &b);
	parse_glb(&b, &g);
	CHECK_INT(count(g.json, "nodes"), 1);
	CHECK_INT(count(g.json, "accessors"), 6);
	CHECK_INT(count(g.json, "bufferViews"), 6);
	CHECK_INT(count(g.json, "buffers"), 1);
	mesh = at(get(g.json, "meshes"), 0);
	CHECK(!strcmp(get_str(mesh, "name"), "tree"));
	prims = get(mesh, "primitives");
	CHECK_INT(json_object_array_length(prims), 2);
	materials = get(g.json, "materials");
	CHECK_INT(json_object_array_length(materials), 2);
	for (size_t i = 0; i < 2; i++) {
		struct json_object *prim = at(prims, i);
		struct json_object *attrs = get(prim, "attributes");
		struct json_object *mat = at(materials, (size_t)get_int(prim, "material"));
		struct json_object *pbr = get(mat, "pbrMetallicRoughness");

		CHECK_INT(get_int(attrs, "POSITION"), 3 * i);
		CHECK_INT(get_int(attrs, "NORMAL"), 3 * i + 1);
		CHECK_INT(get_int(prim, "indices"), 3 * i + 2);
		CHECK_INT(get_int(prim, "mode"), 4);
		CHECK(!strcmp(get_str(mat, "name"), i == 0 ? "bark" : "leaves"));
		CHECK_INT(json_object_array_length(get(pbr, "baseColorFactor")), 4);
		CHECK_NEAR(json_object_get_double(get(pbr, "metallicFactor")), 0.0, 0);
		CHECK_NEAR(json_object_get_double(get(pbr, "roughnessFactor")), i == 0 ? 0.9 : 0.8, 0);
		CHECK(json_object_object_get_ex(mat, "doubleSided", NULL) == (i == 1));
	}
	CHECK(json_object_get_boolean(get(at(materials, 1), "doubleSided")));
	check_accessors(&g);
	json_object_put(g.json);

	/* leaves only */
	free(t.branches[0].points);
	free(t.branches[0].radii);
	t.nbranches = 0;
	buf_reset(&b);
	export_tree(&t, &b);
	parse_glb(&b, &g);
	CHECK_INT(json_object_array_length(get(at(get(g.json, "meshes"), 0), "primitives")), 1);
	CHECK(!strcmp(get_str(at(get(g.json, "materials"), 0), "name"), "leaves"));
	check_accessors(&g);
	json_object_put(g.json);

	buf_finish(&b);
	tree_finish(&t);
}

/* Same tree, same bytes; and appending after other data keeps the chunks intact. */
static void test_deterministic(void)
{
	struct tree t1, t2;
	struct buf a, b;
	struct glb g;

	tree_init(&t1);
	tree_init(&t2);
	buf_init(&a);
	buf_init(&b);
	CHECK_INT(synth_tree(&t1, 120, 4, 99), 0);
	CHECK_INT(synth_tree(&t2, 120, 4, 99), 0);
	export_tree(&t1, &a);
	export_tree(&t2, &b);
	CHECK_INT(a.len, b.len);
	CHECK(!memcmp(a.data, b.data, a.len));
	parse_glb(&a, &g);
	check_accessors(&g);
	json_object_put(g.json);

	buf_reset(&b);
	CHECK_INT(buf_append(&b, "xyz", 3), 0);
	export_tree(&t1, &b);
	CHECK_INT(b.len, a.len + 3);
	CHECK(!memcmp(a.data, b.data + 3, a.len));

	buf_finish(&a);
	buf_finish(&b);
	tree_finish(&t1);
	tree_finish(&t2);
}

int main(void)
{
	test_empty();
	test_tree();
	test_deterministic();
	return 0;
}
