/* SPDX-License-Identifier: MIT */
/* export_skeleton: reads back with json-c, every field as documented, compact numbers. */
#include <math.h>
#include <string.h>

#include <json-c/json.h>

#include "buf.h"
#include "export.h"
#include "synth_tree.h"
#include "test.h"
#include "tree.h"

static struct json_object *get(struct json_object *o, const char *key, enum json_type type)
{
	struct json_object *v = NULL;

	if (!json_object_object_get_ex(o, key, &v)) {
		fprintf(stderr, "missing key %s\n", key);
		CHECK(0);
	}
	CHECK(json_object_is_type(v, type));
	return v;
}

static double num(struct json_object *v)
{
	CHECK(json_object_is_type(v, json_type_double) || json_object_is_type(v, json_type_int));
	return json_object_get_double(v);
}

/* Exported and parsed back; out holds the text, NUL-terminated. */
static struct json_object *export_parse(const struct tree *t, struct buf *out)
{
	struct json_object *root;

	buf_reset(out);
	CHECK_INT(export_skeleton(t, out), 0);
	CHECK(out->len > 0 && out->data[out->len - 1] == '\n');
	CHECK_INT(buf_append(out, "", 1), 0);
	root = json_tokener_parse((const char *)out->data);
	CHECK(root);
	return root;
}

static void check_points(struct json_object *arr, const struct vec3 *p, size_t n)
{
	CHECK_INT(json_object_array_length(arr), n);
	for (size_t i = 0; i < n; i++) {
		struct json_object *xyz = json_object_array_get_idx(arr, i);

		CHECK(json_object_is_type(xyz, json_type_array));
		CHECK_INT(json_object_array_length(xyz), 3);
		/* rounded to micrometres */
		CHECK_NEAR(num(json_object_array_get_idx(xyz, 0)), p[i].x, 5.0001e-7);
		CHECK_NEAR(num(json_object_array_get_idx(xyz, 1)), p[i].y, 5.0001e-7);
		CHECK_NEAR(num(json_object_array_get_idx(xyz, 2)), p[i].z, 5.0001e-7);
	}
}

static void check_tree(struct json_object *root, const struct tree *t)
{
	struct json_object *view = get(root, "view", json_type_array);
	struct json_object *branches = get(root, "branches", json_type_array);
	struct json_object *leaves = get(root, "leaves", json_type_array);

	CHECK(!strcmp(json_object_get_string(get(root, "format", json_type_string)), "edaha-skeleton"));
	CHECK_INT(json_object_get_int(get(root, "version", json_type_int)), 2);
	CHECK(!strcmp(json_object_get_string(get(root, "up", json_type_string)), "y"));
	CHECK(!strcmp(json_object_get_string(get(root, "units", json_type_string)), "m"));
	CHECK_INT(json_object_array_length(view), 3);
	CHECK_INT(json_object_get_int(json_object_array_get_idx(view, 2)), -1);
	CHECK_INT(json_object_array_length(branches), t->nbranches);
	CHECK_INT(json_object_array_length(leaves), t->nleaves);

	for (size_t i = 0; i < t->nbranches; i++) {
		const struct branch *b = &t->branches[i];
		struct json_object *o = json_object_array_get_idx(branches, i);
		struct json_object *radii = get(o, "radii", json_type_array);

		CHECK_INT(json_object_get_int(get(o, "id", json_type_int)), b->id);
		CHECK_INT(json_object_get_int(get(o, "parent", json_type_int)), b->parent);
		CHECK_INT(json_object_get_int(get(o, "generation", json_type_int)), b->generation);
		CHECK(!strcmp(json_object_get_string(get(o, "origin", json_type_string)),
			      origin_name(b->origin)));
		CHECK_NEAR(num(json_object_object_get(o, "parent_t")), b->parent_t, 5.0001e-7);
		check_points(get(o, "points", json_type_array), b->points, b->npoints);
		CHECK_INT(json_object_array_length(radii), b->npoints);
		for (size_t k = 0; k < b->npoints; k++)
			CHECK_NEAR(num(json_object_array_get_idx(radii, k)), b->radii[k], 5.0001e-7);
	}
	for (size_t i = 0; i < t->nleaves; i++) {
		const struct leaf *l = &t->leaves[i];
		struct json_object *o = json_object_array_get_idx(leaves, i);

		CHECK_INT(json_object_get_int(get(o, "id", json_type_int)), l->id);
		CHECK_INT(json_object_get_int(get(o, "branch", json_type_int)), l->branch);
		CHECK(!strcmp(json_object_get_string(get(o, "origin", json_type_string)),
			      origin_name(l->origin)));
		check_points(get(o, "points", json_type_array), l->points, l->npoints);
	}
}

/* The exact text of a small tree: field order and number formatting are part of the format. */
static void test_exact(void)
{
	const struct vec3 trunk[] = { { 0, 0, 0 }, { -0.0000001, 0.1, 1.0 / 3.0 } };
	const double r[] = { 0.25, 0.0000004 };
	const struct vec3 twig[] = { { -0.0000001, 0.1, 0.3 }, { 1e-6, 2.5, -3 } };
	const double tr[] = { 0.1, 0.05 };
	const struct vec3 leaf[] = { { 1, 2, 0 }, { 1.5, 2, 0 }, { 1, 2.5, 0.1234567 } };
	const char *want =
		"{\"format\":\"edaha-skeleton\",\"version\":2,\"up\":\"y\",\"units\":\"m\","
		"\"view\":[0,0,-1],\"season\":\"summer\",\"branches\":["
		"{\"id\":0,\"parent\":-1,\"generation\":0,\"origin\":\"sketch\",\"parent_t\":0,"
		"\"points\":[[0,0,0],[0,0.1,0.333333]],\"radii\":[0.25,0]},"
		"{\"id\":1,\"parent\":0,\"generation\":1,\"origin\":\"propagate\",\"parent_t\":0.7,"
		"\"points\":[[0,0.1,0.3],[0.000001,2.5,-3]],\"radii\":[0.1,0.05]}],"
		"\"leaves\":[{\"id\":0,\"branch\":1,\"branch_t\":0,\"origin\":\"clone\","
		"\"points\":[[1,2,0],[1.5,2,0],[1,2.5,0.123457]]}]}\n";
	struct tree t;
	struct buf out;
	struct json_object *root;

	tree_init(&t);
	buf_init(&out);
	CHECK_INT(tree_add_branch(&t, -1, 0, ORIGIN_SKETCH, trunk, r, 2), 0);
	CHECK_INT(tree_add_branch(&t, 0, 0.7, ORIGIN_PROPAGATE, twig, tr, 2), 1);
	CHECK_INT(tree_add_leaf(&t, 1, ORIGIN_CLONE, leaf, 3), 0);
	root = export_parse(&t, &out);
	if (strcmp((const char *)out.data, want)) {
		fprintf(stderr, "got:  %s\nwant: %s", (const char *)out.data, want);
		CHECK(0);
	}
	check_tree(root, &t);
	json_object_put(root);
	buf_finish(&out);
	tree_finish(&t);
}

static void test_empty(void)
{
	struct tree t;
	struct buf out;
	struct json_object *root;

	tree_init(&t);
	buf_init(&out);
	root = export_parse(&t, &out);
	check_tree(root, &t);
	CHECK(!strcmp((const char *)out.data,
		      "{\"format\":\"edaha-skeleton\",\"version\":2,\"up\":\"y\",\"units\":\"m\","
		      "\"view\":[0,0,-1],\"season\":\"summer\",\"branches\":[],\"leaves\":[]}\n"));
	json_object_put(root);
	buf_finish(&out);
	tree_finish(&t);
}

static void test_synth(void)
{
	struct tree t;
	struct buf a, b;
	struct json_object *root;

	tree_init(&t);
	buf_init(&a);
	buf_init(&b);
	CHECK_INT(synth_tree(&t, 200, 6, 3), 0);
	root = export_parse(&t, &a);
	check_tree(root, &t);
	json_object_put(root);
	/* same tree, same bytes */
	root = export_parse(&t, &b);
	json_object_put(root);
	CHECK_INT(a.len, b.len);
	CHECK(!memcmp(a.data, b.data, a.len));
	/* compact numbers: no float noise */
	CHECK(!strstr((const char *)a.data, "0000000"));
	CHECK(!strstr((const char *)a.data, "9999999"));
	CHECK(!strstr((const char *)a.data, "e-"));
	buf_finish(&a);
	buf_finish(&b);
	tree_finish(&t);
}

int main(void)
{
	test_exact();
	test_empty();
	test_synth();
	return 0;
}
