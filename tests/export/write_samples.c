/* SPDX-License-Identifier: MIT */
/*
 * write_samples DIR: writes sample exports for external checkers (the Khronos glTF
 * validator, assimp): DIR/empty.glb, one-branch.glb, concave-leaf.glb, synth-500.glb,
 * plus synth-500.obj/.mtl and synth-500.skeleton.json, all in summer (summer.sha256 has
 * what they were before seasons); synth-500-SEASON.glb/.obj/.mtl for spring, autumn
 * and winter; a trunk with two vines (synth_vine_tree) in every season,
 * vines-SEASON.glb/.obj/.mtl; and a tree grown a press (synth_wood_tree: the wood's bark
 * beside the twigs' swept tubes) in summer and winter, wood-SEASON.glb/.obj/.mtl, with
 * wood.skeleton.json. Every NAME.glb also as NAME-wind.glb, with the tree's sway at the
 * default breeze (export_glb_wind: KHR_mesh_quantization's byte targets), and
 * synth-500-wind-floats.glb with float targets. Then today's forest (issue 27,
 * export_glb_forest): forest-3.glb and forest-40.glb still, forest-3-wind.glb and
 * forest-40-wind.glb with the wind over the common 8 s loop: 3 trees (500 branches'
 * little sister in summer, the vine tree in autumn, the grown tree in spring) and 40
 * synth_trees in every season, on a sunflower spiral. `write_samples DIR forest` writes
 * the forests alone (blender.sh). See validate_samples.sh.
 */
#include <errno.h>
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "buf.h"
#include "export.h"
#include "live.h"
#include "mesh.h"
#include "synth_tree.h"
#include "synth_vine.h"
#include "synth_wood.h"
#include "tree.h"
#include "wood.h"

static int write_file(const char *dir, const char *name, const struct buf *b)
{
	char path[4096];
	FILE *f;
	int ok;

	if (snprintf(path, sizeof(path), "%s/%s", dir, name) >= (int)sizeof(path))
		return -ENAMETOOLONG;
	f = fopen(path, "wb");
	if (!f) {
		fprintf(stderr, "write_samples: %s: %s\n", path, strerror(errno));
		return -errno;
	}
	ok = fwrite(b->data, 1, b->len, f) == b->len;
	ok = (fclose(f) == 0) && ok;
	if (!ok) {
		fprintf(stderr, "write_samples: %s: write failed\n", path);
		return -EIO;
	}
	printf("%s (%zu bytes)\n", path, b->len);
	return 0;
}

/* The meshes with their marks, as the app keeps them. */
static int build(struct tree_mesh *tm, struct tree_mesh_marks *mk, const struct tree *t)
{
	tree_mesh_init(tm);
	tree_mesh_marks_init(mk);
	return tree_mesh_build_marked(tm, t, mk);
}

static void unbuild(struct tree_mesh *tm, struct tree_mesh_marks *mk)
{
	tree_mesh_marks_finish(mk);
	tree_mesh_finish(tm);
}

/* NAME.glb, and NAME-wind.glb with the wind (plus NAME-wind-floats.glb if floats). */
static int write_glb_ex(const char *dir, const char *name, const struct tree *t, bool floats)
{
	struct export_wind ew = { .strength = 0.0, .angle = EXPORT_WIND_ANGLE, .seed = 1 };
	char wind_name[256];
	size_t len = strlen(name) - strlen(".glb");
	struct tree_mesh tm;
	struct tree_mesh_marks mk;
	struct buf b;
	int r;

	buf_init(&b);
	r = build(&tm, &mk, t);
	if (r >= 0)
		r = export_glb(t, &tm, &mk, &b);
	if (r >= 0)
		r = write_file(dir, name, &b);
	for (int f = 0; f <= (int)floats && r >= 0; f++) {
		ew.floats = f;
		snprintf(wind_name, sizeof(wind_name), "%.*s-wind%s.glb", (int)len, name,
			 f ? "-floats" : "");
		buf_reset(&b);
		r = export_glb_wind(t, &tm, &mk, &ew, &b);
		if (r >= 0)
			r = write_file(dir, wind_name, &b);
	}
	buf_finish(&b);
	unbuild(&tm, &mk);
	return r;
}

static int write_glb(const char *dir, const char *name, const struct tree *t)
{
	return write_glb_ex(dir, name, t, false);
}

/* NAME.obj and NAME.mtl */
static int write_obj(const char *dir, const char *name, const struct tree *t)
{
	char obj_name[256], mtl_name[256];
	struct tree_mesh tm;
	struct tree_mesh_marks mk;
	struct buf obj, mtl;
	int r;

	snprintf(obj_name, sizeof(obj_name), "%s.obj", name);
	snprintf(mtl_name, sizeof(mtl_name), "%s.mtl", name);
	buf_init(&obj);
	buf_init(&mtl);
	r = build(&tm, &mk, t);
	if (r >= 0)
		r = export_obj(t, &tm, &mk, mtl_name, &obj, &mtl);
	if (r >= 0)
		r = write_file(dir, obj_name, &obj);
	if (r >= 0)
		r = write_file(dir, mtl_name, &mtl);
	buf_finish(&obj);
	buf_finish(&mtl);
	unbuild(&tm, &mk);
	return r;
}

static int one_branch(struct tree *t)
{
	const struct vec3 p[] = { { 0, 0, 0 }, { 0.2, 1.5, 0 }, { 0.1, 3, 0 }, { -0.3, 4.2, 0 } };
	const double r[] = { 0.2, 0.16, 0.1, 0.04 };

	return tree_add_branch(t, -1, 0.0, ORIGIN_SKETCH, p, r, 4);
}

static int concave_leaf(struct tree *t)
{
	/* an arrow-shaped leaf at the branch tip, slightly bent out of its plane */
	const struct vec3 leaf[] = { { -0.3, 4.2, 0 },     { -0.2, 4.25, 0.01 }, { -0.1, 4.2, 0 },
				     { -0.18, 4.3, 0.005 }, { -0.15, 4.45, 0 },   { -0.22, 4.36, 0.01 },
				     { -0.3, 4.45, 0 },    { -0.26, 4.3, 0.005 } };
	int r = one_branch(t);

	return r < 0 ? r : tree_add_leaf(t, r, ORIGIN_SKETCH, leaf, 8);
}

static int synth_extras(const char *dir, const struct tree *t)
{
	struct buf skel;
	int r;

	buf_init(&skel);
	r = write_obj(dir, "synth-500", t);
	if (r >= 0)
		r = export_skeleton(t, &skel);
	if (r >= 0)
		r = write_file(dir, "synth-500.skeleton.json", &skel);
	buf_finish(&skel);
	return r;
}

/* The same tree in the seasons given, as BASE-SEASON.glb/.obj/.mtl. */
static int write_seasons(const char *dir, const char *base, struct tree *t,
			 const enum season *seasons, size_t n)
{
	int r = 0;

	for (size_t i = 0; i < n && r >= 0; i++) {
		char name[64];

		t->season = seasons[i];
		snprintf(name, sizeof(name), "%s-%s.glb", base, season_name(seasons[i]));
		r = write_glb(dir, name, t);
		snprintf(name, sizeof(name), "%s-%s", base, season_name(seasons[i]));
		if (r >= 0)
			r = write_obj(dir, name, t);
	}
	t->season = SEASON_SUMMER;
	return r;
}

/* The same tree in the other seasons. */
static int synth_seasons(const char *dir, struct tree *t)
{
	static const enum season seasons[] = { SEASON_SPRING, SEASON_AUTUMN, SEASON_WINTER };

	return write_seasons(dir, "synth-500", t, seasons, 3);
}

/* A trunk with two vines, in every season. */
static int vine_seasons(const char *dir, struct tree *t)
{
	static const enum season seasons[] = { SEASON_SUMMER, SEASON_SPRING, SEASON_AUTUMN,
					       SEASON_WINTER };
	int r = synth_vine_tree(t, 2);

	return r < 0 ? r : write_seasons(dir, "vines", t, seasons, 4);
}

/* A tree grown a press (broadleaf), with leaves and without (winter), and its skeleton. */
static int wood_seasons(const char *dir, struct tree *t)
{
	static const enum season seasons[] = { SEASON_SUMMER, SEASON_WINTER };
	struct buf skel;
	int r = synth_wood_tree(t, 1, WOOD_BROADLEAF);

	if (r >= 0)
		r = write_seasons(dir, "wood", t, seasons, 2);
	buf_init(&skel);
	if (r >= 0)
		r = export_skeleton(t, &skel);
	if (r >= 0)
		r = write_file(dir, "wood.skeleton.json", &skel);
	buf_finish(&skel);
	return r;
}

/* A forest's trees, built, and where they stand. */
struct forest {
	struct tree t[40];
	struct tree_mesh tm[40];
	struct tree_mesh_marks mk[40];
	struct export_forest_tree f[40];
	size_t n;
};

/* Tree k of the forest (its t[k] made) meshed and placed at slot k of a sunflower spiral,
 * `spacing` metres its scale, numbered `number`. */
static int forest_place(struct forest *fo, size_t k, double spacing, uint64_t number)
{
	const double golden = 2.399963229728653; /* radians: 137.5 degrees */
	double rad = spacing * sqrt((double)k + 0.5), a = golden * (double)k;
	int r = build(&fo->tm[k], &fo->mk[k], &fo->t[k]);

	fo->f[k] = (struct export_forest_tree){
		.tree = &fo->t[k], .mesh = &fo->tm[k], .marks = &fo->mk[k],
		.seed = 100 + number, .number = number,
		.position = { rad * cos(a), 0.0, rad * sin(a) },
	};
	fo->n = k + 1;
	return r;
}

static void forest_finish(struct forest *fo)
{
	for (size_t k = 0; k < fo->n; k++) {
		unbuild(&fo->tm[k], &fo->mk[k]);
		tree_finish(&fo->t[k]);
	}
	fo->n = 0;
}

/* NAME.glb still and NAME-wind.glb with the forest's wind over the common loop. */
static int write_forest(const char *dir, const char *name, const struct forest *fo)
{
	const struct export_wind ew = { .strength = 0.0, .angle = EXPORT_WIND_ANGLE };
	char file[256];
	struct buf b;
	int r;

	buf_init(&b);
	snprintf(file, sizeof(file), "%s.glb", name);
	r = export_glb_forest(fo->f, fo->n, NULL, 0.0, &b);
	if (r >= 0)
		r = write_file(dir, file, &b);
	buf_reset(&b);
	snprintf(file, sizeof(file), "%s-wind.glb", name);
	if (r >= 0)
		r = export_glb_forest(fo->f, fo->n, &ew, LIVE_WIND_COMMON_LOOP_S, &b);
	if (r >= 0)
		r = write_file(dir, file, &b);
	buf_finish(&b);
	return r;
}

/* forest-3 and forest-40, still and with the wind. */
static int forests(const char *dir)
{
	static const enum season seasons[] = { SEASON_SUMMER, SEASON_AUTUMN, SEASON_SPRING,
					       SEASON_WINTER };
	struct forest *fo = calloc(1, sizeof(*fo));
	int r = fo ? 0 : -ENOMEM;

	/* three kinds: 60 branches in summer, the vine tree in autumn, the grown tree in
	 * spring, numbered as a day's 3rd, 5th and 6th */
	for (size_t k = 0; k < 3 && r >= 0; k++) {
		tree_init(&fo->t[k]);
		r = k == 0 ? synth_tree(&fo->t[k], 60, 4, 3)
		    : k == 1 ? synth_vine_tree(&fo->t[k], 2)
			     : synth_wood_tree(&fo->t[k], 1, WOOD_BROADLEAF);
		fo->t[k].season = seasons[k];
		if (r >= 0)
			r = forest_place(fo, k, 3.0, k == 0 ? 3 : k + 4);
	}
	if (r >= 0)
		r = write_forest(dir, "forest-3", fo);
	if (fo)
		forest_finish(fo);
	for (size_t k = 0; k < 40 && r >= 0; k++) {
		tree_init(&fo->t[k]);
		r = synth_tree(&fo->t[k], 5 + (int)(k * 7 % 40), (int)(k % 4), 200 + k);
		fo->t[k].season = seasons[k % 4];
		if (r >= 0)
			r = forest_place(fo, k, 4.0, 11 + k);
	}
	if (r >= 0)
		r = write_forest(dir, "forest-40", fo);
	if (fo)
		forest_finish(fo);
	free(fo);
	return r;
}

int main(int argc, char **argv)
{
	struct tree t;
	int r;

	if (argc == 3 && !strcmp(argv[2], "forest")) {
		r = forests(argv[1]);
		if (r < 0)
			fprintf(stderr, "write_samples: %s\n", strerror(-r));
		return r < 0;
	}
	if (argc != 2) {
		fprintf(stderr, "usage: write_samples DIR [forest]\n");
		return 2;
	}
	tree_init(&t);
	r = write_glb(argv[1], "empty.glb", &t);
	if (r >= 0)
		r = one_branch(&t);
	if (r >= 0)
		r = write_glb(argv[1], "one-branch.glb", &t);
	tree_clear(&t);
	if (r >= 0)
		r = concave_leaf(&t);
	if (r >= 0)
		r = write_glb(argv[1], "concave-leaf.glb", &t);
	if (r >= 0)
		r = synth_tree(&t, 500, 10, 1);
	if (r >= 0)
		r = write_glb_ex(argv[1], "synth-500.glb", &t, true);
	if (r >= 0)
		r = synth_extras(argv[1], &t);
	if (r >= 0)
		r = synth_seasons(argv[1], &t);
	if (r >= 0)
		r = vine_seasons(argv[1], &t);
	if (r >= 0)
		r = wood_seasons(argv[1], &t);
	if (r >= 0)
		r = forests(argv[1]);
	tree_finish(&t);
	if (r < 0) {
		fprintf(stderr, "write_samples: %s\n", strerror(-r));
		return 1;
	}
	return 0;
}
