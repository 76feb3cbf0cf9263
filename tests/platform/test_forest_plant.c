/* SPDX-License-Identifier: MIT */
/*
 * Planting a drawing for today's forest (platform/forest_plant.c, docs/forest.md): every
 * drawing of the document fuzzer's corpus (a 2D sketch, 3D trees, generated, edited,
 * vined, undone, in every format version) planted twice gives the same tree and meshes;
 * each planted tree is 3D (a sketch lifted as the 3D button would), its meshes those of
 * its tree (tree_mesh_build_marked), its seed the drawing's; a drawing with no tree is
 * refused as having nothing to plant, a malformed one with its file and line, a missing
 * one with its name; a failed planting leaves nothing behind.
 *   test_forest_plant CORPUS_DIR MALFORMED_DIR
 */
#include <dirent.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "docfile.h"
#include "forest_plant.h"
#include "same.h"
#include "test.h"

static size_t planted, empty, refused;

static void plant_one(const char *path)
{
	struct forest_planted a, b;
	struct tree_mesh m;
	struct tree_mesh_marks mk;
	struct error err = { { 0 } };
	struct doc doc;
	int ret;

	forest_planted_init(&a);
	forest_planted_init(&b);
	ret = forest_plant(path, &a, &err);
	if (ret == -ENODATA) {
		CHECK(strstr(err.msg, path) && strstr(err.msg, "no tree"));
		CHECK(a.tree.nbranches == 0 && a.mesh.bark.nvertices == 0);
		empty++;
		forest_planted_finish(&a);
		forest_planted_finish(&b);
		return;
	}
	if (ret != 0)
		fprintf(stderr, "%s: %s\n", path, err.msg);
	CHECK(ret == 0);
	CHECK(a.tree.nbranches > 0 && a.tree.lifted);
	CHECK(a.mesh.bark.nvertices > 0);
	CHECK(docfile_read(path, &doc, &err) == 0);
	CHECK(a.seed == doc.seed);
	doc_finish(&doc);
	/* the same again, and its meshes its tree's */
	CHECK(forest_plant(path, &b, &err) == 0);
	same_tree(&a.tree, &b.tree);
	same_mesh(&a.mesh.bark, &b.mesh.bark);
	same_mesh(&a.mesh.leaves, &b.mesh.leaves);
	tree_mesh_init(&m);
	tree_mesh_marks_init(&mk);
	CHECK(tree_mesh_build_marked(&m, &a.tree, &mk) == 0);
	same_mesh(&a.mesh.bark, &m.bark);
	same_mesh(&a.mesh.leaves, &m.leaves);
	tree_mesh_finish(&m);
	tree_mesh_marks_finish(&mk);
	/* planting over a planted one empties it first */
	CHECK(forest_plant(path, &a, &err) == 0);
	same_tree(&a.tree, &b.tree);
	forest_planted_finish(&a);
	forest_planted_finish(&b);
	planted++;
}

static void refuse_one(const char *path)
{
	struct forest_planted p;
	struct error err = { { 0 } };

	forest_planted_init(&p);
	CHECK(forest_plant(path, &p, &err) < 0);
	CHECK(strstr(err.msg, path) != NULL);
	CHECK(p.tree.nbranches == 0 && p.mesh.bark.nvertices == 0 && p.mesh.leaves.nvertices == 0);
	forest_planted_finish(&p);
	refused++;
}

typedef void (*each_fn)(const char *path);

static void each(const char *dir, each_fn fn)
{
	DIR *d = opendir(dir);
	struct dirent *e;
	char path[4096];

	CHECK(d != NULL);
	while ((e = readdir(d))) {
		size_t n = strlen(e->d_name);

		if (n < 7 || strcmp(e->d_name + n - 6, ".edaha") != 0)
			continue;
		CHECK(snprintf(path, sizeof(path), "%s/%s", dir, e->d_name) < (int)sizeof(path));
		fn(path);
	}
	closedir(d);
}

int main(int argc, char **argv)
{
	CHECK(argc == 3);
	each(argv[1], plant_one);
	each(argv[2], refuse_one);
	refuse_one("/nonexistent/drawing.edaha");
	CHECK(planted >= 8 && empty >= 1 && refused >= 5);
	printf("forest planting: %zu drawings planted (twice, the same), %zu with no tree, %zu "
	       "refused with their names\n", planted, empty, refused);
	return 0;
}
