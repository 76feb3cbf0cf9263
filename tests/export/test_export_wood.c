/* SPDX-License-Identifier: MIT */
/*
 * A tree's grown wood in its exports (issue 17): a trunk with a limb and two twigs
 * (synth_wood_tree), grown a press. The glb and the obj hold the wood's bark ("wood", in
 * the bark's material) after the swept bark, exactly the wood's triangles, and the swept
 * tubes of the voxelised branches are gone: against the same tree's meshes built as if it
 * had no wood, they have the wood's triangles more and those tubes' triangles fewer; the
 * twigs' tubes are what they were. The same tree without its wood has no "wood" anywhere.
 * skeleton.json's "wood" object reads back with json-c. Same tree, same bytes. The Khronos
 * validator reads the grown tree's glb too (write_samples' wood-SEASON.glb).
 */
#include <stdio.h>
#include <string.h>

#include <json-c/json.h>

#include "buf.h"
#include "export.h"
#include "glb_read.h"
#include "mesh.h"
#include "season.h"
#include "synth_wood.h"
#include "test.h"
#include "tree.h"
#include "wood.h"

/* The grown tree's meshes as the app keeps them, and as they would be without its wood. */
struct grown {
	struct tree t;
	struct tree_mesh tm, plain;
	struct tree_mesh_marks mk, plain_mk;
	size_t swept; /* indices of the voxelised branches' swept tubes, in plain */
};

static void build(struct tree_mesh *tm, struct tree_mesh_marks *mk, const struct tree *t)
{
	tree_mesh_init(tm);
	tree_mesh_marks_init(mk);
	CHECK_INT(tree_mesh_build_marked(tm, t, mk), 0);
	CHECK_INT(mk->nbark, t->nbranches + 1);
}

/* The indices of branch i's part of tm's bark. */
static size_t part(const struct tree_mesh_marks *mk, size_t i)
{
	return mk->bark[i + 1].nindices - mk->bark[i].nindices;
}

/* The same twig's part in both meshes: the same bytes. */
static void check_same_part(const struct grown *g, size_t i)
{
	const struct tree_mesh_mark *a = g->mk.bark, *b = g->plain_mk.bark;
	size_t nv = a[i + 1].nvertices - a[i].nvertices;

	CHECK_INT(nv, b[i + 1].nvertices - b[i].nvertices);
	CHECK_INT(part(&g->mk, i), part(&g->plain_mk, i));
	CHECK(!memcmp(g->tm.bark.positions + 3 * a[i].nvertices,
		      g->plain.bark.positions + 3 * b[i].nvertices, 3 * nv * sizeof(float)));
}

static void grown_init(struct grown *g, int presses, enum wood_mode mode)
{
	struct wood *w;

	tree_init(&g->t);
	CHECK_INT(synth_wood_tree(&g->t, presses, mode), 0);
	CHECK(g->t.wood && g->t.wood->presses == presses);
	CHECK(g->t.wood->bark.nindices > 1000);
	/* the trunk and the limb are wood, the twigs not */
	CHECK_INT(g->t.nbranches, SYNTH_WOOD_BRANCHES);
	CHECK(tree_branch_in_wood(&g->t, 0) && tree_branch_in_wood(&g->t, 1));
	CHECK(!tree_branch_in_wood(&g->t, 2) && !tree_branch_in_wood(&g->t, 3));
	build(&g->tm, &g->mk, &g->t);
	w = g->t.wood;
	g->t.wood = NULL;
	build(&g->plain, &g->plain_mk, &g->t);
	g->t.wood = w;

	/* the app's mesh has empty parts for the wood's branches, the twigs' as they were */
	g->swept = part(&g->plain_mk, 0) + part(&g->plain_mk, 1);
	CHECK(g->swept > 100);
	CHECK_INT(part(&g->mk, 0) + part(&g->mk, 1), 0);
	CHECK_INT(g->plain.bark.nindices - g->tm.bark.nindices, g->swept);
	check_same_part(g, 2);
	check_same_part(g, 3);
	CHECK(g->tm.bark.nindices > 0);
	CHECK(g->tm.leaves.nindices > 0);
	printf("%d press(es): wood %zu triangles; swept tubes left out %zu, twigs' %zu\n",
	       presses, g->t.wood->bark.nindices / 3, g->swept / 3, g->tm.bark.nindices / 3);
}

static void grown_finish(struct grown *g)
{
	tree_mesh_marks_finish(&g->mk);
	tree_mesh_marks_finish(&g->plain_mk);
	tree_mesh_finish(&g->tm);
	tree_mesh_finish(&g->plain);
	tree_finish(&g->t);
}

/* The tree's exports as if it had not been grown (its meshes with the swept tubes). */
#define WITHOUT_WOOD(g, call)                        \
	do {                                         \
		struct wood *kept_ = (g)->t.wood;    \
		(g)->t.wood = NULL;                  \
		call;                                \
		(g)->t.wood = kept_;                 \
	} while (0)

/* Accessor i holds exactly these 4-byte words (floats or indices), little-endian. */
static void check_words(const struct glb *g, int64_t i, const void *want, size_t n)
{
	size_t len;
	const unsigned char *p = glb_accessor_bytes(g, i, &len);

	CHECK_INT(len, 4 * n);
	for (size_t k = 0; k < n; k++) {
		uint32_t w;

		memcpy(&w, (const unsigned char *)want + 4 * k, 4);
		CHECK(u32(p + 4 * k) == w);
	}
}

static void glb_of(const struct tree *t, const struct tree_mesh *tm,
		   const struct tree_mesh_marks *mk, struct buf *b)
{
	buf_reset(b);
	CHECK_INT(export_glb(t, tm, mk, b), 0);
}

static void test_glb(enum season s)
{
	bool leaves = s != SEASON_WINTER;
	struct grown g;
	struct buf a, b, again;
	struct glb ga, gb;
	struct json_object *wood, *bark;
	const struct mesh *wb;
	struct tree t2;
	struct tree_mesh tm2;
	struct tree_mesh_marks mk2;

	grown_init(&g, 1, WOOD_BROADLEAF);
	g.t.season = s;
	wb = &g.t.wood->bark;
	buf_init(&a);
	buf_init(&b);
	buf_init(&again);
	WITHOUT_WOOD(&g, glb_of(&g.t, &g.plain, &g.plain_mk, &a));
	glb_of(&g.t, &g.tm, &g.mk, &b);
	parse_glb(&a, &ga);
	parse_glb(&b, &gb);
	check_accessors(&gb);

	/* without wood: no wood primitive */
	CHECK_INT(json_object_array_length(glb_prims(&ga)), leaves ? 2 : 1);
	CHECK(!glb_prim_named(&ga, "wood"));
	CHECK(!strstr((const char *)a.data + 20, "\"wood"));

	/* grown: bark (the twigs), wood, leaves; the wood in the bark's material */
	CHECK_INT(json_object_array_length(glb_prims(&gb)), leaves ? 3 : 2);
	bark = glb_prim_named(&gb, "bark");
	wood = glb_prim_named(&gb, "wood");
	CHECK(bark && wood);
	CHECK(at(glb_prims(&gb), 0) == bark && at(glb_prims(&gb), 1) == wood);
	CHECK_INT(get_int(wood, "material"), get_int(bark, "material"));
	CHECK_INT(count(gb.json, "materials"), leaves ? 2 : 1);
	CHECK_INT(glb_prim_indices(&gb, bark), g.tm.bark.nindices);
	CHECK_INT(glb_prim_indices(&gb, wood), wb->nindices);
	check_words(&gb, get_int(get(wood, "attributes"), "POSITION"), wb->positions,
		    3 * wb->nvertices);
	check_words(&gb, get_int(get(wood, "attributes"), "NORMAL"), wb->normals,
		    3 * wb->nvertices);
	check_words(&gb, get_int(wood, "indices"), wb->indices, wb->nindices);

	/* exactly the wood's triangles more, the voxelised branches' tubes fewer */
	CHECK_INT(glb_indices(&gb) - glb_indices(&ga), (int64_t)wb->nindices - (int64_t)g.swept);
	CHECK_INT(glb_indices(&gb), g.tm.bark.nindices + wb->nindices +
					    (leaves ? g.tm.leaves.nindices : 0));

	/* the same tree grown again: the same bytes */
	tree_init(&t2);
	CHECK_INT(synth_wood_tree(&t2, 1, WOOD_BROADLEAF), 0);
	t2.season = s;
	build(&tm2, &mk2, &t2);
	glb_of(&t2, &tm2, &mk2, &again);
	CHECK(again.len == b.len && !memcmp(again.data, b.data, b.len));
	tree_mesh_marks_finish(&mk2);
	tree_mesh_finish(&tm2);
	tree_finish(&t2);

	json_object_put(ga.json);
	json_object_put(gb.json);
	buf_finish(&a);
	buf_finish(&b);
	buf_finish(&again);
	grown_finish(&g);
}

/* ---- obj ---- */

static void obj_of(const struct tree *t, const struct tree_mesh *tm,
		   const struct tree_mesh_marks *mk, struct buf *obj, struct buf *mtl)
{
	buf_reset(obj);
	buf_reset(mtl);
	CHECK_INT(export_obj(t, tm, mk, "tree.mtl", obj, mtl), 0);
	CHECK_INT(buf_append(obj, "", 1), 0);
	CHECK_INT(buf_append(mtl, "", 1), 0);
	obj->len--;
	mtl->len--;
}

/* The line after l's, or NULL. */
static const char *next_line(const char *l)
{
	l = strchr(l, '\n');
	return l ? l + 1 : NULL;
}

/* Lines beginning with tag in [from, to) (to NULL: the end). */
static size_t lines_starting(const char *from, const char *to, const char *tag)
{
	size_t n = 0, len = strlen(tag);

	for (const char *l = from; l && *l && (!to || l < to); l = next_line(l))
		n += !strncmp(l, tag, len);
	return n;
}

/* Every face's vertex and normal numbers name lines that are there. */
static void check_faces(const char *text)
{
	size_t nv = lines_starting(text, NULL, "v "), nn = lines_starting(text, NULL, "vn ");

	for (const char *l = text; l && *l; l = next_line(l)) {
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
	struct grown g;
	struct buf obj_a, mtl_a, obj_b, mtl_b, obj_c, mtl_c;
	const char *text, *wood, *next;
	const struct mesh *wb;

	grown_init(&g, 1, WOOD_BROADLEAF);
	g.t.season = s;
	wb = &g.t.wood->bark;
	buf_init(&obj_a);
	buf_init(&mtl_a);
	buf_init(&obj_b);
	buf_init(&mtl_b);
	buf_init(&obj_c);
	buf_init(&mtl_c);
	WITHOUT_WOOD(&g, obj_of(&g.t, &g.plain, &g.plain_mk, &obj_a, &mtl_a));
	obj_of(&g.t, &g.tm, &g.mk, &obj_b, &mtl_b);
	text = (const char *)obj_b.data;

	/* without wood no wood object; with it, one after the bark, in the bark's material */
	CHECK(!strstr((const char *)obj_a.data, "\no wood\n"));
	wood = strstr(text, "\no wood\nusemtl bark\n");
	CHECK(wood && strstr(text, "\no bark\nusemtl bark\n") < wood);
	next = strstr(wood + 1, "\no ");
	CHECK(!next == !leaves);
	CHECK_INT(lines_starting(wood + 1, next, "f "), wb->nindices / 3);
	CHECK_INT(lines_starting(wood + 1, next, "v "), wb->nvertices);
	CHECK_INT(lines_starting(wood + 1, next, "vn "), wb->nvertices);
	CHECK_INT(lines_starting(wood + 1, next, "usemtl "), 1);
	check_faces(text);

	/* the wood's triangles more, the voxelised branches' tubes fewer */
	CHECK_INT((int64_t)lines_starting(text, NULL, "f ") -
			  (int64_t)lines_starting((const char *)obj_a.data, NULL, "f "),
		  ((int64_t)wb->nindices - (int64_t)g.swept) / 3);
	/* the bark's material serves both: the MTL is the same */
	CHECK(mtl_a.len == mtl_b.len && !memcmp(mtl_a.data, mtl_b.data, mtl_a.len));

	/* same tree, same bytes */
	obj_of(&g.t, &g.tm, &g.mk, &obj_c, &mtl_c);
	CHECK(obj_c.len == obj_b.len && !memcmp(obj_c.data, obj_b.data, obj_b.len));
	CHECK(mtl_c.len == mtl_b.len && !memcmp(mtl_c.data, mtl_b.data, mtl_b.len));

	buf_finish(&obj_a);
	buf_finish(&mtl_a);
	buf_finish(&obj_b);
	buf_finish(&mtl_b);
	buf_finish(&obj_c);
	buf_finish(&mtl_c);
	grown_finish(&g);
}

/* Each branch's radii are the tree's: the power law's, the wood's begin applied. */
static void check_radii(struct json_object *root, const struct tree *t)
{
	struct json_object *branches = get(root, "branches");

	CHECK_INT(json_object_array_length(branches), t->nbranches);
	for (size_t i = 0; i < t->nbranches; i++) {
		struct json_object *radii = get(at(branches, i), "radii");

		CHECK_INT(json_object_array_length(radii), t->branches[i].npoints);
		for (size_t k = 0; k < t->branches[i].npoints; k++)
			CHECK_NEAR(json_num(at(radii, k)), t->branches[i].radii[k], 5.0001e-7);
	}
}

static void check_wood(struct json_object *o, const struct wood *w, const char *mode)
{
	struct json_object *grid = get(o, "grid"), *origin = get(o, "origin");
	struct json_object *ids = get(o, "branches");

	CHECK_INT(json_object_object_length(o), 6);
	CHECK_INT(get_int(o, "presses"), w->presses);
	CHECK(!strcmp(get_str(o, "mode"), mode));
	CHECK_INT(json_object_array_length(grid), 3);
	CHECK_INT(json_object_get_int(at(grid, 0)), w->g.nx);
	CHECK_INT(json_object_get_int(at(grid, 1)), w->g.ny);
	CHECK_INT(json_object_get_int(at(grid, 2)), w->g.nz);
	CHECK(w->g.nx == 64 || w->g.ny == 64 || w->g.nz == 64);
	CHECK_NEAR(json_num(get(o, "voxel")), w->g.h, 5.0001e-7);
	CHECK_INT(json_object_array_length(origin), 3);
	CHECK_NEAR(json_num(at(origin, 0)), w->g.origin.x, 5.0001e-7);
	CHECK_NEAR(json_num(at(origin, 1)), w->g.origin.y, 5.0001e-7);
	CHECK_NEAR(json_num(at(origin, 2)), w->g.origin.z, 5.0001e-7);
	/* the trunk and the limb */
	CHECK_INT(json_object_array_length(ids), 2);
	CHECK_INT(json_object_get_int(at(ids, 0)), 0);
	CHECK_INT(json_object_get_int(at(ids, 1)), 1);
}

static void test_skeleton(int presses, enum wood_mode mode)
{
	const char *name = mode == WOOD_CONIFER ? "conifer" : "broadleaf";
	struct tree t, t2;
	struct buf a, b, again;
	struct json_object *bare, *root;

	tree_init(&t);
	tree_init(&t2);
	buf_init(&a);
	buf_init(&b);
	buf_init(&again);
	CHECK_INT(synth_wood_tree(&t, presses, mode), 0);

	/* without its wood: no "wood" key */
	{
		struct wood *w = t.wood;

		t.wood = NULL;
		CHECK_INT(export_skeleton(&t, &a), 0);
		t.wood = w;
	}
	bare = json_text(&a);
	CHECK(!json_object_object_get_ex(bare, "wood", NULL));
	check_radii(bare, &t);
	json_object_put(bare);

	/* with it: the same text up to the leaves, then the wood */
	CHECK_INT(export_skeleton(&t, &b), 0);
	root = json_text(&b);
	CHECK(b.len > a.len && !memcmp(a.data, b.data, a.len - 2)); /* a ends in "}\n" */
	CHECK(!memcmp(b.data + a.len - 2, ",\"wood\":{\"presses\":", 19));
	CHECK_INT(get_int(root, "version"), SKELETON_VERSION);
	check_radii(root, &t);
	check_wood(get(root, "wood"), t.wood, name);
	json_object_put(root);

	/* the same tree grown again: the same bytes */
	CHECK_INT(synth_wood_tree(&t2, presses, mode), 0);
	CHECK_INT(export_skeleton(&t2, &again), 0);
	CHECK(again.len == b.len && !memcmp(again.data, b.data, b.len));

	buf_finish(&a);
	buf_finish(&b);
	buf_finish(&again);
	tree_finish(&t);
	tree_finish(&t2);
}

int main(void)
{
	static const enum season seasons[] = { SEASON_SUMMER, SEASON_AUTUMN, SEASON_WINTER };

	test_skeleton(1, WOOD_BROADLEAF);
	test_skeleton(2, WOOD_CONIFER);
	for (size_t i = 0; i < sizeof(seasons) / sizeof(*seasons); i++) {
		test_glb(seasons[i]);
		test_obj(seasons[i]);
	}
	return 0;
}
