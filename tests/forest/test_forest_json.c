/* SPDX-License-Identifier: MIT */
/*
 * forest.json (src/forest/forest_json.c, docs/forest.md): written and read back with
 * json-c: the format and version, each tree's fields, the skipped files and why, names
 * with quotes, control characters and markup kept as text.
 */
#include <json-c/json.h>
#include <string.h>

#include "forest.h"
#include "test.h"

int main(void)
{
	struct forest_json_tree trees[2] = {
		{ 1, "drawing-000001.edaha", { 1.5, 0.0, -2.25 }, 5.5, 3.25, 62, 400 },
		{ 2, "a \"quoted\"\n<script>.edaha", { -0.000001, 0.0, 7.0 }, 12.0, 9.0, 1000, 20000 },
	};
	struct forest_json_skip skip[1] = { { "bad.edaha", "line 3: not a drawing" } };
	struct json_object *root, *v, *t, *pos;
	struct buf b;

	buf_init(&b);
	CHECK(forest_json(trees, 2, skip, 1, &b) == 0);
	CHECK(b.len > 0 && b.data[b.len - 1] == '\n');
	CHECK(buf_append(&b, "", 1) == 0);
	root = json_tokener_parse((const char *)b.data);
	CHECK(root);
	CHECK(json_object_object_get_ex(root, "format", &v) &&
	      !strcmp(json_object_get_string(v), "edaha-forest"));
	CHECK(json_object_object_get_ex(root, "version", &v) && json_object_get_int(v) == 1);
	CHECK(json_object_object_get_ex(root, "trees", &v) && json_object_array_length(v) == 2);
	for (size_t i = 0; i < 2; i++) {
		t = json_object_array_get_idx(v, i);
		CHECK(json_object_object_get_ex(t, "number", &pos) &&
		      json_object_get_uint64(pos) == trees[i].number);
		CHECK(json_object_object_get_ex(t, "file", &pos) &&
		      !strcmp(json_object_get_string(pos), trees[i].file));
		CHECK(json_object_object_get_ex(t, "position", &pos) &&
		      json_object_array_length(pos) == 3);
		for (size_t k = 0; k < 3; k++)
			CHECK_NEAR(json_object_get_double(json_object_array_get_idx(pos, k)),
				   trees[i].position[k], 1e-6);
		CHECK(json_object_object_get_ex(t, "height", &pos) &&
		      json_object_get_double(pos) == trees[i].height);
		CHECK(json_object_object_get_ex(t, "crown_width", &pos) &&
		      json_object_get_double(pos) == trees[i].crown_width);
		CHECK(json_object_object_get_ex(t, "branches", &pos) &&
		      json_object_get_uint64(pos) == trees[i].branches);
		CHECK(json_object_object_get_ex(t, "leaves", &pos) &&
		      json_object_get_uint64(pos) == trees[i].leaves);
	}
	CHECK(json_object_object_get_ex(root, "skipped", &v) && json_object_array_length(v) == 1);
	t = json_object_array_get_idx(v, 0);
	CHECK(json_object_object_get_ex(t, "why", &pos) &&
	      !strcmp(json_object_get_string(pos), skip[0].why));
	json_object_put(root);
	/* an empty forest */
	buf_reset(&b);
	CHECK(forest_json(NULL, 0, NULL, 0, &b) == 0);
	CHECK(buf_append(&b, "", 1) == 0);
	CHECK(strstr((const char *)b.data, "\"trees\":[]") && strstr((const char *)b.data, "\"skipped\":[]"));
	buf_finish(&b);
	return 0;
}
