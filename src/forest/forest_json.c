/* SPDX-License-Identifier: MIT */
/* forest.json (docs/forest.md, "Headless and for the teacher"), with json-c. */
#include <errno.h>

#include "forest.h"
#include "json_out.h"

static struct json_object *tree_object(const struct forest_json_tree *t)
{
	struct json_object *o = json_object_new_object(), *pos = json_object_new_array();

	for (int k = 0; k < 3; k++)
		pos = json_out_push(pos, json_out_num(t->position[k]));
	o = json_out_set(o, "number", json_object_new_uint64(t->number));
	o = json_out_set(o, "file", json_object_new_string(t->file));
	o = json_out_set(o, "position", pos);
	o = json_out_set(o, "height", json_out_num(t->height));
	o = json_out_set(o, "crown_width", json_out_num(t->crown_width));
	o = json_out_set(o, "branches", json_object_new_uint64(t->branches));
	return json_out_set(o, "leaves", json_object_new_uint64(t->leaves));
}

int forest_json(const struct forest_json_tree *trees, size_t ntrees,
		const struct forest_json_skip *skipped, size_t nskipped, struct buf *out)
{
	struct json_object *root = json_object_new_object(), *list = json_object_new_array();
	struct json_object *skips = json_object_new_array();
	int ret;

	for (size_t i = 0; i < ntrees; i++)
		list = json_out_push(list, tree_object(&trees[i]));
	for (size_t i = 0; i < nskipped; i++) {
		struct json_object *s = json_object_new_object();

		s = json_out_set(s, "file", json_object_new_string(skipped[i].file));
		s = json_out_set(s, "why", json_object_new_string(skipped[i].why));
		skips = json_out_push(skips, s);
	}
	root = json_out_set(root, "format", json_object_new_string("edaha-forest"));
	root = json_out_set(root, "version", json_object_new_int(1));
	root = json_out_set(root, "trees", list);
	root = json_out_set(root, "skipped", skips);
	if (!root)
		return -ENOMEM;
	ret = json_out_append(root, "\n", out);
	json_object_put(root);
	return ret;
}
