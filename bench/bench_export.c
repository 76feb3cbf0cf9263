/* SPDX-License-Identifier: MIT */
/*
 * Mesh building and the three exporters on synthetic trees of 62..500 branches with 10
 * leaves each: median of REPS runs per stage and in total, growth with size, and what
 * came out (triangles, bytes).
 */
#include <stdio.h>
#include <stdlib.h>

#include "bench_util.h"
#include "buf.h"
#include "export.h"
#include "mesh.h"
#include "synth_tree.h"
#include "tree.h"

#define REPS 7
#define LEAVES_PER_BRANCH 10
#define NSIZES 4
#define SEED 2024

enum stage { MESH, GLB, OBJ, SKELETON, TOTAL, NSTAGES };

static const char *const stage_names[NSTAGES] = {
	"tree_mesh_build", "export_glb", "export_obj", "export_skeleton", "total",
};

struct result {
	double median[NSTAGES];
	size_t bark_tris, leaf_tris, glb_bytes, obj_bytes, mtl_bytes, skel_bytes;
};

static int run_size(int nbranches, struct result *res)
{
	double times[NSTAGES][REPS];
	struct tree t;
	struct tree_mesh tm;
	struct buf glb, obj, mtl, skel;
	int r;

	tree_init(&t);
	tree_mesh_init(&tm);
	buf_init(&glb);
	buf_init(&obj);
	buf_init(&mtl);
	buf_init(&skel);
	r = synth_tree(&t, nbranches, LEAVES_PER_BRANCH, SEED);
	for (int rep = 0; rep < REPS && r >= 0; rep++) {
		double t0, t1, t2, t3, t4;

		/* Fresh buffers each time, as for one visitor's export. */
		buf_finish(&glb);
		buf_finish(&obj);
		buf_finish(&mtl);
		buf_finish(&skel);
		tree_mesh_finish(&tm);

		t0 = bench_now();
		r = tree_mesh_build(&tm, &t);
		t1 = bench_now();
		if (r >= 0)
			r = export_glb(&tm, &glb);
		t2 = bench_now();
		if (r >= 0)
			r = export_obj(&tm, "tree.mtl", &obj, &mtl);
		t3 = bench_now();
		if (r >= 0)
			r = export_skeleton(&t, &skel);
		t4 = bench_now();
		times[MESH][rep] = t1 - t0;
		times[GLB][rep] = t2 - t1;
		times[OBJ][rep] = t3 - t2;
		times[SKELETON][rep] = t4 - t3;
		times[TOTAL][rep] = t4 - t0;
	}
	if (r >= 0) {
		for (int s = 0; s < NSTAGES; s++)
			res->median[s] = bench_median(times[s], REPS);
		res->bark_tris = tm.bark.nindices / 3;
		res->leaf_tris = tm.leaves.nindices / 3;
		res->glb_bytes = glb.len;
		res->obj_bytes = obj.len;
		res->mtl_bytes = mtl.len;
		res->skel_bytes = skel.len;
	}
	buf_finish(&glb);
	buf_finish(&obj);
	buf_finish(&mtl);
	buf_finish(&skel);
	tree_mesh_finish(&tm);
	tree_finish(&t);
	return r;
}

int main(void)
{
	static const int sizes[NSIZES] = { 62, 125, 250, 500 };
	struct result res[NSIZES];

	for (int i = 0; i < NSIZES; i++) {
		int r = run_size(sizes[i], &res[i]);

		if (r < 0) {
			fprintf(stderr, "bench_export: %d branches failed: %d\n", sizes[i], r);
			return 1;
		}
	}

	printf("bench_export: synth_tree(n branches, %d leaves each), median of %d runs;"
	       " size = branches\n\n",
	       LEAVES_PER_BRANCH, REPS);
	for (int s = 0; s < NSTAGES; s++) {
		double prev_size = 0, prev_s = 0;

		for (int i = 0; i < NSIZES; i++)
			bench_row(stage_names[s], sizes[i], res[i].median[s], &prev_size, &prev_s);
		printf("\n");
	}

	printf("%8s %8s %12s %12s %12s %12s %14s\n", "branches", "leaves", "bark tris", "leaf tris",
	       "glb bytes", "obj bytes", "skeleton bytes");
	for (int i = 0; i < NSIZES; i++)
		printf("%8d %8d %12zu %12zu %12zu %12zu %14zu\n", sizes[i], sizes[i] * LEAVES_PER_BRANCH,
		       res[i].bark_tris, res[i].leaf_tris, res[i].glb_bytes,
		       res[i].obj_bytes + res[i].mtl_bytes, res[i].skel_bytes);
	return 0;
}
