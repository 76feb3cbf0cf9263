/* SPDX-License-Identifier: MIT */
#pragma once

/*
 * The mass-spring model of a wood grid (steps 4-5, wood.h), shared by the static solve
 * (wood_solve.c, wood_mg.c) and the paper's time stepping (wood_euler.c). Private to them.
 */
#include <stddef.h>
#include <stdint.h>

#include "wood.h"

/* The 26 neighbour offsets (x, y, z), z slowest; direction 25 - d is -d's. */
#define WOOD_DIRS 26
extern const int wood_dir[WOOD_DIRS][3];
/* 1 / rest length squared of each direction (1, 1/2, 1/3). */
extern const double wood_dir_inv_len2[WOOD_DIRS];
/* The offsets as doubles, each divided by its rest length squared (for K's rows). */
extern const double wood_dir_scaled[WOOD_DIRS][3];

/*
 * The kept mass points (held: see wood_model_build), numbered in grid order, and their
 * springs as a 26-neighbour table.
 */
struct wood_model {
	int nx, ny, nz;  /* the grid's */
	size_t n;        /* kept points */
	size_t *cell;    /* n: each point's voxel (wood_index) */
	int32_t *nb;     /* 26 n: the neighbouring kept point in each direction, or -1 */
	uint8_t *fixed;  /* n: 1 when fixed */
	size_t nmass;    /* voxels of density above 0 */
	size_t nfixed;   /* kept points that are fixed */
	size_t nsprings; /* springs between kept points, each once */
	size_t dropped;  /* nmass - n */
	size_t loose;    /* of dropped: joined to a fixed point by springs, but not held */
};

/*
 * Builds the model of g's field: mass points (density > 0), fixed ones (centre at most
 * one voxel above ground_y), and the held closure from the fixed ones (a point is held
 * when its springs to held points span all three directions). 0, -EINVAL (no point fixed)
 * or -ENOMEM.
 */
int wood_model_build(const struct wood_grid *g, double ground_y, struct wood_model *m);
void wood_model_finish(struct wood_model *m);

/*
 * Writes g's flags, displacement (u: 3 a point, voxel units), compression and tension of
 * every kept point from its springs' forces: linear (S = e . (u_j - u_i)) or, when
 * `full`, the springs' own (S = clamp(l - l0)). Every other voxel's fields stay 0.
 */
void wood_model_store(struct wood_grid *g, const struct wood_model *m, const double *u,
		      int full);
/* The force of the spring from point i in direction d to j, k = 1: S > 0 stretched. */
double wood_spring_force(const double *u, size_t i, size_t j, int d, int full);

/* Zeroes g's output fields (compression, tension, displacement, flags). */
void wood_output_clear(struct wood_grid *g);
/* What both solves do first: stats zeroed, the fields cleared, the load checked (finite).
 * 0 or -EINVAL. */
int wood_rest_begin(struct wood_grid *g, const struct wood_params *p,
		    struct wood_solve_stats *stats);
/* Fills stats from the model (iterations and residual 0). */
void wood_model_stats(const struct wood_model *m, struct wood_solve_stats *stats);

/* y = K u over the kept points (the linearised springs, k = 1); fixed rows 0. */
void wood_apply(const struct wood_model *m, const double *u, double *y);
/* (K u)_i of a free point i: the sum over its springs of k e e^T (u_i - u_j). */
static inline void wood_row(const struct wood_model *m, size_t i, const double *u, double o[3])
{
	const int32_t *nb = m->nb + i * WOOD_DIRS;
	const double *ui = u + 3 * i;
	double a0 = 0.0, a1 = 0.0, a2 = 0.0;

	for (int d = 0; d < WOOD_DIRS; d++) {
		const double *uj, *e = wood_dir_scaled[d];
		double s;

		if (nb[d] < 0)
			continue;
		uj = u + 3 * (size_t)nb[d];
		/* e e^T = dir dir^T / |dir|^2 */
		s = e[0] * (ui[0] - uj[0]) + e[1] * (ui[1] - uj[1]) + e[2] * (ui[2] - uj[2]);
		a0 += s * wood_dir[d][0];
		a1 += s * wood_dir[d][1];
		a2 += s * wood_dir[d][2];
	}
	o[0] = a0;
	o[1] = a1;
	o[2] = a2;
}
/* The 3 x 3 block of K at point i (its springs' sum of e e^T), row-major. */
void wood_diag_block(const struct wood_model *m, size_t i, double b[9]);

/* The conjugate gradients' preconditioner (wood_mg.c): z = M^-1 r, symmetric positive
 * definite, fixed rows 0. */
struct wood_precond;
int wood_precond_create(const struct wood_model *m, struct wood_precond **out);
void wood_precond_apply(struct wood_precond *pc, const double *r, double *z);
void wood_precond_destroy(struct wood_precond *pc);
