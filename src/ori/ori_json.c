/* SPDX-License-Identifier: MIT */
/* origami.json: an origami leaf's pattern and its states, for people and tests to read. */
#include "ori_json.h"

#include <errno.h>

#include "json_out.h"

static struct json_object *jpoints2(const double (*p)[2], size_t n)
{
	struct json_object *arr = json_object_new_array_ext((int)n);

	for (size_t i = 0; i < n; i++) {
		struct json_object *xy = json_object_new_array_ext(2);

		xy = json_out_push(xy, json_out_num(p[i][0]));
		xy = json_out_push(xy, json_out_num(p[i][1]));
		arr = json_out_push(arr, xy);
	}
	return arr;
}

static struct json_object *jpoints3(const double (*p)[3], size_t n)
{
	struct json_object *arr = json_object_new_array_ext((int)n);

	for (size_t i = 0; i < n; i++) {
		struct json_object *xyz = json_object_new_array_ext(3);

		for (int c = 0; c < 3; c++)
			xyz = json_out_push(xyz, json_out_num(p[i][c]));
		arr = json_out_push(arr, xyz);
	}
	return arr;
}

static struct json_object *jindices(const int *idx, size_t n)
{
	struct json_object *arr = json_object_new_array_ext((int)n);

	for (size_t i = 0; i < n; i++)
		arr = json_out_push(arr, json_object_new_int(idx[i]));
	return arr;
}

static struct json_object *jcreases(const struct ori_leaf *l)
{
	struct json_object *arr = json_object_new_array_ext((int)l->ncreases);

	for (size_t i = 0; i < l->ncreases; i++) {
		const struct ori_crease *c = &l->creases[i];
		const char *type = c->type == ORI_VALLEY ? "valley" : "mountain";
		struct json_object *o = json_object_new_object();

		o = json_out_set(o, "a", json_object_new_int(c->a));
		o = json_out_set(o, "b", json_object_new_int(c->b));
		o = json_out_set(o, "type", json_object_new_string(type));
		arr = json_out_push(arr, o);
	}
	return arr;
}

static struct json_object *jfaces(const struct ori_leaf *l)
{
	struct json_object *arr = json_object_new_array_ext((int)l->nfaces);

	for (size_t f = 0; f < l->nfaces; f++) {
		const int *idx = l->face_index + l->face_start[f];

		arr = json_out_push(arr, jindices(idx, l->face_len[f]));
	}
	return arr;
}

/* Each lobe's tip against its target on the spiral: a tip that misses shows as the two
 * apart, for whoever tunes a design. */
static struct json_object *jlobes(const struct ori_leaf *l)
{
	struct json_object *arr = json_object_new_array_ext((int)l->nlobes);

	for (size_t i = 0; i < l->nlobes; i++) {
		struct json_object *o = json_object_new_object();

		o = json_out_set(o, "theta", json_out_num(l->lobes[i].theta));
		o = json_out_set(o, "target", json_out_num(l->lobes[i].target));
		o = json_out_set(o, "tip", json_out_num(l->lobes[i].tip));
		arr = json_out_push(arr, o);
	}
	return arr;
}

int ori_json(const struct ori_leaf *l, const char *name, double t, const double (*opened)[3],
	     struct buf *out)
{
	struct json_object *root = json_object_new_object();
	size_t triangles = ori_mesh_triangles(l);
	int r;

	/* the fields first, in its order; ours after them */
	root = json_out_set(root, "format", json_object_new_string(ORI_JSON_FORMAT));
	root = json_out_set(root, "version", json_object_new_int(ORI_JSON_VERSION));
	root = json_out_set(root, "vertices", jpoints2((const double (*)[2])l->flat, l->nvertices));
	root = json_out_set(root, "creases", jcreases(l));
	root = json_out_set(root, "margin", jindices(l->margin, l->nmargin));
	root = json_out_set(root, "faces", jfaces(l));
	root = json_out_set(root, "folded", jpoints2((const double (*)[2])l->folded, l->nvertices));
	root = json_out_set(root, "opened", jpoints3(opened, l->nvertices));
	root = json_out_set(root, "name", json_object_new_string(name));
	root = json_out_set(root, "opening", json_out_num(t));
	root = json_out_set(root, "triangles", json_object_new_int64((int64_t)triangles));
	root = json_out_set(root, "lobes", jlobes(l));
	if (!root)
		return -ENOMEM;
	/* compact, as skeleton.json: a leaf is small, but one format for both */
	r = json_out_append(root, "\n", out);
	json_object_put(root);
	return r;
}
