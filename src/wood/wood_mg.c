/* SPDX-License-Identifier: MIT */
/*
 * The preconditioner of the rest state's conjugate gradients (wood_solve.c): one
 * geometric multigrid V-cycle. Level 0 is the springs themselves (matrix-free); each
 * coarser level has a node every other voxel of the finer one, trilinear interpolation P
 * from it (which carries translations and the small rotations exactly), and the Galerkin
 * operator P^T A P, again 27 3 x 3 blocks a node. Smoothing: one forward point-block
 * Gauss-Seidel sweep before, one backward after, so the cycle is symmetric; the coarsest
 * level solved by a dense Cholesky factor. Block-Jacobi CG needs thousands of iterations
 * on a tree's long thin branches (bending); this needs tens.
 */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "wood_spring.h"

#define MG_SLOTS 27
#define MG_SELF 13
#define MG_MAX_LEVELS 16
/* Levels stop coarsening at this many nodes (a dense factor of 3 n rows). */
#define MG_COARSEST 128

struct mg_level {
	size_t n;
	int nx, ny, nz;
	int32_t *xyz;         /* 3 a node: its grid coordinates on this level */
	const uint8_t *fixed; /* level 0: fixed points (no unknowns); NULL above */
	int32_t *nb;          /* above 0: 27 a node, the node in each slot or -1 */
	double *a;            /* above 0: 27 blocks of 9 a node, P^T A P */
	double *dinv;         /* 9 a node: the inverse of its diagonal block (0 when fixed) */
	int32_t *par;         /* 8 a node: its parents on the next level, -1 none */
	double *w;            /* 8 a node: their weights */
	double *x, *b, *r;    /* 3 a node */
};

struct wood_precond {
	const struct wood_model *m;
	double e[WOOD_DIRS][9]; /* each direction's spring block e e^T */
	int nlevels;
	struct mg_level lv[MG_MAX_LEVELS];
	double *chol; /* the coarsest level's factor, 3n x 3n, lower */
};

void wood_diag_block(const struct wood_model *m, size_t i, double b[9])
{
	for (int r = 0; r < 9; r++)
		b[r] = 0.0;
	for (int d = 0; d < WOOD_DIRS; d++) {
		if (m->nb[i * WOOD_DIRS + (size_t)d] < 0)
			continue;
		for (int r = 0; r < 3; r++)
			for (int s = 0; s < 3; s++)
				b[3 * r + s] += wood_dir[d][r] * wood_dir[d][s] * wood_dir_inv_len2[d];
	}
}

/* The inverse of a symmetric positive definite 3 x 3 block by its adjugate. */
static void invert3(const double a[9], double o[9])
{
	double c0 = a[4] * a[8] - a[5] * a[7], c1 = a[5] * a[6] - a[3] * a[8],
	       c2 = a[3] * a[7] - a[4] * a[6];
	double det = a[0] * c0 + a[1] * c1 + a[2] * c2, k = det > 0.0 ? 1.0 / det : 0.0;

	o[0] = c0 * k;
	o[1] = (a[2] * a[7] - a[1] * a[8]) * k;
	o[2] = (a[1] * a[5] - a[2] * a[4]) * k;
	o[3] = c1 * k;
	o[4] = (a[0] * a[8] - a[2] * a[6]) * k;
	o[5] = (a[2] * a[3] - a[0] * a[5]) * k;
	o[6] = c2 * k;
	o[7] = (a[1] * a[6] - a[0] * a[7]) * k;
	o[8] = (a[0] * a[4] - a[1] * a[3]) * k;
}

static void mul3(const double a[9], const double v[3], double o[3])
{
	for (int k = 0; k < 3; k++)
		o[k] = a[3 * k] * v[0] + a[3 * k + 1] * v[1] + a[3 * k + 2] * v[2];
}

/* The work vectors of a level. */
static int level_alloc(struct mg_level *l)
{
	size_t n = l->n ? l->n : 1;

	l->xyz = malloc(3 * n * sizeof(*l->xyz));
	l->dinv = calloc(9 * n, sizeof(*l->dinv));
	l->par = malloc(8 * n * sizeof(*l->par));
	l->w = calloc(8 * n, sizeof(*l->w));
	l->x = calloc(3 * n, sizeof(*l->x));
	l->b = calloc(3 * n, sizeof(*l->b));
	l->r = calloc(3 * n, sizeof(*l->r));
	if (!l->xyz || !l->dinv || !l->par || !l->w || !l->x || !l->b || !l->r)
		return -ENOMEM;
	for (size_t i = 0; i < 8 * n; i++)
		l->par[i] = -1;
	return 0;
}

static void level_free(struct mg_level *l)
{
	free(l->xyz);
	free(l->nb);
	free(l->a);
	free(l->dinv);
	free(l->par);
	free(l->w);
	free(l->x);
	free(l->b);
	free(l->r);
}

static int level0(struct wood_precond *pc)
{
	const struct wood_model *m = pc->m;
	struct mg_level *l = &pc->lv[0];

	l->n = m->n;
	l->nx = m->nx;
	l->ny = m->ny;
	l->nz = m->nz;
	l->fixed = m->fixed;
	if (level_alloc(l) < 0)
		return -ENOMEM;
	for (size_t i = 0; i < m->n; i++) {
		size_t c = m->cell[i];
		double b[9];

		l->xyz[3 * i] = (int32_t)(c % (size_t)m->nx);
		l->xyz[3 * i + 1] = (int32_t)(c / (size_t)m->nx % (size_t)m->ny);
		l->xyz[3 * i + 2] = (int32_t)(c / ((size_t)m->nx * (size_t)m->ny));
		if (m->fixed[i])
			continue;
		wood_diag_block(m, i, b);
		invert3(b, l->dinv + 9 * i);
	}
	for (int d = 0; d < WOOD_DIRS; d++)
		for (int r = 0; r < 3; r++)
			for (int s = 0; s < 3; s++)
				pc->e[d][3 * r + s] =
					wood_dir[d][r] * wood_dir[d][s] * wood_dir_inv_len2[d];
	return 0;
}

/* The parents (coarse coordinates, weights) of the node at f (fine coordinates): 1, 2,
 * 4 or 8 of them, their number returned. */
static int parents(const int32_t f[3], int32_t out[8][3], double w[8])
{
	int k = 1;

	out[0][0] = out[0][1] = out[0][2] = 0;
	w[0] = 1.0;
	for (int ax = 0; ax < 3; ax++) {
		int32_t c = f[ax] >> 1;

		for (int i = 0; i < k; i++)
			out[i][ax] = c;
		if (f[ax] & 1) {
			/* halfway: half to each side */
			for (int i = 0; i < k; i++) {
				memcpy(out[k + i], out[i], sizeof(out[i]));
				out[k + i][ax] = c + 1;
				w[i] *= 0.5;
				w[k + i] = w[i];
			}
			k *= 2;
		}
	}
	return k;
}

static size_t cidx(const struct mg_level *c, const int32_t p[3])
{
	return (size_t)p[0] + (size_t)c->nx * ((size_t)p[1] + (size_t)c->ny * (size_t)p[2]);
}

static int is_free(const struct mg_level *f, size_t i)
{
	return !f->fixed || !f->fixed[i];
}

/* The next level's nodes (the parents of free nodes, in grid order), f's parent table,
 * and the next level's neighbour table. */
static int coarse_nodes(struct mg_level *f, struct mg_level *c)
{
	size_t cells, k = 0;
	int32_t *map;

	c->nx = f->nx / 2 + 1;
	c->ny = f->ny / 2 + 1;
	c->nz = f->nz / 2 + 1;
	cells = (size_t)c->nx * (size_t)c->ny * (size_t)c->nz;
	map = malloc(cells * sizeof(*map));
	if (!map)
		return -ENOMEM;
	for (size_t q = 0; q < cells; q++)
		map[q] = -1;
	for (size_t i = 0; i < f->n; i++) {
		int32_t p[8][3];
		double w[8];
		int np;

		if (!is_free(f, i))
			continue;
		np = parents(f->xyz + 3 * i, p, w);
		for (int t = 0; t < np; t++)
			map[cidx(c, p[t])] = 0;
	}
	for (size_t q = 0; q < cells; q++)
		if (map[q] == 0)
			k++;
	c->n = k;
	if (level_alloc(c) < 0 || !(c->nb = malloc(MG_SLOTS * (k ? k : 1) * sizeof(*c->nb))) ||
	    !(c->a = calloc(MG_SLOTS * 9 * (k ? k : 1), sizeof(*c->a)))) {
		free(map);
		return -ENOMEM;
	}
	k = 0;
	for (size_t q = 0; q < cells; q++) {
		if (map[q] < 0)
			continue;
		map[q] = (int32_t)k;
		c->xyz[3 * k] = (int32_t)(q % (size_t)c->nx);
		c->xyz[3 * k + 1] = (int32_t)(q / (size_t)c->nx % (size_t)c->ny);
		c->xyz[3 * k + 2] = (int32_t)(q / ((size_t)c->nx * (size_t)c->ny));
		k++;
	}
	for (size_t i = 0; i < f->n; i++) {
		int32_t p[8][3];
		int np;

		if (!is_free(f, i))
			continue;
		np = parents(f->xyz + 3 * i, p, f->w + 8 * i);
		for (int t = 0; t < np; t++)
			f->par[8 * i + (size_t)t] = map[cidx(c, p[t])];
	}
	for (size_t i = 0; i < c->n; i++)
		for (int s = 0; s < MG_SLOTS; s++) {
			int32_t q[3] = { c->xyz[3 * i] + s % 3 - 1, c->xyz[3 * i + 1] + s / 3 % 3 - 1,
					 c->xyz[3 * i + 2] + s / 9 - 1 };

			c->nb[MG_SLOTS * i + (size_t)s] =
				q[0] < 0 || q[1] < 0 || q[2] < 0 || q[0] >= c->nx || q[1] >= c->ny ||
						q[2] >= c->nz ?
					-1 :
					map[cidx(c, q)];
		}
	free(map);
	return 0;
}

/* The slot of coarse node b about coarse node a (they are never further apart). */
static int slot(const struct mg_level *c, int32_t a, int32_t b)
{
	const int32_t *p = c->xyz + 3 * (size_t)a, *q = c->xyz + 3 * (size_t)b;

	return (q[0] - p[0] + 1) + 3 * (q[1] - p[1] + 1) + 9 * (q[2] - p[2] + 1);
}

/* c->a += P_i^T B P_j for the fine block B between fine nodes i and j. */
static void galerkin_add(struct mg_level *f, struct mg_level *c, size_t i, size_t j,
			 const double *B)
{
	const int32_t *pi = f->par + 8 * i, *pj = f->par + 8 * j;
	const double *wi = f->w + 8 * i, *wj = f->w + 8 * j;

	for (int s = 0; s < 8 && pi[s] >= 0; s++)
		for (int t = 0; t < 8 && pj[t] >= 0; t++) {
			size_t k = MG_SLOTS * (size_t)pi[s] + (size_t)slot(c, pi[s], pj[t]);
			double *o = c->a + 9 * k, w = wi[s] * wj[t];

			for (int k = 0; k < 9; k++)
				o[k] += w * B[k];
		}
}

/* The fine blocks: on level 0 the springs' (-e e^T off the diagonal, their sum on it; a
 * fixed neighbour is no unknown), above it the stored ones. */
static void galerkin(struct wood_precond *pc, int lf)
{
	struct mg_level *f = &pc->lv[lf], *c = &pc->lv[lf + 1];
	const struct wood_model *m = pc->m;

	for (size_t i = 0; i < f->n; i++) {
		if (!is_free(f, i))
			continue;
		if (lf > 0) {
			for (size_t s = 0; s < MG_SLOTS; s++) {
				int32_t j = f->nb[MG_SLOTS * i + s];

				if (j >= 0)
					galerkin_add(f, c, i, (size_t)j, f->a + 9 * (MG_SLOTS * i + s));
			}
			continue;
		}
		{
			double d[9], neg[9];

			wood_diag_block(m, i, d);
			galerkin_add(f, c, i, i, d);
			for (int k = 0; k < WOOD_DIRS; k++) {
				int32_t j = m->nb[i * WOOD_DIRS + (size_t)k];

				if (j < 0 || m->fixed[j])
					continue;
				for (int t = 0; t < 9; t++)
					neg[t] = -pc->e[k][t];
				galerkin_add(f, c, i, (size_t)j, neg);
			}
		}
	}
	for (size_t i = 0; i < c->n; i++)
		invert3(c->a + 9 * (MG_SLOTS * i + MG_SELF), c->dinv + 9 * i);
}

/*
 * The coarsest level's dense Cholesky factor. A pivot that vanishes (a coarse node's
 * trilinear function equal to others' on the few fine nodes it reaches) is left out:
 * the system there is consistent, and the factor stays symmetric.
 */
static int factor(struct wood_precond *pc)
{
	struct mg_level *l = &pc->lv[pc->nlevels - 1];
	size_t n = 3 * l->n;
	double *a = calloc(n ? n * n : 1, sizeof(*a));

	if (!a)
		return -ENOMEM;
	for (size_t i = 0; i < l->n; i++)
		for (int s = 0; s < MG_SLOTS; s++) {
			int32_t j = l->nb[MG_SLOTS * i + (size_t)s];

			if (j < 0)
				continue;
			for (int r = 0; r < 3; r++)
				for (int t = 0; t < 3; t++)
					a[(3 * i + (size_t)r) * n + 3 * (size_t)j + (size_t)t] =
						l->a[9 * (MG_SLOTS * i + (size_t)s) + 3 * r + t];
		}
	for (size_t j = 0; j < n; j++) {
		double d = a[j * n + j], d0 = d;

		for (size_t k = 0; k < j; k++)
			d -= a[j * n + k] * a[j * n + k];
		d = d > 1e-12 * d0 ? sqrt(d) : 0.0;
		a[j * n + j] = d;
		for (size_t i = j + 1; i < n; i++) {
			double s = a[i * n + j];

			for (size_t k = 0; k < j; k++)
				s -= a[i * n + k] * a[j * n + k];
			a[i * n + j] = d > 0.0 ? s / d : 0.0;
		}
	}
	pc->chol = a;
	return 0;
}

static void coarsest_solve(struct wood_precond *pc)
{
	struct mg_level *l = &pc->lv[pc->nlevels - 1];
	size_t n = 3 * l->n;
	const double *a = pc->chol;
	double *x = l->x;

	for (size_t i = 0; i < n; i++) {
		double s = l->b[i];

		for (size_t k = 0; k < i; k++)
			s -= a[i * n + k] * x[k];
		x[i] = a[i * n + i] > 0.0 ? s / a[i * n + i] : 0.0;
	}
	for (size_t i = n; i-- > 0;) {
		double s = x[i];

		for (size_t k = i + 1; k < n; k++)
			s -= a[k * n + i] * x[k];
		x[i] = a[i * n + i] > 0.0 ? s / a[i * n + i] : 0.0;
	}
}

/* (A x)_i of a level. */
static void row(const struct wood_precond *pc, const struct mg_level *l, size_t i,
		const double *x, double o[3])
{
	const int32_t *nb;
	const double *b;
	double a0 = 0.0, a1 = 0.0, a2 = 0.0;

	if (l == &pc->lv[0]) {
		wood_row(pc->m, i, x, o);
		return;
	}
	nb = l->nb + MG_SLOTS * i;
	b = l->a + 9 * MG_SLOTS * i;
	for (int s = 0; s < MG_SLOTS; s++, b += 9) {
		const double *xj;

		if (nb[s] < 0)
			continue;
		xj = x + 3 * (size_t)nb[s];
		a0 += b[0] * xj[0] + b[1] * xj[1] + b[2] * xj[2];
		a1 += b[3] * xj[0] + b[4] * xj[1] + b[5] * xj[2];
		a2 += b[6] * xj[0] + b[7] * xj[1] + b[8] * xj[2];
	}
	o[0] = a0;
	o[1] = a1;
	o[2] = a2;
}

/* One point-block Gauss-Seidel sweep, forward or backward. */
static void smooth(const struct wood_precond *pc, struct mg_level *l, int backward)
{
	for (size_t k = 0; k < l->n; k++) {
		size_t i = backward ? l->n - 1 - k : k;
		double ax[3], r[3], dx[3];

		if (!is_free(l, i))
			continue;
		row(pc, l, i, l->x, ax);
		for (int t = 0; t < 3; t++)
			r[t] = l->b[3 * i + (size_t)t] - ax[t];
		mul3(l->dinv + 9 * i, r, dx);
		for (int t = 0; t < 3; t++)
			l->x[3 * i + (size_t)t] += dx[t];
	}
}

static void vcycle(struct wood_precond *pc, int k)
{
	struct mg_level *l = &pc->lv[k], *c = &pc->lv[k + 1];

	if (k == pc->nlevels - 1) {
		coarsest_solve(pc);
		return;
	}
	memset(l->x, 0, 3 * l->n * sizeof(*l->x));
	smooth(pc, l, 0);
	/* restrict the residual: b_c = P^T (b - A x) */
	memset(c->b, 0, 3 * c->n * sizeof(*c->b));
	for (size_t i = 0; i < l->n; i++) {
		double ax[3];

		if (!is_free(l, i))
			continue;
		row(pc, l, i, l->x, ax);
		for (size_t s = 0; s < 8 && l->par[8 * i + s] >= 0; s++) {
			double *o = c->b + 3 * (size_t)l->par[8 * i + s], w = l->w[8 * i + s];

			for (int t = 0; t < 3; t++)
				o[t] += w * (l->b[3 * i + (size_t)t] - ax[t]);
		}
	}
	vcycle(pc, k + 1);
	/* x += P x_c */
	for (size_t i = 0; i < l->n; i++)
		for (int s = 0; s < 8 && l->par[8 * i + (size_t)s] >= 0; s++) {
			const double *xc = c->x + 3 * (size_t)l->par[8 * i + (size_t)s];
			double w = l->w[8 * i + (size_t)s];

			for (int t = 0; t < 3; t++)
				l->x[3 * i + (size_t)t] += w * xc[t];
		}
	smooth(pc, l, 1);
}

static int levels(struct wood_precond *pc)
{
	int rc = level0(pc);

	pc->nlevels = 1;
	while (rc == 0 && pc->lv[pc->nlevels - 1].n > MG_COARSEST && pc->nlevels < MG_MAX_LEVELS) {
		rc = coarse_nodes(&pc->lv[pc->nlevels - 1], &pc->lv[pc->nlevels]);
		pc->nlevels++;
		if (rc == 0)
			galerkin(pc, pc->nlevels - 2);
	}
	if (rc == 0 && pc->nlevels > 1)
		rc = factor(pc);
	return rc;
}

int wood_precond_create(const struct wood_model *m, struct wood_precond **out)
{
	struct wood_precond *pc = calloc(1, sizeof(*pc));
	int rc;

	*out = NULL;
	if (!pc)
		return -ENOMEM;
	pc->m = m;
	rc = levels(pc);
	if (rc < 0) {
		wood_precond_destroy(pc);
		return rc;
	}
	*out = pc;
	return 0;
}

void wood_precond_apply(struct wood_precond *pc, const double *r, double *z)
{
	struct mg_level *l = &pc->lv[0];

	memcpy(l->b, r, 3 * l->n * sizeof(*r));
	if (pc->nlevels == 1) {
		/* few points: block Jacobi */
		for (size_t i = 0; i < l->n; i++)
			mul3(l->dinv + 9 * i, r + 3 * i, z + 3 * i);
		return;
	}
	vcycle(pc, 0);
	memcpy(z, l->x, 3 * l->n * sizeof(*z));
}

void wood_precond_destroy(struct wood_precond *pc)
{
	if (!pc)
		return;
	for (int k = 0; k < pc->nlevels; k++)
		level_free(&pc->lv[k]);
	free(pc->chol);
	free(pc);
}
