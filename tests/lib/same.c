/* SPDX-License-Identifier: MIT */
#include "same.h"

#include <math.h>
#include <string.h>

#include "test.h"
#include "vine.h"
#include "wood.h"

#define SAME(a, b) CHECK(memcmp(&(a), &(b), sizeof(a)) == 0)

void same_mesh(const struct mesh *a, const struct mesh *b)
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

bool mesh_bytes_equal(const struct mesh *a, const struct mesh *b)
{
	if (a->nvertices != b->nvertices || a->nindices != b->nindices)
		return false;
	return (a->nvertices == 0 ||
		(!memcmp(a->positions, b->positions, a->nvertices * 3 * sizeof(float)) &&
		 !memcmp(a->normals, b->normals, a->nvertices * 3 * sizeof(float)))) &&
	       (a->nindices == 0 || !memcmp(a->indices, b->indices, a->nindices * sizeof(uint32_t)));
}

void box_empty(struct box *b)
{
	for (int k = 0; k < 3; k++) {
		b->lo[k] = INFINITY;
		b->hi[k] = -INFINITY;
	}
}

void box_add(struct box *b, const struct mesh *m)
{
	for (size_t v = 0; m && v < m->nvertices; v++) {
		for (int k = 0; k < 3; k++) {
			double x = m->positions[3 * v + (size_t)k];

			b->lo[k] = fmin(b->lo[k], x);
			b->hi[k] = fmax(b->hi[k], x);
		}
	}
}

void check_mesh_sane(const struct mesh *m)
{
	CHECK(m->nindices % 3 == 0);
	for (size_t i = 0; i < 3 * m->nvertices; i++) {
		CHECK(isfinite(m->positions[i]));
		CHECK(isfinite(m->normals[i]));
	}
	for (size_t i = 0; i < m->nindices; i++)
		CHECK(m->indices[i] < m->nvertices);
}

void same_tree(const struct tree *a, const struct tree *b)
{
	CHECK_INT(a->nbranches, b->nbranches);
	CHECK_INT(a->nleaves, b->nleaves);
	CHECK_INT(a->lifted, b->lifted);
	CHECK_INT(a->sides, b->sides);
	CHECK_INT(a->season, b->season);
	CHECK_INT(a->leaf_kind, b->leaf_kind);
	CHECK_INT(a->last_sketched, b->last_sketched);
	CHECK_INT(a->last_sketched_end_us, b->last_sketched_end_us);
	CHECK_INT(a->has_profile, b->has_profile);
	SAME(a->profile, b->profile);
	for (size_t i = 0; i < a->nbranches; i++) {
		const struct branch *x = &a->branches[i], *y = &b->branches[i];

		CHECK_INT(x->id, y->id);
		CHECK_INT(x->parent, y->parent);
		SAME(x->parent_t, y->parent_t);
		CHECK_INT(x->generation, y->generation);
		CHECK_INT(x->level, y->level);
		CHECK_INT(x->origin, y->origin);
		CHECK_INT(x->npoints, y->npoints);
		CHECK(memcmp(x->points, y->points, x->npoints * sizeof(*x->points)) == 0);
		CHECK(memcmp(x->radii, y->radii, x->npoints * sizeof(*x->radii)) == 0);
	}
	for (size_t i = 0; i < a->nleaves; i++) {
		const struct leaf *x = &a->leaves[i], *y = &b->leaves[i];

		CHECK_INT(x->id, y->id);
		CHECK_INT(x->branch, y->branch);
		SAME(x->branch_t, y->branch_t);
		CHECK_INT(x->kind, y->kind);
		CHECK_INT(x->origin, y->origin);
		CHECK_INT(x->npoints, y->npoints);
		CHECK(memcmp(x->points, y->points, x->npoints * sizeof(*x->points)) == 0);
		CHECK((x->local == NULL) == (y->local == NULL));
		CHECK(!x->local || memcmp(x->local, y->local, x->npoints * sizeof(*x->local)) == 0);
	}
	CHECK((a->wood == NULL) == (b->wood == NULL));
	if (a->wood && b->wood) {
		CHECK_INT(a->wood->presses, b->wood->presses);
		CHECK(wood_cells(&a->wood->g) == wood_cells(&b->wood->g));
		CHECK(memcmp(a->wood->g.density, b->wood->g.density,
			     wood_cells(&a->wood->g) * sizeof(double)) == 0);
		CHECK_INT(a->wood->nbranches, b->wood->nbranches);
		CHECK(memcmp(a->wood->voxelised, b->wood->voxelised,
			     a->wood->nbranches * sizeof(*a->wood->voxelised)) == 0);
	}
	CHECK_INT(a->nvines, b->nvines);
	for (size_t i = 0; i < a->nvines && i < b->nvines; i++) {
		const struct vine *x = &a->vines[i], *y = &b->vines[i];

		SAME(x->p, y->p);
		SAME(x->plant, y->plant);
		CHECK_INT(x->nshoots, y->nshoots);
		for (size_t k = 0; k < x->nshoots && k < y->nshoots; k++) {
			CHECK_INT(x->shoots[k].n, y->shoots[k].n);
			CHECK(memcmp(x->shoots[k].axis, y->shoots[k].axis,
				     x->shoots[k].n * sizeof(*x->shoots[k].axis)) == 0);
		}
	}
}
