/* SPDX-License-Identifier: MIT */
/*
 * --dump-voxels (issue 17, docs/wood.md "Voxels dumped"): the voxel space as voxels.json
 * (what is where) and voxels.bin (the fields, x fastest, then y, then z, little-endian as
 * the boards and PCs edaha runs on write it), so that a test can check the rest state and
 * the forces from outside.
 */
#include <errno.h>
#include <string.h>

#include "json_out.h"
#include "wood.h"

enum field_type { F64, U8 };

struct field {
	const char *name;
	enum field_type type;
	int components;
};

/* The order of voxels.bin. */
static const struct field fields[] = {
	{ "density0", F64, 1 },	   { "density", F64, 1 },      { "compression", F64, 1 },
	{ "tension", F64, 1 },	   { "displacement", F64, 3 }, { "flags", U8, 1 },
};
#define NFIELDS (sizeof(fields) / sizeof(fields[0]))

static const void *data_of(const struct wood *w, size_t i)
{
	switch (i) {
	case 0: return w->density0;
	case 1: return w->g.density;
	case 2: return w->g.compression;
	case 3: return w->g.tension;
	case 4: return w->g.displacement;
	default: return w->g.flags;
	}
}

static size_t bytes_of(const struct wood *w, size_t i)
{
	return wood_cells(&w->g) * (size_t)fields[i].components *
	       (fields[i].type == F64 ? sizeof(double) : 1);
}

/* A setting exactly (not to the micrometre: a gravity of 1e-7 is not 0). */
static struct json_object *exact(double v)
{
	return json_object_new_double(v);
}

static struct json_object *triple(double a, double b, double c)
{
	struct json_object *arr = json_object_new_array();

	arr = json_out_push(arr, json_out_num(a));
	arr = json_out_push(arr, json_out_num(b));
	return json_out_push(arr, json_out_num(c));
}

int wood_dump(const struct wood *w, struct buf *json, struct buf *bin)
{
	struct json_object *root = json_object_new_object(), *fs = json_object_new_object(), *dims;
	size_t at = 0, len = bin->len, jlen = json->len;
	int ret;

	dims = json_object_new_array();
	dims = json_out_push(dims, json_object_new_int(w->g.nx));
	dims = json_out_push(dims, json_object_new_int(w->g.ny));
	dims = json_out_push(dims, json_object_new_int(w->g.nz));
	for (size_t i = 0; i < NFIELDS; i++) {
		struct json_object *f = json_object_new_object();

		f = json_out_set(f, "offset", json_object_new_int64((int64_t)at));
		f = json_out_set(f, "type", json_object_new_string(fields[i].type == F64 ? "f64" : "u8"));
		f = json_out_set(f, "components", json_object_new_int(fields[i].components));
		fs = json_out_set(fs, fields[i].name, f);
		at += bytes_of(w, i);
	}
	root = json_out_set(root, "format", json_object_new_string("edaha-voxels"));
	root = json_out_set(root, "version", json_object_new_int(1));
	root = json_out_set(root, "origin", triple(w->g.origin.x, w->g.origin.y, w->g.origin.z));
	root = json_out_set(root, "voxel", exact(w->g.h));
	root = json_out_set(root, "dims", dims);
	root = json_out_set(root, "mode",
			    json_object_new_string(w->p.mode == WOOD_CONIFER ? "conifer" : "broadleaf"));
	root = json_out_set(root, "step", json_object_new_int(w->presses));
	root = json_out_set(root, "alpha", exact(w->p.alpha));
	root = json_out_set(root, "beta", exact(w->p.beta));
	root = json_out_set(root, "gravity", exact(w->p.gravity));
	root = json_out_set(root, "wind", triple(w->p.wind[0], w->p.wind[1], w->p.wind[2]));
	root = json_out_set(root, "fields", fs);
	if (!root)
		return -ENOMEM;
	ret = json_out_append(root, "\n", json);
	json_object_put(root);
	for (size_t i = 0; i < NFIELDS && ret == 0; i++) {
		if (buf_append(bin, data_of(w, i), bytes_of(w, i)) < 0)
			ret = -ENOMEM;
	}
	if (ret < 0) {
		bin->len = len;
		json->len = jlen;
	}
	return ret;
}
