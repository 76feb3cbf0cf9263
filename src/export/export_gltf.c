/* SPDX-License-Identifier: MIT */
#include "export.h"
#include "export_gltf.h"
#include "export_leaves.h"
#include "export_vines.h"
#include "export_wind.h"
#include "numfmt.h"

#include <errno.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "json_out.h"
#include "wood.h"

/* GLB container constants, glTF 2.0 spec section 4.4. */
#define GLB_MAGIC 0x46546c67u      /* "glTF" */
#define GLB_VERSION 2u
#define GLB_CHUNK_JSON 0x4e4f534au /* "JSON" */
#define GLB_CHUNK_BIN 0x004e4942u  /* "BIN\0" */
#define GLB_HEADER_LEN 12u
#define GLB_CHUNK_HEADER_LEN 8u

#define GL_BYTE 5120
#define GL_UNSIGNED_BYTE 5121
#define GL_FLOAT 5126
#define GL_UNSIGNED_INT 5125
#define GL_TRIANGLES 4
#define GL_ARRAY_BUFFER 34962
#define GL_ELEMENT_ARRAY_BUFFER 34963

static const double bark_color[4] = { MATERIAL_BARK_RGB, 1.0 };
static const double leaves_color[4] = { MATERIAL_LEAVES_RGB, 1.0 };
static const double vine_color[4] = { MATERIAL_VINE_RGB, 1.0 };
/* glTF multiplies COLOR_0 by the base colour: white leaves it the leaf's own colour. */
static const double white[4] = { 1.0, 1.0, 1.0, 1.0 };

/*
 * Spring's and autumn's leaves: each leaf its own colour, given as a COLOR_0 vertex
 * attribute on the one leaves primitive, rather than one primitive a palette colour:
 *
 * - The leaves' POSITION, NORMAL and indices stay byte for byte what summer has (one
 *   primitive, one draw), only COLOR_0 is added. Primitives a colour would either reorder
 *   the leaves' vertices and indices, or share the vertices between up to 6 primitives,
 *   which importers that copy each primitive's whole accessors (Debian's assimp 5.2) then
 *   hold 6 times over.
 * - The Khronos validator takes it with no error or warning (validate_samples.sh and
 *   seasons.sh check), nor info or hint; and viewers show it: three.js's GLTFLoader turns
 *   on vertexColors for a primitive with COLOR_0, Blender's importer multiplies COLOR_0
 *   into the material's Base Color (a Color Attribute node).
 * - VEC4 normalized unsigned bytes: 4 bytes a vertex, a quarter of floats (a cherry leaf
 *   has 12 vertices: 30,000 leaves take 1.4 MB), what Blender keeps anyway (byte colours).
 *   Alpha is written, 1: given RGB floats, assimp 5.2 makes it 0. A byte is the palette's
 *   value to the nearest 1/255; entries differ by 0.02 or more in some channel, so each
 *   colour still says which entry its leaf has.
 */

static struct json_object *jint(size_t v)
{
	return json_object_new_int64((int64_t)v);
}

static struct json_object *jstr(const char *s)
{
	return json_object_new_string(s);
}

/* "%.9g" is enough digits for a float to read back as the same float, and no noise for 0.9. */
static struct json_object *jfloat(double v)
{
	char s[32];

	snprintf(s, sizeof(s), "%.9g", v);
	return json_object_new_double_s(v, s);
}

static struct json_object *jvec(const double *v, size_t n)
{
	struct json_object *arr = json_object_new_array();

	for (size_t i = 0; i < n; i++)
		arr = json_out_push(arr, jfloat(v[i]));
	return arr;
}

enum glb_data {
	GLB_FLOATS,
	GLB_U32,
	GLB_LEAF_RGBA, /* data is a struct export_leaves: each vertex its leaf's colour */
	GLB_BYTES,     /* data is the bytes as they go, 4 an element */
	GLB_ZEROS,     /* no data: zeros */
};

/* What goes into the BIN chunk, in order. */
struct glb_view {
	const void *data;
	size_t count; /* 4-byte elements */
	enum glb_data kind;
};

/* The primitives, in the file's order: the tree's swept bark, its wood's bark (the
 * voxelised branches', wood.h; the bark beside the bark), its leaves, then its vines'
 * stems and leaves. A part that is not there is left out, so a tree without wood or vines
 * has the bytes it had. */
enum glb_prim { GLB_BARK, GLB_WOOD, GLB_LEAVES, GLB_VINE, GLB_VINE_LEAVES, GLB_NPRIMS };
static const char *const glb_prim_names[GLB_NPRIMS] = { "bark", "wood", "leaves", "vine",
							"vine-leaves" };

/* The materials, each in the file once, numbered as first used; the wood is bark. */
enum glb_mat { GLB_MAT_BARK, GLB_MAT_LEAVES, GLB_MAT_VINE };
static const enum glb_mat glb_prim_mat[GLB_NPRIMS] = { GLB_MAT_BARK, GLB_MAT_BARK, GLB_MAT_LEAVES,
						       GLB_MAT_VINE, GLB_MAT_LEAVES };

/* How the primitives' vertices move with the wind (export_wind.h). */
static const enum export_wind_bind glb_prim_bind[GLB_NPRIMS] = {
	EXPORT_WIND_BARK, EXPORT_WIND_NEAREST, EXPORT_WIND_LEAVES, EXPORT_WIND_NEAREST,
	EXPORT_WIND_NEAREST
};

/* The morph targets' names (the mesh's extras.targetNames, which Blender and three.js
 * give the shape keys), in live_wind_targets' order. */
static const char *const glb_target_names[LIVE_WIND_TARGETS] = {
	"wind-trunk-along", "wind-trunk-across", "wind-limbs-sin",  "wind-limbs-cos",
	"wind-branches-sin", "wind-branches-cos", "wind-twigs-sin", "wind-twigs-cos",
	"wind-flutter-sin", "wind-flutter-cos",
};

/* What one tree's mesh is made of. */
struct glb_input {
	const struct mesh *mesh[GLB_NPRIMS];            /* NULL: none */
	const struct export_leaves *colors[GLB_NPRIMS]; /* the leaves' COLOR_0 in spring, autumn */
	enum export_look how;
	enum season season;
	const char *name; /* the node's and the mesh's */
	/* what its accessors' names begin with: NULL, the primitive's name ("bark.POSITION",
	 * model.glb's); else this and the primitive's ("tree-3.bark.POSITION", a forest's) */
	const char *label;
	/* the wind, the used primitives' targets in order; NULL: a still model */
	const struct export_wind_anim *anim;
};

/* An accessor's name's first part: "tree-18446744073709551615.vine-leaves" at most. */
#define GLB_LABEL_MAX 48
/* A zero target's one sparse value: 3 floats (or 3 bytes) of zeros. */
#define GLB_SPARSE_ZERO_WORDS 3

/* The materials a file may hold, each once: the bark, the vine, summer's leaves and each
 * season's coloured leaves (a forest's trees may stand in different seasons). */
enum { GLB_SLOT_BARK, GLB_SLOT_VINE, GLB_SLOT_LEAVES, GLB_SLOT_COLORED,
       GLB_NSLOTS = GLB_SLOT_COLORED + SEASON_COUNT };

/*
 * The document being built: one mesh after another, each with its node and, with the
 * wind, its channel of the one animation. Its JSON arrays are NULL after an allocation
 * failed (json_out.h), which the root then shows; `bin` lists what goes into the BIN
 * chunk, in order, pointing into the meshes, which must live until glb_write_doc.
 */
struct glb {
	struct json_object *nodes, *meshes, *accessors, *views, *materials, *channels, *samplers;
	size_t nnodes, nmeshes, naccessors, nmats, nsamplers;
	struct glb_view *bin;
	size_t nviews, cap;
	bool nomem;         /* bin could not grow */
	size_t sparse_view; /* the zero targets' index view (the value's next); 0: none yet */
	size_t bin_len;
	size_t mat_index[GLB_NSLOTS];
	bool have_mat[GLB_NSLOTS];
	bool quantized;     /* some mesh has byte targets: KHR_mesh_quantization */
};

/* 0 or -ENOMEM (g then free-able). */
static int glb_init(struct glb *g)
{
	memset(g, 0, sizeof(*g));
	g->nodes = json_object_new_array();
	g->meshes = json_object_new_array();
	g->accessors = json_object_new_array();
	g->views = json_object_new_array();
	g->materials = json_object_new_array();
	g->channels = json_object_new_array();
	g->samplers = json_object_new_array();
	/* one missing, even if never used, is a failed allocation: the export fails */
	if (!g->nodes || !g->meshes || !g->accessors || !g->views || !g->materials ||
	    !g->channels || !g->samplers)
		return -ENOMEM;
	return 0;
}

static void glb_free(struct glb *g)
{
	json_object_put(g->nodes);
	json_object_put(g->meshes);
	json_object_put(g->accessors);
	json_object_put(g->views);
	json_object_put(g->materials);
	json_object_put(g->channels);
	json_object_put(g->samplers);
	free(g->bin);
	memset(g, 0, sizeof(*g));
}

/* The next view's data in the BIN chunk; a failure to grow is remembered for the end. */
static void glb_bin_push(struct glb *g, const void *data, size_t count, enum glb_data kind)
{
	if (g->nviews == g->cap && !g->nomem) {
		size_t cap = g->cap ? 2 * g->cap : 32;
		struct glb_view *bin = cap <= SIZE_MAX / sizeof(*bin)
					       ? realloc(g->bin, cap * sizeof(*bin)) : NULL;

		if (bin) {
			g->bin = bin;
			g->cap = cap;
		} else {
			g->nomem = true;
		}
	}
	if (!g->nomem)
		g->bin[g->nviews] = (struct glb_view){ data, count, kind };
	g->nviews++;
}

/* A bufferView of count 4-byte elements; target 0: none (animation data), stride 0: none. */
static void glb_add_view_ex(struct glb *g, const void *data, size_t count, enum glb_data kind,
			    int target, size_t stride)
{
	struct json_object *v = json_object_new_object();
	size_t len = 4 * count;

	v = json_out_set(v, "buffer", jint(0));
	v = json_out_set(v, "byteOffset", jint(g->bin_len));
	v = json_out_set(v, "byteLength", jint(len));
	if (stride)
		v = json_out_set(v, "byteStride", jint(stride));
	if (target)
		v = json_out_set(v, "target", jint((size_t)target));
	glb_bin_push(g, data, count, kind);
	/* Every element is 4 bytes, so every view stays 4-byte aligned. */
	g->bin_len += len;
	g->views = json_out_push(g->views, v);
}

static void glb_add_view(struct glb *g, const void *data, size_t count, enum glb_data kind,
			 int target)
{
	glb_add_view_ex(g, data, count, kind, target, 0);
}

/* Appends an accessor; its index. */
static size_t glb_push_accessor(struct glb *g, struct json_object *a)
{
	g->accessors = json_out_push(g->accessors, a);
	return g->naccessors++;
}

static struct json_object *glb_accessor(const char *label, const char *what, size_t view,
					int component, size_t count, const char *type)
{
	struct json_object *a = json_object_new_object();
	char name[GLB_LABEL_MAX + 32];

	snprintf(name, sizeof(name), "%.*s.%s", GLB_LABEL_MAX - 1, label, what);
	a = json_out_set(a, "name", jstr(name));
	a = json_out_set(a, "bufferView", jint(view));
	a = json_out_set(a, "componentType", jint((size_t)component));
	a = json_out_set(a, "count", jint(count));
	a = json_out_set(a, "type", jstr(type));
	return a;
}

/* POSITION needs exact bounds: computed on the float data the validator reads back. */
static struct json_object *glb_bounds(struct json_object *a, const struct mesh *m)
{
	double lo[3], hi[3];

	for (int c = 0; c < 3; c++)
		lo[c] = hi[c] = m->positions[c];
	for (size_t i = 1; i < m->nvertices; i++) {
		for (int c = 0; c < 3; c++) {
			double v = m->positions[3 * i + (size_t)c];

			lo[c] = v < lo[c] ? v : lo[c];
			hi[c] = v > hi[c] ? v : hi[c];
		}
	}
	a = json_out_set(a, "min", jvec(lo, 3));
	return json_out_set(a, "max", jvec(hi, 3));
}

static struct json_object *glb_material(const char *name, const double color[4], double roughness,
					bool double_sided)
{
	struct json_object *pbr = json_object_new_object();
	struct json_object *mat = json_object_new_object();

	pbr = json_out_set(pbr, "baseColorFactor", jvec(color, 4));
	pbr = json_out_set(pbr, "metallicFactor", jint(0));
	pbr = json_out_set(pbr, "roughnessFactor", jfloat(roughness));
	mat = json_out_set(mat, "name", jstr(name));
	mat = json_out_set(mat, "pbrMetallicRoughness", pbr);
	if (double_sided)
		mat = json_out_set(mat, "doubleSided", json_object_new_boolean(1));
	return mat;
}

/* The leaves' material: summer's green as before seasons, else white under COLOR_0. */
static struct json_object *glb_leaves_material(enum export_look how, enum season s)
{
	char name[32];

	if (how == EXPORT_LEAVES_GREEN)
		return glb_material("leaves", leaves_color, 0.8, true);
	snprintf(name, sizeof(name), "leaves-%s", season_name(s));
	return glb_material(name, white, 0.8, true);
}

static struct json_object *glb_new_material(enum glb_mat k, enum export_look how, enum season s)
{
	if (k == GLB_MAT_BARK)
		return glb_material("bark", bark_color, 0.9, false);
	/* a young stem, smoother than bark; closed tubes, so one-sided as the bark */
	if (k == GLB_MAT_VINE)
		return glb_material("vine", vine_color, 0.8, false);
	return glb_leaves_material(how, s);
}

/* Which of the file's materials a primitive of kind k takes: the leaves' by their look. */
static size_t glb_mat_slot(enum glb_mat k, enum export_look how, enum season s)
{
	if (k == GLB_MAT_BARK)
		return GLB_SLOT_BARK;
	if (k == GLB_MAT_VINE)
		return GLB_SLOT_VINE;
	if (how == EXPORT_LEAVES_COLORED && (unsigned)s < SEASON_COUNT)
		return GLB_SLOT_COLORED + (size_t)s;
	return GLB_SLOT_LEAVES;
}

/* The material's index in the file, made when first used. */
static size_t glb_use_material(struct glb *g, enum glb_mat k, enum export_look how, enum season s)
{
	size_t slot = glb_mat_slot(k, how, s);

	if (!g->have_mat[slot]) {
		g->materials = json_out_push(g->materials, glb_new_material(k, how, s));
		g->mat_index[slot] = g->nmats++;
		g->have_mat[slot] = true;
	}
	return g->mat_index[slot];
}

/* One primitive's accessors and views, and its entry for primitives; colors: its COLOR_0. */
static struct json_object *glb_add_prim(struct glb *g, const struct mesh *m, const char *label,
					const struct export_leaves *colors, size_t material)
{
	size_t first = g->naccessors, view = g->nviews, ncols = colors ? 1 : 0;
	struct json_object *prim, *attrs, *pos;

	/* Accessors and bufferViews follow each other: POSITION, NORMAL, COLOR_0 (leaves in
	 * spring and autumn only), indices (in model.glb numbered alike). */
	pos = glb_accessor(label, "POSITION", view, GL_FLOAT, m->nvertices, "VEC3");
	glb_push_accessor(g, glb_bounds(pos, m));
	glb_push_accessor(g, glb_accessor(label, "NORMAL", view + 1, GL_FLOAT, m->nvertices,
					  "VEC3"));
	glb_add_view(g, m->positions, 3 * m->nvertices, GLB_FLOATS, GL_ARRAY_BUFFER);
	glb_add_view(g, m->normals, 3 * m->nvertices, GLB_FLOATS, GL_ARRAY_BUFFER);
	if (colors) {
		struct json_object *col = glb_accessor(label, "COLOR_0", view + 2, GL_UNSIGNED_BYTE,
						       m->nvertices, "VEC4");

		col = json_out_set(col, "normalized", json_object_new_boolean(1));
		glb_push_accessor(g, col);
		glb_add_view(g, colors, m->nvertices, GLB_LEAF_RGBA, GL_ARRAY_BUFFER);
	}
	glb_push_accessor(g, glb_accessor(label, "indices", view + 2 + ncols, GL_UNSIGNED_INT,
					  m->nindices, "SCALAR"));
	glb_add_view(g, m->indices, m->nindices, GLB_U32, GL_ELEMENT_ARRAY_BUFFER);

	attrs = json_object_new_object();
	attrs = json_out_set(attrs, "POSITION", jint(first));
	attrs = json_out_set(attrs, "NORMAL", jint(first + 1));
	if (colors)
		attrs = json_out_set(attrs, "COLOR_0", jint(first + 2));
	prim = json_object_new_object();
	prim = json_out_set(prim, "attributes", attrs);
	prim = json_out_set(prim, "indices", jint(first + 2 + ncols));
	prim = json_out_set(prim, "material", jint(material));
	return json_out_set(prim, "mode", jint(GL_TRIANGLES));
}

/* A target's bounds: the stored values', integers for bytes. */
static struct json_object *glb_target_bounds(const double v[3], bool floats)
{
	struct json_object *arr = json_object_new_array_ext(3);

	for (int c = 0; c < 3; c++)
		arr = json_out_push(arr, floats ? jfloat(v[c]) : json_object_new_int((int)v[c]));
	return arr;
}

/*
 * The targets zero at every vertex of a primitive: one accessor without a view (zeros,
 * glTF says), with one sparse element, vertex 0 set to 0, as Debian's assimp 5.2 refuses
 * an accessor with neither view nor sparse. Every such accessor of the file shares that
 * index and value (16 bytes in all), where a view of zeros would cost 4 bytes a vertex.
 */
static struct json_object *glb_zero_accessor(struct glb *g, const char *label, size_t n,
					     bool floats)
{
	static const double zero[3] = { 0.0, 0.0, 0.0 };
	struct json_object *a = json_object_new_object(), *sparse, *indices, *values;
	char name[GLB_LABEL_MAX + 32];

	if (!g->sparse_view) {
		g->sparse_view = g->nviews;
		glb_add_view(g, NULL, 1, GLB_ZEROS, 0);
		glb_add_view(g, NULL, GLB_SPARSE_ZERO_WORDS, GLB_ZEROS, 0);
	}
	indices = json_object_new_object();
	indices = json_out_set(indices, "bufferView", jint(g->sparse_view));
	indices = json_out_set(indices, "componentType", jint(GL_UNSIGNED_INT));
	values = json_out_set(json_object_new_object(), "bufferView", jint(g->sparse_view + 1));
	sparse = json_object_new_object();
	sparse = json_out_set(sparse, "count", jint(1));
	sparse = json_out_set(sparse, "indices", indices);
	sparse = json_out_set(sparse, "values", values);
	snprintf(name, sizeof(name), "%.*s.wind-zero", GLB_LABEL_MAX - 1, label);
	a = json_out_set(a, "name", jstr(name));
	a = json_out_set(a, "componentType", jint(floats ? GL_FLOAT : GL_BYTE));
	if (!floats)
		a = json_out_set(a, "normalized", json_object_new_boolean(1));
	a = json_out_set(a, "count", jint(n));
	a = json_out_set(a, "type", jstr("VEC3"));
	a = json_out_set(a, "min", glb_target_bounds(zero, floats));
	a = json_out_set(a, "max", glb_target_bounds(zero, floats));
	return json_out_set(a, "sparse", sparse);
}

/*
 * A primitive's morph targets (its entry in primitives gets "targets"): each target's
 * view and accessor, after every view of the still mesh, so that in model.glb its bytes
 * stay where they were; the targets zero at every vertex of the primitive share one
 * accessor without data (glb_zero_accessor).
 */
static struct json_object *glb_add_targets(struct glb *g, struct json_object *prim,
					   const char *label, const struct export_wind_prim *p,
					   bool floats)
{
	struct json_object *targets = json_object_new_array_ext(LIVE_WIND_TARGETS);
	size_t n = p->nvertices, count = floats ? 3 * n : n, stride = floats ? 0 : 4;
	size_t zero = SIZE_MAX; /* the zero accessor's index, once made */

	for (int j = 0; j < LIVE_WIND_TARGETS; j++) {
		struct json_object *a, *target;
		size_t index;

		if (!p->data[j]) {
			if (zero == SIZE_MAX)
				zero = glb_push_accessor(g, glb_zero_accessor(g, label, n, floats));
			target = json_out_set(json_object_new_object(), "POSITION", jint(zero));
			targets = json_out_push(targets, target);
			continue;
		}
		a = glb_accessor(label, glb_target_names[j], g->nviews, floats ? GL_FLOAT : GL_BYTE,
				 n, "VEC3");
		glb_add_view_ex(g, p->data[j], count, floats ? GLB_FLOATS : GLB_BYTES,
				GL_ARRAY_BUFFER, stride);
		if (!floats)
			a = json_out_set(a, "normalized", json_object_new_boolean(1));
		a = json_out_set(a, "min", glb_target_bounds(p->lo[j], floats));
		a = json_out_set(a, "max", glb_target_bounds(p->hi[j], floats));
		index = glb_push_accessor(g, a);
		target = json_out_set(json_object_new_object(), "POSITION", jint(index));
		targets = json_out_push(targets, target);
	}
	return json_out_set(prim, "targets", targets);
}

/*
 * A channel of the animation "wind": node's weights by a CUBICSPLINE sampler of a's keys,
 * its time and values accessors named "LABEL.time" and "LABEL.weights".
 */
static void glb_add_channel(struct glb *g, const struct export_wind_anim *a, size_t node,
			    const char *label)
{
	struct json_object *in, *out, *sampler, *channel, *target;
	double lo = 0.0, hi = a->times[a->nkeys - 1];
	size_t input, output;

	in = glb_accessor(label, "time", g->nviews, GL_FLOAT, a->nkeys, "SCALAR");
	in = json_out_set(in, "min", jvec(&lo, 1));
	in = json_out_set(in, "max", jvec(&hi, 1));
	input = glb_push_accessor(g, in);
	glb_add_view(g, a->times, a->nkeys, GLB_FLOATS, 0);
	out = glb_accessor(label, "weights", g->nviews, GL_FLOAT, a->nkeys * 3 * LIVE_WIND_TARGETS,
			   "SCALAR");
	output = glb_push_accessor(g, out);
	glb_add_view(g, a->values, a->nkeys * 3 * LIVE_WIND_TARGETS, GLB_FLOATS, 0);

	sampler = json_object_new_object();
	sampler = json_out_set(sampler, "input", jint(input));
	sampler = json_out_set(sampler, "interpolation", jstr("CUBICSPLINE"));
	sampler = json_out_set(sampler, "output", jint(output));
	target = json_object_new_object();
	target = json_out_set(target, "node", jint(node));
	target = json_out_set(target, "path", jstr("weights"));
	channel = json_object_new_object();
	channel = json_out_set(channel, "sampler", jint(g->nsamplers));
	channel = json_out_set(channel, "target", target);
	g->channels = json_out_push(g->channels, channel);
	g->samplers = json_out_push(g->samplers, sampler);
	g->nsamplers++;
}

/* The mesh's default weights (0: the rest pose) and its targets' names. */
static struct json_object *glb_mesh_weights(struct json_object *mesh)
{
	struct json_object *weights = json_object_new_array_ext(LIVE_WIND_TARGETS);
	struct json_object *names = json_object_new_array_ext(LIVE_WIND_TARGETS);
	struct json_object *extras = json_object_new_object();

	for (int j = 0; j < LIVE_WIND_TARGETS; j++) {
		weights = json_out_push(weights, jint(0));
		names = json_out_push(names, jstr(glb_target_names[j]));
	}
	mesh = json_out_set(mesh, "weights", weights);
	extras = json_out_set(extras, "targetNames", names);
	return json_out_set(mesh, "extras", extras);
}

/* KHR_mesh_quantization: byte targets; required, as the extension says (a reader that
 * lacks it cannot read them as floats). */
static struct json_object *glb_quantization(struct json_object *root)
{
	static const char ext[] = "KHR_mesh_quantization";

	root = json_out_set(root, "extensionsUsed",
			    json_out_push(json_object_new_array(), jstr(ext)));
	return json_out_set(root, "extensionsRequired",
			    json_out_push(json_object_new_array(), jstr(ext)));
}

/* Whether primitive i goes into the file: an empty primitive is invalid glTF. */
static bool glb_prim_used(const struct glb_input *in, size_t i)
{
	const struct mesh *m = in->mesh[i];

	return m && m->nindices >= 3 && m->nvertices > 0 &&
	       !(glb_prim_mat[i] == GLB_MAT_LEAVES && in->how == EXPORT_LEAVES_NONE);
}

/* A primitive's accessors' label: its name, after in's label if any. */
static void glb_label(char out[GLB_LABEL_MAX], const struct glb_input *in, const char *prim)
{
	if (in->label)
		snprintf(out, GLB_LABEL_MAX, "%s.%s", in->label, prim);
	else
		snprintf(out, GLB_LABEL_MAX, "%s", prim);
}

/*
 * Appends in's mesh, every primitive that has triangles and with in->anim their targets;
 * false (nothing appended) when there is none, else *index is the mesh's.
 */
static bool glb_add_mesh(struct glb *g, const struct glb_input *in, size_t *index)
{
	struct json_object *prims[GLB_NPRIMS], *primitives, *mesh;
	char labels[GLB_NPRIMS][GLB_LABEL_MAX];
	const struct export_wind_anim *anim = in->anim;
	size_t nprims = 0;

	for (size_t i = 0; i < GLB_NPRIMS; i++) {
		enum glb_mat k = glb_prim_mat[i];
		bool colored = k == GLB_MAT_LEAVES && in->how == EXPORT_LEAVES_COLORED;
		size_t mat;

		if (!glb_prim_used(in, i))
			continue;
		mat = glb_use_material(g, k, in->how, in->season);
		glb_label(labels[nprims], in, glb_prim_names[i]);
		prims[nprims] = glb_add_prim(g, in->mesh[i], labels[nprims],
					     colored ? in->colors[i] : NULL, mat);
		nprims++;
	}
	if (nprims == 0)
		return false;
	/* the wind's data after all the still mesh's: in model.glb its bytes stay where they
	 * were */
	for (size_t p = 0; anim && p < nprims; p++)
		prims[p] = glb_add_targets(g, prims[p], labels[p], &anim->prims[p], anim->floats);
	g->quantized = g->quantized || (anim && !anim->floats);
	primitives = json_object_new_array();
	for (size_t p = 0; p < nprims; p++)
		primitives = json_out_push(primitives, prims[p]);
	mesh = json_object_new_object();
	mesh = json_out_set(mesh, "name", jstr(in->name));
	mesh = json_out_set(mesh, "primitives", primitives);
	if (anim)
		mesh = glb_mesh_weights(mesh);
	g->meshes = json_out_push(g->meshes, mesh);
	*index = g->nmeshes++;
	return true;
}

/* Appends a node named name with the mesh (NULL: none) at translation (NULL: none); its
 * index. */
static size_t glb_add_node(struct glb *g, const char *name, const size_t *mesh,
			   const double *translation)
{
	struct json_object *node = json_object_new_object();

	node = json_out_set(node, "name", jstr(name));
	if (mesh)
		node = json_out_set(node, "mesh", jint(*mesh));
	if (translation)
		node = json_out_set(node, "translation", jvec(translation, 3));
	g->nodes = json_out_push(g->nodes, node);
	return g->nnodes++;
}

/* Moves one of g's arrays into root under key when it has anything. */
static struct json_object *glb_move(struct json_object *root, const char *key,
				    struct json_object **arr, size_t n)
{
	struct json_object *a = *arr;

	if (n == 0)
		return root;
	*arr = NULL;
	return json_out_set(root, key, a);
}

/* The JSON document: the arrays move into it; NULL without memory. */
static struct json_object *glb_root(struct glb *g)
{
	struct json_object *root = json_object_new_object(), *asset = json_object_new_object();
	struct json_object *scene = json_object_new_object();

	asset = json_out_set(asset, "version", jstr("2.0"));
	asset = json_out_set(asset, "generator", jstr("edaha"));
	root = json_out_set(root, "asset", asset);
	if (g->quantized)
		root = glb_quantization(root);
	root = json_out_set(root, "scene", jint(0));
	if (g->nnodes) {
		/* every node a root of the scene: a tree is one node */
		struct json_object *nodes = json_object_new_array_ext((int)g->nnodes);

		for (size_t i = 0; i < g->nnodes; i++)
			nodes = json_out_push(nodes, jint(i));
		scene = json_out_set(scene, "nodes", nodes);
	}
	/* Nothing drawn: still a valid glTF, an empty scene. */
	root = json_out_set(root, "scenes", json_out_push(json_object_new_array(), scene));
	root = glb_move(root, "nodes", &g->nodes, g->nnodes);
	root = glb_move(root, "meshes", &g->meshes, g->nmeshes);
	root = glb_move(root, "accessors", &g->accessors, g->naccessors);
	root = glb_move(root, "bufferViews", &g->views, g->nviews);
	if (g->bin_len) {
		struct json_object *buffer = json_object_new_object();

		buffer = json_out_set(buffer, "byteLength", jint(g->bin_len));
		root = json_out_set(root, "buffers", json_out_push(json_object_new_array(), buffer));
	}
	root = glb_move(root, "materials", &g->materials, g->nmats);
	if (g->nsamplers) {
		struct json_object *anim = json_object_new_object();

		anim = json_out_set(anim, "name", jstr("wind"));
		anim = glb_move(anim, "channels", &g->channels, g->nsamplers);
		anim = glb_move(anim, "samplers", &g->samplers, g->nsamplers);
		root = json_out_set(root, "animations", json_out_push(json_object_new_array(), anim));
	}
	return root;
}

/* A colour channel as a normalized unsigned byte: the nearest of 0/255 .. 255/255 (in
 * double: in float, 0.9f * 255 rounds up to 229.5 and so to 230, not 229). */
static unsigned char unorm8(float c)
{
	if (!(c > 0.0f))
		return 0;
	if (c >= 1.0f)
		return 255;
	return (unsigned char)((double)c * 255.0 + 0.5);
}

/* Each vertex of a leaf its palette entry's RGBA; the parts cover the mesh, in order. */
static void glb_write_leaf_rgba(unsigned char *p, const struct export_leaves *el)
{
	unsigned char rgba[SEASON_MAX_COLORS][4];
	size_t n = export_leaves_nparts(el);

	for (size_t k = 0; k < el->ncolors && k < SEASON_MAX_COLORS; k++) {
		rgba[k][0] = unorm8(el->palette[k].r);
		rgba[k][1] = unorm8(el->palette[k].g);
		rgba[k][2] = unorm8(el->palette[k].b);
		rgba[k][3] = 255;
	}
	for (size_t i = 0; i < n; i++) {
		struct export_leaf_part part = export_leaves_part(el, i);

		for (size_t v = part.first_vertex; v < part.end_vertex; v++)
			memcpy(p + 4 * v, rgba[part.color], 4);
	}
}

/* Little-endian, whatever the host: reserved once, then written in place. */
static int glb_append_view(struct buf *out, const struct glb_view *v)
{
	unsigned char *p;
	int r = buf_reserve(out, 4 * v->count);

	if (r < 0)
		return r;
	p = out->data + out->len;
	if (v->kind == GLB_LEAF_RGBA || v->kind == GLB_BYTES || v->kind == GLB_ZEROS) {
		if (v->kind == GLB_LEAF_RGBA)
			glb_write_leaf_rgba(p, v->data);
		else if (v->kind == GLB_BYTES)
			memcpy(p, v->data, 4 * v->count);
		else
			memset(p, 0, 4 * v->count);
		out->len += 4 * v->count;
		return 0;
	}
	for (size_t i = 0; i < v->count; i++, p += 4) {
		uint32_t u;

		if (v->kind == GLB_FLOATS)
			memcpy(&u, &((const float *)v->data)[i], sizeof(u));
		else
			u = ((const uint32_t *)v->data)[i];
		p[0] = (unsigned char)u;
		p[1] = (unsigned char)(u >> 8);
		p[2] = (unsigned char)(u >> 16);
		p[3] = (unsigned char)(u >> 24);
	}
	out->len += 4 * v->count;
	return 0;
}

/* Padding counts from the chunk start, whatever already is in out. */
static int append_fill(struct buf *out, size_t n, unsigned char fill)
{
	static const unsigned char spaces[3] = { ' ', ' ', ' ' }, zeros[3];

	return buf_append(out, fill == ' ' ? spaces : zeros, n);
}

static int glb_write(struct buf *out, const char *json, size_t json_len, const struct glb *g)
{
	size_t json_padded = (json_len + 3) & ~(size_t)3;
	size_t bin_padded = (g->bin_len + 3) & ~(size_t)3;
	size_t total = GLB_HEADER_LEN + GLB_CHUNK_HEADER_LEN + json_padded;
	int r;

	if (g->bin_len > 0)
		total += GLB_CHUNK_HEADER_LEN + bin_padded;
	/* GLB lengths are 32-bit. */
	if (json_len > UINT32_MAX || g->bin_len > UINT32_MAX || total > UINT32_MAX)
		return -EFBIG;

	r = buf_reserve(out, total);
	if (r < 0)
		return r;
	if ((r = buf_append_u32le(out, GLB_MAGIC)) < 0 ||
	    (r = buf_append_u32le(out, GLB_VERSION)) < 0 ||
	    (r = buf_append_u32le(out, (uint32_t)total)) < 0 ||
	    (r = buf_append_u32le(out, (uint32_t)json_padded)) < 0 ||
	    (r = buf_append_u32le(out, GLB_CHUNK_JSON)) < 0 ||
	    (r = buf_append(out, json, json_len)) < 0 ||
	    (r = append_fill(out, json_padded - json_len, ' ')) < 0)
		return r;
	/* No BIN chunk at all when there is no data: an empty one is flagged by validators. */
	if (g->bin_len == 0)
		return 0;
	if ((r = buf_append_u32le(out, (uint32_t)bin_padded)) < 0 ||
	    (r = buf_append_u32le(out, GLB_CHUNK_BIN)) < 0)
		return r;
	for (size_t i = 0; i < g->nviews; i++) {
		r = glb_append_view(out, &g->bin[i]);
		if (r < 0)
			return r;
	}
	return append_fill(out, bin_padded - g->bin_len, 0);
}

/* The GLB of g appended to out, or nothing at all. */
static int glb_write_doc(struct glb *g, struct buf *out)
{
	struct json_object *root;
	struct buf json;
	size_t start = out->len;
	int r;

	if (g->nomem)
		return -ENOMEM;
	root = glb_root(g);
	if (!root)
		return -ENOMEM;
	buf_init(&json);
	r = json_out_append(root, NULL, &json);
	if (r == 0)
		r = glb_write(out, (const char *)json.data, json.len, g);
	json_object_put(root);
	buf_finish(&json);
	if (r < 0)
		out->len = start; /* no half-written file */
	return r;
}

/* The GLB of one mesh (a node named in->name, with its channel of the wind if any). */
static int glb_export(const struct glb_input *in, struct buf *out)
{
	struct glb g;
	size_t mesh;
	int r;

	r = glb_init(&g);
	if (r == 0 && glb_add_mesh(&g, in, &mesh)) {
		size_t node = glb_add_node(&g, in->name, &mesh, NULL);

		if (in->anim)
			glb_add_channel(&g, in->anim, node, "wind");
	}
	if (r == 0)
		r = glb_write_doc(&g, out);
	glb_free(&g);
	return r;
}

/* The wind's targets and keys for in's used primitives over `loop` (0: the tree's own);
 * in->anim stays NULL for a tree without branches or whose meshes cannot be bound (no
 * segment to bind them to). */
static int glb_wind(struct glb_input *in, struct export_wind_anim *anim, const struct tree *t,
		    const struct tree_mesh_marks *mk, const struct export_wind *wind, double loop)
{
	const struct mesh *meshes[GLB_NPRIMS];
	enum export_wind_bind bind[GLB_NPRIMS];
	struct export_wind_tree wt;
	size_t n = 0;
	int r = export_wind_tree_init(&wt, t, wind, loop);

	for (size_t i = 0; r == 0 && i < GLB_NPRIMS; i++) {
		if (!glb_prim_used(in, i))
			continue;
		meshes[n] = in->mesh[i];
		bind[n++] = glb_prim_bind[i];
	}
	if (r == 0 && n > 0) {
		r = export_wind_anim_build(anim, &wt, t, mk, meshes, bind, n, wind->floats);
		if (r == 0)
			in->anim = anim;
		r = r == -EINVAL ? 0 : r;
	}
	export_wind_tree_finish(&wt);
	return r == -ENODATA ? 0 : r;
}

/* One tree's part of a file: what its views point into, until the file is written. */
struct glb_tree {
	struct glb_input in;
	struct export_leaves el, vel;
	struct export_vines ev;
	struct export_wind_anim anim;
};

/* The tree's meshes (m, its wood's bark, its vines meshed), the leaves' colours, and with
 * wind its targets and keys over loop. 0, -EINVAL (the wind's parameters) or -ENOMEM; gt
 * is finish-able either way. */
static int glb_tree_init(struct glb_tree *gt, const struct tree *t, const struct tree_mesh *m,
			 const struct tree_mesh_marks *mk, const struct export_wind *wind,
			 double loop)
{
	int r;

	memset(gt, 0, sizeof(*gt));
	gt->in.mesh[GLB_BARK] = &m->bark;
	/* m leaves the voxelised branches out: their bark is the wood's */
	gt->in.mesh[GLB_WOOD] = t->wood ? &t->wood->bark : NULL;
	gt->in.mesh[GLB_LEAVES] = &m->leaves;
	gt->in.how = export_look(t->season);
	gt->in.season = t->season;
	gt->in.name = "tree";
	r = export_vines_build(&gt->ev, t);
	if (r < 0)
		return r;
	gt->in.mesh[GLB_VINE] = &gt->ev.stems;
	gt->in.mesh[GLB_VINE_LEAVES] = &gt->ev.leaves;
	if (gt->in.how == EXPORT_LEAVES_COLORED) {
		export_leaves_init(&gt->el, t, &m->leaves, mk);
		/* no marks: the vines' leaves one part, in the palette's first colour */
		export_leaves_init(&gt->vel, t, &gt->ev.leaves, NULL);
		gt->in.colors[GLB_LEAVES] = &gt->el;
		gt->in.colors[GLB_VINE_LEAVES] = &gt->vel;
	}
	return wind ? glb_wind(&gt->in, &gt->anim, t, mk, wind, loop) : 0;
}

static void glb_tree_finish(struct glb_tree *gt)
{
	export_wind_anim_finish(&gt->anim);
	export_vines_finish(&gt->ev);
}

/* The tree's GLB, with its wind when given. */
static int glb_tree(const struct tree *t, const struct tree_mesh *m,
		    const struct tree_mesh_marks *mk, const struct export_wind *wind,
		    struct buf *out)
{
	struct glb_tree gt;
	int r = glb_tree_init(&gt, t, m, mk, wind, 0.0);

	if (r == 0)
		r = glb_export(&gt.in, out);
	glb_tree_finish(&gt);
	return r;
}

int export_glb(const struct tree *t, const struct tree_mesh *m, const struct tree_mesh_marks *mk,
	       struct buf *out)
{
	return glb_tree(t, m, mk, NULL, out);
}

int export_glb_wind(const struct tree *t, const struct tree_mesh *m,
		    const struct tree_mesh_marks *mk, const struct export_wind *wind,
		    struct buf *out)
{
	return glb_tree(t, m, mk, wind, out);
}

int export_glb_leaf(const struct mesh *m, const char *name, struct buf *out)
{
	/* no bark: the leaves' primitive alone, in summer's green */
	const struct glb_input in = {
		.mesh = { [GLB_LEAVES] = m },
		.how = EXPORT_LEAVES_GREEN,
		.season = SEASON_SUMMER,
		.name = name,
	};

	return glb_export(&in, out);
}

/* ---- many trees: export_gltf.h ------------------------------------------------------ */

struct export_gltf {
	struct glb g;
	struct glb_tree **trees; /* each allocated once: its views point into it */
	size_t ntrees, cap;
};

struct export_gltf *export_gltf_create(void)
{
	struct export_gltf *d = calloc(1, sizeof(*d));

	if (d && glb_init(&d->g) < 0) {
		export_gltf_destroy(d);
		return NULL;
	}
	return d;
}

void export_gltf_destroy(struct export_gltf *d)
{
	if (!d)
		return;
	for (size_t i = 0; i < d->ntrees; i++) {
		glb_tree_finish(d->trees[i]);
		free(d->trees[i]);
	}
	free(d->trees);
	glb_free(&d->g);
	free(d);
}

/* Room for one more tree; NULL without memory. */
static struct glb_tree *gltf_new_tree(struct export_gltf *d)
{
	struct glb_tree *gt;

	if (d->ntrees == d->cap) {
		size_t cap = d->cap ? 2 * d->cap : 16;
		struct glb_tree **trees = realloc(d->trees, cap * sizeof(*trees));

		if (!trees)
			return NULL;
		d->trees = trees;
		d->cap = cap;
	}
	gt = malloc(sizeof(*gt));
	if (gt)
		d->trees[d->ntrees++] = gt;
	return gt;
}

int export_gltf_add_tree(struct export_gltf *d, const struct tree *t, const struct tree_mesh *m,
			 const struct tree_mesh_marks *mk, const struct export_wind *wind,
			 double loop, const struct export_gltf_node *node)
{
	struct glb_tree *gt = gltf_new_tree(d);
	size_t mesh, index;
	bool has_mesh;
	int r;

	if (!gt)
		return -ENOMEM;
	r = glb_tree_init(gt, t, m, mk, wind, loop);
	if (r < 0)
		return r;
	gt->in.name = node->name;
	gt->in.label = node->name;
	has_mesh = glb_add_mesh(&d->g, &gt->in, &mesh);
	index = glb_add_node(&d->g, node->name, has_mesh ? &mesh : NULL, node->translation);
	if (has_mesh && gt->in.anim) {
		char label[GLB_LABEL_MAX];

		snprintf(label, sizeof(label), "%s.wind", node->name);
		glb_add_channel(&d->g, gt->in.anim, index, label);
	}
	return 0;
}

int export_gltf_write(struct export_gltf *d, struct buf *out)
{
	return glb_write_doc(&d->g, out);
}
