/* SPDX-License-Identifier: MIT */
/* Leaves: ear clipping in the best-fit plane, winding, area, degenerate polygons. */
#include <math.h>
#include <stdint.h>

#include "mesh.h"
#include "mesh_check.h"
#include "rng.h"
#include "test.h"
#include "tree.h"

#define TEST_PI 3.14159265358979323846

/* Area of a planar 3D polygon: half the length of its Newell vector. */
static double polygon_area(const struct vec3 *p, size_t n, struct vec3 *normal)
{
	struct vec3 nn = vec3(0, 0, 0);

	for (size_t i = 0; i < n; i++)
		nn = vec3_add(nn, vec3_cross(p[i], p[(i + 1) % n]));
	*normal = vec3_norm_or(nn, vec3(0, 0, 0));
	return 0.5 * vec3_len(nn);
}

/* Builds one leaf; checks it is n-2 triangles covering exactly the polygon, facing `normal`. */
static void check_leaf(const struct vec3 *p, size_t n, size_t want_tris)
{
	struct tree t;
	struct tree_mesh tm;
	struct vec3 normal;
	double area = polygon_area(p, n, &normal), sum = 0.0;

	tree_init(&t);
	tree_mesh_init(&tm);
	CHECK_INT(tree_add_leaf(&t, 0, ORIGIN_SKETCH, p, n), 0);
	CHECK_INT(tree_mesh_build(&tm, &t), 0);
	check_mesh_sane(&tm.leaves);
	CHECK_INT(tm.bark.nindices, 0);
	CHECK_INT(tm.leaves.nindices / 3, want_tris);
	for (size_t f = 0; f < want_tris; f++) {
		struct vec3 c = tri_cross(&tm.leaves, f);

		/* counter-clockwise seen from the side the normal points to; no slivers the wrong way */
		CHECK(vec3_dot(c, normal) > 0);
		sum += 0.5 * vec3_len(c);
	}
	/* positions are floats: ~1e-7 relative, a few metres from the origin */
	CHECK_NEAR(sum, area, 1e-5 * area + 1e-9);
	for (uint32_t i = 0; i < tm.leaves.nvertices; i++)
		CHECK_NEAR(vec3_dot(mesh_nor(&tm.leaves, i), normal), 1.0, 1e-6);
	tree_mesh_finish(&tm);
	tree_finish(&t);
}

/* Rotates and moves a polygon into a general position in space. */
static void place(struct vec3 *p, size_t n, double yaw, double pitch, struct vec3 at)
{
	for (size_t i = 0; i < n; i++) {
		struct vec3 q = p[i];
		struct vec3 a = vec3(q.x * cos(yaw) - q.z * sin(yaw), q.y, q.x * sin(yaw) + q.z * cos(yaw));

		p[i] = vec3_add(vec3(a.x, a.y * cos(pitch) - a.z * sin(pitch),
				     a.y * sin(pitch) + a.z * cos(pitch)),
				at);
	}
}

static void test_concave(void)
{
	/* an arrow head: two reflex corners */
	struct vec3 arrow[] = { { 0, 0, 0 }, { 0.1, 0.02, 0 }, { 0.2, 0, 0 }, { 0.12, 0.08, 0 },
				{ 0.14, 0.2, 0 }, { 0.1, 0.13, 0 }, { 0.06, 0.2, 0 }, { 0.08, 0.08, 0 } };
	/* an L shape, drawn clockwise */
	struct vec3 ell[] = { { 0, 0, 0 }, { 0, 0.3, 0 }, { 0.1, 0.3, 0 },
			      { 0.1, 0.1, 0 }, { 0.2, 0.1, 0 }, { 0.2, 0, 0 } };

	check_leaf(arrow, 8, 6);
	check_leaf(ell, 6, 4);
	place(arrow, 8, 0.7, -1.1, vec3(3, 5, -2));
	place(ell, 6, 2.0, 0.4, vec3(-1, 7, 0.5));
	check_leaf(arrow, 8, 6);
	check_leaf(ell, 6, 4);
}

/* Random star-shaped polygons (always simple, often concave), some slightly bent. */
static void test_random_stars(void)
{
	struct rng r;

	rng_seed(&r, 42);
	for (int k = 0; k < 500; k++) {
		struct vec3 p[40];
		size_t n = 3 + rng_next(&r) % 38;
		double bend = k % 2 ? 0.0 : 0.003;

		for (size_t i = 0; i < n; i++) {
			double a = 2 * TEST_PI * ((double)i + rng_range(&r, 0.1, 0.9)) / (double)n;
			double rad = rng_range(&r, 0.02, 0.15);

			p[i] = vec3(rad * cos(a), rad * sin(a), bend * rng_range(&r, -1, 1));
		}
		place(p, n, rng_range(&r, 0, 6), rng_range(&r, -1.5, 1.5), vec3(1, 2, 3));
		if (bend == 0.0) {
			check_leaf(p, n, n - 2);
		} else {
			/* not quite planar: same triangle count, area close to the projected one */
			struct tree t;
			struct tree_mesh tm;

			tree_init(&t);
			tree_mesh_init(&tm);
			CHECK(tree_add_leaf(&t, 0, ORIGIN_SKETCH, p, n) >= 0);
			CHECK_INT(tree_mesh_build(&tm, &t), 0);
			check_mesh_sane(&tm.leaves);
			CHECK_INT(tm.leaves.nindices / 3, n - 2);
			tree_mesh_finish(&tm);
			tree_finish(&t);
		}
	}
}

/* Duplicate and closing points are merged; collinear points add no slivers. */
static void test_duplicates(void)
{
	const struct vec3 square[] = { { 0, 0, 0 }, { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 },
				       { 1, 1, 0 }, { 0, 1, 0 }, { 0, 0, 0 } };
	const struct vec3 dedup[] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 } };
	const struct vec3 collinear[] = { { 0, 0, 0 }, { 0.5, 0, 0 }, { 1, 0, 0 },
					  { 1, 1, 0 }, { 0, 1, 0 } };
	struct tree t;
	struct tree_mesh tm;
	struct vec3 n;
	double sum = 0;

	tree_init(&t);
	tree_mesh_init(&tm);
	CHECK_INT(tree_add_leaf(&t, 0, ORIGIN_SKETCH, square, 7), 0);
	CHECK_INT(tree_mesh_build(&tm, &t), 0);
	check_mesh_sane(&tm.leaves);
	CHECK_INT(tm.leaves.nindices, 6);
	CHECK_INT(tm.leaves.nvertices, 4);
	tree_clear(&t);
	check_leaf(dedup, 4, 2);

	CHECK_INT(tree_add_leaf(&t, 0, ORIGIN_SKETCH, collinear, 5), 0);
	CHECK_INT(tree_mesh_build(&tm, &t), 0);
	check_mesh_sane(&tm.leaves);
	CHECK(tm.leaves.nindices / 3 >= 2 && tm.leaves.nindices / 3 <= 3);
	for (size_t f = 0; f < tm.leaves.nindices / 3; f++)
		sum += 0.5 * vec3_len(tri_cross(&tm.leaves, f));
	CHECK_NEAR(sum, polygon_area(collinear, 5, &n), 1e-9);
	tree_mesh_finish(&tm);
	tree_finish(&t);
}

/* Junk must not crash and must not produce non-finite or inside-out geometry. */
static void test_junk(void)
{
	const struct vec3 two[] = { { 0, 0, 0 }, { 1, 0, 0 } };
	const struct vec3 line[] = { { 0, 0, 0 }, { 1, 0, 0 }, { 2, 0, 0 }, { 3, 0, 0 } };
	const struct vec3 point[] = { { 1, 1, 1 }, { 1, 1, 1 }, { 1, 1, 1 } };
	const struct vec3 eight[] = { { 0, 0, 0 }, { 1, 1, 0 }, { 1, 0, 0 }, { 0, 1, 0 } };
	const struct vec3 nan[] = { { 0, 0, 0 }, { 1, NAN, 0 }, { 1, 1, 0 } };
	const struct vec3 tangled[] = { { 0, 0, 0 }, { 2, 0, 0 }, { 2, 2, 0 }, { 1, -1, 0 },
					{ 0.5, 3, 0 }, { -1, 1, 0 }, { 3, 1.5, 0 } };
	struct tree t;
	struct tree_mesh tm;

	tree_init(&t);
	tree_mesh_init(&tm);
	CHECK(tree_add_leaf(&t, 0, ORIGIN_SKETCH, two, 0) >= 0);
	CHECK(tree_add_leaf(&t, 0, ORIGIN_SKETCH, two, 2) >= 0);
	CHECK(tree_add_leaf(&t, 0, ORIGIN_SKETCH, line, 4) >= 0);
	CHECK(tree_add_leaf(&t, 0, ORIGIN_SKETCH, point, 3) >= 0);
	CHECK(tree_add_leaf(&t, 0, ORIGIN_SKETCH, eight, 4) >= 0);
	CHECK(tree_add_leaf(&t, 0, ORIGIN_SKETCH, nan, 3) >= 0);
	CHECK_INT(tree_mesh_build(&tm, &t), 0);
	CHECK_INT(tm.leaves.nindices, 0);
	CHECK_INT(tm.leaves.nvertices, 0);

	/* best effort on a self-intersecting scribble: sane, every face along the normal */
	CHECK(tree_add_leaf(&t, 0, ORIGIN_SKETCH, tangled, 7) >= 0);
	CHECK_INT(tree_mesh_build(&tm, &t), 0);
	check_mesh_sane(&tm.leaves);
	CHECK(tm.leaves.nindices / 3 <= 5);
	for (size_t f = 0; f < tm.leaves.nindices / 3; f++) {
		uint32_t v = tm.leaves.indices[3 * f];

		CHECK(vec3_dot(tri_cross(&tm.leaves, f), mesh_nor(&tm.leaves, v)) > 0);
	}
	tree_mesh_finish(&tm);
	tree_finish(&t);
}

int main(void)
{
	test_concave();
	test_random_stars();
	test_duplicates();
	test_junk();
	return 0;
}
