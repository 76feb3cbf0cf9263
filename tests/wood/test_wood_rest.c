/* SPDX-License-Identifier: MIT */
/*
 * Growing wood, steps 4-5 (issue 17, docs/wood.md): the springs of voxel fields made here
 * and their rest state. A column on the ground (equilibrium, compression growing
 * downwards, tension only across), a cantilever (stretched above, compressed below near
 * the post), the paper's time stepping run to rest against the direct solve (within 1%),
 * what is fixed and what is dropped, no load, determinism, mirror symmetry, wind, a
 * porous field, what is refused, allocation failures.
 */
#include <errno.h>
#include <stdint.h>
#include <string.h>

#include "fail_alloc.h"
#include "test.h"
#include "wood.h"

/* A grid of unit voxels from the origin: the ground at y = 0, so layer 0 is fixed. */
static void grid(struct wood_grid *g, int nx, int ny, int nz)
{
	CHECK_INT(wood_grid_create(g, nx, ny, nz, vec3(0, 0, 0), 1.0), 0);
}

/* Density d in the box [x0, x1] x [y0, y1] x [z0, z1] (inclusive). */
static void box(struct wood_grid *g, int x0, int x1, int y0, int y1, int z0, int z1, double d)
{
	for (int z = z0; z <= z1; z++)
		for (int y = y0; y <= y1; y++)
			for (int x = x0; x <= x1; x++)
				g->density[wood_index(g, x, y, z)] = d;
}

static struct wood_params gravity(double g)
{
	struct wood_params p;

	memset(&p, 0, sizeof(p));
	p.gravity = g;
	return p;
}

static const int DIRS = 26;

static void dir(int d, int e[3])
{
	int k = d < 13 ? d : d + 1;

	e[0] = k % 3 - 1;
	e[1] = k / 3 % 3 - 1;
	e[2] = k / 9 - 1;
}

/* The linear spring force (positive stretched) from (x, y, z) in direction d, or 0 when
 * either end is no kept mass point; *has says whether it is a spring. */
static double spring(const struct wood_grid *g, int x, int y, int z, int d, int *has)
{
	int e[3], a, b, c;
	const double *u, *v;
	double s = 0.0, l2;

	dir(d, e);
	a = x + e[0];
	b = y + e[1];
	c = z + e[2];
	*has = 0;
	if (a < 0 || b < 0 || c < 0 || a >= g->nx || b >= g->ny || c >= g->nz ||
	    !(g->flags[wood_index(g, x, y, z)] & WOOD_MASS) ||
	    !(g->flags[wood_index(g, a, b, c)] & WOOD_MASS))
		return 0.0;
	*has = 1;
	u = g->displacement + 3 * wood_index(g, x, y, z);
	v = g->displacement + 3 * wood_index(g, a, b, c);
	l2 = e[0] * e[0] + e[1] * e[1] + e[2] * e[2];
	for (int k = 0; k < 3; k++)
		s += e[k] * (v[k] - u[k]);
	return s / sqrt(l2);
}

/* The net force on a point from its linear springs and the load. */
static void net_force(const struct wood_grid *g, const struct wood_params *p, int x, int y,
		      int z, double f[3])
{
	f[0] = p->wind[0];
	f[1] = -p->gravity;
	f[2] = p->wind[2];
	for (int d = 0; d < DIRS; d++) {
		int e[3], has;
		double s = spring(g, x, y, z, d, &has), l;

		if (!has)
			continue;
		dir(d, e);
		l = sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
		for (int k = 0; k < 3; k++)
			f[k] += s * e[k] / l;
	}
}

static double max_field(const struct wood_grid *g, const double *v)
{
	double m = 0.0;

	for (size_t i = 0; i < wood_cells(g); i++)
		m = fmax(m, fabs(v[i]));
	return m;
}

/* Sums of a field over a layer y. */
static double layer(const struct wood_grid *g, const double *v, int y)
{
	double s = 0.0;

	for (int z = 0; z < g->nz; z++)
		for (int x = 0; x < g->nx; x++)
			s += v[wood_index(g, x, y, z)];
	return s;
}

/* A column 3 x 3 x 12 on the ground under gravity. */
static void test_column(void)
{
	struct wood_grid g;
	struct wood_params p = gravity(1e-3);
	struct wood_solve_stats st;
	double worst = 0.0, across = 0.0, cmax;

	grid(&g, 5, 13, 5);
	box(&g, 1, 3, 0, 11, 1, 3, 1.0);
	CHECK_INT(wood_rest(&g, &p, 0.0, &st), 0);
	CHECK_INT(st.points, 108);
	CHECK_INT(st.fixed, 9);
	CHECK_INT(st.dropped, 0);
	CHECK(st.residual <= 1e-6);
	CHECK(st.iterations > 0);
	/* 12 layers of springs: 9 points, 8 x (3 + 2 + 2) + 4 x ... counted by hand below */
	{
		size_t n = 0;

		for (int y = 0; y <= 11; y++)
			for (int z = 1; z <= 3; z++)
				for (int x = 1; x <= 3; x++)
					for (int d = 13; d < DIRS; d++) {
						int has;

						(void)spring(&g, x, y, z, d, &has);
						n += (size_t)has;
					}
		CHECK_INT(st.springs, n);
	}
	cmax = max_field(&g, g.compression);
	for (int y = 0; y <= 11; y++)
		for (int z = 1; z <= 3; z++)
			for (int x = 1; x <= 3; x++) {
				uint8_t fl = g.flags[wood_index(&g, x, y, z)];
				double f[3];

				CHECK_INT(fl, y == 0 ? WOOD_MASS | WOOD_FIXED : WOOD_MASS);
				if (y == 0)
					continue;
				net_force(&g, &p, x, y, z, f);
				worst = fmax(worst, sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]));
				/* the springs with a vertical part are compressed (but for the
				 * slightest stretch of the free top's corner diagonals): the tension
				 * is the column's bulging across, the lattice's Poisson effect */
				for (int d = 0; d < DIRS; d++) {
					int e[3], has;
					double s = spring(&g, x, y, z, d, &has);

					dir(d, e);
					if (has && e[1] != 0)
						across = fmax(across, s);
				}
				CHECK(g.tension[wood_index(&g, x, y, z)] <
				      g.compression[wood_index(&g, x, y, z)]);
			}
	printf("column 3 x 3 x 12, g = 1e-3: %d iterations, residual %.2g, worst net force "
	       "%.2g m g, max compression %.4g, stretch of vertical springs at most %.2g\n",
	       st.iterations, st.residual, worst / p.gravity, cmax, across);
	CHECK(worst <= 1e-3 * p.gravity);
	CHECK(across <= 1e-3 * cmax);
	/* lower layers more compressed than upper ones (the free ones, 1 to 11) */
	for (int y = 1; y < 11; y++)
		CHECK(layer(&g, g.compression, y) > layer(&g, g.compression, y + 1));
	for (int y = 2; y < 11; y++)
		for (int z = 1; z <= 3; z++)
			for (int x = 1; x <= 3; x++)
				CHECK(g.compression[wood_index(&g, x, y, z)] >
				      g.compression[wood_index(&g, x, y + 1, z)]);
	/* it sinks: every free point moves down, the top most */
	CHECK(g.displacement[3 * wood_index(&g, 2, 11, 2) + 1] < 0.0);
	CHECK(g.displacement[3 * wood_index(&g, 2, 11, 2) + 1] <
	      g.displacement[3 * wood_index(&g, 2, 5, 2) + 1]);
	/* nothing outside the wood */
	CHECK(g.flags[wood_index(&g, 0, 0, 0)] == 0 && g.compression[wood_index(&g, 0, 5, 0)] == 0);
	wood_grid_finish(&g);
}

/* An L: a post 3 x 3 x 10, an arm 3 thick and wide 12 long from its top. */
static void test_cantilever(void)
{
	struct wood_grid g;
	struct wood_params p = gravity(1e-3);
	struct wood_solve_stats st;

	grid(&g, 18, 11, 5);
	box(&g, 1, 3, 0, 9, 1, 3, 1.0);
	box(&g, 4, 15, 7, 9, 1, 3, 1.0);
	CHECK_INT(wood_rest(&g, &p, 0.0, &st), 0);
	CHECK(st.residual <= 1e-6);
	printf("cantilever: %zu points, %d iterations\n", st.points, st.iterations);
	/* near the post, the arm's upper side stretched and its lower side compressed */
	for (int x = 4; x <= 7; x++) {
		double tu = 0.0, tl = 0.0, cu = 0.0, cl = 0.0;

		for (int z = 1; z <= 3; z++) {
			size_t up = wood_index(&g, x, 9, z), lo = wood_index(&g, x, 7, z);

			tu += g.tension[up];
			tl += g.tension[lo];
			cu += g.compression[up];
			cl += g.compression[lo];
		}
		printf("  x = %d: upper tension %.4g compression %.4g, lower tension %.4g "
		       "compression %.4g\n",
		       x, tu, cu, tl, cl);
		CHECK(tu > 2 * tl);
		CHECK(cl > 2 * cu);
		CHECK(tu > cu);
		CHECK(cl > tl);
	}
	/* the tip sags */
	CHECK(g.displacement[3 * wood_index(&g, 15, 8, 2) + 1] <
	      g.displacement[3 * wood_index(&g, 8, 8, 2) + 1]);
	wood_grid_finish(&g);
}

/* wood_rest_euler to rest against wood_rest: compression and tension of every point
 * within 1% of the largest force. The two differ by the springs' turning (the full
 * springs against the linearised ones), in proportion to the displacements: gravity small
 * enough that the largest is about 0.01 voxel. */
static void compare_euler(const char *name, struct wood_grid *g, double grav, double dt,
			  double damping)
{
	struct wood_params p = gravity(grav);
	struct wood_solve_stats a, b;
	size_t n = wood_cells(g);
	double *comp = malloc(n * sizeof(*comp)), *tens = malloc(n * sizeof(*tens));
	double fmax_ = 0.0, worst = 0.0, umax = 0.0;

	CHECK(comp && tens);
	CHECK_INT(wood_rest(g, &p, 0.0, &a), 0);
	for (size_t i = 0; i < 3 * n; i++)
		umax = fmax(umax, fabs(g->displacement[i]));
	memcpy(comp, g->compression, n * sizeof(*comp));
	memcpy(tens, g->tension, n * sizeof(*tens));
	CHECK_INT(wood_rest_euler(g, &p, 0.0, dt, damping, 20000000, 1e-8 * grav, &b), 0);
	CHECK_INT(a.points, b.points);
	CHECK_INT(a.springs, b.springs);
	for (size_t i = 0; i < n; i++)
		fmax_ = fmax(fmax_, fmax(comp[i], tens[i]));
	for (size_t i = 0; i < n; i++)
		worst = fmax(worst, fmax(fabs(comp[i] - g->compression[i]),
					 fabs(tens[i] - g->tension[i])));
	printf("%s, g = %g: %zu points, largest displacement %.3g voxels; the paper's scheme "
	       "at rest after %d steps (dt %g, C %g); forces differ by at most %.3g%% of the "
	       "largest (%.4g)\n",
	       name, grav, b.points, umax, b.iterations, dt, damping, 100 * worst / fmax_, fmax_);
	CHECK(worst <= 0.01 * fmax_);
	free(comp);
	free(tens);
}

static void test_euler(void)
{
	struct wood_grid g;

	grid(&g, 4, 7, 4);
	box(&g, 1, 2, 0, 5, 1, 2, 1.0);
	compare_euler("column 2 x 2 x 6", &g, 1e-4, 0.1, 1.0);
	wood_grid_finish(&g);

	/* above 128 points: the multigrid's coarse levels at work */
	grid(&g, 5, 17, 5);
	box(&g, 1, 3, 0, 15, 1, 3, 1.0);
	compare_euler("column 3 x 3 x 16", &g, 1e-4, 0.1, 1.0);
	wood_grid_finish(&g);

	grid(&g, 9, 7, 4);
	box(&g, 1, 2, 0, 5, 1, 2, 1.0);
	box(&g, 3, 7, 4, 5, 1, 2, 1.0);
	compare_euler("L, post 2 x 2 x 6, arm 5", &g, 1e-5, 0.1, 1.0);
	wood_grid_finish(&g);

	grid(&g, 7, 6, 7);
	box(&g, 2, 4, 0, 4, 2, 4, 1.0);
	box(&g, 0, 6, 3, 4, 3, 4, 0.5);
	compare_euler("T, post 3 x 3 x 5, bar 7 x 2 x 2", &g, 1e-4, 0.1, 1.0);
	wood_grid_finish(&g);
}

/* A floating blob is dropped; a voxel hanging by one corner is loose; nothing fixed is
 * refused. */
static void test_dropped(void)
{
	struct wood_grid g;
	struct wood_params p = gravity(1e-3);
	struct wood_solve_stats st;

	grid(&g, 10, 10, 6);
	box(&g, 1, 3, 0, 5, 1, 3, 1.0);
	box(&g, 6, 7, 6, 7, 2, 3, 0.25); /* floating, not touching */
	g.density[wood_index(&g, 4, 6, 4)] = 1.0; /* on the column's top corner */
	CHECK_INT(wood_rest(&g, &p, 0.0, &st), 0);
	CHECK_INT(st.points, 54);
	CHECK_INT(st.dropped, 9);
	CHECK_INT(st.loose, 1);
	CHECK(st.residual <= 1e-6);
	for (int z = 2; z <= 3; z++)
		for (int y = 6; y <= 7; y++)
			for (int x = 6; x <= 7; x++) {
				size_t c = wood_index(&g, x, y, z);

				CHECK(g.flags[c] == 0 && g.compression[c] == 0.0 && g.tension[c] == 0.0);
				CHECK(g.displacement[3 * c] == 0.0 && g.displacement[3 * c + 1] == 0.0);
			}
	CHECK(g.flags[wood_index(&g, 4, 6, 4)] == 0);
	CHECK(g.flags[wood_index(&g, 3, 5, 3)] == WOOD_MASS);
	/* the same by the paper's scheme */
	CHECK_INT(wood_rest_euler(&g, &p, 0.0, 0.05, 0.5, 0, 1e-3, &st), -ETIMEDOUT);
	CHECK_INT(st.dropped, 9);
	wood_grid_finish(&g);

	/* nothing on the ground */
	grid(&g, 5, 8, 5);
	box(&g, 1, 3, 3, 6, 1, 3, 1.0);
	CHECK_INT(wood_rest(&g, &p, 0.0, &st), -EINVAL);
	CHECK_INT(wood_rest_euler(&g, &p, 0.0, 0.05, 0.5, 10, 1e-3, &st), -EINVAL);
	/* unless the ground is higher: within one voxel of it */
	CHECK_INT(wood_rest(&g, &p, 2.6, &st), 0);
	CHECK_INT(st.fixed, 9);
	CHECK(g.flags[wood_index(&g, 2, 3, 2)] == (WOOD_MASS | WOOD_FIXED));
	CHECK_INT(wood_rest(&g, &p, 2.4, &st), -EINVAL);
	wood_grid_finish(&g);
}

/* Fixed: the centre at most one voxel above the ground, in a grid with its origin below
 * the ground and voxels of 0.1 m (as wood_grid_for pads it). */
static void test_fixed(void)
{
	struct wood_grid g;
	struct wood_params p = gravity(1e-3);
	struct wood_solve_stats st;

	CHECK_INT(wood_grid_create(&g, 5, 12, 5, vec3(-0.25, -0.3, -0.25), 0.1), 0);
	/* the wood from the ground up (layer 3 is 0.0 to 0.1 m) */
	box(&g, 1, 3, 3, 10, 1, 3, 1.0);
	CHECK_INT(wood_rest(&g, &p, 0.0, &st), 0);
	CHECK_INT(st.fixed, 9);
	for (int y = 3; y <= 10; y++)
		CHECK(g.flags[wood_index(&g, 2, y, 2)] == (y == 3 ? WOOD_MASS | WOOD_FIXED : WOOD_MASS));
	/* the ground a little higher: the centre at 0.15 m is within 0.1 of 0.051 */
	CHECK_INT(wood_rest(&g, &p, 0.051, &st), 0);
	CHECK_INT(st.fixed, 18);
	CHECK_INT(wood_rest(&g, &p, NAN, &st), -EINVAL);
	wood_grid_finish(&g);
}

static int all_zero(const void *v, size_t bytes)
{
	const unsigned char *c = v;

	for (size_t i = 0; i < bytes; i++)
		if (c[i])
			return 0;
	return 1;
}

/* No gravity, no wind: nothing moves, no force, no iteration. */
static void test_no_load(void)
{
	struct wood_grid g;
	struct wood_params p = gravity(0.0);
	struct wood_solve_stats st;
	size_t n;

	grid(&g, 18, 11, 5);
	box(&g, 1, 3, 0, 9, 1, 3, 1.0);
	box(&g, 4, 15, 7, 9, 1, 3, 0.7);
	n = wood_cells(&g);
	/* what a previous run left is cleared */
	g.tension[wood_index(&g, 0, 0, 0)] = 5.0;
	CHECK_INT(wood_rest(&g, &p, 0.0, &st), 0);
	CHECK_INT(st.iterations, 0);
	CHECK(st.residual == 0.0);
	CHECK(st.points == 3 * 3 * 10 + 12 * 3 * 3);
	CHECK(all_zero(g.displacement, 3 * n * sizeof(double)));
	CHECK(all_zero(g.compression, n * sizeof(double)));
	CHECK(all_zero(g.tension, n * sizeof(double)));
	CHECK(g.flags[wood_index(&g, 10, 8, 2)] == WOOD_MASS);
	CHECK_INT(wood_rest_euler(&g, &p, 0.0, 0.05, 0.5, 100, 1e-9, &st), 0);
	CHECK_INT(st.iterations, 0);
	CHECK(all_zero(g.displacement, 3 * n * sizeof(double)));
	CHECK(all_zero(g.compression, n * sizeof(double)));
	CHECK(all_zero(g.tension, n * sizeof(double)));
	wood_grid_finish(&g);
}

/* The same field and settings give the same bits. */
static void test_determinism(void)
{
	struct wood_grid a, b;
	struct wood_params p = gravity(2e-3);
	struct wood_solve_stats sa, sb;
	size_t n;

	p.wind[0] = 3e-4;
	p.wind[2] = -1e-4;
	for (int k = 0; k < 2; k++) {
		struct wood_grid *g = k ? &b : &a;

		grid(g, 20, 14, 9);
		box(g, 2, 5, 0, 12, 2, 5, 1.0);
		box(g, 6, 17, 9, 11, 3, 5, 0.6);
		box(g, 10, 12, 4, 8, 4, 6, 0.3);
	}
	CHECK_INT(wood_rest(&a, &p, 0.0, &sa), 0);
	CHECK_INT(wood_rest(&b, &p, 0.0, &sb), 0);
	n = wood_cells(&a);
	CHECK(sa.iterations == sb.iterations && sa.residual == sb.residual);
	CHECK(memcmp(a.displacement, b.displacement, 3 * n * sizeof(double)) == 0);
	CHECK(memcmp(a.compression, b.compression, n * sizeof(double)) == 0);
	CHECK(memcmp(a.tension, b.tension, n * sizeof(double)) == 0);
	CHECK(memcmp(a.flags, b.flags, n) == 0);
	/* and again on the same grid */
	CHECK_INT(wood_rest(&b, &p, 0.0, &sb), 0);
	CHECK(memcmp(a.compression, b.compression, n * sizeof(double)) == 0);
	wood_grid_finish(&a);
	wood_grid_finish(&b);
}

/* A T symmetric about x = 8 and z = 2: forces mirror-symmetric, sideways displacements
 * opposite (to the solve's tolerance). */
static void test_symmetry(void)
{
	struct wood_grid g;
	struct wood_params p = gravity(1e-3);
	struct wood_solve_stats st;
	double cmax, umax = 0.0, worst = 0.0;

	grid(&g, 17, 12, 5);
	box(&g, 7, 9, 0, 10, 1, 3, 1.0);
	box(&g, 1, 15, 8, 10, 1, 3, 1.0);
	box(&g, 2, 14, 7, 7, 2, 2, 0.5);
	CHECK_INT(wood_rest(&g, &p, 0.0, &st), 0);
	cmax = fmax(max_field(&g, g.compression), max_field(&g, g.tension));
	for (size_t i = 0; i < 3 * wood_cells(&g); i++)
		umax = fmax(umax, fabs(g.displacement[i]));
	for (int z = 0; z < g.nz; z++)
		for (int y = 0; y < g.ny; y++)
			for (int x = 0; x < g.nx; x++) {
				size_t c = wood_index(&g, x, y, z);
				size_t m[3] = { wood_index(&g, 16 - x, y, z), wood_index(&g, x, y, 4 - z),
						wood_index(&g, 16 - x, y, 4 - z) };

				for (int k = 0; k < 3; k++) {
					size_t o = m[k];
					double sx = k == 1 ? 1.0 : -1.0, sz = k == 0 ? 1.0 : -1.0;

					CHECK(g.flags[c] == g.flags[o]);
					worst = fmax(worst, fabs(g.compression[c] - g.compression[o]));
					worst = fmax(worst, fabs(g.tension[c] - g.tension[o]));
					CHECK_NEAR(g.displacement[3 * c], sx * g.displacement[3 * o], 1e-5 * umax);
					CHECK_NEAR(g.displacement[3 * c + 1], g.displacement[3 * o + 1],
						   1e-5 * umax);
					CHECK_NEAR(g.displacement[3 * c + 2], sz * g.displacement[3 * o + 2],
						   1e-5 * umax);
				}
			}
	printf("T: mirror images' forces differ by at most %.2g of the largest\n", worst / cmax);
	CHECK(worst <= 1e-5 * cmax);
	wood_grid_finish(&g);
}

/* Wind across a column: stretched on the windward side at the foot, compressed on the
 * lee side. */
static void test_wind(void)
{
	struct wood_grid g;
	struct wood_params p = gravity(0.0);
	struct wood_solve_stats st;
	double f[3];

	p.wind[0] = 1e-3;
	p.wind[1] = 5.0; /* ignored */
	grid(&g, 5, 13, 5);
	box(&g, 1, 3, 0, 11, 1, 3, 1.0);
	CHECK_INT(wood_rest(&g, &p, 0.0, &st), 0);
	CHECK(st.residual <= 1e-6);
	net_force(&g, &p, 2, 5, 2, f);
	CHECK(fabs(f[0]) + fabs(f[1]) + fabs(f[2]) <= 1e-5 * p.wind[0]);
	CHECK(g.displacement[3 * wood_index(&g, 2, 11, 2)] > 0.0);
	CHECK(g.tension[wood_index(&g, 1, 1, 2)] > 2 * g.tension[wood_index(&g, 3, 1, 2)]);
	CHECK(g.compression[wood_index(&g, 3, 1, 2)] > 2 * g.compression[wood_index(&g, 1, 1, 2)]);
	wood_grid_finish(&g);
}

/* A porous field, half its voxels filled at random: whatever is kept comes to rest. */
static void test_porous(void)
{
	struct wood_grid g;
	struct wood_params p = gravity(1e-3);
	struct wood_solve_stats st;
	uint32_t r = 12345;
	double worst = 0.0;

	p.wind[2] = 4e-4;
	grid(&g, 18, 18, 18);
	for (size_t i = 0; i < wood_cells(&g); i++) {
		r = r * 1664525u + 1013904223u; /* a fixed sequence, the same everywhere */
		g.density[i] = (r >> 16) % 100 < 50 ? 0.1 + (r >> 8) % 9 / 10.0 : 0.0;
	}
	CHECK_INT(wood_rest(&g, &p, 0.0, &st), 0);
	CHECK(st.residual <= 1e-6);
	CHECK(st.points > 1000 && st.loose > 0 && st.dropped >= st.loose);
	for (int z = 0; z < g.nz; z++)
		for (int y = 1; y < g.ny; y++)
			for (int x = 0; x < g.nx; x++) {
				double f[3];

				if (!(g.flags[wood_index(&g, x, y, z)] & WOOD_MASS))
					continue;
				net_force(&g, &p, x, y, z, f);
				worst = fmax(worst, sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]));
			}
	printf("porous field: %zu points kept, %zu dropped (%zu loose), %d iterations, worst "
	       "net force %.2g of the load\n",
	       st.points, st.dropped, st.loose, st.iterations, worst / hypot(p.gravity, p.wind[2]));
	CHECK(worst <= 1e-4 * p.gravity);
	wood_grid_finish(&g);
}

/* Refused: a load that is no number, time steps out of range; the fields cleared. */
static void test_refused(void)
{
	struct wood_grid g;
	struct wood_params p = gravity(NAN);
	struct wood_solve_stats st;

	grid(&g, 5, 8, 5);
	box(&g, 1, 3, 0, 6, 1, 3, 1.0);
	g.flags[0] = WOOD_MASS;
	g.compression[0] = 1.0;
	CHECK_INT(wood_rest(&g, &p, 0.0, &st), -EINVAL);
	CHECK(g.flags[0] == 0 && g.compression[0] == 0.0);
	p = gravity(1e-3);
	p.wind[2] = INFINITY;
	CHECK_INT(wood_rest(&g, &p, 0.0, &st), -EINVAL);
	CHECK_INT(wood_rest_euler(&g, &p, 0.0, 0.1, 1.0, 10, 1e-9, &st), -EINVAL);
	p = gravity(1e-3);
	CHECK_INT(wood_rest(&g, &p, INFINITY, &st), -EINVAL);
	CHECK_INT(wood_rest_euler(&g, &p, 0.0, 0.0, 1.0, 10, 1e-9, &st), -EINVAL);
	CHECK_INT(wood_rest_euler(&g, &p, 0.0, NAN, 1.0, 10, 1e-9, &st), -EINVAL);
	CHECK_INT(wood_rest_euler(&g, &p, 0.0, 0.1, -1.0, 10, 1e-9, &st), -EINVAL);
	CHECK_INT(wood_rest_euler(&g, &p, 0.0, 0.1, 1.0, -1, 1e-9, &st), -EINVAL);
	CHECK_INT(wood_rest_euler(&g, &p, 0.0, 0.1, 1.0, 10, 0.0, &st), -EINVAL);
	CHECK_INT(wood_rest(&g, &p, 0.0, &st), 0);
	CHECK(g.flags[wood_index(&g, 2, 0, 2)] == (WOOD_MASS | WOOD_FIXED));
	wood_grid_finish(&g);
}

#if FAIL_ALLOC_HOOK
/* Every allocation failing in turn: -ENOMEM, the fields cleared, nothing kept. */
static void test_oom(void)
{
	struct wood_grid g;
	struct wood_params p = gravity(1e-3);

	if (!fail_alloc_hooked())
		return;
	/* a tree of points large enough for coarse levels */
	grid(&g, 24, 14, 8);
	box(&g, 2, 5, 0, 12, 2, 5, 1.0);
	box(&g, 6, 21, 9, 11, 3, 5, 1.0);
	for (int euler = 0; euler < 2; euler++)
		for (long n = 0;; n++) {
			struct wood_solve_stats st;
			long before = fail_alloc_live();
			int ret;

			fail_alloc_at(n);
			ret = euler ? wood_rest_euler(&g, &p, 0.0, 0.05, 0.5, 10, 1e-12, &st) :
				      wood_rest(&g, &p, 0.0, &st);
			fail_alloc_off();
			CHECK_INT(fail_alloc_live(), before);
			if (fail_alloc_calls() <= n) {
				CHECK_INT(ret, euler ? -ETIMEDOUT : 0);
				printf("%s: each of its %ld allocations failing in turn\n",
				       euler ? "wood_rest_euler" : "wood_rest", n);
				break;
			}
			CHECK_INT(ret, -ENOMEM);
			CHECK(all_zero(g.flags, wood_cells(&g)));
		}
	wood_grid_finish(&g);
}
#else
static void test_oom(void)
{
}
#endif

int main(void)
{
	test_column();
	test_cantilever();
	test_euler();
	test_dropped();
	test_fixed();
	test_no_load();
	test_determinism();
	test_symmetry();
	test_wind();
	test_porous();
	test_refused();
	test_oom();
	return 0;
}
