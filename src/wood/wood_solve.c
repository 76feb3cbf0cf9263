/* SPDX-License-Identifier: MIT */
/*
 * Step 5 (wood.h, docs/wood.md): the springs' rest state solved directly, as the static
 * equilibrium of the linearised springs, K u = f, by preconditioned conjugate gradients,
 * matrix-free over the 26-neighbour table. Sequential loops in a fixed order, so the same
 * field gives the same bits.
 */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "wood_spring.h"

/* Rest: |f - K u| <= WOOD_REST_TOL |f|. */
#define WOOD_REST_TOL 1e-6

void wood_apply(const struct wood_model *m, const double *u, double *y)
{
	for (size_t i = 0; i < m->n; i++) {
		if (m->fixed[i]) {
			y[3 * i] = y[3 * i + 1] = y[3 * i + 2] = 0.0;
			continue;
		}
		wood_row(m, i, u, y + 3 * i);
	}
}

/* The load: m g down and m wind across on every free point (m = 1). */
static double load(const struct wood_model *m, const struct wood_params *p, double *f)
{
	double s = 0.0;

	for (size_t i = 0; i < m->n; i++) {
		double *fi = f + 3 * i;

		if (m->fixed[i]) {
			fi[0] = fi[1] = fi[2] = 0.0;
			continue;
		}
		fi[0] = p->wind[0];
		fi[1] = -p->gravity;
		fi[2] = p->wind[2];
		s += fi[0] * fi[0] + fi[1] * fi[1] + fi[2] * fi[2];
	}
	return sqrt(s);
}

static double dot(const double *a, const double *b, size_t n)
{
	double s = 0.0;

	for (size_t i = 0; i < n; i++)
		s += a[i] * b[i];
	return s;
}

/* |f - K u| / |f|, r = f - K u. */
static double residual(const struct wood_model *m, const double *f, double fnorm,
		       const double *u, double *r)
{
	wood_apply(m, u, r);
	for (size_t i = 0; i < 3 * m->n; i++)
		r[i] = f[i] - r[i];
	return sqrt(dot(r, r, 3 * m->n)) / fnorm;
}

/*
 * Preconditioned CG from u = 0 to the tolerance, checked on the true residual (CG's
 * recurrence drifts from it; restarts from the true one when they part).
 */
static int pcg(const struct wood_model *m, struct wood_precond *pc, const double *f,
	       double fnorm, double *u, int *iterations, double *res)
{
	size_t n3 = 3 * m->n;
	double *w = malloc(4 * n3 * sizeof(*w));
	double *r, *z, *q, *kq, rz, tol = WOOD_REST_TOL * fnorm;
	int it = 0, max_it = 20000 + (int)fmin(3.0 * (double)n3, 1e6);

	if (!w)
		return -ENOMEM;
	r = w;
	z = w + n3;
	q = w + 2 * n3;
	kq = w + 3 * n3;
	memset(u, 0, n3 * sizeof(*u));
	for (*res = residual(m, f, fnorm, u, r); *res > WOOD_REST_TOL && it < max_it;
	     *res = residual(m, f, fnorm, u, r)) {
		/* aim below the tolerance so the true residual lands under it */
		double aim = 0.5 * tol;

		wood_precond_apply(pc, r, z);
		memcpy(q, z, n3 * sizeof(*q));
		rz = dot(r, z, n3);
		while (it < max_it && sqrt(dot(r, r, n3)) > aim) {
			double a, rz1, beta;

			wood_apply(m, q, kq);
			a = rz / dot(q, kq, n3);
			for (size_t i = 0; i < n3; i++) {
				u[i] += a * q[i];
				r[i] -= a * kq[i];
			}
			wood_precond_apply(pc, r, z);
			rz1 = dot(r, z, n3);
			beta = rz1 / rz;
			for (size_t i = 0; i < n3; i++)
				q[i] = z[i] + beta * q[i];
			rz = rz1;
			it++;
		}
	}
	free(w);
	*iterations = it;
	return *res <= WOOD_REST_TOL ? 0 : -ETIMEDOUT;
}

int wood_rest_begin(struct wood_grid *g, const struct wood_params *p,
		    struct wood_solve_stats *stats)
{
	memset(stats, 0, sizeof(*stats));
	if (!g || !g->density)
		return -EINVAL;
	wood_output_clear(g);
	if (!p || !isfinite(p->gravity) || !isfinite(p->wind[0]) || !isfinite(p->wind[2]))
		return -EINVAL;
	return 0;
}

int wood_rest(struct wood_grid *g, const struct wood_params *p, double ground_y,
	      struct wood_solve_stats *stats)
{
	struct wood_model m;
	struct wood_precond *pc = NULL;
	double *f, *u, fnorm;
	int rc = wood_rest_begin(g, p, stats);

	if (rc < 0)
		return rc;
	rc = wood_model_build(g, ground_y, &m);
	if (rc < 0)
		return rc;
	wood_model_stats(&m, stats);
	f = malloc(3 * (m.n ? m.n : 1) * sizeof(*f));
	u = calloc(3 * (m.n ? m.n : 1), sizeof(*u));
	if (!f || !u) {
		rc = -ENOMEM;
		goto out;
	}
	fnorm = load(&m, p, f);
	if (fnorm > 0.0) {
		/* with no load the rest state is u = 0: no iterations */
		rc = wood_precond_create(&m, &pc);
		if (rc == 0)
			rc = pcg(&m, pc, f, fnorm, u, &stats->iterations, &stats->residual);
	}
	if (rc == 0)
		wood_model_store(g, &m, u, 0);
out:
	wood_precond_destroy(pc);
	free(f);
	free(u);
	wood_model_finish(&m);
	return rc;
}
