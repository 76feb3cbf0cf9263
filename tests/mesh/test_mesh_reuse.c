/* SPDX-License-Identifier: MIT */
/* tree_mesh_rebuild_from (src/mesh/mesh_reuse.c): the meshes of a tree made from those of
 * another are the bytes tree_mesh_build makes, whatever the edit between the two: removed
 * and added branches and leaves, a branch cut, points moved under an unchanged child (its
 * parent or grandparent changed), identical branches side by side, and changes between a
 * branch's or leaf's ends, which only the full comparison (not the key) sees. */
#include <string.h>

#include "mesh_reuse.h"
#include "rng.h"
#include "synth_tree.h"
#include "test.h"

static void same_mesh(const struct mesh *a, const struct mesh *b)
{
	CHECK_INT(a->nvertices, b->nvertices);
	CHECK_INT(a->nindices, b->nindices);
	if (a->nvertices) {
		CHECK(memcmp(a->positions, b->positions, a->nvertices * 3 * sizeof(float)) == 0);
		CHECK(memcmp(a->normals, b->normals, a->nvertices * 3 * sizeof(float)) == 0);
	}
	if (a->nindices)
		CHECK(memcmp(a->indices, b->indices, a->nindices * sizeof(uint32_t)) == 0);
}

/* Meshes `to` from `from`'s meshes and checks them against a build of `to`. */
static void check(const struct tree *from, const struct tree *to)
{
	struct tree_mesh tm, full;
	struct tree_mesh_marks mk;

	tree_mesh_init(&tm);
	tree_mesh_init(&full);
	tree_mesh_marks_init(&mk);
	CHECK_INT(tree_mesh_build_marked(&tm, from, &mk), 0);
	CHECK_INT(tree_mesh_rebuild_from(&tm, &mk, to, from), 0);
	CHECK_INT(tree_mesh_build(&full, to), 0);
	same_mesh(&tm.bark, &full.bark);
	same_mesh(&tm.leaves, &full.leaves);
	/* and the marks are those of a build: a prefix can be cut back */
	CHECK_INT(mk.nbark, to->nbranches + 1);
	CHECK_INT(mk.nleaves, to->nleaves + 1);
	tree_mesh_finish(&tm);
	tree_mesh_finish(&full);
	tree_mesh_marks_finish(&mk);
}

static void copy(struct tree *dst, const struct tree *src)
{
	tree_init(dst);
	CHECK_INT(tree_copy(dst, src), 0);
}

int main(void)
{
	struct tree base, t;
	struct rng r;

	tree_init(&base);
	CHECK_INT(synth_tree(&base, 300, 2, 17), 0);
	rng_seed(&r, 5);

	/* nothing changed, and everything (another tree) */
	copy(&t, &base);
	check(&base, &t);
	CHECK_INT(synth_tree(&t, 200, 1, 18), 0);
	check(&base, &t);
	check(&t, &base);
	tree_finish(&t);

	for (int round = 0; round < 64; round++) {
		copy(&t, &base);
		switch (round % 8) {
		case 0: { /* branches removed (with what hangs on them), both ways */
			bool remove[400] = { false };

			for (int k = 0; k < 3; k++)
				remove[1 + rng_next(&r) % (t.nbranches - 1)] = true;
			CHECK_INT(tree_remove_branches(&t, remove), 0);
			break;
		}
		case 1: { /* a cut */
			int b = (int)(1 + rng_next(&r) % (t.nbranches - 1));

			CHECK_INT(tree_cut_branch(&t, b, t.branches[b].npoints / 2, 0.5), 0);
			break;
		}
		case 2: { /* a branch moved: its children and grandchildren keep their points */
			struct branch *b = &t.branches[1 + rng_next(&r) % (t.nbranches - 1)];

			for (size_t k = 0; k < b->npoints; k++)
				b->points[k].z += 0.3;
			b->radii[0] *= 1.5;
			break;
		}
		case 3: /* leaves changed and removed */
			for (size_t k = 0; k < t.nleaves; k += 7)
				t.leaves[k].points[0].x += 0.01;
			{
				bool remove[1000] = { false };

				CHECK(t.nleaves < 1000);
				for (size_t k = 3; k < t.nleaves; k += 11)
					remove[k] = true;
				tree_remove_leaves(&t, remove);
			}
			break;
		case 5: { /* a point between the ends of a parent: its children mesh anew */
			size_t b = 0;

			for (size_t k = 1; k < t.nbranches; k++)
				if (t.branches[k].parent > 0 && t.branches[t.branches[k].parent].npoints > 4) {
					b = (size_t)t.branches[k].parent;
					if (rng_next(&r) % 4 == 0)
						break;
				}
			CHECK(b > 0);
			t.branches[b].points[t.branches[b].npoints / 2].x += 0.2;
			break;
		}
		case 6: { /* a radius between the ends */
			struct branch *b = &t.branches[1 + rng_next(&r) % (t.nbranches - 1)];

			if (b->npoints > 2)
				b->radii[b->npoints / 2] *= 2.0;
			break;
		}
		case 7: /* a leaf's point between its ends */
			for (size_t k = 0; k < t.nleaves; k += 5)
				if (t.leaves[k].npoints > 2)
					t.leaves[k].points[1].y += 0.02;
			break;
		case 4: /* twins: the same branch again, on the same parent */
			for (int k = 0; k < 4; k++) {
				const struct branch *b = &t.branches[1 + rng_next(&r) % (t.nbranches - 1)];

				CHECK(tree_add_branch(&t, b->parent, b->parent_t, b->origin, b->points, b->radii,
						      b->npoints) >= 0);
			}
			break;
		}
		check(&base, &t);
		check(&t, &base);
		tree_finish(&t);
	}
	tree_finish(&base);
	return 0;
}
