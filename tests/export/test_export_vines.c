/* SPDX-License-Identifier: MIT */
/*
 * A tree's vines in its exports (issue 16): a trunk with two vines grown on it
 * (synth_vine_tree). skeleton.json is version 2 with every vine's fields read back; the
 * glb and obj hold the tree's parts as without vines, plus the vines' stems ("vine") and
 * leaves ("vine-leaves"), exactly vine_mesh_append's triangles, in every season (no
 * leaves in winter, the palette's first colour in spring and autumn); same tree, same
 * bytes. The Khronos validator reads these trees' glb files too (write_samples'
 * vines-SEASON.glb, validate_samples.sh).
 */
#include <string.h>

#include <json-c/json.h>

#include "buf.h"
#include "export.h"
#include "glb_read.h"
#include "mesh.h"
#include "season.h"
#include "synth_vine.h"
#include "test.h"
#include "tree.h"
#include "vine.h"
#include "vine_json.h"

/* Both trees: the trunk alone, and with its two vines. */
struct pair {
	struct tree bare, vines;
	size_t stem_indices, leaf_indices; /* the vines' meshes, made here */
};

static void pair_init(struct pair *p)
{
	struct mesh stems, leaves;

	tree_init(&p->bare);
	tree_init(&p->vines);
	CHECK_INT(synth_vine_tree(&p->bare, 0), 0);
	CHECK_INT(synth_vine_tree(&p->vines, 2), 0);
	CHECK_INT(p->bare.nvines, 0);
	CHECK_INT(p->vines.nvines, 2);
	mesh_init(&stems);
	mesh_init(&leaves);
	for (size_t i = 0; i < p->vines.nvines; i++)
		CHECK_INT(vine_mesh_append(&p->vines.vines[i], &stems, &leaves), 0);
	p->stem_indices = stems.nindices;
	p->leaf_indices = leaves.nindices;
	/* something to find: stems round the trunk, leaves on them */
	CHECK(p->stem_indices > 1000 && p->leaf_indices >= 6 * 40);
	mesh_finish(&stems);
	mesh_finish(&leaves);
}

static void pair_finish(struct pair *p)
{
	tree_finish(&p->bare);
	tree_finish(&p->vines);
}

static void set_season(struct pair *p, enum season s)
{
	p->bare.season = s;
	p->vines.season = s;
}

static struct json_object *skeleton(const struct tree *t, struct buf *b)
{
	buf_reset(b);
	CHECK_INT(export_skeleton(t, b), 0);
	return json_text(b);
}

static void check_point(struct json_object *xyz, struct vec3 p)
{
	CHECK_INT(json_object_array_length(xyz), 3);
	CHECK_NEAR(json_num(at(xyz, 0)), p.x, 5.0001e-7);
	CHECK_NEAR(json_num(at(xyz, 1)), p.y, 5.0001e-7);
	CHECK_NEAR(json_num(at(xyz, 2)), p.z, 5.0001e-7);
}

static void check_shoot(struct json_object *o, const struct vine *v, size_t i)
{
	const struct vine_shoot *s = &v->shoots[i];
	struct json_object *axis = get(o, "axis"), *contacts = get(o, "contacts");
	size_t ncontacts = 0, k = 0;

	CHECK_INT(get_int(o, "parent"), s->parent);
	CHECK_INT(get_int(o, "node"), s->node);
	CHECK_INT(json_object_array_length(axis), s->n);
	for (size_t j = 0; j < s->n; j++)
		check_point(at(axis, j), s->axis[j]);
	CHECK_INT(json_object_array_length(get(o, "smooth")), s->n);
	for (size_t j = 0; j < s->n; j++) {
		if (!s->contact[j])
			continue;
		ncontacts++;
		CHECK_INT(json_object_get_int64(at(contacts, k++)), j);
	}
	CHECK_INT(json_object_array_length(contacts), ncontacts);
	CHECK(json_object_get_boolean(get(o, "stopped")) == s->stopped);
}

/* Vine i of synth_vine_tree as skeleton.json gives it. */
static void check_vine(struct json_object *o, const struct vine *v, size_t i)
{
	struct json_object *shoots = get(o, "shoots"), *leaves = get(o, "leaves");
	struct json_object *main_axis;
	struct vine_params p;
	struct vec3 plant;
	struct vine_leaf *l;
	size_t nl, touching = 0;

	synth_vine_params(i, &p, &plant);
	CHECK_INT(get_int(o, "edaha-vine"), VINE_PARAMS_VERSION);
	CHECK_NEAR(json_num(get(o, "internode")), p.internode, 1e-9);
	CHECK_NEAR(json_num(get(o, "radius")), p.radius, 1e-9);
	CHECK_INT(get_int(o, "leaves_per_node"), p.leaves_per_node);
	CHECK(!strcmp(get_str(o, "twining"), p.twining == VINE_RIGHT ? "right" : "left"));
	CHECK_INT(get_int(o, "seed"), p.seed);
	check_point(get(o, "plant"), plant);
	CHECK_INT(json_object_array_length(shoots), v->nshoots);
	for (size_t s = 0; s < v->nshoots; s++)
		check_shoot(at(shoots, s), v, s);

	/* it twined the trunk: its main axis touches the bark, at R + r from the trunk's axis
	 * (the bark a 16-gon inside the circle of radius R) */
	main_axis = get(at(shoots, 0), "axis");
	for (size_t k = 0; k < json_object_array_length(get(at(shoots, 0), "contacts")); k++) {
		size_t j = (size_t)json_object_get_int64(at(get(at(shoots, 0), "contacts"), k));
		struct json_object *xyz = at(main_axis, j);
		double x = json_num(at(xyz, 0)), z = json_num(at(xyz, 2));

		CHECK_NEAR(sqrt(x * x + z * z), SYNTH_VINE_RADIUS + p.radius, 0.012);
		touching++;
	}
	CHECK(touching > 10);

	CHECK_INT(vine_leaves(v, &l, &nl), 0);
	CHECK(nl > 10);
	CHECK_INT(json_object_array_length(leaves), nl);
	for (size_t k = 0; k < nl; k++) {
		struct json_object *lo = at(leaves, k);

		CHECK_INT(get_int(lo, "shoot"), l[k].shoot);
		CHECK_INT(get_int(lo, "node"), l[k].node);
		CHECK(json_object_get_boolean(get(lo, "cotyledon")) == l[k].cotyledon);
		CHECK_INT(json_object_array_length(get(lo, "points")), 4);
		for (size_t c = 0; c < 4; c++)
			check_point(at(get(lo, "points"), c), l[k].p[c]);
	}
	free(l);
}

static void test_skeleton(void)
{
	struct pair p;
	struct buf a, b;
	struct json_object *bare, *root, *vines;
	struct tree again;

	pair_init(&p);
	buf_init(&a);
	buf_init(&b);

	/* no vines: version 2, and no "vines" key at all */
	bare = skeleton(&p.bare, &a);
	CHECK_INT(get_int(bare, "version"), 2);
	CHECK(!json_object_object_get_ex(bare, "vines", NULL));
	json_object_put(bare);

	/* the same text up to the leaves, then the vines */
	root = skeleton(&p.vines, &b);
	CHECK(b.len > a.len);
	CHECK(!memcmp(a.data, b.data, a.len - 2)); /* a ends in "}\n" */
	CHECK(!memcmp(b.data + a.len - 2, ",\"vines\":[{", 11));
	CHECK_INT(get_int(root, "version"), 2);
	CHECK_INT(json_object_array_length(get(root, "branches")), 1);
	CHECK_INT(json_object_array_length(get(root, "leaves")), 1);
	vines = get(root, "vines");
	CHECK_INT(json_object_array_length(vines), 2);
	for (size_t i = 0; i < 2; i++)
		check_vine(at(vines, i), &p.vines.vines[i], i);
	json_object_put(root);

	/* the command line's writer is the same code: the same bytes, for the tree's vines
	 * given on the tree without them and on the tree with them (in their place) */
	buf_reset(&a);
	CHECK_INT(export_skeleton_vines(&p.bare, p.vines.vines, p.vines.nvines, &a), 0);
	CHECK(a.len == b.len && !memcmp(a.data, b.data, a.len));
	buf_reset(&a);
	CHECK_INT(export_skeleton_vines(&p.vines, p.vines.vines, p.vines.nvines, &a), 0);
	CHECK(a.len == b.len && !memcmp(a.data, b.data, a.len));

	/* the same tree grown again: the same bytes */
	tree_init(&again);
	CHECK_INT(synth_vine_tree(&again, 2), 0);
	buf_reset(&a);
	CHECK_INT(export_skeleton(&again, &a), 0);
	CHECK(a.len == b.len && !memcmp(a.data, b.data, a.len));
	tree_finish(&again);

	buf_finish(&a);
	buf_finish(&b);
	pair_finish(&p);
}

/* The meshes with their marks, as the app keeps them (no vines in them). */
struct meshes {
	struct tree_mesh tm;
	struct tree_mesh_marks mk;
};

static void meshes_build(struct meshes *m, const struct tree *t)
{
	tree_mesh_init(&m->tm);
	tree_mesh_marks_init(&m->mk);
	CHECK_INT(tree_mesh_build_marked(&m->tm, t, &m->mk), 0);
}

static void meshes_finish(struct meshes *m)
{
	tree_mesh_marks_finish(&m->mk);
	tree_mesh_finish(&m->tm);
}

static void glb_of(const struct tree *t, struct buf *b)
{
	struct meshes m;

	meshes_build(&m, t);
	buf_reset(b);
	CHECK_INT(export_glb(t, &m.tm, &m.mk, b), 0);
	meshes_finish(&m);
}

static struct json_object *material_of(const struct glb *g, struct json_object *prim)
{
	return at(get(g->json, "materials"), (size_t)get_int(prim, "material"));
}

/* The tree's own primitive is the same in both files. */
static void check_same_prim(const struct glb *a, const struct glb *b, const char *name)
{
	struct json_object *pa = glb_prim_named(a, name), *pb = glb_prim_named(b, name);

	CHECK(pa && pb);
	CHECK(glb_same_accessor(a, get_int(get(pa, "attributes"), "POSITION"), b,
				get_int(get(pb, "attributes"), "POSITION")));
	CHECK(glb_same_accessor(a, get_int(get(pa, "attributes"), "NORMAL"), b,
				get_int(get(pb, "attributes"), "NORMAL")));
	CHECK(glb_same_accessor(a, get_int(pa, "indices"), b, get_int(pb, "indices")));
	CHECK(!strcmp(get_str(material_of(a, pa), "name"), get_str(material_of(b, pb), "name")));
}

/* Spring's and autumn's vine leaves: every vertex the palette's first colour. */
static void check_vine_leaf_colors(const struct glb *g, struct json_object *prim, enum season s)
{
	const struct season_rgb *pal;
	const unsigned char *rgba;
	unsigned char want[4];
	size_t len;

	CHECK(season_palette(s, &pal) > 1);
	want[0] = (unsigned char)(pal[0].r * 255.0 + 0.5);
	want[1] = (unsigned char)(pal[0].g * 255.0 + 0.5);
	want[2] = (unsigned char)(pal[0].b * 255.0 + 0.5);
	want[3] = 255;
	rgba = glb_accessor_bytes(g, get_int(get(prim, "attributes"), "COLOR_0"), &len);
	CHECK_INT(len, 4 * get_int(at(get(g->json, "accessors"),
				      (size_t)get_int(get(prim, "attributes"), "POSITION")),
				   "count"));
	for (size_t i = 0; i < len; i += 4)
		CHECK(!memcmp(rgba + i, want, 4));
	CHECK(!strcmp(get_str(material_of(g, prim), "name"),
		      s == SEASON_SPRING ? "leaves-spring" : "leaves-autumn"));
}

static void check_vine_material(const struct glb *g, struct json_object *prim)
{
	struct json_object *mat = material_of(g, prim);
	struct json_object *color = get(get(mat, "pbrMetallicRoughness"), "baseColorFactor");
	const double want[4] = { 0.30, 0.45, 0.16, 1.0 };

	CHECK(!strcmp(get_str(mat, "name"), "vine"));
	CHECK(!json_object_object_get_ex(mat, "doubleSided", NULL));
	for (size_t c = 0; c < 4; c++)
		CHECK_NEAR(json_object_get_double(at(color, c)), want[c], 1e-9);
}

static void test_glb(enum season s)
{
	bool leaves = s != SEASON_WINTER;
	struct pair p;
	struct buf a, b, again;
	struct glb ga, gb;
	struct json_object *vine, *vleaves;

	pair_init(&p);
	set_season(&p, s);
	buf_init(&a);
	buf_init(&b);
	buf_init(&again);
	glb_of(&p.bare, &a);
	glb_of(&p.vines, &b);
	parse_glb(&a, &ga);
	parse_glb(&b, &gb);
	check_accessors(&gb);

	/* the tree's own parts as they were, then the vines' */
	CHECK_INT(json_object_array_length(glb_prims(&ga)), leaves ? 2 : 1);
	CHECK_INT(json_object_array_length(glb_prims(&gb)), leaves ? 4 : 2);
	check_same_prim(&ga, &gb, "bark");
	if (leaves)
		check_same_prim(&ga, &gb, "leaves");
	CHECK(!glb_prim_named(&ga, "vine") && !glb_prim_named(&ga, "vine-leaves"));
	vine = glb_prim_named(&gb, "vine");
	CHECK(vine);
	CHECK_INT(glb_prim_indices(&gb, vine), p.stem_indices);
	check_vine_material(&gb, vine);

	/* exactly the vines' triangles more; in winter no leaves at all */
	vleaves = glb_prim_named(&gb, "vine-leaves");
	CHECK(!vleaves == !leaves);
	CHECK_INT(glb_indices(&gb) - glb_indices(&ga),
		  p.stem_indices + (leaves ? p.leaf_indices : 0));
	CHECK_INT(count(gb.json, "materials"), leaves ? 3 : 2);
	if (vleaves) {
		CHECK_INT(glb_prim_indices(&gb, vleaves), p.leaf_indices);
		/* the tree's leaves' material, shared */
		CHECK_INT(get_int(vleaves, "material"), get_int(glb_prim_named(&gb, "leaves"), "material"));
		CHECK(json_object_get_boolean(get(material_of(&gb, vleaves), "doubleSided")));
		CHECK(json_object_object_get_ex(get(vleaves, "attributes"), "COLOR_0", NULL) ==
		      (s != SEASON_SUMMER));
		if (s != SEASON_SUMMER)
			check_vine_leaf_colors(&gb, vleaves, s);
	}

	/* same tree, same bytes */
	glb_of(&p.vines, &again);
	CHECK(again.len == b.len && !memcmp(again.data, b.data, b.len));

	json_object_put(ga.json);
	json_object_put(gb.json);
	buf_finish(&a);
	buf_finish(&b);
	buf_finish(&again);
	pair_finish(&p);
}

static void obj_of(const struct tree *t, struct buf *obj, struct buf *mtl)
{
	struct meshes m;

	meshes_build(&m, t);
	buf_reset(obj);
	buf_reset(mtl);
	CHECK_INT(export_obj(t, &m.tm, &m.mk, "tree.mtl", obj, mtl), 0);
	CHECK_INT(buf_append(obj, "", 1), 0);
	CHECK_INT(buf_append(mtl, "", 1), 0);
	obj->len--;
	mtl->len--;
	meshes_finish(&m);
}

static size_t lines_starting(const struct buf *b, const char *tag)
{
	size_t n = 0, len = strlen(tag);
	const char *text = (const char *)b->data;

	for (const char *l = text; l && *l; l = strchr(l, '\n'), l = l ? l + 1 : NULL)
		n += !strncmp(l, tag, len);
	return n;
}

/* Every face's vertex and normal numbers name lines that are there. */
static void check_faces(const struct buf *obj)
{
	size_t nv = lines_starting(obj, "v "), nn = lines_starting(obj, "vn ");
	const char *l = (const char *)obj->data;

	for (; l && *l; l = strchr(l, '\n'), l = l ? l + 1 : NULL) {
		unsigned long v[3], n[3];

		if (strncmp(l, "f ", 2))
			continue;
		CHECK_INT(sscanf(l, "f %lu//%lu %lu//%lu %lu//%lu", &v[0], &n[0], &v[1], &n[1], &v[2],
				 &n[2]),
			  6);
		for (int c = 0; c < 3; c++)
			CHECK(v[c] >= 1 && v[c] <= nv && n[c] >= 1 && n[c] <= nn);
	}
}

static void test_obj(enum season s)
{
	bool leaves = s != SEASON_WINTER;
	struct pair p;
	struct buf obj_a, mtl_a, obj_b, mtl_b, obj_c, mtl_c;
	char usemtl[64];
	const char *vl;

	pair_init(&p);
	set_season(&p, s);
	buf_init(&obj_a);
	buf_init(&mtl_a);
	buf_init(&obj_b);
	buf_init(&mtl_b);
	buf_init(&obj_c);
	buf_init(&mtl_c);
	obj_of(&p.bare, &obj_a, &mtl_a);
	obj_of(&p.vines, &obj_b, &mtl_b);

	/* the tree's OBJ as it was, then the vines */
	CHECK(obj_b.len > obj_a.len && !memcmp(obj_a.data, obj_b.data, obj_a.len));
	CHECK(!memcmp(obj_b.data + obj_a.len, "o vine\nusemtl vine\n", 19));
	check_faces(&obj_b);
	/* leaves have a front face and a back face each */
	CHECK_INT(lines_starting(&obj_b, "f ") - lines_starting(&obj_a, "f "),
		  (p.stem_indices + (leaves ? 2 * p.leaf_indices : 0)) / 3);
	vl = strstr((const char *)obj_b.data, "\no vine-leaves\n");
	CHECK(!vl == !leaves);
	if (s == SEASON_SUMMER)
		snprintf(usemtl, sizeof(usemtl), "usemtl leaves\n");
	else
		snprintf(usemtl, sizeof(usemtl), "usemtl leaves-%s-0\n", season_name(s));
	if (vl) {
		/* the vines' leaves: their vertices and normals, then one material */
		const char *use = strstr(vl, "\nusemtl ");

		CHECK(use && !strncmp(use + 1, usemtl, strlen(usemtl)));
		CHECK(!strstr(use + 1, "\nusemtl "));
		CHECK(!strstr(use + 1, "\no "));
	}

	/* the MTL: the tree's materials (in spring and autumn the vines' leaves' palette entry
	 * among them), then the vine's */
	if (s == SEASON_SUMMER || s == SEASON_WINTER)
		CHECK(mtl_b.len > mtl_a.len && !memcmp(mtl_a.data, mtl_b.data, mtl_a.len));
	else
		CHECK(strstr((const char *)mtl_b.data, usemtl + strlen("usemtl ")));
	CHECK(strstr((const char *)mtl_b.data, "\nnewmtl vine\nKa 0.000000 0.000000 0.000000\n"
					      "Kd 0.300000 0.450000 0.160000\n"));
	CHECK(!strstr((const char *)mtl_b.data, "newmtl leaves") == !leaves);

	/* same tree, same bytes */
	obj_of(&p.vines, &obj_c, &mtl_c);
	CHECK(obj_c.len == obj_b.len && !memcmp(obj_c.data, obj_b.data, obj_b.len));
	CHECK(mtl_c.len == mtl_b.len && !memcmp(mtl_c.data, mtl_b.data, mtl_b.len));

	buf_finish(&obj_a);
	buf_finish(&mtl_a);
	buf_finish(&obj_b);
	buf_finish(&mtl_b);
	buf_finish(&obj_c);
	buf_finish(&mtl_c);
	pair_finish(&p);
}

int main(void)
{
	static const enum season seasons[] = { SEASON_SUMMER, SEASON_SPRING, SEASON_AUTUMN,
					       SEASON_WINTER };

	test_skeleton();
	for (size_t i = 0; i < sizeof(seasons) / sizeof(*seasons); i++) {
		test_glb(seasons[i]);
		test_obj(seasons[i]);
	}
	return 0;
}
