/* SPDX-License-Identifier: MIT */
/* export_glb: container layout, JSON contents, bounds, determinism. */
#include <stdint.h>
#include <string.h>

#include <json-c/json.h>

#include "buf.h"
#include "export.h"
#include "glb_read.h"
#include "mesh.h"
#include "synth_tree.h"
#include "test.h"
#include "tree.h"

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
