/* SPDX-License-Identifier: MIT */
/*
 * Step 5 as the paper prints it (wood.h, docs/wood.md): every free mass point moved by
 * f = m g + sum S - C v with the improved Euler scheme
 *   v(t + dt) = v(t) + dt (g + sum S - C v(t))            (m = 1)
 *   h(t + dt) = h(t) + dt / 2 (v(t) + v(t + dt))
 * on the full springs (S = k (l - l0) along the current direction, |l - l0| limited),
 * until at rest. Slow (steps grow with the stiffness's condition); for small cases, to
 * check wood_rest against.
 */
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "wood_spring.h"

struct euler {
	const struct wood_model *m;
	double ext[3]; /* the load on every free point */
	double rest_len[WOOD_DIRS];
	double *u, *v, *f, *v1; /* 3 a point: displacement, velocity, net force, new velocity */
};

/* The net force on point i (free): the load and its springs' pulls. */
static void point_force(const struct euler *e, size_t i, double out[3])
{
	const struct wood_model *m = e->m;
	const double *ui = e->u + 3 * i;

	for (int r = 0; r < 3; r++)
		out[r] = e->ext[r];
	for (int d = 0; d < WOOD_DIRS; d++) {
		int32_t j = m->nb[i * WOOD_DIRS + (size_t)d];
		const double *uj;
		double w[3], l;

		if (j < 0)
			continue;
		uj = e->u + 3 * (size_t)j;
		/* the current spring, from i to j: rest offset plus the displacements' difference */
		for (int r = 0; r < 3; r++)
			w[r] = wood_dir[d][r] + (uj[r] - ui[r]);
		l = sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
		if (!(l > 0.0))
			continue;
		/* S = k (l - l0), limited; along w / l */
		l = fmin(fmax(l - e->rest_len[d], -WOOD_SPRING_LIMIT), WOOD_SPRING_LIMIT) / l;
		for (int r = 0; r < 3; r++)
			out[r] += l * w[r];
	}
}

/* Net forces of all free points; whether every speed and net force is below tol. */
static int forces(struct euler *e, double tol, double *fsq)
{
	int rest = 1;

	*fsq = 0.0;
	for (size_t i = 0; i < e->m->n; i++) {
		double *fi = e->f + 3 * i, *vi = e->v + 3 * i, f2, v2;

		if (e->m->fixed[i]) {
			fi[0] = fi[1] = fi[2] = 0.0;
			continue;
		}
		point_force(e, i, fi);
		f2 = fi[0] * fi[0] + fi[1] * fi[1] + fi[2] * fi[2];
		v2 = vi[0] * vi[0] + vi[1] * vi[1] + vi[2] * vi[2];
		*fsq += f2;
		if (!(f2 < tol * tol && v2 < tol * tol))
			rest = 0;
	}
	return rest;
}

/* One step of the improved Euler scheme from the forces at h(t). */
static void step(struct euler *e, double dt, double damping)
{
	for (size_t i = 0; i < 3 * e->m->n; i++) {
		e->v1[i] = e->v[i] + dt * (e->f[i] - damping * e->v[i]);
		e->u[i] += 0.5 * dt * (e->v[i] + e->v1[i]);
		e->v[i] = e->v1[i];
	}
}

static int run(struct euler *e, double dt, double damping, long max_steps, double tol,
	       struct wood_solve_stats *stats)
{
	double fsq, load = 0.0;
	long k = 0;
	int rest;

	for (size_t i = 0; i < e->m->n; i++)
		if (!e->m->fixed[i])
			load += e->ext[0] * e->ext[0] + e->ext[1] * e->ext[1] + e->ext[2] * e->ext[2];
	while (!(rest = forces(e, tol, &fsq)) && k < max_steps) {
		step(e, dt, damping);
		k++;
	}
	stats->iterations = k > INT_MAX ? INT_MAX : (int)k;
	stats->residual = load > 0.0 ? sqrt(fsq / load) : 0.0;
	return rest ? 0 : -ETIMEDOUT;
}

int wood_rest_euler(struct wood_grid *g, const struct wood_params *p, double ground_y,
		    double dt, double damping, long max_steps, double tol,
		    struct wood_solve_stats *stats)
{
	struct wood_model m;
	struct euler e = { .m = &m };
	double *w;
	int rc;

	rc = wood_rest_begin(g, p, stats);
	if (rc < 0)
		return rc;
	if (!(dt > 0.0) || !isfinite(dt) || !(damping >= 0.0) || !isfinite(damping) ||
	    max_steps < 0 || !(tol > 0.0))
		return -EINVAL;
	rc = wood_model_build(g, ground_y, &m);
	if (rc < 0)
		return rc;
	wood_model_stats(&m, stats);
	w = calloc(4 * 3 * (m.n ? m.n : 1), sizeof(*w));
	if (!w) {
		wood_model_finish(&m);
		return -ENOMEM;
	}
	e.u = w;
	e.v = w + 3 * m.n;
	e.f = w + 6 * m.n;
	e.v1 = w + 9 * m.n;
	for (int d = 0; d < WOOD_DIRS; d++)
		e.rest_len[d] = sqrt(1.0 / wood_dir_inv_len2[d]); /* 1, sqrt 2, sqrt 3 */
	e.ext[0] = p->wind[0];
	e.ext[1] = -p->gravity;
	e.ext[2] = p->wind[2];
	rc = run(&e, dt, damping, max_steps, tol, stats);
	/* the last state, at rest or not */
	wood_model_store(g, &m, e.u, 1);
	free(w);
	wood_model_finish(&m);
	return rc;
}
