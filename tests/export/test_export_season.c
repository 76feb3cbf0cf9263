/* SPDX-License-Identifier: MIT */
/*
 * Exports in every season (export.h): spring's and autumn's leaves each in its leaf's
 * palette entry (glTF COLOR_0, OBJ materials), summer's as before seasons whatever the
 * marks, winter without leaves; the bark, the leaves' geometry and the skeleton's elements
 * the same in every season; marks that do not describe the mesh give the palette's first
 * colour, nothing worse.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <json-c/json.h>

#include "buf.h"
#include "export.h"
#include "export_text.h"
#include "glb_read.h"
#include "leaf_colors.h"
#include "mesh.h"
#include "season.h"
#include "synth_tree.h"
#include "test.h"
#include "tree.h"

static const enum season all_seasons[] = { SEASON_SPRING, SEASON_SUMMER, SEASON_AUTUMN,
					   SEASON_WINTER };
#define NSEASONS (sizeof(all_seasons) / sizeof(*all_seasons))

/* One season's files. */
struct files {
	struct buf glb, obj, mtl, skel;
};

static void files_init(struct files *f)
{
	buf_init(&f->glb);
	buf_init(&f->obj);
	buf_init(&f->mtl);
	buf_init(&f->skel);
}

static void files_finish(struct files *f)
{
	buf_finish(&f->glb);
	buf_finish(&f->obj);
	buf_finish(&f->mtl);
	buf_finish(&f->skel);
}

/* The exports of t in season s; the OBJ and MTL NUL-terminated (not counted in len). */
static void export_in(struct tree *t, enum season s, const struct tree_mesh *tm,
		      const struct tree_mesh_marks *mk, struct files *f)
{
	enum season was = t->season;

	t->season = s;
	CHECK_INT(export_glb(t, tm, mk, &f->glb), 0);
	CHECK_INT(export_obj(t, tm, mk, "tree.mtl", &f->obj, &f->mtl), 0);
	CHECK_INT(export_skeleton(t, &f->skel), 0);
	CHECK_INT(buf_append(&f->obj, "", 1), 0);
	CHECK_INT(buf_append(&f->mtl, "", 1), 0);
	CHECK_INT(buf_append(&f->skel, "", 1), 0);
	f->obj.len--;
	f->mtl.len--;
	f->skel.len--;
	t->season = was;
}

static int same_buf(const struct buf *a, const struct buf *b)
{
	return a->len == b->len && !memcmp(a->data, b->data, a->len);
}

/* What a palette colour becomes in COLOR_0: the nearest byte, worked out apart from the
 * exporter. */
static unsigned char byte_of(float c)
{
	long v = lround((double)c * 255.0);

	return (unsigned char)(v < 0 ? 0 : v > 255 ? 255 : v);
}

/* The leaf whose part of the leaves mesh holds vertex v (marks known). */
static size_t leaf_of_vertex(const struct tree_mesh_marks *mk, size_t nleaves, size_t v)
{
	size_t lo = 0, hi = nleaves;

	while (hi - lo > 1) {
		size_t mid = (lo + hi) / 2;

		if (mk->leaves[mid].nvertices <= v)
			lo = mid;
		else
			hi = mid;
	}
	CHECK(mk->leaves[lo].nvertices <= v && v < mk->leaves[lo + 1].nvertices);
	return lo;
}

/* ---- glTF ---- */

static int64_t attr(struct json_object *prim, const char *name)
{
	struct json_object *v;

	if (!json_object_object_get_ex(get(prim, "attributes"), name, &v))
		return -1;
	return json_object_get_int64(v);
}

/* The bark in g is summer's bark: its three accessors and its material. */
static void check_glb_bark(const struct glb *g, const struct glb *summer)
{
	struct json_object *p = glb_prim_of(g, "bark"), *ps = glb_prim_of(summer, "bark");
	struct json_object *mats = get(g->json, "materials"), *mats_s = get(summer->json, "materials");

	CHECK(p && ps);
	CHECK(glb_same_accessor(g, attr(p, "POSITION"), summer, attr(ps, "POSITION")));
	CHECK(glb_same_accessor(g, attr(p, "NORMAL"), summer, attr(ps, "NORMAL")));
	CHECK(glb_same_accessor(g, get_int(p, "indices"), summer, get_int(ps, "indices")));
	CHECK(json_object_equal(at(mats, (size_t)get_int(p, "material")),
				at(mats_s, (size_t)get_int(ps, "material"))));
	/* the bark comes first in the BIN chunk, so its bytes are the same bytes */
	CHECK_INT(get_int(at(get(g->json, "bufferViews"), 0), "byteOffset"), 0);
}

/* Spring's or autumn's leaves: summer's geometry, COLOR_0 each vertex its leaf's entry. */
static void check_glb_colored(const struct glb *g, const struct glb *summer, const struct tree *t,
			      const struct tree_mesh *tm, const struct tree_mesh_marks *mk,
			      bool marks_known)
{
	const struct season_rgb *pal;
	size_t npal = season_palette(t->season, &pal), len, nv = tm->leaves.nvertices;
	char name[32];
	struct json_object *p, *ps = glb_prim_of(summer, "leaves"), *mat, *factor, *acc;
	const unsigned char *rgba;
	float *want = malloc(3 * nv * sizeof(*want));
	bool seen[SEASON_MAX_COLORS] = { false };
	size_t nseen = 0;

	snprintf(name, sizeof(name), "leaves-%s", season_name(t->season));
	p = glb_prim_of(g, name);
	CHECK(p && ps && want);
	CHECK_INT(json_object_object_length(get(p, "attributes")), 3);
	CHECK(glb_same_accessor(g, attr(p, "POSITION"), summer, attr(ps, "POSITION")));
	CHECK(glb_same_accessor(g, attr(p, "NORMAL"), summer, attr(ps, "NORMAL")));
	CHECK(glb_same_accessor(g, get_int(p, "indices"), summer, get_int(ps, "indices")));

	/* white, so that the colour is the vertex colour; double-sided like summer's */
	mat = at(get(g->json, "materials"), (size_t)get_int(p, "material"));
	factor = get(get(mat, "pbrMetallicRoughness"), "baseColorFactor");
	for (size_t c = 0; c < 4; c++)
		CHECK(json_object_get_double(at(factor, c)) == 1.0);
	CHECK(json_object_get_boolean(get(mat, "doubleSided")));

	acc = at(get(g->json, "accessors"), (size_t)attr(p, "COLOR_0"));
	CHECK_INT(get_int(acc, "componentType"), 5121);
	CHECK(json_object_get_boolean(get(acc, "normalized")));
	CHECK(!strcmp(get_str(acc, "type"), "VEC4"));
	CHECK_INT(get_int(acc, "count"), nv);
	rgba = glb_accessor_bytes(g, attr(p, "COLOR_0"), &len);
	CHECK_INT(len, 4 * nv);

	/* The renderer's colours (leaf_colors_fill), to the nearest byte; but for marks that
	 * count the leaves right and are wrong inside, which the app never makes: the
	 * exporters then take them for unknown (so the OBJ and glTF agree), the renderer
	 * paints what it can. */
	CHECK(leaf_colors_fill(t, mk, nv, want));
	for (size_t v = 0; v < nv; v++) {
		const unsigned char *c = rgba + 4 * v;
		size_t k = 0;

		if (marks_known || !mk || mk->nleaves != t->nleaves + 1) {
			CHECK_INT(c[0], byte_of(want[3 * v]));
			CHECK_INT(c[1], byte_of(want[3 * v + 1]));
			CHECK_INT(c[2], byte_of(want[3 * v + 2]));
		}
		CHECK_INT(c[3], 255);
		/* exactly its leaf's entry (or the first, marks unknown) */
		if (marks_known)
			k = season_leaf_color(t->season,
					      &t->leaves[leaf_of_vertex(mk, t->nleaves, v)]);
		CHECK_INT(c[0], byte_of(pal[k].r));
		CHECK_INT(c[1], byte_of(pal[k].g));
		CHECK_INT(c[2], byte_of(pal[k].b));
		nseen += !seen[k];
		seen[k] = true;
	}
	/* enough leaves for every shade */
	CHECK_INT(nseen, marks_known ? npal : 1);
	free(want);
}

static void check_glb(const struct buf *b, const struct buf *summer_b, const struct tree *t,
		      const struct tree_mesh *tm, const struct tree_mesh_marks *mk, bool marks_known)
{
	struct glb g, summer;
	struct json_object *ps;

	parse_glb(b, &g);
	parse_glb(summer_b, &summer);
	check_accessors(&g);
	check_glb_bark(&g, &summer);
	ps = glb_prim_of(&summer, "leaves");
	CHECK(ps);
	CHECK_INT(attr(ps, "COLOR_0"), -1);
	switch (t->season) {
	case SEASON_SUMMER:
		CHECK(same_buf(b, summer_b));
		break;
	case SEASON_WINTER: {
		/* bare: the bark alone, nothing of the leaves */
		size_t len;

		CHECK_INT(json_object_array_length(get(at(get(g.json, "meshes"), 0), "primitives")), 1);
		CHECK_INT(count(g.json, "materials"), 1);
		CHECK_INT(count(g.json, "accessors"), 3);
		CHECK_INT(count(g.json, "bufferViews"), 3);
		glb_accessor_bytes(&g, 2, &len);
		CHECK_INT(g.bin_len, get_int(at(get(g.json, "bufferViews"), 2), "byteOffset") + len);
		CHECK(!strstr(json_object_to_json_string(g.json), "leaves"));
		break;
	}
	case SEASON_SPRING:
	case SEASON_AUTUMN:
	case SEASON_COUNT:
		check_glb_colored(&g, &summer, t, tm, mk, marks_known);
		break;
	}
	json_object_put(g.json);
	json_object_put(summer.json);
}

/* ---- OBJ and MTL ---- */

/*
 * Spring's and autumn's leaf faces: each under the material of its leaf's palette entry,
 * the entry's group once, every triangle of every leaf once in front and once behind,
 * the same faces as summer's.
 */
static void check_obj_colored_faces(const char *leaves, const char *summer_leaves,
				    const struct tree *t, const struct tree_mesh *tm,
				    const struct tree_mesh_marks *mk, bool marks_known)
{
	size_t nb = tm->bark.nvertices, nv = tm->leaves.nvertices, nl = t->nleaves;
	size_t *front = calloc(nl + 1, sizeof(*front)), *back = calloc(nl + 1, sizeof(*back));
	char prefix[32], *faces = lines_of(leaves, "f"), *summer_faces = lines_of(summer_leaves, "f");
	char *a = sorted_lines(faces), *b = sorted_lines(summer_faces);
	bool group_seen[SEASON_MAX_COLORS] = { false };
	long cur = -1;

	CHECK(front && back);
	CHECK(!strcmp(a, b));
	snprintf(prefix, sizeof(prefix), "leaves-%s-", season_name(t->season));
	for (const char *l = leaves; *l; l = strchr(l, '\n') + 1) {
		if (!strncmp(l, "usemtl ", 7)) {
			CHECK(!strncmp(l + 7, prefix, strlen(prefix)));
			cur = strtol(l + 7 + strlen(prefix), NULL, 10);
			CHECK(cur >= 0 && cur < SEASON_MAX_COLORS && !group_seen[cur]);
			group_seen[cur] = true;
		} else if (!strncmp(l, "f ", 2)) {
			unsigned long v[3], n[3];
			size_t leaf = 0;

			CHECK(sscanf(l, "f %lu//%lu %lu//%lu %lu//%lu", &v[0], &n[0], &v[1], &n[1],
				     &v[2], &n[2]) == 6);
			CHECK(cur >= 0);
			for (int c = 0; c < 3; c++) {
				size_t lv = v[c] - 1 - nb, ln = n[c] - 1 - nb;
				bool is_back = ln >= nv;

				CHECK(v[c] > nb && lv < nv && n[c] > nb && ln < 2 * nv);
				/* a vertex's normal is its own, behind or in front */
				CHECK_INT(ln - (is_back ? nv : 0), lv);
				if (!marks_known)
					continue;
				if (c == 0)
					leaf = leaf_of_vertex(mk, nl, lv);
				CHECK_INT(leaf_of_vertex(mk, nl, lv), leaf);
			}
			CHECK_INT(cur, marks_known ? season_leaf_color(t->season, &t->leaves[leaf]) : 0);
			if (n[0] - 1 - nb >= nv)
				back[leaf]++;
			else
				front[leaf]++;
		} else {
			CHECK(!strncmp(l, "v ", 2) || !strncmp(l, "vn ", 3) || !strncmp(l, "o ", 2));
		}
	}
	for (size_t i = 0; marks_known && i < nl; i++) {
		size_t ntri = (mk->leaves[i + 1].nindices - mk->leaves[i].nindices) / 3;

		CHECK_INT(front[i], ntri);
		CHECK_INT(back[i], ntri);
	}
	if (!marks_known) {
		CHECK_INT(front[0], tm->leaves.nindices / 3);
		CHECK_INT(back[0], tm->leaves.nindices / 3);
	}
	free(front);
	free(back);
	free(faces);
	free(summer_faces);
	free(a);
	free(b);
}

/* The MTL's leaves: summer's one green, or one material a palette entry used (its Kd). */
static void check_mtl(const struct buf *mtl, const struct buf *summer_mtl, const struct tree *t,
		      const bool used[SEASON_MAX_COLORS])
{
	const char *text = (const char *)mtl->data;
	const char *leaves_at = strstr((const char *)summer_mtl->data, "\n\nnewmtl leaves\n");
	size_t bark_len = (size_t)(leaves_at - (const char *)summer_mtl->data) + 1;
	const struct season_rgb *pal;
	size_t npal = season_palette(t->season, &pal), nmat = 0;

	/* the header and the bark as in summer */
	CHECK(leaves_at);
	CHECK(mtl->len >= bark_len && !memcmp(text, summer_mtl->data, bark_len));
	for (const char *l = strstr(text, "newmtl "); l; l = strstr(l + 1, "newmtl "))
		nmat++;
	if (t->season == SEASON_WINTER) {
		CHECK_INT(mtl->len, bark_len);
		return;
	}
	for (size_t k = 0; k < npal; k++) {
		char name[64];
		const char *m;
		double kd[3];

		snprintf(name, sizeof(name), "\nnewmtl leaves-%s-%zu\n", season_name(t->season), k);
		m = strstr(text, name);
		CHECK((m != NULL) == used[k]);
		if (!m)
			continue;
		m = strstr(m + 1, "\nKd ");
		CHECK(m && sscanf(m, "\nKd %lf %lf %lf", &kd[0], &kd[1], &kd[2]) == 3);
		CHECK_NEAR(kd[0], pal[k].r, 5e-7);
		CHECK_NEAR(kd[1], pal[k].g, 5e-7);
		CHECK_NEAR(kd[2], pal[k].b, 5e-7);
		nmat--;
	}
	CHECK_INT(nmat, 1); /* and the bark */
}

static void check_obj(const struct files *f, const struct files *summer, const struct tree *t,
		      const struct tree_mesh *tm, const struct tree_mesh_marks *mk, bool marks_known)
{
	char *bark = section(&f->obj, "o bark", "o "), *summer_bark = section(&summer->obj, "o bark", "o ");
	char *leaves = section(&f->obj, "o leaves", "o ");
	char *summer_leaves = section(&summer->obj, "o leaves", "o ");
	bool used[SEASON_MAX_COLORS] = { false };

	CHECK(bark && summer_bark && summer_leaves);
	CHECK(!strcmp(bark, summer_bark));
	/* the header too: the OBJ up to its bark is summer's */
	CHECK(!memcmp(f->obj.data, summer->obj.data, (size_t)(strstr((char *)summer->obj.data,
								      "\no bark\n") - (char *)summer->obj.data)));
	if (t->season == SEASON_SUMMER) {
		CHECK(same_buf(&f->obj, &summer->obj) && same_buf(&f->mtl, &summer->mtl));
	} else if (t->season == SEASON_WINTER) {
		/* summer's OBJ cut before its leaves */
		CHECK(!leaves);
		CHECK_INT(f->obj.len, strstr((char *)summer->obj.data, "\no leaves\n") + 1 -
					      (char *)summer->obj.data);
		CHECK(!memcmp(f->obj.data, summer->obj.data, f->obj.len));
	} else {
		char *v = lines_of(leaves, "v"), *sv = lines_of(summer_leaves, "v");
		char *vn = lines_of(leaves, "vn"), *svn = lines_of(summer_leaves, "vn");

		CHECK(leaves);
		CHECK(!strcmp(v, sv) && !strcmp(vn, svn));
		check_obj_colored_faces(leaves, summer_leaves, t, tm, mk, marks_known);
		for (size_t i = 0; i < (marks_known ? t->nleaves : 1); i++)
			used[marks_known ? season_leaf_color(t->season, &t->leaves[i]) : 0] = true;
		free(v);
		free(sv);
		free(vn);
		free(svn);
	}
	if (t->season != SEASON_SUMMER)
		check_mtl(&f->mtl, &summer->mtl, t, used);
	free(bark);
	free(summer_bark);
	free(leaves);
	free(summer_leaves);
}

/* ---- the tests ---- */

static void check_season(struct tree *t, enum season s, const struct tree_mesh *tm,
			 const struct tree_mesh_marks *mk, bool marks_known, const struct files *summer)
{
	struct files f;
	enum season was = t->season;

	files_init(&f);
	export_in(t, s, tm, mk, &f);
	t->season = s;
	check_glb(&f.glb, &summer->glb, t, tm, mk, marks_known);
	check_obj(&f, summer, t, tm, mk, marks_known);
	check_skeleton_season(&f.skel, &summer->skel, s);
	t->season = was;
	files_finish(&f);
}

/* A tree of 160 leaves, its meshes and their marks, in every season. */
static void test_seasons(void)
{
	struct tree t;
	struct tree_mesh tm;
	struct tree_mesh_marks mk;
	struct files summer, summer_unmarked;

	tree_init(&t);
	tree_mesh_init(&tm);
	tree_mesh_marks_init(&mk);
	files_init(&summer);
	files_init(&summer_unmarked);
	CHECK_INT(synth_tree(&t, 40, 4, 14), 0);
	CHECK_INT(tree_mesh_build_marked(&tm, &t, &mk), 0);
	CHECK_INT(mk.nleaves, t.nleaves + 1);
	CHECK(t.nleaves >= 100 && tm.leaves.nindices > 0 && tm.bark.nindices > 0);

	/* summer never looks at the marks */
	export_in(&t, SEASON_SUMMER, &tm, &mk, &summer);
	export_in(&t, SEASON_SUMMER, &tm, NULL, &summer_unmarked);
	CHECK(same_buf(&summer.glb, &summer_unmarked.glb));
	CHECK(same_buf(&summer.obj, &summer_unmarked.obj));
	CHECK(same_buf(&summer.mtl, &summer_unmarked.mtl));

	for (size_t i = 0; i < NSEASONS; i++)
		check_season(&t, all_seasons[i], &tm, &mk, true, &summer);
	/* no marks: every leaf the palette's first colour */
	for (size_t i = 0; i < NSEASONS; i++)
		check_season(&t, all_seasons[i], &tm, NULL, false, &summer);

	files_finish(&summer);
	files_finish(&summer_unmarked);
	tree_mesh_marks_finish(&mk);
	tree_mesh_finish(&tm);
	tree_finish(&t);
}

/*
 * Marks that do not describe the meshes: unknown (after an allocation failure), of the
 * tree before its last leaf, with a leaf's part running backwards, or cutting a
 * triangle. Spring's leaves all take the first blossom colour; no crash, same geometry.
 */
static void test_marks_not_describing(void)
{
	struct tree t;
	struct tree_mesh tm;
	struct tree_mesh_marks mk, bad;
	struct files summer;

	tree_init(&t);
	tree_mesh_init(&tm);
	tree_mesh_marks_init(&mk);
	tree_mesh_marks_init(&bad);
	files_init(&summer);
	CHECK_INT(synth_tree(&t, 12, 3, 5), 0);
	CHECK_INT(tree_mesh_build_marked(&tm, &t, &mk), 0);
	export_in(&t, SEASON_SUMMER, &tm, &mk, &summer);

	/* unknown */
	check_season(&t, SEASON_SPRING, &tm, &bad, false, &summer);
	check_season(&t, SEASON_AUTUMN, &tm, &bad, false, &summer);

	/* another tree's: this one before its last leaf */
	t.nleaves--;
	CHECK_INT(tree_mesh_build_marked(&tm, &t, &bad), 0);
	t.nleaves++;
	CHECK_INT(tree_mesh_build(&tm, &t), 0);
	check_season(&t, SEASON_SPRING, &tm, &bad, false, &summer);

	/* a part running backwards, then one cutting a triangle */
	CHECK_INT(tree_mesh_build_marked(&tm, &t, &bad), 0);
	bad.leaves[2].nvertices = bad.leaves[3].nvertices + 1;
	check_season(&t, SEASON_AUTUMN, &tm, &bad, false, &summer);
	CHECK_INT(tree_mesh_build_marked(&tm, &t, &bad), 0);
	bad.leaves[2].nindices += 1;
	check_season(&t, SEASON_SPRING, &tm, &bad, false, &summer);
	/* and the good marks again give every leaf its own */
	check_season(&t, SEASON_SPRING, &tm, &mk, true, &summer);

	files_finish(&summer);
	tree_mesh_marks_finish(&bad);
	tree_mesh_marks_finish(&mk);
	tree_mesh_finish(&tm);
	tree_finish(&t);
}

/* No leaves: nothing of the leaves in spring either, summer's MTL as it always was. */
static void test_bare_tree(void)
{
	const struct vec3 p[] = { { 0, 0, 0 }, { 0.1, 2, 0 }, { 0.3, 4, 0.1 } };
	const double r[] = { 0.2, 0.15, 0.05 };
	struct tree t;
	struct tree_mesh tm;
	struct tree_mesh_marks mk;
	struct files spring, winter;

	tree_init(&t);
	tree_mesh_init(&tm);
	tree_mesh_marks_init(&mk);
	files_init(&spring);
	files_init(&winter);
	CHECK_INT(tree_add_branch(&t, -1, 0, ORIGIN_SKETCH, p, r, 3), 0);
	CHECK_INT(tree_mesh_build_marked(&tm, &t, &mk), 0);
	export_in(&t, SEASON_SPRING, &tm, &mk, &spring);
	export_in(&t, SEASON_WINTER, &tm, &mk, &winter);
	CHECK(same_buf(&spring.glb, &winter.glb));
	CHECK(same_buf(&spring.obj, &winter.obj));
	CHECK(same_buf(&spring.mtl, &winter.mtl));
	CHECK(!strstr((const char *)spring.mtl.data, "leaves"));
	files_finish(&spring);
	files_finish(&winter);
	tree_mesh_marks_finish(&mk);
	tree_mesh_finish(&tm);
	tree_finish(&t);
}

int main(void)
{
	test_seasons();
	test_marks_not_describing();
	test_bare_tree();
	return 0;
}
