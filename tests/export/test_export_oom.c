/* SPDX-License-Identifier: MIT */
/*
 * Allocation failure: fails the 1st, 2nd, ... allocation of tree_mesh_build and every
 * exporter in turn, the glTF and OBJ exporters in every season, a tree with a vine too
 * (the exporters mesh it) and a grown tree (its wood's bark, skeleton.json's "wood"),
 * with the wind too (export_glb_wind's bindings, targets and keys; skeleton.json's
 * "wind"), a forest of three trees (export_glb_forest, still and with the wind) and the
 * take-home page (export_page_html, after what its buffer held); each must return
 * -ENOMEM, leave nothing half-built and leak nothing.
 * Allocations fail through tests/lib/fail_alloc.c, which replaces malloc & co., so it is not
 * built with sanitizers, which replace them too.
 */
#include <errno.h>
#include <stdbool.h>
#include <stddef.h>
#include <string.h>

#include "buf.h"
#include "export.h"
#include "fail_alloc.h"
#include "mesh.h"
#include "synth_tree.h"
#include "synth_vine.h"
#include "synth_wood.h"
#include "test.h"
#include "tree.h"

struct job {
	const struct tree *tree;
	const struct tree_mesh *mesh;
	const struct tree_mesh_marks *marks;
};

typedef int (*op_fn)(const struct job *j);

static int op_mesh(const struct job *j)
{
	struct tree_mesh tm;
	int r;

	tree_mesh_init(&tm);
	r = tree_mesh_build(&tm, j->tree);
	if (r < 0)
		CHECK(tm.bark.nindices == 0 && tm.leaves.nindices == 0);
	tree_mesh_finish(&tm);
	return r;
}

static int op_glb(const struct job *j)
{
	struct buf b;
	int r;

	buf_init(&b);
	r = export_glb(j->tree, j->mesh, j->marks, &b);
	if (r < 0)
		CHECK_INT(b.len, 0);
	buf_finish(&b);
	return r;
}

/* The glb with the wind at the default breeze: targets, keys, bindings. */
static int op_glb_wind(const struct job *j)
{
	const struct export_wind ew = { .strength = 0.0, .angle = EXPORT_WIND_ANGLE, .seed = 3 };
	struct buf b;
	int r;

	buf_init(&b);
	r = export_glb_wind(j->tree, j->mesh, j->marks, &ew, &b);
	if (r < 0)
		CHECK_INT(b.len, 0);
	buf_finish(&b);
	return r;
}

static int op_skeleton_wind(const struct job *j)
{
	const struct export_wind ew = { .strength = 0.0, .angle = EXPORT_WIND_ANGLE, .seed = 3 };
	struct buf b;
	int r;

	buf_init(&b);
	r = export_skeleton_wind(j->tree, &ew, &b);
	if (r < 0)
		CHECK_INT(b.len, 0);
	buf_finish(&b);
	return r;
}

static int op_obj(const struct job *j)
{
	struct buf obj, mtl;
	int r;

	buf_init(&obj);
	buf_init(&mtl);
	r = export_obj(j->tree, j->mesh, j->marks, "tree.mtl", &obj, &mtl);
	if (r < 0)
		CHECK_INT(obj.len + mtl.len, 0);
	buf_finish(&obj);
	buf_finish(&mtl);
	return r;
}

static int op_skeleton(const struct job *j)
{
	struct buf b;
	int r;

	buf_init(&b);
	r = export_skeleton(j->tree, &b);
	if (r < 0)
		CHECK_INT(b.len, 0);
	buf_finish(&b);
	return r;
}

/* The page of a few bytes appended to a buffer that holds something: on failure the
 * buffer holds that alone, and takes more. */
static int op_page(const struct job *j)
{
	static const char glb[] = "glTF model bytes", three[] = "var THREE = {};\n";
	const struct export_page_script script = { three, sizeof(three) - 1 };
	const struct export_page page = {
		.glb = glb, .glb_len = sizeof(glb) - 1, .scripts = &script, .nscripts = 1,
		.number = 3, .date = "5 December 2026", .words = export_page_words(EXPORT_PAGE_JA),
		.paper = { 0.975f, 0.953f, 0.898f },
	};
	char before[4096];
	struct buf b;
	int r;

	(void)j;
	memset(before, 'x', sizeof(before));
	buf_init(&b);
	r = buf_append(&b, before, sizeof(before));
	if (r == 0) {
		r = export_page_html(&page, &b);
		if (r < 0) {
			CHECK(b.len == sizeof(before) && !memcmp(b.data, before, b.len) && !b.failed);
			CHECK_INT(buf_append(&b, "", 1), 0);
		}
	}
	buf_finish(&b);
	return r;
}

/* Fails each allocation of op in turn until op gets through without a failure. */
static long exhaust(op_fn op, const struct job *j)
{
	for (long n = 0;; n++) {
		long before = fail_alloc_live();
		int r;

		fail_alloc_at(n);
		r = op(j);
		fail_alloc_off();
		CHECK_INT(fail_alloc_live(), before);
		if (fail_alloc_calls() <= n) {
			CHECK_INT(r, 0);
			return n;
		}
		if (r != -ENOMEM)
			fprintf(stderr, "allocation %ld failed, op returned %d\n", n, r);
		CHECK_INT(r, -ENOMEM);
	}
}

static const enum season seasons[] = { SEASON_SUMMER, SEASON_SPRING, SEASON_AUTUMN,
				       SEASON_WINTER };

/* The glTF and OBJ exporters of a trunk with a vine, in every season, and its skeleton. */
static void vine_tree(void)
{
	struct tree t;
	struct tree_mesh tm;
	struct tree_mesh_marks mk;
	struct job j = { &t, &tm, &mk };
	long n;

	tree_init(&t);
	tree_mesh_init(&tm);
	tree_mesh_marks_init(&mk);
	CHECK_INT(synth_vine_tree(&t, 1), 0);
	CHECK_INT(tree_mesh_build_marked(&tm, &t, &mk), 0);
	for (size_t i = 0; i < sizeof(seasons) / sizeof(*seasons); i++) {
		t.season = seasons[i];
		n = exhaust(op_glb, &j);
		printf("export_glb of a vine in %s: %ld allocations, each failed once\n",
		       season_name(t.season), n);
		CHECK(n > 0);
		n = exhaust(op_glb_wind, &j);
		printf("export_glb_wind of a vine in %s: %ld allocations, each failed once\n",
		       season_name(t.season), n);
		CHECK(n > 0);
		n = exhaust(op_obj, &j);
		printf("export_obj of a vine in %s: %ld allocations, each failed once\n",
		       season_name(t.season), n);
		CHECK(n > 0);
	}
	t.season = SEASON_SUMMER;
	n = exhaust(op_skeleton, &j);
	printf("export_skeleton of a vine: %ld allocations, each failed once\n", n);
	CHECK(n > 0);
	tree_mesh_marks_finish(&mk);
	tree_mesh_finish(&tm);
	tree_finish(&t);
}

/* The glTF and OBJ exporters of a grown tree (its wood's bark), and its skeleton. */
static void wood_tree(void)
{
	struct tree t;
	struct tree_mesh tm;
	struct tree_mesh_marks mk;
	struct job j = { &t, &tm, &mk };
	long n;

	tree_init(&t);
	tree_mesh_init(&tm);
	tree_mesh_marks_init(&mk);
	CHECK_INT(synth_wood_tree(&t, 1, 1 /* broadleaf */), 0);
	CHECK_INT(tree_mesh_build_marked(&tm, &t, &mk), 0);
	n = exhaust(op_glb, &j);
	printf("export_glb of a grown tree: %ld allocations, each failed once\n", n);
	CHECK(n > 0);
	n = exhaust(op_glb_wind, &j);
	printf("export_glb_wind of a grown tree: %ld allocations, each failed once\n", n);
	CHECK(n > 0);
	n = exhaust(op_obj, &j);
	printf("export_obj of a grown tree: %ld allocations, each failed once\n", n);
	CHECK(n > 0);
	n = exhaust(op_skeleton, &j);
	printf("export_skeleton of a grown tree: %ld allocations, each failed once\n", n);
	CHECK(n > 0);
	tree_mesh_marks_finish(&mk);
	tree_mesh_finish(&tm);
	tree_finish(&t);
}

/* A forest of three trees: a summer and an autumn synth_tree and the vine tree. */
struct forest_job {
	struct tree t[3];
	struct tree_mesh tm[3];
	struct tree_mesh_marks mk[3];
	struct export_forest_tree f[3];
	bool wind;
};

static struct forest_job forest_job;

static int op_glb_forest(const struct job *j)
{
	const struct export_wind ew = { .strength = 0.0, .angle = EXPORT_WIND_ANGLE };
	struct buf b;
	int r;

	(void)j;
	buf_init(&b);
	r = export_glb_forest(forest_job.f, 3, forest_job.wind ? &ew : NULL, 8.0, &b);
	if (r < 0)
		CHECK_INT(b.len, 0);
	buf_finish(&b);
	return r;
}

static void forest(void)
{
	struct forest_job *fj = &forest_job;
	long n;

	for (size_t i = 0; i < 3; i++) {
		tree_init(&fj->t[i]);
		tree_mesh_init(&fj->tm[i]);
		tree_mesh_marks_init(&fj->mk[i]);
		if (i < 2)
			CHECK_INT(synth_tree(&fj->t[i], 8 + 4 * (int)i, 2, 20 + i), 0);
		else
			CHECK_INT(synth_vine_tree(&fj->t[i], 1), 0);
		fj->t[i].season = i == 1 ? SEASON_AUTUMN : SEASON_SUMMER;
		CHECK_INT(tree_mesh_build_marked(&fj->tm[i], &fj->t[i], &fj->mk[i]), 0);
		fj->f[i] = (struct export_forest_tree){ .tree = &fj->t[i], .mesh = &fj->tm[i],
							.marks = &fj->mk[i], .seed = i,
							.number = i + 1, .position = { 3.0 * i, 0, 0 } };
	}
	for (int w = 0; w < 2; w++) {
		fj->wind = w;
		n = exhaust(op_glb_forest, NULL);
		printf("export_glb_forest of 3 trees%s: %ld allocations, each failed once\n",
		       w ? " with the wind" : "", n);
		CHECK(n > 0);
	}
	for (size_t i = 0; i < 3; i++) {
		tree_mesh_marks_finish(&fj->mk[i]);
		tree_mesh_finish(&fj->tm[i]);
		tree_finish(&fj->t[i]);
	}
}

int main(void)
{
	struct tree t;
	struct tree_mesh tm;
	struct tree_mesh_marks mk;
	struct job j = { &t, &tm, &mk };
	long n;

	tree_init(&t);
	tree_mesh_init(&tm);
	tree_mesh_marks_init(&mk);
	CHECK_INT(synth_tree(&t, 12, 2, 11), 0);
	CHECK_INT(tree_mesh_build_marked(&tm, &t, &mk), 0);
	CHECK_INT(mk.nleaves, t.nleaves + 1);

	n = exhaust(op_mesh, &j);
	printf("tree_mesh_build: %ld allocations, each failed once\n", n);
	CHECK(n > 0);
	for (size_t i = 0; i < sizeof(seasons) / sizeof(*seasons); i++) {
		t.season = seasons[i];
		n = exhaust(op_glb, &j);
		printf("export_glb in %s: %ld allocations, each failed once\n",
		       season_name(t.season), n);
		CHECK(n > 0);
		n = exhaust(op_glb_wind, &j);
		printf("export_glb_wind in %s: %ld allocations, each failed once\n",
		       season_name(t.season), n);
		CHECK(n > 0);
		n = exhaust(op_obj, &j);
		printf("export_obj in %s: %ld allocations, each failed once\n",
		       season_name(t.season), n);
		CHECK(n > 0);
	}
	t.season = SEASON_SUMMER;
	n = exhaust(op_skeleton, &j);
	printf("export_skeleton: %ld allocations, each failed once\n", n);
	CHECK(n > 0);
	n = exhaust(op_skeleton_wind, &j);
	printf("export_skeleton_wind: %ld allocations, each failed once\n", n);
	CHECK(n > 0);
	n = exhaust(op_page, &j);
	printf("export_page_html: %ld allocations, each failed once\n", n);
	CHECK(n > 1);

	tree_mesh_marks_finish(&mk);
	tree_mesh_finish(&tm);
	tree_finish(&t);
	vine_tree();
	wood_tree();
	forest();
	return 0;
}
