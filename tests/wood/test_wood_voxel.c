/* SPDX-License-Identifier: MIT */
/*
 * Growing wood, steps 2-3 (wood_voxel.c, docs/wood.md): the prisms (closed, outward, one
 * an internode of the thick branches only), the grid about them (padding, h, dims), and
 * the density field: a trunk's volume at 64 and 128, 0..1, full voxels exactly 1; a
 * fork's union not counted twice (against a fine lattice of points); rays exactly
 * through edges and corners (boxes and prisms on the rays' lattice, against what exact
 * geometry gives); the same input, the same bits.
 */
#include <errno.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fail_alloc.h"
#include "mesh.h"
#include "test.h"
#include "tree.h"
#include "wood.h"

#define R2 0.70710678118654752440

static struct vec3 fv(const float *p)
{
	return vec3(p[0], p[1], p[2]);
}

/* A branch of n points from a to b (straight), radius r everywhere. */
static int add_straight(struct tree *t, int parent, double pt, struct vec3 a, struct vec3 b,
			double r, size_t n)
{
	struct vec3 p[32];
	double radii[32];

	for (size_t i = 0; i < n; i++) {
		p[i] = vec3_lerp(a, b, (double)i / (double)(n - 1));
		radii[i] = r;
	}
	return tree_add_branch(t, parent, pt, ORIGIN_SKETCH, p, radii, n);
}

/* Signed volume of triangles [f0, f1) (divergence theorem): positive when outward. */
static double signed_volume(const struct mesh *m, size_t f0, size_t f1)
{
	double v = 0.0;

	for (size_t f = f0; f < f1; f++) {
		const uint32_t *ix = m->indices + 3 * f;
		struct vec3 a = fv(m->positions + 3 * ix[0]), b = fv(m->positions + 3 * ix[1]);
		struct vec3 c = fv(m->positions + 3 * ix[2]);

		v += vec3_dot(a, vec3_cross(b, c)) / 6.0;
	}
	return v;
}

/* Every normal unit and on the side the triangle's winding says (counter-clockwise seen
 * from outside). */
static void check_normals(const struct mesh *m)
{
	for (size_t f = 0; f < m->nindices / 3; f++) {
		const uint32_t *ix = m->indices + 3 * f;
		struct vec3 a = fv(m->positions + 3 * ix[0]), b = fv(m->positions + 3 * ix[1]);
		struct vec3 c = fv(m->positions + 3 * ix[2]);
		struct vec3 g = vec3_cross(vec3_sub(b, a), vec3_sub(c, a));

		for (int k = 0; k < 3; k++) {
			struct vec3 n = fv(m->normals + 3 * ix[k]);

			CHECK_NEAR(vec3_len(n), 1.0, 1e-6);
			if (vec3_len(g) > 1e-9)
				CHECK(vec3_dot(n, g) > 0.0);
		}
	}
}

static double field_sum(const struct wood_grid *g)
{
	double s = 0.0;

	for (size_t i = 0; i < wood_cells(g); i++)
		s += g->density[i];
	return s;
}

static void check_range(const struct wood_grid *g)
{
	for (size_t i = 0; i < wood_cells(g); i++)
		CHECK(g->density[i] >= 0.0 && g->density[i] <= 1.0);
}

/* The voxel holding world point p. */
static size_t voxel_at(const struct wood_grid *g, struct vec3 p)
{
	int x = (int)floor((p.x - g->origin.x) / g->h), y = (int)floor((p.y - g->origin.y) / g->h);
	int z = (int)floor((p.z - g->origin.z) / g->h);

	CHECK(x >= 0 && x < g->nx && y >= 0 && y < g->ny && z >= 0 && z < g->nz);
	return wood_index(g, x, y, z);
}

/* prisms + grid + field of t at `cells`. */
static void voxelise_tree(const struct tree *t, int cells, struct mesh *m, bool *vox,
			  struct wood_grid *g)
{
	mesh_init(m);
	CHECK_INT(wood_prisms(t, cells, m, vox), 0);
	CHECK_INT(wood_grid_for(m, cells, g), 0);
	CHECK_INT(wood_voxelise(g, m), 0);
}

/* A vertical trunk 2 m tall, r = 0.15: its octagonal prism's volume 2 sqrt 2 r^2 L. */
static void test_trunk(int cells)
{
	const double r = 0.15, L = 2.0, exact = 2.0 * sqrt(2.0) * r * r * L;
	struct tree t;
	struct mesh m;
	struct wood_grid g;
	bool vox[1];
	double vol, err;

	tree_init(&t);
	CHECK(add_straight(&t, -1, 0.0, vec3(0, 0, 0), vec3(0, L, 0), r, 5) >= 0);
	voxelise_tree(&t, cells, &m, vox, &g);
	CHECK(vox[0]);
	CHECK_INT(m.nindices, 4 * 28 * 3); /* four internodes, 28 triangles each */
	CHECK_NEAR(signed_volume(&m, 0, m.nindices / 3), exact, 1e-6 * exact);
	check_normals(&m);
	/* the grid: 1.3 L along y, cells of it */
	CHECK_NEAR(g.h, 1.3 * L / cells, 1e-12);
	CHECK_INT(g.ny, cells);
	check_range(&g);
	vol = field_sum(&g) * g.h * g.h * g.h;
	err = (vol - exact) / exact;
	printf("trunk at %d: r = %.2f voxels, volume %.6f, exact %.6f, error %+.3f%%\n", cells,
	       r / g.h, vol, exact, 100.0 * err);
	CHECK(fabs(err) < (cells >= 128 ? 0.01 : 0.02));
	/* on the axis, full; the grid's corners, empty */
	CHECK(g.density[voxel_at(&g, vec3(0, 1.0, 0))] == 1.0);
	CHECK(g.density[wood_index(&g, 0, 0, 0)] == 0.0);
	CHECK(g.density[wood_index(&g, g.nx - 1, g.ny - 1, g.nz - 1)] == 0.0);
	wood_grid_finish(&g);
	mesh_finish(&m);
	tree_finish(&t);
}

/* A box [x0, x1] x [y0, y1] x [z0, z1] (12 triangles, outward): the top's diagonal from
 * (x0, y0) to (x1, y1), the bottom's the other one, so both rules of a tie are used. */
static void add_box(struct mesh *m, double x0, double x1, double y0, double y1, double z0,
		    double z1)
{
	static const uint32_t tri[12][3] = {
		{ 4, 5, 6 }, { 4, 6, 7 },     /* top z1: 4 (x0 y0) 5 (x1 y0) 6 (x1 y1) 7 (x0 y1) */
		{ 0, 3, 1 }, { 1, 3, 2 },     /* bottom z0, diagonal 1-3 */
		{ 0, 1, 5 }, { 0, 5, 4 },     /* y0 */
		{ 2, 3, 7 }, { 2, 7, 6 },     /* y1 */
		{ 1, 2, 6 }, { 1, 6, 5 },     /* x1 */
		{ 3, 0, 4 }, { 3, 4, 7 },     /* x0 */
	};
	const double c[8][3] = { { x0, y0, z0 }, { x1, y0, z0 }, { x1, y1, z0 }, { x0, y1, z0 },
				 { x0, y0, z1 }, { x1, y0, z1 }, { x1, y1, z1 }, { x0, y1, z1 } };
	uint32_t base = (uint32_t)m->nvertices;

	CHECK_INT(mesh_reserve(m, 8, 36), 0);
	for (int i = 0; i < 8; i++) {
		for (int a = 0; a < 3; a++) {
			m->positions[3 * m->nvertices + (size_t)a] = (float)c[i][a];
			m->normals[3 * m->nvertices + (size_t)a] = 0.0f;
		}
		m->nvertices++;
	}
	for (int f = 0; f < 12; f++)
		for (int k = 0; k < 3; k++)
			m->indices[m->nindices++] = base + tri[f][k];
}

/* What exact geometry gives: ray (x, y) inside over one z interval (world), or none. */
typedef bool (*chord_fn)(double x, double y, double *z0, double *z1);

/* The rays: a voxel's centre and (+-1/4, +-1/4) of a voxel about it (docs/wood.md). */
static const double ray_off[5][2] = { { 0.5, 0.5 }, { 0.25, 0.25 }, { 0.75, 0.25 },
				      { 0.25, 0.75 }, { 0.75, 0.75 } };

/* The field must be, voxel by voxel, what those chords give. */
static void check_against(const struct wood_grid *g, chord_fn chord, double eps)
{
	for (int y = 0; y < g->ny; y++)
		for (int x = 0; x < g->nx; x++)
			for (int z = 0; z < g->nz; z++) {
				double want = 0.0;

				for (int r = 0; r < 5; r++) {
					double px = g->origin.x + (x + ray_off[r][0]) * g->h;
					double py = g->origin.y + (y + ray_off[r][1]) * g->h;
					double z0, z1, lo = g->origin.z + z * g->h;

					if (!chord(px, py, &z0, &z1))
						continue;
					z0 = fmax(z0, lo);
					z1 = fmin(z1, lo + g->h);
					if (z1 > z0)
						want += (z1 - z0) / g->h / 5.0;
				}
				CHECK_NEAR(g->density[wood_index(g, x, y, z)], want, eps);
			}
}

/* The box of test_box_edges; a ray on its low sides is in, on its high sides out (the
 * perturbation (+e, +e^2) of docs/wood.md). */
static bool box_chord(double x, double y, double *z0, double *z1)
{
	*z0 = 0.25;
	*z1 = 1.625;
	return x >= 0.75 && x < 2.75 && y >= 0.75 && y < 2.75;
}

/*
 * A box whose sides, corners and top and bottom diagonals fall exactly on rays (unit
 * voxels, rays at quarters): each ray must be counted once, in or out, as the exact box
 * says. The same box twice over (winding 2 inside), and cut in two along a plane of rays
 * (two solids touching), must give the same field bit for bit.
 */
static void test_box_edges(void)
{
	struct wood_grid g, g2;
	struct mesh m;

	CHECK_INT(wood_grid_create(&g, 4, 4, 2, vec3(0, 0, 0), 1.0), 0);
	mesh_init(&m);
	add_box(&m, 0.75, 2.75, 0.75, 2.75, 0.25, 1.625);
	CHECK_INT(wood_voxelise(&g, &m), 0);
	check_against(&g, box_chord, 1e-12);
	CHECK(g.density[wood_index(&g, 1, 1, 0)] == 0.75);

	/* twice over */
	add_box(&m, 0.75, 2.75, 0.75, 2.75, 0.25, 1.625);
	CHECK_INT(wood_grid_create(&g2, 4, 4, 2, vec3(0, 0, 0), 1.0), 0);
	CHECK_INT(wood_voxelise(&g2, &m), 0);
	CHECK(memcmp(g.density, g2.density, wood_cells(&g) * sizeof(double)) == 0);
	wood_grid_finish(&g2);

	/* cut at x = 1.75 (a column of rays on the cut) and at y = 1.25 */
	mesh_clear(&m);
	add_box(&m, 0.75, 1.75, 0.75, 1.25, 0.25, 1.625);
	add_box(&m, 1.75, 2.75, 0.75, 1.25, 0.25, 1.625);
	add_box(&m, 0.75, 1.75, 1.25, 2.75, 0.25, 1.625);
	add_box(&m, 1.75, 2.75, 1.25, 2.75, 0.25, 1.625);
	CHECK_INT(wood_grid_create(&g2, 4, 4, 2, vec3(0, 0, 0), 1.0), 0);
	CHECK_INT(wood_voxelise(&g2, &m), 0);
	for (size_t i = 0; i < wood_cells(&g); i++)
		CHECK_NEAR(g2.density[i], g.density[i], 1e-15);
	wood_grid_finish(&g2);
	wood_grid_finish(&g);
	mesh_finish(&m);
}

/* The octagon of a prism along y of radius 0.5 at x = z = 0 (corners on x and z, as
 * wood_prisms puts them on a vertical trunk): the half-chord along z at x. */
static double octagon_half(double x, double r)
{
	double a = fabs(x), c = R2;

	if (a >= r)
		return 0.0;
	if (a <= r * c)
		return r - a * (1.0 - c) / c;
	return r * c * (r - a) / (r - r * c);
}

static bool y_trunk_chord(double x, double y, double *z0, double *z1)
{
	double h = octagon_half(x, 0.5);

	*z0 = -h;
	*z1 = h;
	return h > 0.0 && y >= 0.0 && y < 2.0;
}

/* The octagon about the z axis, corners at angles k 45 degrees from +x (a prism along z):
 * inside at (x, y) moved by (+e, +e^2), as the rays decide. */
static bool z_trunk_chord(double x, double y, double *z0, double *z1)
{
	const double r = 0.5;
	double px = x + 1e-7, py = y + 1e-11;

	*z0 = -0.75;
	*z1 = 0.75;
	for (int k = 0; k < 8; k++) {
		double a0 = k * VEC_PI / 4, a1 = (k + 1) * VEC_PI / 4;
		double ax = r * cos(a0), ay = r * sin(a0), bx = r * cos(a1), by = r * sin(a1);

		if ((bx - ax) * (py - ay) - (by - ay) * (px - ax) <= 0.0)
			return false;
	}
	return true;
}

/*
 * Prisms from wood_prisms on a grid made so that rays pass exactly through their corners
 * and edges: a trunk along y (rays along its vertical edges at x = 0 and tangent to it at
 * x = +-0.5, rays in its caps' planes at y = 0, 1, 2) and one along z (rays through the
 * caps' corners and the fans' diagonals).
 */
static void test_vertex_rays(void)
{
	struct tree t;
	struct mesh m;
	struct wood_grid g;
	bool vox[1];

	tree_init(&t);
	CHECK(add_straight(&t, -1, 0.0, vec3(0, 0, 0), vec3(0, 2, 0), 0.5, 3) >= 0);
	mesh_init(&m);
	CHECK_INT(wood_prisms(&t, 64, &m, vox), 0);
	CHECK(vox[0]);
	/* x = 0 is the centre ray of column 4, x = 0.5 of column 6, y = 0 and 2 of rows 0, 8 */
	CHECK_INT(wood_grid_create(&g, 9, 9, 8, vec3(-1.125, -0.125, -1.0), 0.25), 0);
	CHECK_INT(wood_voxelise(&g, &m), 0);
	check_against(&g, y_trunk_chord, 1e-6);
	check_range(&g);
	wood_grid_finish(&g);

	tree_clear(&t);
	mesh_clear(&m);
	CHECK(add_straight(&t, -1, 0.0, vec3(0, 0, -0.75), vec3(0, 0, 0.75), 0.5, 3) >= 0);
	CHECK_INT(wood_prisms(&t, 64, &m, vox), 0);
	CHECK(vox[0]);
	/* rays at multiples of 1/16 m from -0.5 to 0.5 in x and y */
	CHECK_INT(wood_grid_create(&g, 9, 9, 8, vec3(-1.125, -1.125, -1.0), 0.25), 0);
	CHECK_INT(wood_voxelise(&g, &m), 0);
	check_against(&g, z_trunk_chord, 1e-6);
	wood_grid_finish(&g);
	mesh_finish(&m);
	tree_finish(&t);
}

/* Inside prism `p` (triangles 28 p .. 28 p + 27 of m, a convex one): behind every face. */
static bool in_prism(const struct mesh *m, size_t p, struct vec3 q)
{
	for (size_t f = 28 * p; f < 28 * (p + 1); f++) {
		const uint32_t *ix = m->indices + 3 * f;
		struct vec3 a = fv(m->positions + 3 * ix[0]), b = fv(m->positions + 3 * ix[1]);
		struct vec3 c = fv(m->positions + 3 * ix[2]);

		if (vec3_dot(vec3_sub(q, a), vec3_cross(vec3_sub(b, a), vec3_sub(c, a))) > 0.0)
			return false;
	}
	return true;
}

/* The union of m's convex prisms by the midpoints of a lattice of n^3 cells over box. */
static double union_volume(const struct mesh *m, size_t nprisms, struct vec3 lo, struct vec3 hi,
			   int n)
{
	struct vec3 d = vec3_scale(vec3_sub(hi, lo), 1.0 / n);
	long in = 0;

	for (int k = 0; k < n; k++)
		for (int j = 0; j < n; j++)
			for (int i = 0; i < n; i++) {
				struct vec3 q = vec3(lo.x + (i + 0.5) * d.x, lo.y + (j + 0.5) * d.y,
						     lo.z + (k + 0.5) * d.z);

				for (size_t p = 0; p < nprisms; p++)
					if (in_prism(m, p, q)) {
						in++;
						break;
					}
			}
	return (double)in * d.x * d.y * d.z;
}

/* A Y fork: a trunk and two children from its top, overlapping it there; the trunk goes
 * on past its top by half its radius (the children start at its tip): 4 prisms. */
static void fork_tree(struct tree *t)
{
	tree_init(t);
	CHECK(add_straight(t, -1, 0.0, vec3(0, 0, 0), vec3(0, 1, 0), 0.1, 2) >= 0);
	CHECK(add_straight(t, 0, 1.0, vec3(0, 1, 0), vec3(-0.5, 1.6, 0.1), 0.08, 2) >= 0);
	CHECK(add_straight(t, 0, 1.0, vec3(0, 1, 0), vec3(0.45, 1.55, -0.1), 0.08, 2) >= 0);
}

static void test_fork(int cells, double want)
{
	struct tree t;
	struct mesh m;
	struct wood_grid g, g2;
	bool vox[3];
	double sum = 0.0, vol, err;

	fork_tree(&t);
	voxelise_tree(&t, cells, &m, vox, &g);
	CHECK(vox[0] && vox[1] && vox[2]);
	CHECK_INT(m.nindices, 4 * 28 * 3);
	/* the trunk's two prisms (48 vertices each) reach 0.05 past its top */
	{
		double top = 0.0;

		for (size_t v = 0; v < 2 * 48; v++)
			top = fmax(top, m.positions[3 * v + 1]);
		CHECK_NEAR(top, 1.05, 1e-6);
	}
	for (size_t p = 0; p < 4; p++)
		sum += signed_volume(&m, 28 * p, 28 * (p + 1));
	check_range(&g);
	vol = field_sum(&g) * g.h * g.h * g.h;
	err = (vol - want) / want;
	printf("fork at %d: union %.6f, lattice %.6f (%+.3f%%), the prisms' sum %.6f\n", cells, vol,
	       want, 100.0 * err, sum);
	CHECK(fabs(err) < (cells >= 128 ? 0.01 : 0.02));
	CHECK(vol < sum - 0.5 * (sum - want));
	/* where all three overlap, one full voxel, not more */
	CHECK(g.density[voxel_at(&g, vec3(0, 0.99, 0))] == 1.0);

	/* the same input, the same bits */
	CHECK_INT(wood_grid_for(&m, cells, &g2), 0);
	CHECK_INT(wood_voxelise(&g2, &m), 0);
	CHECK(memcmp(g.density, g2.density, wood_cells(&g) * sizeof(double)) == 0);
	wood_grid_finish(&g2);
	wood_grid_finish(&g);
	mesh_finish(&m);
	tree_finish(&t);
}

/* The box about a mesh, padded by 15% of its longest side; dims ceil(extent / h); the grid
 * centred on the box in x and z. */
static void test_grid_for(void)
{
	struct mesh m;
	struct wood_grid g;

	mesh_init(&m);
	CHECK_INT(wood_grid_for(&m, 64, &g), -EINVAL);
	add_box(&m, 0.0, 2.0, 0.0, 1.0, 0.0, 0.5);
	CHECK_INT(wood_grid_for(&m, 0, &g), -EINVAL);
	CHECK_INT(wood_grid_for(&m, 1025, &g), -EINVAL);
	CHECK_INT(wood_grid_for(&m, 64, &g), 0);
	CHECK_NEAR(g.h, 2.6 / 64, 1e-15);
	CHECK_INT(g.nx, 64);
	CHECK_INT(g.ny, 40); /* ceil(1.6 / (2.6 / 64)) = ceil(39.4) */
	CHECK_INT(g.nz, 28); /* ceil(1.1 / (2.6 / 64)) = ceil(27.1) */
	/* centred across (x: exactly the padded box; z: 28 cells about its middle 0.25),
	 * from the pad below upward */
	CHECK_NEAR(g.origin.x, -0.3, 1e-15);
	CHECK_NEAR(g.origin.y, -0.3, 1e-15);
	CHECK_NEAR(g.origin.z, 0.25 - 14 * 2.6 / 64, 1e-15);
	for (size_t i = 0; i < wood_cells(&g); i++)
		CHECK(g.density[i] == 0.0 && g.flags[i] == 0);
	wood_grid_finish(&g);
	CHECK_INT(wood_grid_for(&m, 128, &g), 0);
	CHECK_INT(g.nx, 128);
	CHECK_INT(g.ny, 79); /* ceil(78.8) */
	wood_grid_finish(&g);
	mesh_finish(&m);
}

/*
 * Thin twigs are left out, thick branches in; every branch in is at least 1.5 voxels at
 * its root in the grid made of the prisms; a branch that is thick enough only in a grid
 * made without it is left out.
 */
static void test_thin(void)
{
	struct tree t;
	struct mesh m;
	struct wood_grid g;
	bool vox[3];

	tree_init(&t);
	CHECK(add_straight(&t, -1, 0.0, vec3(0, 0, 0), vec3(0, 2, 0), 0.15, 4) >= 0);
	CHECK(add_straight(&t, 0, 0.5, vec3(0, 1, 0), vec3(0.8, 1.6, 0), 0.1, 3) >= 0);
	CHECK(add_straight(&t, 1, 0.5, vec3(0.4, 1.3, 0), vec3(0.6, 1.8, 0.2), 0.01, 3) >= 0);
	for (int cells = 64; cells <= 128; cells *= 2) {
		voxelise_tree(&t, cells, &m, vox, &g);
		CHECK(vox[0] && vox[1] && !vox[2]);
		CHECK_INT(m.nindices, (3 + 2) * 28 * 3);
		CHECK(0.1 >= WOOD_PRISM_MIN_VOXELS * g.h);
		wood_grid_finish(&g);
		mesh_finish(&m);
	}

	/* A trunk 1 m, r 0.1 (h = 1.3 / 64 alone: 1.5 h = 0.03), and a branch of r 0.04 3 m
	 * long: in the trunk's grid it would be thick enough, in its own (h = 4.03 / 64) not. */
	tree_clear(&t);
	CHECK(add_straight(&t, -1, 0.0, vec3(0, 0, 0), vec3(0, 1, 0), 0.1, 2) >= 0);
	CHECK(add_straight(&t, 0, 0.5, vec3(0, 0.5, 0), vec3(3, 0.5, 0), 0.04, 2) >= 0);
	voxelise_tree(&t, 64, &m, vox, &g);
	CHECK(vox[0] && !vox[1]);
	CHECK_NEAR(g.h, 1.3 / 64, 1e-9);
	wood_grid_finish(&g);
	mesh_finish(&m);

	/* nothing thick enough: an empty mesh, and no grid */
	mesh_init(&m);
	CHECK_INT(wood_prisms(&t, 0, &m, vox), -EINVAL);
	tree_clear(&t);
	CHECK_INT(wood_prisms(&t, 64, &m, vox), 0);
	CHECK_INT(m.nindices, 0);
	CHECK_INT(wood_grid_for(&m, 64, &g), -EINVAL);
	mesh_finish(&m);
	tree_finish(&t);
}

/* A curved, leaning branch: its prisms meet (rotation-minimising rings, shared between
 * neighbours), so the field's volume is their volumes' sum (they barely overlap). */
static void test_curved(void)
{
	struct tree t;
	struct mesh m;
	struct wood_grid g;
	struct vec3 p[12];
	double radii[12], sum, vol;
	bool vox[1];

	tree_init(&t);
	for (int i = 0; i < 12; i++) {
		double s = i / 11.0;

		p[i] = vec3(0.6 * sin(1.5 * s), 2.0 * s, 0.4 * (1.0 - cos(1.2 * s)));
		radii[i] = 0.12 * (1.0 - 0.4 * s);
	}
	CHECK(tree_add_branch(&t, -1, 0.0, ORIGIN_SKETCH, p, radii, 12) >= 0);
	voxelise_tree(&t, 128, &m, vox, &g);
	check_normals(&m);
	sum = signed_volume(&m, 0, m.nindices / 3);
	vol = field_sum(&g) * g.h * g.h * g.h;
	printf("curved at 128: field %.6f, prisms %.6f (%+.3f%%)\n", vol, sum,
	       100.0 * (vol - sum) / sum);
	CHECK(sum > 0.0);
	CHECK(fabs(vol - sum) < 0.01 * sum);
	/* each prism on its own closed and outward */
	for (size_t i = 0; i < 11; i++)
		CHECK(signed_volume(&m, 28 * i, 28 * (i + 1)) > 0.0);
	wood_grid_finish(&g);
	mesh_finish(&m);
	tree_finish(&t);
}

/*
 * A branch leaning towards the rays, in many internodes: the rays cross the caps the
 * prisms share. Every voxel wholly inside is 1 exactly (not two stretches that round
 * short), which the thickening's "surface layer" (density below 1) relies on.
 */
static void test_shared_caps(void)
{
	const double r = 0.3;
	struct vec3 a = vec3(0.1, 0.2, -0.8), b = vec3(0.3, 0.5, 0.9);
	struct vec3 d = vec3_norm_or(vec3_sub(b, a), vec3(0, 0, 1));
	double len = vec3_dist(a, b), inner = r * cos(VEC_PI / 8);
	struct tree t;
	struct mesh m;
	struct wood_grid g;
	bool vox[1];
	size_t full = 0;

	tree_init(&t);
	CHECK(add_straight(&t, -1, 0.0, a, b, r, 17) >= 0);
	for (int cells = 64; cells <= 128; cells *= 2) {
		full = 0;
		voxelise_tree(&t, cells, &m, vox, &g);
		for (int z = 0; z < g.nz; z++)
			for (int y = 0; y < g.ny; y++)
				for (int x = 0; x < g.nx; x++) {
					bool inside = true;

					for (int c = 0; c < 8 && inside; c++) {
						struct vec3 q = vec3_sub(
							vec3(g.origin.x + (x + (c & 1)) * g.h,
							     g.origin.y + (y + (c >> 1 & 1)) * g.h,
							     g.origin.z + (z + (c >> 2)) * g.h), a);
						double s = vec3_dot(q, d);
						double off = vec3_len(vec3_sub(q, vec3_scale(d, s)));

						inside = s > 1e-9 && s < len - 1e-9 && off < inner - 1e-9;
					}
					if (inside) {
						CHECK(g.density[wood_index(&g, x, y, z)] == 1.0);
						full++;
					}
				}
		CHECK(full > 100);
		wood_grid_finish(&g);
		mesh_finish(&m);
	}
	tree_finish(&t);
}

static void test_errors(void)
{
	struct wood_grid g;
	struct mesh m;

	CHECK_INT(wood_grid_create(&g, 4, 4, 4, vec3(0, 0, 0), 1.0), 0);
	mesh_init(&m);
	CHECK_INT(wood_voxelise(&g, &m), 0);
	CHECK(field_sum(&g) == 0.0);
	add_box(&m, 0.5, 1.5, 0.5, 1.5, 0.5, 1.5);
	m.indices[4] = 99;
	CHECK_INT(wood_voxelise(&g, &m), -EINVAL);
	mesh_finish(&m);
	wood_grid_finish(&g);
}

#if FAIL_ALLOC_HOOK
/* Every allocation failing in turn: -ENOMEM, the mesh and flags as they were, no leak. */
static void test_oom(void)
{
	struct tree t;
	struct mesh m;
	struct wood_grid g;

	if (!fail_alloc_hooked())
		return;
	fork_tree(&t);
	for (long n = 0;; n++) {
		long before = fail_alloc_live();
		bool vox[3] = { false, true, false };
		int r;

		mesh_init(&m);
		fail_alloc_at(n);
		r = wood_prisms(&t, 64, &m, vox);
		fail_alloc_off();
		if (r < 0) {
			CHECK_INT(r, -ENOMEM);
			CHECK_INT(m.nvertices + m.nindices, 0);
			CHECK(!vox[0] && vox[1] && !vox[2]);
		}
		mesh_finish(&m);
		CHECK_INT(fail_alloc_live(), before);
		if (fail_alloc_calls() <= n) {
			CHECK_INT(r, 0);
			break;
		}
	}
	mesh_init(&m);
	CHECK_INT(wood_prisms(&t, 64, &m, NULL), 0);
	for (long n = 0;; n++) {
		long before = fail_alloc_live();
		int r, v = -1;

		fail_alloc_at(n);
		r = wood_grid_for(&m, 64, &g);
		if (r == 0)
			v = wood_voxelise(&g, &m);
		fail_alloc_off();
		CHECK(r == 0 || r == -ENOMEM);
		CHECK(v == -1 || v == 0 || v == -ENOMEM);
		if (r == 0)
			wood_grid_finish(&g);
		CHECK_INT(fail_alloc_live(), before);
		if (fail_alloc_calls() <= n) {
			CHECK_INT(r, 0);
			CHECK_INT(v, 0);
			break;
		}
	}
	mesh_finish(&m);
	tree_finish(&t);
}
#else
static void test_oom(void)
{
}
#endif

int main(void)
{
	struct tree t;
	struct mesh m;
	double want;

	test_grid_for();
	test_box_edges();
	test_vertex_rays();
	test_trunk(64);
	test_trunk(128);
	test_thin();
	test_curved();
	test_shared_caps();
	test_errors();
	test_oom();

	/* the fork's union by the midpoints of 200^3 cells over its prisms' box */
	fork_tree(&t);
	mesh_init(&m);
	CHECK_INT(wood_prisms(&t, 64, &m, NULL), 0);
	want = union_volume(&m, 4, vec3(-0.6, -0.01, -0.2), vec3(0.55, 1.7, 0.2), 200);
	mesh_finish(&m);
	tree_finish(&t);
	test_fork(64, want);
	test_fork(128, want);
	return 0;
}
