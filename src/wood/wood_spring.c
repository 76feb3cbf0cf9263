/* SPDX-License-Identifier: MIT */
/*
 * Step 4 (wood.h, docs/wood.md): the mass-spring model of a wood grid. Mass points are
 * the voxels of density above 0, springs join 26-neighbours; the fixed points are those
 * at most one voxel above the ground; the kept points are those held from the fixed ones
 * through springs in all three directions (the rest are dropped), so that the linearised
 * stiffness of the kept points is positive definite.
 */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "wood_spring.h"

const int wood_dir[WOOD_DIRS][3] = {
	{ -1, -1, -1 }, { 0, -1, -1 }, { 1, -1, -1 }, { -1, 0, -1 }, { 0, 0, -1 },
	{ 1, 0, -1 },   { -1, 1, -1 }, { 0, 1, -1 },  { 1, 1, -1 },  { -1, -1, 0 },
	{ 0, -1, 0 },   { 1, -1, 0 },  { -1, 0, 0 },  { 1, 0, 0 },   { -1, 1, 0 },
	{ 0, 1, 0 },    { 1, 1, 0 },   { -1, -1, 1 }, { 0, -1, 1 },  { 1, -1, 1 },
	{ -1, 0, 1 },   { 0, 0, 1 },   { 1, 0, 1 },   { -1, 1, 1 },  { 0, 1, 1 },
	{ 1, 1, 1 },
};

#define I2 (1.0 / 2.0)
#define I3 (1.0 / 3.0)
const double wood_dir_inv_len2[WOOD_DIRS] = {
	I3, I2, I3, I2, 1, I2, I3, I2, I3, I2, 1, I2, 1,
	1,  I2, 1, I2, I3, I2, I3, I2, 1, I2, I3, I2, I3,
};

#define S2 (1.0 / 2.0)
#define S3 (1.0 / 3.0)
const double wood_dir_scaled[WOOD_DIRS][3] = {
	{ -S3, -S3, -S3 }, { 0, -S2, -S2 }, { S3, -S3, -S3 }, { -S2, 0, -S2 }, { 0, 0, -1 },
	{ S2, 0, -S2 },    { -S3, S3, -S3 }, { 0, S2, -S2 }, { S3, S3, -S3 },  { -S2, -S2, 0 },
	{ 0, -1, 0 },      { S2, -S2, 0 },  { -1, 0, 0 },    { 1, 0, 0 },      { -S2, S2, 0 },
	{ 0, 1, 0 },       { S2, S2, 0 },   { -S3, -S3, S3 }, { 0, -S2, S2 },  { S3, -S3, S3 },
	{ -S2, 0, S2 },    { 0, 0, 1 },     { S2, 0, S2 },   { -S3, S3, S3 },  { 0, S2, S2 },
	{ S3, S3, S3 },
};

/* Per-voxel state while building. */
enum {
	ST_MASS = 1u << 0,
	ST_HELD = 1u << 1,
	ST_QUEUED = 1u << 2,
	ST_JOINED = 1u << 3, /* reached from a fixed point through springs */
	ST_FIXED = 1u << 4,
};

struct build {
	const struct wood_grid *g;
	uint8_t *st;
	size_t *queue; /* a ring of cells, each at most once in it */
	size_t cap, head, count;
};

static void push(struct build *b, size_t c)
{
	b->queue[(b->head + b->count) % b->cap] = c;
	b->count++;
}

static size_t pop(struct build *b)
{
	size_t c = b->queue[b->head];

	b->head = (b->head + 1) % b->cap;
	b->count--;
	return c;
}

/* The neighbour of cell c (at x, y, z) in direction d, or SIZE_MAX outside the grid. */
static size_t neighbour(const struct wood_grid *g, int x, int y, int z, int d)
{
	int a = x + wood_dir[d][0], b = y + wood_dir[d][1], c = z + wood_dir[d][2];

	if (a < 0 || b < 0 || c < 0 || a >= g->nx || b >= g->ny || c >= g->nz)
		return SIZE_MAX;
	return wood_index(g, a, b, c);
}

static void coords(const struct wood_grid *g, size_t c, int *x, int *y, int *z)
{
	*x = (int)(c % (size_t)g->nx);
	*y = (int)(c / (size_t)g->nx % (size_t)g->ny);
	*z = (int)(c / ((size_t)g->nx * (size_t)g->ny));
}

/* Whether c's springs to held points span all three directions: det(sum d d^T) > 0,
 * exact in integers. */
static int spans(const struct build *b, size_t c)
{
	long m[3][3] = { { 0 } };
	int x, y, z;

	coords(b->g, c, &x, &y, &z);
	for (int d = 0; d < WOOD_DIRS; d++) {
		size_t o = neighbour(b->g, x, y, z, d);

		if (o == SIZE_MAX || !(b->st[o] & ST_HELD))
			continue;
		for (int r = 0; r < 3; r++)
			for (int s = 0; s < 3; s++)
				m[r][s] += wood_dir[d][r] * wood_dir[d][s];
	}
	return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
		       m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
		       m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]) >
	       0;
}

/* Queues c's mass neighbours that have `bit` clear and are not queued. */
static void push_neighbours(struct build *b, size_t c, uint8_t bit)
{
	int x, y, z;

	coords(b->g, c, &x, &y, &z);
	for (int d = 0; d < WOOD_DIRS; d++) {
		size_t o = neighbour(b->g, x, y, z, d);

		if (o == SIZE_MAX || (b->st[o] & (ST_MASS | bit | ST_QUEUED)) != ST_MASS)
			continue;
		b->st[o] |= ST_QUEUED;
		push(b, o);
	}
}

/* Flood fill of `bit` from the fixed points; with `held`, a point takes it only when
 * spans() (re-examined whenever a neighbour takes it). The closure does not depend on
 * the order. */
static void flood(struct build *b, size_t ncells, uint8_t bit, int held)
{
	for (size_t c = 0; c < ncells; c++)
		if (b->st[c] & ST_FIXED)
			b->st[c] |= bit;
	for (size_t c = 0; c < ncells; c++)
		if (b->st[c] & ST_FIXED)
			push_neighbours(b, c, bit);
	while (b->count) {
		size_t c = pop(b);

		b->st[c] &= (uint8_t)~ST_QUEUED;
		if (held && !spans(b, c))
			continue;
		b->st[c] |= bit;
		push_neighbours(b, c, bit);
	}
}

/* Marks mass and fixed voxels; the number of each. */
static void classify(const struct wood_grid *g, double ground_y, uint8_t *st, size_t *nmass,
		     size_t *nfixed)
{
	*nmass = *nfixed = 0;
	for (int z = 0; z < g->nz; z++)
		for (int y = 0; y < g->ny; y++) {
			/* the voxel's centre at most one voxel above the ground */
			int low = g->origin.y + (y + 0.5) * g->h <= ground_y + g->h;

			for (int x = 0; x < g->nx; x++) {
				size_t c = wood_index(g, x, y, z);

				if (!(g->density[c] > 0.0))
					continue;
				st[c] = ST_MASS;
				(*nmass)++;
				if (low) {
					st[c] |= ST_FIXED;
					(*nfixed)++;
				}
			}
		}
}

/* Numbers the held points in grid order and fills the neighbour table. */
static int number(const struct wood_grid *g, const uint8_t *st, struct wood_model *m)
{
	size_t ncells = wood_cells(g), k = 0;
	int32_t *id = malloc(ncells * sizeof(*id));

	if (!id)
		return -ENOMEM;
	for (size_t c = 0; c < ncells; c++)
		id[c] = (st[c] & ST_HELD) ? (int32_t)k++ : -1;
	m->cell = malloc((m->n ? m->n : 1) * sizeof(*m->cell));
	m->nb = malloc((m->n ? m->n : 1) * WOOD_DIRS * sizeof(*m->nb));
	m->fixed = malloc(m->n ? m->n : 1);
	if (!m->cell || !m->nb || !m->fixed) {
		free(id);
		return -ENOMEM;
	}
	k = 0;
	for (size_t c = 0; c < ncells; c++) {
		int x, y, z;

		if (id[c] < 0)
			continue;
		coords(g, c, &x, &y, &z);
		m->cell[k] = c;
		m->fixed[k] = (st[c] & ST_FIXED) != 0;
		m->nfixed += m->fixed[k];
		for (int d = 0; d < WOOD_DIRS; d++) {
			size_t o = neighbour(g, x, y, z, d);
			int32_t j = o == SIZE_MAX ? -1 : id[o];

			m->nb[k * WOOD_DIRS + (size_t)d] = j;
			m->nsprings += j >= 0 && d < WOOD_DIRS / 2;
		}
		k++;
	}
	free(id);
	return 0;
}

int wood_model_build(const struct wood_grid *g, double ground_y, struct wood_model *m)
{
	size_t ncells = wood_cells(g), nfixed, joined = 0;
	struct build b = { .g = g };
	int rc;

	memset(m, 0, sizeof(*m));
	m->nx = g->nx;
	m->ny = g->ny;
	m->nz = g->nz;
	if (!isfinite(ground_y))
		return -EINVAL;
	b.st = calloc(ncells, 1);
	if (!b.st)
		return -ENOMEM;
	classify(g, ground_y, b.st, &m->nmass, &nfixed);
	if (!nfixed) {
		free(b.st);
		return -EINVAL;
	}
	if (m->nmass >= (size_t)INT32_MAX) {
		free(b.st);
		return -ENOMEM;
	}
	b.cap = m->nmass;
	b.queue = malloc(b.cap * sizeof(*b.queue));
	if (!b.queue) {
		free(b.st);
		return -ENOMEM;
	}
	flood(&b, ncells, ST_JOINED, 0);
	flood(&b, ncells, ST_HELD, 1);
	free(b.queue);
	for (size_t c = 0; c < ncells; c++) {
		m->n += (b.st[c] & ST_HELD) != 0;
		joined += (b.st[c] & ST_JOINED) != 0;
	}
	m->dropped = m->nmass - m->n;
	m->loose = joined - m->n;
	rc = number(g, b.st, m);
	free(b.st);
	if (rc < 0)
		wood_model_finish(m);
	return rc;
}

void wood_model_finish(struct wood_model *m)
{
	free(m->cell);
	free(m->nb);
	free(m->fixed);
	memset(m, 0, sizeof(*m));
}

double wood_spring_force(const double *u, size_t i, size_t j, int d, int full)
{
	const double *a = u + 3 * i, *b = u + 3 * j;
	const int *e = wood_dir[d];
	double l0 = sqrt((double)(e[0] * e[0] + e[1] * e[1] + e[2] * e[2])), s = 0.0;

	if (!full) {
		/* the stretch along the rest direction: e . (u_j - u_i) / l0 */
		for (int r = 0; r < 3; r++)
			s += e[r] * (b[r] - a[r]);
		return s / l0;
	}
	for (int r = 0; r < 3; r++) {
		double v = e[r] + (b[r] - a[r]);

		s += v * v;
	}
	return fmin(fmax(sqrt(s) - l0, -WOOD_SPRING_LIMIT), WOOD_SPRING_LIMIT);
}

void wood_model_store(struct wood_grid *g, const struct wood_model *m, const double *u,
		      int full)
{
	for (size_t i = 0; i < m->n; i++) {
		size_t c = m->cell[i];
		double comp = 0.0, tens = 0.0;

		for (int d = 0; d < WOOD_DIRS; d++) {
			int32_t j = m->nb[i * WOOD_DIRS + (size_t)d];
			double s;

			if (j < 0)
				continue;
			s = wood_spring_force(u, i, (size_t)j, d, full);
			if (s < 0.0)
				comp -= s;
			else if (s > 0.0)
				tens += s;
		}
		g->compression[c] = comp;
		g->tension[c] = tens;
		memcpy(g->displacement + 3 * c, u + 3 * i, 3 * sizeof(*u));
		g->flags[c] = (uint8_t)(WOOD_MASS | (m->fixed[i] ? WOOD_FIXED : 0));
	}
}

void wood_output_clear(struct wood_grid *g)
{
	size_t n = wood_cells(g);

	memset(g->compression, 0, n * sizeof(*g->compression));
	memset(g->tension, 0, n * sizeof(*g->tension));
	memset(g->displacement, 0, 3 * n * sizeof(*g->displacement));
	memset(g->flags, 0, n * sizeof(*g->flags));
}

void wood_model_stats(const struct wood_model *m, struct wood_solve_stats *stats)
{
	memset(stats, 0, sizeof(*stats));
	stats->points = m->n;
	stats->fixed = m->nfixed;
	stats->springs = m->nsprings;
	stats->dropped = m->dropped;
	stats->loose = m->loose;
}
