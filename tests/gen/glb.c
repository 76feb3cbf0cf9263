/* SPDX-License-Identifier: MIT */
#include "glb.h"

#include <json-c/json.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define GLB_MAGIC 0x46546c67u /* "glTF" */
#define CHUNK_JSON 0x4e4f534au
#define CHUNK_BIN 0x004e4942u
#define GL_FLOAT 5126
#define GL_UNSIGNED_INT 5125

static uint32_t le32(const unsigned char *p)
{
	return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

static int fail(const char *path, const char *what)
{
	fprintf(stderr, "%s: %s\n", path, what);
	return -1;
}

static unsigned char *slurp(const char *path, size_t *len)
{
	FILE *f = fopen(path, "rb");
	unsigned char *data = NULL;
	long n;

	if (!f)
		return NULL;
	if (fseek(f, 0, SEEK_END) == 0 && (n = ftell(f)) >= 0 && fseek(f, 0, SEEK_SET) == 0) {
		data = malloc((size_t)n + 1);
		if (data && fread(data, 1, (size_t)n, f) != (size_t)n) {
			free(data);
			data = NULL;
		}
		*len = (size_t)n;
	}
	fclose(f);
	return data;
}

static json_object *get(json_object *o, const char *k)
{
	json_object *v = NULL;

	return o && json_object_object_get_ex(o, k, &v) ? v : NULL;
}

static json_object *item(json_object *arr, json_object *index)
{
	if (!arr || !index || !json_object_is_type(index, json_type_int))
		return NULL;
	return json_object_array_get_idx(arr, (size_t)json_object_get_int(index));
}

/* An accessor's count and where its bytes start in bin; -1 if it does not fit. */
static long accessor(json_object *root, json_object *index, int type, size_t size, size_t *count,
		     size_t binlen)
{
	json_object *acc = item(get(root, "accessors"), index);
	json_object *view = acc ? item(get(root, "bufferViews"), get(acc, "bufferView")) : NULL;
	json_object *ct = get(acc, "componentType"), *n = get(acc, "count");
	size_t off, len;

	if (!view || !ct || !n || json_object_get_int(ct) != type || json_object_get_int(n) < 0)
		return -1;
	*count = (size_t)json_object_get_int(n);
	off = (size_t)json_object_get_int(get(view, "byteOffset")) +
	      (size_t)json_object_get_int(get(acc, "byteOffset"));
	len = *count * size;
	if (off > binlen || len > binlen - off ||
	    (size_t)json_object_get_int(get(view, "byteLength")) < len)
		return -1;
	return (long)off;
}

int glb_load(const char *path, struct glb *g)
{
	size_t len = 0, jlen, blen;
	unsigned char *data = slurp(path, &len), *bin;
	json_object *root = NULL, *prims, *mats;
	int ret = -1;

	memset(g, 0, sizeof(*g));
	if (!data)
		return fail(path, "cannot read");
	if (len < 20 || le32(data) != GLB_MAGIC || le32(data + 4) != 2 || le32(data + 8) != len) {
		fail(path, "not a GLB 2 file of its stated length");
		goto out;
	}
	jlen = le32(data + 12);
	if (le32(data + 16) != CHUNK_JSON || jlen > len - 20 || len - 20 - jlen < 8) {
		fail(path, "no JSON chunk followed by a chunk");
		goto out;
	}
	blen = le32(data + 20 + jlen);
	bin = data + 28 + jlen;
	if (le32(data + 24 + jlen) != CHUNK_BIN || blen > len - 28 - jlen) {
		fail(path, "no BIN chunk");
		goto out;
	}
	{
		json_tokener *tok = json_tokener_new();

		root = tok ? json_tokener_parse_ex(tok, (const char *)data + 20, (int)jlen) : NULL;
		if (tok)
			json_tokener_free(tok);
	}
	prims = get(json_object_array_get_idx(get(root, "meshes"), 0), "primitives");
	mats = get(root, "materials");
	if (!root) {
		fail(path, "unreadable JSON chunk");
		goto out;
	}
	for (size_t i = 0; prims && i < json_object_array_length(prims); i++) {
		json_object *p = json_object_array_get_idx(prims, i), *mat = item(mats, get(p, "material"));
		struct glb_prim *q = &g->prims[g->nprims];
		size_t nidx;
		long off;

		if (g->nprims == sizeof(g->prims) / sizeof(g->prims[0]) || !mat || !get(mat, "name")) {
			fail(path, "a primitive without a named material, or too many");
			goto out;
		}
		snprintf(q->material, sizeof(q->material), "%s", json_object_get_string(get(mat, "name")));
		off = accessor(root, get(p, "indices"), GL_UNSIGNED_INT, 4, &nidx, blen);
		if (off < 0 || nidx % 3) {
			fail(path, "bad index accessor");
			goto out;
		}
		q->ntriangles = nidx / 3;
		off = accessor(root, get(get(p, "attributes"), "POSITION"), GL_FLOAT, 12, &q->nvertices, blen);
		if (off < 0) {
			fail(path, "bad POSITION accessor");
			goto out;
		}
		q->positions = malloc(q->nvertices * 12 + 1);
		if (!q->positions)
			goto out;
		memcpy(q->positions, bin + off, q->nvertices * 12); /* little-endian floats */
		g->nprims++;
	}
	ret = 0;
out:
	json_object_put(root);
	free(data);
	if (ret < 0)
		glb_free(g);
	return ret;
}

void glb_free(struct glb *g)
{
	for (size_t i = 0; i < g->nprims; i++)
		free(g->prims[i].positions);
	memset(g, 0, sizeof(*g));
}

const struct glb_prim *glb_prim(const struct glb *g, const char *material)
{
	for (size_t i = 0; i < g->nprims; i++)
		if (!strcmp(g->prims[i].material, material))
			return &g->prims[i];
	return NULL;
}
