/* SPDX-License-Identifier: MIT */
/* skeleton.json's "vines" section: a grown vine as numbers, for tools and tests to read. */
#include "vine_json.h"

#include <errno.h>
#include <stdlib.h>

#include "json_out.h"

static struct json_object *jpoint(struct vec3 p)
{
	struct json_object *xyz = json_object_new_array_ext(3);

	xyz = json_out_push(xyz, json_out_num(p.x));
	xyz = json_out_push(xyz, json_out_num(p.y));
	return json_out_push(xyz, json_out_num(p.z));
}

static struct json_object *jpoints(const struct vec3 *p, size_t n)
{
	struct json_object *arr = json_object_new_array_ext((int)n);

	for (size_t i = 0; i < n; i++)
		arr = json_out_push(arr, jpoint(p[i]));
	return arr;
}

/* Every key of a vine file, in the file's order (docs/vine-format.md). */
static struct json_object *jparams(struct json_object *o, const struct vine_params *p)
{
	o = json_out_set(o, "edaha-vine", json_object_new_int(VINE_PARAMS_VERSION));
	o = json_out_set(o, "internode", json_out_num(p->internode));
	o = json_out_set(o, "radius", json_out_num(p->radius));
	o = json_out_set(o, "step_time", json_out_num(p->step_time));
	o = json_out_set(o, "angle", json_out_num(p->angle));
	o = json_out_set(o, "free_nodes", json_object_new_int(p->free_nodes));
	o = json_out_set(o, "twining",
			 json_object_new_string(p->twining == VINE_RIGHT ? "right" : "left"));
	o = json_out_set(o, "leaves_per_node", json_object_new_int(p->leaves_per_node));
	o = json_out_set(o, "cotyledons", json_object_new_int(p->cotyledons));
	o = json_out_set(o, "leaf_size", json_out_num(p->leaf_size));
	o = json_out_set(o, "points_per_internode", json_object_new_int(p->points_per_internode));
	o = json_out_set(o, "ring_sides", json_object_new_int(p->ring_sides));
	o = json_out_set(o, "sweep", json_out_num(p->sweep));
	o = json_out_set(o, "internodes", json_object_new_int(p->internodes));
	/* exactly: a seed past 2^53 would round as a double */
	return json_out_set(o, "seed", json_object_new_uint64(p->seed));
}

static struct json_object *jshoot(const struct vine *v, size_t i)
{
	const struct vine_shoot *s = &v->shoots[i];
	struct json_object *o = json_object_new_object();
	struct json_object *contacts = json_object_new_array();
	struct vec3 *smooth;

	if (vine_smooth(v, i, &smooth) < 0) {
		json_object_put(o);
		json_object_put(contacts);
		return NULL;
	}
	for (size_t k = 0; k < s->n; k++)
		if (s->contact[k])
			contacts = json_out_push(contacts, json_object_new_int64((int64_t)k));
	o = json_out_set(o, "parent", json_object_new_int(s->parent));
	o = json_out_set(o, "node", json_object_new_int(s->node));
	o = json_out_set(o, "axis", jpoints(s->axis, s->n));
	o = json_out_set(o, "smooth", jpoints(smooth, s->n));
	o = json_out_set(o, "contacts", contacts);
	o = json_out_set(o, "stopped", json_object_new_boolean(s->stopped));
	free(smooth);
	return o;
}

static struct json_object *jleaf(const struct vine_leaf *l)
{
	struct json_object *o = json_object_new_object();

	o = json_out_set(o, "shoot", json_object_new_int64((int64_t)l->shoot));
	o = json_out_set(o, "node", json_object_new_int64((int64_t)l->node));
	o = json_out_set(o, "cotyledon", json_object_new_boolean(l->cotyledon));
	return json_out_set(o, "points", jpoints(l->p, 4));
}

static struct json_object *jvine(const struct vine *v)
{
	struct json_object *o = jparams(json_object_new_object(), &v->p);
	struct json_object *shoots = json_object_new_array_ext((int)v->nshoots);
	struct json_object *leaves;
	struct vine_leaf *l;
	size_t nl;

	o = json_out_set(o, "plant", jpoint(v->plant));
	for (size_t i = 0; i < v->nshoots; i++)
		shoots = json_out_push(shoots, jshoot(v, i));
	o = json_out_set(o, "shoots", shoots);
	if (vine_leaves(v, &l, &nl) < 0) {
		json_object_put(o);
		return NULL;
	}
	leaves = json_object_new_array_ext((int)nl);
	for (size_t i = 0; i < nl; i++)
		leaves = json_out_push(leaves, jleaf(&l[i]));
	free(l);
	return json_out_set(o, "leaves", leaves);
}

struct json_object *vine_json_set(struct json_object *root, const struct vine *vines,
				  size_t nvines)
{
	struct json_object *arr = json_object_new_array_ext((int)nvines);

	for (size_t i = 0; i < nvines; i++)
		arr = json_out_push(arr, jvine(&vines[i]));
	return json_out_set(root, "vines", arr);
}
