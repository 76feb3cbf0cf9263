/* SPDX-License-Identifier: MIT */
/* Branch tubes: counts, closed surfaces, outward normals, frames, degenerate input. Level
 * of detail and joints in detail: test_mesh_detail.c. */
#include <errno.h>
#include <math.h>
#include <stdint.h>

#include "mesh.h"
#include "mesh_check.h"
#include "synth_tree.h"
#include "test.h"
#include "tree.h"

#define TEST_PI 3.14159265358979323846

static void build(struct tree_mesh *tm, const struct tree *t)
{
	CHECK_INT(tree_mesh_build(tm, t), 0);
	check_mesh_sane(&tm->bark);
	check_mesh_sane(&tm->leaves);
}

static int add_straight(struct tree *t, size_t npoints, double len, double radius)
{
	struct vec3 p[32];
	double r[32];

	CHECK(npoints <= 32);
	for (size_t i = 0; i < npoints; i++) {
		p[i] = vec3(0.5, len * (double)i / (double)(npoints - 1), -0.25);
		r[i] = radius;
	}
	return tree_add_branch(t, -1, 0.0, ORIGIN_SKETCH, p, r, npoints);
}

/* Ring sides of a tube of one radius follow from the counts: V = P*s + 2(s + 1), F = 2 s P
 * for P rings. */
static size_t sides_of(const struct mesh *m, size_t nrings)
{
	size_t ntri = m->nindices / 3, s = ntri / (2 * nrings);

	CHECK_INT(ntri, 2 * s * nrings);
	CHECK_INT(m->nvertices, nrings * s + 2 * (s + 1));
	return s;
}

/* Counts of a tube whose rings have these radii (each its own sides): V = sum s + (s0 + 1)
 * + (sl + 1) for the rings, root disc and tip cone; F = 2 sum s. */
static void check_counts(const struct mesh *m, size_t first_vertex, size_t first_index,
			 const double *ring_r, size_t nrings)
{
	size_t sum = 0;

	for (size_t i = 0; i < nrings; i++)
		sum += (size_t)mesh_ring_sides(ring_r[i]);
	CHECK_INT(m->nvertices - first_vertex, sum + (size_t)mesh_ring_sides(ring_r[0]) + 1 +
						       (size_t)mesh_ring_sides(ring_r[nrings - 1]) + 1);
	CHECK_INT((m->nindices - first_index) / 3, 2 * sum);
}

static void test_straight(void)
{
	struct tree t;
	struct tree_mesh tm;
	struct vec3 centre = vec3(0.5, 1.5, -0.25);
	size_t s;

	tree_init(&t);
	tree_mesh_init(&tm);
	CHECK_INT(add_straight(&t, 5, 3.0, 0.1), 0);
	build(&tm, &t);
	CHECK_INT(tm.leaves.nindices, 0);

	/* collinear points need no ring of their own (mesh.h): the ends' rings only */
	s = sides_of(&tm.bark, 2);
	CHECK_INT(s, mesh_ring_sides(0.1));
	CHECK(s >= 3 && s <= 16);
	/* A sphere-like closed surface. */
	CHECK_INT(check_closed_surface(&tm.bark), 2);

	/* Convex: normals and faces point away from the middle of the tube. */
	for (uint32_t i = 0; i < tm.bark.nvertices; i++) {
		struct vec3 d = vec3_sub(mesh_pos(&tm.bark, i), centre);

		CHECK(vec3_dot(mesh_nor(&tm.bark, i), d) > 0);
	}
	for (size_t f = 0; f < tm.bark.nindices / 3; f++) {
		const uint32_t *tri = &tm.bark.indices[3 * f];
		struct vec3 mid = vec3_scale(vec3_add(vec3_add(mesh_pos(&tm.bark, tri[0]),
							       mesh_pos(&tm.bark, tri[1])),
						      mesh_pos(&tm.bark, tri[2])),
					     1.0 / 3.0);

		CHECK(vec3_dot(tri_cross(&tm.bark, f), vec3_sub(mid, centre)) > 0);
	}
	/* Side vertices sit at the radius, on rings through the end points. */
	for (uint32_t i = 0; i < 2 * s; i++) {
		struct vec3 p = mesh_pos(&tm.bark, i);

		CHECK_NEAR(hypot(p.x - 0.5, p.z + 0.25), 0.1, 1e-6);
		CHECK_NEAR(p.y, 3.0 * (i / s), 1e-6);
	}

	tree_mesh_finish(&tm);
	tree_finish(&t);
}

/* Thin twigs get few sides, trunks many (see test_mesh_detail.c for more). */
static void test_sides_adapt(void)
{
	struct tree t;
	struct tree_mesh tm;
	size_t thin, mid, thick;

	tree_init(&t);
	tree_mesh_init(&tm);
	CHECK_INT(add_straight(&t, 3, 1.0, 0.003), 0);
	build(&tm, &t);
	thin = sides_of(&tm.bark, 2);
	tree_clear(&t);
	CHECK_INT(add_straight(&t, 3, 1.0, 0.08), 0);
	build(&tm, &t);
	mid = sides_of(&tm.bark, 2);
	tree_clear(&t);
	CHECK_INT(add_straight(&t, 3, 1.0, 0.4), 0);
	build(&tm, &t);
	thick = sides_of(&tm.bark, 2);
	CHECK_INT(thin, 3);
	CHECK_INT(mid, 10);
	CHECK_INT(thick, 16);
	CHECK(thin < mid && mid < thick);
	tree_mesh_finish(&tm);
	tree_finish(&t);
}

/*
 * A curve in the sketch plane: a rotation-minimising frame never twists, so the first
 * vertex of every ring stays on the +z side of its point (the start frame faces the viewer).
 */
static void test_planar_frames(void)
{
	struct vec3 p[12];
	double r[12];
	struct tree t;
	struct tree_mesh tm;
	size_t s = 0;

	for (int i = 0; i < 12; i++) {
		double a = 1.4 * TEST_PI * i / 11;

		p[i] = vec3(2.0 * cos(a), 2.0 * sin(a) + 1.0, 0.0);
		r[i] = 0.2 - 0.01 * i;
	}
	tree_init(&t);
	tree_mesh_init(&tm);
	CHECK_INT(tree_add_branch(&t, -1, 0, ORIGIN_SKETCH, p, r, 12), 0);
	build(&tm, &t);
	/* turning 23 degrees a point: every point keeps its ring, sides shrinking with r */
	check_counts(&tm.bark, 0, 0, r, 12);
	CHECK_INT(check_closed_surface(&tm.bark), 2);
	for (int i = 0; i < 12; i++) {
		struct vec3 q = mesh_pos(&tm.bark, (uint32_t)s);

		CHECK_NEAR(q.x, p[i].x, 1e-5);
		CHECK_NEAR(q.y, p[i].y, 1e-5);
		CHECK_NEAR(q.z, r[i], 1e-5);
		s += (size_t)mesh_ring_sides(r[i]);
	}
	tree_mesh_finish(&tm);
	tree_finish(&t);
}

/* A 3D helix with a hairpin and repeated points: still closed, finite, unit normals. */
static void test_awkward(void)
{
	struct vec3 p[40];
	double r[40];
	size_t n = 0, distinct = 0;
	struct tree t;
	struct tree_mesh tm;

	for (int i = 0; i < 30; i++) {
		double a = 0.5 * i;

		p[n] = vec3(cos(a), 0.1 * i, sin(a));
		r[n++] = 0.05;
		distinct++;
		if (i % 7 == 3) { /* a repeated point */
			p[n] = p[n - 1];
			r[n] = r[n - 1];
			n++;
		}
	}
	/* a hairpin: straight back the way it came */
	p[n] = vec3_add(p[n - 1], vec3(0, -0.5, 0));
	r[n++] = 0.02;
	p[n] = vec3_add(p[n - 1], vec3(0, 0.3, 0));
	r[n++] = 0.0; /* clamped, never a point */
	distinct += 2;

	tree_init(&t);
	tree_mesh_init(&tm);
	CHECK_INT(tree_add_branch(&t, -1, 0, ORIGIN_SKETCH, p, r, n), 0);
	build(&tm, &t);
	/* every distinct point keeps its ring (the helix turns 28 degrees a point) */
	{
		double rr[40];
		size_t k = 0;

		for (size_t i = 0; i < n; i++)
			if (i == 0 || vec3_dist(p[i], p[i - 1]) > 0)
				rr[k++] = r[i] < 0.0005 ? 0.0005 : r[i];
		CHECK_INT(k, distinct);
		check_counts(&tm.bark, 0, 0, rr, k);
	}
	CHECK_INT(check_closed_surface(&tm.bark), 2);
	tree_mesh_finish(&tm);
	tree_finish(&t);
}

static void test_degenerate(void)
{
	const struct vec3 one[] = { { 1, 2, 3 } };
	const struct vec3 same[] = { { 1, 2, 3 }, { 1, 2, 3 }, { 1, 2, 3 + 1e-9 } };
	const struct vec3 with_nan[] = { { 0, 0, 0 }, { NAN, 1, 0 }, { 0, INFINITY, 0 } };
	const struct vec3 ok_with_nan[] = { { 0, 0, 0 }, { NAN, 1, 0 }, { 0, 1, 0 } };
	const double r[] = { 0.1, NAN, -1 };
	struct tree t;
	struct tree_mesh tm;

	tree_init(&t);
	tree_mesh_init(&tm);
	/* an empty tree: empty meshes */
	build(&tm, &t);
	CHECK_INT(tm.bark.nvertices + tm.bark.nindices + tm.leaves.nvertices, 0);

	CHECK(tree_add_branch(&t, -1, 0, ORIGIN_SKETCH, one, r, 0) >= 0);
	CHECK(tree_add_branch(&t, 0, 0.5, ORIGIN_SKETCH, one, r, 1) >= 0);
	CHECK(tree_add_branch(&t, 0, 0.5, ORIGIN_SKETCH, same, r, 3) >= 0);
	CHECK(tree_add_branch(&t, 0, 0.5, ORIGIN_SKETCH, with_nan, r, 3) >= 0);
	build(&tm, &t);
	CHECK_INT(tm.bark.nvertices, 0);
	CHECK_INT(tm.bark.nindices, 0);

	/* bad points are skipped, bad radii clamped: the rest is a normal tube */
	CHECK(tree_add_branch(&t, 0, 0.5, ORIGIN_SKETCH, ok_with_nan, r, 3) >= 0);
	build(&tm, &t);
	check_counts(&tm.bark, 0, 0, (const double[]){ 0.1, 0.0005 }, 2);
	CHECK_INT(check_closed_surface(&tm.bark), 2);
	tree_mesh_finish(&tm);
	tree_finish(&t);
}

/* A child's root lies on its parent's axis: its first ring is inside the parent's tube. */
static void test_joint(void)
{
	const struct vec3 trunk[] = { { 0, 0, 0 }, { 0, 4, 0 } };
	const double tr[] = { 0.2, 0.2 };
	const struct vec3 child[] = { { 0, 2, 0 }, { 1, 3, 0 }, { 2, 3.5, 0 } };
	const double cr[] = { 0.08, 0.06, 0.03 };
	struct tree t;
	struct tree_mesh tm;
	uint32_t first;
	size_t s, first_index;

	tree_init(&t);
	tree_mesh_init(&tm);
	CHECK_INT(tree_add_branch(&t, -1, 0, ORIGIN_SKETCH, trunk, tr, 2), 0);
	build(&tm, &t);
	first = (uint32_t)tm.bark.nvertices;
	first_index = tm.bark.nindices;
	CHECK_INT(tree_add_branch(&t, 0, 0.5, ORIGIN_SKETCH, child, cr, 3), 1);
	build(&tm, &t);
	/* the child's vertices follow the trunk's, its root ring first (the trunk leaves it
	 * room: not shrunk); it bends 18 degrees, so its middle point keeps a ring */
	check_counts(&tm.bark, first, first_index, cr, 3);
	s = (size_t)mesh_ring_sides(cr[0]);
	for (uint32_t i = first; i < first + s; i++) {
		struct vec3 q = mesh_pos(&tm.bark, i);

		CHECK(hypot(q.x, q.z) < 0.2);
		CHECK(fabs(q.y - 2.0) < 0.2);
		CHECK_NEAR(vec3_dist(q, child[0]), cr[0], 1e-6);
	}
	tree_mesh_finish(&tm);
	tree_finish(&t);
}

/* A big synthetic tree: sane everywhere, light, and the same twice. */
static void test_synth(void)
{
	struct tree t;
	struct tree_mesh a, b;

	tree_init(&t);
	tree_mesh_init(&a);
	tree_mesh_init(&b);
	CHECK_INT(synth_tree(&t, 1000, 5, 7), 0);
	CHECK_INT(t.nbranches, 1000);
	CHECK_INT(t.nleaves, 5000);
	build(&a, &t);
	CHECK_INT(tree_mesh_build(&b, &t), 0);
	/* light: under 10 faces per branch point on average (test_mesh_detail: the budget) */
	{
		size_t points = 0;

		for (size_t i = 0; i < t.nbranches; i++)
			points += t.branches[i].npoints;
		CHECK(a.bark.nindices / 3 < 10 * points);
	}
	CHECK_INT(a.bark.nvertices, b.bark.nvertices);
	CHECK_INT(a.bark.nindices, b.bark.nindices);
	CHECK(!memcmp(a.bark.positions, b.bark.positions, a.bark.nvertices * 3 * sizeof(float)));
	CHECK(!memcmp(a.bark.normals, b.bark.normals, a.bark.nvertices * 3 * sizeof(float)));
	CHECK(!memcmp(a.bark.indices, b.bark.indices, a.bark.nindices * sizeof(uint32_t)));
	/* rebuilding into used meshes starts from scratch */
	CHECK_INT(tree_mesh_build(&b, &t), 0);
	CHECK_INT(a.bark.nindices, b.bark.nindices);
	tree_mesh_finish(&a);
	tree_mesh_finish(&b);
	tree_finish(&t);
}

int main(void)
{
	test_straight();
	test_sides_adapt();
	test_planar_frames();
	test_awkward();
	test_degenerate();
	test_joint();
	test_synth();
	return 0;
}
