/* SPDX-License-Identifier: MIT */
/*
 * Step 7 of growing wood (issue 17, docs/wood.md): the bark as the density's iso-surface
 * (wood_iso, marching tetrahedra) on fields made here: one voxel, balls of a few sizes, a
 * block, samples exactly at the iso value, two blobs, wood touching the grid's edge, a
 * random field. Every mesh closed (each undirected edge in two triangles, each directed
 * edge once: one orientation), a manifold (one fan about each vertex), no triangle
 * without area (above 1e-12 h^2), no two vertices in one place, every vertex used, unit
 * normals on the side of the faces about them; balls' normals outward and near radial,
 * their Euler characteristic 2, their volume within 5% of the wood (sum of density h^3)
 * from 4 voxels of radius up; a 3D checkerboard (no gradient anywhere inside); the mesh
 * bit for bit the same twice and when appended; allocation failures.
 */
#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fail_alloc.h"
#include "iso_check.h"
#include "iso_fields.h"
#include "mesh.h"
#include "test.h"
#include "wood.h"

static void iso_mesh(const struct wood_grid *g, struct mesh *m, struct iso_stats *st)
{
	mesh_init(m);
	CHECK_INT(wood_iso(g, 0.5, m), 0);
	check_mesh(m, 0, 0, g->h, st);
}

/* One voxel of density 1: the samples' star cut half-way along its 14 edges, 24
 * triangles, its volume exactly an eighth of the star's 4 h^3. In a grid of one voxel
 * (all padding about it) and in the middle of a larger one: the same mesh. */
static void test_one_voxel(void)
{
	const double h = 0.25;
	struct wood_grid g1, g3;
	struct mesh m1, m3;
	struct iso_stats st;

	iso_grid(&g1, 1, 1, 1, vec3(1, 2, 3), h);
	g1.density[0] = 1.0;
	iso_mesh(&g1, &m1, &st);
	CHECK_INT(st.vertices, 14);
	CHECK_INT(st.faces, 24);
	CHECK_INT(st.euler, 2);
	CHECK_INT(st.components, 1);
	CHECK_NEAR(st.volume, 0.5 * h * h * h, 1e-6 * h * h * h);
	CHECK_INT(st.normals_off, 0);
	for (size_t v = 0; v < m1.nvertices; v++)
		CHECK(vec3_dot(nrm(&m1, (uint32_t)v),
			       vec3_sub(pos(&m1, (uint32_t)v), iso_voxel_centre(&g1, 0, 0, 0))) > 0);

	iso_grid(&g3, 3, 3, 3, vec3(1 - h, 2 - h, 3 - h), h);
	g3.density[wood_index(&g3, 1, 1, 1)] = 1.0;
	iso_mesh(&g3, &m3, &st);
	CHECK_INT(m3.nvertices, m1.nvertices);
	CHECK_INT(m3.nindices, m1.nindices);
	for (size_t i = 0; i < 3 * m1.nvertices; i++)
		CHECK_NEAR(m3.positions[i], m1.positions[i], 1e-6);
	printf("one voxel: %zu vertices, %zu triangles, volume %.6f h^3\n", st.vertices, st.faces,
	       st.volume / (h * h * h));
	mesh_finish(&m1);
	mesh_finish(&m3);
	wood_grid_finish(&g1);
	wood_grid_finish(&g3);
}

/*
 * wood_iso_keep_volume on m, g's iso-surface: the volume the wood's within 0.5%, each
 * vertex moved along its own normal by at most a third of a voxel, the normals and
 * triangles as they were, the mesh still closed and oriented; a failed allocation leaves
 * it as it was.
 */
static void check_keep_volume(const struct wood_grid *g, struct mesh *m)
{
	size_t n = m->nvertices;
	float *before = malloc(3 * n * sizeof(*before)), *normals = malloc(3 * n * sizeof(*normals));
	uint32_t *idx = malloc(m->nindices * sizeof(*idx));
	double wood = iso_wood(g), worst = 0.0, err;
	struct iso_stats st;

	CHECK(before && normals && idx);
	memcpy(before, m->positions, 3 * n * sizeof(*before));
	memcpy(normals, m->normals, 3 * n * sizeof(*normals));
	memcpy(idx, m->indices, m->nindices * sizeof(*idx));
	if (FAIL_ALLOC_HOOK && fail_alloc_hooked()) {
		fail_alloc_at(0);
		CHECK_INT(wood_iso_keep_volume(m, 0, 0, wood, g->h), -ENOMEM);
		fail_alloc_off();
		CHECK(!memcmp(before, m->positions, 3 * n * sizeof(*before)));
	}
	CHECK_INT(wood_iso_keep_volume(m, 0, 0, wood, g->h), 0);
	CHECK(!memcmp(normals, m->normals, 3 * n * sizeof(*normals)));
	CHECK(!memcmp(idx, m->indices, m->nindices * sizeof(*idx)));
	for (size_t v = 0; v < n; v++) {
		struct vec3 d = vec3_sub(pos(m, (uint32_t)v), vec3(before[3 * v], before[3 * v + 1],
								       before[3 * v + 2]));
		double along = vec3_dot(d, nrm(m, (uint32_t)v));

		CHECK(vec3_len(vec3_sub(d, vec3_scale(nrm(m, (uint32_t)v), along))) < 1e-4 * g->h);
		worst = fmax(worst, fabs(along) / g->h);
	}
	check_mesh(m, 0, 0, g->h, &st);
	err = st.volume / wood - 1;
	printf("  kept to the wood: volume %+.3f%%, vertices moved up to %.3f voxels\n", 100 * err,
	       worst);
	CHECK(fabs(err) < 0.005);
	CHECK(worst <= 0.35 + 1e-6);
	free(before);
	free(normals);
	free(idx);
}

/* A ball of radius R voxels in a grid with room about it; its centre off the samples by
 * `off` voxels (0: samples exactly on its sphere, density exactly 0.5); its volume within
 * tol of the wood (the 5% from 4 voxels up; the surface's chords and the clamped
 * field take more from smaller balls, and the field itself is 1/4 (h/R)^2 above the
 * ball's volume). */
static void test_ball(double R, double off, double tol)
{
	const double h = 0.01;
	int n = (int)ceil(2 * R) + 4;
	struct wood_grid g;
	struct mesh m;
	struct iso_stats st;
	struct vec3 c;
	double wood, err, worst = 1.0, mean = 0.0;

	iso_grid(&g, n, n, n, vec3(-0.3, 0.1, 0.2), h);
	c = vec3_add(iso_voxel_centre(&g, n / 2, n / 2, n / 2), vec3(off * h, 0.7 * off * h,
								    0.3 * off * h));
	iso_ball(&g, c, R * h);
	iso_mesh(&g, &m, &st);
	CHECK_INT(st.euler, 2);
	CHECK_INT(st.components, 1);
	for (size_t v = 0; v < m.nvertices; v++) {
		struct vec3 d = vec3_sub(pos(&m, (uint32_t)v), c);
		double cosine = vec3_dot(nrm(&m, (uint32_t)v), d) / vec3_len(d);

		CHECK(cosine > 0.0);
		worst = cosine < worst ? cosine : worst;
		mean += acos(cosine > 1.0 ? 1.0 : cosine) / (double)m.nvertices;
	}
	wood = iso_wood(&g);
	err = (st.volume - wood) / wood;
	printf("ball R %4.1f h (centre off %.2f h): %6zu vertices %6zu triangles, volume %+.2f%% "
	       "of the wood (%+.2f%% of 4/3 pi R^3), smallest triangle %.2g h^2, normals "
	       "%.1f deg from radial (mean; worst %.1f), %zu of %zu corners' normals against "
	       "their triangle's\n",
	       R, off, st.vertices, st.faces, 100 * err,
	       100 * (st.volume / (4.0 / 3.0 * VEC_PI * pow(R * h, 3)) - 1), st.min_area,
	       mean * 180 / VEC_PI, acos(worst) * 180 / VEC_PI, st.corners_off, 3 * st.faces);
	CHECK_INT(st.normals_off, 0);
	CHECK(mean < 3.0 * VEC_PI / 180 && acos(worst) < 10.0 * VEC_PI / 180);
	CHECK(fabs(err) < tol);
	check_keep_volume(&g, &m);
	mesh_finish(&m);
	wood_grid_finish(&g);
}

/* A branch: a cylinder of radius r voxels across the grid's y (its ends flat, cut where
 * the wood stops), its axis off the samples; volume within tol of the wood. Thin ones
 * lose more than balls of their radius: 1.5 voxels, the thinnest branch step 2
 * voxelises, about 10%. */
static void test_branch(double r, double tol)
{
	const double h = 0.01;
	int n = (int)ceil(2 * r) + 6, len = 40;
	struct wood_grid g;
	struct mesh m;
	struct iso_stats st;
	double cx, cz, err;

	iso_grid(&g, n, len, n, vec3(0.2, -0.1, 0), h);
	cx = g.origin.x + (n / 2 + 0.21) * h;
	cz = g.origin.z + (n / 2 + 0.37) * h;
	for (int z = 0; z < n; z++)
		for (int y = 3; y < len - 3; y++)
			for (int x = 0; x < n; x++) {
				struct vec3 p = iso_voxel_centre(&g, x, y, z);

				g.density[wood_index(&g, x, y, z)] =
					iso_clamp01(0.5 + (r * h - hypot(p.x - cx, p.z - cz)) / h);
			}
	iso_mesh(&g, &m, &st);
	CHECK_INT(st.euler, 2);
	CHECK_INT(st.components, 1);
	CHECK_INT(st.normals_off, 0);
	err = st.volume / iso_wood(&g) - 1;
	printf("branch r %.1f h, %d voxels long: %zu triangles, volume %+.2f%% of the wood\n", r,
	       len - 6, st.faces, 100 * err);
	CHECK(fabs(err) < tol);
	check_keep_volume(&g, &m);
	mesh_finish(&m);
	wood_grid_finish(&g);
}

/* A block of voxels of density 1: sharp edges and corners. */
static void test_block(void)
{
	const double h = 0.02;
	struct wood_grid g;
	struct mesh m;
	struct iso_stats st;
	double wood, err;

	iso_grid(&g, 12, 11, 10, vec3(0, 0, 0), h);
	iso_block(&g, 2, 2, 2, 10, 9, 8, 1.0);
	iso_mesh(&g, &m, &st);
	CHECK_INT(st.euler, 2);
	CHECK_INT(st.components, 1);
	CHECK_INT(st.normals_off, 0);
	wood = iso_wood(&g);
	err = (st.volume - wood) / wood;
	CHECK(err < 0.0 && err > -0.15); /* its edges and corners cut off */
	printf("block 8 x 7 x 6 voxels: %zu vertices %zu triangles, volume %+.2f%% of the wood\n",
	       st.vertices, st.faces, 100 * err);
	mesh_finish(&m);
	wood_grid_finish(&g);
}

/* Samples exactly at 0.5: a block of 1 in a shell of 0.5, a grid all 0.5, a ball with
 * samples on its sphere (test_ball with no offset does that too). Inside, as >= 0.5; the
 * vertices kept off the samples, so no triangle collapses. */
static void test_exact(void)
{
	const double h = 0.05;
	struct wood_grid g;
	struct mesh m;
	struct iso_stats st;

	iso_grid(&g, 9, 9, 9, vec3(0, 0, 0), h);
	iso_block(&g, 2, 2, 2, 7, 7, 7, 0.5);
	iso_block(&g, 3, 3, 3, 6, 6, 6, 1.0);
	iso_mesh(&g, &m, &st);
	CHECK_INT(st.euler, 2);
	CHECK_INT(st.components, 1);
	printf("block in a shell of 0.5: %zu triangles, smallest %.2g h^2, volume %.3f h^3 "
	       "(5^3 voxels at 0.5 or more)\n", st.faces, st.min_area, st.volume / (h * h * h));
	mesh_finish(&m);
	wood_grid_finish(&g);

	iso_grid(&g, 4, 3, 5, vec3(0, 0, 0), h);
	iso_block(&g, 0, 0, 0, 4, 3, 5, 0.5);
	iso_mesh(&g, &m, &st);
	CHECK_INT(st.euler, 2);
	CHECK_INT(st.components, 1);
	CHECK_INT(st.normals_off, 0);
	mesh_finish(&m);
	wood_grid_finish(&g);
}

/* Two balls apart: two closed parts. */
static void test_two_blobs(void)
{
	const double h = 0.01;
	struct wood_grid g;
	struct mesh m;
	struct iso_stats st;

	iso_grid(&g, 30, 16, 16, vec3(0, 0, 0), h);
	iso_ball(&g, vec3(0.08, 0.08, 0.08), 0.05);
	iso_ball(&g, vec3(0.22, 0.081, 0.079), 0.045);
	iso_mesh(&g, &m, &st);
	CHECK_INT(st.components, 2);
	CHECK_INT(st.euler, 4);
	CHECK(fabs(st.volume / iso_wood(&g) - 1) < 0.05);
	mesh_finish(&m);
	wood_grid_finish(&g);
}

/* Wood up to the grid's sides: the padding closes it there. A ball cut by three sides
 * (its centre at a corner of the grid), and a grid full of wood. */
static void test_grid_edge(void)
{
	const double h = 0.01;
	struct wood_grid g;
	struct mesh m;
	struct iso_stats st;

	iso_grid(&g, 10, 10, 10, vec3(0, 0, 0), h);
	iso_ball(&g, vec3(0.001, 0.0, 0.002), 0.07);
	iso_mesh(&g, &m, &st);
	CHECK_INT(st.euler, 2);
	CHECK_INT(st.components, 1);
	CHECK_INT(st.normals_off, 0);
	mesh_finish(&m);
	wood_grid_finish(&g);

	iso_grid(&g, 5, 6, 7, vec3(0, 0, 0), h);
	iso_block(&g, 0, 0, 0, 5, 6, 7, 1.0);
	iso_mesh(&g, &m, &st);
	CHECK_INT(st.euler, 2);
	CHECK_INT(st.components, 1);
	CHECK_INT(st.normals_off, 0);
	mesh_finish(&m);
	wood_grid_finish(&g);
}

static uint64_t xorshift(uint64_t *s)
{
	*s ^= *s << 13;
	*s ^= *s >> 7;
	*s ^= *s << 17;
	return *s;
}

/* A random field of 0, 0.5 and 1 (many samples exactly at the iso value, every kind of
 * tetrahedron): still closed, oriented and a manifold, however many parts and handles. */
static void test_random(void)
{
	const double h = 0.03;
	struct wood_grid g;
	struct mesh m;
	struct iso_stats st;
	uint64_t seed = 0x9e3779b97f4a7c15u;

	iso_grid(&g, 14, 13, 12, vec3(-0.2, 0.0, 0.1), h);
	for (size_t i = 0; i < wood_cells(&g); i++)
		g.density[i] = 0.5 * (double)(xorshift(&seed) % 3);
	iso_mesh(&g, &m, &st);
	/* the gradient of noise says little: some faces against their corners' normals */
	printf("random 0 / 0.5 / 1: %zu triangles, %zu parts, Euler %ld, smallest %.2g h^2, %zu "
	       "faces against their corners' normals\n", st.faces, st.components, st.euler,
	       st.min_area, st.normals_off);
	mesh_finish(&m);
	wood_grid_finish(&g);
}

/* A 3D checkerboard of 0 and 1: every sample's opposite neighbours alike, so the
 * gradient vanishes inside (the faces' normals there), and every cube is ambiguous for
 * marching cubes (not for tetrahedra). */
static void test_checkerboard(void)
{
	const double h = 0.02;
	struct wood_grid g;
	struct mesh m;
	struct iso_stats st;

	iso_grid(&g, 7, 8, 6, vec3(0, 0, 0), h);
	for (int z = 0; z < g.nz; z++)
		for (int y = 0; y < g.ny; y++)
			for (int x = 0; x < g.nx; x++)
				g.density[wood_index(&g, x, y, z)] = (x + y + z) % 2;
	iso_mesh(&g, &m, &st);
	printf("checkerboard: %zu triangles, %zu parts, Euler %ld, smallest %.2g h^2\n",
	       st.faces, st.components, st.euler, st.min_area);
	mesh_finish(&m);
	wood_grid_finish(&g);
}

/* Twice the same mesh, bit for bit; appended after what out has, its indices moved by it. */
static void test_determinism_append(void)
{
	const double h = 0.01;
	struct wood_grid g, one;
	struct mesh a, b;
	struct iso_stats st;
	size_t v0, i0;

	iso_grid(&g, 16, 16, 16, vec3(0, 0, 0), h);
	iso_ball(&g, vec3(0.081, 0.079, 0.08), 0.055);
	mesh_init(&a);
	mesh_init(&b);
	CHECK_INT(wood_iso(&g, 0.5, &a), 0);
	CHECK_INT(wood_iso(&g, 0.5, &b), 0);
	CHECK(a.nvertices == b.nvertices && a.nindices == b.nindices);
	CHECK(!memcmp(a.positions, b.positions, 3 * a.nvertices * sizeof(float)));
	CHECK(!memcmp(a.normals, b.normals, 3 * a.nvertices * sizeof(float)));
	CHECK(!memcmp(a.indices, b.indices, a.nindices * sizeof(uint32_t)));

	/* b: one voxel's surface first, then the ball's */
	mesh_clear(&b);
	iso_grid(&one, 1, 1, 1, vec3(1, 1, 1), h);
	one.density[0] = 1.0;
	CHECK_INT(wood_iso(&one, 0.5, &b), 0);
	v0 = b.nvertices;
	i0 = b.nindices;
	CHECK_INT(wood_iso(&g, 0.5, &b), 0);
	CHECK_INT(b.nvertices - v0, a.nvertices);
	CHECK_INT(b.nindices - i0, a.nindices);
	CHECK(!memcmp(b.positions + 3 * v0, a.positions, 3 * a.nvertices * sizeof(float)));
	CHECK(!memcmp(b.normals + 3 * v0, a.normals, 3 * a.nvertices * sizeof(float)));
	for (size_t i = 0; i < a.nindices; i++)
		CHECK_INT(b.indices[i0 + i], a.indices[i] + v0);
	check_mesh(&b, v0, i0, h, &st);
	check_mesh(&b, 0, 0, h, &st);
	CHECK_INT(st.components, 2);
	mesh_finish(&a);
	mesh_finish(&b);
	wood_grid_finish(&g);
	wood_grid_finish(&one);
}

/* No wood, or an iso value that leaves every sample on one side: nothing appended. */
static void test_nothing(void)
{
	struct wood_grid g;
	struct mesh m;

	iso_grid(&g, 4, 4, 4, vec3(0, 0, 0), 0.1);
	mesh_init(&m);
	CHECK_INT(wood_iso(&g, 0.5, &m), 0);
	CHECK(m.nvertices == 0 && m.nindices == 0);
	iso_block(&g, 1, 1, 1, 3, 3, 3, 0.9);
	CHECK_INT(wood_iso(&g, 1.5, &m), 0);
	CHECK(m.nvertices == 0 && m.nindices == 0);
	/* at 0 the padding is inside too: no side to the wood */
	CHECK_INT(wood_iso(&g, 0.0, &m), 0);
	CHECK(m.nvertices == 0 && m.nindices == 0);
	mesh_finish(&m);
	wood_grid_finish(&g);
}

/* Any allocation failing: -ENOMEM, and out as it was (what it had kept). */
static void test_oom(void)
{
	struct wood_grid g;
	struct mesh m;

	if (!FAIL_ALLOC_HOOK || !fail_alloc_hooked())
		return;
	iso_grid(&g, 12, 12, 12, vec3(0, 0, 0), 0.01);
	iso_ball(&g, vec3(0.06, 0.06, 0.06), 0.045);
	for (long at = 0;; at++) {
		int r;

		mesh_init(&m);
		CHECK_INT(mesh_reserve(&m, 1, 3), 0);
		m.nvertices = 1;
		m.positions[0] = 7.0f;
		fail_alloc_at(at);
		r = wood_iso(&g, 0.5, &m);
		fail_alloc_off();
		if (fail_alloc_calls() <= at) {
			CHECK_INT(r, 0);
			mesh_finish(&m);
			printf("allocation failures: %ld places, each -ENOMEM with nothing appended\n",
			       at);
			break;
		}
		CHECK_INT(r, -ENOMEM);
		CHECK(m.nvertices == 1 && m.nindices == 0 && m.positions[0] == 7.0f);
		mesh_finish(&m);
	}
	wood_grid_finish(&g);
}

int main(void)
{
	test_one_voxel();
	test_ball(2.5, 0.37, 0.15);
	test_ball(4, 0, 0.05);
	test_ball(4, 0.29, 0.05);
	test_ball(8, 0.31, 0.05);
	test_ball(16, 0.13, 0.05);
	test_branch(1.5, 0.12);
	test_branch(3, 0.05);
	test_branch(6, 0.05);
	test_block();
	test_exact();
	test_two_blobs();
	test_grid_edge();
	test_random();
	test_checkerboard();
	test_determinism_append();
	test_nothing();
	test_oom();
	printf("ok\n");
	return 0;
}
