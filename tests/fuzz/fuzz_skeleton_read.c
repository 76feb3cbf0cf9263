/* SPDX-License-Identifier: MIT */
/*
 * libFuzzer: the skeleton.json reader (skeleton_read, --skeleton) on arbitrary bytes. A
 * refusal names the file and a line of it ("fuzz:LINE: "; only running out of memory
 * names the file alone) and leaves the tree as it was. What is accepted is within every
 * limit an import op holds (checked here again), and reads the same a second time.
 */
#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "doc.h"
#include "fuzz_refusal.h"
#include "skeleton_read.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static bool in(double v, double lo, double hi)
{
	return isfinite(v) && v >= lo && v <= hi;
}

/* The limits of skeleton_read's contract, written out again. */
static void check_tree(const struct tree *t)
{
	size_t total = 0;

	if (t->nbranches > TREE_MAX_BRANCHES || t->nleaves || t->lifted)
		abort();
	for (size_t i = 0; i < t->nbranches; i++) {
		const struct branch *b = &t->branches[i];

		if (b->id != (int)i || b->parent < -1 || b->parent >= (int)i ||
		    !in(b->parent_t, 0, 1) || b->generation < 0 || b->generation > 1000 ||
		    b->npoints < 2 || b->npoints > DOC_MAX_STROKE_POINTS || b->origin != ORIGIN_SKETCH)
			abort();
		total += b->npoints;
		for (size_t k = 0; k < b->npoints; k++)
			if (!in(b->points[k].x, -DOC_MAX_COORD_M, DOC_MAX_COORD_M) ||
			    !in(b->points[k].y, -DOC_MAX_COORD_M, DOC_MAX_COORD_M) ||
			    !in(b->points[k].z, -DOC_MAX_COORD_M, DOC_MAX_COORD_M) ||
			    !in(b->radii[k], 0, DOC_MAX_COORD_M))
				abort();
	}
	if (total > DOC_MAX_POINTS)
		abort();
}

static bool same(const struct tree *a, const struct tree *b)
{
	if (a->nbranches != b->nbranches)
		return false;
	for (size_t i = 0; i < a->nbranches; i++) {
		const struct branch *x = &a->branches[i], *y = &b->branches[i];

		if (x->parent != y->parent || x->parent_t != y->parent_t ||
		    x->generation != y->generation || x->npoints != y->npoints ||
		    memcmp(x->points, y->points, x->npoints * sizeof(*x->points)) ||
		    memcmp(x->radii, y->radii, x->npoints * sizeof(*x->radii)))
			return false;
	}
	return true;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	struct vec3 p[2] = { { 1, 2, 3 }, { 4, 5, 6 } };
	double r[2] = { 0.5, 0.25 };
	struct error err = { { 0 } };
	struct tree t, again;
	int ret;

	tree_init(&t);
	tree_init(&again);
	if (tree_add_branch(&t, -1, 0, ORIGIN_CLONE, p, r, 2) != 0)
		abort();
	ret = skeleton_read((const char *)data, size, "fuzz", &t, &err);
	if (ret < 0) {
		fuzz_check_refusal(ret, &err, fuzz_lines_of(data, size));
		/* untouched */
		if (t.nbranches != 1 || t.branches[0].origin != ORIGIN_CLONE ||
		    t.branches[0].radii[1] != 0.25)
			abort();
	} else {
		if (ret != 0)
			abort();
		check_tree(&t);
		if (skeleton_read((const char *)data, size, "again", &again, &err) != 0 ||
		    !same(&t, &again))
			abort();
	}
	tree_finish(&t);
	tree_finish(&again);
	return 0;
}
