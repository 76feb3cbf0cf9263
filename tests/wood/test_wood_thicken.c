/* SPDX-License-Identifier: MIT */
/*
 * Step 6 of growing wood (wood.h, docs/wood.md "Step 6: thickening") on fields built by
 * hand: the growth exactly (beta 1 and not), conifers by compression and broadleaf trees
 * by tension, who does not grow, the overflow's 1 / distance shares, a full neighbour and
 * a full ring, the grid's edge, every Csi from the field before, two sources at once
 * (mirror images stay mirrored), and on seeded random
 * fields with many overflows: conservation, 0 <= density <= 1, nothing decreases, the
 * other fields untouched, the same result twice.
 */
#include <errno.h>
#include <stdint.h>
#include <string.h>

#include "fail_alloc.h"
#include "rng.h"
#include "test.h"
#include "wood.h"

static struct wood_params params(enum wood_mode mode, double alpha, double beta)
{
	struct wood_params p;

	memset(&p, 0, sizeof(p));
	p.mode = mode;
	p.grid = 64;
	p.alpha = alpha;
	p.beta = beta;
	return p;
}

static void grid(struct wood_grid *g, int nx, int ny, int nz)
{
	CHECK_INT(wood_grid_create(g, nx, ny, nz, vec3(0, 0, 0), 0.01), 0);
}

/* A mass point of density d with compression c and tension t. */
static size_t mass(struct wood_grid *g, int x, int y, int z, double d, double c, double t)
{
	size_t i = wood_index(g, x, y, z);

	g->density[i] = d;
	g->compression[i] = c;
	g->tension[i] = t;
	g->flags[i] = WOOD_MASS;
	return i;
}

static double density_sum(const struct wood_grid *g)
{
	double s = 0.0;

	for (size_t i = 0; i < wood_cells(g); i++)
		s += g->density[i];
	return s;
}

static int cheb(int dx, int dy, int dz)
{
	int m = abs(dx);

	m = abs(dy) > m ? abs(dy) : m;
	return abs(dz) > m ? abs(dz) : m;
}

/* The sum of 1 / distance over ring r about (cx, cy, cz), inside the grid, skipping
 * voxels at 1.0. */
static double ring_weight(const struct wood_grid *g, int cx, int cy, int cz, int r)
{
	double w = 0.0;

	for (int z = 0; z < g->nz; z++)
		for (int y = 0; y < g->ny; y++)
			for (int x = 0; x < g->nx; x++) {
				int dx = x - cx, dy = y - cy, dz = z - cz;

				if (cheb(dx, dy, dz) == r &&
				    g->density[wood_index(g, x, y, z)] < 1.0)
					w += 1.0 / sqrt(dx * dx + dy * dy + dz * dz);
			}
	return w;
}

/* One surface voxel: Delta rho = (alpha rho f)^beta exactly, nothing else changes. */
static void test_exact(void)
{
	static const struct {
		double alpha, beta, rho, f;
	} cases[] = {
		{ 1.5, 1.0, 0.5, 0.4 },   /* 0.3 */
		{ 2.0, 2.0, 0.25, 0.6 },  /* 0.09 */
		{ 0.5, 0.5, 0.3, 0.9 },   /* sqrt 0.135 */
		{ 3.0, 1.7, 0.35, 0.2 },
	};

	for (size_t k = 0; k < sizeof(cases) / sizeof(*cases); k++) {
		struct wood_grid g;
		struct wood_params p = params(WOOD_CONIFER, cases[k].alpha, cases[k].beta);
		double rho = cases[k].rho, added = -1, lost = -1;
		double csi = pow(cases[k].alpha * rho * cases[k].f, cases[k].beta);
		size_t c;

		grid(&g, 5, 5, 5);
		c = mass(&g, 2, 2, 2, rho, cases[k].f, 0.0);
		CHECK(rho + csi < 1.0);
		CHECK_INT(wood_thicken(&g, &p, &added, &lost), 0);
		CHECK(g.density[c] == rho + csi);
		CHECK(added == csi);
		CHECK(lost == 0.0);
		for (size_t i = 0; i < wood_cells(&g); i++)
			if (i != c)
				CHECK(g.density[i] == 0.0);
		wood_grid_finish(&g);
	}
}

/* The numbers themselves, not pow's: (2 * 0.25 * 0.6)^2 = 0.09, (0.5 * 0.5 * 0.36)^0.5 =
 * 0.3; added and lost may be NULL. */
static void test_exact_numbers(void)
{
	struct wood_grid g;
	struct wood_params p = params(WOOD_CONIFER, 2.0, 2.0);
	size_t a, b;

	grid(&g, 3, 3, 3);
	a = mass(&g, 1, 1, 1, 0.25, 0.6, 0.0);
	CHECK_INT(wood_thicken(&g, &p, NULL, NULL), 0);
	CHECK_NEAR(g.density[a], 0.25 + 0.09, 1e-15);
	p = params(WOOD_BROADLEAF, 0.5, 0.5);
	b = mass(&g, 0, 0, 0, 0.5, 0.0, 0.36);
	g.density[a] = 1.0;
	CHECK_INT(wood_thicken(&g, &p, NULL, NULL), 0);
	CHECK_NEAR(g.density[b], 0.5 + 0.3, 1e-15);
	wood_grid_finish(&g);
}

/* Conifers grow by compression, broadleaf trees by tension; no force, no growth. */
static void test_modes(void)
{
	struct wood_grid g;
	struct wood_params con = params(WOOD_CONIFER, 1.0, 1.0);
	struct wood_params bro = params(WOOD_BROADLEAF, 1.0, 1.0);
	size_t a, b;
	double added;

	grid(&g, 4, 3, 3);
	a = mass(&g, 1, 1, 1, 0.5, 0.4, 0.1);
	b = mass(&g, 2, 1, 1, 0.5, 0.0, 0.3); /* compressed not at all */
	CHECK_INT(wood_thicken(&g, &con, &added, NULL), 0);
	CHECK(g.density[a] == 0.5 + 0.5 * 0.4);
	CHECK(g.density[b] == 0.5);
	CHECK(added == 0.5 * 0.4);

	g.density[a] = 0.5;
	CHECK_INT(wood_thicken(&g, &bro, &added, NULL), 0);
	CHECK(g.density[a] == 0.5 + 0.5 * 0.1);
	CHECK(g.density[b] == 0.5 + 0.5 * 0.3);
	CHECK(added == 0.5 * 0.1 + 0.5 * 0.3);
	wood_grid_finish(&g);
}

/* The interior (1.0), a voxel that is not a mass point, a mass point flagged at density 0:
 * none grows, however pressed. */
static void test_who_grows(void)
{
	struct wood_grid g;
	struct wood_params p = params(WOOD_CONIFER, 1.0, 1.0);
	size_t in, out, zero, fixed;
	double added = -1, lost = -1;

	grid(&g, 5, 5, 5);
	in = mass(&g, 1, 1, 1, 1.0, 5.0, 5.0);
	out = wood_index(&g, 3, 3, 3);
	g.density[out] = 0.5;
	g.compression[out] = 5.0;
	zero = mass(&g, 1, 3, 1, 0.0, 5.0, 5.0);
	/* a fixed mass point grows like any other */
	fixed = mass(&g, 3, 1, 3, 0.5, 0.2, 0.0);
	g.flags[fixed] |= WOOD_FIXED;
	CHECK_INT(wood_thicken(&g, &p, &added, &lost), 0);
	CHECK(g.density[in] == 1.0);
	CHECK(g.density[out] == 0.5);
	CHECK(g.density[zero] == 0.0);
	CHECK(g.density[fixed] == 0.5 + 0.5 * 0.2);
	CHECK(added == 0.5 * 0.2);
	CHECK(lost == 0.0);
	wood_grid_finish(&g);
}

/* One overflow in open space: ring 1 takes it all, faces 1, edges 1/sqrt 2, corners
 * 1/sqrt 3 of a share; the source ends at exactly 1.0. */
static void test_overflow_weights(void)
{
	struct wood_grid g;
	struct wood_params p = params(WOOD_CONIFER, 1.0, 1.0);
	const double W = 6.0 + 12.0 / sqrt(2.0) + 8.0 / sqrt(3.0);
	double added, lost, e, face = 0, edge = 0;
	size_t c;

	grid(&g, 5, 5, 5);
	c = mass(&g, 2, 2, 2, 0.9, 0.4, 0.0); /* Csi 0.36, excess 0.26 */
	CHECK_INT(wood_thicken(&g, &p, &added, &lost), 0);
	e = 0.36 - 0.1;
	CHECK(g.density[c] == 1.0);
	CHECK_NEAR(added, 0.36, 1e-16);
	CHECK(lost == 0.0);
	for (int z = 0; z < 5; z++)
		for (int y = 0; y < 5; y++)
			for (int x = 0; x < 5; x++) {
				int dx = x - 2, dy = y - 2, dz = z - 2;
				int d2 = dx * dx + dy * dy + dz * dz, r = cheb(dx, dy, dz);
				double d = g.density[wood_index(&g, x, y, z)];

				if (r == 0)
					continue;
				if (r > 1) {
					CHECK(d == 0.0);
					continue;
				}
				CHECK_NEAR(d, e / (W * sqrt((double)d2)), 1e-16);
				if (d2 == 1)
					face = d;
				if (d2 == 2)
					edge = d;
			}
	CHECK_NEAR(face / edge, sqrt(2.0), 1e-12);
	CHECK_NEAR(face, 0.26 / W, 1e-15);
	CHECK_NEAR(density_sum(&g) - 0.9, 0.36, 1e-15);
	wood_grid_finish(&g);
}

/* A face neighbour at 1.0 takes nothing; one at 0.995 fills to exactly 1.0, and the rest
 * share what it could not take. */
static void test_saturation(void)
{
	struct wood_grid g;
	struct wood_params p = params(WOOD_CONIFER, 1.0, 1.0);
	const double W = 6.0 + 12.0 / sqrt(2.0) + 8.0 / sqrt(3.0);
	double added, lost, e = 0.5, rest;
	size_t c, full, near;

	grid(&g, 5, 5, 5);
	c = mass(&g, 2, 2, 2, 0.5, 2.0, 0.0); /* Csi 1.0, excess 0.5 */
	full = wood_index(&g, 3, 2, 2);
	near = wood_index(&g, 1, 2, 2);
	g.density[full] = 1.0;
	g.density[near] = 0.995;
	CHECK_INT(wood_thicken(&g, &p, &added, &lost), 0);
	CHECK(g.density[c] == 1.0);
	CHECK(g.density[full] == 1.0);
	CHECK(g.density[near] == 1.0);
	rest = e - (1.0 - 0.995);
	CHECK_NEAR(g.density[wood_index(&g, 2, 3, 2)], rest / (W - 2.0), 1e-15);
	CHECK_NEAR(g.density[wood_index(&g, 2, 3, 3)], rest / ((W - 2.0) * sqrt(2.0)), 1e-15);
	CHECK_NEAR(g.density[wood_index(&g, 3, 3, 3)], rest / ((W - 2.0) * sqrt(3.0)), 1e-15);
	CHECK(g.density[wood_index(&g, 0, 2, 2)] == 0.0); /* ring 2: nothing */
	CHECK(lost == 0.0);
	CHECK_NEAR(density_sum(&g) - (0.5 + 1.0 + 0.995), added, 1e-14);
	wood_grid_finish(&g);
}

/* An excess of 30 fills ring 1 (26 voxels) to exactly 1.0 (faces and edges in the first
 * round, corners in the second) and spills 4 into ring 2, in 1 / distance there; ring 3
 * takes nothing. */
static void test_ring_spill(void)
{
	struct wood_grid g;
	struct wood_params p = params(WOOD_CONIFER, 1.0, 1.0);
	double added, lost, W2;
	size_t c;

	grid(&g, 7, 7, 7);
	c = mass(&g, 3, 3, 3, 0.5, 61.0, 0.0); /* Csi 30.5, excess 30 */
	W2 = ring_weight(&g, 3, 3, 3, 2);
	CHECK_INT(wood_thicken(&g, &p, &added, &lost), 0);
	CHECK(added == 30.5);
	CHECK(lost == 0.0);
	CHECK(g.density[c] == 1.0);
	for (int z = 0; z < 7; z++)
		for (int y = 0; y < 7; y++)
			for (int x = 0; x < 7; x++) {
				int dx = x - 3, dy = y - 3, dz = z - 3, r = cheb(dx, dy, dz);
				double d = g.density[wood_index(&g, x, y, z)];

				if (r == 1)
					CHECK(d == 1.0);
				else if (r == 2)
					CHECK_NEAR(d, 4.0 / (W2 * sqrt(dx * dx + dy * dy + dz * dz)),
						   1e-14);
				else if (r == 3)
					CHECK(d == 0.0);
			}
	CHECK_NEAR(density_sum(&g), 0.5 + 30.5, 1e-12);
	wood_grid_finish(&g);
}

/* At a corner the ring is the part inside the grid: 7 voxels of 3^3 share it. In 2^3 the
 * whole grid fills and what is left is lost. */
static void test_edge(void)
{
	struct wood_grid g;
	struct wood_params p = params(WOOD_CONIFER, 1.0, 1.0);
	const double W = 3.0 + 3.0 / sqrt(2.0) + 1.0 / sqrt(3.0);
	double added, lost;

	grid(&g, 3, 3, 3);
	mass(&g, 0, 0, 0, 0.5, 1.2, 0.0); /* Csi 0.6, excess 0.1 */
	CHECK_INT(wood_thicken(&g, &p, &added, &lost), 0);
	CHECK(lost == 0.0);
	CHECK_NEAR(g.density[wood_index(&g, 1, 0, 0)], 0.1 / W, 1e-15);
	CHECK_NEAR(g.density[wood_index(&g, 0, 1, 1)], 0.1 / (W * sqrt(2.0)), 1e-15);
	CHECK_NEAR(g.density[wood_index(&g, 1, 1, 1)], 0.1 / (W * sqrt(3.0)), 1e-15);
	CHECK(g.density[wood_index(&g, 2, 0, 0)] == 0.0);
	wood_grid_finish(&g);

	grid(&g, 2, 2, 2);
	mass(&g, 0, 0, 0, 0.5, 20.0, 0.0); /* Csi 10, room for 7.5 */
	mass(&g, 1, 1, 1, 0.0, 0.0, 0.0);
	g.density[wood_index(&g, 1, 1, 0)] = 0.25;
	CHECK_INT(wood_thicken(&g, &p, &added, &lost), 0);
	CHECK(added == 10.0);
	CHECK_NEAR(lost, 10.0 - 0.5 - 7.0 + 0.25, 1e-14);
	for (size_t i = 0; i < wood_cells(&g); i++)
		CHECK(g.density[i] == 1.0);
	wood_grid_finish(&g);

	/* a long thin grid: the excess runs along it ring after ring, up to its far end */
	grid(&g, 12, 1, 1);
	mass(&g, 0, 0, 0, 0.5, 9.0, 0.0); /* Csi 4.5, excess 4: voxels 1..4 fill */
	CHECK_INT(wood_thicken(&g, &p, &added, &lost), 0);
	CHECK(lost == 0.0);
	for (int x = 0; x < 12; x++)
		CHECK(g.density[x] == (x <= 4 ? 1.0 : 0.0));
	wood_grid_finish(&g);
}

/* Every Csi from the field before: B next to A grows by its own density, not by the
 * density A's overflow gives it; both are added before any overflow spreads. */
static void test_previous_field(void)
{
	struct wood_grid g;
	struct wood_params p = params(WOOD_CONIFER, 1.0, 1.0);
	double added, lost, W, e, csib = 0.2 * 0.5;
	size_t a, b;

	grid(&g, 5, 5, 5);
	a = mass(&g, 1, 2, 2, 0.8, 1.0, 0.0);  /* first in scan order: Csi 0.8, excess 0.6 */
	b = mass(&g, 2, 2, 2, 0.2, 0.5, 0.0);  /* Csi 0.1 */
	/* A's ring 1 after every own Csi is in: all open */
	W = ring_weight(&g, 1, 2, 2, 1);
	CHECK_INT(wood_thicken(&g, &p, &added, &lost), 0);
	e = 0.8 - 0.2;
	CHECK(g.density[a] == 1.0);
	CHECK_NEAR(g.density[b], 0.2 + csib + e / W, 1e-15);
	/* had B's Csi been taken after A's overflow, it would be this much more */
	CHECK(fabs(g.density[b] - (0.2 + e / W + (0.2 + e / W) * 0.5)) > 1e-3);
	CHECK_NEAR(added, 0.8 + csib, 1e-15);
	CHECK(lost == 0.0);

	/* the other way about: the later voxel in scan order overflows into the earlier, whose
	 * Csi was from its density 0.3 */
	wood_grid_finish(&g);
	grid(&g, 5, 5, 5);
	a = mass(&g, 1, 2, 2, 0.3, 0.5, 0.0); /* Csi 0.15 */
	b = mass(&g, 2, 2, 2, 0.8, 1.0, 0.0); /* Csi 0.8, excess 0.6 */
	W = ring_weight(&g, 2, 2, 2, 1);
	CHECK_INT(wood_thicken(&g, &p, &added, &lost), 0);
	CHECK_NEAR(g.density[a], 0.3 + 0.15 + 0.6 / W, 1e-15);
	wood_grid_finish(&g);
}

/*
 * Two sources whose rings meet, mirror images about x = 3, each with more than its ring 1
 * can take: neither goes first, so the field is its own mirror image (bit for bit but for
 * the sums' rounding), what they share is split between them, and both spill into ring
 * 2. Taking them one after another, the first would have filled the voxels between them
 * and pushed the second's excess further out on its side.
 */
static void test_two_sources(void)
{
	struct wood_grid g;
	struct wood_params p = params(WOOD_CONIFER, 1.0, 1.0);
	double added, lost, worst = 0.0;
	size_t a, b;

	grid(&g, 9, 7, 7);
	a = mass(&g, 3, 3, 3, 0.5, 60.0, 0.0); /* Csi 30, excess 29.5: the rings 1 hold 43 */
	b = mass(&g, 5, 3, 3, 0.5, 60.0, 0.0);
	CHECK_INT(wood_thicken(&g, &p, &added, &lost), 0);
	CHECK(g.density[a] == 1.0 && g.density[b] == 1.0);
	CHECK(added == 60.0 && lost == 0.0);
	for (int z = 0; z < 7; z++)
		for (int y = 0; y < 7; y++)
			for (int x = 0; x < 9; x++) {
				double d = g.density[wood_index(&g, x, y, z)];
				double m = g.density[wood_index(&g, 8 - x, y, z)];

				CHECK(d >= 0.0 && d <= 1.0);
				worst = fmax(worst, fabs(d - m));
			}
	printf("two sources: the field mirrors itself within %.2g\n", worst);
	CHECK(worst <= 1e-14);
	/* the column between them (x = 4) is in both rings 1: full; so is each ring 1 */
	for (int z = 2; z <= 4; z++)
		for (int y = 2; y <= 4; y++)
			CHECK(g.density[wood_index(&g, 4, y, z)] == 1.0);
	/* both spilled beyond ring 1 by the same amount: the outer columns alike */
	CHECK(g.density[wood_index(&g, 1, 3, 3)] > 0.0);
	CHECK(g.density[wood_index(&g, 1, 3, 3)] == g.density[wood_index(&g, 7, 3, 3)]);
	CHECK_NEAR(density_sum(&g), 1.0 + 60.0, 1e-12);
	wood_grid_finish(&g);
}

/* A random field: a few blobs of 1.0 with fractional rims, mass points where above 0,
 * forces up to fmax. */
static void random_field(struct wood_grid *g, struct rng *r, double fmax)
{
	for (size_t i = 0; i < wood_cells(g); i++) {
		double u = rng_uniform(r);

		g->density[i] = u < 0.3 ? 0.0 : u < 0.5 ? 1.0 : rng_uniform(r);
		g->flags[i] = g->density[i] > 0.0 ? WOOD_MASS : 0;
		g->compression[i] = fmax * rng_uniform(r);
		g->tension[i] = rng_uniform(r) < 0.2 ? 0.0 : fmax * rng_uniform(r);
		if (g->flags[i] && rng_uniform(r) < 0.05)
			g->flags[i] |= WOOD_FIXED;
	}
}

static size_t overflows(const struct wood_grid *g, const struct wood_params *p)
{
	size_t n = 0;

	for (size_t i = 0; i < wood_cells(g); i++) {
		double d = g->density[i], f = p->mode == WOOD_CONIFER ? g->compression[i]
								       : g->tension[i];

		if ((g->flags[i] & WOOD_MASS) && d > 0.0 && d < 1.0 &&
		    d + pow(p->alpha * d * f, p->beta) > 1.0)
			n++;
	}
	return n;
}

static void copy_grid(struct wood_grid *dst, const struct wood_grid *src)
{
	size_t n = wood_cells(src);

	grid(dst, src->nx, src->ny, src->nz);
	memcpy(dst->density, src->density, n * sizeof(*dst->density));
	memcpy(dst->compression, src->compression, n * sizeof(*dst->compression));
	memcpy(dst->tension, src->tension, n * sizeof(*dst->tension));
	memcpy(dst->flags, src->flags, n * sizeof(*dst->flags));
}

/* Conservation, 0..1, nothing decreases, the other fields untouched, twice the same. */
static void random_case(uint64_t seed, int nx, int ny, int nz, enum wood_mode mode,
			double alpha, double beta, double fmax, bool want_lost)
{
	struct rng r;
	struct wood_grid g0, g, h;
	struct wood_params p = params(mode, alpha, beta);
	double added, lost, added2, lost2, before, after, dsum = 0.0;
	size_t n = (size_t)nx * (size_t)ny * (size_t)nz, nover;

	rng_seed(&r, seed);
	grid(&g0, nx, ny, nz);
	random_field(&g0, &r, fmax);
	nover = overflows(&g0, &p);
	CHECK(nover >= n / 20);
	copy_grid(&g, &g0);
	copy_grid(&h, &g0);
	CHECK_INT(wood_thicken(&g, &p, &added, &lost), 0);
	CHECK_INT(wood_thicken(&h, &p, &added2, &lost2), 0);
	/* bit for bit the same */
	CHECK(memcmp(g.density, h.density, n * sizeof(*g.density)) == 0);
	CHECK(memcmp(&added, &added2, sizeof(added)) == 0);
	CHECK(memcmp(&lost, &lost2, sizeof(lost)) == 0);
	for (size_t i = 0; i < n; i++) {
		CHECK(g.density[i] >= 0.0 && g.density[i] <= 1.0);
		CHECK(g.density[i] >= g0.density[i]);
		dsum += g.density[i] - g0.density[i];
	}
	CHECK(memcmp(g.compression, g0.compression, n * sizeof(*g.compression)) == 0);
	CHECK(memcmp(g.tension, g0.tension, n * sizeof(*g.tension)) == 0);
	CHECK(memcmp(g.flags, g0.flags, n * sizeof(*g.flags)) == 0);
	before = density_sum(&g0);
	after = density_sum(&g);
	CHECK(added > 0.0);
	CHECK(lost >= 0.0);
	CHECK(want_lost ? lost > 0.0 : lost == 0.0);
	/* wood is lost only when the rings, out to the grid's far side, found no room: then
	 * the whole grid is full */
	for (size_t i = 0; lost > 0.0 && i < n; i++)
		CHECK(g.density[i] == 1.0);
	CHECK_NEAR(dsum, added - lost, 1e-12 * added);
	CHECK_NEAR(after - before, added - lost, 1e-12 * (added + before));
	printf("  seed %llu %dx%dx%d %s alpha %g beta %g: %zu overflows, added %.6f, lost %.6f, "
	       "|sum d - (added - lost)| / added = %.2e\n", (unsigned long long)seed, nx, ny, nz,
	       mode == WOOD_CONIFER ? "conifer" : "broadleaf", alpha, beta, nover, added, lost,
	       fabs(dsum - (added - lost)) / added);
	wood_grid_finish(&g0);
	wood_grid_finish(&g);
	wood_grid_finish(&h);
}

static void test_random(void)
{
	random_case(1, 16, 16, 16, WOOD_CONIFER, 1.0, 1.0, 3.0, false);
	random_case(2, 16, 12, 10, WOOD_BROADLEAF, 2.0, 1.5, 2.0, false);
	random_case(3, 9, 17, 11, WOOD_CONIFER, 0.7, 0.6, 5.0, false);
	random_case(4, 24, 24, 24, WOOD_BROADLEAF, 1.0, 2.0, 2.0, false);
	/* so much growth the grid fills: the rest is lost at its edge */
	random_case(5, 4, 3, 5, WOOD_CONIFER, 5.0, 1.0, 10.0, true);
}

/* Errors leave the field as it was. */
static void test_errors(void)
{
	struct wood_grid g;
	struct wood_params p = params(WOOD_CONIFER, NAN, 1.0);
	double added = -1, lost = -1;
	size_t c;

	grid(&g, 3, 3, 3);
	c = mass(&g, 1, 1, 1, 0.5, 1.0, 1.0);
	mass(&g, 0, 0, 0, 0.5, 1.0, 1.0);
	CHECK_INT(wood_thicken(&g, &p, &added, &lost), -EINVAL);
	CHECK(g.density[c] == 0.5);
	CHECK(added == 0.0 && lost == 0.0);
	p = params(WOOD_CONIFER, 1e200, 3.0); /* a Csi of infinity */
	CHECK_INT(wood_thicken(&g, &p, &added, &lost), -EINVAL);
	CHECK(g.density[c] == 0.5);
	p = params((enum wood_mode)7, 1.0, 1.0);
	CHECK_INT(wood_thicken(&g, &p, &added, &lost), -EINVAL);
	CHECK(g.density[c] == 0.5);
	/* a force of NaN */
	p = params(WOOD_CONIFER, 1.0, 1.0);
	g.compression[c] = NAN;
	CHECK_INT(wood_thicken(&g, &p, &added, &lost), -EINVAL);
	CHECK(g.density[c] == 0.5);
	g.compression[c] = 1.0;
	if (FAIL_ALLOC_HOOK && fail_alloc_hooked()) {
		fail_alloc_at(0);
		CHECK_INT(wood_thicken(&g, &p, &added, &lost), -ENOMEM);
		fail_alloc_off();
		CHECK(g.density[c] == 0.5);
	}
	CHECK_INT(wood_thicken(&g, &p, &added, &lost), 0);
	CHECK(g.density[c] > 0.5);
	wood_grid_finish(&g);

	/* nothing to grow: 0, nothing added, nothing allocated */
	grid(&g, 2, 2, 2);
	if (FAIL_ALLOC_HOOK && fail_alloc_hooked())
		fail_alloc_at(0);
	CHECK_INT(wood_thicken(&g, &p, &added, &lost), 0);
	fail_alloc_off();
	CHECK(added == 0.0 && lost == 0.0);
	wood_grid_finish(&g);
}

int main(void)
{
	test_exact();
	test_exact_numbers();
	test_modes();
	test_who_grows();
	test_overflow_weights();
	test_saturation();
	test_ring_spill();
	test_edge();
	test_previous_field();
	test_two_sources();
	test_random();
	test_errors();
	return 0;
}
